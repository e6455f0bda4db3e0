// Technique "forward": brute-force forward shading. Every shaded point evaluates every light, so
// its cost is pixels x lights. It is slow on purpose: it defines the right answer that every other
// technique is compared with. It has no light data and no passes of its own: its lighting
// interface (shaders/lighting/forward/lighting.glsl) hands the shared passes every light. Opaque
// surfaces are lit from the visibility buffer, or per fragment of a geometry pass with
// --surfaces gbuffer (the reference the tests compare with).
#include "lighting/technique.h"

namespace lll {

namespace {

class Forward final : public Technique {
 public:
  explicit Forward(bool visibility) : visibility_(visibility) {}

  OpaqueShading opaqueShading() const override {
    return visibility_ ? OpaqueShading::Visibility : OpaqueShading::Geometry;
  }

  LightingInterface lighting() const override { return {"forward"}; }

 private:
  bool visibility_;
};

}  // namespace

std::unique_ptr<Technique> createForward(Context&, const GpuScene&, const RenderSettings&,
                                         const FrameTargets&, const VisibilityBuffer* visibility) {
  return std::make_unique<Forward>(visibility != nullptr);
}

}  // namespace lll
