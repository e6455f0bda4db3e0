// lll: the command-line front end. Parses options and calls the library (app/commands.h).
// Exit codes: 0 success, 1 failure (or a validation message under --validate), 2 bad input.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <charconv>
#include <cmath>
#include <cstdlib>

#include "app/commands.h"
#include "bench/bench.h"
#include "core/errors.h"
#include "scene/light_animation.h"
#include "shared/limits.h"
#include "shared/particle_types.h"
#include "view/viewer.h"

namespace {

// CLI11's Range lets NaN through (every comparison with it is false) and takes "inf": a number
// option must parse as a finite number within [lo, hi].
CLI::Validator finiteIn(double lo, double hi) {
  return CLI::Validator(
      [lo, hi](std::string& text) -> std::string {
        double value = 0.0;
        const char* end = text.data() + text.size();
        const auto [ptr, ec] = std::from_chars(text.data(), end, value);
        if (ec != std::errc() || ptr != end || !std::isfinite(value))
          return fmt::format("{} is not a finite number", text);
        if (value < lo || value > hi) return fmt::format("{} is not between {} and {}", text, lo, hi);
        return {};
      },
      fmt::format("NUMBER in [{} - {}]", lo, hi));
}

// CLI11 runs no validator on an empty value and converts it to zero: `--tile ''` would get past
// the tile check. No option of lll takes an empty value.
void rejectEmptyValues(const CLI::App& command) {
  for (const CLI::Option* option : command.get_options()) {
    for (const std::string& value : option->results())
      if (value.empty()) throw CLI::ValidationError(option->get_name(), "an empty value is not allowed");
  }
  for (const CLI::App* sub : command.get_subcommands()) rejectEmptyValues(*sub);
}

// An option naming one of an enum's values (core/enum_names.h): CLI11 checks the name against
// `allowed` (default: all of them) and the option is stored as the enum, parsed once here.
template <lll::NamedEnum E>
CLI::Option* addChoice(CLI::App& cmd, const std::string& name, E& value, const std::string& help,
                       std::vector<std::string> allowed = lll::enumNames<E>()) {
  return cmd
      .add_option_function<std::string>(
          name, [&value](const std::string& text) { value = lll::enumFromName<E>(text).value(); }, help)
      ->check(CLI::IsMember(std::move(allowed)));
}

void addRenderOptions(CLI::App& cmd, lll::RenderJob& job) {
  auto& s = job.settings;
  cmd.add_option("scene", job.scene.scene, "built-in scene name (see `lll scenes`) or .gltf/.glb path");
  cmd.add_option("--width", s.width, "image width in pixels")->check(CLI::Range(1u, 8192u));
  cmd.add_option("--height", s.height, "image height in pixels")->check(CLI::Range(1u, 8192u));
  cmd.add_option("--technique", s.technique, "lighting technique (see `lll techniques`)");
  cmd.add_option("--lights", job.scene.extraLights,
                 "random point lights: scattered in the scene bounds, added to the file's own lights")
      ->check(CLI::Range(0u, lll::gpu::kMaxLights));
  cmd.add_option("--light-range-scale", job.scene.lightRangeScale,
                 "multiplies the ranges of the --lights lights (light-volume overdraw studies)")
      ->check(finiteIn(0.0, lll::kMaxLightRangeScale));
  // One seed for the lights and the particles: main copies it into the settings after parsing.
  cmd.add_option("--seed", job.scene.seed, "seed for random lights and particles (0 to 4294967295)");
  cmd.add_option("--camera", s.camera, "camera name, or eye and target as \"ex,ey,ez,tx,ty,tz\"");
  cmd.add_option("--frames", s.frames,
                 "frames to render (timings are medians over them); with --particles: fixed 1/60 s "
                 "simulation steps, only the last frame is drawn")
      ->check(CLI::Range(1u, 100000u));
  cmd.add_option("--time", job.scene.time,
                 "seconds: the --lights lights orbit and bob (seeded), drawn where they are at this time")
      ->check(finiteIn(0.0, lll::kMaxAnimationSeconds));
  cmd.add_flag("--animate", s.animateLights,
               "the --lights lights move 1/60 s each frame, from --time (0 unless given)");
  addChoice(cmd, "--light-motion", s.lightMotion,
            "where moving lights are placed each frame: gpu (a pass writes their positions) | cpu "
            "(placed and uploaded) | auto (gpu unless the CPU reads them: deferred, prepass, "
            "--shadows all, --gi)");
  cmd.add_option("--exposure", s.exposure, "exposure multiplier before tonemapping")
      ->check(finiteIn(1e-6, 1e6));
  cmd.add_option("--ambient", s.ambient, "constant ambient radiance")->check(finiteIn(0.0, 1e3));
  cmd.add_option("--device", job.device.device, "auto | gpu | cpu | INDEX (see `lll devices`)");
  cmd.add_flag("--validate", job.device.validation,
               "Khronos validation layers on; any message fails the run");
  cmd.add_option("--tile", s.tileSize,
                 "light list tile size in pixels (default: lll 16, tiled and clustered 8)")
      ->check(CLI::IsMember({1u, 2u, 4u, 8u, 16u}));
  addChoice(cmd, "--lll-fill", s.lllFill, "light linked list fill: shells | ray | compute");
  cmd.add_option("--lll-fill-splits", s.lllFillSplits,
                 "compute fill: workgroups sharing each 8x8-tile cell's lights (1 to 64; 0: a quarter of the "
                 "light count from 4 to 64; 64 on a CPU device)")
      ->check(CLI::Range(0u, 64u));
  cmd.add_option(
         "--lll-slices", s.lllSlices,
         "lists per tile, one per depth slice: 1 (one list per tile) to 32; slices split the depth in "
         "front of the tile's nearest surface and, where deep, its surfaces' depth range")
      ->check(CLI::Range(0u, 32u));
  addChoice(cmd, "--lll-link", s.lllLink, "link format: compact (8 B, <=256 lights) | wide (16 B) | auto");
  addChoice(cmd, "--lll-records", s.lllRecords,
            "opaque shading reads listed lights from: storage (light buffer) | uniform (uniform block, <=256 "
            "lights) | auto (uniform on a GPU where they fit)");
  addChoice(cmd, "--lll-shade", s.lllShade,
            "lll opaque shading: compute (thin G-buffer, list walk in a compute pass) | fragment");
  addChoice(cmd, "--surfaces", s.surfaces,
            "opaque surfaces: visibility (one raster pass of triangle ids, surfaces rebuilt in compute) | "
            "gbuffer (depth prepass, then geometry passes)");
  addChoice(cmd, "--glass", s.glass,
            "how glass is lit: compute (its fragments stored per pixel, then lit and blended in compute) | "
            "raster (lit in the fragment shader and blended draw by draw)");
  addChoice(cmd, "--raster", s.raster,
            "who rasterizes the visibility buffer: hardware | compute (64-bit atomics, one thread per "
            "small triangle) | auto (compute on a GPU, hardware on a CPU device)");
  cmd.add_option("--cluster-slices", s.clusterSlices,
                 "clustered: depth slices per tile between its nearest and farthest surface (1 to 32)")
      ->check(CLI::Range(1u, 32u));
  cmd.add_option(
      "--sun", job.scene.suns,
      "a directional light, \"x,y,z,lux[,r,g,b]\": x,y,z towards the sun, its illuminance in lux and "
      "linear colour; repeatable (4 at most, with the scene's own)");
  addChoice(cmd, "--shadows", s.shadows,
            "shadows: sun (the brightest directional light casts cascaded shadow maps) | all (the sun "
            "and the --shadow-lights most important spot and point lights) | none");
  cmd.add_option("--shadow-lights", s.shadowLights,
                 "--shadows all: how many local lights cast shadows each frame (0 to 1024)")
      ->check(CLI::Range(0u, 1024u));
  cmd.add_option(
         "--shadow-light-resolution", s.shadowLightResolution,
         "texels along each local light's shadow view (a spot's cone, a point light's cube face; 16 to "
         "4096)")
      ->check(CLI::Range(16u, 4096u));
  cmd.add_option("--cascades", s.cascades, "sun shadow cascades (1 to 4)")->check(CLI::Range(1u, 4u));
  cmd.add_option("--shadow-resolution", s.shadowResolution, "texels along each cascade's side (16 to 8192)")
      ->check(CLI::Range(16u, 8192u));
  addChoice(cmd, "--shadow-filter", s.shadowFilter,
            "shadow filter: pcf (3x3 bilinear comparisons) | none (one texel)");
  addChoice(cmd, "--shadow-raster", s.shadowRaster,
            "who draws the shadow casters: hardware | compute | auto (compute on a GPU, hardware on a "
            "CPU device)");
  addChoice(cmd, "--gi", job.scene.gi.mode,
            "indirect light: none | vpl (instant radiosity: photons traced from the lights leave virtual "
            "point lights) | vpl-only (the virtual point lights without the direct lights)");
  cmd.add_option("--photons", job.scene.gi.photons, "--gi: photons traced from the lights")
      ->check(CLI::Range(1u, lll::gi::kMaxPhotons));
  cmd.add_option("--bounces", job.scene.gi.bounces,
                 "--gi: deposits per photon at most (1: one-bounce indirect light)")
      ->check(CLI::Range(1u, lll::gi::kMaxBounces));
  cmd.add_option(
         "--vpl-count", job.scene.gi.vplCount,
         "--gi: merge the photons' deposits on a grid into at most this many virtual point lights (0: no "
         "merging)")
      ->check(CLI::Range(0u, lll::gpu::kMaxLights));
  cmd.add_option(
         "--vpl-cutoff", job.scene.gi.vplCutoff,
         "--gi: a virtual point light reaches until its irradiance falls to this fraction of the scene's "
         "mean indirect irradiance (smaller: longer ranges, longer light lists)")
      ->check(finiteIn(1e-9, 1.0));
  cmd.add_option("--vpl-range", job.scene.gi.vplRange,
                 "--gi: every virtual point light's range in metres instead of --vpl-cutoff's (a range that "
                 "does not shrink as --vpl-count grows)")
      ->check(finiteIn(0.0, 1e6));
  addChoice(cmd, "--vpl-hierarchy", job.scene.gi.hierarchy,
            "--gi: grid (the default: a lighting grid hierarchy, the deposits merged on grids of "
            "doubling cells, each level's VPLs lighting a band of distances; --vpl-count is its finest "
            "level's) | none (one grid, ranges from --vpl-cutoff or --vpl-range; either of those, or "
            "--vpl-count 0, asks for it)");
  cmd.add_option("--vpl-alpha", job.scene.gi.vplAlpha,
                 "--vpl-hierarchy grid: the radius of a level's band in its cells (larger: more accurate, "
                 "longer light lists)")
      ->check(finiteIn(lll::gi::kMinHierarchyAlpha, lll::gi::kMaxHierarchyAlpha));
  cmd.add_option("--vpl-retrace", job.scene.gi.retrace,
                 "--gi with moving lights (--animate): photons of the moving lights traced again each frame, "
                 "so that their indirect light follows them (0: it stays where it was first traced)")
      ->check(CLI::Range(0u, lll::gi::kMaxPhotons));
  cmd.add_option(
         "--vpl-interleave", s.vplInterleave,
         "--gi: each pixel of a KxK block evaluates a (K*K)th of the virtual point lights and a filter "
         "gathers the others from its neighbours on the same surface (1: every pixel evaluates every "
         "VPL; opaque surfaces drawn from the visibility buffer only; 1 to 4)")
      ->check(CLI::Range(1u, lll::gpu::kMaxVplInterleave));
  addChoice(cmd, "--debug-view", s.debugView,
            "none | heatmap | bounds | tiles (lll; heatmap and tiles: tiled, clustered)");
  addChoice(cmd, "--deferred-translucent", s.deferredTranslucent,
            "deferred: glass and smoke left unlit (as in the seeds' Figure 1.1) or lit by a forward pass");
  addChoice(cmd, "--aa", s.antiAliasing, "none | edge (deferred: edge-detect anti-aliasing)");
  CLI::Option* particles = cmd.add_option(
      "--particles", s.particles,
      "particle preset: a built-in name (smoke, sparks, dust) or a .json file; the emitter sits "
      "at the scene's smoke source");
  // Without --particles these would be silently ignored.
  addChoice(cmd, "--particle-lighting", s.particleLighting,
            "light particles per pixel, on a 4x4 atlas per particle interpolated per pixel (atlas), "
            "or once per particle at its centre (vertex)")
      ->needs(particles);
  addChoice(cmd, "--particle-render", s.particleRender,
            "draw particles as quads through the rasterizer, or blend them per tile in compute "
            "(auto: compute on a GPU, raster on a CPU device)")
      ->needs(particles);
  addChoice(cmd, "--particle-resolution", s.particleResolution,
            "blend particles at full, half or quarter resolution, upsampled with the depth "
            "(compute renderer)")
      ->needs(particles);
  cmd.add_option("--particle-tile-groups", s.particleTileGroups,
                 "compute renderer: workgroups each particle tile's slabs are shared out to (default: "
                 "slabs x scale / 8, at least 4 or the slabs, at most 32; a slab per 4,096 particle slots "
                 "up to 64, scale 1 at full resolution, 2 at half, 4 at quarter)")
      ->check(CLI::Range(1u, lll::gpu::kParticleMaxGroups))
      ->needs(particles);
  cmd.add_option("--particle-count", s.particleCount, "particle slots, overriding the preset's count")
      ->check(CLI::Range(1u, 1000000u))
      ->needs(particles);
  cmd.add_option("--particle-emitter", s.particleEmitter,
                 "where the emitter sits, \"x,y,z\" (default: the scene's smoke source)")
      ->needs(particles);
}

void addReferenceOptions(CLI::App& cmd, lll::ReferenceJob& job) {
  auto& o = job.options;
  cmd.add_option("scene", job.scene.scene, "built-in scene name (see `lll scenes`) or .gltf/.glb path");
  cmd.add_option("--camera", job.camera, "camera name, or eye and target as \"ex,ey,ez,tx,ty,tz\"");
  cmd.add_option("--width", job.width, "image width in pixels")->check(CLI::Range(1u, 8192u));
  cmd.add_option("--height", job.height, "image height in pixels")->check(CLI::Range(1u, 8192u));
  cmd.add_flag("--indirect", o.indirectOnly,
               "indirect light only: no emission or direct light at the surfaces the camera sees");
  cmd.add_option("--bounces", o.bounces, "diffuse bounces of indirect light (1: one-bounce)")
      ->check(CLI::Range(0u, lll::gi::kMaxBounces))
      ->capture_default_str();
  cmd.add_option("--spp", o.spp, "samples per pixel, all through the pixel's centre")
      ->check(CLI::Range(1u, lll::gi::kMaxReferenceSpp))
      ->capture_default_str();
  cmd.add_option("--seed", o.seed, "seed of the random paths (0 to 4294967295)");
  cmd.add_option("--threads", o.threads, "threads (0: one per hardware thread)")
      ->check(CLI::Range(0u, lll::gi::kMaxReferenceThreads));
  CLI::Option* vpls =
      addChoice(cmd, "--vpls", o.vpls,
                "instead of path tracing: the virtual point lights of `render --gi vpl-only` (photons "
                "traced with --bounces, merged as --vpl-count and --vpl-hierarchy say) summed at the "
                "camera's hits as the renderer lights them, unshadowed (as the renderer) or shadowed "
                "(a shadow ray to each VPL)",
                {"unshadowed", "shadowed"});
  auto& gi = job.scene.gi;
  cmd.add_option("--photons", gi.photons, "--vpls: photons traced from the lights")
      ->check(CLI::Range(1u, lll::gi::kMaxPhotons))
      ->needs(vpls);
  cmd.add_option("--vpl-count", gi.vplCount, "--vpls: as `render --vpl-count`")
      ->check(CLI::Range(0u, lll::gpu::kMaxLights))
      ->needs(vpls);
  addChoice(cmd, "--vpl-hierarchy", gi.hierarchy, "--vpls: as `render --vpl-hierarchy` (grid | none)")
      ->needs(vpls);
  cmd.add_option("--vpl-alpha", gi.vplAlpha, "--vpls: as `render --vpl-alpha`")
      ->check(finiteIn(lll::gi::kMinHierarchyAlpha, lll::gi::kMaxHierarchyAlpha))
      ->needs(vpls);
  cmd.add_option("--exposure", job.exposure, "exposure multiplier before tonemapping (.png only)")
      ->check(finiteIn(1e-6, 1e6));
  cmd.add_option("-o,--out", job.out, "radiance image (.exr, .pfm) or tonemapped sRGB .png")->required();
}

void addBenchOptions(CLI::App& cmd, lll::bench::BenchOptions& options) {
  cmd.add_option("--suite", options.suites, "suite to run, repeatable (default: every suite)")
      ->check(CLI::IsMember(lll::bench::suiteNames()));
  cmd.add_option("--technique", options.techniques,
                 "run only this technique's scenarios, repeatable (default: all; see `lll techniques`)");
  cmd.add_flag("--quick", options.quick,
               "tiny sizes and few frames: a suite runs in under a minute on lavapipe");
  cmd.add_flag("--full-forward", options.fullForward,
               "on a CPU device, also run forward over more than 4096 lights (hours)");
  cmd.add_option("--out", options.outDir, "directory for results.json, results.csv, summary.md and charts")
      ->capture_default_str();
  cmd.add_option("--particle-count", options.particleCounts,
                 "smoke suite: only these particle counts, repeatable (default 1,024, 65,536, 1,000,000)")
      ->check(CLI::Range(1u, 1000000u));
  cmd.add_option("--frames", options.timedFrames, "timed frames per scenario (default 30; 2 with --quick)")
      ->check(CLI::Range(1u, 100000u));
  cmd.add_option("--warmup", options.warmupFrames, "untimed frames first (default 5; 1 with --quick)")
      ->check(CLI::Range(0u, 100000u));
  cmd.add_option("--device", options.device.device, "auto | gpu | cpu | INDEX (see `lll devices`)");
  cmd.add_flag("--validate", options.device.validation,
               "Khronos validation layers on; any message fails the run");
  cmd.add_option(
      "--replot", options.replotDir,
      "run nothing: redraw the charts of DIR from its results.json (results from a machine without "
      "gnuplot)");
}

void addLllMemoryOptions(CLI::App& cmd, lll::LllMemoryQuery& query) {
  cmd.add_option("--width", query.width, "image width in pixels")
      ->check(CLI::Range(1u, 65536u))
      ->capture_default_str();
  cmd.add_option("--height", query.height, "image height in pixels")
      ->check(CLI::Range(1u, 65536u))
      ->capture_default_str();
  cmd.add_option("--tile", query.tile, "tile size in pixels")
      ->check(CLI::IsMember({1u, 2u, 4u, 8u, 16u}))
      ->capture_default_str();
  cmd.add_option("--links-per-tile", query.linksPerTile, "average light list length the pool is sized for")
      ->check(CLI::Range(1u, 1u << 16))
      ->capture_default_str();
  addChoice(cmd, "--link", query.link, "link format: compact (8 B) | wide (16 B)", {"compact", "wide"})
      ->default_str("compact");
  cmd.add_option("--lll-slices", query.slices, "lists (depth slices) per tile, as lll render's --lll-slices")
      ->check(CLI::Range(1u, 32u))
      ->capture_default_str();
}

// Settles --vpl-hierarchy against the options only one of its modes takes: the single grid's options
// ask for it when --vpl-hierarchy is not given; given with the other mode, an option is an error (its
// message; empty when there is none).
std::string giOptionConflict(const CLI::App& cmd, lll::GiRequest& gi) {
  // --vpl-cutoff, --vpl-range and --vpl-count 0 are the single grid's: without --vpl-hierarchy they
  // ask for it (the default is the hierarchy), with --vpl-hierarchy grid they conflict.
  const char* single = cmd.count("--vpl-cutoff") > 0                      ? "--vpl-cutoff"
                       : cmd.count("--vpl-range") > 0                     ? "--vpl-range"
                       : cmd.count("--vpl-count") > 0 && gi.vplCount == 0 ? "--vpl-count 0"
                                                                          : nullptr;
  if (single && cmd.count("--vpl-hierarchy") == 0) {
    if (cmd.count("--vpl-alpha") > 0)
      return fmt::format(
          "--vpl-alpha sets the lighting grid hierarchy's accuracy, but {} asks for one grid "
          "(--vpl-hierarchy none)",
          single);
    gi.hierarchy = lll::GiHierarchy::None;
  }
  if (single && gi.hierarchy == lll::GiHierarchy::Grid)
    return fmt::format(
        "{}: the lighting grid hierarchy (--vpl-hierarchy grid) sets every VPL's range from "
        "its level and needs a count; leave --vpl-hierarchy out or make it none",
        single);
  if (gi.hierarchy != lll::GiHierarchy::Grid && cmd.count("--vpl-alpha") > 0)
    return "--vpl-alpha: it sets the lighting grid hierarchy's accuracy, but --vpl-hierarchy is none";
  return {};
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"lll: real-time rendering with many dynamic lights (Light Linked List)"};
  // At most one, checked below: with require_subcommand(1) CLI11 answers a misspelt command such as
  // `lll rendr` with "A subcommand is required", never naming the word it did not know.
  app.require_subcommand(0, 1);
  lll::RenderJob job;
  lll::bench::BenchOptions bench;
  lll::LllMemoryQuery lllMemory;
  if (std::getenv("LLL_VALIDATE")) job.device.validation = bench.device.validation = true;

