// `lll bench`: the statistics, the suites' contents, a real --quick ThreeL run written to disk and
// read back (CSV rows, JSON, summary, charts), and the CLI's answer to an unknown suite.
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "bench/bench.h"
#include "bench/report.h"
#include "cli_test_support.h"
#include "core/errors.h"
#include "lighting/technique.h"
#include "scene/scene_source.h"
#include "test_support.h"

namespace lll::bench {
namespace {

namespace fs = std::filesystem;

FrameResult frameOf(std::initializer_list<std::pair<const char*, double>> passes) {
  FrameResult frame;
  for (const auto& [name, ms] : passes) frame.passes.push_back({name, ms});
  return frame;
}

TEST(BenchStats, MedianMinMaxOfKnownSamples) {
  const std::vector<FrameResult> odd = {frameOf({{"a", 3.0}, {"b", 10.0}}),
                                        frameOf({{"a", 1.0}, {"b", 30.0}}),
                                        frameOf({{"a", 2.0}, {"b", 20.0}})};
  const auto s = summarizePasses(odd);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].name, "a");
  EXPECT_DOUBLE_EQ(s[0].medianMs, 2.0);
  EXPECT_DOUBLE_EQ(s[0].minMs, 1.0);
  EXPECT_DOUBLE_EQ(s[0].maxMs, 3.0);
  EXPECT_EQ(s[1].name, "b");
  EXPECT_DOUBLE_EQ(s[1].medianMs, 20.0);
  const std::vector<FrameResult> even = {frameOf({{"a", 4.0}}), frameOf({{"a", 1.0}}), frameOf({{"a", 3.0}}),
                                         frameOf({{"a", 2.0}})};
  EXPECT_DOUBLE_EQ(summarizePasses(even)[0].medianMs, 2.5);
}

TEST(BenchStats, PassOrderKeepsEveryFramesOwnOrder) {
  ScenarioResult lll, forward;
  for (const char* name : {"depth-prepass", "lll-fill", "lll-shade", "tonemap", "frame"})
    lll.passes.push_back({name});
  for (const char* name : {"depth-prepass", "forward-opaque", "tonemap", "frame"})
    forward.passes.push_back({name});
  EXPECT_EQ(passOrder({&lll, &forward}), (std::vector<std::string>{"depth-prepass", "lll-fill", "lll-shade",
                                                                   "forward-opaque", "tonemap", "frame"}));
}

size_t variantsPerLightCount() {
  size_t n = 0;
  // lll: 3 fills, the compute fill with the hardware rasterizing the visibility buffer, on G-buffer
  // surfaces and with fragment shading
  for (const TechniqueInfo& t : techniques()) n += t.name == "lll" ? 6 : 1;
  return n;
}

TEST(BenchSuites, ScalingRunsEveryRegisteredTechniqueAndEveryFill) {
  const auto quick = buildSuite("scaling", SuiteOptions{.quick = true});
  EXPECT_EQ(quick.size(), 3 * variantsPerLightCount());
  const auto full = buildSuite("scaling", SuiteOptions{});
  EXPECT_EQ(full.size(), 7 * variantsPerLightCount());
  EXPECT_EQ(full.back().scene.extraLights, 65536u);
  EXPECT_EQ(full.back().settings.width, 1920u);
}

TEST(BenchSuites, ForwardOverManyLightsIsSkippedOnCpuUnlessAsked) {
  size_t skipped = 0;
  for (const Scenario& s : buildSuite("scaling", SuiteOptions{.cpuDevice = true})) {
    EXPECT_EQ(!s.skip.empty(), s.settings.technique == "forward" && s.scene.extraLights > 4096) << s.name;
    skipped += !s.skip.empty();
  }
  EXPECT_EQ(skipped, 2u);  // 16384 and 65536 lights
  for (const Scenario& s : buildSuite("scaling", SuiteOptions{.fullForward = true, .cpuDevice = true}))
    EXPECT_TRUE(s.skip.empty());
}

