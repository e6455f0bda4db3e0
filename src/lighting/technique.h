#pragma once
// A lighting technique: the passes that turn the depth prepass and the scene into lit HDR radiance.
// One technique = one .cpp file in src/lighting/ plus its shaders, registered in registry.cpp.
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "render/frame.h"

namespace lll {

class Technique {
 public:
  virtual ~Technique() = default;

  // Records the technique's passes, each in a ScopedPass. On entry frame.targets.depth holds the
  // prepass (DEPTH_READ_ONLY_OPTIMAL) and hdr is COLOR_ATTACHMENT_OPTIMAL with undefined contents;
  // on exit hdr holds the lit frame, still COLOR_ATTACHMENT_OPTIMAL.
  virtual void render(FrameContext& frame) = 0;

  // Called once the frame's GPU work completed. Returning true asks the renderer to record the
  // same frame again (the light linked list grows its pool on overflow and says so here).
  virtual bool afterFrame() { return false; }

  // Technique-specific numbers for --stats (links used, pool bytes, G-buffer bytes, ...).
  virtual std::vector<std::pair<std::string, double>> stats() const { return {}; }
};

struct TechniqueInfo {
  std::string name;
  std::string description;
  // `visibility` is the frame's visibility buffer, null with --surfaces gbuffer.
  std::unique_ptr<Technique> (*create)(Context& context, const GpuScene& scene,
                                       const RenderSettings& settings, const FrameTargets& targets,
                                       const VisibilityBuffer* visibility);
};

const std::vector<TechniqueInfo>& techniques();
// Throws InputError naming the known techniques when `name` is not one of them.
const TechniqueInfo& findTechnique(const std::string& name);

}  // namespace lll
