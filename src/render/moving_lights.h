#pragma once
// Moving lights placed on the GPU (--light-motion, scene/light_animation.h): the motions are
// uploaded once, and a frame whose lights moved starts with the pass "lights-move", one invocation
// a light writing its position at the frame's time into the light array. The CPU then neither
// places the lights nor uploads the array again: at a million moving lights that was 133 ms a frame
// on a 2-core CPU (placing them 43 ms, converting and uploading the array 90 ms; bench/README.md).
// Where the CPU needs the positions itself (deferred's and the pre-pass's light volumes, the local
// shadows' views, the VPLs that follow the lights) the renderer places them there instead
// (Renderer::moveLightsTo).
#include <cstdint>

#include "gpu/pipeline.h"
#include "gpu/resources.h"
#include "scene/scene.h"
#include "shared/gpu_types.h"

namespace lll {

class FrameGraph;

class MovingLights {
 public:
  MovingLights(Context& context, const LightAnimation& animation);

  // Records "lights-move": the animation's lights of `lights` (the light array) placed at `seconds`.
  // The light array's readers do not declare it (it is otherwise written between frames), so the
  // barriers before and after are the pass's own.
  void record(FrameGraph& graph, const Buffer& lights, float seconds) const;

 private:
  Context& context_;
  uint32_t first_;
  uint32_t count_;
  Buffer motions_;
  PipelineLayout layout_;
  Pipeline pipeline_;
};

}  // namespace lll
