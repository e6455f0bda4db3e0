// Hostile values for every option of the `lll` command line (issue 16): each ends in exit code 2
// with a message naming the option, never in a crash; a failed run leaves no output behind, a
// finished one no temporary; `lll bench` checks --out before running and, when interrupted,
// leaves valid results for the scenarios that finished.
#include <gtest/gtest.h>

#include <csignal>
#include <set>
#include <string>
#include <vector>

#include "cli_test_support.h"
#include "test_presets_json.h"

namespace lll {
namespace {

using namespace lll::test;

// The names of the files in `dir`.
std::set<std::string> filesIn(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.insert(entry.path().filename().string());
  return names;
}

// Values no numeric option takes: not numbers, not finite, negative, beyond 64 bits, empty.
const std::vector<std::string> kHostileNumbers = {
    "abc", "nan", "NaN", "inf", "-inf", "-1", "1e999", "18446744073709551616", "0x", "", "1,5", " "};

struct OptionCase {
  std::vector<std::string> command;  // the arguments before the option
  std::string option;
};

class HostileCli : public CliTest {};

TEST_F(HostileCli, EveryNumericOptionRejectsHostileValues) {
  const std::vector<std::string> render = {"render", "plane", "--out", outPng()};
  const std::vector<std::string> particles = {"render", "atrium", "--out", outPng(), "--particles", "smoke"};
  const std::vector<std::string> bench = {"bench",   "--suite", "threel",
                                          "--quick", "--out",   (dir_ / "b").string()};
  const std::vector<OptionCase> cases = {
      {render, "--width"},          {render, "--height"},
      {render, "--lights"},         {render, "--seed"},
      {render, "--frames"},         {render, "--exposure"},
      {render, "--ambient"},        {render, "--light-range-scale"},
      {render, "--tile"},           {particles, "--particle-count"},
      {render, "--lll-slices"},     {{"lll-memory"}, "--lll-slices"},
      {render, "--cascades"},       {render, "--shadow-resolution"},
      {bench, "--frames"},          {bench, "--warmup"},
      {bench, "--particle-count"},  {{"lll-memory"}, "--width"},
      {{"lll-memory"}, "--height"}, {{"lll-memory"}, "--links-per-tile"},
      {{"lll-memory"}, "--tile"},   {render, "--time"},
  };
  for (const OptionCase& c : cases) {
    for (const std::string& value : kHostileNumbers) {
      std::vector<std::string> args = c.command;
      args.insert(args.end(), {c.option, value});
      const CliResult r = runLll(args);
      EXPECT_EQ(r.exitCode, 2) << c.option << " '" << value << "': " << r;
      EXPECT_TRUE(contains(r.output, c.option)) << c.option << " '" << value << "' not named: " << r;
    }
  }
  EXPECT_FALSE(fs::exists(outPng()));
  EXPECT_FALSE(fs::exists(dir_ / "b" / "results.json"));
}

// Every option that takes a word, with values none of them takes, and every output path with
// values that name no file that can be written: a crash, a hang or an exit other than 2 fails.
TEST_F(HostileCli, EveryWordOptionRejectsHostileValues) {
  const std::string longWord(5000, 'x');
  const std::vector<std::string> words = {"nosuch", "",         "-",      "nan",
                                          "1e999",  "\xff\xfe", longWord, (dir_ / "missing" / "x").string()};
  const std::vector<std::string> render = {"render", "plane", "--out", outPng()};
  const std::vector<std::string> particles = {"render", "atrium", "--out", outPng(), "--particles", "smoke"};
  const std::vector<OptionCase> cases = {
      {render, "--technique"},
      {render, "--camera"},
      {render, "--device"},
      {render, "--lll-fill"},
      {render, "--lll-link"},
      {render, "--lll-records"},
      {render, "--lll-shade"},
      {render, "--light-motion"},
      {render, "--debug-view"},
      {render, "--deferred-translucent"},
      {render, "--aa"},
      {render, "--particles"},
      {particles, "--particle-lighting"},
      {particles, "--particle-render"},
      {particles, "--particle-resolution"},
      {particles, "--particle-tile-groups"},
      {particles, "--particle-emitter"},
      {render, "--surfaces"},
      {render, "--glass"},
      {render, "--raster"},
      {render, "--gi"},
      {render, "--vpl-hierarchy"},
      {render, "--shadows"},
      {render, "--shadow-filter"},
      {render, "--shadow-raster"},
      {{"bench", "--quick"}, "--suite"},
      {{"bench", "--quick", "--suite", "threel"}, "--technique"},
      {{"lll-memory"}, "--link"},
      {{"reference", "cornell", "--out", outPng()}, "--vpls"},
  };
  for (const OptionCase& c : cases) {
    for (const std::string& value : words) {
      std::vector<std::string> args = c.command;
      args.insert(args.end(), {c.option, value});
      const CliResult r = runLll(args);
      EXPECT_EQ(r.exitCode, 2) << c.option << " '" << value.substr(0, 40) << "': " << r;
    }
  }
  const std::vector<std::string> paths = {"", (dir_ / "missing" / "x.png").string(), longWord + ".png",
                                          dir_.string(), "/proc/self/x.png"};
  for (const std::string option : {"--out", "--hdr", "--stats"}) {
    for (const std::string& path : paths) {
      const CliResult r = runLll({"render", "plane", "--width", "8", option, path});
      EXPECT_EQ(r.exitCode, 2) << option << " '" << path.substr(0, 40) << "': " << r;
    }
  }
  EXPECT_FALSE(fs::exists(outPng()));
}

TEST_F(HostileCli, SeedIsAnyThirtyTwoBitNumber) {
  expectBadInput(render("plane", {"--seed", "abc"}), {"--seed", "abc"});
  expectBadInput(render("plane", {"--seed", "4294967296"}), {"--seed", "4294967296"});
  const CliResult r = render("plane", {"--lights", "3", "--seed", "4294967295"});
  EXPECT_EQ(r.exitCode, 0) << r;
  EXPECT_TRUE(fs::exists(outPng()));
}

TEST_F(HostileCli, NanExposureAndAmbient) {
  expectBadInput(render("plane", {"--exposure", "nan"}), {"--exposure", "nan", "not a finite number"});
  expectBadInput(render("plane", {"--ambient", "nan"}), {"--ambient", "nan", "not a finite number"});
  expectBadInput(render("plane", {"--ambient", "inf"}), {"--ambient", "inf"});
}

TEST_F(HostileCli, ParticleOptionsNeedParticles) {
  expectBadInput(render("atrium", {"--particle-emitter", "0,1,0"}), {"--particle-emitter", "--particles"});
  expectBadInput(render("atrium", {"--particle-count", "64"}), {"--particle-count", "--particles"});
  expectBadInput(render("atrium", {"--particle-lighting", "vertex"}), {"--particle-lighting", "--particles"});
}

TEST_F(HostileCli, HostileCameraAndEmitterPositions) {
  expectBadInput(render("plane", {"--camera", "nan,0,0,0,0,0"}), {"--camera"});
  expectBadInput(render("plane", {"--camera", "1e39,0,0,0,0,0"}), {"--camera"});
  expectBadInput(render("plane", {"--camera", "3e38,0,0,-3e38,0,0"}), {"camera", "not finite"});
  expectBadInput(render("atrium", {"--particles", "smoke", "--particle-emitter", "0,inf,0"}),
                 {"--particle-emitter"});
  expectBadInput(render("plane", {"--device", "99999999999999999999999"}), {"--device"});
}

// ---- outputs: all or nothing ----

TEST_F(HostileCli, UnwritableHdrLeavesNoPng) {
  // /proc/self takes no new files, even for root (the CI user).
  expectBadInput(render("plane", {"--hdr", "/proc/self/out.pfm"}), {"--hdr", "/proc/self/out.pfm"});
  EXPECT_TRUE(filesIn(dir_).empty());
}

TEST_F(HostileCli, UnwritableStatsLeavesNoPng) {
  expectBadInput(render("plane", {"--stats", "/proc/self/stats.json"}), {"--stats", "/proc/self/stats.json"});
  EXPECT_TRUE(filesIn(dir_).empty());
}

TEST_F(HostileCli, EmptyOutputPathIsAnError) {
  expectBadInput(runLll({"render", "plane", "--out", ""}), {"--out", "empty"});
  expectBadInput(render("plane", {"--stats", ""}), {"--stats", "empty"});
  EXPECT_TRUE(filesIn(dir_).empty());
}

TEST_F(HostileCli, TwoOutputsToOneFile) {
  expectBadInput(render("plane", {"--stats", outPng()}), {"--stats", "--out"});
}

TEST_F(HostileCli, OutputThatIsAFolder) {
  fs::create_directories(dir_ / "folder.png");
  expectBadInput(runLll({"render", "plane", "--out", (dir_ / "folder.png").string()}),
                 {"folder.png", "folder"});
}

TEST_F(HostileCli, FinishedRenderLeavesOnlyItsOutputs) {
  const CliResult r =
      render("plane", {"--hdr", (dir_ / "out.pfm").string(), "--stats", (dir_ / "out.json").string()});
  ASSERT_EQ(r.exitCode, 0) << r;
  EXPECT_EQ(filesIn(dir_), (std::set<std::string>{"out.png", "out.pfm", "out.json"}));
}

// ---- particle presets ----

TEST_F(HostileCli, PresetWithADuplicateKey) {
  const fs::path path = dir_ / "twice.json";
  std::string text = test::stillPreset().dump();
  text.insert(1, "\"drag\": 5, ");  // the preset's own "drag" follows
  std::ofstream(path) << text;
  expectBadInput(render("atrium", {"--particles", path.string()}), {path.string(), "\"drag\"", "twice"});
}

TEST_F(HostileCli, PresetObjectFieldOfTheWrongType) {
  for (const auto& [field, value] : std::vector<std::pair<std::string, json>>{
           {"emitter", 5}, {"velocity", json::array({1, 2})}, {"floor", "bounce"}}) {
    json preset = test::stillPreset();
    preset[field] = value;
    const fs::path path = dir_ / (field + ".json");
    std::ofstream(path) << preset.dump();
    const CliResult r = render("atrium", {"--particles", path.string()});
    expectBadInput(r, {path.string(), "\"" + field + "\" must be an object"});
    EXPECT_FALSE(contains(r.output, "\"" + field + ".")) << r;
    EXPECT_FALSE(contains(r.output, "is not a preset field")) << r;
  }
}

// ---- bench ----

TEST_F(HostileCli, BenchOutThatIsAFileFailsBeforeRunning) {
  const fs::path file = dir_ / "results";
  std::ofstream(file) << "not a folder";
  const CliResult r = runLll({"bench", "--suite", "threel", "--quick", "--out", file.string()});
  EXPECT_EQ(r.exitCode, 2) << r;
  EXPECT_TRUE(contains(r.output, file.string())) << r;
  EXPECT_FALSE(contains(r.output, "threel16")) << "a scenario ran before --out was checked: " << r;
}

TEST_F(HostileCli, BenchOutThatCannotBeCreatedFailsBeforeRunning) {
  const CliResult r = runLll({"bench", "--suite", "threel", "--quick", "--out", "/proc/self/bench"});
  EXPECT_EQ(r.exitCode, 2) << r;
  EXPECT_TRUE(contains(r.output, "/proc/self/bench")) << r;
  EXPECT_FALSE(contains(r.output, "threel16")) << r;
}

// SIGINT once the first scenario's results are on disk: the run stops, finishes its files with the
// scenarios done and exits 130; results.json and results.csv agree and say it was interrupted.
TEST_F(HostileCli, InterruptedBenchLeavesValidPartialResults) {
  const fs::path out = dir_ / "bench";
  bool interrupted = false;
  const CliResult r =
      runLll({"bench", "--suite", "threel", "--quick", "--frames", "200", "--out", out.string()}, {},
             std::chrono::seconds(240), [&](pid_t pid) {
               if (!interrupted && fs::exists(out / "results.json")) {
                 interrupted = true;
                 kill(pid, SIGINT);
               }
             });
  ASSERT_TRUE(interrupted) << "results.json never appeared while the bench ran: " << r;
  EXPECT_EQ(r.exitCode, 130) << r;
  const json results = json::parse(readFile(out / "results.json"));
  EXPECT_TRUE(results.at("interrupted").get<bool>());
  const size_t done = results.at("results").size();
  EXPECT_GE(done, 1u);
  EXPECT_LT(done, 20u) << "the whole suite ran: the interrupt came too late to test anything";
  size_t csvRows = 0, passes = 0;
  std::istringstream csv(readFile(out / "results.csv"));
  for (std::string line; std::getline(csv, line);) ++csvRows;
  for (const json& result : results.at("results")) passes += result.at("passes").size();
  EXPECT_EQ(csvRows, passes + 1) << "one CSV row per pass, plus the header";
  EXPECT_TRUE(contains(readFile(out / "summary.md"), "interrupted"));
  for (const std::string& name : filesIn(out)) EXPECT_NE(name[0], '.') << "temporary left behind: " << name;
}

}  // namespace
}  // namespace lll
