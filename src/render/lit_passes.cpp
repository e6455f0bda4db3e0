#include "render/lit_passes.h"

#include "gpu/context.h"
#include "gpu/vk_check.h"
#include "render/gpu_scene.h"
#include "render/visibility.h"

namespace lll {

LitPasses::LitPasses(Context& context, const GpuScene& scene, const FrameTargets& targets,
                     const VisibilityBuffer* visibility, OpaqueShading opaque, LightingInterface lighting)
    : context_(context),
      opaque_(opaque),
      lighting_(std::move(lighting)),
      pixels_(double(targets.width) * targets.height) {
  SpecializationConstants constants = lightTypeConstants(scene);
  if (opaque_ == OpaqueShading::Visibility) {
    if (!visibility) throw std::logic_error("LitPasses: visibility shading without a visibility buffer");
    constants.merge(visibility->surfaceConstants(scene));
    const std::string shader = litShader(lighting_, "shade_visibility.comp");
    computeLayout_ = PipelineLayout(context, {shader}, {scene.textureTableLayout()}, constants);
    compute_ = Pipeline(context, computeLayout_, shader, constants);
  } else if (opaque_ == OpaqueShading::GBuffer) {
    gbuffer_ = std::make_unique<GBuffer>(context, scene, targets);
    const std::string shader = litShader(lighting_, "shade_gbuffer.comp");
    computeLayout_ = PipelineLayout(context, {shader});
    compute_ = Pipeline(context, computeLayout_, shader, constants);
    depthSampler_ = createNearestClampSampler(context);
  }
  const std::string fragment = litShader(lighting_, "shade_geometry.frag");
  meshLayout_ = PipelineLayout(context, {"common/mesh.vert", fragment}, {scene.materialSetLayout()});
  GraphicsPipelineDesc desc;
  desc.vertexShader = "common/mesh.vert";
  desc.fragmentShader = fragment;
  desc.colorFormats = {kHdrFormat};
  desc.depthFormat = kDepthFormat;
  desc.depthWrite = false;
  desc.constants = constants;
  if (opaque_ == OpaqueShading::Geometry) {
    desc.depthCompare = VK_COMPARE_OP_EQUAL;  // shade each pixel once: the depth pass decided
    geometryOpaque_ = Pipeline(context, meshLayout_, desc);
  }
  desc.depthCompare = VK_COMPARE_OP_GREATER_OR_EQUAL;
  desc.blend = BlendMode::Alpha;
  glass_ = Pipeline(context, meshLayout_, desc);
}

LitPasses::~LitPasses() {
  vkDestroySampler(context_.device(), depthSampler_, nullptr);
}

DescriptorWriter LitPasses::litDescriptors(const FrameContext& frame) const {
  DescriptorWriter writer = meshPassDescriptors(frame);
  lighting_.bind(writer);
  return writer;
}

void LitPasses::shadeOpaque(FrameContext& frame) {
  const FrameTargets& t = frame.targets;
  constexpr VkPipelineStageFlags2 kCompute = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
  switch (opaque_) {
    case OpaqueShading::Own:
      return;
    case OpaqueShading::Geometry:
      frame.graph.pass(
          "shade-opaque",
          std::vector<ResourceUse>{uses(t.hdr, Use::ColorWrite), uses(t.depth, Use::DepthTest)} +
              lighting_.reads(VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT),
          [&](VkCommandBuffer) { drawGeometry(frame, geometryOpaque_, DrawFilter::Opaque, true); });
      return;
    case OpaqueShading::GBuffer:
      // The G-buffer pass leaves ambient and emission in hdr; the compute pass adds the lights.
      gbuffer_->record(frame, "gbuffer", t.hdr);
      frame.graph.pass("shade-opaque",
                       std::vector<ResourceUse>{uses(t.hdr, Use::StorageReadWrite, kCompute),
                                                uses(t.depth, Use::Sampled, kCompute),
                                                uses(gbuffer_->target0(), Use::Sampled, kCompute),
                                                uses(gbuffer_->target1(), Use::Sampled, kCompute)} +
                           lighting_.reads(kCompute),
                       [&](VkCommandBuffer cmd) {
                         DescriptorWriter writer = litDescriptors(frame);
                         writer
                             .image(9, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, t.depth.view(),
                                    VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL, depthSampler_)
                             .image(11, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, gbuffer_->target0().view(),
                                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)
                             .image(12, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, gbuffer_->target1().view(),
                                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
                         dispatch(frame, cmd, writer);
                       });
      return;
    case OpaqueShading::Visibility:
      // Every pixel written whole, from its rebuilt surface.
      frame.graph.pass("shade-opaque",
                       std::vector<ResourceUse>{uses(t.hdr, Use::StorageWrite, kCompute),
                                                uses(t.visibility, Use::StorageRead, kCompute)} +
                           lighting_.reads(kCompute),
                       [&](VkCommandBuffer cmd) {
                         DescriptorWriter writer = litDescriptors(frame);
                         frame.visibility->bindSurfaceData(writer, frame);
                         const VkDescriptorSet textures = frame.scene.textureTable();
                         vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, computeLayout_.handle(),
                                                 1, 1, &textures, 0, nullptr);
                         dispatch(frame, cmd, writer);
                       });
      return;
  }
}

void LitPasses::dispatch(FrameContext& frame, VkCommandBuffer cmd, DescriptorWriter& writer) {
  compute_.bind(cmd);
  writer.image(13, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, frame.targets.hdr.view(), VK_IMAGE_LAYOUT_GENERAL)
      .push(context_, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, computeLayout_);
  dispatchPerPixel(cmd, frame.targets);
}

void LitPasses::shadeGlass(FrameContext& frame) {
  if (!frame.scene.hasBlendDraws()) return;
  const FrameTargets& t = frame.targets;
  frame.graph.pass("glass",
                   std::vector<ResourceUse>{uses(t.hdr, Use::ColorBlend), uses(t.depth, Use::DepthTest)} +
                       lighting_.reads(VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT),
                   [&](VkCommandBuffer) { drawGeometry(frame, glass_, DrawFilter::Blend, false); });
}

void LitPasses::drawGeometry(FrameContext& frame, const Pipeline& pipeline, DrawFilter filter,
                             bool clearHdr) {
  const FrameTargets& t = frame.targets;
  beginRendering(frame.cmd, t.width, t.height, {{t.hdr.view(), clearHdr}}, t.depth.view(),
                 VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL, false);
  pipeline.bind(frame.cmd);
  litDescriptors(frame).push(context_, frame.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, meshLayout_);
  frame.scene.draw(frame.cmd, meshLayout_.handle(), filter);
  vkCmdEndRendering(frame.cmd);
}

std::vector<std::pair<std::string, double>> LitPasses::stats() const {
  if (!gbuffer_) return {};
  return {{"gbuffer-bytes-per-pixel", GBuffer::kBytesPerPixel},
          {"gbuffer_bytes", GBuffer::kBytesPerPixel * pixels_}};
}

}  // namespace lll