// Constant density: ranges scaled by (1024 / N)^(1/3), intensities by its square, every technique
// once (lll with its compute fill), brute force and the light-volume techniques only up to 65,536.
TEST(BenchSuites, DensityKeepsLightsPerPixelAndSkipsTheSlowTechniquesBeyondTheirLimit) {
  const auto full = buildSuite("density", SuiteOptions{});
  ASSERT_EQ(full.size(), 7 * techniques().size());
  size_t skipped = 0;
  for (const Scenario& s : full) {
    const uint32_t n = s.scene.extraLights;
    EXPECT_NEAR(s.scene.lightRangeScale, std::cbrt(1024.0 / n), 1e-6) << s.name;
    EXPECT_TRUE(s.scene.scaleIntensityWithRange);
    EXPECT_EQ(s.settings.lllFill, LllFill::Compute);
    const bool slow = s.settings.technique == "forward" || s.settings.technique == "deferred" ||
                      s.settings.technique == "prepass";
    EXPECT_EQ(!s.skip.empty(), slow && n > kDensityVolumeLimit) << s.name << " " << s.settings.technique;
    skipped += !s.skip.empty();
  }
  EXPECT_EQ(skipped, 3u * 3u);  // 262,144, 1,048,576 and 4,194,304 lights
  EXPECT_EQ(full.back().scene.extraLights, 4194304u);
}

// The density scenes: a quarter the range and a sixteenth the intensity at 64x the lights.
TEST(BenchSuites, SlicesIsLllWithAndWithoutDepthSlicesOnBothLightSets) {
  const auto full = buildSuite("slices", SuiteOptions{});
  // Per light count: 6 slice counts at tile 8; on the dense lights also at tile 16, and the two
  // peers at tile 16.
  ASSERT_EQ(full.size(), 3u * 6u + 3u * (6u + 6u + 2u));
  size_t dense = 0, sliced = 0, peers = 0;
  std::set<std::string> labels;
  for (const Scenario& s : full) {
    EXPECT_TRUE(s.skip.empty());
    dense += s.scene.scaleIntensityWithRange;
    labels.insert(seriesLabel(s));
    if (s.settings.technique != "lll") {
      ++peers;
      EXPECT_TRUE(s.settings.technique == "tiled" || s.settings.technique == "clustered");
      EXPECT_EQ(s.settings.tileSize, 16u);
      EXPECT_TRUE(s.scene.scaleIntensityWithRange);
      EXPECT_EQ(seriesLabel(s), s.settings.technique + "/tile16");
      continue;
    }
    EXPECT_EQ(s.settings.lllFill, LllFill::Compute);
    EXPECT_LE(s.settings.lllSlices, 32u);
    sliced += s.settings.lllSlices > 1;
    EXPECT_TRUE(s.settings.tileSize == 8u || s.settings.tileSize == 16u);
    if (s.settings.tileSize == 16u) {
      EXPECT_TRUE(s.scene.scaleIntensityWithRange);
      EXPECT_EQ(seriesLabel(s), techniqueLabel(s.settings) + "/tile16");
      continue;
    }
    // Every count but the default is named in the label.
    EXPECT_EQ(seriesLabel(s) == "lll/compute", s.settings.lllSlices == RenderSettings{}.lllSlices);
  }
  EXPECT_EQ(dense, 3u * 14u);
  EXPECT_EQ(sliced, 30u + 15u);
  EXPECT_EQ(peers, 6u);
  EXPECT_EQ(labels.size(), 6u + 6u + 2u);  // each slice count and tile size is its own series
  EXPECT_TRUE(labels.count("lll/compute/slices16")) << fmt::format("{}", fmt::join(labels, ", "));
  EXPECT_TRUE(labels.count("lll/compute/slices32/tile16")) << fmt::format("{}", fmt::join(labels, ", "));
}

// Moving lights: every technique with the dense lights moving (the light-volume ones and forward
// only where they finish, as in the density suite), lll standing still as the control, and lll
// with the lights placed on the CPU (what the GPU's placing saves).
TEST(BenchSuites, MovingIsEveryTechniqueWithMovingLightsAndLllStill) {
  const auto full = buildSuite("moving", SuiteOptions{});
  size_t still = 0, cpu = 0;
  for (const Scenario& s : full) {
    EXPECT_TRUE(s.scene.scaleIntensityWithRange) << s.name;
    EXPECT_TRUE(s.scene.extraLights == 4096u || s.scene.extraLights == 131072u ||
                s.scene.extraLights == 1048576u)
        << s.name;
    if (!s.settings.animateLights) {
      ++still;
      EXPECT_FALSE(s.scene.movingLights);
      EXPECT_EQ(s.settings.technique, "lll");
      EXPECT_EQ(seriesLabel(s), "lll/compute/static");
      continue;
    }
    EXPECT_TRUE(s.scene.movingLights) << s.name;
    if (s.settings.lightMotion == LightPlacement::Cpu) {
      ++cpu;
      EXPECT_EQ(seriesLabel(s), "lll/compute/cpu-motion");
      continue;
    }
    EXPECT_EQ(s.settings.lightMotion, LightPlacement::Auto) << seriesLabel(s);
    EXPECT_EQ(s.skip.empty(), s.scene.extraLights <= kDensityVolumeLimit ||
                                  (s.settings.technique != "forward" && s.settings.technique != "deferred" &&
                                   s.settings.technique != "prepass"))
        << seriesLabel(s) << " " << s.name;
  }
  EXPECT_EQ(still, 3u);
  EXPECT_EQ(cpu, 3u);
  EXPECT_EQ(full.size(), 3u * (techniques().size() + 2u));
}

