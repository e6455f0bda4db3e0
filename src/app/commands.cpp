#include "app/commands.h"

#include <fmt/format.h>

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "lighting/lll_memory.h"
#include "lighting/technique.h"
#include "particles/particle_setup.h"
#include "render/image_io.h"
#include "render/output_files.h"
#include "render/renderer.h"
#include "render/stats.h"
#include "scene/builtin_scenes.h"
#include "scene/errors.h"

namespace lll {

namespace {

// Fails the run when validation spoke: under --validate every message is an error.
int validationExitCode(const Context& context) {
  const auto messages = context.validationMessages();
  if (messages.empty()) return 0;
  fmt::print(stderr, "lll: error: {} validation message(s); see above\n", messages.size());
  return 1;
}

// The image writers would reject a bad output path only after the render; checking the extension,
// the folder and that a file can be created there first makes a typo fail at once instead of after
// minutes of work.
void addOutput(PendingOutputs& outputs, const char* option, const std::optional<std::string>& path,
               const std::vector<std::string>& extensions) {
  if (!path) return;
  std::string ext = std::filesystem::path(*path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (!path->empty() && !extensions.empty() &&
      std::find(extensions.begin(), extensions.end(), ext) == extensions.end())
    throw InputError(
        fmt::format("{} {}: expected a name ending in {}", option, *path, fmt::join(extensions, " or ")));
  outputs.add(option, *path);
}

// Photon tracing's progress on stderr once it has run a second: redrawn in place on a terminal,
// every quarter on a log.
std::function<void(double)> photonProgress() {
  const auto begin = std::chrono::steady_clock::now();
  const bool terminal = isatty(fileno(stderr));
  return [=, shownQuarter = 0](double fraction) mutable {
    if (std::chrono::steady_clock::now() - begin < std::chrono::seconds(1) && fraction < 1.0) return;
    if (terminal) {
      fmt::print(stderr, "\rlll: tracing photons {:3.0f}%{}", 100.0 * fraction, fraction >= 1.0 ? "\n" : "");
    } else if (int(fraction * 4.0) > shownQuarter) {
      shownQuarter = int(fraction * 4.0);
      fmt::print(stderr, "lll: tracing photons {:3.0f}%\n", 100.0 * fraction);
    }
  };
}

void printIndirectLight(const GiRequest& request, const gi::PhotonStats& s) {
  fmt::print(stderr,
             "lll: gi {}: {} photons, {} bounces at most: {} deposits in {:.1f} ms; {} virtual point lights "
             "(cell {:.3g} m) in {:.1f} ms\n",
             request.mode, s.photons, request.bounces, s.deposits, s.traceMs, s.vpls, s.cellSize, s.mergeMs);
}

}  // namespace

int runRender(const RenderJob& job) {
  findTechnique(job.settings.technique);  // reject a bad name before any slow work
  validateResolution(job.settings.width, job.settings.height);
  PendingOutputs outputs;
  addOutput(outputs, "--out", job.outPng, {".png"});
  addOutput(outputs, "--hdr", job.outHdr, {".exr", ".pfm"});
  addOutput(outputs, "--stats", job.outStats, {});
  std::vector<std::string> warnings;
  IndirectLightReport gi;
  if (job.scene.gi.mode != "none") gi.progress = photonProgress();
  const Scene scene = loadScene(job.scene, &warnings, &gi);
  for (const std::string& w : warnings) fmt::print(stderr, "lll: warning: {}\n", w);
  if (job.scene.gi.mode != "none") printIndirectLight(job.scene.gi, gi.stats);
  particleOptions(scene, job.settings);  // a bad preset fails before Vulkan starts
  Context context(job.device);
  Renderer renderer(context, scene, job.settings);
  std::vector<FrameResult> frames;
  if (renderer.particles()) {
    // --frames N: N fixed simulation steps, the last one in the drawn frame. Drawing the others
    // would change nothing in the image and costs minutes on a CPU device.
    renderer.advanceParticles(job.settings.frames - 1);
    frames.push_back(renderer.renderFrame(true));
  } else {
    for (uint32_t i = 0; i < job.settings.frames; ++i)
      frames.push_back(renderer.renderFrame(i + 1 == job.settings.frames));
  }
  if (job.outPng) outputs.write(*job.outPng, [&](const auto& file) { writePng(file, renderer.ldrImage()); });
  if (job.outHdr) outputs.write(*job.outHdr, [&](const auto& file) { writeHdr(file, renderer.hdrImage()); });
  if (job.outStats) {
    RunInfo run{scene.name,          job.settings.technique, job.settings.width,    job.settings.height,
                scene.lights.size(), scene.triangleCount(),  renderer.camera().name};
    outputs.write(*job.outStats,
                  [&](const auto& file) { writeStatsJson(file, context, run, frames, renderer.stats()); });
  }
  outputs.commit();
  const auto summary = summarizePasses(frames);
  for (const PassSummary& s : summary) fmt::print(stderr, "lll: {:<24} {:9.3f} ms\n", s.name, s.medianMs);
  return validationExitCode(context);
}

int printScenes() {
  for (const BuiltinSceneInfo& info : builtinScenes())
    fmt::print("{:<12} {}{}\n", info.name, info.description,
               info.name == kDefaultSceneName ? " (default)" : "");
  fmt::print("or a path to a .gltf/.glb file\n");
  return 0;
}

int printTechniques() {
  for (const TechniqueInfo& t : techniques()) fmt::print("{:<10} {}\n", t.name, t.description);
  return 0;
}

int printDevices() {
  for (const DeviceInfo& d : lll::listDevices())
    fmt::print("{}: {} ({}, {}, Vulkan {}){}\n", d.index, d.name, d.type, d.driver, d.apiVersion,
               d.usable ? "" : "  unusable: " + d.whyUnusable);
  return 0;
}

int printLllMemory(const LllMemoryQuery& query) {
  if (query.width == 0 || query.height == 0 || query.tile == 0)
    throw InputError(fmt::format("lll-memory: width, height and tile must be positive (got {} x {}, tile {})",
                                 query.width, query.height, query.tile));
  if (query.link != "compact" && query.link != "wide")
    throw InputError(fmt::format("--link {}: expected compact or wide", query.link));
  // The technique's two link layouts (shaders/shared/lll_types.h): compact 8 bytes, wide 16.
  const uint32_t linkBytes = query.link == "wide" ? 16 : 8;
  const LllMemory m = estimateLllMemory(query.width, query.height, query.tile, query.linksPerTile, linkBytes);
  // MiB, two decimals: the chapter's "MB" (506.25 MB at 1920x1080 per pixel) are MiB.
  auto line = [](const char* what, uint64_t bytes) {
    fmt::print("{:<11} {} bytes ({:.2f} MiB)\n", what, bytes, double(bytes) / (1024.0 * 1024.0));
  };
  fmt::print("lll-memory: {} x {} pixels, {} x {} pixel tiles, {} links per tile, {} links of {} bytes\n",
             query.width, query.height, query.tile, query.tile, query.linksPerTile, query.link, linkBytes);
  fmt::print("{:<11} {} x {} = {}\n", "tiles", m.tilesX, m.tilesY, uint64_t(m.tilesX) * m.tilesY);
  fmt::print("{:<11} {}\n", "links", m.links);
  line("link pool", m.poolBytes);
  line("heads", m.headBytes);
  line("tile depth", m.depthBytes);
  line("total", m.poolBytes + m.headBytes + m.depthBytes);
  return 0;
}

}  // namespace lll
