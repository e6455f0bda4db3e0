#include "lighting/lll.h"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <glm/gtc/packing.hpp>
#include <stdexcept>

#include "core/errors.h"
#include "gpu/context.h"
#include "gpu/pipeline.h"
#include "gpu/vk_check.h"
#include "lighting/light_bins.h"
#include "lighting/light_volumes.h"
#include "render/frame.h"
#include "render/interleaved_vpls.h"
#include "render/visibility.h"
#include "shared/lll_types.h"

namespace lll {

namespace {

// Lights per raster-fill batch: bounds entries keep 16 bits of id, 0xFFFF marks "no light".
constexpr uint32_t kShellBatch = 0xFFFF;
// Bounds layers (as Bezrati's sample's 12): overlapping lights rarely overwrite each other's depth.
constexpr uint32_t kBoundsLayers = 8;
// Shell meshes of the raster fills: sphere, cone, box (the fill_shell.vert specialization).
constexpr uint32_t kShellShapes = 3;

// shaders/common/lll_data.glsl's kLinkFormat.
constexpr uint32_t kLinkFormatConstant = 42;
// shaders/lighting/lll/lighting.glsl's kRecordsFromUniformBlock.
constexpr uint32_t kRecordsFromUniformBlockConstant = 43;

// The shaders' link format (kLinkCompact or kLinkWide) for --lll-link and the scene's lights.
uint32_t linkFormatFor(LllLink link, uint32_t lightCount) {
  const bool fitsCompact = lightCount <= gpu::kCompactLinkMaxLights;
  if (link == LllLink::Wide || (link == LllLink::Auto && !fitsCompact)) return gpu::kLinkWide;
  if (!fitsCompact)
    throw InputError(fmt::format("--lll-link compact: {} lights, but compact links index at most {}",
                                 lightCount, gpu::kCompactLinkMaxLights));
  return gpu::kLinkCompact;
}

// Whether the opaque shading reads listed lights' records from the uniform block (--lll-records).
// Auto: on a GPU while they fit; lavapipe (a CPU device) compiles a shader variant per bind of
// uniform blocks' values (common/frame.glsl).
bool recordsFromUniformBlock(const Context& context, LllRecords records, uint32_t lightCount) {
  const bool fits = lightCount <= gpu::kUniformLightRecords;
  if (records == LllRecords::Uniform && !fits)
    throw InputError(fmt::format("--lll-records uniform: {} lights, but the uniform block holds at most {}",
                                 lightCount, gpu::kUniformLightRecords));
  return records == LllRecords::Uniform || (records == LllRecords::Auto && fits && !context.isCpuDevice());
}

// Indexed mesh of a light shell on the GPU.
struct ShellMesh {
  Buffer vertices;
  Buffer indices;
  uint32_t indexCount = 0;
  ShellMesh() = default;
  ShellMesh(Context& context, const VolumeMesh& mesh)
      : vertices(context, mesh.positions.size() * sizeof(glm::vec3), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT,
                 MemoryUse::Device),
        indices(context, mesh.indices.size() * 4, VK_BUFFER_USAGE_INDEX_BUFFER_BIT, MemoryUse::Device),
        indexCount(uint32_t(mesh.indices.size())) {
    vertices.upload(std::span<const glm::vec3>(mesh.positions));
    indices.upload(std::span<const uint32_t>(mesh.indices));
  }
};

class LightLinkedList final : public Technique {
 public:
  LightLinkedList(Context& context, const GpuScene& scene, const RenderSettings& settings,
                  const FrameTargets& targets, const VisibilityBuffer* visibility);
  ~LightLinkedList() override;
  void buildLightData(FrameContext& frame) override;
  OpaqueShading opaqueShading() const override { return opaqueShading_; }
  LightingInterface lighting() const override;
  bool afterFrame() override;
  std::vector<std::pair<std::string, double>> stats() const override;
  TileLightLists readLists();

