#version 460
// The bench's ALU roofline probe (bench/alu_probe.h): per pixel, the same light evaluation as the
// shading passes (common/brdf.glsl's evaluateLight, with the scene's light types compiled in or
// out the same way) for `lights` point lights that all reach it, with no list to walk and no light
// or surface read from memory: the surface comes from the pixel's position and each light from its
// index in a few multiply-adds. One store per pixel keeps the work from being optimized away.
// Shadow lookups are memory reads, not arithmetic: the probe leaves them out.
#define LLL_NO_LOCAL_SHADOWS
#include "common/brdf.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, rgba16f) uniform writeonly image2D probeTarget;
layout(push_constant) uniform ProbeBlock {
  uvec4 probe;  // x lights, y width, z height
};

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
  vec3 sum = vec3(0.0);
  BrdfTerms terms = brdfTerms(s);
  for (uint i = 0u; i < probe.x; ++i) {
    float t = float(i);
    GpuLight light;
    light.positionRange = vec4(fract(t * 0.618034) * 20.0 - 10.0, 1.0 + fract(t * 0.414214) * 4.0,
                               fract(t * 0.732051) * 20.0 - 10.0, 1.0e4);
    light.colorIntensity = vec4(fract(t * 0.25) + 0.25, fract(t * 0.5) + 0.25, 0.75, 50.0);
    light.directionType = vec4(0.0, -1.0, 0.0, float(kLightPoint));
    light.spotParams = vec4(-1.0, -0.5, 1.0, 0.0);
    sum += evaluateLight(light, s, terms);
  }
  imageStore(probeTarget, ivec2(pixel), vec4(sum, 1.0));
}
