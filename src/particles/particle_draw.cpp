// Drawing the particles inside a technique's frame: particles-light (per-particle lighting, with
// --particle-lighting vertex) and particles-draw (one indirect draw of camera-facing quads, back to
// front, premultiplied alpha over the lit frame, depth-tested against the prepass and faded where
// they meet it).
#include <fmt/format.h>

#include "gpu/context.h"
#include "particles/particle_system.h"
#include "render/frame.h"
#include "scene/errors.h"

namespace lll {

ParticleLighting parseParticleLighting(const std::string& name) {
  if (name == "pixel") return ParticleLighting::Pixel;
  if (name == "vertex") return ParticleLighting::Vertex;
  throw InputError(fmt::format("--particle-lighting {}: expected pixel or vertex", name));
}

const ParticleSystem::DrawPipelines& ParticleSystem::pipelinesFor(ParticleShading shading) {
  auto found = drawPipelines_.find(shading);
  if (found != drawPipelines_.end()) return found->second;
  const bool perParticle = lighting_ == ParticleLighting::Vertex && shading != ParticleShading::Unlit;
  GraphicsPipelineDesc desc;
  desc.vertexShader = perParticle ? "particles/draw_vertex_lit.vert" : "particles/draw.vert";
  desc.fragmentShader = perParticle || shading == ParticleShading::Unlit ? "particles/draw_prelit.frag"
                        : shading == ParticleShading::AllLights          ? "particles/draw_all_lights.frag"
                                                                         : "particles/draw_light_list.frag";
  desc.vertexInput = VertexInput::None;
  desc.cullMode = VK_CULL_MODE_NONE;  // a turned quad may face either way
  desc.depthWrite = false;
  desc.blend = BlendMode::Alpha;
  desc.colorFormats = {kHdrFormat};
  desc.depthFormat = kDepthFormat;
  DrawPipelines pipelines;
  pipelines.draw = Pipeline(context_, layout_, desc);
  if (perParticle)
    pipelines.light = Pipeline(context_, layout_,
                               shading == ParticleShading::AllLights ? "particles/light_all_lights.comp"
                                                                     : "particles/light_light_list.comp");
  return drawPipelines_.emplace(shading, std::move(pipelines)).first->second;
}

DescriptorWriter ParticleSystem::descriptors(const FrameContext& frame, const LightListBuffers& lists) const {
  DescriptorWriter writer;
  writer.storage(0, frame.uniformBuffer.handle())
      .storage(1, frame.scene.lightBuffer().handle())
      .storage(11, uniforms_.handle())
      .storage(12, particles_.handle())
      .storage(13, drawOrder_.handle())
      .storage(14, counters_.handle());
  if (lists.heads)
    writer.storage(3, lists.uniforms)
        .storage(4, lists.heads)
        .storage(5, lists.links)
        .storage(6, lists.counters)
        .storage(7, lists.tileDepth);
  if (radiance_) writer.storage(15, radiance_.handle());
  return writer;
}

void ParticleSystem::lightParticles(FrameContext& frame, const DrawPipelines& pipelines,
                                    const LightListBuffers& lists) {
  VkCommandBuffer cmd = frame.cmd;
  ScopedPass pass(frame.timer, cmd, "particles-light");
  // The technique's light lists may have been written by fragment shaders (the raster fills).
  memoryBarrier(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
  pipelines.light.bind(cmd);
  descriptors(frame, lists).push(context_, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_.handle());
  vkCmdDispatchIndirect(cmd, counters_.handle(), offsetof(gpu::ParticleCounters, dispatch));
  memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
}

void ParticleSystem::draw(FrameContext& frame, ParticleShading shading, const LightListBuffers& lists) {
  if (shading == ParticleShading::LightList && !lists.heads)
    throw std::logic_error("ParticleSystem::draw: light-list shading needs the technique's light lists");
  const DrawPipelines& pipelines = pipelinesFor(shading);
  if (pipelines.light) lightParticles(frame, pipelines, lists);
  VkCommandBuffer cmd = frame.cmd;
  const FrameTargets& t = frame.targets;
  ScopedPass pass(frame.timer, cmd, "particles-draw");
  // Blends over what the technique drew last, in whichever pass that was.
  memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
  beginRendering(cmd, t.width, t.height, {{t.hdr.view(), false}}, t.depth.view(),
                 VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL, false);
  pipelines.draw.bind(cmd);
  descriptors(frame, lists)
      .image(16, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, t.depth.view(),
             VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL, depthSampler_)
      .push(context_, cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_.handle());
  vkCmdDrawIndirect(cmd, counters_.handle(), offsetof(gpu::ParticleCounters, draw), 1,
                    sizeof(VkDrawIndirectCommand));
  vkCmdEndRendering(cmd);
}

}  // namespace lll