 private:
  void createBuffers();
  void createPipelines();
  // shaders/common/lll_data.glsl's kLinkFormat: every pass that reads or writes links is compiled
  // for the pool's format, so no walk tests it per link.
  SpecializationConstants linkConstants() const { return {{kLinkFormatConstant, linkFormat_}}; }
  // What the lit passes' lighting interface is compiled for: the links and where records are read.
  SpecializationConstants lightingConstants() const {
    SpecializationConstants constants = linkConstants();
    constants[kRecordsFromUniformBlockConstant] = uniformRecords_ ? 1u : 0u;
    return constants;
  }
  void createShells(const GpuScene& scene);
  void allocatePool(uint64_t links);
  // The frame's bindings, the lists, the fills' bounds and shell order: what the passes building
  // the lists bind.
  DescriptorWriter descriptors(const FrameContext& frame) const;
  void clear(FrameContext& frame);
  void reduceTileDepth(FrameContext& frame);
  void fillCompute(FrameContext& frame);
  void fillRaster(FrameContext& frame);
  void drawShellBatch(FrameContext& frame, uint32_t first, uint32_t end, bool backFaces);
  std::vector<ResourceUse> fillUses(VkPipelineStageFlags2 stages) const;
  void measureLists(FrameContext& frame);

  Context& context_;
  LllFill fill_;
  OpaqueShading opaqueShading_;
  uint32_t linkFormat_;
  uint32_t linkBytes_;
  bool autoLinkFormat_;
  bool uniformRecords_;
  uint32_t tilesX_ = 0;
  uint32_t tilesY_ = 0;
  uint32_t tiles_ = 0;
  uint32_t fillSplits_ = 1;
  uint32_t slices_ = 1;   // lists per tile
  uint32_t classes_ = 1;  // heads per list: 1 + K*K with --vpl-interleave K and VPLs (lll_data.glsl)
  uint64_t poolCapacity_ = 0;
  uint64_t maxPoolLinks_ = 0;
  uint32_t overflows_ = 0;
  float tileHalfDiagonalPixels_ = 0.0f;
  gpu::LllCounters lastCounters_{};
  bool countersValid_ = false;
  bool measured_ = false;

  gpu::LllUniforms uniforms_{};
  Buffer uniformBuffer_;
  Buffer heads_;
  Buffer links_;
  Buffer counters_;
  Buffer tileRange_;  // nearest and farthest linear depth of each tile
  Buffer bounds_;
  Buffer shellOrder_;
  // The compute fill's first level; its cells' far depths are written by the tile-depth pass.
  LightBins bins_;
  // shellOrder_ holds sphere-filled lights, then cone-filled ones, then boxes: shape s fills
  // shellOrder_[shapeStart_[s], shapeStart_[s + 1]).
  uint32_t shapeStart_[kShellShapes + 1] = {};
  ShellMesh shellMeshes_[kShellShapes];  // sphere, cone, box
  VkSampler depthSampler_ = VK_NULL_HANDLE;

