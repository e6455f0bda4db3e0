// Technique "forward": brute-force forward shading. Every shaded pixel loops over every light, so
// its cost is pixels x lights. It is slow on purpose: it defines the right answer that every other
// technique is compared with.
#include "gpu/context.h"
#include "gpu/pipeline.h"
#include "lighting/technique.h"
#include "particles/particle_system.h"

namespace lll {

namespace {

class Forward final : public Technique {
 public:
  Forward(Context& context, const GpuScene& scene) : layout_(meshPassLayout(context, scene)) {
    GraphicsPipelineDesc desc;
    desc.vertexShader = "common/mesh.vert";
    desc.fragmentShader = "lighting/forward.frag";
    desc.colorFormats = {kHdrFormat};
    desc.depthFormat = kDepthFormat;
    desc.depthWrite = false;
    desc.depthCompare = VK_COMPARE_OP_EQUAL;  // shade each pixel once: the prepass decided visibility
    opaque_ = Pipeline(context, layout_, desc);
    desc.depthCompare = VK_COMPARE_OP_GREATER_OR_EQUAL;
    desc.blend = BlendMode::Alpha;
    blend_ = Pipeline(context, layout_, desc);
  }

  void render(FrameContext& frame) override {
    {
      ScopedPass pass(frame.timer, frame.cmd, "forward-opaque");
      drawSceneIntoHdr(frame, opaque_, layout_, DrawFilter::Opaque, true);
    }
    if (frame.scene.hasBlendDraws()) {
      ScopedPass pass(frame.timer, frame.cmd, "forward-blend");
      drawSceneIntoHdr(frame, blend_, layout_, DrawFilter::Blend, false);
    }
    if (frame.particles) frame.particles->draw(frame, ParticleShading::AllLights);
  }

 private:
  PipelineLayout layout_;
  Pipeline opaque_;
  Pipeline blend_;
};

}  // namespace

std::unique_ptr<Technique> createForward(Context& context, const GpuScene& scene, const RenderSettings&,
                                         const FrameTargets&) {
  return std::make_unique<Forward>(context, scene);
}

}  // namespace lll
