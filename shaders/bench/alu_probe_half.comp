#version 460
// A probe of 16-bit arithmetic (bench/alu_probe.h): alu_probe.comp's lights and surfaces, with
// each light's evaluation (common/brdf.glsl's evaluateLight for a point light: offset, distance,
// KHR window, the lobes, the colour) written in f16vec2, two lights a component, so that a
// device that pairs 16-bit operations evaluates two lights an instruction. Only its time means
// anything: half floats overflow where GGX's peak passes 65504 (alpha below 0.0022) and where the
// products below do, which this probe does not guard against; its image is not used.
#extension GL_EXT_shader_explicit_arithmetic_types_float16 : require
#define LLL_NO_LOCAL_SHADOWS
#include "common/brdf.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, rgba16f) uniform writeonly image2D probeTarget;
layout(push_constant) uniform ProbeBlock {
  uvec4 probe;  // x lights, y width, z height
};

// alu_probe.comp's light `i`: position (w range) and colour (w intensity).
void probeLight(uint i, out vec4 positionRange, out vec4 colorIntensity) {
  float t = float(i);
  positionRange = vec4(fract(t * 0.618034) * 20.0 - 10.0, 1.0 + fract(t * 0.414214) * 4.0,
                       fract(t * 0.732051) * 20.0 - 10.0, 1.0e4);
  colorIntensity = vec4(fract(t * 0.25) + 0.25, fract(t * 0.5) + 0.25, 0.75, 50.0);
}

void main() {
  uvec2 pixel = gl_GlobalInvocationID.xy;
  if (pixel.x >= probe.y || pixel.y >= probe.z) return;
  vec2 uv = (vec2(pixel) + 0.5) / vec2(probe.yz);
  Surface s;
  s.position = vec3(uv.x * 20.0 - 10.0, 0.0, uv.y * 20.0 - 10.0);
  s.normal = normalize(vec3(uv.x - 0.5, 1.0, uv.y - 0.5));
  s.view = normalize(vec3(0.0, 6.0, 12.0) - s.position);
  s.baseColor = vec3(0.3 + 0.6 * uv.x, 0.6, 0.3 + 0.5 * uv.y);
  s.alpha = 1.0;
  s.metallic = uv.y;
  s.roughness = 0.15 + 0.7 * uv.x;
  s.occlusion = 1.0;
  s.emissive = vec3(0.0);
  BrdfTerms terms = brdfTerms(s);
  // The surface's terms in both halves.
  f16vec2 px = f16vec2(s.position.x), py = f16vec2(s.position.y), pz = f16vec2(s.position.z);
  f16vec2 nx = f16vec2(s.normal.x), ny = f16vec2(s.normal.y), nz = f16vec2(s.normal.z);
  f16vec2 vx = f16vec2(s.view.x), vy = f16vec2(s.view.y), vz = f16vec2(s.view.z);
  f16vec2 nDotVSigned = f16vec2(terms.nDotVSigned), nDotV = f16vec2(terms.nDotV);
  f16vec2 a2 = f16vec2(terms.a2), smithV = f16vec2(terms.smithV);
  f16vec2 oneMinusA2 = f16vec2(1.0 - terms.a2), a2MinusOne = f16vec2(terms.a2 - 1.0);
  f16vec2 specularScale = f16vec2(terms.a2 * (0.5 / kPi));
  f16vec3 diffuse = f16vec3(terms.diffuse), f0 = f16vec3(terms.f0);
  f16vec2 sumR = f16vec2(0.0), sumG = f16vec2(0.0), sumB = f16vec2(0.0);
  for (uint i = 0u; i + 1u < probe.x; i += 2u) {
    vec4 p0, c0, p1, c1;
    probeLight(i, p0, c0);
    probeLight(i + 1u, p1, c1);
    f16vec2 tx = f16vec2(p0.x, p1.x) - px, ty = f16vec2(p0.y, p1.y) - py, tz = f16vec2(p0.z, p1.z) - pz;
    f16vec2 d2 = tx * tx + ty * ty + tz * tz;
    f16vec2 inverseRange2 = f16vec2(1.0 / (p0.w * p0.w), 1.0 / (p1.w * p1.w));
    f16vec2 inverseDistance = inversesqrt(max(d2, f16vec2(1e-4)));
    f16vec2 lx = tx * inverseDistance, ly = ty * inverseDistance, lz = tz * inverseDistance;
    f16vec2 nDotL = nx * lx + ny * ly + nz * lz;
    f16vec2 ratio2 = d2 * inverseRange2;
    f16vec2 window = clamp(f16vec2(1.0) - ratio2 * ratio2, f16vec2(0.0), f16vec2(1.0));
    window *= window;
    // Zero where the light is behind the surface or out of range (the 32-bit loop branches).
    window *= f16vec2(greaterThan(nDotL, f16vec2(0.0)));
    f16vec2 q = max(d2, f16vec2(1e-4));
    f16vec2 scale = f16vec2(c0.w, c1.w) * window;
    f16vec2 lDotV = lx * vx + ly * vy + lz * vz;
    f16vec2 inverseLength = inversesqrt(max(f16vec2(2.0) + f16vec2(2.0) * lDotV, f16vec2(1e-4)));
    f16vec2 nDotH = max((nDotL + nDotVSigned) * inverseLength, f16vec2(0.0));
    f16vec2 vDotH = clamp((f16vec2(1.0) + lDotV) * inverseLength, f16vec2(0.0), f16vec2(1.0));
    f16vec2 m = f16vec2(1.0) - vDotH, m2 = m * m, schlick = m2 * m2 * m;
    f16vec2 dd = nDotH * nDotH * a2MinusOne + f16vec2(1.0);
    f16vec2 nDotLClamped = max(nDotL, f16vec2(0.0));
    f16vec2 sum = nDotLClamped * smithV + nDotV * sqrt(nDotLClamped * nDotLClamped * oneMinusA2 + a2);
    f16vec2 pp = dd * dd * sum;
    f16vec2 r = scale * nDotLClamped / (q * pp);
    f16vec2 specular = specularScale * r;
    f16vec2 specularSchlick = specular * schlick;
    f16vec2 wx = f16vec2(1.0 - kDielectricF0) * (f16vec2(1.0) - schlick) * (pp * r);
    f16vec2 wy = specular - specularSchlick;
    sumR += f16vec2(c0.r, c1.r) * (diffuse.r * wx + (f0.r * wy + specularSchlick));
    sumG += f16vec2(c0.g, c1.g) * (diffuse.g * wx + (f0.g * wy + specularSchlick));
    sumB += f16vec2(c0.b, c1.b) * (diffuse.b * wx + (f0.b * wy + specularSchlick));
  }
  vec3 sum =
      vec3(float(sumR.x) + float(sumR.y), float(sumG.x) + float(sumG.y), float(sumB.x) + float(sumB.y));
  imageStore(probeTarget, ivec2(pixel), vec4(sum, 1.0));
}
