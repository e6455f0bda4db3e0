#include "render/moving_lights.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>
#include <vector>

#include "gpu/context.h"
#include "render/frame.h"
#include "render/frame_graph.h"
#include "scene/light_animation.h"

namespace lll {

namespace {

constexpr uint32_t kGroupSize = 64;     // move_lights.comp's workgroup
constexpr uint32_t kMaxGroups = 65535;  // the least maxComputeWorkGroupCount[0] a device may have

// `value` with only its first 12 significant bits: a product of two such floats is exact.
float first12Bits(double value) {
  return std::bit_cast<float>(std::bit_cast<uint32_t>(float(value)) & 0xFFFFF000u);
}

// A rate (turns a second) as the shader's two floats: the first 12 significant bits, and the rest.
glm::vec2 splitRate(double turnsPerSecond) {
  const float high = first12Bits(turnsPerSecond);
  return {high, float(turnsPerSecond - double(high))};
}

float turns(double radians) {
  return float(radians / (2.0 * std::numbers::pi));
}

struct MovePush {
  glm::vec4 seconds;  // x, y the time split as splitRate does (exactly), z the time
  glm::uvec4 range;   // x the first moving light, y how many
};

// The GPU's form of a motion (shared/gpu_types.h): the centre, the speeds in turns a second split
// for exact products with the time, the phases in turns.
gpu::GpuLightMotion toGpuMotion(const LightMotion& m) {
  gpu::GpuLightMotion g{};
  g.centerRadius = glm::vec4(orbitCenter(m), m.radius);
  g.orbit = glm::vec4(splitRate(double(m.angularSpeed) / (2.0 * std::numbers::pi)), turns(m.phase), 0.0f);
  g.bob = glm::vec4(splitRate(m.bobFrequency), turns(m.bobPhase), m.bobAmplitude);
  return g;
}

}  // namespace

MovingLights::MovingLights(Context& context, const LightAnimation& animation)
    : context_(context),
      first_(animation.first),
      count_(uint32_t(animation.motions.size())),
      layout_(context, {"lighting/move_lights.comp"}),
      pipeline_(context, layout_, "lighting/move_lights.comp") {
  std::vector<gpu::GpuLightMotion> motions;
  motions.reserve(animation.motions.size());
  for (const LightMotion& m : animation.motions) motions.push_back(toGpuMotion(m));
  motions_ = Buffer(context, std::max<size_t>(motions.size(), 1) * sizeof(gpu::GpuLightMotion),
                    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::Device, "light motions");
  motions_.upload(std::span<const gpu::GpuLightMotion>(motions));
}

void MovingLights::record(FrameGraph& graph, const Buffer& lights, float seconds) const {
  if (count_ == 0) return;
  graph.pass("lights-move", {}, [&](VkCommandBuffer cmd) {
    // After every read of the last frame (and the upload); before every reader of this one.
    memoryBarrier(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                  VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                  VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    pipeline_.bind(cmd);
    DescriptorWriter()
        .storage(0, lights.handle())
        .storage(1, motions_.handle())
        .push(context_, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_);
    const float high = first12Bits(seconds);
    const MovePush push{glm::vec4(high, seconds - high, seconds, 0.0f), glm::uvec4(first_, count_, 0u, 0u)};
    vkCmdPushConstants(cmd, layout_.handle(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(push), &push);
    vkCmdDispatch(cmd, std::min(divideRoundingUp(count_, kGroupSize), kMaxGroups), 1, 1);
    memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_READ_BIT);
  });
}

}  // namespace lll
