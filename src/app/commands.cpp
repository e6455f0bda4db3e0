#include "app/commands.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <vector>

#include "bench/progress.h"
#include "core/errors.h"
#include "gi/light_falloff.h"
#include "lighting/lll_memory.h"
#include "lighting/technique.h"
#include "particles/particle_setup.h"
#include "render/image_io.h"
#include "render/output_files.h"
#include "render/stats.h"
#include "render/tonemap.h"
#include "renderer/renderer.h"
#include "scene/builtin_scenes.h"
#include "scene/camera.h"
#include "scene/light_animation.h"

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
  const std::string ext = lowercaseExtension(*path);
  if (!path->empty() && !extensions.empty() &&
      std::find(extensions.begin(), extensions.end(), ext) == extensions.end())
    throw InputError(
        fmt::format("{} {}: expected a name ending in {}", option, *path, fmt::join(extensions, " or ")));
  outputs.add(option, *path);
}

// A progress bar for work still running after a couple of seconds (a reference render, photon
// tracing): a quick one (the tests', a preview) prints nothing.
class SlowWorkProgress {
 public:
  explicit SlowWorkProgress(std::string label) : label_(std::move(label)), bar_(kSteps) {}

  void update(double fraction) {
    if (!shown_ && std::chrono::steady_clock::now() - begin_ < std::chrono::seconds(2)) return;
    const size_t step = std::min(kSteps - 1, size_t(fraction * double(kSteps)));
    if (shown_ && step <= *shown_) return;
    bar_.start(step, label_);
    shown_ = step;
  }
  void finish() {
    if (shown_) bar_.finish(kSteps);
  }

 private:
  static constexpr size_t kSteps = 20;
  std::string label_;
  std::chrono::steady_clock::time_point begin_ = std::chrono::steady_clock::now();
  bench::ProgressBar bar_;  // says nothing until started; it times from its construction
  std::optional<size_t> shown_;
};

