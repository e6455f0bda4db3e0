#version 460
// particles-upsample (--particle-resolution half or quarter): the particle layer, blended at a
// lower resolution by particles-composite, over the frame. Each frame pixel takes its four nearest
// layer pixels, weighted bilinearly and by how near the depth each was blended against is to the
// pixel's own (relative difference), so smoke behind an edge is not taken from the pixels of the
// surface in front of it, and composites colour + transmittance x scene.
#include "common/frame.glsl"
#include "shared/particle_types.h"

layout(local_size_x = kTileGroupSize, local_size_y = kTileGroupSize) in;
layout(set = 0, binding = 16) uniform sampler2D sceneDepth;
layout(set = 0, binding = 21, rgba16f) uniform image2D hdr;
layout(set = 0, binding = 23, rgba16f) uniform readonly image2D particleLayer;
layout(set = 0, binding = 24, r32f) uniform readonly image2D particleLayerDepth;
layout(push_constant) uniform UpsampleBlock {
  uvec4 upsample;  // x scale (frame pixels per layer pixel)
};

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, ivec2(frame.viewport.xy)))) return;
  float scale = float(upsample.x);
  ivec2 last = imageSize(particleLayer) - 1;
  float depth = linearizeDepth(texelFetch(sceneDepth, pixel, 0).r);
  // The pixel's centre in layer pixels, and the layer pixel centres around it.
  vec2 at = (vec2(pixel) + 0.5) / scale - 0.5;
  ivec2 base = ivec2(floor(at));
  vec2 f = at - vec2(base);
  vec4 sum = vec4(0.0);
  float weights = 0.0;
  for (int i = 0; i < 4; ++i) {
    ivec2 corner = ivec2(i & 1, i >> 1);
    ivec2 p = clamp(base + corner, ivec2(0), last);
    vec2 w2 = mix(1.0 - f, f, vec2(corner));
    float difference = abs(imageLoad(particleLayerDepth, p).r - depth) / max(depth, 1e-6);
    float w = w2.x * w2.y / (difference + 0.01) + 1e-6;
    sum += w * imageLoad(particleLayer, p);
    weights += w;
  }
  vec4 layer = sum / weights;
  if (layer.a >= 1.0 && layer.rgb == vec3(0.0)) return;
  vec4 scene = imageLoad(hdr, pixel);
  imageStore(hdr, pixel, vec4(layer.rgb + layer.a * scene.rgb, scene.a));
}
