#version 460
// G-buffer pass (src/render/gbuffer.h): what the BRDF needs, once per visible pixel (depth EQUAL
// the prepass). Ambient and emission need no light, so they go straight into the accumulation
// target, as Infinity's forward-lit "FL" channels do; the G-buffer keeps only what lighting reads.
// Layout and decoding: common/gbuffer.glsl.
#include "common/gbuffer.glsl"
#include "common/mesh_fragment.glsl"

// False for deferred, which lights the sun in a pass of its own, as Infinity did
// (lighting/deferred_sun.comp): then the accumulation starts with ambient and emission alone.
layout(constant_id = 40) const bool kSunInAccumulation = true;

layout(location = 0) out vec4 outAccumulation;
layout(location = 1) out vec4 outGbuffer0;
layout(location = 2) out vec4 outGbuffer1;

void main() {
  GpuMaterial m = materials[draw.ids.x];
  Surface s = surfaceAtFragment(m);
  if (m.flags.x == kAlphaMask && s.alpha < m.alpha.x) discard;
  outAccumulation = vec4(kSunInAccumulation ? unlistedLight(s) : ambientAndEmission(s), 1.0);
  outGbuffer0 = gbuffer0Of(s);
  outGbuffer1 = gbuffer1Of(s);
}
