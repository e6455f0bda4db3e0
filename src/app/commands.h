#pragma once
// What each `lll` subcommand does, as library functions; main.cpp only parses the command line.
#include <string>

#include "gpu/context.h"
#include "render/settings.h"
#include "scene/scene_source.h"

namespace lll {

struct RenderJob {
  SceneRequest scene;
  RenderSettings settings;
  ContextOptions device;
  std::string outPng;    // --out
  std::string outHdr;    // --hdr
  std::string outStats;  // --stats
};

// Each returns the process exit code: 0 success, 1 a validation message was seen under --validate.
// They throw InputError for bad input (exit 2) and other exceptions for failures (exit 1).
int runRender(const RenderJob& job);
int printScenes();
int printTechniques();
int printDevices();

}  // namespace lll
