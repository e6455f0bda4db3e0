// Building a glTF surface from a material and its texture samples, wherever they were sampled:
// in a mesh pass's fragment shader (common/material.glsl, implicit derivatives) or in a compute
// pass rebuilding the surface from the visibility buffer (common/visibility_surface.glsl, explicit
// gradients). Normal mapping uses the file's tangent frame (glTF's TANGENT) or, where the mesh has
// none, a frame built from the surface's screen-space derivatives.
#ifndef LLL_MATERIAL_SURFACE_GLSL
#define LLL_MATERIAL_SURFACE_GLSL
#include "common/brdf.glsl"
#include "common/frame.glsl"
#include "common/sun_shadow.glsl"
#include "common/texture_transform.glsl"

// Screen-space derivatives of the surface at a pixel (position and texture coordinates, per pixel
// right and down).
struct SurfaceDerivatives {
  vec3 dpx, dpy;
  vec2 duvx, duvy;
};

// The tangent frame where the file gives none: T along grad(u) and B along -grad(v) in the plane of
// n (glTF's bitangent: texture v runs down the image, the normal map's green up). grad(u) solves
// dot(g, dp/dx) = du/dx, dot(g, dp/dy) = du/dy; the cross products below give it times the
// determinant n . (dp/dx x dp/dy), whose sign depends on which way the framebuffer's y points
// (down in Vulkan with lll's projection), so it is divided out. T and B keep their relative
// lengths (a cotangent frame); the caller normalizes the result. False where the UVs do not vary
// across the pixel.
bool derivativeTangentFrame(vec3 n, SurfaceDerivatives d, out vec3 t, out vec3 b) {
  vec3 dpyPerp = cross(d.dpy, n), dpxPerp = cross(n, d.dpx);
  vec3 gradU = dpyPerp * d.duvx.x + dpxPerp * d.duvy.x;
  vec3 gradV = dpyPerp * d.duvx.y + dpxPerp * d.duvy.y;
  float determinantSign = dot(d.dpx, dpyPerp) < 0.0 ? -1.0 : 1.0;
  float scale = max(dot(gradU, gradU), dot(gradV, gradV));
  t = vec3(0.0);
  b = vec3(0.0);
  if (!(scale > 1e-20)) return false;
  float unit = determinantSign * inversesqrt(scale);
  t = gradU * unit;
  b = -gradV * unit;
  return true;
}

// The shading normal for a surface whose front-facing interpolated normal is `n`, given the normal
// map's texel (`mapped`, 0..1). `tangent` is glTF's (w = 0 when the mesh has none).
vec3 perturbNormal(GpuMaterial m, vec3 n, vec3 mapped, vec4 tangent, SurfaceDerivatives d) {
  // No normal map: the default 1x1 texel (128, 128, 255) would decode to (1/255, 1/255, 1), a
  // 0.32 degree tilt of every surface.
  if ((m.flags.z & kMaterialNormalTexture) == 0u) return n;
  vec3 t, b;
  if (tangent.w != 0.0 && dot(tangent.xyz, tangent.xyz) > 0.0) {
    t = normalize(tangent.xyz - n * dot(n, tangent.xyz));  // interpolation bends it off the plane
    b = cross(n, t) * (tangent.w < 0.0 ? -1.0 : 1.0);
  } else if (!derivativeTangentFrame(n, d, t, b)) {
    return n;  // no UV variation: keep the geometric normal
  }
  vec3 tangentNormal = mapped * 2.0 - 1.0;
  tangentNormal.xy *= m.params.z;
  return normalize(mat3(t, b, n) * tangentNormal);
}

// A material's texels at a surface point, sampled by the caller.
struct MaterialSamples {
  vec4 baseColor;
  vec4 metallicRoughness;
  vec3 normal;  // the normal map's texel, 0..1
  vec3 emissive;
  float occlusion;
};

Surface assembleSurface(GpuMaterial m, MaterialSamples t, vec3 position, vec3 normal, vec4 tangent,
                        SurfaceDerivatives d, bool frontFacing) {
  Surface s;
  s.position = position;
  s.view = normalize(frame.cameraPosition.xyz - position);
  // A back face (double-sided material) turns its whole tangent frame: its normal is the front's
  // perturbed normal reversed.
  s.normal = perturbNormal(m, normalize(normal), t.normal, tangent, d);
  if (!frontFacing) s.normal = -s.normal;
  vec4 base = m.baseColorFactor * t.baseColor;
  s.baseColor = base.rgb;
  s.alpha = base.a;
  s.roughness = clamp(m.params.y * t.metallicRoughness.g, 0.0, 1.0);
  s.metallic = clamp(m.params.x * t.metallicRoughness.b, 0.0, 1.0);
  s.occlusion = 1.0 + m.params.w * (t.occlusion - 1.0);
  s.emissive = m.emissive.rgb * t.emissive;
  return s;
}

// What needs no light: emission and a small constant ambient.
vec3 ambientAndEmission(Surface s) {
  return frame.ambient.rgb * s.baseColor * s.occlusion + s.emissive;
}

// The directional lights (the sun), which reach every pixel and so never enter a light list. The
// first casts the shadow; `sunVisible` is how much of it reaches the surface.
vec3 directionalLight(Surface s, float sunVisible) {
  vec3 sum = vec3(0.0);
  for (uint i = 0u; i < frame.display.z; ++i)
    sum +=
        brdfCosine(s, frame.sunDirection[i].xyz) * frame.sunIlluminance[i].rgb * (i == 0u ? sunVisible : 1.0);
  return sum;
}

// What every technique adds besides its listed lights: emission, a small constant ambient and the
// directional lights.
vec3 unlistedLightWith(Surface s, float sunVisible) {
  return ambientAndEmission(s) + directionalLight(s, sunVisible);
}

// As above, the sun's shadow looked up in its cascades (common/sun_shadow.glsl).
vec3 unlistedLight(Surface s) {
  return unlistedLightWith(s, sunVisibleAt(s.position, s.normal));
}

#endif
