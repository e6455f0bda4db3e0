#pragma once
// What `lll bench` measures: a scenario is one scene at one size rendered by one technique with
// one set of options. A suite is a list of scenarios that answers one question (how does the frame
// time grow with the light count, what does the tile size cost, ...).
#include <string>
#include <vector>

#include "render/settings.h"
#include "scene/scene_source.h"

namespace lll::bench {

struct Scenario {
  std::string suite;
  std::string name;  // what varies inside the suite: "threel16 1920x1080", "1024 lights", "tile 4"
  SceneRequest scene;
  RenderSettings settings;  // size, technique and its options, particles
  std::string skip;         // why the suite leaves it out (recorded, not run); empty to run it
  // Also time the ALU roofline probe (bench/alu_probe.h) with every light at every pixel, after each
  // timed frame: its pass "alu-probe" (where every light does reach every pixel, as in ThreeL's test).
  bool aluProbe = false;
  // The line it belongs to in the suite's charts, when not its technique's label (gi: "lll, cutoff 0.05").
  std::string series;
  // Instant radiosity's error: the rendered frame against the path-traced indirect light of the same
  // scene without VPLs (gi/path_tracer.h), as "gi-error-vs-reference" in the technique's stats.
  bool compareWithReference = false;
};

// The light linked list's variant: its fill, with "/gbuffer" when opaque surfaces come from the raster
// G-buffer instead of the visibility buffer, "/fragment-shade" when they are lit
// in the fragment shader rather than the default compute pass; empty for other techniques.
std::string lllVariant(const RenderSettings& settings);
// "lll/ray" for the light linked list (its fill matters as much as the technique), else the name.
std::string techniqueLabel(const RenderSettings& settings);
// The scenario's line in its suite's charts: its series, or its technique's label.
std::string seriesLabel(const Scenario& scenario);

struct SuiteOptions {
  bool quick = false;        // tiny sizes and counts, so a suite runs on lavapipe in under a minute
  bool fullForward = false;  // forward with more than kForwardLightLimitOnCpu lights on a CPU device
  bool cpuDevice = false;    // lavapipe: hours per frame for brute force over tens of thousands of lights
  std::vector<uint32_t> particleCounts;  // smoke: only these particle counts (empty: the suite's own)
};

// Brute-force forward over more lights than this is skipped on a CPU device unless --full-forward.
inline constexpr uint32_t kForwardLightLimitOnCpu = 4096;
// The density suite runs forward, deferred and pre-pass up to this many lights (beyond it a frame
// takes seconds: every light per pixel, or one draw per light placed on the CPU).
inline constexpr uint32_t kDensityVolumeLimit = 65536;

// The suites `lll bench --suite` accepts, in the order they run.
const std::vector<std::string>& suiteNames();

// The scenarios of one suite, ordered so that scenarios sharing a scene follow each other (the
// runner loads each scene once). Throws InputError for an unknown suite name.
std::vector<Scenario> buildSuite(const std::string& suite, const SuiteOptions& options);

}  // namespace lll::bench
