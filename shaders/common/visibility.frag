#version 460
// The visibility pass's pixel id: the surface record shifted over the triangle bits, or'ed with the
// triangle (gl_PrimitiveID counts the draw's triangles from 0 for each instance).
layout(constant_id = 20) const uint kTriangleBits = 16u;

layout(location = 0) flat in uint inRecord;
layout(location = 0) out uint outId;

void main() {
  outId = (inRecord << kTriangleBits) | uint(gl_PrimitiveID);
}
