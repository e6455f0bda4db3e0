// The tiled compute particle renderer (--particle-render compute), after AMD's GPUParticles11 and
// MiniEngine's ParticleTileRender: no quad reaches the rasterizer.
//   particles-bin        each visible particle (draw order) writes what the tiles need of it and
//                        counts itself in the tiles its disc may cover;
//   particles-bin-scan   a prefix sum of the counts in blocks (particles/tile_scan.comp);
//   particles-bin-scatter  each particle appends its key to those tiles.
//   particles-composite  workgroups per tile (groups) each put their run of the tile's slabs in
//                        order nearest first (consecutive cells of at most 256 particles together
//                        sorted as one) and blend every pixel front to back into (colour,
//                        transmittance), stopping where it is opaque (lit/particles_tiles.comp);
//                        with glass in the scene, two layers at once: the particles in front of
//                        the nearest glass and those behind it;
//   particles-merge      with more than one group a tile: each particle pixel's groups combined
//                        front to back into group 0's (particles/merge_groups.comp), both layers;
//   particles-resolve    group 0's layer, upsampled with the depth below full resolution, over
//                        the frame (particles/resolve.comp); with glass, the layer behind it
//                        before the glass pass (particles-resolve-behind-glass), the one in front
//                        after.
// A tile's list is cut into slabs of the draw order (one per kParticlesPerSlab slots, up to
// kParticleMaxSlabs): a tile sorts and reads one slab at a time, front first, and stops at the
// slab that made it opaque. With a million particles a tile may hold a hundred thousand; sorting
// them all before blending the first cost most of the frame.
// The entry array grows when a frame asked for more than it holds and the frame is drawn again
// (afterFrame), as the light bins do: no particle is dropped.
// A cell of more than kParticleTileSharedSort particles is not sorted: the composite marks its keys in
// a bitmap of the slab's range of keys in shared memory and reads them back in order (the sort it
// replaced, in place in the entry array, cost most of a million particles' composite on the H200).
// A group that finds a group in front of it made its whole tile opaque stops and writes nothing
// (tiles.opaque); particles-merge stops combining at that group.
#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstring>
#include <stdexcept>

#include "gpu/context.h"
#include "particles/particle_system.h"
#include "render/frame.h"

