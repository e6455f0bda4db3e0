// The `lll` command line, run as a child process: every kind of bad input ends in exit code 2 and a
// message that names the input, never in a crash, a hang or a half-written image; a good render
// writes a valid PNG, PFM and stats JSON; the listing and lll-memory subcommands print what they
// promise.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_test_support.h"
#include "test_presets_json.h"

namespace lll {
namespace {

using namespace lll::test;

// ---- scene files ----

TEST_F(CliTest, MissingFile) {
  const std::string path = (dir_ / "nowhere.gltf").string();
  expectBadInput(render(path), {path, "cannot read"});
}

TEST_F(CliTest, NotGltf) {
  const fs::path path = dir_ / "notes.gltf";
  std::ofstream(path) << "These are not the triangles you are looking for.\n";
  expectBadInput(render(path.string()), {"notes.gltf", "not a glTF file"});
}

TEST_F(CliTest, InvalidJson) {
  const fs::path path = dir_ / "broken.gltf";
  std::ofstream(path) << R"({"asset": {"version": "2.0"}, "meshes": [{"primitives": [)";
  expectBadInput(render(path.string()), {"broken.gltf", "not a valid glTF"});
}

TEST_F(CliTest, TruncatedBin) {
  const QuadGltf quad;
  expectBadInput(render(quad.write(dir_, "truncated", quad.bin.size() - 5).string()), {"truncated.gltf"});
}

TEST_F(CliTest, MissingBin) {
  const fs::path path = QuadGltf().write(dir_, "nobin");
  fs::remove(dir_ / "quad.bin");
  expectBadInput(render(path.string()), {"nobin.gltf"});
}

TEST_F(CliTest, AccessorOutOfRange) {
  QuadGltf quad;
  quad.doc["accessors"][0]["count"] = 40;  // 40 positions in a 48-byte view
  expectBadInput(render(quad.write(dir_, "accessor").string()), {"accessor.gltf", "accessor 0"});
}

TEST_F(CliTest, IndexOutOfRange) {
  QuadGltf quad;
  const uint16_t badIndex = 7;  // the quad has 4 vertices
  std::memcpy(quad.bin.data() + 48 + 2, &badIndex, sizeof(badIndex));
  expectBadInput(render(quad.write(dir_, "index").string()), {"index.gltf", "7"});
}

TEST_F(CliTest, UnsupportedRequiredExtension) {
  QuadGltf quad;
  quad.doc["extensionsUsed"] = {"KHR_texture_basisu"};
  quad.doc["extensionsRequired"] = {"KHR_texture_basisu"};
  expectBadInput(render(quad.write(dir_, "basisu").string()), {"basisu.gltf", "KHR_texture_basisu"});
}

TEST_F(CliTest, MissingTextureImageWarnsAndRenders) {
  QuadGltf quad;
  quad.doc["images"] = {{{"uri", "lost-texture.png"}}};
  quad.doc["textures"] = {{{"source", 0}}};
  quad.doc["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
  quad.doc["meshes"][0]["primitives"][0]["material"] = 0;
  const CliResult r = render(quad.write(dir_, "textured").string());
  EXPECT_EQ(r.exitCode, 0) << r;
  EXPECT_TRUE(contains(r.output, "warning")) << r;
  EXPECT_TRUE(contains(r.output, "lost-texture.png")) << r;
  EXPECT_TRUE(contains(r.output, "neutral texture")) << r;
  EXPECT_TRUE(fs::exists(outPng()));
}

TEST_F(CliTest, UnknownSceneListsBuiltins) {
  expectBadInput(render("nosuchscene"), {"nosuchscene", "atrium", "plane"});
}

// ---- options ----

TEST_F(CliTest, ZeroWidth) {
  expectBadInput(runLll({"render", "plane", "--width", "0", "--height", "18", "--out", outPng()}),
                 {"--width", "0"});
}

TEST_F(CliTest, NegativeWidth) {
  expectBadInput(runLll({"render", "plane", "--width", "-5", "--height", "18", "--out", outPng()}),
                 {"--width", "-5"});
}

TEST_F(CliTest, HugeWidth) {
  expectBadInput(runLll({"render", "plane", "--width", "100000", "--height", "18", "--out", outPng()}),
                 {"--width", "100000"});
}

TEST_F(CliTest, ZeroHeight) {
  expectBadInput(runLll({"render", "plane", "--width", "32", "--height", "0", "--out", outPng()}),
                 {"--height", "0"});
}

TEST_F(CliTest, LightsBeyondTheOptionsRange) {
  expectBadInput(render("plane", {"--lights", "20000000"}), {"--lights", "20000000"});
}

TEST_F(CliTest, LightsBeyondTheLightCap) {
  // Within the option's range, but the plane's own light makes it one more than the cap.
  expectBadInput(render("plane", {"--lights", "16777216"}), {"--lights 16777216", "16777217", "at most"});
}

TEST_F(CliTest, LllSlicesBeyondTheMost) {
  expectBadInput(render("plane", {"--technique", "lll", "--lll-slices", "33"}), {"--lll-slices", "33"});
}

TEST_F(CliTest, AbsurdLightRangeScale) {
  expectBadInput(render("plane", {"--lights", "4", "--light-range-scale", "0"}),
                 {"--light-range-scale", "0"});
}

TEST_F(CliTest, UnknownTechniqueListsTechniques) {
  expectBadInput(render("plane", {"--technique", "nosuch"}), {"--technique nosuch", "forward", "lll"});
}

TEST_F(CliTest, UnknownCameraListsCameras) {
  expectBadInput(render("plane", {"--camera", "nosuch"}), {"--camera nosuch", "top"});
}

TEST_F(CliTest, UnknownCommand) {
  const CliResult r = runLll({"paint"});
  EXPECT_EQ(r.exitCode, 2) << r;
  EXPECT_TRUE(contains(r.output, "paint")) << r;
}

TEST_F(CliTest, NoCommand) {
  const CliResult r = runLll({});
  EXPECT_EQ(r.exitCode, 2) << r;
  EXPECT_TRUE(contains(r.output, "command is required")) << r;
  EXPECT_TRUE(contains(r.output, "render")) << r;
}

// ---- output paths: checked before the scene is even loaded ----

TEST_F(CliTest, OutInMissingDirectoryFailsBeforeRendering) {
  const std::string path = (dir_ / "no-such-dir" / "out.png").string();
  // The scene is bad too: naming the path shows it was checked first, before any slow work.
  const CliResult r = runLll({"render", "nosuchscene", "--width", "32", "--height", "18", "--out", path});
  EXPECT_EQ(r.exitCode, 2) << r;
  EXPECT_TRUE(contains(r.output, path)) << r;
  EXPECT_FALSE(contains(r.output, "nosuchscene")) << r;
  EXPECT_FALSE(fs::exists(path));
}

TEST_F(CliTest, OutWithoutPngExtension) {
  const std::string path = (dir_ / "out.jpg").string();
  const CliResult r = runLll({"render", "plane", "--width", "32", "--height", "18", "--out", path});
  EXPECT_EQ(r.exitCode, 2) << r;
  EXPECT_TRUE(contains(r.output, path)) << r;
  EXPECT_FALSE(fs::exists(path));
}

TEST_F(CliTest, HdrWithJpgExtension) {
  const std::string hdr = (dir_ / "out.jpg").string();
  expectBadInput(render("nosuchscene", {"--hdr", hdr}), {"--hdr", hdr, ".pfm"});
  EXPECT_FALSE(fs::exists(hdr));
}

TEST_F(CliTest, StatsInMissingDirectory) {
  const std::string stats = (dir_ / "no-such-dir" / "stats.json").string();
  expectBadInput(render("nosuchscene", {"--stats", stats}), {"--stats", stats});
}

// ---- the environment ----

TEST_F(CliTest, NoVulkanDevice) {
  const CliResult r =
      runLll({"render", "plane", "--width", "32", "--height", "18", "--out", outPng()},
             {{"VK_DRIVER_FILES", "/nonexistent.json"}, {"VK_ICD_FILENAMES", "/nonexistent.json"}});
  expectBadInput(r, {"no Vulkan device"});
}

// ---- a good render ----

uint32_t bigEndian32(const std::string& bytes, size_t offset) {
  uint32_t v = 0;
  for (size_t i = 0; i < 4; ++i) v = v << 8 | uint8_t(bytes[offset + i]);
  return v;
}

TEST_F(CliTest, RenderWritesPngPfmAndStats) {
  const fs::path png = dir_ / "plane.png", pfm = dir_ / "plane.pfm", stats = dir_ / "plane.json";
  const CliResult r = runLll({"render", "plane", "--width", "64", "--height", "36", "--out", png.string(),
                              "--hdr", pfm.string(), "--stats", stats.string(), "--validate"});
  ASSERT_EQ(r.exitCode, 0) << r;

  const std::string pngBytes = readFile(png);
  ASSERT_GE(pngBytes.size(), 24u);
  EXPECT_EQ(pngBytes.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  EXPECT_EQ(pngBytes.substr(12, 4), "IHDR");
  EXPECT_EQ(bigEndian32(pngBytes, 16), 64u);
  EXPECT_EQ(bigEndian32(pngBytes, 20), 36u);

  std::ifstream pfmIn(pfm, std::ios::binary);
  std::string magic;
  uint32_t width = 0, height = 0;
  float scale = 0.0f;
  pfmIn >> magic >> width >> height >> scale;
  pfmIn.get();  // the one whitespace byte before the pixels
  EXPECT_EQ(magic, "PF");
  EXPECT_EQ(width, 64u);
  EXPECT_EQ(height, 36u);
  EXPECT_LT(scale, 0.0f);  // little-endian
  std::vector<float> pixels(size_t(64) * 36 * 3);
  pfmIn.read(reinterpret_cast<char*>(pixels.data()), std::streamsize(pixels.size() * sizeof(float)));
  EXPECT_EQ(size_t(pfmIn.gcount()), pixels.size() * sizeof(float));
  EXPECT_EQ(pfmIn.peek(), EOF) << "bytes after the pixels";
  float brightest = 0.0f;
  for (float v : pixels) {
    ASSERT_TRUE(std::isfinite(v));
    brightest = std::max(brightest, v);
  }
  EXPECT_GT(brightest, 0.01f);

  const json j = json::parse(readFile(stats));
  EXPECT_FALSE(j.at("device").get<std::string>().empty());
  EXPECT_FALSE(j.at("driver").get<std::string>().empty());
  EXPECT_EQ(j.at("width"), 64);
  EXPECT_EQ(j.at("height"), 36);
  EXPECT_EQ(j.at("lights"), 1);  // the plane's one point light
  EXPECT_EQ(j.at("technique"), "forward");
  EXPECT_EQ(j.at("validation_messages"), 0);
  ASSERT_FALSE(j.at("passes").empty());
  for (const json& pass : j.at("passes")) {
    EXPECT_FALSE(pass.at("name").get<std::string>().empty());
    EXPECT_GE(pass.at("median_ms").get<double>(), 0.0) << pass.dump();
  }
}

// A named choice reaches the renderer as the value it names: lll's fill names its pass.
TEST_F(CliTest, ChosenFillNamesItsPass) {
  for (const std::string fill : {"ray", "shells"}) {
    const fs::path stats = dir_ / (fill + ".json");
    const CliResult r =
        render("plane", {"--technique", "lll", "--lll-fill", fill, "--stats", stats.string()});
    ASSERT_EQ(r.exitCode, 0) << r;
    const json j = json::parse(readFile(stats));
    std::vector<std::string> passes;
    for (const json& pass : j.at("passes")) passes.push_back(pass.at("name").get<std::string>());
    EXPECT_NE(std::find(passes.begin(), passes.end(), "lll-fill-" + fill), passes.end())
        << fill << ": " << fmt::format("{}", fmt::join(passes, ", "));
  }
}

// ---- particles ----

// The tests' still preset with one change, written as `name` in the test's folder.
std::string bentPreset(const fs::path& dir, const std::string& name, const std::function<void(json&)>& bend) {
  json preset = test::stillPreset();
  bend(preset);
  const fs::path path = dir / name;
  std::ofstream(path) << preset.dump(2);
  return path.string();
}

TEST_F(CliTest, ParticlePresetMissingField) {
  const std::string preset = bentPreset(dir_, "nospeed.json", [](json& p) { p["velocity"].erase("speed"); });
  expectBadInput(render("atrium", {"--particles", preset}),
                 {"nospeed.json", "\"velocity.speed\"", "missing"});
}

TEST_F(CliTest, ParticlePresetIllTypedField) {
  const std::string preset = bentPreset(dir_, "drag.json", [](json& p) { p["drag"] = "lots"; });
  expectBadInput(render("atrium", {"--particles", preset}), {"drag.json", "\"drag\"", "must be a number"});
}

TEST_F(CliTest, ParticlePresetAbsurdCount) {
  const std::string preset = bentPreset(dir_, "huge.json", [](json& p) { p["count"] = 50000000; });
  expectBadInput(render("atrium", {"--particles", preset}), {"huge.json", "\"count\"", "1 to 1000000"});
}

TEST_F(CliTest, ParticlePresetZeroCount) {
  const std::string preset = bentPreset(dir_, "none.json", [](json& p) { p["count"] = 0; });
  expectBadInput(render("atrium", {"--particles", preset}), {"none.json", "\"count\"", "1 to 1000000"});
}

TEST_F(CliTest, ParticlePresetNotJson) {
  const fs::path path = dir_ / "smoke.json";
  std::ofstream(path) << "{ \"count\": 12,";
  expectBadInput(render("atrium", {"--particles", path.string()}), {"smoke.json", "not valid JSON"});
}

TEST_F(CliTest, UnknownParticlePresetListsBuiltins) {
  expectBadInput(render("atrium", {"--particles", "fog"}), {"--particles fog", "smoke", "sparks", "dust"});
}

TEST_F(CliTest, ParticleCountBeyondTheLimit) {
  expectBadInput(render("atrium", {"--particles", "smoke", "--particle-count", "2000000"}),
                 {"--particle-count", "2000000"});
}

TEST_F(CliTest, UnknownParticleLighting) {
  expectBadInput(render("atrium", {"--particles", "smoke", "--particle-lighting", "texel"}),
                 {"--particle-lighting", "texel"});
}

TEST_F(CliTest, UnknownParticleRender) {
  expectBadInput(render("atrium", {"--particles", "smoke", "--particle-render", "splat"}),
                 {"--particle-render", "splat"});
}

TEST_F(CliTest, RasterParticlesOnlyAtFullResolution) {
  expectBadInput(render("atrium", {"--particles", "smoke", "--particle-render", "raster",
                                   "--particle-resolution", "half"}),
                 {"--particle-resolution half", "compute"});
  expectBadInput(render("atrium", {"--particles", "smoke", "--particle-resolution", "eighth"}),
                 {"--particle-resolution", "eighth"});
}

// Tile groups belong to the compute renderer, 1 to kParticleMaxGroups of them.
TEST_F(CliTest, ParticleTileGroupsOnlyForTheComputeRenderer) {
  expectBadInput(render("atrium", {"--particles", "smoke", "--particle-render", "raster",
                                   "--particle-tile-groups", "4"}),
                 {"--particle-tile-groups 4", "compute"});
  expectBadInput(render("atrium", {"--particles", "smoke", "--particle-tile-groups", "33"}),
                 {"--particle-tile-groups", "33"});
  expectBadInput(render("atrium", {"--particles", "smoke", "--particle-tile-groups", "0"}),
                 {"--particle-tile-groups", "0"});
}

// The sun's shadow options: named with the value when out of range.
TEST_F(CliTest, BadShadowOptions) {
  expectBadInput(render("plane", {"--shadows", "every"}), {"--shadows", "every"});
  expectBadInput(render("plane", {"--shadow-lights", "2000"}), {"--shadow-lights", "2000"});
  expectBadInput(render("plane", {"--shadow-light-resolution", "8"}), {"--shadow-light-resolution", "8"});
  expectBadInput(render("plane", {"--cascades", "5"}), {"--cascades", "5"});
  expectBadInput(render("plane", {"--cascades", "0"}), {"--cascades", "0"});
  expectBadInput(render("plane", {"--shadow-resolution", "8"}), {"--shadow-resolution", "8"});
  expectBadInput(render("plane", {"--shadow-filter", "vsm"}), {"--shadow-filter", "vsm"});
}

TEST_F(CliTest, ParticlesNeedASmokeSourceOrAnEmitter) {
  expectBadInput(render("plane", {"--particles", "smoke"}),
                 {"plane", "no smoke source", "--particle-emitter"});
}

TEST_F(CliTest, ParticleEmitterOfTwoNumbers) {
  expectBadInput(render("plane", {"--particles", "smoke", "--particle-emitter", "1,2"}),
                 {"--particle-emitter 1,2", "x,y,z"});
}

TEST_F(CliTest, SmokeRendersWithTimedParticlePasses) {
  const fs::path stats = dir_ / "smoke.json";
  const CliResult r =
      runLll({"render", "atrium", "--width", "48", "--height", "27", "--out", outPng(), "--particles",
              "smoke", "--particle-count", "300", "--frames", "30", "--stats", stats.string(), "--validate"});
  ASSERT_EQ(r.exitCode, 0) << r;
  EXPECT_TRUE(fs::exists(outPng()));
  const json j = json::parse(readFile(stats));
  std::vector<std::string> passes;
  for (const json& pass : j.at("passes")) passes.push_back(pass.at("name"));
  // The draw: the rasterizer's on a CPU device, the tiles' on a GPU (--particle-render auto).
  const bool compute = j.at("technique_stats").at("particle_render_compute") == 1.0;
  EXPECT_EQ(compute, j.at("device_type") != "cpu") << j.dump();
  std::vector<std::string> expected = {"particles-simulate", "particles-sort", "particles-indirect"};
  if (compute)
    expected.insert(expected.end(), {"particles-bin", "particles-composite"});
  else
    expected.push_back("particles-draw");
  for (const std::string& name : expected)
    EXPECT_NE(std::find(passes.begin(), passes.end(), name), passes.end())
        << name << " not timed: " << j.dump();
  // --frames 30: thirty fixed steps, one frame drawn.
  EXPECT_EQ(j.at("frames"), 1);
  EXPECT_EQ(j.at("technique_stats").at("particle_steps"), 30);
  EXPECT_EQ(j.at("technique_stats").at("particle_slots"), 300);
  // The smoke spawns 300 / 6 (its longest lifetime) particles a second: 25 in half a second, so
  // spawn ids 0 to 24 are alive, none old enough to have died.
  EXPECT_EQ(j.at("technique_stats").at("particles_alive"), 25);
}

// ---- help and listings ----

TEST_F(CliTest, HelpListsSubcommands) {
  const CliResult r = runLll({"--help"});
  EXPECT_EQ(r.exitCode, 0) << r;
  for (const char* command : {"render", "scenes", "techniques", "devices", "bench", "lll-memory"})
    EXPECT_TRUE(contains(r.output, command)) << command << " missing: " << r;
}

TEST_F(CliTest, RenderHelpListsOptions) {
  const CliResult r = runLll({"render", "--help"});
  EXPECT_EQ(r.exitCode, 0) << r;
  for (const char* option :
       {"--technique", "--width", "--lights", "--camera", "--out", "--hdr", "--stats", "--particles",
        "--particle-lighting", "--particle-render", "--particle-count", "--particle-emitter"})
    EXPECT_TRUE(contains(r.output, option)) << option << " missing: " << r;
}

TEST_F(CliTest, ScenesListsTheAtrium) {
  const CliResult r = runLll({"scenes"});
  EXPECT_EQ(r.exitCode, 0) << r;
  EXPECT_TRUE(contains(r.output, "\natrium ") || r.output.rfind("atrium ", 0) == 0) << r;
  EXPECT_TRUE(contains(r.output, "(default)")) << r;
}

TEST_F(CliTest, TechniquesListsForwardAndLll) {
  const CliResult r = runLll({"techniques"});
  EXPECT_EQ(r.exitCode, 0) << r;
  EXPECT_TRUE(r.output.rfind("forward ", 0) == 0) << r;
  EXPECT_TRUE(contains(r.output, "\nlll ")) << r;
}

// ---- lll-memory: the chapter's figures ----

TEST_F(CliTest, LllMemoryPerPixelTiles) {
  const CliResult r = runLll({"lll-memory", "--tile", "1", "--lll-slices", "1"});
  EXPECT_EQ(r.exitCode, 0) << r;
  EXPECT_TRUE(contains(lineStartingWith(r.output, "tiles"), "1920 x 1080 = 2073600")) << r;
  EXPECT_TRUE(contains(lineStartingWith(r.output, "links"), "66355200")) << r;  // 32 per tile
  // 1920 x 1080 x 32 links x 8 bytes: the chapter's 506.25 MB (which are MiB).
  const std::string pool = lineStartingWith(r.output, "link pool");
  EXPECT_TRUE(contains(pool, "530841600 bytes")) << r;
  EXPECT_TRUE(contains(pool, "506.25 MiB")) << r;
  EXPECT_TRUE(contains(lineStartingWith(r.output, "heads"), "8294400 bytes")) << r;
  EXPECT_TRUE(contains(lineStartingWith(r.output, "tile depth"), "16588800 bytes")) << r;  // near, far
  EXPECT_TRUE(contains(lineStartingWith(r.output, "total"), "555724800 bytes")) << r;
}

TEST_F(CliTest, LllMemoryHeadsPerDepthSlice) {
  const CliResult r = runLll({"lll-memory", "--tile", "8", "--lll-slices", "16"});
  EXPECT_EQ(r.exitCode, 0) << r;
  EXPECT_TRUE(contains(lineStartingWith(r.output, "heads"), "2073600 bytes")) << r;  // 32,400 tiles x 16 x 4
  expectBadInput(runLll({"lll-memory", "--lll-slices", "0"}), {"--lll-slices", "0"});
}

TEST_F(CliTest, LllMemoryEighthTiles) {
  const CliResult r = runLll({"lll-memory", "--tile", "8"});
  EXPECT_EQ(r.exitCode, 0) << r;
  EXPECT_TRUE(contains(lineStartingWith(r.output, "tiles"), "240 x 135 = 32400")) << r;
  EXPECT_TRUE(contains(lineStartingWith(r.output, "link pool"), "7.91 MiB")) << r;
}

TEST_F(CliTest, LllMemoryWideLinksAndOtherSizes) {
  const CliResult r = runLll({"lll-memory", "--width", "1000", "--height", "500", "--tile", "16",
                              "--links-per-tile", "10", "--link", "wide"});
  EXPECT_EQ(r.exitCode, 0) << r;
  // ceil(1000 / 16) x ceil(500 / 16) = 63 x 32 tiles, x 10 links x 16 bytes.
  EXPECT_TRUE(contains(lineStartingWith(r.output, "tiles"), "63 x 32 = 2016")) << r;
  EXPECT_TRUE(contains(lineStartingWith(r.output, "link pool"), "322560 bytes")) << r;
  EXPECT_TRUE(contains(lineStartingWith(r.output, "link pool"), "0.31 MiB")) << r;
}

TEST_F(CliTest, LllMemoryRejectsOddTile) {
  const CliResult r = runLll({"lll-memory", "--tile", "3"});
  EXPECT_EQ(r.exitCode, 2) << r;
  EXPECT_TRUE(contains(r.output, "--tile")) << r;
}

}  // namespace
}  // namespace lll
