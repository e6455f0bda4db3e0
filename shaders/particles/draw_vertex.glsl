// The particle draw's vertex shader: vertices 6i to 6i + 5 are the i-th visible particle back to
// front (the sorted draw order), two triangles of a quad facing the camera, turned by the
// particle's rotation. One instance of 6 x visible vertices rather than an instance per particle:
// six-vertex instances leave most of a GPU's vertex batch empty. What does not vary across the quad (colour,
// opacity, emission, and with vertex lighting the lit radiance) is computed here once per vertex and passed
// flat.
#include "particles/puff.glsl"

layout(location = 0) out vec3 outWorldPosition;
layout(location = 1) out vec2 outOffset;   // on the quad along the camera's right/up, radius 1
layout(location = 2) out vec2 outPattern;  // the puff's noise coordinates, turning with the particle
layout(location = 3) flat out vec4 outAlbedoOpacity;
// rgb: radiance not from this pass's lights (ambient + emission; with vertex lighting all of it)
layout(location = 4) flat out vec3 outBaseRadiance;
layout(location = 5) flat out uint outOrder;  // in the draw order (--particle-lighting atlas)

const vec2 kCorners[6] = vec2[](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(1.0, 1.0), vec2(-1.0, -1.0),
                                vec2(1.0, 1.0), vec2(-1.0, 1.0));

void main() {
  uint order = uint(gl_VertexIndex) / 6u;
  uint slot = drawOrder[order].y;
  Particle p = particles[slot];
#ifdef PARTICLE_VERTEX_LIGHTING
  PuffLook look = puffLook(p, slot, particleRadiance[order].rgb);
#else
  PuffLook look = puffLook(p, slot, vec3(0.0));
#endif
  vec2 corner = kCorners[uint(gl_VertexIndex) % 6u];
  float c = cos(p.attributes.y), s = sin(p.attributes.y);
  vec2 offset = vec2(c * corner.x - s * corner.y, s * corner.x + c * corner.y);
  vec3 world = p.positionAge.xyz + (cameraRight() * offset.x + cameraUp() * offset.y) * look.radius;
  outWorldPosition = world;
  outOffset = offset;
  outPattern = corner * 1.5 + look.patternSeed;
  outAlbedoOpacity = look.albedoOpacity;
  outBaseRadiance = look.baseRadiance;
  outOrder = order;
  gl_Position = frame.viewProj * vec4(world, 1.0);
}
