#version 460
// particles-resolve: the particle layers over the frame. Each particle pixel's groups are combined
// front to back (over is associative: group 0 holds the nearest slabs) into colour and
// transmittance, and the frame pixel becomes colour + transmittance x scene. At full resolution the
// frame pixel is the particle pixel; at half or quarter (--particle-resolution) a frame pixel takes
// its four nearest particle pixels, weighted bilinearly and by how near the depth each was blended
// against is to its own (relative difference), so smoke behind an edge is not taken from the
// pixels of the surface in front of it.
#include "particles/tiles.glsl"

layout(local_size_x = kTileGroupSize, local_size_y = kTileGroupSize) in;
layout(set = 0, binding = 16) uniform sampler2D sceneDepth;
layout(set = 0, binding = 21, rgba16f) uniform image2D hdr;
layout(set = 0, binding = 24, r32f) uniform readonly image2D particleLayerDepth;

// The other layer with glass in the scene (the front one when this resolves the one behind, and the
// other way round); without glass, the same one.
layout(std430, set = 0, binding = 36) readonly buffer OtherParticleLayerBlock {
  uvec2 otherParticleLayers[];
};

// Colour (rgb) and transmittance (a) of the groups at particle pixel `pixel`, front to back up to the
// first that left either layer opaque there: a group behind it may have stopped early once it saw
// the whole tile opaque (particles-composite), so what it left is never read; what it held is hidden.
vec4 particlePixel(ivec2 pixel) {
  vec3 colour = vec3(0.0);
  float transmittance = 1.0, other = 1.0;
  for (uint g = 0u; g < tileHeader.groups; ++g) {
    uint index = particleLayerIndex(g, pixel);
    uvec2 packed = particleLayers[index];
    vec2 ba = unpackHalf2x16(packed.y);
    colour += transmittance * vec3(unpackHalf2x16(packed.x), ba.x);
    transmittance *= ba.y;
    other *= unpackHalf2x16(otherParticleLayers[index].y).y;
    // A group's transmittance below kParticleOpaqueTransmittance is at most it once packed as a half,
    // and a product of transmittances is at most each of them.
    if (min(transmittance, other) <= kParticleOpaqueTransmittance) break;
  }
  return vec4(colour, transmittance);
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
