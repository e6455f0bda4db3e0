#version 460
// particles-merge (more than one group a tile): each particle pixel's groups combined front to back
// (over is associative: group 0 holds the nearest slabs) into group 0's (colour, transmittance),
// with glass in the scene both layers at once, so particles-resolve reads one value where it read
// every group (four times over below full resolution, where a frame pixel takes four particle
// pixels; twice with glass). The groups are combined up to the first that left either layer opaque:
// a group behind it may have stopped early once it saw the whole tile opaque (particles-composite),
// so what it left is never read; what it held is hidden. A tile's unused groups (kTileGroupUnused,
// the last ones) wrote nothing and are skipped.
#define PARTICLE_LAYERS_READ_WRITE
#include "particles/tiles.glsl"

layout(local_size_x = kTileGroupSize, local_size_y = kTileGroupSize) in;
layout(constant_id = 0) const bool kBehindGlass = false;
layout(std430, set = 0, binding = 36) buffer ParticleLayersBehindBlock {
  uvec2 particleLayersBehind[];
};
// Per tile and group: kTileGroupUnused where the tile needed fewer groups (particles-composite).
layout(std430, set = 0, binding = 47) readonly buffer ParticleTileOpaqueBlock {
  uint tileGroupOpaque[];
};

// `layer` (colour, transmittance) with the packed one behind it over.
vec4 under(vec4 layer, uvec2 packed) {
  vec2 ba = unpackHalf2x16(packed.y);
  return vec4(layer.rgb + layer.a * vec3(unpackHalf2x16(packed.x), ba.x), layer.a * ba.y);
}

uvec2 pack(vec4 layer) {
  return uvec2(packHalf2x16(layer.rg), packHalf2x16(layer.ba));
}

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, ivec2(tileHeader.layerWidth, tileHeader.layerHeight)))) return;
  uvec2 tileXY = uvec2(pixel) / kParticleTileSize;
  uint tile = tileXY.y * tileHeader.tilesX + tileXY.x;
  // The tile's groups: group 1 unused, group 0 alone holds it all.
  if (tileGroupOpaque[tile * tileHeader.groups + 1u] == kTileGroupUnused) return;
  uint index = particleLayerIndex(0u, pixel);
  vec4 front = under(vec4(0.0, 0.0, 0.0, 1.0), particleLayers[index]);
  vec4 behind = kBehindGlass ? under(vec4(0.0, 0.0, 0.0, 1.0), particleLayersBehind[index]) : vec4(1.0);
  // A group's transmittance below kParticleOpaqueTransmittance is at most it once packed as a half,
  // and a product of transmittances is at most each of them.
  for (uint g = 1u; g < tileHeader.groups && min(front.a, behind.a) > kParticleOpaqueTransmittance; ++g) {
    if (tileGroupOpaque[tile * tileHeader.groups + g] == kTileGroupUnused) break;  // so are the rest
    uint at = particleLayerIndex(g, pixel);
    front = under(front, particleLayers[at]);
    if (kBehindGlass) behind = under(behind, particleLayersBehind[at]);
  }
  particleLayers[index] = pack(front);
  if (kBehindGlass) particleLayersBehind[index] = pack(behind);
}
