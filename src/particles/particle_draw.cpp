// Drawing the particles inside a technique's frame: particles-light (per-particle lighting, with
// --particle-lighting vertex) and, with --particle-render raster, particles-draw (one indirect draw
// of camera-facing quads, back to front, premultiplied alpha over the lit frame, depth-tested
// against the prepass and faded where they meet it). The compute renderer is particle_tiles.cpp.
#include <fmt/format.h>

#include "core/errors.h"
#include "gpu/context.h"
#include "particles/particle_system.h"
#include "render/frame.h"

namespace lll {

const ParticleSystem::DrawPipelines& ParticleSystem::pipelinesFor(const FrameContext& frame,
                                                                  const LightingInterface& lighting) {
  auto found = drawPipelines_.find(lighting.key());
  if (found != drawPipelines_.end()) return found->second;
  const bool vertex = lighting_ == ParticleLighting::Vertex;
  const bool atlas = lighting_ == ParticleLighting::Atlas;
  const SpecializationConstants constants = lighting.with(lightTypeConstants(frame.scene));
  DrawPipelines pipelines;
  // With glass, the variant that blends only what lies behind it (kBehindGlass in the shaders).
  const bool glass = frame.scene.hasBlendDraws();
  if (render_ == ParticleRender::Raster) {
    GraphicsPipelineDesc desc;
    desc.vertexShader = vertex ? "particles/draw_vertex_lit.vert" : "particles/draw.vert";
    desc.fragmentShader = vertex  ? "particles/draw_prelit.frag"
                          : atlas ? "particles/draw_atlas.frag"
                                  : litShader(lighting, "particles_pixel.frag");
    desc.vertexInput = VertexInput::None;
    desc.cullMode = VK_CULL_MODE_NONE;  // a turned quad may face either way
    desc.depthWrite = false;
    desc.blend = BlendMode::Alpha;
    desc.colorFormats = {kHdrFormat};
    desc.depthFormat = kDepthFormat;
    desc.constants = constants;
    pipelines.drawLayout = PipelineLayout(context_, {desc.vertexShader, desc.fragmentShader});
    pipelines.draw = Pipeline(context_, pipelines.drawLayout, desc);
    if (glass) {
      desc.constants[kBehindGlassConstant] = 1;
      pipelines.drawBehindGlass = Pipeline(context_, pipelines.drawLayout, desc);
    }
  } else {
    const std::string shader = litShader(lighting, "particles_tiles.comp");
    pipelines.compositeLayout = PipelineLayout(context_, {shader});
    SpecializationConstants compositeConstants = constants;
    compositeConstants[0] = vertex ? 0 : atlas ? 2 : 1;        // the light's source (particles_tiles.comp)
    compositeConstants[kBehindGlassConstant] = glass ? 1 : 0;  // with glass: both layers
    pipelines.composite = Pipeline(context_, pipelines.compositeLayout, shader, compositeConstants);
  }
  if (vertex || atlas) {
    const std::string shader = litShader(lighting, vertex ? "particles_vertex.comp" : "particles_atlas.comp");
    pipelines.lightLayout = PipelineLayout(context_, {shader});
    pipelines.light = Pipeline(context_, pipelines.lightLayout, shader, constants);
  }
  return drawPipelines_.emplace(lighting.key(), std::move(pipelines)).first->second;
}

DescriptorWriter ParticleSystem::systemDescriptors(const FrameContext& frame) const {
  DescriptorWriter writer;
  writer.storage(0, frame.uniformBuffer.handle())
      .storage(1, frame.scene.lightBuffer().handle())
      .storage(11, uniforms_.handle())
      .storage(12, particles_.handle())
      .storage(13, drawOrder_.handle())
      .storage(14, counters_.handle());
  if (radiance_) writer.storage(15, radiance_.handle());
  if (atlas_) writer.storage(22, atlas_.handle());
  writer.image(31, noise_.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, noiseSampler_);
  if (frame.shadows) frame.shadows->bind(writer);
  if (frame.lightShadows) frame.lightShadows->bind(writer);
  return writer;
}

DescriptorWriter ParticleSystem::descriptors(const FrameContext& frame,
                                             const LightingInterface& lighting) const {
  DescriptorWriter writer = systemDescriptors(frame);
  lighting.bind(writer);
  return writer;
}

void ParticleSystem::lightParticles(FrameContext& frame, const DrawPipelines& pipelines,
                                    const LightingInterface& lighting) {
  frame.graph.pass(
      "particles-light",
      std::vector<ResourceUse>{
          uses(counters_, Use::IndirectRead), uses(counters_, Use::StorageRead, kCompute),
          uses(uniforms_, Use::StorageRead, kCompute), uses(particles_, Use::StorageRead, kCompute),
          uses(drawOrder_, Use::StorageRead, kCompute),
          uses(radiance_ ? radiance_ : atlas_, Use::StorageWrite, kCompute)} +
          lighting.reads(kCompute),
      [&](VkCommandBuffer cmd) {
        pipelines.light.bind(cmd);
        descriptors(frame, lighting)
            .push(context_, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipelines.lightLayout);
        vkCmdDispatchIndirect(
            cmd, counters_.handle(),
            atlas_ ? offsetof(gpu::ParticleCounters, atlas) : offsetof(gpu::ParticleCounters, dispatch));
      });
}

const Image& particleSceneDepth(const FrameTargets& targets, ParticleLayer layer) {
  return layer == ParticleLayer::InFrontOfGlass ? targets.glassDepth : targets.depth;
}

const Image& particleSampledDepth(const FrameTargets& targets, ParticleLayer layer) {
  return layer == ParticleLayer::InFrontOfGlass ? targets.glassDepth : targets.sampledDepth();
}

const Image& particleGlassDepth(const FrameTargets& targets, ParticleLayer layer) {
  return layer == ParticleLayer::BehindGlass ? targets.glassDepth : particleSceneDepth(targets, layer);
}

const char* particlePassSuffix(ParticleLayer layer) {
  return layer == ParticleLayer::BehindGlass ? "-behind-glass" : "";
}

void ParticleSystem::draw(FrameContext& frame, const LightingInterface& lighting, ParticleLayer layer) {
  const DrawPipelines& pipelines = pipelinesFor(frame, lighting);
  if (layer != ParticleLayer::All && !frame.targets.glassDepth)
    throw std::logic_error("particles drawn about the glass without the glass depth");
  // Lighting and binning are the frame's, whichever layers are drawn.
  const bool first = layer != ParticleLayer::InFrontOfGlass;
  if (first && pipelines.light) lightParticles(frame, pipelines, lighting);
  if (render_ == ParticleRender::Raster) {
    drawRaster(frame, pipelines, lighting, layer);
  } else {
    // With glass the one composite (before it) blends both layers; each is resolved on its side of it.
    if (first) {
      binTiles(frame);
      composite(frame, pipelines, lighting);
      mergeGroups(frame);
    }
    resolve(frame, layer);
  }
}

void ParticleSystem::drawRaster(FrameContext& frame, const DrawPipelines& pipelines,
                                const LightingInterface& lighting, ParticleLayer layer) {
  const FrameTargets& t = frame.targets;
  const Image& depth = particleSceneDepth(t, layer);
  const Image& glass = particleGlassDepth(t, layer);
  constexpr VkPipelineStageFlags2 kShaders =
      VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
  std::vector<ResourceUse> reads{uses(t.hdr, Use::ColorBlend),
                                 uses(depth, Use::DepthTest),
                                 uses(depth, Use::Sampled, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT),
                                 uses(counters_, Use::IndirectRead),
                                 uses(counters_, Use::StorageRead, kShaders),
                                 uses(uniforms_, Use::StorageRead, kShaders),
                                 uses(particles_, Use::StorageRead, kShaders),
                                 uses(drawOrder_, Use::StorageRead, kShaders)};
  if (radiance_) reads.push_back(uses(radiance_, Use::StorageRead, kShaders));
  if (atlas_) reads.push_back(uses(atlas_, Use::StorageRead, kShaders));
  if (layer == ParticleLayer::BehindGlass)
    reads.push_back(uses(glass, Use::Sampled, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT));
  // Blends over what the technique drew last, in whichever pass that was.
  const std::string name = std::string("particles-draw") + particlePassSuffix(layer);
  frame.graph.pass(name, reads + lighting.reads(kShaders), [&](VkCommandBuffer cmd) {
    beginRendering(cmd, t.width, t.height, {{t.hdr.view(), false}}, depth.view(),
                   VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL, false);
    (layer == ParticleLayer::BehindGlass ? pipelines.drawBehindGlass : pipelines.draw).bind(cmd);
    descriptors(frame, lighting)
        .image(16, depth.view(), VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL, depthSampler_)
        .image(25, glass.view(), VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL, depthSampler_)
        .push(context_, cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines.drawLayout);
    vkCmdDrawIndirect(cmd, counters_.handle(), offsetof(gpu::ParticleCounters, draw), 1,
                      sizeof(VkDrawIndirectCommand));
    vkCmdEndRendering(cmd);
  });
}

}  // namespace lll
