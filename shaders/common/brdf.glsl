// The glTF 2.0 specification's reference BRDF (Appendix B): Lambert diffuse, GGX distribution,
// height-correlated Smith visibility, Schlick Fresnel; and KHR_lights_punctual attenuation.
#ifndef LLL_BRDF_GLSL
#define LLL_BRDF_GLSL
#include "shared/gpu_types.h"
#ifndef LLL_NO_LOCAL_SHADOWS
#include "common/local_shadow.glsl"
#else
// A pass that defines LLL_NO_LOCAL_SHADOWS (bench/alu_probe.comp) binds no shadow atlas.
const bool kLocalShadows = false;
float localShadow(GpuLight light, vec3 position, vec3 normal, vec3 l, float distance) {
  return 1.0;
}
#endif

const float kPi = 3.14159265358979;

// Whether the scene has spot, box and virtual point lights (lightTypeConstants, render/frame.h): a
// pass that sets them false compiles those branches out of every light evaluation.
layout(constant_id = 30) const bool kSceneHasSpots = true;
layout(constant_id = 31) const bool kSceneHasBoxes = true;
layout(constant_id = 32) const bool kSceneHasVpls = true;

struct Surface {
  vec3 position;
  vec3 normal;  // unit, facing the viewer's side for double-sided materials
  vec3 view;    // unit, from the surface towards the eye
  vec3 baseColor;
  float alpha;
  float metallic;
  float roughness;
  float occlusion;
  vec3 emissive;
};

// normalize(l + v), defined also where l = -v exactly (grazing light and view, opposite).
vec3 halfVector(vec3 l, vec3 v) {
  vec3 h = l + v;
  return h * inversesqrt(max(dot(h, h), 1e-12));
}

float distributionGgx(float nDotH, float alphaRoughness) {
  float a2 = alphaRoughness * alphaRoughness;
  float d = nDotH * nDotH * (a2 - 1.0) + 1.0;
  return a2 / (kPi * d * d);
}

float visibilitySmithGgxCorrelated(float nDotL, float nDotV, float alphaRoughness) {
  float a2 = alphaRoughness * alphaRoughness;
  float ggxV = nDotL * sqrt(nDotV * nDotV * (1.0 - a2) + a2);
  float ggxL = nDotV * sqrt(nDotL * nDotL * (1.0 - a2) + a2);
  float sum = ggxV + ggxL;
  return sum > 0.0 ? 0.5 / sum : 0.0;
}

// Dielectric specular reflectance at normal incidence (IOR 1.5), glTF's f0 for non-metals.
const float kDielectricF0 = 0.04;

// What brdfCosine needs of a surface whatever the light: computed once per surface, outside the
// loop over its lights (the compiler need not find that it may hoist them).
struct BrdfTerms {
  vec3 diffuse;  // the dielectric's Lambert lobe before its Fresnel weight: (1 - metallic) baseColor / pi
  vec3 f0;       // mix(0.04, baseColor, metallic)
  float nDotV;
  float nDotVSigned;  // dot(normal, view) unclamped: n.h from n.l and n.v (brdfLobeWeights)
  float alpha;        // roughness^2, at least 1e-3
  float a2;           // alpha^2
  float smithV;       // the view's square root in the height-correlated Smith term
};

BrdfTerms brdfTerms(Surface s) {
  BrdfTerms t;
  t.diffuse = (1.0 - s.metallic) * s.baseColor / kPi;
  t.f0 = mix(vec3(kDielectricF0), s.baseColor, s.metallic);
  t.nDotVSigned = dot(s.normal, s.view);
  t.nDotV = max(t.nDotVSigned, 1e-4);
  t.alpha = max(s.roughness * s.roughness, 1e-3);
  t.a2 = t.alpha * t.alpha;
  t.smithV = sqrt(t.nDotV * t.nDotV * (1.0 - t.a2) + t.a2);
  return t;
}

