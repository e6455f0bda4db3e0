#version 460
// HDR to display (post/display.glsl), for frames whose last shading pass does not write the display
// image itself (render/lit_passes.h).
#include "shared/gpu_types.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(std430, set = 0, binding = 0) readonly buffer FrameBlock {  // see common/frame.glsl
  FrameUniforms frame;
};
layout(set = 0, binding = 1, rgba16f) uniform readonly image2D hdrImage;
layout(set = 0, binding = 2, rgba8) uniform writeonly image2D ldrImage;

#include "post/display.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (p.x >= int(frame.viewport.x) || p.y >= int(frame.viewport.y)) return;
  imageStore(ldrImage, p, displayColor(p, imageLoad(hdrImage, p).rgb));
}
