// The shadow casters' compute rasterizer, per texel of each view's cell (shadows/shadow_raster.h):
// the nearest depth of the first pass's key and its bin's large triangles, the key then reset to 0.
// Workgroup z is the view; texels outside this frame's cells are neither read nor written. Included by
// caster_resolve.comp (into a buffer, copied into a D32 atlas) and caster_resolve_image.comp (straight into
// an R32F atlas), which define shadowDepthOut(texel, size, depth).
#include "common/frame.glsl"
#include "shared/shadow_types.h"

layout(local_size_x = 8, local_size_y = 8) in;

// The views to draw (shared/shadow_types.h, ShadowRasterView): a header, then the views.
layout(std430, set = 0, binding = 26) readonly buffer ShadowViewsBlock {
  uvec4 shadowViewHeader;  // x views, y atlas width, z atlas height
  ShadowRasterView shadowViews[];
};
layout(push_constant) uniform RasterBlock {
  RasterPush raster;
};

#include "common/raster_triangle.glsl"

void main() {
  ivec2 size = ivec2(shadowViewHeader.yz);
  uvec4 cell = shadowViews[gl_WorkGroupID.z].cell;
  ivec2 cellLo = ivec2(cell.xy), cellEnd = min(cellLo + ivec2(cell.zz), size);
  // Tiles on the atlas's 8-texel grid (each within one bin), from the one holding the cell's corner.
  ivec2 tileLo = (cellLo & ~7) + ivec2(gl_WorkGroupID.xy) * 8;
  if (any(greaterThanEqual(tileLo, cellEnd))) return;  // the whole workgroup
  ivec2 texel = tileLo + ivec2(gl_LocalInvocationID.xy);
  bool inside = all(greaterThanEqual(texel, cellLo)) && all(lessThan(texel, cellEnd));
  uint64_t best = rasterNearest(texel, tileLo, inside, size);
  if (!inside) return;
  shadowDepthOut(texel, size, uintBitsToFloat(uint(best >> 32)));
  // Cleared for the next frame: the triangle pass writes keys only within the views' cells, and
  // every cell drawn is resolved here in the same frame, so no pass over the whole atlas is needed.
  keys[uint(texel.y) * uint(size.x) + uint(texel.x)] = 0ul;
}
