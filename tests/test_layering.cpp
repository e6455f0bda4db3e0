// The folders of src/ are layers (README.md, "How it is built"): a file includes headers of its own
// folder, of shaders/shared/, and of lower layers only. So the frame's shared code (render/) knows
// nothing of the techniques, the particles or the shadows that plug into it, and a technique
// nothing of another's code or of the particles'.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace lll {
namespace {

namespace fs = std::filesystem;

// scene/ and gi/ are one layer: the scene loader adds the virtual point lights that gi/ traces
// (scene/scene_source.h), and gi/ traces photons through the scene's types.
const std::map<std::string, int> kLayers = {
    {"core", 0},     {"gpu", 1},       {"scene", 2},    {"gi", 2},    {"render", 3}, {"shadows", 4},
    {"lighting", 5}, {"particles", 5}, {"renderer", 6}, {"bench", 7}, {"view", 7},   {"app", 8},
};

bool allowed(const std::string& from, const std::string& to) {
  if (to == from || to == "shared") return true;
  if ((from == "scene" && to == "gi") || (from == "gi" && to == "scene")) return true;
  const auto target = kLayers.find(to);
  return target != kLayers.end() && target->second < kLayers.at(from);
}

TEST(Layering, EveryIncludeReachesItsOwnFolderOrALowerLayer) {
  const fs::path src = fs::path(LLL_SOURCE_DIR) / "src";
  ASSERT_TRUE(fs::is_directory(src)) << src;
  const std::regex include(R"(^\s*#\s*include\s+"([a-z_]+)/)");
  std::vector<std::string> wrong;
  std::set<std::string> folders;
  size_t includes = 0;
  for (const fs::directory_entry& entry : fs::recursive_directory_iterator(src)) {
    if (!entry.is_regular_file()) continue;
    const fs::path relative = fs::relative(entry.path(), src);
    if (relative.begin() == relative.end() || std::next(relative.begin()) == relative.end())
      continue;  // src/lll.h
    const std::string folder = relative.begin()->string();
    folders.insert(folder);
    std::ifstream in(entry.path());
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
      std::smatch match;
      if (!std::regex_search(line, match, include)) continue;
      ++includes;
      if (!kLayers.contains(folder) || !allowed(folder, match[1].str()))
        wrong.push_back(relative.string() + ":" + std::to_string(number) + ": " + line);
    }
  }
  EXPECT_GT(includes, 300u) << "the sources were not read";
  for (const std::string& folder : folders)
    EXPECT_TRUE(kLayers.contains(folder)) << "src/" << folder << "/ has no layer: add it to kLayers";
  for (const std::string& w : wrong) ADD_FAILURE() << "includes a folder of its own layer or above: " << w;
}

TEST(Layering, TheRuleRefusesWhatItShould) {
  EXPECT_TRUE(allowed("lighting", "render"));
  EXPECT_TRUE(allowed("render", "shared"));
  EXPECT_FALSE(allowed("render", "lighting"));
  EXPECT_FALSE(allowed("lighting", "particles"));  // one layer: neither knows the other
  EXPECT_FALSE(allowed("render", "renderer"));
  EXPECT_FALSE(allowed("gpu", "scene"));
  EXPECT_FALSE(allowed("core", "nosuch"));
}

}  // namespace
}  // namespace lll
