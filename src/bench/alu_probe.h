#pragma once
// The ALU roofline of opaque shading (issue 11): a compute pass that evaluates the same light
// model as the shading passes, for every light at every pixel, with no light list and no memory
// traffic but one store per pixel (shaders/bench/alu_probe.comp). Timed in the same run as a
// scenario, it says how far the technique's "shade-opaque" is from the arithmetic it must do
// when every light reaches every pixel (ThreeL's test).
#include <cstdint>
#include <optional>
#include <vector>

#include "gpu/pass_timer.h"
#include "gpu/pipeline.h"
#include "gpu/resources.h"

namespace lll {

struct Scene;

class AluProbe {
 public:
  // For frames of width x height of `scene` (its light types are compiled in or out as the
  // shading passes do).
  AluProbe(Context& context, const Scene& scene, uint32_t width, uint32_t height);
  ~AluProbe();

  // One timed run over `lights` lights: the pass "alu-probe"; where the device has 16-bit floats,
  // also "alu-probe-half", the same evaluation in packed half floats, two lights an instruction
  // (a probe of how far 16-bit arithmetic could go; its image is not a usable one).
  std::vector<PassTime> run(uint32_t lights);

 private:
  Context& context_;
  uint32_t width_, height_;
  PipelineLayout layout_;
  Pipeline pipeline_;
  PipelineLayout halfLayout_;
  std::optional<Pipeline> halfPipeline_;
  Image target_;
  PassTimer timer_;
};

}  // namespace lll
