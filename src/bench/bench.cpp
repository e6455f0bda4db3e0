#include "bench/bench.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <signal.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <map>
#include <optional>

#include "bench/alu_probe.h"
#include "bench/progress.h"
#include "bench/report.h"
#include "core/errors.h"
#include "gi/path_tracer.h"
#include "lighting/technique.h"
#include "particles/presets.h"
#include "render/image_compare.h"
#include "renderer/renderer.h"
#include "scene/light_animation.h"

namespace lll::bench {

namespace {

// A scenario that cannot run in this build or on this device: recorded as skipped.
class NotAvailable : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Thrown between frames once requestStop() was called. Not a std::exception: no scenario's
// handler may record it as a failure.
struct Interrupted {};

std::atomic<bool> stopRequested{false};
static_assert(std::atomic<bool>::is_always_lock_free, "requestStop runs in a signal handler");

void stopIfRequested() {
  if (stopRequested.load()) throw Interrupted{};
}

struct FrameCounts {
  uint32_t warmup = 0;
  uint32_t timed = 0;
  double minWarmupSeconds = 0.0;  // warm-up frames go on until this much time has passed too
};

// Loads scenes as scenarios ask for them and keeps the last: suites put scenarios that share a
// scene next to each other, so each scene is built once without holding them all in memory.
class SceneCache {
 public:
  const Scene& get(const SceneRequest& request) {
    if (!scene_ || request != key_) {
      scene_.reset();
      gi_ = {};
      scene_ = loadScene(request, nullptr, &gi_);
      key_ = request;
    }
    return *scene_;
  }
  // What tracing the photons of the last scene took (zeros without --gi).
  const gi::PhotonStats& photonStats() const { return gi_.stats; }

 private:
  SceneRequest key_;
  std::optional<Scene> scene_;
  IndirectLightReport gi_;
};

// The path-traced indirect light each gi-error scenario is compared with, once per scene, size and
// bounce count: 2,048 samples per pixel (64 with --quick) on every CPU core.
class ReferenceCache {
 public:
  const HdrImage& get(const Scenario& s, const Camera& camera, bool quick) {
    SceneRequest direct = s.scene;
    direct.gi = GiRequest{};
    const std::string key = fmt::format("{}\n{}\n{}x{}\n{}", s.scene.scene, camera.name, s.settings.width,
                                        s.settings.height, s.scene.gi.bounces);
    auto it = images_.find(key);
    if (it == images_.end()) {
      gi::ReferenceOptions options;
      options.spp = quick ? 64 : 2048;
      options.bounces = s.scene.gi.bounces;
      options.indirectOnly = true;
      const gi::RadianceImage image =
          gi::renderReference(loadScene(direct), camera, s.settings.width, s.settings.height, options);
      it = images_.emplace(key, HdrImage::fromRgb(image.width, image.height, image.rgb)).first;
    }
    return it->second;
  }

