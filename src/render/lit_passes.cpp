#include "render/lit_passes.h"

#include <algorithm>
#include <cstring>

#include "gpu/context.h"
#include "gpu/vk_check.h"
#include "render/gpu_scene.h"
#include "render/visibility.h"

namespace lll {
namespace {
// post/display.glsl's kWritesDisplay.
constexpr uint32_t kWritesDisplayConstant = 60;
constexpr uint32_t kGlassLightPartsConstant = 61;  // common/glass_layers.glsl
}  // namespace

LitPasses::LitPasses(Context& context, const GpuScene& scene, const FrameTargets& targets,
                     const VisibilityBuffer* visibility, OpaqueShading opaque, LightingInterface lighting,
                     bool computeGlass, uint32_t vplInterleave, bool lastShading)
    : context_(context),
      opaque_(opaque),
      lighting_(std::move(lighting)),
      pixels_(double(targets.width) * targets.height),
      computeGlass_(computeGlass && scene.hasBlendDraws()) {
  const uint32_t interleave = vplInterleaveIn(scene, opaque_, vplInterleave);
  writesDisplay_ = lastShading && opaque_ == OpaqueShading::Visibility && interleave == 1 &&
                   (computeGlass_ || !scene.hasBlendDraws());
  SpecializationConstants constants = lighting_.with(lightTypeConstants(scene));
  constants[kWritesDisplayConstant] = writesDisplay_ ? 1u : 0u;
  if (opaque_ == OpaqueShading::Visibility) {
    if (!visibility) throw std::logic_error("LitPasses: visibility shading without a visibility buffer");
    SpecializationConstants opaqueConstants = constants;
    opaqueConstants.merge(visibility->surfaceConstants(scene));
    std::string shader = litShader(lighting_, "shade_visibility.comp");
    if (interleave > 1) {
      interleaved_ = std::make_unique<InterleavedVpls>(context, targets, interleave, lighting_.listParts > 1);
      opaqueConstants.merge(interleaved_->constants());
      shader = litShader(lighting_, "shade_visibility_interleaved.comp");
      if (interleaved_->classesElsewhere()) {
        SpecializationConstants classConstants = constants;
        classConstants.merge(interleaved_->constants());
        const std::string classes = litShader(lighting_, "vpl_classes.comp");
        vplClassesLayout_ = PipelineLayout(context, {classes});
        vplClasses_ = Pipeline(context, vplClassesLayout_, classes, classConstants);
      }
    }
    shader = visibility->surfaceShader(shader);
    computeLayout_ = PipelineLayout(context, {shader}, {scene.textureTableLayout()}, opaqueConstants);
    compute_ = Pipeline(context, computeLayout_, shader, opaqueConstants);
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
  if (!computeGlass_) {
    desc.blend = BlendMode::Alpha;
    glass_ = Pipeline(context, meshLayout_, desc);
    return;
  }
  glassTestsDepth_ = targets.rasterDepthComplete;
  desc.fragmentShader =
      glassTestsDepth_ ? "common/glass_fragments_tested.frag" : "common/glass_fragments.frag";
  desc.colorFormats = {};
  if (glassTestsDepth_) {
    desc.depthFormat = VK_FORMAT_UNDEFINED;
    desc.depthTest = false;
  }
  glassFragmentsLayout_ =
      PipelineLayout(context, {"common/mesh.vert", desc.fragmentShader}, {scene.materialSetLayout()});
  glassFragments_ = Pipeline(context, glassFragmentsLayout_, desc);
  // Lights in parts (LightingInterface::listParts): glass-light lights each on workgroups of its own.
  glassParts_ = std::max(lighting_.listParts, 1u);
  constants[kGlassLightPartsConstant] = glassParts_ > 1 ? glassParts_ : 0u;
  const std::string shader = litShader(lighting_, "shade_glass.comp");
  glassLayout_ = PipelineLayout(context, {shader});
  glassCompute_ = Pipeline(context, glassLayout_, shader, constants);
  if (glassParts_ > 1) {
    const std::string parts = litShader(lighting_, "shade_glass_parts.comp");
    glassLightLayout_ = PipelineLayout(context, {parts});
    glassLight_ = Pipeline(context, glassLightLayout_, parts, constants);
  }
  const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  const uint64_t pixels = uint64_t(targets.width) * targets.height;
  requireStorageBufferFits(context, pixels, 4, "the glass fragments' list heads", "pixels",
                           "use a lower resolution or --glass raster");
  glassHeads_ = Buffer(context, pixels * 4, storage, MemoryUse::Device, "glass heads");
  const uint64_t groups = uint64_t(divideRoundingUp(targets.width, gpu::kTileGroupSize)) *
                          divideRoundingUp(targets.height, gpu::kTileGroupSize);
  glassGroups_ = Buffer(context, groups * 8, storage, MemoryUse::Device, "glass groups");
  glassDispatch_ = Buffer(context, 2 * sizeof(gpu::GlassGroupDispatch),
                          storage | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, MemoryUse::Device, "glass dispatch");
  glassGroupsLayout_ = PipelineLayout(context, {"common/glass_groups.comp"});
  glassGroupsPipeline_ = Pipeline(context, glassGroupsLayout_, "common/glass_groups.comp");
  glassCounters_ =
      Buffer(context, sizeof(gpu::GlassCounters), storage, MemoryUse::Readback, "glass counters");
  // An eighth of the pixels to start with: where glass covers more, the first frame grows the pool.
  allocateGlassPool(std::max<uint64_t>(pixels / 8, 16384));
}

void LitPasses::allocateGlassPool(uint64_t fragments) {
  requireStorageBufferFits(context_, fragments, sizeof(gpu::GlassFragment), "the glass fragments",
                           "fragments", "use a lower resolution or --glass raster");
  glassCapacity_ = fragments;
  glassNodes_ = Buffer(context_, fragments * sizeof(gpu::GlassFragment), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                       MemoryUse::Device, "glass fragments");
  glassNext_ = Buffer(context_, fragments * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::Device,
                      "glass fragment links");
  // A vec4 per fragment and part (one, unread, without parts: the glass pass's layout has it).
  const uint64_t lightSlots = glassParts_ > 1 ? fragments * glassParts_ : 1;
  requireStorageBufferFits(context_, lightSlots, 16, "the glass fragments' light per part",
                           "fragments x parts",
                           "use a lower resolution, a smaller --vpl-interleave or --glass raster");
  glassPartLight_ = Buffer(context_, lightSlots * 16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::Device,
                           "glass light per part");
}

DescriptorWriter& LitPasses::bindGlassLists(DescriptorWriter& writer) const {
  return writer.storage(32, glassHeads_.handle())
      .storage(41, glassGroups_.handle())
      .storage(33, glassNodes_.handle())
      .storage(34, glassNext_.handle())
      .storage(35, glassCounters_.handle());
}

void LitPasses::shadeGlassInCompute(FrameContext& frame) {
  const FrameTargets& t = frame.targets;
  constexpr VkPipelineStageFlags2 kFragment = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
  // The heads and group flags are cleared whole once; after that the glass pass clears what it read.
  const bool clearLists = !glassListsCleared_;
  glassListsCleared_ = true;
  frame.graph.step({uses(glassHeads_, Use::TransferWrite), uses(glassGroups_, Use::TransferWrite),
                    uses(glassDispatch_, Use::TransferWrite), uses(glassCounters_, Use::TransferWrite)},
                   [&, clearLists](VkCommandBuffer cmd) {
                     if (clearLists) {
                       vkCmdFillBuffer(cmd, glassHeads_.handle(), 0, VK_WHOLE_SIZE, gpu::kGlassListEnd);
                       vkCmdFillBuffer(cmd, glassGroups_.handle(), 0, VK_WHOLE_SIZE, 0);
                     }
                     const gpu::GlassGroupDispatch none[2] = {{0, 1, 1, 0}, {0, glassParts_, 1, 0}};
                     vkCmdUpdateBuffer(cmd, glassDispatch_.handle(), 0, sizeof(none), none);
                     const gpu::GlassCounters start{0, uint32_t(glassCapacity_), 0, 0};
                     vkCmdUpdateBuffer(cmd, glassCounters_.handle(), 0, sizeof(start), &start);
                   });
  const Image& opaqueDepth = glassTestsDepth_ ? t.sampledDepth() : t.depth;
  frame.graph.pass(
      "glass-fragments",
      {glassTestsDepth_ ? uses(opaqueDepth, Use::Sampled, kFragment) : uses(opaqueDepth, Use::DepthTest),
       uses(glassHeads_, Use::StorageReadWrite, kFragment), uses(glassNodes_, Use::StorageWrite, kFragment),
       uses(glassNext_, Use::StorageWrite, kFragment), uses(glassGroups_, Use::StorageWrite, kFragment),
       uses(glassCounters_, Use::StorageReadWrite, kFragment)},
      [&](VkCommandBuffer cmd) {
        beginRendering(cmd, t.width, t.height, {}, glassTestsDepth_ ? VK_NULL_HANDLE : t.depth.view(),
                       VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL, false);
        glassFragments_.bind(cmd);
        DescriptorWriter writer = meshPassDescriptors(frame);
        if (glassTestsDepth_) writer.image(36, opaqueDepth.view(), sampledLayout(opaqueDepth));
        bindGlassLists(writer).push(context_, cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, glassFragmentsLayout_);
        frame.scene.draw(cmd, glassFragmentsLayout_.handle(), DrawFilter::Blend);
        vkCmdEndRendering(cmd);
      });
  frame.graph.pass("glass-groups",
                   {uses(glassGroups_, Use::StorageReadWrite, kCompute),
                    uses(glassDispatch_, Use::StorageReadWrite, kCompute)},
                   [&](VkCommandBuffer cmd) {
                     glassGroupsPipeline_.bind(cmd);
                     DescriptorWriter()
                         .storage(0, frame.uniformBuffer.handle())
                         .storage(41, glassGroups_.handle())
                         .storage(42, glassDispatch_.handle())
                         .push(context_, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, glassGroupsLayout_);
                     const uint32_t groups = divideRoundingUp(t.width, gpu::kTileGroupSize) *
                                             divideRoundingUp(t.height, gpu::kTileGroupSize);
                     vkCmdDispatch(cmd, divideRoundingUp(groups, 64u), 1, 1);
                   });
  if (glassParts_ > 1)
    frame.graph.pass(
        "glass-light",
        std::vector<ResourceUse>{
            uses(glassDispatch_, Use::IndirectRead), uses(glassGroups_, Use::StorageRead, kCompute),
            uses(glassHeads_, Use::StorageRead, kCompute), uses(glassNodes_, Use::StorageRead, kCompute),
            uses(glassNext_, Use::StorageRead, kCompute), uses(glassCounters_, Use::StorageRead, kCompute),
            uses(glassPartLight_, Use::StorageWrite, kCompute)} +
            lighting_.reads(kCompute),
        [&](VkCommandBuffer cmd) {
          glassLight_.bind(cmd);
          DescriptorWriter writer = litDescriptors(frame);
          bindGlassLists(writer)
              .storage(43, glassPartLight_.handle())
              .push(context_, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, glassLightLayout_);
          vkCmdDispatchIndirect(cmd, glassDispatch_.handle(), sizeof(gpu::GlassGroupDispatch));
        });
  frame.graph.pass(
      "glass",
      std::vector<ResourceUse>{
          uses(t.hdr, Use::StorageReadWrite, kCompute), uses(t.ldr, Use::StorageWrite, kCompute),
          uses(glassDispatch_, Use::IndirectRead), uses(glassGroups_, Use::StorageReadWrite, kCompute),
          uses(glassHeads_, Use::StorageReadWrite, kCompute), uses(glassNodes_, Use::StorageRead, kCompute),
          uses(glassNext_, Use::StorageRead, kCompute), uses(glassPartLight_, Use::StorageRead, kCompute),
          uses(glassCounters_, Use::StorageReadWrite, kCompute)} +
          lighting_.reads(kCompute),
      [&](VkCommandBuffer cmd) {
        glassCompute_.bind(cmd);
        DescriptorWriter writer = litDescriptors(frame);
        bindGlassLists(writer)
            .storage(43, glassPartLight_.handle())
            .image(13, t.hdr.view(), VK_IMAGE_LAYOUT_GENERAL)
            .image(40, t.ldr.view(), VK_IMAGE_LAYOUT_GENERAL)
            .push(context_, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, glassLayout_);
        vkCmdDispatchIndirect(cmd, glassDispatch_.handle(), 0);
      });
  // afterFrame reads the counters (overflow, the deepest pixel).
  frame.graph.barriers({uses(glassCounters_, Use::HostRead)});
}

bool LitPasses::afterFrame() {
  if (!computeGlass_) return false;
  std::memcpy(&lastGlass_, glassCounters_.mapped(), sizeof(lastGlass_));
  if (lastGlass_.fragments <= glassCapacity_) return false;
  // Overflow: the frame is drawn again with a pool that fits; no glass fragment is silently dropped.
  ++glassOverflows_;
  allocateGlassPool(
      grownCapacity(lastGlass_.fragments, storageBufferCapacity(context_, sizeof(gpu::GlassFragment))));
  return true;
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
                             .image(9, t.depth.view(), VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL, depthSampler_)
                             .image(11, gbuffer_->target0().view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)
                             .image(12, gbuffer_->target1().view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
                         dispatch(frame, cmd, writer);
                       });
      return;
    case OpaqueShading::Visibility:
      if (interleaved_ && interleaved_->classesElsewhere()) interleaved_->resetSlots(frame);
      // Every pixel written whole, from its rebuilt surface.
      frame.graph.pass("shade-opaque",
                       std::vector<ResourceUse>{uses(t.hdr, Use::StorageWrite, kCompute),
                                                uses(t.ldr, Use::StorageWrite, kCompute),
                                                uses(t.visibility, Use::StorageRead, kCompute)} +
                           lighting_.reads(kCompute) +
                           (interleaved_ ? interleaved_->shadingWrites() : std::vector<ResourceUse>{}),
                       [&](VkCommandBuffer cmd) {
                         DescriptorWriter writer = litDescriptors(frame);
                         frame.visibility->bindSurfaceData(writer, frame);
                         writer.image(40, t.ldr.view(), VK_IMAGE_LAYOUT_GENERAL);
                         if (interleaved_) interleaved_->bindSlots(interleaved_->bindImages(writer));
                         const VkDescriptorSet textures = frame.scene.textureTable();
                         vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, computeLayout_.handle(),
                                                 1, 1, &textures, 0, nullptr);
                         dispatch(frame, cmd, writer);
                       });
      if (interleaved_) interleaved_->filter(frame);
      // The slots' classes (the glossy metals' every class, the edge pixels' missing ones), lit on
      // their own surfaces and added to their pixels by the last of each slot's classes.
      if (interleaved_ && interleaved_->classesElsewhere()) {
        frame.graph.pass("vpl-classes",
                         std::vector<ResourceUse>{uses(t.hdr, Use::StorageReadWrite, kCompute)} +
                             interleaved_->classesUses() + lighting_.reads(kCompute),
                         [&](VkCommandBuffer cmd) {
                           vplClasses_.bind(cmd);
                           DescriptorWriter writer = litDescriptors(frame);
                           writer.image(13, t.hdr.view(), VK_IMAGE_LAYOUT_GENERAL);
                           interleaved_->bindSlots(writer).push(context_, cmd, VK_PIPELINE_BIND_POINT_COMPUTE,
                                                                vplClassesLayout_);
                           interleaved_->dispatchClasses(cmd);
                         });
      }
      return;
  }
}