namespace lll {

namespace {
// The composite's bitmap of a slab's keys (32 a word in kParticleTileBitmapWords words) holds the
// longest slab, ceil(visible / slabs) keys: below 2 x kParticlesPerSlab slots where the slabs are
// bit_ceil(slots / kParticlesPerSlab), and kMaxParticles / kParticleMaxSlabs + 1 where they are capped.
static_assert(gpu::kMaxParticles / gpu::kParticleMaxSlabs + 1 <= 32 * gpu::kParticleTileBitmapWords);
static_assert(2 * gpu::kParticlesPerSlab <= 32 * gpu::kParticleTileBitmapWords);
static_assert(gpu::kParticleTileSharedSort <= gpu::kParticleTileBitmapWords);
static_assert(gpu::kParticleTileSharedSort <=
              gpu::kParticleTileSize * gpu::kParticleTileSize);  // one key an invocation
static_assert(gpu::kParticleMaxSlabs <=
              gpu::kParticleTileSize * gpu::kParticleTileSize);  // one cell an invocation
// Initial entries per tile (grown on overflow, grownCapacity).
constexpr uint64_t kInitialEntriesPerTile = 64;
}  // namespace

// Fitted on the H200, settled smoke at 1080p (vertex-lit; every particle pass, ms, with 1 / 2 / 4 / 8 /
// 16 / 32 groups; bench/README.md 2026-12-04 (fourth) and 2026-12-03 (fifth)):
//   full:    65,536 (16 slabs) 1.64 / 1.69 / 1.59;  131,072 (32) 2.58 / 2.62 / 2.35 / 2.51;
//            262,144 (64) 3.94 / - / 3.75 / 3.59 / 4.45;  a million (64) 10.28 / 10.20 / 9.15 /
//            8.58 / 8.47 / 11.23;
//   half:    65,536 - / - / 2.03 / 2.27 / 3.02;  a million - / - / - / 11.19 / 11.16 / 13.84;
//   quarter: 65,536 - / - / 1.59 / 1.47 / 1.86;  a million - / - / 14.85 / 9.84 / 8.66 / 8.75.
// More groups help where a tile holds many particles, mostly the tiles at a plume's edge, which never
// turn opaque and blend every slab; they cost where the groups behind blend what the front ones make
// opaque before they see it, and past what the GPU runs at once.
uint32_t defaultParticleTileGroups(uint32_t slabs, uint32_t scale) {
  return std::clamp(slabs * scale / 8, std::min(4u, slabs), gpu::kParticleMaxGroups);
}

void ParticleSystem::prepareTiles(const FrameContext& frame) {
  Tiles& t = tiles_;
  if (t.width == frame.targets.width && t.height == frame.targets.height) return;
  t.width = frame.targets.width;
  t.height = frame.targets.height;
  t.header = {};
  t.header.scale = resolutionScale_;
  const uint32_t layerWidth = divideRoundingUp(t.width, resolutionScale_);
  const uint32_t layerHeight = divideRoundingUp(t.height, resolutionScale_);
  t.header.tilesX = divideRoundingUp(layerWidth, gpu::kParticleTileSize);
  t.header.tilesY = divideRoundingUp(layerHeight, gpu::kParticleTileSize);
  t.header.layerWidth = layerWidth;
  t.header.layerHeight = layerHeight;
  // At full resolution particles-resolve reads the frame's depth: a 1 x 1 stand-in.
  const bool layered = resolutionScale_ > 1;
  t.layerDepth = Image(context_, layered ? layerWidth : 1, layered ? layerHeight : 1, VK_FORMAT_R32_SFLOAT,
                       VK_IMAGE_USAGE_STORAGE_BIT, "particle layer depth");
  t.header.cellsX = std::clamp(std::bit_ceil(capacity_ / gpu::kParticlesPerSlab), 1u, gpu::kParticleMaxSlabs);
  t.header.cellsY = t.header.tilesX * t.header.tilesY;
  const uint64_t tiles = t.header.cellsY;
  const uint64_t cells = tiles * t.header.cellsX;
  // As many as one storage buffer holds.
  const uint64_t layerBytes = uint64_t(layerWidth) * layerHeight * sizeof(glm::uvec2);
  const uint64_t mostGroups =
      tileGroups_ ? tileGroups_ : defaultParticleTileGroups(t.header.cellsX, resolutionScale_);
  t.header.groups = uint32_t(std::clamp<uint64_t>(
      std::min<uint64_t>({t.header.cellsX, mostGroups, storageBufferCapacity(context_, layerBytes)}), 1,
      gpu::kParticleMaxGroups));
  requireStorageBufferFits(context_, layerBytes * t.header.groups, 1, "the particle layers", "bytes",
                           "use a lower resolution or --particle-resolution half");
  t.layers = Buffer(context_, layerBytes * t.header.groups, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                    MemoryUse::Device, "particle layers");
  t.opaque = Buffer(context_, tiles * t.header.groups * sizeof(uint32_t),
                    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::Device,
                    "particle tile groups opaque");
  if (frame.targets.glassDepth) {
    t.layersBehind = Buffer(context_, layerBytes * t.header.groups, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                            MemoryUse::Device, "particle layers behind glass");
    t.layerDepthBehind =
        Image(context_, layered ? layerWidth : 1, layered ? layerHeight : 1, VK_FORMAT_R32_SFLOAT,
              VK_IMAGE_USAGE_STORAGE_BIT, "particle layer depth behind glass");
  }
  t.maxEntries = storageBufferCapacity(context_, 4);
  t.headerBuffer = Buffer(context_, sizeof(gpu::ParticleTileHeader),
                          VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                          MemoryUse::Readback, "particle tiles header");
  t.scanBlocks = uint32_t(divideRoundingUp(cells, uint64_t(gpu::kParticleScanBlock)));
  // 8192 x 8192 pixels (the CLI's most) with 64 slabs: 16,384 blocks; Vulkan dispatches 65,535 or more.
  if (t.scanBlocks > 65535)
    throw std::logic_error(fmt::format("{} particle tile cells: more blocks than one dispatch holds", cells));
  t.blockSums = Buffer(context_, uint64_t(t.scanBlocks) * sizeof(glm::uvec2),
                       VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::Device, "particle tiles block sums");
  t.cells = Buffer(context_, cells * sizeof(gpu::LightBinCell),
                   VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::Device,
                   "particle tiles cells");
  requireStorageBufferFits(context_, capacity_, sizeof(gpu::ParticleScreen), "the particles' screen data",
                           "particles", "use fewer particles (--particle-count)");
  t.screen = Buffer(context_, uint64_t(capacity_) * sizeof(gpu::ParticleScreen),
                    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::Device, "particle screen data");
  allocateTileEntries(std::min(t.maxEntries, std::max<uint64_t>(tiles * kInitialEntriesPerTile, capacity_)));
  if (!t.count) {
    t.binLayout = PipelineLayout(context_, {"particles/bin.comp"});
    const uint32_t centreLit = lighting_ == ParticleLighting::Vertex ? 1 : 0;
    const SpecializationConstants constants = lightTypeConstants(frame.scene);
    // Invocations a particle (particles/bin.comp): 8 at full resolution, one below it.
    const uint32_t lanes = resolutionScale_ == 1 ? 8 : 1;
    auto bin = [&](uint32_t scatter) {
      SpecializationConstants c = constants;
      c[0] = scatter;
      c[1] = centreLit;
      c[2] = lanes;
      c[3] = gpu::kParticleGroupSize * lanes;
      return Pipeline(context_, t.binLayout, "particles/bin.comp", c);
    };
    t.count = bin(0);
    t.scatter = bin(1);
    t.scanLayout = PipelineLayout(context_, {"particles/tile_scan.comp"});
    for (uint32_t step = 0; step < 3; ++step)
      t.scan[step] =
          Pipeline(context_, t.scanLayout, "particles/tile_scan.comp", SpecializationConstants{{0, step}});
    t.mergeLayout = PipelineLayout(context_, {"particles/merge_groups.comp"});
    for (uint32_t glass = 0; glass < 2; ++glass)
      t.merge[glass] = Pipeline(context_, t.mergeLayout, "particles/merge_groups.comp",
                                SpecializationConstants{{0, glass}});
    t.resolveLayout = PipelineLayout(context_, {"particles/resolve.comp"});
    t.resolve = Pipeline(context_, t.resolveLayout, "particles/resolve.comp");
  }
}

void ParticleSystem::allocateTileEntries(uint64_t entries) {
  requireStorageBufferFits(context_, entries, 4, "the particle tiles", "entries",
                           "use fewer or smaller particles or a lower resolution");
  tiles_.header.capacity = uint32_t(std::max<uint64_t>(entries, 1));
  tiles_.entries = Buffer(context_, uint64_t(tiles_.header.capacity) * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                          MemoryUse::Device, "particle tile entries");
}

void ParticleSystem::binTiles(FrameContext& frame) {
  prepareTiles(frame);
  Tiles& t = tiles_;
  const std::vector<ResourceUse> particleReads{
      uses(counters_, Use::IndirectRead), uses(counters_, Use::StorageRead, kCompute),
      uses(uniforms_, Use::StorageRead, kCompute), uses(particles_, Use::StorageRead, kCompute),
      uses(drawOrder_, Use::StorageRead, kCompute)};
  std::vector<ResourceUse> clears{uses(t.headerBuffer, Use::TransferWrite), uses(t.cells, Use::TransferWrite),
                                  uses(t.opaque, Use::TransferWrite)};
  if (radiance_) clears.push_back(uses(radiance_, Use::StorageRead, kCompute));
  // The count and the scatter: one shader, one layout.
  auto dispatch = [&](VkCommandBuffer cmd, const Pipeline& pipeline) {
    pipeline.bind(cmd);
    DescriptorWriter writer = systemDescriptors(frame);
    // Read only with vertex lighting (specialization constant 1); a stand-in otherwise.
    if (!radiance_) writer.storage(15, t.screen.handle());
    writer.storage(17, t.headerBuffer.handle())
        .storage(18, t.cells.handle())
        .storage(19, t.entries.handle())
        .storage(20, t.screen.handle())
        .push(context_, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, t.binLayout);
    vkCmdDispatchIndirect(cmd, counters_.handle(), offsetof(gpu::ParticleCounters, dispatch));
  };
  // Three timed passes: the count (with the clears), the prefix sum, the scatter.
  frame.graph.pass("particles-bin", clears + particleReads, [&](VkCommandBuffer cmd) {
    gpu::ParticleTileHeader header = t.header;
    header.requested = 0;
    vkCmdUpdateBuffer(cmd, t.headerBuffer.handle(), 0, sizeof(header), &header);
    vkCmdFillBuffer(cmd, t.cells.handle(), 0, VK_WHOLE_SIZE, 0);
    vkCmdFillBuffer(cmd, t.opaque.handle(), 0, VK_WHOLE_SIZE, 0);
    frame.graph.barriers({uses(t.headerBuffer, Use::StorageRead, kCompute),
                          uses(t.cells, Use::StorageReadWrite, kCompute),
                          uses(t.screen, Use::StorageWrite, kCompute)});
    dispatch(cmd, t.count);
  });
  frame.graph.pass(
      "particles-bin-scan",
      {uses(t.headerBuffer, Use::StorageReadWrite, kCompute), uses(t.cells, Use::StorageReadWrite, kCompute),
       uses(t.blockSums, Use::StorageReadWrite, kCompute)},
      [&](VkCommandBuffer cmd) {
        // The three steps share one layout: the descriptors pushed once stay bound.
        for (uint32_t step = 0; step < 3; ++step) {
          if (step > 0)
            frame.graph.barriers({uses(t.headerBuffer, Use::StorageReadWrite, kCompute),
                                  uses(t.cells, Use::StorageReadWrite, kCompute),
                                  uses(t.blockSums, Use::StorageReadWrite, kCompute)});
          t.scan[step].bind(cmd);
          if (step == 0)
            DescriptorWriter()
                .storage(17, t.headerBuffer.handle())
                .storage(18, t.cells.handle())
                .storage(49, t.blockSums.handle())
                .push(context_, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, t.scanLayout);
          vkCmdDispatch(cmd, step == 1 ? 1 : t.scanBlocks, 1, 1);
        }
      });
  frame.graph.pass(
      "particles-bin-scatter",
      particleReads +
          std::vector<ResourceUse>{uses(t.headerBuffer, Use::StorageRead, kCompute),
                                   uses(t.cells, Use::StorageReadWrite, kCompute),
                                   // Only read, but one shader with the count pass, which writes it.
                                   uses(t.screen, Use::StorageReadWrite, kCompute),
                                   uses(t.entries, Use::StorageWrite, kCompute)},
      [&](VkCommandBuffer cmd) { dispatch(cmd, t.scatter); });
}

void ParticleSystem::composite(FrameContext& frame, const DrawPipelines& pipelines,
                               const LightingInterface& lighting) {
  Tiles& t = tiles_;
  const FrameTargets& targets = frame.targets;
  const Image& depth = targets.sampledDepth();
  // With glass: its depth, and the layer behind it. Without: stand-ins the shader never touches.
  const bool behind = bool(targets.glassDepth);
  const Image& glass = behind ? targets.glassDepth : depth;
  const Buffer& layersBehind = behind ? t.layersBehind : t.layers;
  const Image& layerDepthBehind = behind ? t.layerDepthBehind : t.layerDepth;
  std::vector<ResourceUse> used{uses(depth, Use::Sampled, kCompute),
                                uses(counters_, Use::StorageRead, kCompute),
                                uses(uniforms_, Use::StorageRead, kCompute),
                                uses(t.headerBuffer, Use::StorageReadWrite, kCompute),
                                uses(t.cells, Use::StorageRead, kCompute),
                                uses(t.entries, Use::StorageRead, kCompute),
                                uses(t.screen, Use::StorageRead, kCompute),
                                uses(t.layers, Use::StorageWrite, kCompute),
                                uses(t.opaque, Use::StorageReadWrite, kCompute),
                                uses(t.layerDepth, Use::StorageWrite, kCompute)};
  if (atlas_) used.push_back(uses(atlas_, Use::StorageRead, kCompute));
  if (behind) {
    used.push_back(uses(glass, Use::Sampled, kCompute));
    used.push_back(uses(t.layersBehind, Use::StorageWrite, kCompute));
    used.push_back(uses(t.layerDepthBehind, Use::StorageWrite, kCompute));
  }
  frame.graph.pass("particles-composite", used + lighting.reads(kCompute), [&](VkCommandBuffer cmd) {
    pipelines.composite.bind(cmd);
    DescriptorWriter writer = descriptors(frame, lighting);
    writer.storage(17, t.headerBuffer.handle())
        .storage(18, t.cells.handle())
        .storage(19, t.entries.handle())
        .storage(20, t.screen.handle())
        .storage(23, t.layers.handle())
        .storage(47, t.opaque.handle())
        .image(16, depth.view(), sampledLayout(depth), depthSampler_)
        .image(25, glass.view(), sampledLayout(glass), depthSampler_)
        .image(24, t.layerDepth.view(), VK_IMAGE_LAYOUT_GENERAL)
        .storage(36, layersBehind.handle())
        .image(37, layerDepthBehind.view(), VK_IMAGE_LAYOUT_GENERAL);
    // Read only with atlas lighting (specialization constant 0 == 2); a stand-in otherwise.
    if (!atlas_) writer.storage(22, t.screen.handle());
    writer.push(context_, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipelines.compositeLayout);
    vkCmdDispatch(cmd, t.header.tilesX, t.header.tilesY, t.header.groups);
  });
}

void ParticleSystem::mergeGroups(FrameContext& frame) {
  Tiles& t = tiles_;
  if (t.header.groups <= 1) return;
  const bool behind = bool(frame.targets.glassDepth);
  std::vector<ResourceUse> used{uses(t.headerBuffer, Use::StorageRead, kCompute),
                                uses(t.layers, Use::StorageReadWrite, kCompute),
                                uses(t.opaque, Use::StorageRead, kCompute)};
  if (behind) used.push_back(uses(t.layersBehind, Use::StorageReadWrite, kCompute));
  frame.graph.pass("particles-merge", used, [&](VkCommandBuffer cmd) {
    t.merge[behind ? 1 : 0].bind(cmd);
    // Without glass binding 36 is never read: the front layer stands in.
    DescriptorWriter()
        .storage(0, frame.uniformBuffer.handle())
        .storage(17, t.headerBuffer.handle())
        .storage(23, t.layers.handle())
        .storage(36, (behind ? t.layersBehind : t.layers).handle())
        .storage(47, t.opaque.handle())
        .push(context_, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, t.mergeLayout);
    vkCmdDispatch(cmd, divideRoundingUp(t.header.layerWidth, gpu::kTileGroupSize),
                  divideRoundingUp(t.header.layerHeight, gpu::kTileGroupSize), 1);
  });
}

void ParticleSystem::resolve(FrameContext& frame, ParticleLayer layer) {
  Tiles& t = tiles_;
  const FrameTargets& targets = frame.targets;
  const Image& depth = particleSampledDepth(targets, layer);
  const bool behind = layer == ParticleLayer::BehindGlass;
  const Buffer& layers = behind ? t.layersBehind : t.layers;
  const Image& layerDepth = behind ? t.layerDepthBehind : t.layerDepth;
  const std::vector<ResourceUse> used{
      uses(targets.hdr, Use::StorageReadWrite, kCompute), uses(depth, Use::Sampled, kCompute),
      uses(t.headerBuffer, Use::StorageRead, kCompute), uses(layers, Use::StorageRead, kCompute),
      uses(layerDepth, Use::StorageRead, kCompute)};
  frame.graph.pass(std::string("particles-resolve") + particlePassSuffix(layer), used,
                   [&](VkCommandBuffer cmd) {
                     t.resolve.bind(cmd);
                     DescriptorWriter()
                         .storage(0, frame.uniformBuffer.handle())
                         .storage(17, t.headerBuffer.handle())
                         .storage(23, layers.handle())
                         .image(16, depth.view(), sampledLayout(depth), depthSampler_)
                         .image(21, targets.hdr.view(), VK_IMAGE_LAYOUT_GENERAL)
                         .image(24, layerDepth.view(), VK_IMAGE_LAYOUT_GENERAL)
                         .push(context_, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, t.resolveLayout);
                     dispatchPerPixel(cmd, targets);
                   });
  frame.graph.barriers({uses(t.headerBuffer, Use::HostRead)});
}

bool ParticleSystem::afterFrame() {
  Tiles& t = tiles_;
  if (render_ != ParticleRender::Compute || !t.headerBuffer) return false;
  gpu::ParticleTileHeader read{};
  std::memcpy(&read, t.headerBuffer.mapped(), sizeof(read));
  t.lastRequested = read.requested;
  t.longestCell = read.longest;
  t.stoppedGroups = read.stopped;
  t.unusedGroups = read.unused;
  if (read.requested <= t.header.capacity) return false;
  ++t.overflows;
  allocateTileEntries(grownCapacity(read.requested, t.maxEntries));
  return true;
}

}  // namespace lll