 private:
  std::map<std::string, HdrImage> images_;
};

// gi-error compares 8x8-pixel block means: the reference's per-pixel noise (about 9% at 2,048
// samples in the Cornell room) averages down to ~1% in a block.
constexpr uint32_t kReferenceErrorBlock = 8;

struct Caches {
  SceneCache scenes;
  ReferenceCache references;
  bool quick = false;
};

void requireRegistered(const std::string& technique) {
  std::vector<std::string> names;
  for (const TechniqueInfo& t : techniques()) names.push_back(t.name);
  if (std::find(names.begin(), names.end(), technique) == names.end())
    throw NotAvailable(
        fmt::format("technique {} is not built yet (built: {})", technique, fmt::join(names, ", ")));
}

// A technique that does not draw particles would time the scene without its smoke.
void requireParticlePass(const Scenario& s, const FrameResult& frame) {
  if (s.settings.particles.empty()) return;
  for (const PassTime& pass : frame.passes)
    if (pass.name == "particles-draw" || pass.name == "particles-composite") return;
  throw NotAvailable(fmt::format("{} does not draw particles", s.settings.technique));
}

// The GPU memory of the lighting data: the depth target every technique reads (4 B/px), plus what
// the technique reports under keys ending in "_bytes" (link pool, heads, G-buffers, ...). The
// particle system's buffers ("particle_*") are the scene's, not the lighting's.
NamedValues lightingMemory(const RenderSettings& settings, const NamedValues& techniqueStats) {
  NamedValues memory = {{"depth_bytes", 4.0 * settings.width * settings.height}};
  for (const auto& [key, value] : techniqueStats)
    if (key.ends_with("_bytes") && !key.starts_with("particle")) memory.emplace_back(key, value);
  return memory;
}

// A scenario's result and the frame it rendered after the timed ones (for the comparison with
// forward's).
struct Measured {
  ScenarioResult result;
  LdrImage image;
};

Measured measure(Context& context, Caches& caches, const Scenario& s, FrameCounts counts) {
  const Scene& cached = caches.scenes.get(s.scene);
  // Moving lights move in a copy: the cache's scene is shared by the scenarios.
  std::optional<Scene> moving;
  if (s.settings.animateLights) moving.emplace(cached);
  const Scene& scene = moving ? *moving : cached;
  Measured m;
  ScenarioResult& r = m.result;
  r.scenario = s;
  r.lightCount = scene.lights.size();
  Renderer renderer(context, scene, s.settings);
  // Frame i shows the lights at i / 60 s; the untimed frame compared with forward's at 0 s. The
  // light array's upload happens between frames, outside every timed pass.
  // Returns the CPU's part of a moving frame (placing the lights, re-tracing photons for --gi, the
  // upload), in ms.
  auto moveLightsTo = [&](float seconds) {
    if (!moving) return 0.0;
    const auto begin = std::chrono::steady_clock::now();
    renderer.moveLightsTo(*moving, seconds);
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin).count();
  };
  std::vector<double> lightUpdateMs;  // of the timed frames
  // Particles start with none alive: time the plume at its steady state.
  if (renderer.particles()) renderer.advanceParticles(stepsToSteadyState(renderer.particles()->preset()));
  std::optional<AluProbe> probe;
  if (s.aluProbe) probe.emplace(context, scene, s.settings.width, s.settings.height);
  std::vector<FrameResult> timed;
  const auto warmupStart = std::chrono::steady_clock::now();
  uint32_t warmup = counts.warmup;
  for (uint32_t i = 0; i < warmup + counts.timed; ++i) {
    stopIfRequested();
    const double updateMs = i > 0 ? moveLightsTo(float(i) * kAnimationFrameSeconds) : 0.0;
    FrameResult frame = renderer.renderFrame(false);
    if (i == 0) requireParticlePass(s, frame);
    if (probe)
      for (const PassTime& p : probe->run(uint32_t(scene.lights.size()))) frame.passes.push_back(p);
    const std::chrono::duration<double> warming = std::chrono::steady_clock::now() - warmupStart;
    if (i + 1 == warmup && warming.count() < counts.minWarmupSeconds) ++warmup;  // one more
    if (i < warmup) continue;
    timed.push_back(std::move(frame));
    if (moving && i > 0) lightUpdateMs.push_back(updateMs);
  }
  r.passes = summarizePasses(timed);
  for (const FrameResult& frame : timed) r.rerenders += frame.rerenders;
  r.techniqueStats = renderer.stats();
  r.memory = lightingMemory(s.settings, r.techniqueStats);
  if (!lightUpdateMs.empty()) r.techniqueStats.emplace_back("light-update-cpu-ms", median(lightUpdateMs));
  if (s.scene.gi.mode != GiMode::None) {
    const gi::PhotonStats& g = caches.scenes.photonStats();
    r.techniqueStats.insert(r.techniqueStats.end(), {{"gi-photons", double(g.photons)},
                                                     {"gi-deposits", double(g.deposits)},
                                                     {"gi-trace-ms", g.traceMs},
                                                     {"gi-merge-ms", g.mergeMs},
                                                     {"gi-cell-m", g.cellSize},
                                                     {"gi-levels", double(g.levels)}});
  }
  moveLightsTo(0.0f);
  renderer.renderFrame(true);  // untimed: the image every technique's is compared on
  m.image = renderer.ldrImage();
  if (s.compareWithReference)
    r.techniqueStats.emplace_back(
        "gi-error-vs-reference",
        relativeBlockError(renderer.hdrImage(), caches.references.get(s, renderer.camera(), caches.quick),
                           std::min({kReferenceErrorBlock, s.settings.width, s.settings.height})));
  return m;
}

Measured runScenario(Context& context, Caches& caches, const Scenario& s, FrameCounts counts) {
  Measured m;
  ScenarioResult& r = m.result;
  r.scenario = s;
  try {
    if (!s.skip.empty()) throw NotAvailable(s.skip);
    requireRegistered(s.settings.technique);
    m = measure(context, caches, s, counts);
  } catch (const NotAvailable& e) {
    r.status = Status::Skipped;
    r.message = e.what();
  } catch (const InputError& e) {
    r.status = Status::Skipped;
    r.message = e.what();
  } catch (const std::exception& e) {
    r.status = Status::Failed;
    r.message = e.what();
  }
  r.date = isoDate();
  return m;
}

// Pairs each technique's frame with forward's frame of the same scenario, whichever ran first:
// forward's frames are kept for the rest of the run, the others only until forward's arrives.
class ForwardComparisons {
 public:
  void add(BenchReport& report, size_t index, LdrImage image) {
    const ScenarioResult& r = report.results[index];
    if (r.status != Status::Ok) return;
    const std::string key = r.scenario.suite + '\n' + r.scenario.name;
    if (r.scenario.settings.technique != "forward") {
      const auto forward = forward_.find(key);
      if (forward != forward_.end())
        compare(report.results[index], image, forward->second);
      else
        waiting_[key].emplace_back(index, std::move(image));
      return;
    }
    for (auto& [waitingIndex, waitingImage] : waiting_[key])
      compare(report.results[waitingIndex], waitingImage, image);
    waiting_.erase(key);
    forward_[key] = std::move(image);
  }

