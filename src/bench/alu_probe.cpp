#include "bench/alu_probe.h"

#include <glm/glm.hpp>

#include "gpu/context.h"
#include "render/frame.h"
#include "scene/scene.h"

namespace lll {

namespace {

constexpr uint32_t kGroupSize = 8;  // alu_probe.comp's workgroup is 8x8

}  // namespace

AluProbe::AluProbe(Context& context, const Scene& scene, uint32_t width, uint32_t height)
    : context_(context),
      width_(width),
      height_(height),
      layout_(context, {"bench/alu_probe.comp"}),
      pipeline_(context, layout_, "bench/alu_probe.comp", lightTypeConstants(scene)),
      target_(context, width, height, kHdrFormat, VK_IMAGE_USAGE_STORAGE_BIT, "alu-probe"),
      timer_(context) {
  if (context.float16Features()) {
    halfLayout_ = PipelineLayout(context, {"bench/alu_probe_half.comp"});
    halfPipeline_.emplace(context, halfLayout_, "bench/alu_probe_half.comp", lightTypeConstants(scene));
  }
}

AluProbe::~AluProbe() {
  vkDeviceWaitIdle(context_.device());
}

std::vector<PassTime> AluProbe::run(uint32_t lights) {
  context_.submitAndWait([&](VkCommandBuffer cmd) {
    timer_.reset(cmd);
    const auto dispatch = [&](const char* name, const PipelineLayout& layout, const Pipeline& pipeline) {
      // The target's contents never matter: from UNDEFINED every time, which also orders this
      // dispatch's writes after the last one's.
      target_.transition(cmd, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL,
                         VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                         VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
      ScopedPass pass(timer_, cmd, name);
      pipeline.bind(cmd);
      DescriptorWriter()
          .image(0, target_.view(), VK_IMAGE_LAYOUT_GENERAL)
          .push(context_, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout);
      const glm::uvec4 push(lights, width_, height_, 0);
      vkCmdPushConstants(cmd, layout.handle(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(push), &push);
      vkCmdDispatch(cmd, divideRoundingUp(width_, kGroupSize), divideRoundingUp(height_, kGroupSize), 1);
    };
    dispatch("alu-probe", layout_, pipeline_);
    if (halfPipeline_) dispatch("alu-probe-half", halfLayout_, *halfPipeline_);
  });
  std::vector<PassTime> times;
  for (const PassTime& p : timer_.read())
    if (p.name.starts_with("alu-probe")) times.push_back(p);
  return times;
}

}  // namespace lll
