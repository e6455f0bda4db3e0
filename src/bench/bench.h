#pragma once
// `lll bench`: runs suites of scenarios (scene x size x technique x options), times every pass
// with GPU timestamps over warm-up plus timed frames, and writes results.json, results.csv,
// summary.md and charts into one directory.
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bench/scenario.h"
#include "gpu/context.h"
#include "render/image_compare.h"
#include "render/stats.h"

namespace lll::bench {

struct BenchOptions {
  std::vector<std::string> suites;      // empty: every suite
  std::vector<std::string> techniques;  // only these techniques' scenarios; empty: all
  bool quick = false;
  bool fullForward = false;
  std::vector<uint32_t> particleCounts;  // --particle-count: the smoke suite's counts (empty: its own)
  std::optional<uint32_t> warmupFrames;  // default kWarmupFrames (kQuickWarmupFrames with quick)
  std::optional<uint32_t> timedFrames;   // default kTimedFrames (kQuickTimedFrames with quick)
  std::filesystem::path outDir = "bench-out";
  ContextOptions device;
  // --replot DIR: no run; redraw DIR's charts from its results.json (for results measured on a
  // machine without gnuplot).
  std::filesystem::path replotDir;
};

// Warm-up lets the LLL grow its link pool and the driver settle; the median of the timed frames
// is what the tables show.
inline constexpr uint32_t kWarmupFrames = 5;
inline constexpr uint32_t kTimedFrames = 30;
inline constexpr uint32_t kQuickWarmupFrames = 1;
// On a GPU the warm-up also lasts at least this long (a scenario's first timed frame otherwise can
// run at the clocks the GPU idled down to while the scene loaded: on the H200, a shadows suite
// begun from a 345 MHz idle clock timed some of its first rows 2 to 4 times slow with 3 warm-up
// frames of 2 ms each).
inline constexpr double kMinWarmupSeconds = 0.25;
inline constexpr uint32_t kQuickTimedFrames = 2;

enum class Status { Ok, Skipped, Failed };
const char* statusName(Status status);

using NamedValues = std::vector<std::pair<std::string, double>>;

struct ScenarioResult {
  Scenario scenario;
  Status status = Status::Ok;
  std::string message;  // why it was skipped or failed
  uint64_t lightCount = 0;
  std::vector<PassSummary> passes;  // each pass, then "frame"
  NamedValues memory;               // bytes of the lighting data: depth + the technique's "*_bytes"
  NamedValues techniqueStats;       // everything Technique::stats() reported
  uint32_t rerenders = 0;           // over the timed frames
  std::string date;                 // when it finished, ISO 8601 UTC
  // The frame after the timed ones against forward's frame of the same scenario (same scene,
  // size, camera and particle step), when forward ran in the suite: a fast but wrong technique
  // shows here.
  std::optional<ImageDifference> vsForward;

  double memoryBytes() const;
  // The named pass, or nullptr when the scenario has none of that name.
  const PassSummary* pass(const std::string& name) const;
};

struct BenchReport {
  DeviceInfo device;
  std::string commit;
  std::string date;  // when the run started
  bool quick = false;
  bool timestamps = false;  // false: the device has no GPU timestamps and every time is zero
  uint32_t warmupFrames = 0;
  uint32_t timedFrames = 0;
  std::vector<std::string> suites;
  std::vector<std::string> onlyTechniques;  // --technique: the other scenarios were left out
  std::vector<ScenarioResult> results;
  size_t validationMessages = 0;
  bool interrupted = false;  // stopped by requestStop(): results holds the scenarios that finished
};

// Runs the suites on `context`, showing progress on stderr. Scenarios that cannot run here (an
// unregistered technique, too many lights, a technique that draws no particles) are recorded as skipped;
// those that throw anything else are recorded as failed. Throws InputError for an unknown suite.
// `finished` is called with the report so far after each scenario. After requestStop() the run
// ends between two frames, drops the scenario it was in and returns with `interrupted` set.
BenchReport runBench(Context& context, const BenchOptions& options,
                     const std::function<void(const BenchReport&)>& finished = {});

// Asks a running runBench to stop; async-signal-safe (the CLI calls it on SIGINT and SIGTERM).
void requestStop();

// Throws InputError unless `dir` is, or can be made, a folder that takes new files.
void checkOutputFolder(const std::filesystem::path& dir);
// Writes results.json and results.csv, each replaced whole (never seen half-written).
void writeResults(const BenchReport& report, const std::filesystem::path& dir);
// writeResults, then summary.md and, when gnuplot is installed, the PNG charts.
void writeReport(const BenchReport& report, const std::filesystem::path& dir);

// Exit code of an interrupted bench, as a shell reports a process ended by SIGINT.
inline constexpr int kInterruptedExitCode = 130;

// The CLI command: checks --out, creates the context, runs, writing the results after every
// scenario. Returns 0; 1 when a scenario failed or validation spoke under --validate;
// kInterruptedExitCode after SIGINT or SIGTERM, with the finished scenarios written.
int runBenchCommand(const BenchOptions& options);

}  // namespace lll::bench
