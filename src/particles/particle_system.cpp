// The particle system's state and its per-frame compute passes: simulate, sort, indirect
// arguments. Drawing is in particle_draw.cpp.
#include "particles/particle_system.h"

#include <fmt/format.h>

#include <cmath>
#include <cstring>

#include "core/errors.h"
#include "gpu/context.h"
#include "gpu/vk_check.h"
#include "particles/puff_noise.h"
#include "render/frame.h"

namespace lll {

namespace {

uint32_t checkedCapacity(const ParticleSystemOptions& options) {
  const uint32_t count = options.count ? options.count : options.preset.count;
  if (count == 0 || count > gpu::kMaxParticles)
    throw InputError(fmt::format("--particle-count {}: a particle system holds 1 to {} particles", count,
                                 gpu::kMaxParticles));
  return count;
}

void computeToCompute(VkCommandBuffer cmd) {
  memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
}

// Auto: compute on a GPU. On a CPU device the rasterizer: Mesa's llvmpipe ends a shader
// invocation's loops once they have run 65,535 iterations in all (see lighting/light_bins.h), and a
// composite invocation loops over every particle of its tile and, lit per pixel, every light of
// each: a dense plume would silently lose its far particles.
// Below full resolution only the compute renderer draws particles.
ParticleRender resolveRender(const Context& context, const ParticleSystemOptions& options) {
  if (options.render != ParticleRender::Auto) return options.render;
  return context.isCpuDevice() && options.resolutionScale == 1 ? ParticleRender::Raster
                                                               : ParticleRender::Compute;
}

void packCurve(const std::vector<float>& keys, glm::vec4 (&out)[2]) {
  for (size_t i = 0; i < keys.size(); ++i) out[i / 4][int(i % 4)] = keys[i];
}

}  // namespace

ParticleSystem::ParticleSystem(Context& context, const ParticleSystemOptions& options)
    : context_(context),
      preset_(options.preset),
      lighting_(options.lighting),
      render_(resolveRender(context, options)),
      resolutionScale_(options.resolutionScale),
      tileGroups_(options.tileGroups),
      capacity_(checkedCapacity(options)),
      // The emitter spawns capacity / lifetimeMax particles a second: a slot's previous particle
      // has always died when its next one is born.
      stepsPerLifetime_(double(options.preset.lifetimeMax) * gpu::kParticleStepsPerSecond),
      sorter_(context, capacity_),
      layout_(context, {"particles/simulate.comp", "particles/sort_keys.comp", "particles/indirect.comp"}) {
  createBuffers();
  uploadUniforms(options.source, options.seed);
  simulate_ = Pipeline(context, layout_, "particles/simulate.comp");
  keys_ = Pipeline(context, layout_, "particles/sort_keys.comp");
  indirect_ = Pipeline(context, layout_, "particles/indirect.comp");
}

ParticleSystem::~ParticleSystem() {
  vkDestroySampler(context_.device(), depthSampler_, nullptr);
  vkDestroySampler(context_.device(), noiseSampler_, nullptr);
}

void ParticleSystem::createBuffers() {
  const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  const VkDeviceSize stateBytes = VkDeviceSize(capacity_) * sizeof(gpu::Particle);
  const VkDeviceSize orderBytes = VkDeviceSize(sorter_.paddedCount()) * sizeof(glm::uvec2);
  const VkDeviceSize largest = context_.properties().limits.maxStorageBufferRange;
  if (stateBytes > largest || orderBytes > largest)
    throw InputError(
        fmt::format("{} particles need a {:.1f} MiB storage buffer; this device's largest is {:.1f} MiB",
                    capacity_, double(stateBytes) / 1048576.0, double(largest) / 1048576.0));
  uniforms_ =
      Buffer(context_, sizeof(gpu::ParticleUniforms), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::Upload);
  particles_ = Buffer(context_, stateBytes, storage, MemoryUse::Device);
  drawOrder_ = Buffer(context_, orderBytes, storage, MemoryUse::Device);
  counters_ = Buffer(context_, sizeof(gpu::ParticleCounters), storage | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT,
                     MemoryUse::Device);
  if (lighting_ == ParticleLighting::Vertex)
    radiance_ = Buffer(context_, VkDeviceSize(capacity_) * sizeof(glm::vec4), storage, MemoryUse::Device);
  if (lighting_ == ParticleLighting::Atlas) {
    const uint64_t texels = uint64_t(capacity_) * gpu::kParticleAtlasSide * gpu::kParticleAtlasSide;
    requireStorageBufferFits(context_, texels, sizeof(glm::uvec2), "the particles' light atlases", "texels",
                             "use fewer particles or --particle-lighting vertex");
    atlas_ =
        Buffer(context_, texels * sizeof(glm::uvec2), storage, MemoryUse::Device, "particle light atlases");
  }
  // Every slot starts dead: lifetime 0.
  context_.submitAndWait([&](VkCommandBuffer cmd) {
    vkCmdFillBuffer(cmd, particles_.handle(), 0, VK_WHOLE_SIZE, 0);
    vkCmdFillBuffer(cmd, counters_.handle(), 0, VK_WHOLE_SIZE, 0);
  });
  depthSampler_ = createNearestClampSampler(context_);
  createNoise();
}

void ParticleSystem::createNoise() {
  const uint32_t side = puffNoiseSide();
  const std::vector<uint8_t> texels = bakePuffNoise();
  noise_ = Image(context_, side, side, VK_FORMAT_R8_UNORM,
                 VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, "puff noise");
  uploadImage(context_, noise_, texels.data(), texels.size(), [&](VkCommandBuffer cmd) {
    noise_.transition(cmd, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                      VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
  });
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.magFilter = info.minFilter = VK_FILTER_LINEAR;
  info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  info.addressModeU = info.addressModeV = info.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
  VK_CHECK(vkCreateSampler(context_.device(), &info, nullptr, &noiseSampler_));
}

void ParticleSystem::uploadUniforms(const glm::vec3& source, uint32_t seed) {
  const ParticlePreset& p = preset_;
  gpu::ParticleUniforms u{};
  u.emitter = glm::vec4(source + p.emitterOffset, p.emitterRadius);
  u.direction = glm::vec4(p.direction, std::cos(glm::radians(p.spreadDegrees)));
  u.speedLifetime = glm::vec4(p.speedMin, p.speedMax, p.lifetimeMin, p.lifetimeMax);
  u.forces = glm::vec4(p.drag, p.buoyancy, p.turbulenceStrength, 1.0f / p.turbulenceSize);
  u.gravity = glm::vec4(p.gravity, p.turbulenceSpeed);
  u.variation = glm::vec4(p.sizeVariation, p.colorVariation, p.spin, p.restitution);
  u.shading = glm::vec4(p.wrap, p.back, p.focus, p.softness);
  u.blend = glm::vec4(p.additive, source.y, 0.0f, 0.0f);
  packCurve(p.size, u.sizeKeys);
  packCurve(p.opacity, u.opacityKeys);
  packCurve(p.emission, u.emissionKeys);
  for (size_t i = 0; i < p.color.size(); ++i) u.colorKeys[i] = glm::vec4(p.color[i], 0.0f);
  u.keyCounts = glm::uvec4(p.size.size(), p.opacity.size(), p.emission.size(), p.color.size());
  const uint32_t shape = p.shape == EmitterShape::Point  ? gpu::kEmitterPoint
                         : p.shape == EmitterShape::Disc ? gpu::kEmitterDisc
                                                         : gpu::kEmitterSphere;
  const uint32_t floor = p.floor == FloorMode::None     ? gpu::kFloorNone
                         : p.floor == FloorMode::Bounce ? gpu::kFloorBounce
                                                        : gpu::kFloorKill;
  u.modes = glm::uvec4(shape, floor, capacity_, seed);
  uniforms_.upload(&u, sizeof(u));
}

// Spawn id k is born at k * lifetimeMax / capacity seconds; step s covers [s dt, (s + 1) dt), so
// its spawns are ids ceil(s * capacity / stepsPerLifetime) up to the same for s + 1. The product is
// formed before the division so that whole numbers come out exact: no drift, no off-by-one.
uint64_t ParticleSystem::spawnedBefore(uint64_t step) const {
  return uint64_t(std::ceil(double(step) * double(capacity_) / stepsPerLifetime_));
}

gpu::ParticleStepPush ParticleSystem::stepPush(uint64_t step) const {
  const double dt = 1.0 / gpu::kParticleStepsPerSecond;
  const double interval = stepsPerLifetime_ * dt / double(capacity_);
  const uint64_t first = spawnedBefore(step), end = spawnedBefore(step + 1);
  gpu::ParticleStepPush push{};
  push.spawn = glm::uvec4(uint32_t(first % capacity_), uint32_t(end - first), uint32_t(first), 0);
  push.time = glm::vec4(float(dt), float(double(step) * dt), float(interval),
                        float(double(first) * interval - double(step) * dt));
  return push;
}

void ParticleSystem::recordStep(VkCommandBuffer cmd) {
  simulate_.bind(cmd);
  DescriptorWriter()
      .storage(11, uniforms_.handle())
      .storage(12, particles_.handle())
      .push(context_, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_);
  const gpu::ParticleStepPush push = stepPush(steps_++);
  vkCmdPushConstants(cmd, layout_.handle(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(push), &push);
  vkCmdDispatch(cmd, divideRoundingUp(capacity_, gpu::kParticleGroupSize), 1, 1);
}

void ParticleSystem::recordSteps(VkCommandBuffer cmd, uint32_t steps) {
  // Outside a frame (catching up before the first one): each step reads the one before it.
  for (uint32_t i = 0; i < steps; ++i) {
    recordStep(cmd);
    computeToCompute(cmd);
  }
}

void ParticleSystem::update(FrameContext& frame, bool advance) {
  FrameGraph& graph = frame.graph;
  if (advance)
    graph.pass(
        "particles-simulate",
        {uses(uniforms_, Use::StorageRead, kCompute), uses(particles_, Use::StorageReadWrite, kCompute)},
        [&](VkCommandBuffer cmd) { recordStep(cmd); });
  graph.pass("particles-sort", {uses(counters_, Use::TransferWrite)}, [&](VkCommandBuffer cmd) {
    vkCmdFillBuffer(cmd, counters_.handle(), 0, VK_WHOLE_SIZE, 0);
    graph.barriers({uses(uniforms_, Use::StorageRead, kCompute), uses(particles_, Use::StorageRead, kCompute),
                    uses(drawOrder_, Use::StorageWrite, kCompute),
                    uses(counters_, Use::StorageReadWrite, kCompute)});
    sort(frame);
  });
  graph.pass("particles-indirect",
             {uses(uniforms_, Use::StorageRead, kCompute), uses(counters_, Use::StorageReadWrite, kCompute)},
             [&](VkCommandBuffer cmd) { buildIndirect(cmd); });
}

void ParticleSystem::sort(FrameContext& frame) {
  VkCommandBuffer cmd = frame.cmd;
  keys_.bind(cmd);
  DescriptorWriter()
      .storage(0, frame.uniformBuffer.handle())
      .storage(11, uniforms_.handle())
      .storage(12, particles_.handle())
      .storage(13, drawOrder_.handle())
      .storage(14, counters_.handle())
      .push(context_, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_);
  const gpu::SortPush push{glm::uvec4(0, 0, sorter_.paddedCount(), 0)};
  vkCmdPushConstants(cmd, layout_.handle(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(push), &push);
  vkCmdDispatch(cmd, divideRoundingUp(sorter_.paddedCount(), gpu::kParticleGroupSize), 1, 1);
  // The merge stages' barriers are the sort's own (see BitonicSorter).
  computeToCompute(cmd);
  sorter_.record(cmd, drawOrder_);
}

void ParticleSystem::buildIndirect(VkCommandBuffer cmd) {
  indirect_.bind(cmd);
  DescriptorWriter()
      .storage(11, uniforms_.handle())
      .storage(14, counters_.handle())
      .push(context_, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_);
  vkCmdDispatch(cmd, 1, 1, 1);
}

std::vector<gpu::Particle> ParticleSystem::readParticles() const {
  const auto bytes = readBack(context_, particles_, VkDeviceSize(capacity_) * sizeof(gpu::Particle));
  std::vector<gpu::Particle> out(capacity_);
  std::memcpy(out.data(), bytes.data(), bytes.size());
  return out;
}

std::vector<glm::uvec2> ParticleSystem::readDrawOrder() const {
  const auto bytes = readBack(context_, drawOrder_, VkDeviceSize(sorter_.paddedCount()) * sizeof(glm::uvec2));
  std::vector<glm::uvec2> out(sorter_.paddedCount());
  std::memcpy(out.data(), bytes.data(), bytes.size());
  return out;
}

gpu::ParticleCounters ParticleSystem::readCounters() const {
  const auto bytes = readBack(context_, counters_, sizeof(gpu::ParticleCounters));
  gpu::ParticleCounters out;
  std::memcpy(&out, bytes.data(), sizeof(out));
  return out;
}

std::vector<std::pair<std::string, double>> ParticleSystem::stats() const {
  const gpu::ParticleCounters counters = readCounters();
  return {{"particle_slots", double(capacity_)},
          {"particles_alive", double(counters.alive.x)},
          {"particles_drawn", double(counters.dispatch.w)},
          {"particle_steps", double(steps_)},
          {"particle_state_bytes", double(particles_.size())},
          {"particle_sort_bytes", double(drawOrder_.size())},
          {"particle_radiance_bytes", double(radiance_ ? radiance_.size()
                                             : atlas_  ? atlas_.size()
                                                       : 0)},
          {"particle_render_compute", render_ == ParticleRender::Compute ? 1.0 : 0.0},
          {"particle_tile_entries_used", double(tiles_.lastRequested)},
          {"particle_tile_entries_capacity", double(tiles_.entries ? tiles_.header.capacity : 0)},
          {"particle_tile_bytes", double(tiles_.entries ? tiles_.entries.size() + tiles_.cells.size() +
                                                              tiles_.screen.size() + tiles_.layers.size()
                                                        : 0)},
          {"particle_tile_slabs", double(tiles_.header.cellsX)},
          {"particle_tile_groups", double(tiles_.header.groups)},
          {"particle_resolution_scale", double(resolutionScale_)},
          {"particle_tile_longest", double(tiles_.longestCell)},
          {"particle_tile_groups_stopped", double(tiles_.stoppedGroups)},
          {"particle_tile_groups_unused", double(tiles_.unusedGroups)},
          {"particle_tile_overflows", double(tiles_.overflows)}};
}

}  // namespace lll
