#pragma once
// Shadow casters drawn by the hardware into a depth atlas, for any set of views: the sun's cascades
// (orthographic) and the local lights' cones and cube faces (perspective) alike.
//
// The casters are the opaque and alpha-masked primitives of every instance whose bounds may overlap
// a view's clip volume (not only those in the camera's frustum), nearest the light first so that
// the depth test rejects what lies behind them early, in one raster pass with a viewport per view.
// Single-sided materials cast from their front faces only (glTF culls their back faces),
// double-sided ones from both. Blended (glass) primitives cast no shadow. Views use reverse depth
// (1 nearest the light) and a y-down projection, as the camera does, so front faces keep their
// winding.
#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

#include "gpu/pipeline.h"
#include "gpu/resources.h"
#include "scene/scene.h"

namespace lll {

class Context;
class GpuScene;
struct FrameContext;

// A view a shadow map is drawn from: its projection and its square cell of the atlas (texels).
struct ShadowView {
  glm::mat4 viewProj{1.0f};
  uint32_t x = 0;
  uint32_t y = 0;
  uint32_t size = 0;
  // A local light's position and range (the compute rasterizer skips triangles beyond it); w 0 for
  // the sun's cascades, which reach everywhere.
  glm::vec4 reach{0.0f};
};

// Whether a world-space box may overlap the clip volume of `viewProj` (reverse depth: 0 <= z <= w):
// false only when all eight corners lie outside one of its six planes.
bool boxMayOverlapView(const glm::mat4& viewProj, const Bounds& box);

class ShadowCasters {
 public:
  ShadowCasters(Context& context, const GpuScene& scene);

  // Whether any primitive is alpha-masked (the compute rasterizer leaves those to the hardware).
  bool hasMasked() const { return hasMasked_; }
  // Each view's casters this frame, nearest the light first, their transforms uploaded for draw().
  // Before recording the frame.
  void cull(std::span<const ShadowView> views);
  // Draws the casters of `mode` (opaque or alpha-masked) of every view cull() was given, inside a
  // rendering begun on the atlas.
  void draw(const FrameContext& frame, VkCommandBuffer cmd, AlphaMode mode) const;
  // Instances drawn, summed over the views, at the last cull().
  uint32_t castersDrawn() const { return uint32_t(order_.size()); }

 private:
  Context& context_;
  const GpuScene& scene_;
  bool hasMasked_ = false;
  PipelineLayout layout_;
  Pipeline opaque_;
  Pipeline masked_;
  std::vector<Bounds> instanceBounds_;              // world-space box of each scene instance
  std::vector<std::vector<uint32_t>> opaqueDraws_;  // per mesh: its opaque primitives (draws())
  std::vector<std::vector<uint32_t>> maskedDraws_;  // per mesh: its alpha-masked primitives
  std::vector<ShadowView> views_;                   // as the last cull() was given them
  std::vector<uint32_t> firstCaster_;               // per view, where its casters start in order_
  std::vector<uint32_t> order_;                     // the scene instances drawn, view after view
  Buffer casters_;                                  // their transforms, in order_'s order
};

}  // namespace lll