 private:
  static void compare(ScenarioResult& r, const LdrImage& image, const LdrImage& forward) {
    if (image.width == forward.width && image.height == forward.height)
      r.vsForward = compareImages(image, forward);
  }

  std::map<std::string, LdrImage> forward_;
  std::map<std::string, std::vector<std::pair<size_t, LdrImage>>> waiting_;
};

// The suites asked for, each once, in the order given; every suite when none is named.
std::vector<std::string> chosenSuites(const BenchOptions& options) {
  if (options.suites.empty()) return suiteNames();
  std::vector<std::string> suites;
  for (const std::string& suite : options.suites) {
    if (std::find(suiteNames().begin(), suiteNames().end(), suite) == suiteNames().end())
      throw InputError(
          fmt::format("--suite {}: unknown suite (known: {})", suite, fmt::join(suiteNames(), ", ")));
    if (std::find(suites.begin(), suites.end(), suite) == suites.end()) suites.push_back(suite);
  }
  return suites;
}

// Throws InputError for a --suite or --technique that does not exist.
void checkNames(const BenchOptions& options) {
  chosenSuites(options);
  for (const std::string& technique : options.techniques) findTechnique(technique);
}

// The suites' scenarios, less those of techniques that --technique left out.
std::vector<Scenario> chosenScenarios(const BenchReport& report, const SuiteOptions& suiteOptions) {
  const std::vector<std::string>& only = report.onlyTechniques;
  std::vector<Scenario> scenarios;
  for (const std::string& suite : report.suites)
    for (Scenario& s : buildSuite(suite, suiteOptions))
      if (only.empty() || std::find(only.begin(), only.end(), s.settings.technique) != only.end())
        scenarios.push_back(std::move(s));
  return scenarios;
}

BenchReport reportHeader(const Context& context, const BenchOptions& options) {
  BenchReport report;
  report.device = context.info();
  report.commit = gitCommit();
  report.date = isoDate();
  report.quick = options.quick;
  report.timestamps = context.timestampPeriodNs() > 0.0;
  report.warmupFrames = options.warmupFrames.value_or(options.quick ? kQuickWarmupFrames : kWarmupFrames);
  report.timedFrames = options.timedFrames.value_or(options.quick ? kQuickTimedFrames : kTimedFrames);
  report.suites = chosenSuites(options);
  report.onlyTechniques = options.techniques;
  return report;
}

}  // namespace

