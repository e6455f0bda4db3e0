// Replays every input that ever broke the glTF loader (tests/fuzz-regressions/, see its README):
// reject-* must be refused naming the file, repair-* must load with a warning, and nothing may
// crash or load into a scene that breaks an invariant.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "core/errors.h"
#include "scene/gltf_loader.h"
#include "scene_invariants.h"

namespace lll {
namespace {

namespace fs = std::filesystem;

TEST(FuzzRegressions, EveryInputThatOnceFailedIsHandled) {
  size_t replayed = 0;
  for (const auto& entry : fs::directory_iterator(LLL_FUZZ_REGRESSIONS_DIR)) {
    const std::string name = entry.path().filename().string();
    if (entry.path().extension() == ".md") continue;
    ++replayed;
    SCOPED_TRACE(name);
    LoadReport report;
    try {
      const Scene scene = loadGltf(entry.path(), &report);
      EXPECT_NE(name.rfind("reject-", 0), 0u) << "loaded, but must be refused";
      EXPECT_EQ(test::sceneInvariantViolation(scene), "");
      if (name.rfind("repair-", 0) == 0) {
        EXPECT_FALSE(report.warnings.empty()) << "repaired without a warning";
      }
    } catch (const InputError& e) {
      EXPECT_EQ(name.rfind("repair-", 0), std::string::npos)
          << "refused, but glTF allows a repair: " << e.what();
      EXPECT_NE(std::string(e.what()).find(entry.path().string()), std::string::npos) << e.what();
    }
  }
  EXPECT_GE(replayed, 12u);
}

}  // namespace
}  // namespace lll