// BRDF * cos(theta_l) / q for light arriving from unit direction l (nDotL = dot(normal, l) > 0),
// q > 0 the inverse square's denominator (1 for the sun), times `scale`, as three weights w:
//   diffuse lobe t.diffuse * w.x, specular lobe t.f0 * w.y + w.z, their sum the radiance.
// glTF's material is mix(dielectric_brdf, metal_brdf, metallic): the dielectric's diffuse is weighted
// by its own Fresnel term (f0 = 0.04), the metal has none, and the two specular lobes blend into one
// with f0 = mix(0.04, baseColor, metallic). Weighting the diffuse by 1 - F of that blended f0 instead
// darkens partly metallic surfaces (0.86x the specification at metallic 0.5).
// This runs once per light per pixel, so it is written for the fewest instructions: the half vector
// h = (l + v) / |l + v| is never formed (|l + v|^2 = 2 + 2 l.v, so n.h = (n.l + n.v) / |l + v| and
// v.h = (1 + l.v) / |l + v|: one dot product and one inverse square root); the GGX distribution
// a2 / (pi dd^2), the Smith visibility 0.5 / sum and the 1 / q share one reciprocal; Schlick's
// F = f0 + (1 - f0) (1 - v.h)^5 is f0 (1 - s) + s, so a colour costs two multiply-adds a lobe pair and
// the light's colour one more (evaluateLight). `a2d` is the distribution's alpha^2: t.a2, or a
// virtual point light's wider lobe (lightDistributionA2).
vec3 brdfLobeWeights(Surface s, BrdfTerms t, vec3 l, float nDotL, float q, float a2d, float scale) {
  float lDotV = dot(l, s.view);
  float inverseLength = inversesqrt(max(2.0 + 2.0 * lDotV, 1e-12));  // 1 / |l + v|, defined at l = -v
  float nDotH = max((nDotL + t.nDotVSigned) * inverseLength, 0.0);
  float vDotH = clamp((1.0 + lDotV) * inverseLength, 0.0, 1.0);
  float m = 1.0 - vDotH, m2 = m * m, schlick = m2 * m2 * m;
  float dd = nDotH * nDotH * (a2d - 1.0) + 1.0;
  float sum = nDotL * t.smithV + t.nDotV * sqrt(nDotL * nDotL * (1.0 - t.a2) + t.a2);
  float p = dd * dd * sum;
  float r = scale * nDotL / (q * p);  // every factor > 0: nDotL, nDotV > 0, dd >= a2d, q >= 1e-4
  float specular = a2d * (0.5 / kPi) * r;
  float specularSchlick = specular * schlick;
  // The diffuse: (1 - the dielectric's F) / q, p r = scale nDotL / q.
  return vec3((1.0 - kDielectricF0) * (1.0 - schlick) * (p * r), specular - specularSchlick, specularSchlick);
}

// The weights' radiance per unit light colour.
vec3 brdfOfWeights(BrdfTerms t, vec3 w) {
  return t.diffuse * w.x + (t.f0 * w.y + w.z);
}

vec3 brdfCosineOver(Surface s, BrdfTerms t, vec3 l, float nDotL, float q, float a2d) {
  return brdfOfWeights(t, brdfLobeWeights(s, t, l, nDotL, q, a2d, 1.0));
}

vec3 brdfCosineOver(Surface s, BrdfTerms t, vec3 l, float nDotL, float q) {
  return brdfCosineOver(s, t, l, nDotL, q, t.a2);
}

// BRDF * cos(theta_l) for light arriving from unit direction l.
vec3 brdfCosine(Surface s, vec3 l) {
  float nDotL = dot(s.normal, l);
  if (nDotL <= 0.0) return vec3(0.0);
  return brdfCosineOver(s, brdfTerms(s), l, nDotL, 1.0);
}

// Whether a light record is of `type` (kLightPoint...): its float compared, no conversion.
bool lightIs(GpuLight light, uint type) {
  return light.directionType.w == float(type);
}

// KHR_lights_punctual's recommended smooth window, 1 at the light and 0 at its range, from the
// squared ratio of distance to range.
float rangeWindowSquared(float ratioSquared) {
  float window = clamp(1.0 - ratioSquared * ratioSquared, 0.0, 1.0);
  return window * window;
}

float rangeWindow(float distance, float range) {
  float ratio = distance / range;
  return rangeWindowSquared(ratio * ratio);
}

