// glass-light (--glass compute where the lighting interface splits a point's lights into parts,
// LightingInterface::listParts > 1: lll's heads with --vpl-interleave): workgroup (x, y) lights
// part y of the lights of every glass layer in group x's 8x8 pixels, into glassLight; the glass pass
// adds the parts up and blends. One workgroup walking every part of a pixel's lights one after
// another left the few thousand invocations over the glass waiting on their lists' links (H200,
// 5,144 VPLs in 10 lists: 1.07 ms for 25,000 glass fragments); sharing the parts among a group's
// invocations instead was slower still (1.08, and 1.48 with one part): a group of glass is mostly
// full already, so that only added barriers.
#define GLASS_LIGHT_WRITE
#include "common/glass_layers.glsl"
#include "common/lighting.glsl"

layout(local_size_x = kTileGroupSize, local_size_y = kTileGroupSize) in;

void main() {
  uvec2 pixel = glassGroupOrigin() + gl_LocalInvocationID.xy;
  if (pixel.x >= uint(frame.viewport.x) || pixel.y >= uint(frame.viewport.y)) return;
  uint nodes[kGlassLayers], listed;
  uint count = nearestGlassLayers(glassHeads[glassHeadIndex(pixel)], nodes, listed);
  uint part = gl_WorkGroupID.y;
  for (uint i = 0u; i < count; ++i) {
    GlassFragment f = glassFragments[nodes[i]];
    glassLight[nodes[i] * kGlassLightParts + part] =
        vec4(lightSurfacePart(glassSurface(f), pixel, f.positionDepth.w, part), 0.0);
  }
}
