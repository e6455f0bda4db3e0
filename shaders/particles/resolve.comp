#version 460
// particles-resolve: the particle layer over the frame: the frame pixel becomes colour +
// transmittance x scene, from group 0's (colour, transmittance), which with more than one group a
// tile particles-merge made the combination of them all. At full resolution the frame pixel is the
// particle pixel; at half or quarter (--particle-resolution) a frame pixel takes its four nearest
// particle pixels, weighted bilinearly and by how near the depth each was blended against is to its
// own (relative difference), so smoke behind an edge is not taken from the pixels of the surface in
// front of it.
#include "particles/tiles.glsl"

layout(local_size_x = kTileGroupSize, local_size_y = kTileGroupSize) in;
layout(set = 0, binding = 16) uniform sampler2D sceneDepth;
layout(set = 0, binding = 21, rgba16f) uniform image2D hdr;
layout(set = 0, binding = 24, r32f) uniform readonly image2D particleLayerDepth;

// Colour (rgb) and transmittance (a) of the particles at particle pixel `pixel`.
vec4 particlePixel(ivec2 pixel) {
  uvec2 packed = particleLayers[particleLayerIndex(0u, pixel)];
  return vec4(unpackHalf2x16(packed.x), unpackHalf2x16(packed.y));
}

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, ivec2(frame.viewport.xy)))) return;
  vec4 layer;
  uint scale = tileHeader.scale;
  if (scale == 1u) {
    layer = particlePixel(pixel);
  } else {
    ivec2 last = ivec2(tileHeader.layerWidth, tileHeader.layerHeight) - 1;
    float depth = linearizeDepth(texelFetch(sceneDepth, pixel, 0).r);
    // The pixel's centre in particle pixels, and the particle pixel centres around it.
    vec2 at = (vec2(pixel) + 0.5) / float(scale) - 0.5;
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
      sum += w * particlePixel(p);
      weights += w;
    }
    layer = sum / weights;
  }
  if (layer.a >= 1.0 && layer.rgb == vec3(0.0)) return;
  vec4 scene = imageLoad(hdr, pixel);
  imageStore(hdr, pixel, vec4(layer.rgb + layer.a * scene.rgb, scene.a));
}