// The band a VPL of the lighting grid hierarchy lights (gi/vpl_hierarchy.h): rising from `inner`
// to 2 inner (none when inner is 0), falling from `outer` to 2 outer, smoothstep both ways, so that
// a level's fall and the next level's rise add up to 1. The light record keeps the radii's
// reciprocals (scene/lights.cpp), so the band costs no division: smoothstep(a, 2a, d) = S(d / a - 1)
// with S(x) = smoothstep(0, 1, x).
float unitSmoothstep(float x) {
  float t = clamp(x, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

float hierarchyBand(float distance, float inverseInner, float inverseOuter) {
  float rise = inverseInner > 0.0 ? unitSmoothstep(distance * inverseInner - 1.0) : 1.0;
  return rise * (1.0 - unitSmoothstep(distance * inverseOuter - 1.0));
}

float spotAttenuation(GpuLight light, vec3 towardsLight) {
  if (!kSceneHasSpots || !lightIs(light, kLightSpot)) return 1.0;
  float cd = dot(light.directionType.xyz, -towardsLight);
  float t = clamp((cd - light.spotParams.x) * light.spotParams.z, 0.0, 1.0);
  return t * t;
}

// A box light's window: KHR's (1 - x^4)^2 along each of the box's axes, x the position over the half
// extent, so the light fades to exactly zero at every face. `offset` is from the box's centre.
// The light stores its axes over their half extents (gpu_types.h): three dot products.
float boxWindow(GpuLight light, vec3 offset) {
  vec3 x = light.directionType.xyz, y = light.spotParams.xyz;
  vec3 q = vec3(dot(offset, x), dot(offset, y), dot(offset, cross(x, y)) * light.spotParams.w);
  vec3 w = clamp(1.0 - q * q * q * q, 0.0, 1.0);
  w *= w;
  return w.x * w.y * w.z;
}

// A box light's axes scaled by its half extents (its corners are centre +- x +- y +- z).
void boxHalfAxes(GpuLight light, out vec3 x, out vec3 y, out vec3 z) {
  vec3 ux = light.directionType.xyz, uy = light.spotParams.xyz;  // axes over half extents
  float hx = 1.0 / length(ux), hy = 1.0 / length(uy);
  x = ux * (hx * hx);
  y = uy * (hy * hy);
  z = cross(ux, uy) * (hx * hx * hy * hy / light.spotParams.w);
}

// A light's attenuation at a point `toLight` away from it (`l` its direction, `distance` its length,
// `distanceSquared` its square, all inside the light's range) as window / max(q, 1e-4): returns
// the window (range sphere, spot cone, box or VPL band, with a VPL's cosine) and sets q, the
// squared distance its inverse square divides by.
float lightWindow(GpuLight light, vec3 toLight, vec3 l, float distance, float distanceSquared, out float q) {
  q = distanceSquared;
  if (kSceneHasBoxes && lightIs(light, kLightBox)) return boxWindow(light, -toLight);
  float range = light.positionRange.w;
  if (kSceneHasVpls && lightIs(light, kLightVpl)) {
    // A Lambertian emitter: cos(theta) about its normal; its 1/d^2 clamped at its near distance,
    // where the point stops standing for the patch of surface it was merged from; KHR's window to
    // its range, or its hierarchy band.
    float cosine = max(dot(light.directionType.xyz, -l), 0.0);
    float clamped = max(distance, light.spotParams.x);
    q = clamped * clamped;
    float window = light.spotParams.z > 0.0 ? hierarchyBand(distance, light.spotParams.y, light.spotParams.z)
                                            : rangeWindow(clamped, range);
    return window * cosine;
  }
  return rangeWindowSquared(distanceSquared / (range * range)) * spotAttenuation(light, l);
}

// The GGX distribution's alpha (and alpha^2) for a light `inverseDistance` away: a virtual point
// light stands for the patch of surface it was merged from, a disc of about its near distance in
// radius (half its cell: gi/vpl_hierarchy.h), so its specular lobe is the surface's widened by half
// the angle that patch subtends (the half vector turns half as far as the light), alpha + near /
// (2 d), at most 1: the lobe of an area light, not a point's glint. Every other light keeps the
// surface's.
float lightDistributionAlpha(GpuLight light, float alpha, float inverseDistance) {
  if (!kSceneHasVpls || !lightIs(light, kLightVpl)) return alpha;
  return min(alpha + 0.5 * light.spotParams.x * inverseDistance, 1.0);
}

float lightDistributionA2(GpuLight light, BrdfTerms t, float inverseDistance) {
  if (!kSceneHasVpls || !lightIs(light, kLightVpl)) return t.a2;
  float alpha = lightDistributionAlpha(light, t.alpha, inverseDistance);
  return alpha * alpha;
}

// How much of a light's intensity reaches a point `toLight` away from it (`distance` its length,
// `l` its direction): inverse square times the light's window (range sphere, spot cone or box).
float lightAttenuation(GpuLight light, vec3 toLight, vec3 l, float distance) {
  if (distance >= light.positionRange.w) return 0.0;
  float q;
  float window = lightWindow(light, toLight, l, distance, distance * distance, q);
  return window / max(q, 1e-4);
}

// lightAttenuation times the light's shadow at `position` (common/local_shadow.glsl), looked up only
// where the light reaches and the surface faces it (`normal` zero: a particle, which always does).
float shadowedAttenuation(GpuLight light, vec3 position, vec3 normal, vec3 toLight, vec3 l, float distance) {
  float attenuation = lightAttenuation(light, toLight, l, distance);
  if (kLocalShadows && attenuation > 0.0 && dot(normal, l) >= 0.0)
    attenuation *= localShadow(light, position, normal, l, distance);
  return attenuation;
}

// Radiance one light reflects from the surface towards the eye; `t` is brdfTerms(s), computed once
// per surface by the loops over lights.
vec3 evaluateLight(GpuLight light, Surface s, BrdfTerms t) {
  vec3 toLight = light.positionRange.xyz - s.position;
  float distanceSquared = dot(toLight, toLight);
  float range = light.positionRange.w;
  if (distanceSquared >= range * range) return vec3(0.0);
  float inverseDistance = inversesqrt(max(distanceSquared, 1e-12));
  float distance = distanceSquared * inverseDistance;
  vec3 l = toLight * inverseDistance;
  float nDotL = dot(s.normal, l);
  if (nDotL <= 0.0) return vec3(0.0);
  float q;
  float window = lightWindow(light, toLight, l, distance, distanceSquared, q);
  if (window <= 0.0) return vec3(0.0);
  if (kLocalShadows) window *= localShadow(light, s.position, s.normal, l, distance);
  vec3 w = brdfLobeWeights(s, t, l, nDotL, max(q, 1e-4), lightDistributionA2(light, t, inverseDistance),
                           light.colorIntensity.w * window);
  return light.colorIntensity.rgb * brdfOfWeights(t, w);
}

// The same radiance in its two lobes, added to `diffuse` and `specular` (the VPL filter scales only
// the diffuse by the albedo: gi/interleaved_vpls.glsl). evaluateLight's steps, kept apart so that the
// loop every shading pass runs stays exactly as it was measured.
void evaluateLightLobes(GpuLight light, Surface s, BrdfTerms t, inout vec3 diffuse, inout vec3 specular) {
  vec3 toLight = light.positionRange.xyz - s.position;
  float distanceSquared = dot(toLight, toLight);
  float range = light.positionRange.w;
  if (distanceSquared >= range * range) return;
  float inverseDistance = inversesqrt(max(distanceSquared, 1e-12));
  float distance = distanceSquared * inverseDistance;
  vec3 l = toLight * inverseDistance;
  float nDotL = dot(s.normal, l);
  if (nDotL <= 0.0) return;
  float q;
  float window = lightWindow(light, toLight, l, distance, distanceSquared, q);
  if (window <= 0.0) return;
  if (kLocalShadows) window *= localShadow(light, s.position, s.normal, l, distance);
  vec3 w = brdfLobeWeights(s, t, l, nDotL, max(q, 1e-4), lightDistributionA2(light, t, inverseDistance),
                           light.colorIntensity.w * window);
  diffuse += light.colorIntensity.rgb * (t.diffuse * w.x);
  specular += light.colorIntensity.rgb * (t.f0 * w.y + w.z);
}

vec3 evaluateLight(GpuLight light, Surface s) {
  return evaluateLight(light, s, brdfTerms(s));
}

#endif
