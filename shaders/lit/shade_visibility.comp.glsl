// Opaque shading from the visibility buffer (--surfaces visibility, the default), for techniques
// that light opaque surfaces through their lighting interface: each invocation rebuilds its pixel's
// surface from the pixel's triangle and material and writes everything it sends to the eye (black
// where nothing was drawn). With 8x8 groups and lll's 8-pixel tiles a group walks one list, so its
// loads are uniform across the group. (Reading the list once per workgroup into shared memory, one
// invocation following the links, was slower on the H200: 0.342 against 0.286 ms for ThreeL's 16
// lights at 1080p, 4.14 against 3.47 ms for its 256.) Every light at once (forward) is loaded into
// shared memory 64 lights at a time instead: 0.206 against 0.231 ms, 2.27 against 2.70 ms.
#include "common/lighting.glsl"
#include "common/visibility_surface.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 13, rgba16f) uniform writeonly image2D hdr;

#ifdef LIGHTING_EVERY_LIGHT
const uint kLightsPerChunk = 64u;
shared GpuLight chunkLights[kLightsPerChunk];

// Every light, loaded by the workgroup 64 at a time; every invocation must call it.
vec3 lightFromChunks(Surface s, bool covered) {
  vec3 sum = vec3(0.0);
  uint lightCount = frame.counts.x;
  for (uint first = 0u; first < lightCount; first += kLightsPerChunk) {
    uint count = min(kLightsPerChunk, lightCount - first);
    if (gl_LocalInvocationIndex < count)
      chunkLights[gl_LocalInvocationIndex] = lights[first + gl_LocalInvocationIndex];
    barrier();
    if (covered)
      for (uint i = 0u; i < count; ++i) sum += evaluateLight(chunkLights[i], s);
    barrier();
  }
  return sum;
}
#endif

void main() {
  uvec2 pixel = gl_GlobalInvocationID.xy;
  bool inside = pixel.x < uint(frame.viewport.x) && pixel.y < uint(frame.viewport.y);
  Surface s;
  float viewDepth;
  bool covered = rebuildSurface(pixel, inside, s, viewDepth);  // every invocation: it has barriers
  vec3 color = vec3(0.0);
#ifdef LIGHTING_EVERY_LIGHT
  color = lightFromChunks(s, covered);
  bool replaced;
  if (covered) color = lightingView(s, pixel, viewDepth, unlistedLight(s) + color, replaced);
#else
  bool replaced;
  if (covered) color = shadePixel(s, pixel, viewDepth, replaced);
#endif
  if (inside) imageStore(hdr, ivec2(pixel), vec4(color, 1.0));
}
