// libFuzzer target for the glTF/GLB loader: each input is written to a file (the loader reads
// files, and the .bin and images beside them) and loaded. A file may be refused with InputError;
// anything else thrown, a crash, a sanitizer report or a loaded scene that breaks an invariant
// (tests/scene_invariants.h: out-of-range indices, NaN, infinite or absurd values) is a finding.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/errors.h"
#include "scene/gltf_loader.h"
#include "scene_invariants.h"

namespace {

// One folder per process, in memory when /dev/shm exists: the loader looks for referenced files
// only beside the input, so nothing outside it is read.
const std::filesystem::path& inputPath() {
  static const std::filesystem::path path = [] {
    const std::filesystem::path base =
        std::filesystem::is_directory("/dev/shm") ? "/dev/shm" : std::filesystem::temp_directory_path();
    const std::filesystem::path dir = base / ("lll-fuzz-" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    return dir / "input.glb";
  }();
  return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  {
    std::ofstream out(inputPath(), std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
  }
  try {
    lll::LoadReport report;
    const lll::Scene scene = lll::loadGltf(inputPath(), &report);
    const std::string violation = lll::test::sceneInvariantViolation(scene);
    if (!violation.empty()) {
      std::fprintf(stderr, "loaded scene breaks an invariant: %s\n", violation.c_str());
      std::abort();
    }
  } catch (const lll::InputError&) {
    // Refused with a message: what a broken file should get.
  }
  return 0;
}
