#include "render/visibility.h"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cstdlib>
#include <stdexcept>

#include "gpu/context.h"
#include "render/frame.h"
#include "render/gpu_scene.h"

namespace lll {

namespace {

// Constant ids of common/visibility_surface.glsl and common/visibility.frag.
constexpr uint32_t kTriangleBitsConstant = 20;
constexpr uint32_t kTextureCountConstant = 21;
constexpr uint32_t kComputedLevelOfDetailConstant = 22;
constexpr uint32_t kSecondTexCoordsConstant = 23;
constexpr uint32_t kVertexColorsConstant = 24;
constexpr uint32_t kTextureTransformsConstant = 25;

bool masked(const GpuScene& scene, const DrawItem& d) {
  return scene.scene().materials[d.material].alphaMode == AlphaMode::Mask;
}

bool doubleSided(const GpuScene& scene, const DrawItem& d) {
  return scene.scene().materials[d.material].doubleSided;
}

// Bits for triangle indices 0 .. triangles - 1 (at least one).
uint32_t bitsFor(uint64_t triangles) {
  return std::max(1u, uint32_t(std::bit_width(std::max<uint64_t>(triangles, 2) - 1)));
}

struct IdLayout {
  uint32_t triangleBits = 1;
  uint64_t maxRecords = 0;  // (primitive, instance) pairs if every instance is visible
};

IdLayout idLayout(const GpuScene& scene) {
  IdLayout layout;
  uint64_t largest = 1;
  for (const DrawItem& d : scene.draws()) {
    if (scene.isBlended(d)) continue;
    largest = std::max<uint64_t>(largest, d.indexCount / 3);
    layout.maxRecords += scene.meshInstanceCount(d.mesh);
  }
  layout.triangleBits = bitsFor(largest);
  return layout;
}

}  // namespace

std::string VisibilityBuffer::problem(const Context& context, const GpuScene& scene) {
  if (!context.visibilityBufferFeatures())
    return fmt::format(
        "{} lacks shaderDrawParameters, multiDrawIndirect, drawIndirectFirstInstance or "
        "geometryShader",
        context.info().name);
  if (!scene.textureTableProblem().empty()) return scene.textureTableProblem();
  const IdLayout layout = idLayout(scene);
  // Record indices up to 2^(32 - bits) - 2, so that no id is all ones (kNoSurface).
  const uint64_t recordLimit = (uint64_t(1) << (32 - layout.triangleBits)) - 1;
  if (layout.maxRecords > recordLimit)
    return fmt::format(
        "{} primitive instances with up to {} triangles each do not fit 32-bit pixel ids (at most {})",
        layout.maxRecords, uint64_t(1) << layout.triangleBits, recordLimit);
  return {};
}

VisibilityBuffer::VisibilityBuffer(Context& context, const GpuScene& scene, bool computeRaster,
                                   uint32_t width, uint32_t height)
    : context_(context), triangleBits_(idLayout(scene).triangleBits) {
  // The surface rebuild reads the scene's vertices and indices as storage buffers (lavapipe's are
  // at most 128 MiB: 2 million vertices).
  const char* advice = "render it with --surfaces gbuffer, which reads them as vertex streams";
  requireStorageBufferFits(context, scene.scene().vertices.size(), sizeof(Vertex),
                           "the visibility buffer's surface rebuild", "vertices", advice);
  requireStorageBufferFits(context, scene.scene().indices.size(), sizeof(uint32_t),
                           "the visibility buffer's surface rebuild", "indices", advice);
  const SpecializationConstants constants = {{kTriangleBitsConstant, triangleBits_}};
  layout_ = PipelineLayout(context, {"common/visibility.vert", "common/visibility.frag"});
  GraphicsPipelineDesc desc;
  desc.vertexShader = "common/visibility.vert";
  desc.fragmentShader = "common/visibility.frag";
  desc.vertexInput = VertexInput::PositionInstanced;
  desc.colorFormats = {kVisibilityFormat};
  desc.depthFormat = kDepthFormat;
  desc.constants = constants;
  opaque_ = Pipeline(context, layout_, desc);
  maskedLayout_ = PipelineLayout(context, {"common/visibility_mask.vert", "common/visibility_mask.frag"},
                                 {scene.materialSetLayout()});
  desc.vertexShader = "common/visibility_mask.vert";
  desc.fragmentShader = "common/visibility_mask.frag";
  desc.vertexInput = VertexInput::Mesh;
  masked_ = Pipeline(context, maskedLayout_, desc);
  for (const DrawItem& d : scene.draws()) hasMaskedDraws_ |= !scene.isBlended(d) && masked(scene, d);

  const uint64_t maxRecords = std::max<uint64_t>(1, idLayout(scene).maxRecords);
  const uint64_t draws = std::max<size_t>(1, scene.draws().size());
  records_ = Buffer(context, maxRecords * sizeof(gpu::SurfaceRecord), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                    MemoryUse::Upload, "surface-records");
  commands_ = Buffer(context, draws * sizeof(VkDrawIndexedIndirectCommand),
                     VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, MemoryUse::Upload, "visibility-draws");
  bases_ = Buffer(context, draws * sizeof(uint32_t), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::Upload,
                  "visibility-record-bases");
  if (computeRaster)
    compute_ = std::make_unique<ComputeRaster>(context, width, height, uint32_t(maxRecords), triangleBits_);
}

VisibilityBuffer::~VisibilityBuffer() = default;

void VisibilityBuffer::prepareFrame(const GpuScene& scene) {
  auto* records = static_cast<gpu::SurfaceRecord*>(records_.mapped());
  auto* commands = static_cast<VkDrawIndexedIndirectCommand*>(commands_.mapped());
  auto* bases = static_cast<uint32_t*>(bases_.mapped());
  uint32_t* starts = compute_ ? compute_->triangleStarts() : nullptr;
  recordCount_ = 0;
  triangleCount_ = 0;
  singleSided_ = doubleSided_ = 0;
  maskedDraws_.clear();
  const std::vector<DrawItem>& draws = scene.draws();
  // Commands in three groups, each contiguous: single-sided opaque, double-sided opaque, masked.
  for (int group = 0; group < 3; ++group) {
    for (uint32_t i = 0; i < draws.size(); ++i) {
      const DrawItem& d = draws[i];
      const uint32_t visible = scene.meshVisibleInstances(d.mesh);
      if (scene.isBlended(d) || visible == 0) continue;
      const int dGroup = masked(scene, d) ? 2 : doubleSided(scene, d) ? 1 : 0;
      if (dGroup != group) continue;
      const uint32_t first = scene.meshFirstInstance(d.mesh);
      for (uint32_t k = 0; k < visible; ++k) {
        records[recordCount_ + k] = {d.firstIndex, d.vertexOffset, d.material, first + k};
        if (starts && group < 2) {
          starts[recordCount_ + k] = triangleCount_;
          triangleCount_ += d.indexCount / 3;
        }
      }
      if (group == 2) {
        maskedDraws_.push_back({i, recordCount_});
      } else {
        const uint32_t command = singleSided_ + doubleSided_;
        commands[command] = {d.indexCount, visible, d.firstIndex, int32_t(d.vertexOffset), first};
        bases[command] = recordCount_;
        ++(group == 0 ? singleSided_ : doubleSided_);
      }
      recordCount_ += visible;
    }
    if (group == 0) singleSidedRecords_ = recordCount_;
    if (group == 1) {
      opaqueRecords_ = recordCount_;
      if (starts) starts[recordCount_] = triangleCount_;
    }
  }
}

void VisibilityBuffer::record(FrameContext& frame) const {
  const FrameTargets& t = frame.targets;
  if (compute_) {
    compute_->record(frame, records_, opaqueRecords_, singleSidedRecords_, triangleCount_);
    if (maskedDraws_.empty()) return;
    frame.graph.pass("visibility-masked",
                     {uses(t.depth, Use::DepthReadWrite), uses(t.visibility, Use::ColorBlend)},
                     [&](VkCommandBuffer cmd) {
                       beginRendering(cmd, t.width, t.height, {{t.visibility.view(), false, {}}},
                                      t.depth.view(), VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, false);
                       vkCmdBindIndexBuffer(cmd, frame.scene.indexBuffer().handle(), 0, VK_INDEX_TYPE_UINT32);
                       drawMasked(cmd, frame);
                       vkCmdEndRendering(cmd);
                     });
    return;
  }
  frame.graph.pass(
      "visibility", {uses(t.depth, Use::DepthWrite), uses(t.visibility, Use::ColorWrite)},
      [&](VkCommandBuffer cmd) {
        VkClearColorValue noSurface{};
        noSurface.uint32[0] = gpu::kNoSurface;
        beginRendering(cmd, t.width, t.height, {{t.visibility.view(), true, noSurface}}, t.depth.view(),
                       VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, true);
        const VkDeviceSize offsets[2] = {0, 0};
        const GpuScene& scene = frame.scene;
        const VkBuffer streams[2] = {scene.positionBuffer().handle(), scene.frameInstances().handle()};
        vkCmdBindIndexBuffer(cmd, scene.indexBuffer().handle(), 0, VK_INDEX_TYPE_UINT32);
        if (singleSided_ + doubleSided_ > 0) {
          vkCmdBindVertexBuffers(cmd, 0, 2, streams, offsets);
          opaque_.bind(cmd);
          DescriptorWriter()
              .storage(0, frame.uniformBuffer.handle())
              .storage(16, bases_.handle())
              .push(context_, cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_);
          const uint32_t stride = sizeof(VkDrawIndexedIndirectCommand);
          // gl_DrawID restarts at 0 in each call: the push constant says where the call's commands begin.
          const auto drawGroup = [&](uint32_t first, uint32_t count, VkCullModeFlags cull) {
            if (count == 0) return;
            const gpu::VisibilityPush push{glm::uvec4(0, 0, first, 0)};
            vkCmdPushConstants(cmd, layout_.handle(),
                               VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(push),
                               &push);
            vkCmdSetCullMode(cmd, cull);
            vkCmdDrawIndexedIndirect(cmd, commands_.handle(), VkDeviceSize(first) * stride, count, stride);
          };
          drawGroup(0, singleSided_, VK_CULL_MODE_BACK_BIT);
          drawGroup(singleSided_, doubleSided_, VK_CULL_MODE_NONE);
        }
        drawMasked(cmd, frame);
        vkCmdEndRendering(cmd);
      });
}

void VisibilityBuffer::drawMasked(VkCommandBuffer cmd, const FrameContext& frame) const {
  if (maskedDraws_.empty()) return;
  const GpuScene& scene = frame.scene;
  const VkDeviceSize offsets[2] = {0, 0};
  const VkBuffer meshStreams[2] = {scene.vertexBuffer().handle(), scene.frameInstances().handle()};
  vkCmdBindVertexBuffers(cmd, 0, 2, meshStreams, offsets);
  masked_.bind(cmd);
  DescriptorWriter()
      .storage(0, frame.uniformBuffer.handle())
      .storage(2, scene.materialBuffer().handle())
      .push(context_, cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, maskedLayout_);
  for (const MaskedDraw& m : maskedDraws_) {
    const DrawItem& d = scene.draws()[m.draw];
    scene.bindMaterialSet(cmd, maskedLayout_.handle(), d.material);
    const gpu::VisibilityPush push{glm::uvec4(m.recordBase, d.material, 0, 0)};
    vkCmdPushConstants(cmd, maskedLayout_.handle(), VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT,
                       0, sizeof(push), &push);
    vkCmdSetCullMode(cmd, doubleSided(scene, d) ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT);
    vkCmdDrawIndexed(cmd, d.indexCount, scene.meshVisibleInstances(d.mesh), d.firstIndex,
                     int32_t(d.vertexOffset), scene.meshFirstInstance(d.mesh));
  }
}

void VisibilityBuffer::bindSurfaceData(DescriptorWriter& writer, const FrameContext& frame) const {
  writer.storage(16, records_.handle())
      .storage(17, frame.scene.frameInstances().handle())
      .storage(18, frame.scene.vertexBuffer().handle())
      .storage(19, frame.scene.indexBuffer().handle())
      .image(20, frame.targets.visibility.view(), VK_IMAGE_LAYOUT_GENERAL);
}

SpecializationConstants VisibilityBuffer::surfaceConstants(const GpuScene& scene) const {
  return {{kTriangleBitsConstant, triangleBits_},
          {kTextureCountConstant, scene.textureCount()},
          {kComputedLevelOfDetailConstant, context_.isCpuDevice() ? 1u : 0u},
          {kSecondTexCoordsConstant, scene.secondTexCoords() ? 1u : 0u},
          {kVertexColorsConstant, scene.vertexColors() ? 1u : 0u},
          {kTextureTransformsConstant, scene.textureTransforms() ? 1u : 0u}};
}

std::string VisibilityBuffer::surfaceShader(const std::string& shader) const {
  if (!context_.nonUniformTextureFeatures()) return shader;
  const std::string suffix = ".comp";
  if (!shader.ends_with(suffix))
    throw std::logic_error("VisibilityBuffer::surfaceShader: not a .comp: " + shader);
  return shader.substr(0, shader.size() - suffix.size()) + "_nonuniform" + suffix;
}

}  // namespace lll
