#pragma once
// How far one displayed image is from another (a technique's frame from forward's): per pixel the
// largest difference over R, G and B of the 8-bit values, summarized. The tests bound it
// (tests/image_compare.h); `lll bench` records it beside every timing.
#include <cstddef>

#include "render/images.h"

namespace lll {

struct ImageDifference {
  double psnr = 0.0;          // over RGB, in dB; infinity when identical
  int worst = 0;              // largest difference of any pixel
  int p999 = 0;               // 99.9th percentile of the per-pixel differences
  double typicalShare = 0.0;  // share of pixels within `typical` (compareImages' argument)
  size_t worstX = 0, worstY = 0;
  size_t pixels = 0;
};

// Throws std::invalid_argument when the two images differ in size.
ImageDifference compareImages(const LdrImage& candidate, const LdrImage& reference, int typical = 2);

// Relative RMS difference over RGB of two radiance images compared as means of `block` x `block`
// pixels (partial blocks at the right and bottom edges left out): against a noisy reference (the
// path tracer's) the block averages its per-pixel noise down, while an approximation's error
// (instant radiosity's) varies slowly across the image. Throws std::invalid_argument when the
// images differ in size or no block fits.
double relativeBlockError(const HdrImage& candidate, const HdrImage& reference, uint32_t block);

}  // namespace lll
