#include "image_bound.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <vector>

#include "render/image_io.h"
#include "test_support.h"

namespace lll::test {

namespace {

void appendToReport(const std::string& label, const ImageDifference& d, const ImageBound& bound) {
  const char* path = std::getenv("LLL_TEST_IMAGE_REPORT");
  if (path == nullptr || *path == '\0') return;
  const bool fresh = !std::ifstream(path).good();
  std::ofstream out(path, std::ios::app);
  if (fresh) out << "test,label,device,psnr_db,p999,max,share_within_typical,bound_typical,bound_worst\n";
  const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
  char line[512];
  std::string name = label, device = gpuContext().info().name;  // one CSV field each
  std::replace(name.begin(), name.end(), ',', ';');
  std::replace(device.begin(), device.end(), ',', ';');
  std::snprintf(line, sizeof(line), "%s.%s,%s,%s,%.2f,%d,%d,%.5f,%d,%d\n",
                test ? test->test_suite_name() : "", test ? test->name() : "", name.c_str(), device.c_str(),
                d.psnr, d.p999, d.worst, d.typicalShare, bound.typical, bound.worst);
  out << line;
}

// With $LLL_TEST_IMAGE_DIR set, a comparison that fails leaves the candidate, the reference and
// their difference (x 16) there as PNGs, named after the label, to look at.
void dumpImages(const std::string& label, const LdrImage& candidate, const LdrImage& reference) {
  const char* dir = std::getenv("LLL_TEST_IMAGE_DIR");
  if (dir == nullptr || *dir == '\0') return;
  std::string name = label;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '-';
  LdrImage diff = candidate;
  for (size_t i = 0; i < diff.rgba.size(); ++i)
    diff.rgba[i] =
        i % 4 == 3 ? 255
                   : uint8_t(std::min(255, 16 * std::abs(int(candidate.rgba[i]) - int(reference.rgba[i]))));
  std::filesystem::create_directories(dir);
  writePng(std::filesystem::path(dir) / (name + "-candidate.png"), candidate);
  writePng(std::filesystem::path(dir) / (name + "-reference.png"), reference);
  writePng(std::filesystem::path(dir) / (name + "-difference.png"), diff);
}

}  // namespace

ImageDifference expectWithinBound(const LdrImage& candidate, const LdrImage& reference,
                                  const ImageBound& bound, const std::string& label) {
  EXPECT_EQ(candidate.width, reference.width) << label;
  EXPECT_EQ(candidate.height, reference.height) << label;
  const ImageDifference d = compareImages(candidate, reference, bound.typical);
  std::printf("[ image    ] %s: %.2f dB, 99.9th percentile %d, max %d at (%zu, %zu), %.3f%% within %d\n",
              label.c_str(), d.psnr, d.p999, d.worst, d.worstX, d.worstY, 100.0 * d.typicalShare,
              bound.typical);
  ::testing::Test::RecordProperty(label + " psnr", std::to_string(d.psnr));
  ::testing::Test::RecordProperty(label + " max", std::to_string(d.worst));
  appendToReport(label, d, bound);
  if (d.psnr < bound.minPsnr || d.typicalShare < bound.typicalShare || d.worst > bound.worst)
    dumpImages(label, candidate, reference);
  EXPECT_GE(d.psnr, bound.minPsnr) << label;
  EXPECT_GE(d.typicalShare, bound.typicalShare)
      << label << ": too many pixels differ by more than " << bound.typical << " of 255";
  EXPECT_LE(d.worst, bound.worst) << label << ": pixel (" << d.worstX << ", " << d.worstY << ")";
  return d;
}

double psnr(const LdrImage& a, const LdrImage& b) {
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  return compareImages(a, b).psnr;
}

HdrSummary summarize(const HdrImage& image) {
  HdrSummary s;
  const size_t pixels = size_t(image.width) * image.height;
  double luminance = 0.0;
  for (size_t i = 0; i < pixels && i * 4 + 3 < image.rgba.size(); ++i) {
    const float* p = &image.rgba[i * 4];
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]) || !std::isfinite(p[3])) {
      ++s.nonFinite;
      continue;
    }
    luminance += 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
  }
  s.meanLuminance = luminance / double(std::max<size_t>(pixels, 1));
  return s;
}

double shareAboveBlack(const LdrImage& image) {
  const size_t pixels = image.rgba.size() / 4;
  size_t lit = 0;
  for (size_t i = 0; i < pixels; ++i) {
    const uint8_t* p = &image.rgba[i * 4];
    if (std::max({p[0], p[1], p[2]}) > 2) ++lit;
  }
  return double(lit) / double(std::max<size_t>(pixels, 1));
}

}  // namespace lll::test
