#include "render/image_compare.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace lll {

ImageDifference compareImages(const LdrImage& candidate, const LdrImage& reference, int typical) {
  if (candidate.width != reference.width || candidate.height != reference.height ||
      candidate.rgba.size() != reference.rgba.size())
    throw std::invalid_argument("compareImages: the images differ in size");
  ImageDifference d;
  const size_t pixels = candidate.rgba.size() / 4;
  std::vector<int> perPixel(pixels);
  double squares = 0.0;
  size_t within = 0;
  for (size_t i = 0; i < pixels; ++i) {
    int largest = 0;
    for (size_t c = 0; c < 3; ++c) {
      const int diff = std::abs(int(candidate.rgba[i * 4 + c]) - int(reference.rgba[i * 4 + c]));
      squares += double(diff) * diff;
      largest = std::max(largest, diff);
    }
    perPixel[i] = largest;
    if (largest <= typical) ++within;
    if (largest > d.worst) {
      d.worst = largest;
      d.worstX = i % std::max(candidate.width, 1u);
      d.worstY = i / std::max(candidate.width, 1u);
    }
  }
  d.pixels = pixels;
  const double mse = squares / double(std::max<size_t>(pixels * 3, 1));
  d.psnr = mse == 0.0 ? INFINITY : 10.0 * std::log10(255.0 * 255.0 / mse);
  d.typicalShare = double(within) / double(std::max<size_t>(pixels, 1));
  if (pixels > 0) {
    const size_t rank = std::min(pixels - 1, size_t(std::ceil(0.999 * double(pixels))) - 1);
    std::nth_element(perPixel.begin(), perPixel.begin() + long(rank), perPixel.end());
    d.p999 = perPixel[rank];
  }
  return d;
}

double relativeBlockError(const HdrImage& candidate, const HdrImage& reference, uint32_t block) {
  if (candidate.width != reference.width || candidate.height != reference.height)
    throw std::invalid_argument("relativeBlockError: the images differ in size");
  if (block == 0 || block > reference.width || block > reference.height)
    throw std::invalid_argument("relativeBlockError: no block fits in the image");
  double difference = 0.0, magnitude = 0.0;
  for (uint32_t by = 0; by + block <= reference.height; by += block) {
    for (uint32_t bx = 0; bx + block <= reference.width; bx += block) {
      glm::dvec3 got(0.0), want(0.0);
      for (uint32_t y = by; y < by + block; ++y) {
        for (uint32_t x = bx; x < bx + block; ++x) {
          got += glm::dvec3(glm::vec3(candidate.at(x, y)));
          want += glm::dvec3(glm::vec3(reference.at(x, y)));
        }
      }
      difference += glm::dot(got - want, got - want);
      magnitude += glm::dot(want, want);
    }
  }
  return magnitude > 0.0 ? std::sqrt(difference / magnitude) : 0.0;
}

}  // namespace lll