  PipelineLayout layout_;
  PipelineLayout fillLayout_;
  Pipeline tileDepthPipeline_;
  Pipeline statsPipeline_;
  Pipeline computeFill_;
  Pipeline shellFront_[kShellShapes];
  Pipeline shellBack_[kShellShapes];
};

LightLinkedList::LightLinkedList(Context& context, const GpuScene& scene, const RenderSettings& settings,
                                 const FrameTargets& targets, const VisibilityBuffer* visibility)
    : context_(context),
      fill_(settings.lllFill),
      // --lll-shade fragment: opaque surfaces lit in the fragment shader of a second geometry pass
      // (the chapter's forward shading); compute: in a compute pass over a thin G-buffer.
      opaqueShading_(settings.lllShade == LllShade::Fragment ? OpaqueShading::Geometry
                     : visibility                            ? OpaqueShading::Visibility
                                                             : OpaqueShading::GBuffer),
      linkFormat_(linkFormatFor(settings.lllLink, scene.lightCount())),
      linkBytes_(linkFormat_ == gpu::kLinkCompact ? 8 : 16),
      autoLinkFormat_(settings.lllLink == LllLink::Auto),
      uniformRecords_(recordsFromUniformBlock(context, settings.lllRecords, scene.lightCount())) {
  const uint32_t tile = settings.tileSize;
  validateTileSize(tile);
  tilesX_ = divideRoundingUp(targets.width, tile);
  tilesY_ = divideRoundingUp(targets.height, tile);
  tiles_ = tilesX_ * tilesY_;
  if (settings.lllFillSplits > kMaxCellSplits)
    throw InputError(fmt::format("--lll-fill-splits {}: expected 0 (by light count) to {}",
                                 settings.lllFillSplits, kMaxCellSplits));
  fillSplits_ =
      settings.lllFillSplits ? settings.lllFillSplits : lllFillSplitsFor(context, scene.lightCount());
  if (settings.lllSlices > gpu::kMaxLllSlices)
    throw InputError(fmt::format("--lll-slices {}: expected 1 (one list per tile) to {} lists per tile",
                                 settings.lllSlices, gpu::kMaxLllSlices));
  slices_ = lllListsPerTile(settings);
  // --vpl-interleave: the lights before the VPLs in one list, each class of VPLs in its own, so
  // that a pixel walks only the class it evaluates (render/interleaved_vpls.h).
  if (const uint32_t k = vplInterleaveIn(scene, opaqueShading_, settings.vplInterleave); k > 1)
    classes_ = 1 + k * k;  // at most gpu::kMaxLllListClasses (the compute fill's shared arrays)
  uniforms_.slicing = glm::uvec4(slices_, classes_, 0, 0);
  uniforms_.params = glm::uvec4(0, 0, debugViewCode(settings.debugView), fillSplits_);
  uniforms_.grid = glm::vec4(float(targets.width) / float(tilesX_ * tile),
                             float(targets.height) / float(tilesY_ * tile), 0.0f, 0.0f);
  // Half a tile's diagonal in pixels, 10% more for the rays' divergence across the tile.
  tileHalfDiagonalPixels_ = 1.1f * std::sqrt(2.0f) * 0.5f * float(tile);
  // The pool is one storage buffer; compact links address at most 2^24 - 1 of them.
  maxPoolLinks_ = storageBufferCapacity(context, linkBytes_);
  if (linkFormat_ == gpu::kLinkCompact)
    maxPoolLinks_ = std::min<uint64_t>(
        maxPoolLinks_, settings.lllCompactLinkLimit ? settings.lllCompactLinkLimit : gpu::kCompactLinkEnd);
  bins_ = LightBins(context, tilesX_, tilesY_, tile, scene.lightCount());
  createBuffers();
  createPipelines();
  if (fill_ != LllFill::Compute) createShells(scene);
  allocatePool(uint64_t(tiles_) * std::max(1u, settings.linksPerTile) * std::min(slices_, 2u));
  // Last: a raw handle, which a throw above would leak (the destructor does not run then).
  depthSampler_ = createNearestClampSampler(context_);
}

LightLinkedList::~LightLinkedList() {
  vkDestroySampler(context_.device(), depthSampler_, nullptr);
}

void LightLinkedList::createBuffers() {
  const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  uniformBuffer_ =
      Buffer(context_, sizeof(gpu::LllUniforms), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::Upload);
  requireStorageBufferFits(
      context_, uint64_t(tiles_) * slices_ * classes_, 4, "the light linked list's head array",
      "lists (heads)",
      "use fewer --lll-slices, a larger --tile, a lower resolution or a smaller --vpl-interleave");
  heads_ = Buffer(context_, uint64_t(tiles_) * slices_ * classes_ * 4, storage, MemoryUse::Device);
  tileRange_ = Buffer(context_, uint64_t(tiles_) * 8, storage, MemoryUse::Device);
  // Read by the CPU after each frame: link requests (overflow) and list statistics.
  counters_ = Buffer(context_, sizeof(gpu::LllCounters), storage, MemoryUse::Readback);
  if (fill_ == LllFill::Shells)
    bounds_ = Buffer(context_, uint64_t(tiles_) * 4 * kBoundsLayers, storage, MemoryUse::Device);
}

void LightLinkedList::allocatePool(uint64_t links) {
  requireStorageBufferFits(context_, links, linkBytes_, "the light linked list's pool", "links",
                           slices_ > 1
                               ? "use fewer --lll-slices, a larger --tile, a lower resolution or fewer lights"
                               : "use a larger --tile, a lower resolution or fewer lights");
  if (links > maxPoolLinks_)  // what remains: compact links address at most 2^24 - 1
    throw InputError(fmt::format("{} links: compact links address at most {}: use --lll-link wide or auto",
                                 links, maxPoolLinks_));
  poolCapacity_ = links;
  links_ = Buffer(context_, links * linkBytes_, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::Device);
  uniforms_.params.x = uint32_t(links);
}

void LightLinkedList::createPipelines() {
  const SpecializationConstants constants = linkConstants();
  // Layouts as the shaders declare them: one for the compute passes, one for the shell fills.
  layout_ = PipelineLayout(
      context_, {"lighting/lll/tile_depth.comp", "lighting/lll/stats.comp", "lighting/lll/fill_compute.comp"},
      {}, constants);
  tileDepthPipeline_ = Pipeline(context_, layout_, "lighting/lll/tile_depth.comp", constants);
  statsPipeline_ = Pipeline(context_, layout_, "lighting/lll/stats.comp", constants);
  if (fill_ == LllFill::Compute)
    computeFill_ = Pipeline(context_, layout_, "lighting/lll/fill_compute.comp", constants);

  GraphicsPipelineDesc fill;
  fill.vertexShader = "lighting/lll/fill_shell.vert";
  fill.fragmentShader =
      fill_ == LllFill::Ray ? "lighting/lll/fill_ray.frag" : "lighting/lll/fill_shells.frag";
  fillLayout_ = PipelineLayout(context_, {fill.vertexShader, fill.fragmentShader}, {}, constants);
  fill.vertexInput = VertexInput::Position;
  fill.depthTest = false;  // the software depth test against the tile depth replaces it
  fill.depthWrite = false;
  fill.constants = constants;
  for (uint32_t shape = 0; fill_ != LllFill::Compute && shape < kShellShapes; ++shape) {
    fill.specialization = {shape, 1, kBoundsLayers};
    fill.cullMode = VK_CULL_MODE_FRONT_BIT;  // keep back faces
    shellBack_[shape] = Pipeline(context_, fillLayout_, fill);
    if (fill_ != LllFill::Shells) continue;
    fill.specialization = {shape, 0, kBoundsLayers};
    fill.cullMode = VK_CULL_MODE_BACK_BIT;
    shellFront_[shape] = Pipeline(context_, fillLayout_, fill);
  }
}

void LightLinkedList::createShells(const GpuScene& scene) {
  shellMeshes_[0] = ShellMesh(context_, sphereShell());
  shellMeshes_[1] = ShellMesh(context_, coneShell());
  shellMeshes_[2] = ShellMesh(context_, boxShell());
  // Narrow spots get the cone shell; points and wide spots (cone larger than the sphere) the
  // sphere; boxes the box.
  std::vector<uint32_t> byShape[kShellShapes];
  const auto& lights = scene.scene().lights;
  for (uint32_t i = 0; i < lights.size(); ++i) {
    const bool narrowSpot = lights[i].type == LightType::Spot && std::cos(lights[i].outerConeAngle) >= 0.5f;
    byShape[lights[i].type == LightType::Box ? 2 : narrowSpot ? 1 : 0].push_back(i);
  }
  std::vector<uint32_t> order;
  for (uint32_t shape = 0; shape < kShellShapes; ++shape) {
    shapeStart_[shape] = uint32_t(order.size());
    order.insert(order.end(), byShape[shape].begin(), byShape[shape].end());
  }
  shapeStart_[kShellShapes] = uint32_t(order.size());
  shellOrder_ = Buffer(context_, std::max<size_t>(order.size(), 1) * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                       MemoryUse::Device);
  if (!order.empty()) shellOrder_.upload(std::span<const uint32_t>(order));
}

DescriptorWriter LightLinkedList::descriptors(const FrameContext& frame) const {
  DescriptorWriter writer = meshPassDescriptors(frame);
  lighting().bind(writer);
  if (bounds_) writer.storage(8, bounds_.handle());
  if (shellOrder_) writer.storage(10, shellOrder_.handle());
  bins_.bind(writer);
  return writer;
}

void LightLinkedList::buildLightData(FrameContext& frame) {
  uniforms_.grid.z =
      tileHalfDiagonalPixels_ * 2.0f * frame.uniforms.depthParams.w / float(frame.targets.height);
  uniformBuffer_.upload(&uniforms_, sizeof(uniforms_));
  measured_ = frame.capture;
  clear(frame);
  if (fill_ == LllFill::Compute) bins_.clear(frame);
  reduceTileDepth(frame);
  if (fill_ == LllFill::Compute) {
    bins_.build(frame);
    fillCompute(frame);
  } else
    fillRaster(frame);
  if (frame.capture) measureLists(frame);
  // afterFrame reads the link counter (overflow) and the statistics.
  frame.graph.barriers({uses(counters_, Use::HostRead)});
}

LightingInterface LightLinkedList::lighting() const {
  return {"lll",
          [this](DescriptorWriter& writer) {
            writer.storage(3, uniformBuffer_.handle())
                .storage(4, heads_.handle())
                .storage(5, links_.handle())
                .storage(6, counters_.handle())
                .storage(7, tileRange_.handle());
          },
          {&heads_, &links_, &tileRange_},
          classes_,
          lightingConstants()};
}

// The heads and counters are emptied by the tile-depth pass (lighting/lll/tile_depth.comp); only the
// shells' depth bounds need a clear of their own.
void LightLinkedList::clear(FrameContext& frame) {
  if (!bounds_) return;
  frame.graph.pass("lll-clear", {uses(bounds_, Use::TransferWrite)}, [&](VkCommandBuffer cmd) {
    vkCmdFillBuffer(cmd, bounds_.handle(), 0, VK_WHOLE_SIZE, 0xFFFFFFFFu);
  });
}

void LightLinkedList::reduceTileDepth(FrameContext& frame) {
  frame.graph.pass("lll-tile-depth",
                   {uses(frame.targets.sampledDepth(), Use::Sampled, kCompute),
                    uses(tileRange_, Use::StorageWrite, kCompute), uses(heads_, Use::StorageWrite, kCompute),
                    uses(counters_, Use::StorageWrite, kCompute), bins_.farDepthWrite(kCompute)},
                   [&](VkCommandBuffer cmd) {
                     tileDepthPipeline_.bind(cmd);
                     // Only this pass samples the depth buffer: binding it while shading reads it as an
                     // attachment makes lavapipe resolve the depth image for every draw.
                     descriptors(frame)
                         .image(9, frame.targets.sampledDepth().view(),
                                sampledLayout(frame.targets.sampledDepth()), depthSampler_)
                         .push(context_, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_);
                     vkCmdDispatch(cmd, divideRoundingUp(tilesX_, gpu::kTileGroupSize),
                                   divideRoundingUp(tilesY_, gpu::kTileGroupSize), 1);
                   });
}

// What a fill reads and writes, in `stages`.
std::vector<ResourceUse> LightLinkedList::fillUses(VkPipelineStageFlags2 stages) const {
  std::vector<ResourceUse> out = {
      uses(tileRange_, Use::StorageRead, stages), uses(heads_, Use::StorageReadWrite, stages),
      uses(links_, Use::StorageWrite, stages), uses(counters_, Use::StorageReadWrite, stages)};
  if (bounds_) out.push_back(uses(bounds_, Use::StorageReadWrite, stages));
  if (shellOrder_) out.push_back(uses(shellOrder_, Use::StorageRead, VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT));
  if (fill_ == LllFill::Compute) {
    const std::vector<ResourceUse> binned = bins_.reads(stages);
    out.insert(out.end(), binned.begin(), binned.end());
  }
  return out;
}

void LightLinkedList::fillCompute(FrameContext& frame) {
  frame.graph.pass(
      "lll-fill-compute", fillUses(VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT), [&](VkCommandBuffer cmd) {
        computeFill_.bind(cmd);
        descriptors(frame).push(context_, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_);
        vkCmdDispatch(cmd, divideRoundingUp(tilesX_, 8) * fillSplits_, divideRoundingUp(tilesY_, 8), 1);
      });
}

// Batches of shells in one pass; the barriers between them are the pass's own (the bounds buffer
// is cleared and refilled per batch, front faces store before back faces read).
void LightLinkedList::fillRaster(FrameContext& frame) {
  frame.graph.pass(
      fill_ == LllFill::Ray ? "lll-fill-ray" : "lll-fill-shells",
      fillUses(VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT), [&](VkCommandBuffer cmd) {
        const uint32_t shellLights = shapeStart_[kShellShapes];
        for (uint32_t first = 0; first < shellLights; first += kShellBatch) {
          const uint32_t end = std::min(shellLights, first + kShellBatch);
          if (fill_ == LllFill::Shells) {
            if (first > 0) {  // a new batch reuses the ids: forget the previous batch's bounds
              memoryBarrier(cmd, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT,
                            VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
              vkCmdFillBuffer(cmd, bounds_.handle(), 0, VK_WHOLE_SIZE, 0xFFFFFFFFu);
              memoryBarrier(cmd, VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                            VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
            }
            drawShellBatch(frame, first, end, false);
            // Every front face has stored its depth before any back face reads it.
            memoryBarrier(cmd, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                          VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
          }
          drawShellBatch(frame, first, end, true);
        }
      });
}

void LightLinkedList::drawShellBatch(FrameContext& frame, uint32_t first, uint32_t end, bool backFaces) {
  VkCommandBuffer cmd = frame.cmd;
  // No attachments: the tile grid is the render area, the lists are the output.
  beginRendering(cmd, tilesX_, tilesY_, {}, VK_NULL_HANDLE, VK_IMAGE_LAYOUT_UNDEFINED, false);
  const gpu::FillPush push{glm::uvec4(first, 0, 0, 0)};
  for (uint32_t shape = 0; shape < kShellShapes; ++shape) {
    struct {
      const ShellMesh& mesh;
      uint32_t begin, end;
    } r = {shellMeshes_[shape], std::max(first, shapeStart_[shape]), std::min(end, shapeStart_[shape + 1])};
    if (r.begin >= r.end) continue;
    const Pipeline& pipeline = backFaces ? shellBack_[shape] : shellFront_[shape];
    pipeline.bind(cmd);
    descriptors(frame).push(context_, cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, fillLayout_);
    vkCmdPushConstants(cmd, fillLayout_.handle(), kGraphicsStages, 0, sizeof(push), &push);
    const VkDeviceSize offset = 0;
    VkBuffer vertices = r.mesh.vertices.handle();
    vkCmdBindVertexBuffers(cmd, 0, 1, &vertices, &offset);
    vkCmdBindIndexBuffer(cmd, r.mesh.indices.handle(), 0, VK_INDEX_TYPE_UINT32);
    vkCmdDrawIndexed(cmd, r.mesh.indexCount, r.end - r.begin, 0, 0, r.begin);
  }
  vkCmdEndRendering(cmd);
}

void LightLinkedList::measureLists(FrameContext& frame) {
  frame.graph.pass("lll-stats",
                   {uses(heads_, Use::StorageRead, kCompute), uses(links_, Use::StorageRead, kCompute),
                    uses(counters_, Use::StorageReadWrite, kCompute)},
                   [&](VkCommandBuffer cmd) {
                     statsPipeline_.bind(cmd);
                     descriptors(frame).push(context_, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_);
                     vkCmdDispatch(cmd, divideRoundingUp(tiles_ * slices_ * classes_, 64), 1, 1);
                   });
}

bool LightLinkedList::afterFrame() {
  // Bins that overflowed left lights out of the fill: draw again with room for them (the pool's
  // count of that frame is not the one it needs).
  if (fill_ == LllFill::Compute && bins_.afterFrame()) return true;
  std::memcpy(&lastCounters_, counters_.mapped(), sizeof(lastCounters_));
  countersValid_ = true;
  const uint64_t requested = lastCounters_.linksRequested;
  if (requested <= poolCapacity_) return false;
  // Overflow: the frame is rendered again with a pool that fits; no light is silently dropped.
  ++overflows_;
  if (requested > maxPoolLinks_ && linkFormat_ == gpu::kLinkCompact && autoLinkFormat_) {
    // Compact links address 2^24 links; auto mode moves to wide links rather than fail.
    linkFormat_ = gpu::kLinkWide;
    linkBytes_ = 16;
    maxPoolLinks_ = storageBufferCapacity(context_, linkBytes_);
    createPipelines();  // and the renderer, seeing lighting()'s constants change, the lit passes
  }
  allocatePool(grownCapacity(requested, maxPoolLinks_));
  return true;
}

std::vector<std::pair<std::string, double>> LightLinkedList::stats() const {
  std::vector<std::pair<std::string, double>> s = {
      {"links_used", double(lastCounters_.linksRequested)},
      {"link_pool_capacity", double(poolCapacity_)},
      {"link_pool_bytes", double(poolCapacity_ * linkBytes_)},
      {"head_bytes", double(tiles_) * slices_ * classes_ * 4},
      {"tile_depth_bytes", double(tiles_) * 8},
      {"lists_per_tile", double(slices_)},
      {"heads_per_list", double(classes_)},
      {"link_bytes_each", double(linkBytes_)},
      {"records_from_uniform_block", uniformRecords_ ? 1.0 : 0.0},
      {"overflows", double(overflows_)},
      {"tiles", double(tiles_)},
      {"fill_workgroups_per_cell", double(fillSplits_)},
  };
  if (bounds_) s.push_back({"bounds_bytes", double(bounds_.size())});
  if (fill_ == LllFill::Compute) {
    const auto binned = bins_.stats();
    s.insert(s.end(), binned.begin(), binned.end());
  }
  if (measured_ && countersValid_) {
    s.push_back({"longest_list", double(lastCounters_.longestList)});
    s.push_back({"mean_list", double(lastCounters_.totalListLength) /
                                  double(std::max(1u, lastCounters_.listsWithLights))});
    s.push_back({"lists_with_lights", double(lastCounters_.listsWithLights)});
  }
  return s;
}

TileLightLists LightLinkedList::readLists() {
  const std::vector<uint32_t> heads = readBackWords(context_, heads_),
                              words = readBackWords(context_, links_),
                              depth = readBackWords(context_, tileRange_);
  TileLightLists lists;
  lists.tilesX = tilesX_;
  lists.tilesY = tilesY_;
  lists.slices = slices_;
  for (uint32_t t = 0; t < tiles_; ++t)
    lists.tileRange.emplace_back(std::bit_cast<float>(depth[2 * t]), std::bit_cast<float>(depth[2 * t + 1]));
  lists.lists.resize(size_t(tiles_) * slices_);
  // A list's class heads (--vpl-interleave) read one after the other, as the walk does.
  for (size_t head = 0; head < lists.lists.size() * classes_; ++head) {
    const size_t t = head / classes_;
    uint32_t link = heads[head];
    for (uint64_t guard = 0; link != gpu::kLinkEnd && guard < poolCapacity_; ++guard) {
      if (linkFormat_ == gpu::kLinkCompact) {
        if (link == gpu::kCompactLinkEnd) break;
        const glm::vec2 d = glm::unpackHalf2x16(words[2 * link]);
        lists.lists[t].push_back({words[2 * link + 1] >> 24, d.x, d.y});
        link = words[2 * link + 1] & gpu::kCompactLinkEnd;
      } else {
        const uint32_t* w = &words[4 * size_t(link)];
        lists.lists[t].push_back({w[2], std::bit_cast<float>(w[0]), std::bit_cast<float>(w[1])});
        link = w[3];
      }
    }
  }
  return lists;
}

}  // namespace

TileLightLists readTileLightLists(Technique& technique) {
  auto* list = dynamic_cast<LightLinkedList*>(&technique);
  if (!list) throw std::invalid_argument("readTileLightLists needs the lll technique");
  return list->readLists();
}

std::unique_ptr<Technique> createLightLinkedList(Context& context, const GpuScene& scene,
                                                 const RenderSettings& settings, const FrameTargets& targets,
                                                 const VisibilityBuffer* visibility) {
  return std::make_unique<LightLinkedList>(context, scene, settings, targets, visibility);
}

}  // namespace lll
