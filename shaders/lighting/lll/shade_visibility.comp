#version 460
// Shading with the light linked list from the visibility buffer (--surfaces visibility, the
// default): each invocation rebuilds its pixel's surface from the pixel's triangle and material,
// adds its tile's lights to its ambient and emission, and writes the radiance (black where nothing
// was drawn). With tile 8 a workgroup is one tile, and its list is read once into shared memory
// (lighting/lll/tile_cache.glsl); other tile sizes and the debug views walk per pixel.
#include "common/visibility_surface.glsl"
#include "lighting/lll/shade.glsl"
#include "lighting/lll/tile_cache.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

// The tile size is 8 and no debug view is on: a workgroup's pixels share one list.
layout(constant_id = 23) const bool kWorkgroupIsTile = false;

layout(set = 0, binding = 13, rgba16f) uniform writeonly image2D hdr;

void main() {
  uvec2 pixel = gl_GlobalInvocationID.xy;
  bool inside = pixel.x < uint(frame.viewport.x) && pixel.y < uint(frame.viewport.y);
  Surface s;
  float viewDepth;
  bool covered = rebuildSurface(pixel, inside, s, viewDepth);  // every invocation: it has barriers
  vec3 color = vec3(0.0);
  if (kWorkgroupIsTile) {
    color = shadeFromTileCache(s, viewDepth, covered, tileIndexOf(gl_WorkGroupID.xy * 8u));
    if (covered) color += ambientAndEmissive(s);
  } else if (covered) {
    bool opaque;
    color = shadeSurface(s, pixel, viewDepth, ambientAndEmissive(s), opaque);
  }
  if (inside) imageStore(hdr, ivec2(pixel), vec4(color, 1.0));
}
