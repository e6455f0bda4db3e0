#version 460
// Blended surfaces (glass, smoke) for the techniques that light opaque surfaces from screen-space
// buffers, which hold one surface per pixel and so cannot light what lies over it.
// kDynamicLights false: ambient and emission only, the deferred renderer's unlit glass (the
// seeds' Figure 1.1); true: the separate forward pass engines add to fix it, every light per pixel.
#include "common/mesh_fragment.glsl"

layout(constant_id = 0) const bool kDynamicLights = true;

layout(location = 0) out vec4 outColor;

void main() {
  GpuMaterial m = materials[draw.ids.x];
  Surface s = surfaceAtFragment(m);
  vec3 color = ambientAndEmissive(s);
  if (kDynamicLights) {
    uint lightCount = frame.counts.x;
    for (uint i = 0; i < lightCount; ++i) color += evaluateLight(lights[i], s);
  }
  outColor = vec4(color * s.alpha, s.alpha);  // premultiplied, as BlendMode::Alpha expects
}
