#pragma once
// Image comparisons for the tests: a candidate against its reference (usually `forward`, the
// brute-force renderer) under a per-pixel bound, not PSNR alone: a light missing from one tile
// moves a few hundred pixels by a lot and the PSNR hardly at all. Differences are of 8-bit display
// values, per pixel the largest over R, G and B.
#include <cstddef>
#include <string>

#include "render/image_compare.h"
#include "renderer/renderer.h"

namespace lll::test {

struct ImageBound {
  double minPsnr = 45.0;
  int typical = 2;              // at least `typicalShare` of the pixels differ by at most this...
  double typicalShare = 0.999;  // ...
  int worst = 16;               // ...and none by more than this
};

// Same BRDF and lights, different order of summation, storage rounding (G-buffer, fp16 targets):
// the bound of the issue "trust on the GPU".
inline constexpr ImageBound kSameImage{};
// Smoke blends many translucent layers, each rounded to fp16 in the HDR target.
inline constexpr ImageBound kSmokeBound{40.0, 2, 0.999, 16};
// The light pre-pass is exact for non-metals; a metal's correction for its own f0 takes the colour
// of the Fresnel-weighted highlights (shaders/lighting/prepass_combine.frag), so pixels where
// differently coloured lights overlap on a coloured metal move: camp, all metal, at 1,024
// coloured lights: 14 of 255 at worst, 99.90% of pixels within 2 (lavapipe and H200).
inline constexpr ImageBound kPrepassBound{45.0, 2, 0.995, 24};
// The compute rasterizer against the hardware pass: where a snapped edge passes exactly through a
// pixel centre the two may give the pixel to different triangles (lavapipe rounds its viewport
// transform its own way): seen on lavapipe, 2 pixels of the atrium at 160x90 moved by 29 of 255,
// 1 of the 64x36 one by 47, the rest identical; on the H200 every image test passes unchanged.
inline constexpr ImageBound kRasterBound{45.0, 2, 0.999, 64};

// Compares and fails the current test where the candidate leaves `bound`; prints and records the
// numbers and appends them to the CSV file $LLL_TEST_IMAGE_REPORT when that is set (how the GPU
// results in tests/README.md were collected).
ImageDifference expectWithinBound(const LdrImage& candidate, const LdrImage& reference,
                                  const ImageBound& bound, const std::string& label);

// Peak signal-to-noise ratio of two 8-bit images over RGB, in dB (infinity when identical).
double psnr(const LdrImage& a, const LdrImage& b);

struct HdrSummary {
  size_t nonFinite = 0;        // pixels with a NaN or infinite channel (alpha included)
  double meanLuminance = 0.0;  // of the finite pixels
};
HdrSummary summarize(const HdrImage& image);

// Share of pixels whose displayed colour has a channel above 2 of 255 (so rounding is not light).
double shareAboveBlack(const LdrImage& image);

}  // namespace lll::test
