#include "shadows/shadow_atlas.h"

#include <fmt/format.h>

#include <utility>

#include "core/errors.h"
#include "gpu/context.h"
#include "gpu/vk_check.h"
#include "render/frame.h"
#include "shadows/shadow_raster.h"

namespace lll {

ShadowAtlas::ShadowAtlas(Context& context, const GpuScene& scene, const ShadowAtlasDesc& desc)
    : context_(&context), pass_(desc.pass) {
  bool compute = false;
  if (desc.maxViews > 0) {
    casters_ = std::make_unique<ShadowCasters>(context, scene);
    // auto: compute where it fits, on a GPU (bench/README.md, "The sun's shadow").
    const std::string problem = ShadowRaster::problem(context, desc.width, desc.height);
    if (desc.raster == RasterChoice::Compute && !problem.empty())
      throw InputError(fmt::format("{}: {}", desc.request, problem));
    compute = desc.raster == RasterChoice::Compute ||
              (desc.raster == RasterChoice::Auto && problem.empty() && !context.isCpuDevice());
  }
  // The compute rasterizer writes an R32F atlas itself, unless the hardware must draw alpha-masked
  // casters over its depths: then they are copied into a D32 one.
  const bool intoImage = compute && !casters_->hasMasked();
  if (intoImage)
    image_ = Image(context, desc.width, desc.height, VK_FORMAT_R32_SFLOAT,
                   VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT, desc.image);
  else
    image_ = Image(context, desc.width, desc.height, VK_FORMAT_D32_SFLOAT,
                   VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                       VK_IMAGE_USAGE_TRANSFER_DST_BIT,  // the compute rasterizer's copy
                   desc.image);
  // Read as plain floats and compared in the shaders (common/shadow_compare.glsl): an R32F image
  // has no comparison sampling everywhere.
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.magFilter = info.minFilter = VK_FILTER_NEAREST;
  info.addressModeU = info.addressModeV = info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  VK_CHECK(vkCreateSampler(context.device(), &info, nullptr, &sampler_));
  if (compute)
    computeRaster_ = std::make_unique<ShadowRaster>(context, scene, desc.width, desc.height, desc.maxViews,
                                                    desc.pass, intoImage);
}

ShadowAtlas::ShadowAtlas() = default;

ShadowAtlas::~ShadowAtlas() {
  computeRaster_.reset();
  if (sampler_ != VK_NULL_HANDLE) vkDestroySampler(context_->device(), sampler_, nullptr);
}

ShadowAtlas::ShadowAtlas(ShadowAtlas&& other) noexcept {
  *this = std::move(other);
}

ShadowAtlas& ShadowAtlas::operator=(ShadowAtlas&& other) noexcept {
  if (this == &other) return *this;
  computeRaster_.reset();
  if (sampler_ != VK_NULL_HANDLE) vkDestroySampler(context_->device(), sampler_, nullptr);
  context_ = other.context_;
  pass_ = std::move(other.pass_);
  image_ = std::move(other.image_);
  sampler_ = std::exchange(other.sampler_, VK_NULL_HANDLE);
  casters_ = std::move(other.casters_);
  computeRaster_ = std::move(other.computeRaster_);
  views_ = other.views_;
  return *this;
}

void ShadowAtlas::setViews(std::span<const ShadowView> views) {
  views_ = casters_ ? uint32_t(views.size()) : 0u;
  if (views_ == 0) return;
  if (computeRaster_) computeRaster_->setViews(views);
  // The hardware draws the casters (all of them, or the alpha-masked ones after the compute pass).
  if (!computeRaster_ || casters_->hasMasked()) casters_->cull(views);
}

void ShadowAtlas::record(FrameContext& frame) const {
  constexpr VkPipelineStageFlags2 kReaders = VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT |
                                             VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT |
                                             VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
  const bool drawing = views_ > 0;
  // The hardware's pass: every caster (`clear`), or the alpha-masked ones over the compute depth.
  const auto drawCasters = [&](VkCommandBuffer cmd, bool clear) {
    beginRendering(cmd, image_.width(), image_.height(), {}, image_.view(),
                   VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, clear);
    if (drawing && clear) casters_->draw(frame, cmd, AlphaMode::Opaque);
    if (drawing) casters_->draw(frame, cmd, AlphaMode::Mask);
    vkCmdEndRendering(cmd);
  };
  if (!drawing) {
    // Nothing reads an atlas no view was drawn into; a depth atlas is cleared all the same.
    if (image_.format() == VK_FORMAT_D32_SFLOAT)
      frame.graph.step({uses(image_, Use::DepthWrite)}, [&](VkCommandBuffer cmd) { drawCasters(cmd, true); });
  } else if (!computeRaster_) {
    frame.graph.pass(pass_, {uses(image_, Use::DepthWrite)},
                     [&](VkCommandBuffer cmd) { drawCasters(cmd, true); });
  } else {
    computeRaster_->record(frame, image_);
    if (casters_->hasMasked())
      frame.graph.pass(pass_ + "-masked", {uses(image_, Use::DepthReadWrite)},
                       [&](VkCommandBuffer cmd) { drawCasters(cmd, false); });
  }
  // Every later pass may read it, in any shader stage: one transition here covers them all.
  frame.graph.step({uses(image_, Use::Sampled, kReaders)}, [](VkCommandBuffer) {});
}

void ShadowAtlas::bind(DescriptorWriter& writer, uint32_t binding) const {
  writer.image(binding, image_.view(),
               image_.format() == VK_FORMAT_D32_SFLOAT ? VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL
                                                       : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
               sampler_);
}

}  // namespace lll