TEST(BenchSuites, DensityScalesIntensityWithTheSquareOfTheRange) {
  SceneRequest plain{"atrium", 16, 1};
  SceneRequest scaled = plain;
  scaled.lightRangeScale = 0.25f;
  scaled.scaleIntensityWithRange = true;
  const Scene a = loadScene(plain), b = loadScene(scaled);
  ASSERT_EQ(a.lights.size(), b.lights.size());
  const size_t own = a.lights.size() - 16;
  for (size_t i = own; i < a.lights.size(); ++i) {
    EXPECT_FLOAT_EQ(b.lights[i].range, a.lights[i].range * 0.25f);
    EXPECT_FLOAT_EQ(b.lights[i].intensity, a.lights[i].intensity * 0.0625f);
  }
  EXPECT_EQ(b.lights[0].range, a.lights[0].range);  // the scene's own lights are left alone
}

TEST(BenchSuites, ThreelIsEveryLllFillAndForwardAtTwoSizes) {
  const auto threel = buildSuite("threel", SuiteOptions{.quick = true});
  ASSERT_EQ(threel.size(), 32u);
  std::set<std::string> labels, names;
  size_t atDefaultTile = 0;
  for (const Scenario& s : threel) {
    labels.insert(techniqueLabel(s.settings));
    names.insert(s.name);
    if (s.series == "lll/compute/tile16") {  // lll's compute fill at its own default tile
      ++atDefaultTile;
      EXPECT_EQ(s.settings.tileSize, 0u);
      EXPECT_EQ(s.settings.lllFill, LllFill::Compute);
      continue;
    }
    EXPECT_EQ(s.settings.tileSize, 8u);  // ThreeL's
  }
  EXPECT_EQ(atDefaultTile, 4u);
  EXPECT_EQ(labels,
            (std::set<std::string>{"lll/shells", "lll/ray", "lll/compute", "lll/compute/hardware-raster",
                                   "lll/compute/gbuffer", "lll/compute/fragment-shade", "forward"}));
  EXPECT_EQ(names, (std::set<std::string>{"threel16 32x18", "threel16 64x36", "threel256 32x18",
                                          "threel256 64x36"}));
  EXPECT_THROW(buildSuite("nope", SuiteOptions{}), InputError);
}

