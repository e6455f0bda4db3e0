// HDR radiance to the display image: exposure, a filmic curve (Narkowicz's ACES fit), sRGB
// encoding, and the heatmap's legend. post/tonemap.comp applies it to the whole HDR image; the
// shading passes that write a frame's last colours apply it to their own pixels instead
// (render/lit_passes.h, kWritesDisplay), which spares the frame a pass. Needs `frame`.
#ifndef LLL_DISPLAY_GLSL
#define LLL_DISPLAY_GLSL
#include "common/debug_colors.glsl"
#include "common/finite.glsl"
#include "common/srgb.glsl"

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

// Radiance as the RGBA16F target holds it once stored: rounded to half floats, so that a pass that
// writes both images shows what post/tonemap.comp would have read back.
vec3 storedRadiance(vec3 c) {
  return vec3(unpackHalf2x16(packHalf2x16(c.xy)), unpackHalf2x16(packHalf2x16(vec2(c.z, 0.0))).x);
}

// The display colour of pixel p whose HDR target holds `hdr`.
// A highlight past fp16's range was stored as infinity: it shows as the brightest value (the curve
// would make Inf / Inf = NaN of it). A NaN stays a NaN: the tests look for those in the HDR image.
vec4 displayColor(ivec2 p, vec3 hdr) {
  hdr = finiteRadiance(hdr);
  vec3 display;
  if (frame.display.x == kDisplayDebug) {
    display = clamp(hdr, 0.0, 1.0);
    vec3 legend;
    if (heatmapLegend(p, legend)) display = legend;
  } else {
    display = filmic(max(hdr * frame.ambient.w, vec3(0.0)));
  }
  return vec4(srgbEncode(display), 1.0);
}

#ifdef LLL_DISPLAY_FROM_SHADING
// A shading pass that may write the frame's last colours (lit/shade_visibility, lit/shade_glass):
// with kWritesDisplay (render/lit_passes.h) it writes their display colours too, and the frame
// records no tonemap pass.
layout(constant_id = 60) const bool kWritesDisplay = false;
layout(set = 0, binding = 40, rgba8) uniform writeonly image2D displayImage;

void storeDisplay(ivec2 p, vec3 radiance) {
  if (kWritesDisplay) imageStore(displayImage, p, displayColor(p, storedRadiance(radiance)));
}
#endif

#endif
