// particles-light (--particle-lighting vertex): the light each visible particle receives at its
// centre, with the normal facing the camera, once per particle instead of once per pixel. The
// light-list variant walks the list of the tile under the centre (clamped onto the screen) at the
// centre's depth: a particle whose centre is off-screen or hidden takes that tile's lights.
#define PARTICLE_WRITES_RADIANCE
#include "particles/scattering.glsl"

layout(local_size_x = 64) in;

void main() {
  uint order = gl_GlobalInvocationID.x;
  if (order >= particleCounters.dispatch.w) return;
  vec3 center = particles[drawOrder[order].y].positionAge.xyz;
  vec3 towardEye = normalize(frame.cameraPosition.xyz - center);
#ifdef PARTICLE_LIGHT_LIST
  vec4 clip = frame.viewProj * vec4(center, 1.0);
  float depth = max(clip.w, frame.depthParams.x);  // w is the view depth
  vec2 pixel = clamp((clip.xy / depth * 0.5 + 0.5) * frame.viewport.xy, vec2(0.0), frame.viewport.xy - 1.0);
  vec3 light = scatterFromLightList(center, cameraBack(), towardEye, tileIndexOf(uvec2(pixel)), depth);
#else
  vec3 light = scatterAllLights(center, cameraBack(), towardEye);
#endif
  particleRadiance[order] = vec4(light, 0.0);
}