TEST(BenchSuites, SmokeIsThePlumeAtThreeCountsTwoLightingsLllAndForwardComputeAndRaster) {
  const auto full = buildSuite("smoke", SuiteOptions{});
  // 3 counts x 3 lightings x 2 techniques in compute; in raster too 1,024 with every lighting and
  // 65,536 with atlas and vertex lighting; sparks and dust at 65,536 with lll both ways.
  // Atlas- and vertex-lit smoke with lll at half and quarter resolution: 3 counts x 4.
  ASSERT_EQ(full.size(), 18u + 6u + 4u + 4u + 12u);
  std::set<uint32_t> counts;
  std::set<std::string> labels, lightings, presets, series;
  for (const Scenario& s : full) {
    EXPECT_EQ(s.settings.width, 1920u);
    EXPECT_EQ(s.settings.height, 1080u);
    EXPECT_EQ(s.scene.scene, "atrium");
    EXPECT_EQ(s.scene.extraLights, 256u);
    EXPECT_TRUE(s.settings.particleRender == ParticleRender::Compute || s.settings.particleCount <= 65536)
        << s.name;
    EXPECT_TRUE(s.settings.particleRender == ParticleRender::Compute ||
                s.settings.particleLighting != ParticleLighting::Pixel || s.settings.particleCount <= 1024)
        << s.name;
    counts.insert(s.settings.particleCount);
    labels.insert(techniqueLabel(s.settings));
    lightings.insert(std::string(nameOf(s.settings.particleLighting)));
    presets.insert(s.settings.particles);
    series.insert(seriesLabel(s));
  }
  EXPECT_EQ(counts, (std::set<uint32_t>{1024, 65536, 1000000}));
  EXPECT_EQ(labels, (std::set<std::string>{"lll/compute", "forward"}));
  EXPECT_EQ(lightings, (std::set<std::string>{"pixel", "atlas", "vertex"}));
  EXPECT_EQ(presets, (std::set<std::string>{"smoke", "sparks", "dust"}));
  EXPECT_EQ(series.count("lll/compute, raster"), 1u);
  EXPECT_EQ(series.count("sparks lll/compute, compute"), 1u);
  EXPECT_EQ(series.count("lll/compute, compute quarter"), 1u);
  EXPECT_EQ(buildSuite("smoke", SuiteOptions{.quick = true}).size(), 12u + 6u + 4u + 4u + 8u);
  // --particle-count picks the counts (the GPU runs take the million-slot case on its own), smoke only.
  const auto picked = buildSuite("smoke", SuiteOptions{.particleCounts = {2048}});
  EXPECT_EQ(picked.size(), 6u + 4u + 4u);
  for (const Scenario& s : picked) EXPECT_EQ(s.settings.particleCount, 2048u);
}

// Shadows: every technique without and with the sun's (4 cascades of 2048), then lll's cascades by
// both rasterizers at 1, 2, 4 cascades and half and double resolution (a CPU device runs the
// hardware rows alone); K local lights' shadows for every technique at K = 1, 16, 64 and 256, with
// the sun and in the atrium without it (and without shadows there), and lll at 16 and 64 with the
// hardware drawing the local casters (not on a CPU device); then the measure on the atrium
// lit by spots alone: lll without shadows, with the sun's, and with the sun and 16 or 64 shadowed
// spots (64 also drawn by the hardware, not on a CPU device).
TEST(BenchSuites, ShadowsSuiteIsEveryTechniqueWithAndWithoutAndBothRasterizers) {
  const auto full = buildSuite("shadows", SuiteOptions{});
  const size_t techniques = lll::techniques().size();
  ASSERT_EQ(full.size(), 2 * techniques + 2 * 5 + 4 * techniques + 5 * techniques + 2 + 5);
  std::map<std::string, int> byRaster;
  std::map<std::pair<bool, uint32_t>, int> byLights;  // (with the sun, K)
  std::vector<std::string> spotRows;
  for (const Scenario& s : full) {
    EXPECT_EQ(s.settings.width, 1920u);
    if (s.scene.scene == "atrium-spots") {
      EXPECT_EQ(s.settings.technique, "lll");
      EXPECT_EQ(s.scene.suns.size(), 1u);
      spotRows.push_back(s.settings.shadows == ShadowMode::All
                             ? fmt::format("{} {}", s.settings.shadowLights, s.settings.shadowRaster)
                             : std::string(nameOf(s.settings.shadows)));
      continue;
    }
    EXPECT_EQ(s.scene.scene, "atrium");
    const bool sun = !s.scene.suns.empty();
    if (s.settings.shadows == ShadowMode::All) {
      if (s.settings.shadowRaster == RasterChoice::Hardware) {
        EXPECT_EQ(s.settings.technique, "lll");
        EXPECT_TRUE(sun);
        EXPECT_NE(s.series.find("hardware raster"), std::string::npos) << s.series;
        continue;
      }
      ++byLights[{sun, s.settings.shadowLights}];
      EXPECT_NE(
          s.series.find(fmt::format("{}{} shadowed light", sun ? "sun + " : "", s.settings.shadowLights)),
          std::string::npos)
          << s.series;
      continue;
    }
    if (!sun) {
      EXPECT_EQ(s.settings.shadows, ShadowMode::None);
      ++byRaster["no sun"];
      continue;
    }
    ++byRaster[s.settings.shadows == ShadowMode::None ? "none"
                                                      : std::string(nameOf(s.settings.shadowRaster))];
    if (s.settings.shadowRaster != RasterChoice::Auto) {
      EXPECT_EQ(s.settings.technique, "lll");
      EXPECT_NE(s.series.find(fmt::format("{} raster", s.settings.shadowRaster)), std::string::npos)
          << s.series;
    }
  }
  EXPECT_EQ(byRaster["none"], int(techniques));
  EXPECT_EQ(byRaster["no sun"], int(techniques));
  EXPECT_EQ(byRaster["auto"], int(techniques));
  EXPECT_EQ(byRaster["hardware"], 5);
  EXPECT_EQ(byRaster["compute"], 5);
  for (const bool sun : {true, false})
    for (const uint32_t k : {1u, 16u, 64u, 256u})
      EXPECT_EQ((byLights[{sun, k}]), int(techniques)) << sun << k;
  EXPECT_EQ(byLights.size(), 8u);
  EXPECT_EQ(spotRows, (std::vector<std::string>{"none", "sun", "16 auto", "64 auto", "64 hardware"}));
  const auto cpu = buildSuite("shadows", SuiteOptions{.cpuDevice = true});
  EXPECT_EQ(cpu.size(), 2 * techniques + 5 + 4 * techniques + 5 * techniques + 4);
  for (const Scenario& s : cpu) EXPECT_NE(s.settings.shadowRaster, RasterChoice::Compute) << s.name;
}

