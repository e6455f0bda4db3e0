// `lll bench`'s instant-radiosity suites: the gi, gi-error and gi-hierarchy suites' contents, and
// quick runs of gi-error (each frame against the path-traced reference) and gi-moving.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <optional>
#include <set>

#include "bench/bench.h"
#include "scene/scene_source.h"
#include "test_support.h"

namespace lll::bench {
namespace {

// Instant radiosity: the atrium's VPLs alone at four counts and two cutoffs, every technique (the
// brute-force and light-volume ones left out past 65,536); the Cornell room against the reference.
TEST(BenchSuites, GiSuitesVaryTheVplCountAndCutoff) {
  std::set<uint32_t> counts;
  std::set<float> cutoffs;
  int interleaved = 0;
  for (const Scenario& s : buildSuite("gi", SuiteOptions{})) {
    if (s.settings.vplInterleave > 1) {  // lll and tiled at Infinity's count, K = 2 and 3
      ++interleaved;
      EXPECT_EQ(s.scene.gi.vplCount, 5144u);
      EXPECT_TRUE(s.settings.technique == "lll" || s.settings.technique == "tiled") << s.settings.technique;
      EXPECT_NE(s.series.find(fmt::format("/interleave{}", s.settings.vplInterleave)), std::string::npos);
    }
    EXPECT_EQ(s.scene.gi.mode, GiMode::VplOnly);
    EXPECT_GE(s.scene.gi.photons, 2 * s.scene.gi.vplCount) << "too few deposits to merge into the count";
    counts.insert(s.scene.gi.vplCount);
    cutoffs.insert(s.scene.gi.vplCutoff);
    const std::string& t = s.settings.technique;
    EXPECT_EQ(!s.skip.empty(),
              (t == "forward" || t == "deferred" || t == "prepass") && s.scene.gi.vplCount > 65536)
        << s.name << " " << t;
    EXPECT_TRUE(s.series.ends_with(fmt::format("cutoff {}", s.scene.gi.vplCutoff))) << s.series;
  }
  EXPECT_EQ(counts, (std::set<uint32_t>{512, 5144, 65536, 1048576}));
  EXPECT_EQ(interleaved, 8) << "2 cutoffs x 2 patterns x 2 techniques";
  EXPECT_EQ(cutoffs.size(), 2u);
  const auto error = buildSuite("gi-error", SuiteOptions{});
  EXPECT_EQ(error.size(), 44u) << "4 counts x (4 reaches + 3 hierarchies + 4 interleaved)";
  std::set<float> alphas;
  for (const Scenario& s : error) {
    EXPECT_TRUE(s.compareWithReference);
    EXPECT_EQ(s.scene.scene, "cornell");
    if (s.scene.gi.hierarchy == GiHierarchy::Grid) {
      alphas.insert(s.scene.gi.vplAlpha);
      EXPECT_EQ(s.scene.gi.vplRange, 0.0f) << "the hierarchy refuses a fixed range";
      EXPECT_TRUE(s.series.starts_with(fmt::format("hierarchy {}", s.scene.gi.vplAlpha))) << s.series;
    }
  }
  EXPECT_EQ(alphas, (std::set<float>{1.0f, gi::kDefaultHierarchyAlpha, 3.0f}));
}

// The lighting grid hierarchy in the atrium: every technique at four counts (brute force and the
// light volumes up to 5,144), lll and tiled interleaved, lll at tile 16 (interleaved at K = 3 and 4
// beside forward) and at other alphas, and lll at the short cutoff beside each count.
TEST(BenchSuites, GiHierarchySuiteSetsTheHierarchyAndItsComparisons) {
  std::map<std::string, int> bySeries;
  std::set<uint32_t> counts;
  for (const Scenario& s : buildSuite("gi-hierarchy", SuiteOptions{})) {
    EXPECT_EQ(s.scene.gi.mode, GiMode::VplOnly);
    EXPECT_EQ(s.settings.width, 1920u);
    counts.insert(s.scene.gi.vplCount);
    ++bySeries[s.series];
    const std::string& t = s.settings.technique;
    if (s.scene.gi.hierarchy == GiHierarchy::Grid) {
      EXPECT_EQ(!s.skip.empty(),
                (t == "forward" || t == "deferred" || t == "prepass") && s.scene.gi.vplCount > 5144)
          << s.name << " " << t;
      EXPECT_NE(s.series.find(fmt::format("hierarchy {}", s.scene.gi.vplAlpha)), std::string::npos)
          << s.series;
      // Tile 16 in scenarios of its own, or named in the series where it shares forward's scenario
      // (issue 15's interleaved rows, compared with forward).
      EXPECT_EQ(s.settings.tileSize == 16,
                s.name.ends_with("tile 16") || s.series.find("tile 16") != std::string::npos)
          << s.name << " " << s.series;
    } else {
      EXPECT_EQ(t, "lll");
      EXPECT_EQ(s.scene.gi.vplCutoff, 0.05f);
    }
  }
  EXPECT_EQ(counts, (std::set<uint32_t>{512, 5144, 65536, 1048576}));
  EXPECT_EQ(bySeries["lll/compute, cutoff 0.05"], 4);
  EXPECT_EQ(bySeries["lll/compute/interleave2, hierarchy 1.5"], 4) << "tile 8 and 16 at 5,144 and 65,536";
  EXPECT_EQ(bySeries["tiled/interleave2, hierarchy 1.5"], 2);
  EXPECT_EQ(bySeries["lll/compute/interleave3 tile 16, hierarchy 1.5"], 2);
  EXPECT_EQ(bySeries["lll/compute/interleave4 tile 16, hierarchy 1.5"], 2);
  EXPECT_EQ(bySeries["lll/compute, hierarchy 1"], 1);
  EXPECT_EQ(bySeries["lll/compute, hierarchy 3"], 1);
}

// The error suite really compares: each scenario's frame against the path-traced indirect light.
TEST(BenchQuick, GiErrorSuiteMeasuresTheErrorAgainstTheReference) {
  Context& context = test::gpuContext();
  const size_t before = context.validationMessages().size();
  BenchOptions options;
  options.suites = {"gi-error"};
  options.quick = true;
  const BenchReport report = runBench(context, options);
  ASSERT_EQ(report.results.size(), 22u) << "2 counts x (4 reaches + 3 hierarchies + 4 interleaved)";
  for (const ScenarioResult& r : report.results) {
    ASSERT_EQ(r.status, Status::Ok) << r.scenario.name << ": " << r.message;
    std::optional<double> error, traceMs, levels;
    for (const auto& [key, value] : r.techniqueStats) {
      if (key == "gi-error-vs-reference") error = value;
      if (key == "gi-trace-ms") traceMs = value;
      if (key == "gi-levels") levels = value;
    }
    ASSERT_TRUE(error && traceMs && levels) << r.scenario.name;
    EXPECT_EQ(*levels > 1.0, r.scenario.scene.gi.hierarchy == GiHierarchy::Grid) << r.scenario.name;
    // 64 samples per pixel at 48x27: the reference is noisy, but VPLs are not off by half.
    EXPECT_GT(*error, 0.0);
    EXPECT_LT(*error, 0.5) << r.scenario.name;
  }
  test::expectNoValidationMessagesSince(before);
}

// Moving lights with instant radiosity: every scenario renders; the budgeted ones re-trace their
// share of the moving lights' photons each frame, and every one reports the CPU's light update.
TEST(BenchQuick, GiMovingSuiteReTracesTheBudgetEachFrame) {
  Context& context = test::gpuContext();
  const size_t before = context.validationMessages().size();
  BenchOptions options;
  options.suites = {"gi-moving"};
  options.quick = true;
  const BenchReport report = runBench(context, options);
  ASSERT_EQ(report.results.size(), 5u);
  for (const ScenarioResult& r : report.results) {
    ASSERT_EQ(r.status, Status::Ok) << r.scenario.name << ": " << r.message;
    std::map<std::string, double> stats(r.techniqueStats.begin(), r.techniqueStats.end());
    EXPECT_TRUE(stats.contains("light-update-cpu-ms")) << r.scenario.name;
    const uint32_t budget = r.scenario.scene.gi.retrace;
    EXPECT_EQ(stats.contains("vpl-retraced-photons"), budget > 0) << r.scenario.name;
    if (budget > 0) {
      ASSERT_GT(stats["vpl-moving-photons"], 0.0);
      EXPECT_EQ(stats["vpl-retraced-photons"], std::min<double>(budget, stats["vpl-moving-photons"]));
    }
  }
  test::expectNoValidationMessagesSince(before);
}

}  // namespace
}  // namespace lll::bench
