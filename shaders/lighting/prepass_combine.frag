#version 460
// Light pre-pass step 3: the scene again with its full material, result = C(material, sums).
// Diffuse is exact: (1 - F) = (1 - f0)(1 - w) per light, and the light pass summed E * (1 - w).
// Specular is f0 * sum(S) + (1 - f0) * sum(w * S); the buffers hold sum(S) in colour but
// sum(w * S) only as one number, so its colour is taken to be that of sum(S). That is the
// approximation, exact for a single light or lights of one colour: the seed's limit that "very
// limited range of materials can be factored in this way" without "extra storage" for them
// (the exact sum would need a third RGB sum). Taking F once per pixel at n.v instead,
// the classic light pre-pass shortcut, drops the atrium to ~31 dB against forward.
#extension GL_EXT_samplerless_texture_functions : require
#include "common/material.glsl"

layout(set = 0, binding = 3) uniform texture2D diffuseLight;
layout(set = 0, binding = 4) uniform texture2D specularLight;

layout(location = 0) in vec3 inWorldPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;
layout(location = 0) out vec4 outColor;

void main() {
  GpuMaterial m = materials[draw.ids.x];
  Surface s = sampleSurface(m, inWorldPosition, inNormal, inUv, gl_FrontFacing);
  if (m.flags.x == kAlphaMask && s.alpha < m.alpha.x) discard;
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec3 f0 = mix(vec3(0.04), s.baseColor, s.metallic);
  vec3 diffuseColor = mix(s.baseColor, vec3(0.0), s.metallic);
  vec4 lobes = texelFetch(specularLight, pixel, 0);
  float total = lobes.r + lobes.g + lobes.b;
  float fresnelWeight = total > 0.0 ? clamp(lobes.a / total, 0.0, 1.0) : 0.0;  // average w of the lobes
  vec3 diffuse = (1.0 - f0) * diffuseColor / kPi * texelFetch(diffuseLight, pixel, 0).rgb;
  vec3 specular = (f0 + (1.0 - f0) * fresnelWeight) * lobes.rgb;
  outColor = vec4(ambientAndEmissive(s) + diffuse + specular, 1.0);
}