const char* statusName(Status status) {
  switch (status) {
    case Status::Ok:
      return "ok";
    case Status::Skipped:
      return "skipped";
    case Status::Failed:
      return "failed";
  }
  return "unknown";
}

double ScenarioResult::memoryBytes() const {
  double sum = 0.0;
  for (const auto& [key, bytes] : memory) sum += bytes;
  return sum;
}

const PassSummary* ScenarioResult::pass(const std::string& name) const {
  for (const PassSummary& p : passes)
    if (p.name == name) return &p;
  return nullptr;
}

BenchReport runBench(Context& context, const BenchOptions& options,
                     const std::function<void(const BenchReport&)>& finished) {
  checkNames(options);
  BenchReport report = reportHeader(context, options);
  if (report.timedFrames == 0) throw InputError("--frames 0: at least one timed frame is needed");
  const SuiteOptions suiteOptions{options.quick, options.fullForward, context.isCpuDevice(),
                                  options.particleCounts};
  const std::vector<Scenario> scenarios = chosenScenarios(report, suiteOptions);
  const FrameCounts counts{report.warmupFrames, report.timedFrames,
                           options.quick || context.isCpuDevice() ? 0.0 : kMinWarmupSeconds};
  Caches caches;
  caches.quick = options.quick;
  ForwardComparisons comparisons;
  ProgressBar progress(scenarios.size());
  for (size_t i = 0; i < scenarios.size(); ++i) {
    const Scenario& s = scenarios[i];
    const std::string label = fmt::format("{} {} {}", s.suite, techniqueLabel(s.settings), s.name);
    progress.start(i, label);
    try {
      stopIfRequested();
      Measured measured = runScenario(context, caches, s, counts);
      report.results.push_back(std::move(measured.result));
      comparisons.add(report, report.results.size() - 1, std::move(measured.image));
    } catch (const Interrupted&) {
      report.interrupted = true;
      break;
    }
    const ScenarioResult& r = report.results.back();
    if (r.status != Status::Ok)
      progress.note(fmt::format("lll: bench: {} {}: {}", label, statusName(r.status), r.message));
    report.validationMessages = context.validationMessages().size();
    if (finished) finished(report);
  }
  progress.finish(report.results.size());
  report.validationMessages = context.validationMessages().size();
  return report;
}

void requestStop() {
  stopRequested.store(true);
}

namespace {

// The first signal asks the run to stop between frames; the handler then resets itself, so a
// second one ends the process at once.
void onStopSignal(int) {
  requestStop();
}

void installStopHandlers() {
  struct sigaction action {};
  action.sa_handler = &onStopSignal;
  action.sa_flags = SA_RESETHAND;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

}  // namespace

int runBenchCommand(const BenchOptions& options) {
  if (!options.replotDir.empty()) {
    const BenchReport report = readResultsJson(options.replotDir / "results.json");
    const auto charts = writeCharts(report, options.replotDir);
    fmt::print(stderr, "lll: bench: {} charts redrawn in {}\n", charts.size(), options.replotDir.string());
    return charts.empty() ? 1 : 0;
  }
  checkNames(options);  // before the slow start of Vulkan
  checkOutputFolder(options.outDir);
  installStopHandlers();
  Context context(options.device);
  const BenchReport report =
      runBench(context, options, [&](const BenchReport& sofar) { writeResults(sofar, options.outDir); });
  writeReport(report, options.outDir);
  const auto failed = std::count_if(report.results.begin(), report.results.end(),
                                    [](const ScenarioResult& r) { return r.status == Status::Failed; });
  fmt::print(stderr, "lll: bench: {} scenarios ({} failed) written to {}\n", report.results.size(), failed,
             options.outDir.string());
  if (report.interrupted) {
    fmt::print(stderr, "lll: bench: interrupted; the results hold the scenarios that finished\n");
    return kInterruptedExitCode;
  }
  if (report.validationMessages > 0)
    fmt::print(stderr, "lll: error: {} validation message(s); see above\n", report.validationMessages);
  return failed > 0 || report.validationMessages > 0 ? 1 : 0;
}

}  // namespace lll::bench
