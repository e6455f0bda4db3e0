#include "renderer/renderer.h"
#include "render/compute_raster.h"
#include "render/lit_passes.h"
#include "render/visibility.h"

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/errors.h"
#include "gi/moving_vpls.h"
#include "gpu/context.h"
#include "particles/particle_setup.h"
#include "scene/light_animation.h"
#include "scene/lights.h"
#include "shared/lll_types.h"

namespace lll {

namespace {

// --raster auto: the compute rasterizer where it was measured faster than the hardware pass.
bool computeRasterWins(const Context& context) {
  return !context.isCpuDevice();
}

// A frame needing more than this many re-renders has a bug, not a small pool.
constexpr uint32_t kMaxRerenders = 8;
// Lights per tile shown as red in the heatmap view (ThreeL's Sponza peaks around 35).
constexpr uint32_t kHeatmapScale = 32;
// Particle steps per submission when advancing without drawing: a long run is split so that no one
// command buffer keeps the GPU busy for long.
constexpr uint32_t kParticleStepsPerSubmission = 256;

}  // namespace

Renderer::Renderer(Context& context, const Scene& scene, const RenderSettings& settings)
    : context_(context),
      scene_(scene),
      settings_(settings),
      camera_(resolveCamera(scene, settings.camera)),
      sceneBounds_(scene.worldBounds()),
      timer_(context) {
  validateResolution(settings.width, settings.height);
  settings_.tileSize = tileSizeFor(settings_);
  validateTileSize(settings_.tileSize);  // every frame's uniforms divide by it
  if (scene.lights.size() > gpu::kMaxLights)
    throw InputError(
        fmt::format("{} lights: at most {} are supported", scene.lights.size(), gpu::kMaxLights));
  requireStorageBufferFits(context, scene.lights.size(), sizeof(gpu::GpuLight), "the light array");
  gpuScene_ = std::make_unique<GpuScene>(context, scene);
  chooseSurfaces();
  createTargets();
  uniformBuffer_ =
      Buffer(context, sizeof(gpu::FrameUniforms), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::Upload);
  shadows_ = std::make_unique<SunShadows>(context, *gpuScene_, sunShadowOptions(settings));
  lightShadows_ = std::make_unique<LocalShadows>(context, *gpuScene_, localShadowOptions(settings));
  gpuScene_->setShadowedLights(lightShadows_->casting());
  chooseLightMotion();
  updateUniforms();

  depthLayout_ = PipelineLayout(context, {"common/mesh.vert", "common/depth_mask.frag"},
                                {gpuScene_->materialSetLayout()});
  GraphicsPipelineDesc depth;
  depth.vertexShader = "common/mesh.vert";
  depth.depthFormat = kDepthFormat;
  depthOpaque_ = Pipeline(context, depthLayout_, depth);
  depth.fragmentShader = "common/depth_mask.frag";
  depthMask_ = Pipeline(context, depthLayout_, depth);

  tonemapLayout_ = PipelineLayout(context, {"post/tonemap.comp"});
  tonemap_ = Pipeline(context, tonemapLayout_, "post/tonemap.comp");
  if (auto options = particleOptions(scene, settings))
    particles_ = std::make_unique<ParticleSystem>(context, *options);
  // Particles and glass drawn in depth order: the particles behind the nearest glass before it.
  if (particles_ && gpuScene_->hasBlendDraws())
    targets_.glassDepth = Image(context, settings_.width, settings_.height, kDepthFormat,
                                VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                    VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                "glass depth");
  technique_ =
      findTechnique(settings.technique).create(context, *gpuScene_, settings_, targets_, visibility_.get());
  createLitPasses();
}

void Renderer::createLitPasses() {
  lit_.reset();
  lit_ = std::make_unique<LitPasses>(context_, *gpuScene_, targets_, visibility_.get(),
                                     technique_->opaqueShading(), technique_->lighting(),
                                     settings_.glass == GlassLighting::Compute, settings_.vplInterleave,
                                     /*lastShading=*/!particles_);
}

void Renderer::chooseSurfaces() {
  const RasterChoice raster = settings_.raster;
  if (settings_.surfaces == SurfaceSource::Gbuffer) {
    if (raster == RasterChoice::Compute)
      throw InputError("--raster compute rasterizes the visibility buffer: it needs --surfaces visibility");
    return;
  }
  surfacesFallback_ = VisibilityBuffer::problem(context_, *gpuScene_);
  if (surfacesFallback_.empty()) {
    std::string computeProblem = ComputeRaster::problem(context_, settings_.width, settings_.height);
    const TechniqueInfo& technique = findTechnique(settings_.technique);
    if (computeProblem.empty() && technique.redrawsOpaque && technique.redrawsOpaque(settings_))
      computeProblem = fmt::format(
          "--technique {} (with these options) draws opaque geometry again with an EQUAL depth test, "
          "which needs the hardware pass's depth",
          settings_.technique);
    if (raster == RasterChoice::Compute && !computeProblem.empty())
      throw InputError(fmt::format("--raster compute: {}", computeProblem));
    // auto: compute where the measurement says it wins (bench/README.md, "Compute rasterization").
    const bool compute =
        raster == RasterChoice::Compute ||
        (raster == RasterChoice::Auto && computeProblem.empty() && computeRasterWins(context_));
    visibility_ =
        std::make_unique<VisibilityBuffer>(context_, *gpuScene_, compute, settings_.width, settings_.height);
    return;
  }
  if (raster == RasterChoice::Compute)
    throw InputError(
        fmt::format("--raster compute: the visibility buffer is unavailable: {}", surfacesFallback_));
  fmt::print(stderr, "lll: warning: --surfaces visibility: {}; rendering with --surfaces gbuffer\n",
             surfacesFallback_);
}

Renderer::~Renderer() {
  vkDeviceWaitIdle(context_.device());
}

void Renderer::createTargets() {
  const uint32_t w = settings_.width, h = settings_.height;
  targets_.width = w;
  targets_.height = h;
  targets_.depth = Image(context_, w, h, kDepthFormat,
                         VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                             VK_IMAGE_USAGE_TRANSFER_DST_BIT |  // the compute rasterizer's copy
                             VK_IMAGE_USAGE_TRANSFER_SRC_BIT,   // the glass depth's start
                         "depth");
  targets_.hdr = Image(context_, w, h, kHdrFormat,
                       VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_STORAGE_BIT |
                           VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                       "hdr");
  targets_.ldr =
      Image(context_, w, h, kLdrFormat, VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, "ldr");
  if (visibility_)
    targets_.visibility =
        Image(context_, w, h, kVisibilityFormat,
              VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_STORAGE_BIT, "visibility");
  if (visibility_ && visibility_->computeRaster()) {
    targets_.rasterDepth = Image(context_, w, h, VK_FORMAT_R32_SFLOAT,
                                 VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT, "raster-depth");
    targets_.rasterDepthComplete = !visibility_->hasMaskedDraws();
  }
  hdrReadback_ =
      Buffer(context_, VkDeviceSize(w) * h * 8, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::Readback);
  ldrReadback_ =
      Buffer(context_, VkDeviceSize(w) * h * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::Readback);
}

void Renderer::updateUniforms() {
  const Bounds& bounds = sceneBounds_;
  const float aspect = float(settings_.width) / float(settings_.height);
  glm::vec3 forward = glm::normalize(camera_.target - camera_.eye);
  glm::vec3 up = camera_.up;
  if (std::abs(glm::dot(glm::normalize(up), forward)) > 0.999f) up = glm::vec3(0.0f, 0.0f, -1.0f);
  // Far plane just beyond the farthest corner of the scene; near as close as reverse-Z allows.
  float far = 1.0f;
  if (bounds.valid()) {
    for (int i = 0; i < 8; ++i) {
      const glm::vec3 corner(i & 1 ? bounds.max.x : bounds.min.x, i & 2 ? bounds.max.y : bounds.min.y,
                             i & 4 ? bounds.max.z : bounds.min.z);
      far = std::max(far, glm::length(corner - camera_.eye) * 1.01f);
    }
  }
  const float near = std::clamp(far * 1e-4f, 1e-3f, 0.05f);
  gpu::FrameUniforms& u = uniforms_;
  u.view = glm::lookAt(camera_.eye, camera_.target, up);
  u.proj = glm::perspectiveRH_ZO(camera_.yfov, aspect, far, near);  // near/far swapped: reverse-Z
  u.proj[1][1] *= -1.0f;                                            // Vulkan's y points down
  u.viewProj = u.proj * u.view;
  u.invViewProj = glm::inverse(u.viewProj);
  // Finite inputs can still overflow: a camera or scene 1e30 m across, a field of view of 1e-30.
  const auto finite = [](const glm::mat4& m) {
    for (int i = 0; i < 16; ++i)
      if (!std::isfinite(m[i / 4][i % 4])) return false;
    return true;
  };
  if (!finite(u.viewProj) || !finite(u.invViewProj))
    throw InputError(fmt::format(
        "camera '{}' (eye {}, {}, {}; field of view {} rad) over scene bounds {} m across gives a projection "
        "that is not finite; the camera or the scene is out of any sensible range",
        camera_.name, camera_.eye.x, camera_.eye.y, camera_.eye.z, camera_.yfov,
        bounds.valid() ? glm::length(bounds.extent()) : 0.0f));
  u.cameraPosition = glm::vec4(camera_.eye, 1.0f);
  u.viewport = glm::vec4(settings_.width, settings_.height, 1.0f / settings_.width, 1.0f / settings_.height);
  const float tanHalf = std::tan(camera_.yfov * 0.5f);
  u.depthParams = glm::vec4(near, far, tanHalf * aspect, tanHalf);
  const uint32_t tile = settings_.tileSize;
  u.counts = glm::uvec4(gpuScene_->lightCount(), tile, divideRoundingUp(settings_.width, tile),
                        divideRoundingUp(settings_.height, tile));
  u.ambient = glm::vec4(glm::vec3(settings_.ambient), settings_.exposure);
  const bool debugColors =
      settings_.debugView == DebugView::Heatmap || settings_.debugView == DebugView::Bounds;
  u.display = glm::uvec4(debugColors ? gpu::kDisplayDebug : gpu::kDisplayFilmic,
                         settings_.debugView == DebugView::Heatmap ? kHeatmapScale : 0u, 0u,
                         gpuScene_->firstTrailingVpl());
  const std::vector<DirectionalLight>& suns = gpuScene_->scene().directionalLights;
  u.display.z = uint32_t(std::min<size_t>(suns.size(), gpu::kMaxDirectionalLights));  // loaders refuse more
  // The sun that casts the shadow goes first (shaders read its shadow as the first's).
  std::vector<uint32_t> order(u.display.z);
  for (uint32_t i = 0; i < u.display.z; ++i) order[i] = i;
  if (u.display.z > 0) std::swap(order[0], order[uint32_t(shadowCastingSun(suns))]);
  for (uint32_t i = 0; i < u.display.z; ++i) {
    const DirectionalLight& sun = suns[order[i]];
    u.sunDirection[i] = glm::vec4(-glm::normalize(sun.direction), 0.0f);
    u.sunIlluminance[i] = glm::vec4(sun.color * sun.illuminance, 0.0f);
  }
  uniformBuffer_.upload(&uniforms_, sizeof(uniforms_));
  shadows_->update(uniforms_, bounds);
  lightShadows_->update(uniforms_);
}

FrameResult Renderer::renderFrame(bool capture) {
  FrameResult result;
  lastCaptured_ = capture;
  updateUniforms();
  // A frame recorded again (the technique asked for it) must not advance the particles twice.
  for (bool advance = true;; advance = false) {
    context_.submitAndWait([&](VkCommandBuffer cmd) { recordFrame(cmd, capture, advance); });
    // Both are asked: each grows what overflowed before the frame is drawn again.
    const bool techniqueAgain = technique_->afterFrame();
    const bool particlesAgain = particles_ && particles_->afterFrame();
    const bool glassAgain = lit_->afterFrame();
    // A technique whose interface changed (lll's links grown past the compact format) is drawn
    // again with lit passes compiled for it.
    if (techniqueAgain && technique_->lighting().key() != lit_->lighting().key()) createLitPasses();
    if (!techniqueAgain && !particlesAgain && !glassAgain) break;
    if (++result.rerenders > kMaxRerenders)
      throw std::runtime_error(fmt::format("technique {} asked for more than {} re-renders of one frame",
                                           settings_.technique, kMaxRerenders));
  }
  result.passes = timer_.read();
  return result;
}

// --light-motion: the GPU places moving lights unless something reads their positions on the CPU.
void Renderer::chooseLightMotion() {
  const LightPlacement motion = settings_.lightMotion;
  std::string cpuReader;
  if (findTechnique(settings_.technique).readsLightsOnCpu)
    cpuReader = fmt::format("--technique {} places its light volumes on the CPU", settings_.technique);
  else if (lightShadows_->casting())
    cpuReader = "--shadows all places the lights' shadow views on the CPU";
  else if (scene_.movingIndirect)
    cpuReader = "--gi traces the moving lights' photons on the CPU";
  if (motion == LightPlacement::Gpu && !cpuReader.empty())
    throw InputError(fmt::format("--light-motion gpu: {}", cpuReader));
  if (motion == LightPlacement::Cpu || !cpuReader.empty() || scene_.lightAnimation.empty()) return;
  movingLights_ = std::make_unique<MovingLights>(context_, scene_.lightAnimation);
}

void Renderer::updateLights() {
  gpuLightTime_.reset();
  gpuScene_->uploadLights(scene_.lights);
  lightShadows_->lightsRewritten();
}

void Renderer::moveLightsTo(Scene& scene, float seconds) {
  if (scene.lightAnimation.empty() && !scene.movingIndirect) return;
  if (movingLights_) {
    checkAnimationTime(seconds);
    gpuLightTime_ = seconds;
    return;
  }
  if (!scene.lightAnimation.empty()) placeLightsAt(scene.lights, scene.lightAnimation, seconds);
  if (scene.movingIndirect)
    scene.movingIndirect.vpls->moveTo(seconds, scene.lights, scene.movingIndirect.first);
  updateLights();
}

void Renderer::advanceParticles(uint32_t steps) {
  if (!particles_) return;
  for (uint32_t done = 0; done < steps; done += kParticleStepsPerSubmission) {
    const uint32_t batch = std::min(kParticleStepsPerSubmission, steps - done);
    context_.submitAndWait([&](VkCommandBuffer cmd) { particles_->recordSteps(cmd, batch); });
  }
}

std::vector<std::pair<std::string, double>> Renderer::stats() const {
  auto s = technique_->stats();
  const auto lit = lit_->stats();
  s.insert(s.end(), lit.begin(), lit.end());
  const auto shadows = shadows_->stats();
  s.insert(s.end(), shadows.begin(), shadows.end());
  const auto lightShadows = lightShadows_->stats();
  s.insert(s.end(), lightShadows.begin(), lightShadows.end());
  if (scene_.movingIndirect) {  // the CPU's share of a frame with moving lights and --gi
    const gi::MovingVplStats& g = scene_.movingIndirect.vpls->stats();
    s.insert(s.end(), {{"vpl-moving-photons", double(g.movingPhotons)},
                       {"vpl-retraced-photons", double(g.retraced)},
                       {"vpl-retrace-ms", g.retraceMs},
                       {"vpl-retrace-trace-ms", g.traceMs},
                       {"vpl-retrace-merge-ms", g.mergeMs},
                       {"vpl-slots", double(g.slots)},
                       {"vpl-lit-slots", double(g.litSlots)},
                       {"vpl-dropped-cells", double(g.droppedCells)}});
  }
  if (!scene_.lightAnimation.empty()) s.push_back({"light-motion-gpu", movingLights_ ? 1.0 : 0.0});
  s.push_back({"instances", double(scene_.instances.size())});
  s.push_back({"visible_instances", double(gpuScene_->visibleInstances())});
  // 1 when opaque surfaces came from the visibility buffer (its ids are lighting memory too).
  s.push_back({"visibility-buffer", visibility_ ? 1.0 : 0.0});
  s.push_back({"compute-raster", visibility_ && visibility_->computeRaster() ? 1.0 : 0.0});
  // 1 when a pass of the last frame depth-tested or copied the D32 depth, which the compute
  // rasterizer then had to fill (render/compute_raster.h).
  if (visibility_ && visibility_->computeRaster())
    s.push_back({"raster-depth-copy", visibility_->rasterDepthCopied() ? 1.0 : 0.0});
  if (visibility_) s.push_back({"visibility_bytes", 4.0 * settings_.width * settings_.height});
  if (particles_) {
    const auto p = particles_->stats();
    s.insert(s.end(), p.begin(), p.end());
  }
  return s;
}

void Renderer::recordFrame(VkCommandBuffer cmd, bool capture, bool advanceParticles) {
  gpuScene_->prepareFrame(uniforms_.viewProj, camera_.eye);
  if (visibility_) visibility_->prepareFrame(*gpuScene_);
  timer_.reset(cmd);
  FrameGraph graph(cmd, timer_);
  if (gpuLightTime_) movingLights_->record(graph, gpuScene_->lightBuffer(), *gpuLightTime_);
  FrameContext frame{context_,  cmd,       graph,   *gpuScene_,        targets_,       uniformBuffer_,
                     uniforms_, settings_, capture, visibility_.get(), shadows_.get(), lightShadows_.get()};
  // The shadows first: every lighting pass after them reads them.
  shadows_->record(frame);
  lightShadows_->record(frame);
  if (visibility_)
    visibility_->record(frame);
  else
    depthPrepass(frame);
  if (particles_) particles_->update(frame, advanceParticles);
  // The frame every technique shares: its light data, opaque shading (its own or the shared pass
  // through its lighting interface), then glass and particles through that interface.
  technique_->buildLightData(frame);
  if (technique_->opaqueShading() == OpaqueShading::Own)
    technique_->shadeOpaque(frame);
  else
    lit_->shadeOpaque(frame);
  // With glass (glassDepth exists only with particles): the particles behind the nearest glass,
  // then the glass over them, then the particles in front.
  const bool aboutGlass = bool(targets_.glassDepth);
  if (aboutGlass) {
    glassDepth(frame);
    particles_->draw(frame, technique_->lighting(), ParticleLayer::BehindGlass);
  }
  lit_->shadeGlass(frame);
  if (particles_)
    particles_->draw(frame, technique_->lighting(),
                     aboutGlass ? ParticleLayer::InFrontOfGlass : ParticleLayer::All);
  // The last shading passes may have written the display image already (LitPasses::writesDisplay).
  if (!lit_->writesDisplay()) tonemap(frame);
  if (capture) captureImages(graph);
}

void Renderer::depthPrepass(FrameContext& frame) {
  frame.graph.pass("depth-prepass", {uses(targets_.depth, Use::DepthWrite)}, [&](VkCommandBuffer cmd) {
    beginRendering(cmd, targets_.width, targets_.height, {}, targets_.depth.view(),
                   VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, true);
    depthOpaque_.bind(cmd);
    meshPassDescriptors(frame).push(context_, cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, depthLayout_);
    gpuScene_->draw(cmd, depthLayout_.handle(), DrawFilter::OpaqueOnly);
    depthMask_.bind(cmd);
    gpuScene_->draw(cmd, depthLayout_.handle(), DrawFilter::MaskOnly);
    vkCmdEndRendering(cmd);
  });
}

// The nearest surface, opaque or glass, at each pixel: the opaque depth copied, the glass drawn
// into it (every pixel a pane covers counts, whatever its alpha).
void Renderer::glassDepth(FrameContext& frame) {
  frame.graph.step({uses(targets_.depth, Use::TransferRead), uses(targets_.glassDepth, Use::TransferWrite)},
                   [&](VkCommandBuffer cmd) {
                     VkImageCopy copy{};
                     copy.srcSubresource = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 0, 1};
                     copy.dstSubresource = copy.srcSubresource;
                     copy.extent = {targets_.width, targets_.height, 1};
                     vkCmdCopyImage(cmd, targets_.depth.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                    targets_.glassDepth.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                                    &copy);
                   });
  frame.graph.pass("glass-depth", {uses(targets_.glassDepth, Use::DepthReadWrite)}, [&](VkCommandBuffer cmd) {
    beginRendering(cmd, targets_.width, targets_.height, {}, targets_.glassDepth.view(),
                   VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, false);
    depthOpaque_.bind(cmd);
    meshPassDescriptors(frame).push(context_, cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, depthLayout_);
    gpuScene_->draw(cmd, depthLayout_.handle(), DrawFilter::Blend);
    vkCmdEndRendering(cmd);
  });
}