  CLI::App* render = app.add_subcommand("render", "render a scene off-screen to PNG (and HDR, stats)");
  addRenderOptions(*render, job);
  render->add_option("-o,--out", job.outPng, "display image, tonemapped sRGB PNG");
  render->add_option("--hdr", job.outHdr, "linear HDR image, .exr or .pfm");
  render->add_option("--stats", job.outStats,
                     "JSON with per-pass GPU times, device, driver, resolution, lights");
  lll::RenderJob viewRender;
  lll::view::ViewJob view;
  CLI::App* viewCmd = app.add_subcommand(
      "view", "an interactive window: fly through a scene, change any render option live, GPU timings");
  addRenderOptions(*viewCmd, viewRender);
  viewCmd->add_option("--screenshot", view.screenshot,
                      "with --frames N: write the N-th frame's image (.png, or .exr radiance), then exit");
  viewCmd->add_option(
      "--script", view.script,
      "replay input from a file: \"FRAME key w down\", \"FRAME look DX DY\", resize, drop, set, "
      "preset-save, print-camera (see src/view/input_script.h)");
  viewCmd->add_option("--resolution-scale", view.resolutionScale, "render resolution over window resolution")
      ->check(finiteIn(0.1, 4.0));
  lll::ReferenceJob reference;
  CLI::App* referenceCmd = app.add_subcommand(
      "reference", "path-trace a reference image of direct and indirect light on the CPU (.exr/.pfm/.png)");
  addReferenceOptions(*referenceCmd, reference);
  CLI::App* scenes = app.add_subcommand("scenes", "list the built-in scenes");
  CLI::App* techniques = app.add_subcommand("techniques", "list the lighting techniques");
  CLI::App* devices = app.add_subcommand("devices", "list the Vulkan devices");
  CLI::App* benchCmd = app.add_subcommand(
      "bench", "time suites of scenarios x techniques; write results.json/.csv, summary.md, charts");
  addBenchOptions(*benchCmd, bench);
  CLI::App* lllMemoryCmd = app.add_subcommand(
      "lll-memory", "memory of the light linked list (link pool, heads, tile depths) for a resolution");
  addLllMemoryOptions(*lllMemoryCmd, lllMemory);

