#include "render/interleaved_vpls.h"

#include <fmt/format.h>

#include <algorithm>

#include "core/errors.h"
#include "gpu/context.h"
#include "render/gpu_scene.h"
#include "shared/limits.h"

namespace lll {
namespace {

void checkVplInterleave(uint32_t side) {
  if (side < 1 || side > gpu::kMaxVplInterleave)
    throw InputError(
        fmt::format("--vpl-interleave {}: expected 1 (every pixel evaluates every VPL) to {} "
                    "(each pixel of a {}x{} block a {}th of them)",
                    side, gpu::kMaxVplInterleave, gpu::kMaxVplInterleave, gpu::kMaxVplInterleave,
                    gpu::kMaxVplInterleave * gpu::kMaxVplInterleave));
}

}  // namespace

uint32_t vplInterleaveIn(const GpuScene& scene, OpaqueShading opaque, uint32_t requested) {
  checkVplInterleave(requested);
  const bool vpls = scene.vplsTrail() && scene.firstTrailingVpl() < scene.lightCount();
  return vpls && opaque == OpaqueShading::Visibility ? requested : 1u;
}

InterleavedVpls::InterleavedVpls(Context& context, const FrameTargets& targets, uint32_t side,
                                 bool classesElsewhere)
    : context_(context), side_(side), classesElsewhere_(classesElsewhere) {
  checkVplInterleave(side);
  // Slots for an eighth of the pixels, the glossy metals' and the edge pixels' (the atrium's VPLs at
  // K = 4, 1080p: 0.6% of the pixels lack a class; more at lower resolutions, where more surfaces are
  // narrower than the pattern): in a frame with more, the metals beyond walk every class themselves
  // (the same light, slower) and the edge pixels beyond stand the classes found for the others.
  if (classesElsewhere_) slots_ = std::max(1u, targets.width * targets.height / 8);
  const uint32_t classes = side_ * side_;
  requireStorageBufferFits(context, uint64_t(slots_) * classes, 8, "the VPL slots' light per class",
                           "slots x classes", "use a lower resolution or a smaller --vpl-interleave");
  constexpr VkBufferUsageFlags kSlots = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  header_ = Buffer(context, sizeof(gpu::EveryClassHeader),
                   kSlots | VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT,
                   MemoryUse::Device, "VPL slots' header");
  surfaces_ = Buffer(context, uint64_t(slots_) * sizeof(gpu::EveryClassSurface), kSlots, MemoryUse::Device,
                     "VPL slots' surfaces");
  light_ = Buffer(context, uint64_t(slots_) * classes * 8, kSlots, MemoryUse::Device,
                  "VPL slots' light per class");
  // Written by the shading pass, read by vpl-filter's texel fetches.
  constexpr VkImageUsageFlags kStorage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
  indirect_ = Image(context, targets.width, targets.height, VK_FORMAT_R16G16B16A16_SFLOAT, kStorage,
                    "interleaved VPL light");
  key_ = Image(context, targets.width, targets.height, VK_FORMAT_R32G32B32A32_UINT, kStorage,
               "interleaved VPL surface key");
  albedoKey_ = Image(context, targets.width, targets.height, VK_FORMAT_R32G32B32A32_UINT, kStorage,
                     "interleaved VPL albedo key");
  rowSums_ = Image(context, targets.width, targets.height, VK_FORMAT_R32G32B32A32_UINT, kStorage,
                   "interleaved VPL row sums");
  nearest_ = createNearestClampSampler(context);
  rowsLayout_ = PipelineLayout(context, {"gi/vpl_filter_rows.comp"}, {}, constants());
  rows_ = Pipeline(context, rowsLayout_, "gi/vpl_filter_rows.comp", constants());
  layout_ = PipelineLayout(context, {"gi/vpl_filter.comp"}, {}, constants());
  filter_ = Pipeline(context, layout_, "gi/vpl_filter.comp", constants());
}

InterleavedVpls::~InterleavedVpls() {
  vkDestroySampler(context_.device(), nearest_, nullptr);
}

std::vector<ResourceUse> InterleavedVpls::shadingWrites() const {
  return {uses(indirect_, Use::StorageWrite, kCompute), uses(key_, Use::StorageWrite, kCompute),
          uses(albedoKey_, Use::StorageWrite, kCompute), uses(header_, Use::StorageReadWrite, kCompute),
          uses(surfaces_, Use::StorageWrite, kCompute)};
}

void InterleavedVpls::resetSlots(FrameContext& frame) {
  frame.graph.step({uses(header_, Use::TransferWrite)}, [&](VkCommandBuffer cmd) {
    const gpu::EveryClassHeader start{0, side_ * side_, 1, 0, slots_, 0, 0, 0};
    vkCmdUpdateBuffer(cmd, header_.handle(), 0, sizeof(start), &start);
  });
}

std::vector<ResourceUse> InterleavedVpls::classesUses() const {
  return {uses(header_, Use::IndirectRead), uses(header_, Use::StorageRead, kCompute),
          uses(surfaces_, Use::StorageReadWrite, kCompute), uses(light_, Use::StorageReadWrite, kCompute)};
}

DescriptorWriter& InterleavedVpls::bindSlots(DescriptorWriter& writer) const {
  return writer.storage(44, header_.handle()).storage(45, surfaces_.handle()).storage(46, light_.handle());
}

void InterleavedVpls::dispatchClasses(VkCommandBuffer cmd) const {
  vkCmdDispatchIndirect(cmd, header_.handle(), 0);
}

DescriptorWriter& InterleavedVpls::bindImages(DescriptorWriter& writer) const {
  return writer.image(38, indirect_.view(), VK_IMAGE_LAYOUT_GENERAL)
      .image(39, key_.view(), VK_IMAGE_LAYOUT_GENERAL)
      .image(48, albedoKey_.view(), VK_IMAGE_LAYOUT_GENERAL);
}

void InterleavedVpls::dispatch(VkCommandBuffer cmd, const FrameTargets& targets) const {
  // Per class a sub-image of ceil(size / k) pixels a side, in whole groups; the classes side by side.
  const uint32_t groupsX = divideRoundingUp(divideRoundingUp(targets.width, side_), gpu::kTileGroupSize);
  const uint32_t groupsY = divideRoundingUp(divideRoundingUp(targets.height, side_), gpu::kTileGroupSize);
  vkCmdDispatch(cmd, groupsX * side_, groupsY * side_, 1);
}

void InterleavedVpls::filter(FrameContext& frame) {
  const FrameTargets& t = frame.targets;
  // What both passes read: the frame's constants and the shading's two images, by texel fetches.
  auto bindShading = [&](DescriptorWriter& writer) -> DescriptorWriter& {
    return writer.storage(0, frame.uniformBuffer.handle())
        .image(38, indirect_.view(), sampledLayout(indirect_), nearest_)
        .image(39, key_.view(), sampledLayout(key_), nearest_);
  };
  frame.graph.pass("vpl-filter-rows",
                   {uses(indirect_, Use::Sampled, kCompute), uses(key_, Use::Sampled, kCompute),
                    uses(rowSums_, Use::StorageWrite, kCompute)},
                   [&](VkCommandBuffer cmd) {
                     rows_.bind(cmd);
                     DescriptorWriter writer;
                     bindShading(writer)
                         .image(50, rowSums_.view(), VK_IMAGE_LAYOUT_GENERAL)
                         .push(context_, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, rowsLayout_);
                     dispatchPerPixel(cmd, t);
                   });
  frame.graph.pass("vpl-filter",
                   {uses(t.hdr, Use::StorageReadWrite, kCompute), uses(indirect_, Use::Sampled, kCompute),
                    uses(key_, Use::Sampled, kCompute), uses(albedoKey_, Use::Sampled, kCompute),
                    uses(rowSums_, Use::Sampled, kCompute), uses(header_, Use::StorageReadWrite, kCompute),
                    uses(surfaces_, Use::StorageWrite, kCompute)},
                   [&](VkCommandBuffer cmd) {
                     filter_.bind(cmd);
                     DescriptorWriter writer;
                     bindShading(writer)
                         .image(13, t.hdr.view(), VK_IMAGE_LAYOUT_GENERAL)
                         .image(48, albedoKey_.view(), sampledLayout(albedoKey_), nearest_)
                         .image(50, rowSums_.view(), sampledLayout(rowSums_), nearest_)
                         .storage(44, header_.handle())
                         .storage(45, surfaces_.handle())
                         .push(context_, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_);
                     dispatchPerPixel(cmd, t);
                   });
}

std::vector<std::pair<std::string, double>> InterleavedVpls::stats() const {
  const double pixels = double(indirect_.width()) * indirect_.height();
  return {{"vpl-interleave", double(side_)},
          {"vpl_interleave_bytes",
           pixels * (8.0 + 16.0 + 16.0 + 16.0) + double(header_.size() + surfaces_.size() + light_.size())}};
}

}  // namespace lll