void Renderer::tonemap(FrameContext& frame) {
  frame.graph.pass(
      "tonemap",
      {uses(targets_.hdr, Use::StorageRead, kCompute), uses(targets_.ldr, Use::StorageWrite, kCompute)},
      [&](VkCommandBuffer cmd) {
        tonemap_.bind(cmd);
        DescriptorWriter()
            .storage(0, uniformBuffer_.handle())
            .image(1, targets_.hdr.view(), VK_IMAGE_LAYOUT_GENERAL)
            .image(2, targets_.ldr.view(), VK_IMAGE_LAYOUT_GENERAL)
            .push(context_, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, tonemapLayout_);
        dispatchPerPixel(cmd, targets_);
      });
}

void Renderer::captureImages(FrameGraph& graph) {
  graph.step({uses(targets_.hdr, Use::TransferRead), uses(targets_.ldr, Use::TransferRead),
              uses(hdrReadback_, Use::TransferWrite), uses(ldrReadback_, Use::TransferWrite)},
             [&](VkCommandBuffer cmd) {
               VkBufferImageCopy copy{};
               copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
               copy.imageExtent = {targets_.width, targets_.height, 1};
               vkCmdCopyImageToBuffer(cmd, targets_.hdr.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                      hdrReadback_.handle(), 1, &copy);
               vkCmdCopyImageToBuffer(cmd, targets_.ldr.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                      ldrReadback_.handle(), 1, &copy);
             });
  graph.barriers({uses(hdrReadback_, Use::HostRead), uses(ldrReadback_, Use::HostRead)});
}

HdrImage Renderer::hdrImage() const {
  HdrImage image{targets_.width, targets_.height, {}};
  const size_t count = size_t(targets_.width) * targets_.height * 4;
  image.rgba.resize(count);
  const auto* halves = static_cast<const uint16_t*>(hdrReadback_.mapped());
  for (size_t i = 0; i < count; ++i) image.rgba[i] = glm::unpackHalf1x16(halves[i]);
  return image;
}

LdrImage Renderer::ldrImage() const {
  LdrImage image{targets_.width, targets_.height, {}};
  image.rgba.resize(size_t(targets_.width) * targets_.height * 4);
  std::memcpy(image.rgba.data(), ldrReadback_.mapped(), image.rgba.size());
  return image;
}

}  // namespace lll
