#include "render/stats.h"

#include <fmt/format.h>

#include <algorithm>
#include <ctime>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "core/errors.h"
#include "git_commit.h"

namespace lll {

std::string gitCommit() {
  return LLL_GIT_COMMIT;
}

std::string isoDate() {
  const std::time_t now = std::time(nullptr);
  char buffer[32];
  std::strftime(buffer, sizeof(buffer), "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  return buffer;
}

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

std::vector<PassSummary> summarizePasses(const std::vector<FrameResult>& frames) {
  std::vector<std::string> order;
  std::map<std::string, std::vector<double>> samples;
  for (const FrameResult& frame : frames) {
    for (const PassTime& pass : frame.passes) {
      if (!samples.count(pass.name)) order.push_back(pass.name);
      samples[pass.name].push_back(pass.ms);
    }
  }
  std::vector<PassSummary> summaries;
  for (const std::string& name : order) {
    const std::vector<double>& v = samples[name];
    const auto [least, most] = std::minmax_element(v.begin(), v.end());
    summaries.push_back({name, median(v), *least, *most});
  }
  return summaries;
}

void writeStatsJson(const std::filesystem::path& path, const Context& context, const RunInfo& run,
                    const std::vector<FrameResult>& frames,
                    const std::vector<std::pair<std::string, double>>& extra) {
  nlohmann::json j;
  j["device"] = context.info().name;
  j["device_type"] = context.info().type;
  j["driver"] = context.info().driver;
  j["vulkan"] = context.info().apiVersion;
  j["commit"] = gitCommit();
  j["date"] = isoDate();
  j["scene"] = run.scene;
  j["technique"] = run.technique;
  j["camera"] = run.camera;
  j["width"] = run.width;
  j["height"] = run.height;
  j["lights"] = run.lightCount;
  j["triangles"] = run.triangleCount;
  j["frames"] = frames.size();
  j["timestamps"] = context.timestampPeriodNs() > 0.0;
  nlohmann::json passes = nlohmann::json::array();
  for (const PassSummary& s : summarizePasses(frames))
    passes.push_back({{"name", s.name}, {"median_ms", s.medianMs}, {"min_ms", s.minMs}, {"max_ms", s.maxMs}});
  j["passes"] = passes;
  uint32_t rerenders = 0;
  for (const FrameResult& f : frames) rerenders += f.rerenders;
  j["rerenders"] = rerenders;
  nlohmann::json technique = nlohmann::json::object();
  for (const auto& [key, value] : extra) technique[key] = value;
  j["technique_stats"] = technique;
  j["validation_messages"] = context.validationMessages().size();
  std::ofstream out(path);
  if (!out) throw InputError(fmt::format("--stats {}: cannot open for writing", path.string()));
  out << j.dump(2) << "\n";
  out.close();
  if (!out) throw InputError(fmt::format("--stats {}: write failed (disk full?)", path.string()));
}

}  // namespace lll