// Splits one CSV line, honouring quoted fields (device names hold commas).
std::vector<std::string> csvFields(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (c == '"' && quoted && i + 1 < line.size() && line[i + 1] == '"')
      fields.back() += line[++i];
    else if (c == '"')
      quoted = !quoted;
    else if (c == ',' && !quoted)
      fields.emplace_back();
    else
      fields.back() += c;
  }
  return fields;
}

std::string readText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

bool gnuplotInstalled() {
  return std::system("command -v gnuplot >/dev/null 2>&1") == 0;
}

void expectPng(const fs::path& path) {
  const std::string bytes = readText(path);
  ASSERT_GE(bytes.size(), 8u) << path;
  EXPECT_EQ(bytes.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8)) << path;
}

fs::path freshDir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("lll-{}-{}", name, getpid());
  fs::remove_all(dir);
  return dir;
}

// Every CSV row: its key (scenario, technique, fill), with times checked on the way.
std::map<std::string, size_t> checkCsv(const fs::path& path, const Context& context) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line,
            "suite,scenario,scene,lights,width,height,technique,fill,tile,pass,median_ms,min_ms,max_ms,"
            "memory_bytes,psnr_vs_forward_db,p999_vs_forward,max_vs_forward,device,driver,commit,date");
  std::map<std::string, size_t> rows;
  while (std::getline(in, line)) {
    const auto f = csvFields(line);
    EXPECT_EQ(f.size(), 21u) << line;
    if (f.size() != 21) continue;
    const double median = std::stod(f[10]), min = std::stod(f[11]), max = std::stod(f[12]);
    EXPECT_TRUE(std::isfinite(median) && min > 0.0 && min <= median && median <= max) << line;
    EXPECT_GE(std::stod(f[13]), 4.0 * std::stod(f[4]) * std::stod(f[5])) << "memory holds the depth";
    // Every technique but forward itself is compared with forward's frame of the same scenario.
    if (f[6] == "forward")
      EXPECT_EQ(f[14], "") << line;
    else
      EXPECT_GE(std::stod(f[14]), 45.0) << line;
    EXPECT_EQ(f[17], context.info().name);
    EXPECT_EQ(f[19], gitCommit());
    ++rows[f[1] + "|" + f[6] + "|" + f[7] + "|" + f[8]];
  }
  return rows;
}

