#version 460
// common/gbuffer_visibility.glsl with the texture table indexed uniformly across each workgroup.
#include "common/gbuffer_visibility.glsl"
