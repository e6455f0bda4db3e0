#version 460
// The shadow casters' resolve (shadows/caster_resolve.glsl) into a buffer, for the copy into a D32
// atlas: where alpha-masked casters are drawn by the hardware over the compute depth.
layout(std430, set = 0, binding = 24) writeonly buffer DepthBlock {
  float depthOut[];
};

void shadowDepthOut(ivec2 texel, ivec2 size, float depth) {
  depthOut[uint(texel.y) * uint(size.x) + uint(texel.x)] = depth;
}

#include "shadows/caster_resolve.glsl"