  try {
    app.parse(argc, argv);
    rejectEmptyValues(app);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  for (auto [cmd, gi] : {std::pair{render, &job.scene.gi}, std::pair{viewCmd, &viewRender.scene.gi}}) {
    if (const std::string error = giOptionConflict(*cmd, *gi); !error.empty()) {
      fmt::print(stderr, "lll: error: {}\n", error);
      return 2;
    }
  }
  job.settings.seed = job.scene.seed;
  job.scene.movingLights = render->count("--time") > 0 || job.settings.animateLights;
  viewRender.settings.seed = viewRender.scene.seed;
  viewRender.scene.movingLights = viewCmd->count("--time") > 0 || viewRender.settings.animateLights;
  view.scene = viewRender.scene;
  view.settings = viewRender.settings;
  view.device = viewRender.device;
  view.frames = viewCmd->count("--frames") > 0 ? viewRender.settings.frames : 0;
  if (view.screenshot && view.frames == 0) {
    fmt::print(stderr, "lll: error: view --screenshot needs --frames N (the frame it writes)\n");
    return 2;
  }
  if (app.get_subcommands().empty()) {
    fmt::print(stderr, "lll: error: a command is required\n{}", app.help());
    return 2;
  }
  try {
    if (*render) return lll::runRender(job);
    if (*viewCmd) return lll::view::runView(view);
    if (*referenceCmd) return lll::runReference(reference);
    if (*scenes) return lll::printScenes();
    if (*techniques) return lll::printTechniques();
    if (*devices) return lll::printDevices();
    if (*benchCmd) return lll::bench::runBenchCommand(bench);
    if (*lllMemoryCmd) return lll::printLllMemory(lllMemory);
  } catch (const lll::InputError& e) {
    fmt::print(stderr, "lll: error: {}\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    fmt::print(stderr, "lll: failure: {}\n", e.what());
    return 1;
  }
  return 0;
}
