#pragma once
// What a technique sees of the frame being recorded, and small helpers every pass uses.
#include <vulkan/vulkan.h>

#include <algorithm>
#include <initializer_list>
#include <string>

#include "gpu/pass_timer.h"
#include "gpu/pipeline.h"
#include "gpu/resources.h"
#include "render/frame_graph.h"
#include "render/gpu_scene.h"
#include "render/settings.h"
#include "shared/gpu_types.h"

namespace lll {

class Context;
class VisibilityBuffer;

// Screen-sized targets. Their layouts are the frame graph's business (render/frame_graph.h).
struct FrameTargets {
  uint32_t width = 0;
  uint32_t height = 0;
  Image depth;  // D32 reverse-Z
  Image hdr;    // RGBA16F linear radiance
  Image ldr;    // RGBA8 display-encoded
  // D32 reverse-Z, with particles in a scene with glass: the opaque depth with the glass drawn into
  // it (Renderer's glass-depth pass), so particles can be drawn behind the nearest glass before it
  // and in front of it after it (ParticleLayer). Null otherwise.
  Image glassDepth;
  // R32UI, with --surfaces visibility: each pixel's surface id (render/visibility.h) or kNoSurface;
  // GENERAL layout after the visibility pass. Null with --surfaces gbuffer.
  Image visibility;
  // R32F reverse-Z, with --raster compute: the opaque depth as the compute rasterizer's resolve
  // writes it. The D32 `depth` then holds it only once a pass uses `depth` (the frame graph copies
  // it in first, render/compute_raster.h): a buffer-to-depth-image copy cost 0.100 ms of a 0.74 ms
  // frame on the H200, and passes that only sample the depth have no need of it.
  Image rasterDepth;
  // Whether rasterDepth is the whole opaque depth: not where alpha-masked primitives are drawn by
  // the hardware into `depth` after the compute rasterizer.
  bool rasterDepthComplete = false;

  // The opaque depth for passes that sample it (texelFetch or a nearest sampler, `.r`): rasterDepth
  // where it is complete, else the D32 depth. Bind it in sampledLayout(sampledDepth()).
  const Image& sampledDepth() const { return rasterDepthComplete ? rasterDepth : depth; }
};

struct FrameContext {
  Context& context;
  VkCommandBuffer cmd;
  FrameGraph& graph;  // every pass goes through it: it derives the barriers and times the pass
  const GpuScene& scene;
  const FrameTargets& targets;
  const Buffer& uniformBuffer;  // FrameUniforms
  const gpu::FrameUniforms& uniforms;
  const RenderSettings& settings;
  bool capture;  // the frame is read back: techniques may add diagnostic passes (stats)
  // With --surfaces visibility: the visibility buffer drawn this frame (targets.visibility holds
  // its ids). Null with --surfaces gbuffer.
  const VisibilityBuffer* visibility = nullptr;
  // The sun's shadow (shadows/sun_shadows.h), drawn before any lighting: meshPassDescriptors binds
  // it for every pass that lights surfaces.
  const DescriptorSource* shadows = nullptr;
  // The local lights' shadows (shadows/local_shadows.h), drawn before any lighting: meshPassDescriptors
  // and the light volumes bind them for every pass that evaluates lights.
  const DescriptorSource* lightShadows = nullptr;
};

inline constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
inline constexpr VkFormat kHdrFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
inline constexpr VkFormat kLdrFormat = VK_FORMAT_R8G8B8A8_UNORM;
inline constexpr VkFormat kVisibilityFormat = VK_FORMAT_R32_UINT;

struct ColorTarget {
  VkImageView view;
  bool clear;                      // clear to `clearValue`, else load
  VkClearColorValue clearValue{};  // zeros unless given
};

struct FrameResult {
  std::vector<PassTime> passes;  // GPU time of each pass, then "frame"
  uint32_t rerenders = 0;        // times the frame was recorded again (e.g. link pool growth)
};

// Throws InputError unless `tile` is 1, 2, 4, 8 or 16 (gpu::kMaxTileSize).
void validateTileSize(uint32_t tile);
// The shaders' code of a debug view (shared/lll_types.h's kDebugNone, kDebugHeatmap, ...).
uint32_t debugViewCode(DebugView view);
// Checks a requested resolution; throws InputError for zero, negative-as-huge or oversized values.
void validateResolution(uint32_t width, uint32_t height);

// Begins dynamic rendering over the whole frame, with viewport and scissor set.
// depthLayout is DEPTH_ATTACHMENT_OPTIMAL for a writing pass, DEPTH_READ_ONLY_OPTIMAL otherwise.
void beginRendering(VkCommandBuffer cmd, uint32_t width, uint32_t height,
                    std::initializer_list<ColorTarget> colors, VkImageView depth, VkImageLayout depthLayout,
                    bool clearDepth);

inline constexpr VkShaderStageFlags kGraphicsStages =
    VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;

// Set 0 of a mesh pass: frame uniforms (0), lights (1), materials (2), and the shadows for the
// passes that light; each pass's reflected layout takes the bindings its shaders declare.
DescriptorWriter meshPassDescriptors(const FrameContext& frame);

// The specialization constants of common/brdf.glsl: whether the scene has spot and box lights, so a
// pass can compile the other light types' branches out of its light evaluation.
SpecializationConstants lightTypeConstants(const Scene& scene);
SpecializationConstants lightTypeConstants(const GpuScene& scene);

inline uint32_t divideRoundingUp(uint32_t value, uint32_t divisor) {
  return (value + divisor - 1) / divisor;
}

// Throws InputError when `count` `items` of `bytesEach` bytes (`what`, e.g. "the light array") do
// not fit in one storage buffer of `context`'s device (maxStorageBufferRange), naming the limit,
// the largest count that fits and `advice` (what the user can change; may be empty).
void requireStorageBufferFits(const Context& context, uint64_t count, uint64_t bytesEach,
                              const std::string& what, const std::string& items = "lights",
                              const std::string& advice = "");
// The capacity to grow a GPU-filled array to when a frame asked for `requested` entries: a quarter
// more, so a slowly growing scene re-renders rarely, but no more than `most`, and exactly
// `requested` when even that is more (the allocation then refuses it with the numbers).
inline uint64_t grownCapacity(uint64_t requested, uint64_t most) {
  if (requested > most) return requested;
  return std::min(most, std::max(requested, requested + requested / 4));
}
// The most items of `bytesEach` bytes one storage buffer of `context`'s device holds.
uint64_t storageBufferCapacity(const Context& context, uint64_t bytesEach);

// A mesh pass onto the HDR target (cleared first when `clearHdr`), depth-tested read-only against
// the prepass: binds `pipeline`, pushes meshPassDescriptors and draws the scene's `filter` draws.
void drawSceneIntoHdr(FrameContext& frame, const Pipeline& pipeline, const PipelineLayout& layout,
                      DrawFilter filter, bool clearHdr);

// One invocation per pixel of the frame, in kTileGroupSize x kTileGroupSize groups.
void dispatchPerPixel(VkCommandBuffer cmd, const FrameTargets& targets);

}  // namespace lll
