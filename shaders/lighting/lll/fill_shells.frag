#version 460
#define LLL_FILL_PASS
// Bezrati's fill. Front faces (kBackFaces = 0) store light id and depth in the bounds buffer, the
// depth negated when the software depth test fails. Back faces read it back: same id and negative
// depth means both faces are hidden; another id means the front face was clipped by the near plane
// (or overwritten by another light), so the list gets 0 as its minimum depth. Then a link is pushed.
#include "lighting/lll/light_shape.glsl"

layout(constant_id = 1) const uint kBackFaces = 0u;
// Bounds layers picked by id, as in Bezrati's sample, so overlapping lights rarely collide.
layout(constant_id = 2) const uint kBoundsLayers = 8u;
layout(std430, set = 0, binding = 8) buffer BoundsBlock {
  uint tileBounds[];
};

layout(location = 0) flat in uint inLight;
layout(location = 1) flat in uint inBatchId;
layout(location = 2) in float inDepth;

void main() {
  uvec2 tile = uvec2(gl_FragCoord.xy);
  if (tile.x >= frame.counts.z || tile.y >= frame.counts.w) return;
  uint tileIndex = tile.y * frame.counts.z + tile.x;
  uint slot = (inBatchId % kBoundsLayers) * frame.counts.z * frame.counts.w + tileIndex;
  if (kBackFaces == 0u) {
    uint depthBits = halfRoundedDown(max(inDepth, 0.0));
    if (inDepth > tileRange[tileIndex].y) depthBits |= 0x8000u;  // occluded: store it negated
    tileBounds[slot] = (inBatchId << 16) | depthBits;
    return;
  }
  uint stored = tileBounds[slot];
  float frontDepth = 0.0;
  if ((stored >> 16) == inBatchId) {
    if ((stored & 0x8000u) != 0u) return;
    frontDepth = unpackHalf2x16(stored & 0xFFFFu).x;
  }
  pushLink(tileIndex, inLight, frontDepth, inDepth);
}
