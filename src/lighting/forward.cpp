// Technique "forward": brute-force forward shading. Every shaded pixel loops over every light, so
// its cost is pixels x lights. It is slow on purpose: it defines the right answer that every other
// technique is compared with.
#include "gpu/context.h"
#include "gpu/pipeline.h"
#include "lighting/technique.h"
#include "particles/particle_system.h"
#include "render/visibility.h"

namespace lll {

namespace {

class Forward final : public Technique {
 public:
  Forward(Context& context, const GpuScene& scene, const VisibilityBuffer* visibility)
      : layout_(meshPassLayout(context, scene)) {
    if (visibility) {
      SpecializationConstants constants = visibility->surfaceConstants(scene);
      constants.merge(lightTypeConstants(scene));
      computeLayout_ = PipelineLayout(context, {"lighting/forward_visibility.comp"},
                                      {scene.textureTableLayout()}, constants);
      opaqueCompute_ = Pipeline(context, computeLayout_, "lighting/forward_visibility.comp", constants);
    }
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
    if (opaqueCompute_) {
      opaqueFromVisibility(frame);
    } else {
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
  // Every pixel's surface rebuilt from the visibility buffer and lit by every light, in compute.
  void opaqueFromVisibility(FrameContext& frame) {
    const FrameTargets& t = frame.targets;
    ScopedPass pass(frame.timer, frame.cmd, "forward-opaque");
    t.hdr.transition(frame.cmd, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL,
                     VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, 0,
                     VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    opaqueCompute_.bind(frame.cmd);
    DescriptorWriter writer = meshPassDescriptors(frame);
    frame.visibility->bindSurfaceData(writer, frame);
    writer.image(13, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, t.hdr.view(), VK_IMAGE_LAYOUT_GENERAL)
        .push(frame.context, frame.cmd, VK_PIPELINE_BIND_POINT_COMPUTE, computeLayout_);
    const VkDescriptorSet textures = frame.scene.textureTable();
    vkCmdBindDescriptorSets(frame.cmd, VK_PIPELINE_BIND_POINT_COMPUTE, computeLayout_.handle(), 1, 1,
                            &textures, 0, nullptr);
    dispatchPerPixel(frame.cmd, t);
    hdrFromComputeToAttachment(frame.cmd, t);
  }

  PipelineLayout layout_;
  Pipeline opaque_;
  Pipeline blend_;
  PipelineLayout computeLayout_;
  Pipeline opaqueCompute_;
};

}  // namespace

std::unique_ptr<Technique> createForward(Context& context, const GpuScene& scene, const RenderSettings&,
                                         const FrameTargets&, const VisibilityBuffer* visibility) {
  return std::make_unique<Forward>(context, scene, visibility);
}

}  // namespace lll
