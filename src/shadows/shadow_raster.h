#pragma once
// The sun's shadow casters rasterized in compute (--shadow-raster compute): the visibility buffer's
// rasterizer (render/compute_raster.h, common/raster_triangle.glsl) pointed at the shadow atlas's
// cascades. On the H200 the hardware pass is bound by its few raster units; compute runs on all.
//   "shadow-sun"          one invocation per opaque caster triangle (every instance) draws it into
//                         each cascade's cell: small boxes covered with 64-bit atomic max, large
//                         triangles listed;
//   "shadow-sun-bins"     each large triangle appended to the 32x32-texel bins it touches, by a
//                         workgroup (the visibility buffer's thread-per-triangle listing took 3.6 ms
//                         of 5.3 on the H200: a near cascade's triangle spans thousands of bins);
//   "shadow-sun-resolve"  one invocation per atlas texel keeps the nearest depth of its key and its
//                         bin's large triangles; the depths are copied into the atlas;
//   "shadow-sun-masked"   alpha-masked casters drawn by the hardware over that depth (they need
//                         their texture), only where the scene has them.
// Single-sided primitives are culled by their back faces, as the hardware pass culls them.
#include <string>

#include "gpu/pipeline.h"
#include "gpu/resources.h"
#include "render/compute_raster.h"

namespace lll {

class Context;
class GpuScene;
struct FrameContext;

class ShadowRaster {
 public:
  // Why `context`'s device cannot rasterize an atlas of width x height texels this way; empty
  // when it can.
  static std::string problem(const Context& context, uint32_t width, uint32_t height);

  ShadowRaster(Context& context, const GpuScene& scene, uint32_t width, uint32_t height);

  // Rasterizes every opaque caster into the cascades `shadowUniforms` (gpu::SunShadow) describes,
  // then copies the depths into `atlas`.
  void record(FrameContext& frame, const Buffer& shadowUniforms, const Image& atlas) const;

 private:
  Context& context_;
  const GpuScene& scene_;
  uint32_t width_;
  uint32_t height_;
  uint32_t records_ = 0;
  uint32_t singleSided_ = 0;
  uint32_t triangles_ = 0;
  PipelineLayout layout_;
  Pipeline trianglePipeline_;
  Pipeline binPipeline_;
  Pipeline resolvePipeline_;
  Buffer recordBuffer_;  // SurfaceRecord per (instance, opaque primitive), single-sided first
  Buffer starts_;        // each record's first triangle, and the total
  Buffer instances_;
  RasterWorkspace work_;
};

}  // namespace lll
