// The library as other programs use it: installed with `cmake --install`, found by a separate
// project's find_package(lll), the example program (examples/render_gltf/) built against it and
// run; its image must be what `lll render` draws.
#include <gtest/gtest.h>

#include <cstdlib>

#include "cli_test_support.h"
#include "image_bound.h"
#include "render/image_io.h"

namespace lll {
namespace {

namespace fs = std::filesystem;

// Runs a shell command with its output in `log`; returns the exit status.
int shell(const std::string& command, const fs::path& log) {
  const int status = std::system((command + " > '" + log.string() + "' 2>&1").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

class InstalledPackage : public test::CliTest {};

TEST_F(InstalledPackage, BuildsAndRunsTheExampleProgram) {
  const fs::path prefix = dir_ / "prefix", build = dir_ / "example", log = dir_ / "log.txt";
  ASSERT_EQ(shell("cmake --install '" LLL_BUILD_DIR "' --prefix '" + prefix.string() + "'", log), 0)
      << test::readFile(log);
  EXPECT_TRUE(fs::exists(prefix / "include/lll/lll.h"));
  EXPECT_TRUE(fs::exists(prefix / "lib/cmake/lll/lllConfig.cmake"));
  // A project outside the source tree, as a user's: only the install prefix tells it where lll is.
  const fs::path project = dir_ / "render_gltf";
  fs::copy(fs::path(LLL_SOURCE_DIR) / "examples/render_gltf", project);
  const std::string flags = LLL_EXAMPLE_FLAGS;
  ASSERT_EQ(shell("cmake -S '" + project.string() + "' -B '" + build.string() +
                      "' -G Ninja -DCMAKE_BUILD_TYPE=Release" + " -DCMAKE_PREFIX_PATH='" + prefix.string() +
                      "' -DCMAKE_CXX_FLAGS='" + flags + "' -DCMAKE_EXE_LINKER_FLAGS='" + flags + "'",
                  log),
            0)
      << test::readFile(log);
  ASSERT_EQ(shell("cmake --build '" + build.string() + "'", log), 0) << test::readFile(log);

  const std::string scene = std::string(LLL_ASSETS_DIR) + "/camp/camp.gltf";
  const fs::path example = dir_ / "example.png";
  ASSERT_EQ(shell("'" + (build / "render_gltf").string() + "' '" + scene + "' '" + example.string() +
                      "' lll cpu 96 64",
                  log),
            0)
      << test::readFile(log);
  EXPECT_TRUE(test::contains(test::readFile(log), "frame")) << "the example prints its pass timings";
  const auto rendered = test::runLll({"render", scene, "--technique", "lll", "--device", "cpu", "--width",
                                      "96", "--height", "64", "--out", outPng()});
  ASSERT_EQ(rendered.exitCode, 0) << rendered;
  test::expectWithinBound(readPng(example), readPng(outPng()), test::kSameImage,
                          "installed example vs lll render");

  // Bad input through the library: exit 2 and the file named, as the lll command does.
  EXPECT_EQ(shell("'" + (build / "render_gltf").string() + "' '" + (dir_ / "missing.gltf").string() + "' '" +
                      (dir_ / "x.png").string() + "'",
                  log),
            2);
  EXPECT_TRUE(test::contains(test::readFile(log), "missing.gltf")) << test::readFile(log);
}

}  // namespace
}  // namespace lll
