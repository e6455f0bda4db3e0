#pragma once
// A depth atlas of shadow views and who draws them, shared by the sun's cascades
// (shadows/sun_shadows.h) and the local lights' views (shadows/local_shadows.h): the image (D32
// where the hardware draws casters, R32F where the compute rasterizer writes it alone), its sampler
// (the shaders compare, common/shadow_compare.glsl: reverse depth, lit where nearer the light than
// stored), the hardware's casters (shadows/shadow_casters.h) and, with --shadow-raster compute or
// auto's choice on a GPU, the compute rasterizer (shadows/shadow_raster.h).
#include <memory>
#include <span>
#include <string>

#include "gpu/pipeline.h"
#include "gpu/resources.h"
#include "render/settings.h"
#include "shadows/shadow_casters.h"

namespace lll {

class Context;
class GpuScene;
class ShadowRaster;
struct FrameContext;

struct ShadowAtlasDesc {
  uint32_t width = 1;
  uint32_t height = 1;
  uint32_t maxViews = 0;  // 0: nothing casts; the atlas is cleared each frame and never drawn
  RasterChoice raster = RasterChoice::Auto;  // auto: compute on a GPU where it fits
  std::string pass;                          // the passes' names ("shadow-sun")
  std::string image;                         // the image's name ("sun-shadow-atlas")
  std::string request;  // the options that asked for it, for a refusal ("--shadow-raster compute")
};

class ShadowAtlas {
 public:
  ShadowAtlas();
  // Throws InputError (naming desc.request) when compute is asked for and the device cannot.
  ShadowAtlas(Context& context, const GpuScene& scene, const ShadowAtlasDesc& desc);
  ~ShadowAtlas();
  ShadowAtlas(ShadowAtlas&&) noexcept;
  ShadowAtlas& operator=(ShadowAtlas&&) noexcept;

  // This frame's views: handed to the compute rasterizer, and culled for the hardware (all casters,
  // or the alpha-masked ones the compute pass leaves to it). Before recording the frame.
  void setViews(std::span<const ShadowView> views);
  // The atlas's passes (an untimed clear when no view is set), leaving it readable by every shader
  // stage for the rest of the frame.
  void record(FrameContext& frame) const;
  // The atlas and its sampler at `binding`.
  void bind(DescriptorWriter& writer, uint32_t binding) const;

  bool computeRaster() const { return computeRaster_ != nullptr; }
  uint32_t castersDrawn() const { return casters_ ? casters_->castersDrawn() : 0; }
  uint32_t width() const { return image_.width(); }
  uint32_t height() const { return image_.height(); }
  double bytes() const { return 4.0 * width() * height(); }

 private:
  Context* context_ = nullptr;
  std::string pass_;
  Image image_;
  VkSampler sampler_ = VK_NULL_HANDLE;
  std::unique_ptr<ShadowCasters> casters_;
  std::unique_ptr<ShadowRaster> computeRaster_;
  uint32_t views_ = 0;  // set this frame
};

}  // namespace lll
