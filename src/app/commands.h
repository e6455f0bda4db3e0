#pragma once
// What each `lll` subcommand does, as library functions; main.cpp only parses the command line.
#include <cstdint>
#include <optional>
#include <string>

#include "gi/path_tracer.h"
#include "gpu/context.h"
#include "lighting/lll.h"
#include "render/settings.h"
#include "scene/scene_source.h"

namespace lll {

struct RenderJob {
  SceneRequest scene;
  RenderSettings settings;
  ContextOptions device;
  // Each output when asked for; an option given with an empty path is an error, not "no output".
  std::optional<std::string> outPng;    // --out
  std::optional<std::string> outHdr;    // --hdr
  std::optional<std::string> outStats;  // --stats
};

// Each returns the process exit code: 0 success, 1 a validation message was seen under --validate.
// They throw InputError for bad input (exit 2) and other exceptions for failures (exit 1).
int runRender(const RenderJob& job);
int printScenes();
int printTechniques();
int printDevices();

// `lll reference`: the path-traced reference image (gi/path_tracer.h), on the CPU, no Vulkan.
struct ReferenceJob {
  SceneRequest scene;
  std::string camera;  // as `lll render --camera`
  uint32_t width = 1280;
  uint32_t height = 720;
  float exposure = 1.0f;  // for a .png only: radiance files are written as computed
  gi::ReferenceOptions options;
  std::optional<std::string> out;  // .exr or .pfm: linear radiance; .png: tonemapped as `lll render`
};
int runReference(const ReferenceJob& job);

// `lll lll-memory`: what the light linked list needs at a resolution, tile size and average list length.
struct LllMemoryQuery {
  uint32_t width = 1920;
  uint32_t height = 1080;
  uint32_t tile = kLllDefaultTile;
  uint32_t linksPerTile = 32;
  LllLink link = LllLink::Compact;               // compact (8-byte links) | wide (16-byte links)
  uint32_t slices = RenderSettings{}.lllSlices;  // lists (heads) per tile, as --lll-slices
};
int printLllMemory(const LllMemoryQuery& query);

}  // namespace lll