TEST(BenchQuick, ThreelSuiteWritesOneCsvRowPerScenarioAndPass) {
  Context& context = test::gpuContext();
  const size_t before = context.validationMessages().size();
  BenchOptions options;
  options.suites = {"threel"};
  options.quick = true;
  const BenchReport report = runBench(context, options);
  const fs::path dir = freshDir("bench-test");
  writeReport(report, dir);

  ASSERT_EQ(report.results.size(), 32u);  // 28 at ThreeL's tile 8, lll/compute at its own tile
  std::map<std::string, size_t> expectedRows;
  for (const ScenarioResult& r : report.results) {
    const std::string& technique = r.scenario.settings.technique;
    const bool built = std::any_of(techniques().begin(), techniques().end(),
                                   [&](const TechniqueInfo& t) { return t.name == technique; });
    EXPECT_EQ(r.status, built ? Status::Ok : Status::Skipped) << r.scenario.name << ": " << r.message;
    if (r.status != Status::Ok) continue;
    EXPECT_NE(r.pass("frame"), nullptr);
    EXPECT_NE(r.pass("alu-probe"), nullptr) << "ThreeL's scenarios time the ALU roofline probe beside them";
    EXPECT_EQ(r.lightCount, r.scenario.scene.scene == "threel16" ? 16u : 256u);
    const std::string fill = bench::lllVariant(r.scenario.settings);
    if (technique == "lll") {
      EXPECT_GT(r.memory.size(), 1u) << "the link pool and heads, not only depth";
    }
    expectedRows[r.scenario.name + "|" + technique + "|" + fill + "|" +
                 std::to_string(tileSizeFor(r.scenario.settings))] = r.passes.size();
  }
  EXPECT_GE(expectedRows.size(), 4u);  // forward at least, in all four scene x size
  EXPECT_EQ(checkCsv(dir / "results.csv", context), expectedRows);

  const auto json = nlohmann::json::parse(readText(dir / "results.json"));
  EXPECT_EQ(json["device"], context.info().name);
  EXPECT_EQ(json["commit"], gitCommit());
  ASSERT_EQ(json["results"].size(), 32u);
  for (const auto& r : json["results"]) {
    EXPECT_EQ(r["driver"], context.info().driver);
    EXPECT_FALSE(r["date"].get<std::string>().empty());
    if (r["status"] == "ok") {
      EXPECT_GE(r["memory"]["depth_bytes"].get<double>(), 4.0 * 32 * 18);
      // Every technique but forward is compared with forward's frame of the same scenario.
      if (r["technique"] == "forward") {
        EXPECT_TRUE(r["vs_forward"].is_null());
        continue;
      }
      ASSERT_TRUE(r["vs_forward"].is_object()) << r["label"];
      if (r["vs_forward"]["psnr_db"].is_number()) {
        EXPECT_GE(r["vs_forward"]["psnr_db"].get<double>(), 45.0);
      }
      EXPECT_LE(r["vs_forward"]["max"].get<int>(), 16) << r["label"];
    }
  }
  const std::string summary = readText(dir / "summary.md");
  EXPECT_NE(summary.find(context.info().name), std::string::npos);
  EXPECT_NE(summary.find("| forward |"), std::string::npos);
  EXPECT_NE(summary.find("Image against forward's frame"), std::string::npos);
  EXPECT_NE(summary.find("Opaque shading against the ALU-only probe"), std::string::npos);
  if (gnuplotInstalled()) expectPng(dir / "threel.png");
  test::expectNoValidationMessagesSince(before);
  fs::remove_all(dir);
}

// The smoke suite really runs: forward's quick scenarios draw the settled plume and time every
// particle pass; the particle buffers are not counted as lighting memory.
TEST(BenchQuick, SmokeSuiteTimesTheParticlePasses) {
  Context& context = test::gpuContext();
  const size_t before = context.validationMessages().size();
  BenchOptions options;
  options.suites = {"smoke"};
  options.techniques = {"forward"};
  options.quick = true;
  const BenchReport report = runBench(context, options);
  ASSERT_EQ(report.results.size(), 11u);
  for (const ScenarioResult& r : report.results) {
    ASSERT_EQ(r.status, Status::Ok) << r.scenario.name << ": " << r.message;
    for (const char* pass : {"particles-simulate", "particles-sort", "particles-indirect"})
      EXPECT_NE(r.pass(pass), nullptr) << r.scenario.name << " has no " << pass;
    const bool compute = r.scenario.settings.particleRender == ParticleRender::Compute;
    EXPECT_EQ(r.pass("particles-draw") != nullptr, !compute) << r.scenario.name;
    EXPECT_EQ(r.pass("particles-bin") != nullptr, compute) << r.scenario.name;
    EXPECT_EQ(r.pass("particles-composite") != nullptr, compute) << r.scenario.name;
    EXPECT_EQ(r.pass("particles-light") != nullptr,
              r.scenario.settings.particleLighting != ParticleLighting::Pixel);
    double alive = 0.0;
    for (const auto& [key, value] : r.techniqueStats)
      if (key == "particles_alive") alive = value;
    // Settled: the slots are in use (the smoke spawns count / 6 a second; its puffs live 4 to 6 s).
    EXPECT_GT(alive, 0.6 * r.scenario.settings.particleCount) << r.scenario.name;
    for (const auto& [key, value] : r.memory) EXPECT_FALSE(key.starts_with("particle")) << key;
  }
  test::expectNoValidationMessagesSince(before);
}

