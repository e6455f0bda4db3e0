#version 460
// Shading with the light linked list from the visibility buffer (--surfaces visibility, the
// default): each invocation rebuilds its pixel's surface from the pixel's triangle and material,
// walks its tile's list, and writes the lit radiance (black where nothing was drawn). With 8x8
// groups and 8-pixel tiles a group walks one list, so its loads are uniform across the group.
// (Reading the list once per workgroup into shared memory, one invocation following the links,
// was slower on the H200: 0.342 against 0.286 ms for ThreeL's 16 lights at 1080p, 4.14 against
// 3.47 ms for its 256; the chain of dependent loads is the same, and the barriers add to it.)
#include "common/visibility_surface.glsl"
#include "lighting/lll/shade.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 13, rgba16f) uniform writeonly image2D hdr;

void main() {
  uvec2 pixel = gl_GlobalInvocationID.xy;
  bool inside = pixel.x < uint(frame.viewport.x) && pixel.y < uint(frame.viewport.y);
  Surface s;
  float viewDepth;
  bool covered = rebuildSurface(pixel, inside, s, viewDepth);  // every invocation: it has barriers
  if (!inside) return;
  vec3 color = vec3(0.0);
  if (covered) {
    bool opaque;
    color = shadeSurface(s, pixel, viewDepth, ambientAndEmissive(s), opaque);
  }
  imageStore(hdr, ivec2(pixel), vec4(color, 1.0));
}
