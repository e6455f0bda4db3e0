#version 460
#define LLL_FILL_PASS
// Light shells for the raster fills: a coarse sphere or cone mesh that contains the light's exact
// volume (a box light is its own exact shell), grown by the tile inflation, drawn into the tile grid (one
// fragment per tile centre).
#include "lighting/lll/light_shape.glsl"

layout(location = 0) in vec3 inPosition;
layout(std430, set = 0, binding = 10) readonly buffer ShellOrderBlock {
  uint shellLights[];
};
layout(push_constant) uniform FillBlock {
  FillPush fill;
};
// 0: sphere shell, 1: cone shell, 2: box (lighting/light_volumes.h).
layout(constant_id = 0) const uint kShape = 0u;

layout(location = 0) flat out uint outLight;
layout(location = 1) flat out uint outBatchId;
layout(location = 2) out float outDepth;

void main() {
  uint lightIndex = shellLights[gl_InstanceIndex];
  GpuLight light = lights[lightIndex];
  vec3 center = light.positionRange.xyz;
  float range = light.positionRange.w;
  float inflation = tileInflation(toViewDepthSpace(center).z, range);
  vec3 world;
  if (kShape == 0u) {
    world = center + inPosition * (range + inflation);
  } else if (kShape == 2u) {
    // The unit cube onto the box, each half extent grown by the inflation; (x, y, cross(x, y)) is
    // right-handed, so the mesh keeps its winding.
    vec3 x, y, z;
    boxHalfAxes(light, x, y, z);
    float hx = length(x), hy = length(y), hz = length(z);
    world = center + (x / hx) * (inPosition.x * (hx + inflation)) +
            (y / hy) * (inPosition.y * (hy + inflation)) + (z / hz) * (inPosition.z * (hz + inflation));
  } else {
    // Moving the apex back by inflation / sin(angle) widens the cone by `inflation` everywhere.
    vec3 axis = light.directionType.xyz;
    float cosAngle = light.spotParams.x;
    float sinAngle = sqrt(max(1.0 - cosAngle * cosAngle, 1e-6));
    float back = inflation / sinAngle;
    float len = range + inflation + back;
    vec3 side = normalize(abs(axis.y) < 0.99 ? cross(axis, vec3(0, 1, 0)) : cross(axis, vec3(1, 0, 0)));
    vec3 up = cross(axis, side);  // (side, up, axis) right-handed: the mesh keeps its winding
    float radius = len * sinAngle / cosAngle;
    world = center - axis * back + (side * inPosition.x + up * inPosition.y) * radius +
            axis * (inPosition.z * len);
  }
  vec4 clip = frame.viewProj * vec4(world, 1.0);
  outDepth = clip.w;
  outLight = lightIndex;
  outBatchId = uint(gl_InstanceIndex) - fill.range.x;
  // No far plane (z = near: ndc depth near / w), so lights reaching past the scene are never cut;
  // the near plane still clips, which the back faces detect (Bezrati 1.3.2).
  clip.z = frame.depthParams.x;
  clip.xy = (clip.xy + clip.ww) * lll.grid.xy - clip.ww;
  gl_Position = clip;
}