ScenarioResult fakeResult(const std::string& suite, const std::string& name, const std::string& technique,
                          uint32_t lights, std::vector<PassSummary> passes) {
  ScenarioResult r;
  r.scenario.suite = suite;
  r.scenario.name = name;
  r.scenario.scene.scene = "atrium";
  r.scenario.settings.technique = technique;
  r.lightCount = lights;
  r.passes = std::move(passes);
  r.memory = {{"depth_bytes", 8.0e6}, {"link_pool_bytes", 1.0e6 * lights}};
  return r;
}

// Charts from made-up numbers, with techniques that may not be built yet.
BenchReport syntheticReport() {
  BenchReport report;
  report.suites = {"scaling", "density", "threel", "tiles"};
  for (const uint32_t lights : {16u, 256u, 4096u}) {
    const double l = lights;
    report.results.push_back(fakeResult("scaling", fmt::format("{} lights", lights), "forward", lights,
                                        {{"frame", 0.1 * l, 0.09 * l, 0.12 * l}}));
    report.results.push_back(fakeResult("scaling", fmt::format("{} lights", lights), "lll", lights,
                                        {{"frame", 2.0 + 0.01 * l, 1.9 + 0.01 * l, 2.2 + 0.01 * l}}));
  }
  for (const char* name : {"threel16 1920x1080", "threel16 3840x2160"}) {
    report.results.push_back(
        fakeResult("threel", name, "forward", 16,
                   {{"depth-prepass", 1, 1, 1}, {"forward-opaque", 8, 8, 9}, {"frame", 9, 9, 10}}));
    report.results.push_back(fakeResult(
        "threel", name, "lll", 16,
        {{"depth-prepass", 1, 1, 1}, {"lll-fill", 2, 2, 2}, {"lll-shade", 3, 3, 3}, {"frame", 6, 6, 6}}));
  }
  for (const uint32_t lights : {1024u, 65536u}) {
    const double l = lights / 1024.0;
    report.results.push_back(fakeResult("density", fmt::format("{} lights", lights), "forward", lights,
                                        {{"visibility", 0.5, 0.5, 0.5},
                                         {"shade-opaque", 2.0 * l, 2.0 * l, 2.0 * l},
                                         {"glass", 1.0 * l, 1.0 * l, 1.0 * l},
                                         {"frame", 3.5 * l, 3.4 * l, 3.6 * l}}));
    report.results.push_back(fakeResult("density", fmt::format("{} lights", lights), "tiled", lights,
                                        {{"visibility", 0.5, 0.5, 0.5},
                                         {"grid-count", 0.2 * l, 0.2 * l, 0.2 * l},
                                         {"shade-opaque", 0.3 * l, 0.3 * l, 0.3 * l},
                                         {"frame", 1.0 + 0.5 * l, 1.0 + 0.5 * l, 1.0 + 0.5 * l}}));
  }
  for (const uint32_t tile : {1u, 2u, 4u, 8u, 16u}) {
    ScenarioResult r = fakeResult("tiles", fmt::format("tile {}", tile), "lll", 1024,
                                  {{"frame", 4.0 + 8.0 / tile, 4.0, 5.0 + 8.0 / tile}});
    r.scenario.settings.tileSize = tile;
    r.memory = {{"link_pool_bytes", 64.0e6 / (tile * tile)}};
    report.results.push_back(r);
  }
  return report;
}

