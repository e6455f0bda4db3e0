// particles-light (--particle-lighting vertex): the light each visible particle receives at its
// centre from the technique's lights, with the normal facing the camera, once per particle instead
// of once per pixel. A lighting interface that picks lights by pixel (lll's tile lists) gets the
// pixel under the centre (clamped onto the screen) and the centre's depth: a particle whose centre
// is off-screen or hidden takes that tile's lights.
#define PARTICLE_WRITES_RADIANCE
#include "particles/scatter_lights.glsl"

layout(local_size_x = 64) in;

void main() {
  uint order = gl_GlobalInvocationID.x;
  if (order >= particleCounters.dispatch.w) return;
  vec3 center = particles[drawOrder[order].y].positionAge.xyz;
  vec3 towardEye = normalize(frame.cameraPosition.xyz - center);
  vec4 clip = frame.viewProj * vec4(center, 1.0);
  float depth = max(clip.w, frame.depthParams.x);  // w is the view depth
  vec2 pixel = clamp((clip.xy / depth * 0.5 + 0.5) * frame.viewport.xy, vec2(0.0), frame.viewport.xy - 1.0);
  particleRadiance[order] = vec4(scatterLights(center, cameraBack(), towardEye, uvec2(pixel), depth), 0.0);
}
