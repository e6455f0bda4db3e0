#version 460
// HDR to display: exposure, a filmic curve (Narkowicz's ACES fit), sRGB encoding.
#include "common/debug_colors.glsl"
#include "common/finite.glsl"
#include "common/srgb.glsl"
#include "shared/gpu_types.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(std430, set = 0, binding = 0) readonly buffer FrameBlock {  // see common/frame.glsl
  FrameUniforms frame;
};
layout(set = 0, binding = 1, rgba16f) uniform readonly image2D hdrImage;
layout(set = 0, binding = 2, rgba8) uniform writeonly image2D ldrImage;

// The curve tends to 2.51 / 2.43 (clamped to 1), but at infinity it is inf / inf: a light close to
// a surface can overflow the half-float target, so x is held to the largest half first.
vec3 filmic(vec3 x) {
  x = min(x, vec3(65504.0));
  return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

// The heatmap's legend, bottom left: one 8-pixel cell per light count from 1 to the scale (red),
// separated by dark ticks, so counts can be read off by counting cells.
bool heatmapLegend(ivec2 p, out vec3 color) {
  color = vec3(0.0);
  int scale = int(frame.display.y);
  int x = p.x - 8, y = int(frame.viewport.y) - 1 - p.y - 8;
  if (scale == 0 || x < 0 || y < 0 || y >= 12 || x >= scale * 8) return false;
  color = x % 8 == 7 ? vec3(0.05) : heat(float(x / 8 + 1) / float(scale));
  return true;
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (p.x >= int(frame.viewport.x) || p.y >= int(frame.viewport.y)) return;
  // A highlight past fp16's range was stored as infinity: show it as the brightest value (the curve
  // would make Inf / Inf = NaN of it). A NaN stays a NaN: the tests look for those in the HDR image.
  vec3 hdr = finiteRadiance(imageLoad(hdrImage, p).rgb);
  vec3 display;
  if (frame.display.x == kDisplayDebug) {
    display = clamp(hdr, 0.0, 1.0);
    vec3 legend;
    if (heatmapLegend(p, legend)) display = legend;
  } else {
    display = filmic(max(hdr * frame.ambient.w, vec3(0.0)));
  }
  imageStore(ldrImage, p, vec4(srgbEncode(display), 1.0));
}