TEST(BenchCharts, EverySuiteWithResultsGetsAValidPng) {
  const fs::path dir = freshDir("bench-charts");
  fs::create_directories(dir);
  const auto charts = writeCharts(syntheticReport(), dir);
  EXPECT_TRUE(fs::exists(dir / "charts.gp"));
  if (gnuplotInstalled()) {
    EXPECT_EQ(charts.size(), 6u);
    for (const fs::path& png : {dir / "scaling.png", dir / "density.png", dir / "density-passes.png",
                                dir / "density-memory.png", dir / "threel.png", dir / "tiles.png"})
      expectPng(png);
  }
  // The per-pass density chart: a technique's own passes (tiled's grid-count) and its shading,
  // never a surface pass, and no series for what a technique lacks (forward has no own passes).
  std::ifstream data(dir / "density-passes.dat");
  const std::string text((std::istreambuf_iterator<char>(data)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("# tiled: own passes"), std::string::npos) << text;
  EXPECT_NE(text.find("\n65536 12.8 12.8 12.8\n"), std::string::npos) << text;  // grid-count 0.2 x 64
  EXPECT_EQ(text.find("# forward: own passes"), std::string::npos) << text;
  EXPECT_NE(text.find("\n1024 3 3 3\n"), std::string::npos) << text;  // forward: shade-opaque + glass
  fs::remove_all(dir);
}

// --replot: results.json holds what the charts need; reading it back gives the same charts.
TEST(BenchCharts, ReplotReadsWhatResultsJsonWrote) {
  const fs::path dir = freshDir("bench-replot");
  fs::create_directories(dir);
  BenchReport written = syntheticReport();
  written.device.name = "test device";
  written.device.driver = "test driver";
  written.commit = "abc";
  writeResultsJson(written, dir / "results.json");
  const BenchReport read = readResultsJson(dir / "results.json");
  EXPECT_EQ(read.suites, written.suites);
  EXPECT_EQ(read.device.name, "test device");
  ASSERT_EQ(read.results.size(), written.results.size());
  for (size_t i = 0; i < read.results.size(); ++i) {
    const ScenarioResult &a = read.results[i], &b = written.results[i];
    EXPECT_EQ(a.scenario.suite, b.scenario.suite);
    EXPECT_EQ(techniqueLabel(a.scenario.settings), techniqueLabel(b.scenario.settings));
    EXPECT_EQ(a.scenario.settings.surfaces, b.scenario.settings.surfaces);
    EXPECT_EQ(a.scenario.settings.raster, b.scenario.settings.raster);
    EXPECT_EQ(a.scenario.settings.glass, b.scenario.settings.glass);
    EXPECT_EQ(a.lightCount, b.lightCount);
    EXPECT_DOUBLE_EQ(a.memoryBytes(), b.memoryBytes());
    ASSERT_EQ(a.passes.size(), b.passes.size());
    for (size_t p = 0; p < a.passes.size(); ++p) {
      EXPECT_EQ(a.passes[p].name, b.passes[p].name);
      EXPECT_DOUBLE_EQ(a.passes[p].medianMs, b.passes[p].medianMs);
    }
  }
  const auto charts = writeCharts(read, dir);
  if (gnuplotInstalled()) {
    EXPECT_EQ(charts.size(), 6u);
  }
  fs::remove_all(dir);
}

// An option's name that is none of its choices (a hand-edited file, a newer lll's) is bad input
// naming the file, the field, the value and the choices.
TEST(BenchCharts, AnUnknownOptionNameInResultsJsonIsBadInput) {
  const fs::path dir = freshDir("bench-replot-option");
  fs::create_directories(dir);
  writeResultsJson(syntheticReport(), dir / "results.json");
  nlohmann::json j = nlohmann::json::parse(readText(dir / "results.json"));
  ASSERT_FALSE(j.at("results").empty());
  j["results"][0]["surfaces"] = "mesh-shaders";
  std::ofstream(dir / "results.json") << j.dump();
  try {
    readResultsJson(dir / "results.json");
    ADD_FAILURE() << "read an unknown --surfaces";
  } catch (const InputError& e) {
    for (const std::string& named : {(dir / "results.json").string(), std::string("surfaces"),
                                     std::string("mesh-shaders"), std::string("visibility or gbuffer")})
      EXPECT_NE(std::string(e.what()).find(named), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

TEST(BenchCli, ReplotOfABrokenResultsFileIsBadInputNamingIt) {
  const fs::path dir = freshDir("bench-replot-broken");
  fs::create_directories(dir);
  std::ofstream(dir / "results.json") << "{\"device\": 3";
  const test::CliResult r = test::runLll({"bench", "--replot", dir.string()});
  EXPECT_EQ(r.exitCode, 2) << r;
  EXPECT_NE(r.output.find((dir / "results.json").string()), std::string::npos) << r;
  EXPECT_FALSE(fs::exists(dir / "charts.gp"));
  fs::remove_all(dir);
}

TEST(BenchCli, UnknownSuiteIsBadInputNamingTheKnownSuites) {
  const test::CliResult r = test::runLll({"bench", "--suite", "nope", "--out", "/dev/null"});
  EXPECT_EQ(r.exitCode, 2) << r;
  EXPECT_NE(r.output.find("threel"), std::string::npos) << r;
  EXPECT_NE(r.output.find("scaling"), std::string::npos) << r;
}

}  // namespace
}  // namespace lll::bench
