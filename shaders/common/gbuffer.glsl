// Writing and reading the thin G-buffer (src/render/gbuffer.h, written by common/gbuffer.frag or,
// from the visibility buffer, common/gbuffer_visibility.comp):
//   gbuffer0 RGBA8:   rgb base colour, sRGB-encoded here (a storage image cannot have an sRGB
//                     format), a metallic
//   gbuffer1 RGBA16F: xyz world-space unit normal (facing the viewer), w roughness
#ifndef LLL_GBUFFER_GLSL
#define LLL_GBUFFER_GLSL
#include "common/brdf.glsl"
#include "common/frame.glsl"
#include "common/srgb.glsl"

// The two G-buffer texels of a surface (its ambient and emission go to the accumulation target).
vec4 gbuffer0Of(Surface s) {
  return vec4(srgbEncode(s.baseColor), s.metallic);
}
vec4 gbuffer1Of(Surface s) {
  return vec4(s.normal, s.roughness);
}

// The surface the BRDF needs at `position` from the two G-buffer texels. Ambient and emission are
// already in the accumulation target, so those fields are left neutral.
Surface surfaceFromGbuffer(vec4 g0, vec4 g1, vec3 position) {
  Surface s;
  s.position = position;
  s.normal = normalize(g1.xyz);
  s.view = normalize(frame.cameraPosition.xyz - position);
  s.baseColor = srgbDecode(g0.rgb);
  s.alpha = 1.0;
  s.metallic = g0.a;
  s.roughness = g1.w;
  s.occlusion = 1.0;
  s.emissive = vec3(0.0);
  return s;
}

// World position of a pixel's surface from its linear depth: the ray through the pixel with unit
// view depth, built from the camera's axes (the rows of the view matrix), scaled by the depth.
// No matrix inverse per pixel.
vec3 reconstructPosition(vec2 fragCoord, float linearDepth) {
  vec2 ndc = fragCoord * frame.viewport.zw * 2.0 - 1.0;
  vec3 right = vec3(frame.view[0][0], frame.view[1][0], frame.view[2][0]);
  vec3 up = vec3(frame.view[0][1], frame.view[1][1], frame.view[2][1]);
  vec3 back = vec3(frame.view[0][2], frame.view[1][2], frame.view[2][2]);
  // Framebuffer y points down (the projection flips it), view-space y up.
  vec3 ray = right * (ndc.x * frame.depthParams.z) - up * (ndc.y * frame.depthParams.w) - back;
  return frame.cameraPosition.xyz + ray * linearDepth;
}

#endif