void LitPasses::dispatch(FrameContext& frame, VkCommandBuffer cmd, DescriptorWriter& writer) {
  compute_.bind(cmd);
  writer.image(13, frame.targets.hdr.view(), VK_IMAGE_LAYOUT_GENERAL)
      .push(context_, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, computeLayout_);
  if (interleaved_)
    interleaved_->dispatch(cmd, frame.targets);
  else
    dispatchPerPixel(cmd, frame.targets);
}

void LitPasses::shadeGlass(FrameContext& frame) {
  if (!frame.scene.hasBlendDraws()) return;
  if (computeGlass_) return shadeGlassInCompute(frame);
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
  std::vector<std::pair<std::string, double>> s;
  if (interleaved_) s = interleaved_->stats();
  if (gbuffer_)
    s.insert(s.end(), {{"gbuffer-bytes-per-pixel", GBuffer::kBytesPerPixel},
                       {"gbuffer_bytes", GBuffer::kBytesPerPixel * pixels_}});
  if (computeGlass_)
    s.insert(s.end(),
             {{"glass-fragments", double(lastGlass_.fragments)},
              {"glass-fragment-capacity", double(glassCapacity_)},
              {"glass-deepest-pixel", double(lastGlass_.deepest)},
              {"glass-pool-overflows", double(glassOverflows_)},
              {"glass_bytes", double(glassHeads_.size() + glassNodes_.size() + glassNext_.size() +
                                     glassGroups_.size() + glassDispatch_.size() + glassPartLight_.size())}});
  return s;
}

}  // namespace lll
