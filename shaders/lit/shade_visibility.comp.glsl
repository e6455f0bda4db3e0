// Opaque shading from the visibility buffer (--surfaces visibility, the default), for techniques
// that light opaque surfaces through their lighting interface: each invocation rebuilds its pixel's
// surface from the pixel's triangle and material and writes everything it sends to the eye (black
// where nothing was drawn). With 8x8 groups and lll's 8-pixel tiles a group walks one list, so its
// loads are uniform across the group. (Reading the list once per workgroup into shared memory, one
// invocation following the links, was slower on the H200: 0.342 against 0.286 ms for ThreeL's 16
// lights at 1080p, 4.14 against 3.47 ms for its 256.) Every light at once (forward) is loaded into
// shared memory 64 lights at a time instead: 0.206 against 0.231 ms, 2.27 against 2.70 ms. The
// same for a list's lights (every record of a scene of at most 256 in shared memory, the walk
// reading the one a link names there) was 3.3x slower on the H200: 0.725 against 0.223 ms, 8.27
// against 2.40 (registers 56 -> 103; bench/README.md 2026-12-04 fourth).
#include "common/lighting.glsl"
#include "common/visibility_surface.glsl"
#define LLL_DISPLAY_FROM_SHADING
#include "post/display.glsl"
#ifdef LLL_INTERLEAVED_VPLS
#include "gi/interleaved_vpls.glsl"
#endif

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 13, rgba16f) uniform writeonly image2D hdr;

// The lights' sums: one, or with LLL_INTERLEAVED_VPLS (lit/shade_visibility_interleaved) the VPLs of
// the pixel's class apart from the rest.
#ifdef LLL_INTERLEAVED_VPLS
#define LightSums InterleavedSums
#define startSums(pixel) startInterleavedSums(pixel)
#define directOf(sums) sums.direct
// Light `index` (its record `light`, read only where it counts) added to `sums`.
#define addLight(sums, index, light, s)                                          \
  {                                                                              \
    uint role_ = interleavedRole(index, frame.display.w, sums.pixelClass);       \
    if (role_ == kLightDirect)                                                   \
      sums.direct += evaluateLight(light, s, terms);                             \
    else if (role_ == kLightIndirect)                                            \
      evaluateLightLobes(light, s, terms, sums.indirect, sums.indirectSpecular); \
  }
#else
#define LightSums vec3
#define startSums(pixel) vec3(0.0)
#define directOf(sums) sums
#define addLight(sums, index, light, s) sums += evaluateLight(light, s, terms)
#endif

#ifdef LIGHTING_EVERY_LIGHT
const uint kLightsPerChunk = 64u;
shared GpuLight chunkLights[kLightsPerChunk];

// Every light, loaded by the workgroup 64 at a time; every invocation must call it.
void lightFromChunks(Surface s, bool covered, inout LightSums sums) {
  BrdfTerms terms = brdfTerms(s);
  uint lightCount = frame.counts.x;
  for (uint first = 0u; first < lightCount; first += kLightsPerChunk) {
    uint count = min(kLightsPerChunk, lightCount - first);
    if (gl_LocalInvocationIndex < count)
      chunkLights[gl_LocalInvocationIndex] = lights[first + gl_LocalInvocationIndex];
    barrier();
    if (covered)
      for (uint i = 0u; i < count; ++i) addLight(sums, first + i, chunkLights[i], s);
    barrier();
  }
}
#endif

void main() {
#ifdef LLL_INTERLEAVED_VPLS
  uvec2 pixel = interleavedPixel(gl_WorkGroupID.xy, gl_LocalInvocationID.xy);
#else
  uvec2 pixel = gl_GlobalInvocationID.xy;
#endif
  bool inside = pixel.x < uint(frame.viewport.x) && pixel.y < uint(frame.viewport.y);
  Surface s;
  float viewDepth;
  bool covered = rebuildSurface(pixel, inside, s, viewDepth);  // every invocation: it has barriers
  vec3 color = vec3(0.0);
  LightSums sums = startSums(pixel);
#ifdef LLL_INTERLEAVED_VPLS
  if (covered && evaluatesEveryClass(s.metallic, s.roughness))
    placeEveryClassPixel(sums, pixel, s, viewDepth);
#endif
#ifdef LIGHTING_EVERY_LIGHT
  lightFromChunks(s, covered, sums);
#else
  if (covered) {
#ifdef LLL_INTERLEAVED_VPLS
    // Only the lights this pixel evaluates where the interface keeps the classes apart (lll's lists).
    LightCursor cursor = sums.pixelClass == kEveryClass ? lightsAt(pixel, viewDepth)
                         : sums.pixelClass == kClassesElsewhere
                             ? lightsAtPart(pixel, viewDepth, 0u)
                             : lightsAtInClass(pixel, viewDepth, sums.pixelClass);
#else
    LightCursor cursor = lightsAt(pixel, viewDepth);
#endif
    BrdfTerms terms = brdfTerms(s);
    uint light;
    bool listed;
    while (nextLink(cursor, light, listed))
      if (listed) addLight(sums, light, lightRecord(light), s);
  }
#endif
  bool replaced = false;
  if (covered) color = lightingView(s, pixel, viewDepth, unlistedLight(s) + directOf(sums), replaced);
  if (inside) {
    imageStore(hdr, ivec2(pixel), vec4(color, 1.0));
    storeDisplay(ivec2(pixel), color);
  }
#ifdef LLL_INTERLEAVED_VPLS
  if (inside) storeInterleaved(pixel, covered && !replaced, s, viewDepth, sums, frame.view);
#endif
}
