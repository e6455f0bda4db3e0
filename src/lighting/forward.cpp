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
  Forward(Context& context, const GpuScene& scene)
      : layout_(meshPassLayout(context, scene)) {
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
    const FrameTargets& t = frame.targets;
    {
      ScopedPass pass(frame.timer, frame.cmd, "forward-opaque");
      beginRendering(frame.cmd, t.width, t.height, {{t.hdr.view(), true}}, t.depth.view(),
                     VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL, false);
      opaque_.bind(frame.cmd);
      meshPassDescriptors(frame).push(frame.context, frame.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS,
                                      layout_.handle());
      frame.scene.draw(frame.cmd, layout_.handle(), DrawFilter::Opaque, frame.eye);
      vkCmdEndRendering(frame.cmd);
    }
    if (frame.scene.hasBlendDraws()) {
      ScopedPass pass(frame.timer, frame.cmd, "forward-blend");
      beginRendering(frame.cmd, t.width, t.height, {{t.hdr.view(), false}}, t.depth.view(),
                     VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL, false);
      blend_.bind(frame.cmd);
      meshPassDescriptors(frame).push(frame.context, frame.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS,
                                      layout_.handle());
      frame.scene.draw(frame.cmd, layout_.handle(), DrawFilter::Blend, frame.eye);
      vkCmdEndRendering(frame.cmd);
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
