#pragma once
// The --stats JSON: what ran (device, driver, resolution, lights, technique, commit) and how long
// each pass took on the GPU, as median/min/max over the frames rendered.
#include <filesystem>
#include <string>
#include <vector>

#include "gpu/context.h"
#include "render/frame.h"

namespace lll {

struct PassSummary {
  std::string name;
  double medianMs = 0.0;
  double minMs = 0.0;
  double maxMs = 0.0;
};

// The median of `values` (the mean of the two middle ones for an even count); 0 for none.
double median(std::vector<double> values);

// Median/min/max of each pass over frames; passes keep the order of the first frame.
std::vector<PassSummary> summarizePasses(const std::vector<FrameResult>& frames);

struct RunInfo {
  std::string scene;
  std::string technique;
  uint32_t width = 0;
  uint32_t height = 0;
  uint64_t lightCount = 0;
  uint64_t triangleCount = 0;
  std::string camera;
};

std::string gitCommit();
std::string isoDate();

void writeStatsJson(const std::filesystem::path& path, const Context& context, const RunInfo& run,
                    const std::vector<FrameResult>& frames,
                    const std::vector<std::pair<std::string, double>>& extra);

}  // namespace lll