void printIndirectLight(const GiRequest& request, const gi::PhotonStats& s) {
  fmt::print(
      stderr,
      "lll: gi {}: {} photons, {} bounces at most: {} deposits in {:.1f} ms; {} virtual point lights "
      "({}cell {:.3g} m) in {:.1f} ms\n",
      request.mode, s.photons, request.bounces, s.deposits, s.traceMs, s.vpls,
      s.levels > 0 ? fmt::format("{} hierarchy levels, alpha {}, finest ", s.levels, request.vplAlpha) : "",
      s.cellSize, s.mergeMs);
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
  SlowWorkProgress photonProgress("tracing photons");
  if (job.scene.gi.mode != GiMode::None) gi.progress = [&](double f) { photonProgress.update(f); };
  Scene scene = loadScene(job.scene, &warnings, &gi);  // not const: --animate moves its lights
  photonProgress.finish();
  for (const std::string& w : warnings) fmt::print(stderr, "lll: warning: {}\n", w);
  if (job.scene.gi.mode != GiMode::None) printIndirectLight(job.scene.gi, gi.stats);
  particleOptions(scene, job.settings);  // a bad preset fails before Vulkan starts
  Context context(job.device);
  Renderer renderer(context, scene, job.settings);
  std::vector<FrameResult> frames;
  // --animate: frame i shows the moving lights at --time + i / 60 s.
  auto moveLightsTo = [&](uint32_t frame) {
    if (job.settings.animateLights && frame > 0)
      renderer.moveLightsTo(scene, job.scene.time + float(frame) * kAnimationFrameSeconds);
  };
  if (renderer.particles()) {
    // --frames N: N fixed simulation steps, the last one in the drawn frame. Drawing the others
    // would change nothing in the image and costs minutes on a CPU device.
    renderer.advanceParticles(job.settings.frames - 1);
    // Every frame's light update still happens: the VPLs of --gi follow the lights a budget a frame.
    for (uint32_t i = 1; i < job.settings.frames; ++i) moveLightsTo(i);
    frames.push_back(renderer.renderFrame(true));
  } else {
    for (uint32_t i = 0; i < job.settings.frames; ++i) {
      moveLightsTo(i);
      frames.push_back(renderer.renderFrame(i + 1 == job.settings.frames));
    }
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

int runReference(const ReferenceJob& job) {
  validateResolution(job.width, job.height);
  if (!(job.exposure > 0.0f) || !std::isfinite(job.exposure))
    throw InputError(fmt::format("--exposure {}: expected a positive finite number", job.exposure));
  if (!job.out) throw InputError("--out: required, a .exr, .pfm or .png file");
  gi::ReferenceOptions options = job.options;
  SceneRequest request = job.scene;
  if (options.vpls != gi::VplGather::Off) {  // the scene's gi options apply to its VPLs
    request.gi.mode = GiMode::VplOnly;
    request.gi.bounces = options.bounces;
  }
  gi::validateReferenceOptions(options);
  PendingOutputs outputs;
  addOutput(outputs, "--out", job.out, {".exr", ".pfm", ".png"});
  std::vector<std::string> warnings;
  IndirectLightReport photons;
  const Scene scene = loadScene(request, &warnings, &photons);
  for (const std::string& w : warnings) fmt::print(stderr, "lll: warning: {}\n", w);
  const Camera camera = resolveCamera(scene, job.camera);
  if (options.vpls != gi::VplGather::Off)
    fmt::print(stderr, "lll: {} photons, {} bounces at most: {} virtual point lights\n", request.gi.photons,
               request.gi.bounces, photons.stats.vpls);
  else if (scene.directionalLights.empty() &&
           std::none_of(scene.lights.begin(), scene.lights.end(), gi::emitsLight))
    fmt::print(stderr,
               "lll: warning: scene '{}' has no point, spot, box or directional light: the image is black\n",
               scene.name);

  const auto begin = std::chrono::steady_clock::now();
  SlowWorkProgress progress(fmt::format("{}x{}, {} spp", job.width, job.height, job.options.spp));
  options.progress = [&](double fraction) { progress.update(fraction); };
  const gi::RadianceImage radiance = gi::renderReference(scene, camera, job.width, job.height, options);
  const HdrImage hdr = HdrImage::fromRgb(radiance.width, radiance.height, radiance.rgb);
  progress.finish();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();

  outputs.write(*job.out, [&](const auto& file) {
    if (lowercaseExtension(*job.out) == ".png")
      writePng(file, tonemapFilmic(hdr, job.exposure));
    else
      writeHdr(file, hdr);
  });
  outputs.commit();
  fmt::print(stderr, "lll: reference {} camera '{}' {}x{}, {} spp, {} bounce(s){}: {:.2f} s\n", scene.name,
             camera.name, job.width, job.height, job.options.spp, job.options.bounces,
             options.vpls == gi::VplGather::Shadowed     ? ", the VPLs shadowed"
             : options.vpls == gi::VplGather::Unshadowed ? ", the VPLs unshadowed"
             : job.options.indirectOnly                  ? ", indirect only"
                                                         : "",
             seconds);
  return 0;
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
  if (query.link == LllLink::Auto)
    throw InputError("--link auto: lll-memory sizes one format, compact or wide");
  // The technique's two link layouts (shaders/shared/lll_types.h): compact 8 bytes, wide 16.
  const uint32_t linkBytes = query.link == LllLink::Wide ? 16 : 8;
  const uint32_t slices = std::max(query.slices, 1u);
  const LllMemory m =
      estimateLllMemory(query.width, query.height, query.tile, query.linksPerTile, linkBytes, slices);
  // MiB, two decimals: the chapter's "MB" (506.25 MB at 1920x1080 per pixel) are MiB.
  auto line = [](const char* what, uint64_t bytes) {
    fmt::print("{:<11} {} bytes ({:.2f} MiB)\n", what, bytes, double(bytes) / (1024.0 * 1024.0));
  };
  fmt::print(
      "lll-memory: {} x {} pixels, {} x {} pixel tiles, {} links per tile, {} links of {} bytes, {} lists "
      "per tile\n",
      query.width, query.height, query.tile, query.tile, query.linksPerTile, query.link, linkBytes, slices);
  fmt::print("{:<11} {} x {} = {}\n", "tiles", m.tilesX, m.tilesY, uint64_t(m.tilesX) * m.tilesY);
  fmt::print("{:<11} {}\n", "links", m.links);
  line("link pool", m.poolBytes);
  line("heads", m.headBytes);
  line("tile depth", m.depthBytes);
  line("total", m.poolBytes + m.headBytes + m.depthBytes);
  return 0;
}

}  // namespace lll
