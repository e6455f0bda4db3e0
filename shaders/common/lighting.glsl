// What the shared lit passes (shaders/lit/*: opaque shading, glass, particles) compute with a
// technique's lighting interface, written once. Each interface, shaders/lighting/<name>/lighting.glsl,
// provides its light data's bindings (3 to 10) and
//   LightCursor lightsAt(uvec2 pixel, float viewDepth);      the lights that may reach a point
//   bool nextLight(inout LightCursor cursor, out uint light); the next one (index into lights[])
//   vec3 lightingView(Surface s, uvec2 pixel, float viewDepth, vec3 color, out bool replaced);
//                                                             a debug view over or instead of color
// and may provide (defining LIGHTING_CLASS_LISTS)
//   LightCursor lightsAtInClass(uvec2 pixel, float viewDepth, uint vplClass);
//                                   the lights a pixel that evaluates one class of VPLs walks
//                                   (--vpl-interleave, gi/interleaved_vpls.glsl); by default all
//                                   of lightsAt's, the shading pass skipping the other classes
// and (defining LIGHTING_LINK_WALK)
//   bool nextLink(inout LightCursor cursor, out uint light, out bool listed);
//                                   the next entry of its lists, whether or not it holds the point
//                                   (`listed`), so that a workgroup sharing a list walks it in step;
//                                   by default nextLight's lights, each listed. The passes whose
//                                   workgroups light points of a few tiles at nearby depths walk
//                                   links (opaque, glass, VPL classes: the atrium with 65,536 lights
//                                   shades in 18.7 ms against 23.1 on the H200); the particles, whose
//                                   invocations hold points of many depths or tiles, keep nextLight
//                                   (per-pixel smoke 56.6 -> 62.5 ms walking links)
// and (defining LIGHTING_LIGHT_RECORD)
//   GpuLight lightRecord(uint light);
//                                   the record of a light its lists name, where the opaque shading
//                                   pass reads it; by default lights[light]
// and (defining LIGHTING_LIST_PARTS)
//   LightCursor lightsAtPart(uvec2 pixel, float viewDepth, uint part);
//                                   part `part` of lightsAt's lights, of as many disjoint parts as
//                                   the C++ side's LightingInterface::listParts says, so that
//                                   several workgroups can walk one point's lights (glass-light,
//                                   vpl-classes); by default one part, all of them
// and cmake/EmbedShaders.cmake compiles every template with every interface.
#ifndef LLL_LIGHTING_GLSL
#define LLL_LIGHTING_GLSL
#include "common/material_surface.glsl"

#ifndef LIGHTING_CLASS_LISTS
LightCursor lightsAtInClass(uvec2 pixel, float viewDepth, uint vplClass) {
  return lightsAt(pixel, viewDepth);
}
#endif

#ifndef LIGHTING_LINK_WALK
bool nextLink(inout LightCursor cursor, out uint light, out bool listed) {
  listed = true;
  return nextLight(cursor, light);
}
#endif

#ifndef LIGHTING_LIGHT_RECORD
GpuLight lightRecord(uint light) {
  return lights[light];
}
#endif

#ifndef LIGHTING_LIST_PARTS
LightCursor lightsAtPart(uvec2 pixel, float viewDepth, uint part) {
  return lightsAt(pixel, viewDepth);
}
#endif

vec3 lightCursorSum(Surface s, LightCursor cursor) {
  vec3 sum = vec3(0.0);
  BrdfTerms terms = brdfTerms(s);
  uint light;
  bool listed;
  while (nextLink(cursor, light, listed))
    if (listed) sum += evaluateLight(lights[light], s, terms);
  return sum;
}

// Radiance the lights reflect from `s` towards the eye.
vec3 lightSurface(Surface s, uvec2 pixel, float viewDepth) {
  return lightCursorSum(s, lightsAt(pixel, viewDepth));
}

// The same from part `part` of the lights (lightsAtPart): the parts' sums add up to lightSurface's.
vec3 lightSurfacePart(Surface s, uvec2 pixel, float viewDepth, uint part) {
  return lightCursorSum(s, lightsAtPart(pixel, viewDepth, part));
}

// Everything that leaves `s` towards the eye: ambient, emission and the lights, or the debug view
// that replaces them (`replaced`: shown as is, glass included).
vec3 shadePixel(Surface s, uvec2 pixel, float viewDepth, out bool replaced) {
  return lightingView(s, pixel, viewDepth, unlistedLight(s) + lightSurface(s, pixel, viewDepth), replaced);
}

#endif
