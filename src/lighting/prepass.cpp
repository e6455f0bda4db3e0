// Technique "prepass": Resistance 2's light pre-pass (seeds/resistance2-prelighting.txt).
//   prepass-normals      depth again, into a depth-stencil target, and view-space normals with
//                        roughness and metallic (the seed's step 1: written with the early depth
//                        pass)
//   prepass-lights       every visible light into a diffuse and a specular buffer: a stencil volume
//                        marks its pixels (z-pass; z-fail when the camera may be inside), then its
//                        back faces shade where the stencil is set and clear it; lights covering
//                        few pixels skip the stencil step and are drawn like deferred volumes
//   prepass-combine      the scene again with its full material: C(material, buffers)
// Glass and particles are the shared passes', forward-lit through the forward lighting interface,
// as R2 did for what did not factor.
// Per pixel: normal buffer 8 B + diffuse and specular buffers 16 B + depth-stencil 5 B (D32S8).
// The approximation in C is explained in shaders/lighting/prepass_combine.frag.
#include "gpu/context.h"
#include "gpu/pipeline.h"
#include "lighting/technique.h"
#include "lighting/volume_lights.h"

namespace lll {

namespace {

constexpr VkFormat kNormalFormat = VK_FORMAT_R32G32_UINT;  // lighting/prepass_terms.glsl
// fp32: thousands of dim lights (instant radiosity's VPLs) blended into fp16 lose light to rounding
// (12.6% of 1,024 VPLs on lavapipe; 3 of 255 on the H200), see deferred.cpp.
constexpr VkFormat kLightBufferFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
constexpr double kNormalBytesPerPixel = 8;
constexpr double kLightBufferBytesPerPixel = 16 + 16;

// Below this screen area a light skips the stencil step (the seed: "stenciling is skipped for
// smaller lights"): marking costs a second draw and two pipeline changes per light, while a
// volume this small rejects most pixels by its own depth test and depth-range discard.
constexpr float kSmallLightPixels = 32.0f * 32.0f;

// Light-volume draw groups, each with its own pipelines.
constexpr uint32_t kSmall = 0;         // no stencil: front faces against depth, instanced
constexpr uint32_t kStencilZPass = 1;  // camera outside: count the faces in front of the scene
constexpr uint32_t kStencilZFail = 2;  // camera may be inside: count the faces behind the scene

// The sun's screen-space shadow buffer (lighting/prepass_sun_shadow.comp): 8 bits, as Resistance 2's.
constexpr VkFormat kSunShadowFormat = VK_FORMAT_R8_UNORM;

VkFormat depthStencilFormat(Context& context) {
  for (VkFormat format : {VK_FORMAT_D32_SFLOAT_S8_UINT, VK_FORMAT_D24_UNORM_S8_UINT}) {
    VkFormatProperties properties{};
    vkGetPhysicalDeviceFormatProperties(context.physicalDevice(), format, &properties);
    if (properties.optimalTilingFeatures & VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT) return format;
  }
  throw std::runtime_error(context.info().name + " has no depth-stencil format for stencil light volumes");
}

VkStencilOpState stencilOps(VkCompareOp compare, VkStencilOp pass, VkStencilOp depthFail) {
  VkStencilOpState ops{};
  ops.failOp = VK_STENCIL_OP_KEEP;
  ops.passOp = pass;
  ops.depthFailOp = depthFail;
  ops.compareOp = compare;
  ops.compareMask = ops.writeMask = 0xFF;
  return ops;
}

// Dynamic rendering with the depth-stencil image as both depth and stencil attachment
// (frame.h's beginRendering attaches depth only).
void beginDepthStencilRendering(VkCommandBuffer cmd, const FrameTargets& t,
                                std::initializer_list<ColorTarget> colors, VkImageView depthStencil,
                                VkImageLayout layout, bool clear) {
  std::vector<VkRenderingAttachmentInfo> colorInfos;
  for (const ColorTarget& c : colors) {
    VkRenderingAttachmentInfo info{};
    info.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO;
    info.imageView = c.view;
    info.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    info.loadOp = c.clear ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD;
    info.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    colorInfos.push_back(info);
  }
  VkRenderingAttachmentInfo depthInfo{};
  depthInfo.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO;
  depthInfo.imageView = depthStencil;
  depthInfo.imageLayout = layout;
  depthInfo.loadOp = clear ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD;
  depthInfo.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  depthInfo.clearValue.depthStencil = {0.0f, 0};  // reverse-Z far; no light marked
  VkRenderingInfo info{};
  info.sType = VK_STRUCTURE_TYPE_RENDERING_INFO;
  info.renderArea = {{0, 0}, {t.width, t.height}};
  info.layerCount = 1;
  info.colorAttachmentCount = uint32_t(colorInfos.size());
  info.pColorAttachments = colorInfos.data();
  info.pDepthAttachment = &depthInfo;
  info.pStencilAttachment = &depthInfo;
  vkCmdBeginRendering(cmd, &info);
  const VkViewport viewport{0.0f, 0.0f, float(t.width), float(t.height), 0.0f, 1.0f};
  const VkRect2D scissor{{0, 0}, {t.width, t.height}};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
}

uint32_t drawGroup(const PlacedLightVolume& v) {
  if (v.cameraInside) return kStencilZFail;
  return v.screenPixels < kSmallLightPixels ? kSmall : kStencilZPass;
}

struct LightPassCounts {
  uint32_t small = 0;
  uint32_t stencilZPass = 0;
  uint32_t stencilZFail = 0;
};

class Prepass final : public Technique {
 public:
  Prepass(Context& context, const GpuScene& scene, const FrameTargets& targets)
      : meshLayout_(context,
                    {"common/mesh.vert", "lighting/prepass_normals.frag", "lighting/prepass_combine.frag"},
                    {scene.materialSetLayout()}),
        sunShadowLayout_(context, {"lighting/prepass_sun_shadow.comp"}),
        lightLayout_(context, {"lighting/light_volume.vert", "lighting/prepass_light.frag"}),
        depthStencilFormat_(depthStencilFormat(context)),
        volumes_(context, uint32_t(scene.scene().lights.size())),
        pixels_(double(targets.width) * targets.height) {
    const VkImageUsageFlags color = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
    normals_ = Image(context, targets.width, targets.height, kNormalFormat, color, "prepass-normals");
    diffuse_ = Image(context, targets.width, targets.height, kLightBufferFormat, color, "prepass-diffuse");
    specular_ = Image(context, targets.width, targets.height, kLightBufferFormat, color, "prepass-specular");
    sunShadow_ = Image(context, targets.width, targets.height, kSunShadowFormat,
                       VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT, "prepass-sun-shadow");
    sunShadowPipeline_ = Pipeline(context, sunShadowLayout_, "lighting/prepass_sun_shadow.comp");
    depthStencil_ = Image(context, targets.width, targets.height, depthStencilFormat_,
                          VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, "prepass-depth-stencil");
    createScenePipelines(context);
    createLightPipelines(context);
  }

  OpaqueShading opaqueShading() const override { return OpaqueShading::Own; }

  void shadeOpaque(FrameContext& frame) override {
    normalsPass(frame);
    sunShadowPass(frame);
    lightPass(frame);
    combinePass(frame);
  }

  LightingInterface lighting() const override { return {"forward"}; }

  std::vector<std::pair<std::string, double>> stats() const override {
    const double depthStencilBytes = depthStencilFormat_ == VK_FORMAT_D32_SFLOAT_S8_UINT ? 5 : 4;
    std::vector<std::pair<std::string, double>> s = {
        {"gbuffer-bytes-per-pixel", kNormalBytesPerPixel},
        {"light-buffer-bytes-per-pixel", kLightBufferBytesPerPixel},
        {"depth-stencil-bytes-per-pixel", depthStencilBytes},
        // Totals for the bench's memory column (keys ending in _bytes).
        {"normals_bytes", kNormalBytesPerPixel * pixels_},
        {"light_buffers_bytes", kLightBufferBytesPerPixel * pixels_},
        {"sun_shadow_buffer_bytes", pixels_},
        {"depth_stencil_bytes", depthStencilBytes * pixels_},
        {"lights-drawn", volumes_.counts().visible},
        {"lights-stencil-marked", counts_.stencilZPass + counts_.stencilZFail},
        {"lights-stencil-marked-z-fail", counts_.stencilZFail},
        {"lights-small-unstenciled", counts_.small}};
    return s;
  }

 private:
  void createScenePipelines(Context& context) {
    GraphicsPipelineDesc desc;
    desc.vertexShader = "common/mesh.vert";
    desc.fragmentShader = "lighting/prepass_normals.frag";
    desc.colorFormats = {kNormalFormat};
    desc.depthFormat = desc.stencilFormat = depthStencilFormat_;
    normalsPipeline_ = Pipeline(context, meshLayout_, desc);
    desc.fragmentShader = "lighting/prepass_combine.frag";
    desc.colorFormats = {kHdrFormat};
    desc.depthFormat = kDepthFormat;
    desc.stencilFormat = VK_FORMAT_UNDEFINED;
    desc.depthWrite = false;
    desc.depthCompare = VK_COMPARE_OP_EQUAL;  // one combine per pixel: the prepass decided
    combinePipeline_ = Pipeline(context, meshLayout_, desc);
  }

  // Marking counts, per pixel, the volume's faces in front of the scene (z-pass: front +1, back
  // -1) or, when the near plane may clip the front faces, the faces behind it (z-fail: front +1,
  // back -1 on depth failure, the seed's variant); for a closed convex shell either count is
  // non-zero exactly where the scene lies inside it. Shading then draws the back faces with no
  // depth test, which cover every marked pixel once, lights where the stencil is set and zeroes it
  // for the next light. Depth clamp keeps faces beyond the far plane.
  void createLightPipelines(Context& context) {
    GraphicsPipelineDesc desc;
    desc.vertexShader = "lighting/light_volume.vert";
    desc.vertexInput = VertexInput::Vertices;
    desc.fragmentShader = "lighting/prepass_light.frag";
    desc.colorFormats = {kLightBufferFormat, kLightBufferFormat};
    desc.depthFormat = desc.stencilFormat = depthStencilFormat_;
    desc.depthWrite = false;
    desc.depthClamp = true;
    desc.blend = BlendMode::Additive;
    smallPipeline_ = Pipeline(context, lightLayout_, desc);

    desc.stencilTest = true;
    desc.cullMode = VK_CULL_MODE_FRONT_BIT;
    desc.depthTest = false;
    desc.stencilFront = desc.stencilBack =
        stencilOps(VK_COMPARE_OP_NOT_EQUAL, VK_STENCIL_OP_ZERO, VK_STENCIL_OP_ZERO);
    desc.specialization = {0u};  // no discard: every marked fragment must reach the stencil op
    shadePipeline_ = Pipeline(context, lightLayout_, desc);

    desc.fragmentShader.clear();
    desc.specialization.clear();
    desc.colorWrite = false;
    desc.blend = BlendMode::None;
    desc.cullMode = VK_CULL_MODE_NONE;
    desc.depthTest = true;
    desc.stencilFront =
        stencilOps(VK_COMPARE_OP_ALWAYS, VK_STENCIL_OP_INCREMENT_AND_WRAP, VK_STENCIL_OP_KEEP);
    desc.stencilBack = stencilOps(VK_COMPARE_OP_ALWAYS, VK_STENCIL_OP_DECREMENT_AND_WRAP, VK_STENCIL_OP_KEEP);
    markZPassPipeline_ = Pipeline(context, lightLayout_, desc);
    desc.stencilFront =
        stencilOps(VK_COMPARE_OP_ALWAYS, VK_STENCIL_OP_KEEP, VK_STENCIL_OP_INCREMENT_AND_WRAP);
    desc.stencilBack = stencilOps(VK_COMPARE_OP_ALWAYS, VK_STENCIL_OP_KEEP, VK_STENCIL_OP_DECREMENT_AND_WRAP);
    markZFailPipeline_ = Pipeline(context, lightLayout_, desc);
  }

  void normalsPass(FrameContext& frame) {
    const FrameTargets& t = frame.targets;
    frame.graph.pass(
        "prepass-normals", {uses(normals_, Use::ColorWrite), uses(depthStencil_, Use::DepthStencilWrite)},
        [&](VkCommandBuffer cmd) {
          beginDepthStencilRendering(cmd, t, {{normals_.view(), true}}, depthStencil_.view(),
                                     VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL, true);
          normalsPipeline_.bind(cmd);
          meshPassDescriptors(frame).push(frame.context, cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, meshLayout_);
          frame.scene.draw(cmd, meshLayout_.handle(), DrawFilter::Opaque);
          vkCmdEndRendering(cmd);
        });
  }

  // Resistance 2's screen-space sun shadow: how much of the sun reaches each pixel, 8 bits.
  void sunShadowPass(FrameContext& frame) {
    frame.graph.pass("prepass-sun-shadow",
                     {uses(frame.targets.depth, Use::Sampled, kCompute),
                      uses(normals_, Use::Sampled, kCompute), uses(sunShadow_, Use::StorageWrite, kCompute)},
                     [&](VkCommandBuffer cmd) {
                       sunShadowPipeline_.bind(cmd);
                       meshPassDescriptors(frame)
                           .image(5, frame.targets.depth.view(), VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL)
                           .image(6, normals_.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)
                           .image(7, sunShadow_.view(), VK_IMAGE_LAYOUT_GENERAL)
                           .push(frame.context, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, sunShadowLayout_);
                       dispatchPerPixel(cmd, frame.targets);
                     });
  }

  void lightPass(FrameContext& frame) {
    const FrameTargets& t = frame.targets;
    constexpr VkPipelineStageFlags2 kFragment = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
    volumes_.prepare(frame.scene.scene().lights, frame.uniforms, &drawGroup);
    frame.graph.pass("prepass-lights",
                     {uses(diffuse_, Use::ColorWrite), uses(specular_, Use::ColorWrite),
                      uses(depthStencil_, Use::StencilWrite), uses(t.depth, Use::Sampled, kFragment),
                      uses(normals_, Use::Sampled, kFragment)},
                     [&](VkCommandBuffer cmd) {
                       beginDepthStencilRendering(
                           cmd, t, {{diffuse_.view(), true}, {specular_.view(), true}}, depthStencil_.view(),
                           VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_STENCIL_ATTACHMENT_OPTIMAL, false);
                       DescriptorWriter writer;
                       writer.image(6, normals_.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
                       volumes_.addBindings(writer, frame)
                           .push(frame.context, cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, lightLayout_);
                       volumes_.bindGeometry(cmd);
                       counts_ = {};
                       for (const VolumeRun& run : volumes_.runs()) drawRun(cmd, run);
                       vkCmdEndRendering(cmd);
                     });
  }

  void drawRun(VkCommandBuffer cmd, const VolumeRun& run) {
    if (run.group == kSmall) {
      smallPipeline_.bind(cmd);
      volumes_.draw(cmd, run.shape, run.first, run.count);
      counts_.small += run.count;
      return;
    }
    const Pipeline& mark = run.group == kStencilZFail ? markZFailPipeline_ : markZPassPipeline_;
    (run.group == kStencilZFail ? counts_.stencilZFail : counts_.stencilZPass) += run.count;
    for (uint32_t i = run.first; i < run.first + run.count; ++i) {
      mark.bind(cmd);
      volumes_.draw(cmd, run.shape, i, 1);
      shadePipeline_.bind(cmd);
      volumes_.draw(cmd, run.shape, i, 1);
    }
  }

  void combinePass(FrameContext& frame) {
    const FrameTargets& t = frame.targets;
    constexpr VkPipelineStageFlags2 kFragment = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
    frame.graph.pass(
        "prepass-combine",
        {uses(t.hdr, Use::ColorWrite), uses(t.depth, Use::DepthTest), uses(diffuse_, Use::Sampled, kFragment),
         uses(specular_, Use::Sampled, kFragment), uses(sunShadow_, Use::Sampled, kFragment)},
        [&](VkCommandBuffer cmd) {
          beginRendering(cmd, t.width, t.height, {{t.hdr.view(), true}}, t.depth.view(),
                         VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL, false);
          combinePipeline_.bind(cmd);
          meshPassDescriptors(frame)
              .image(3, diffuse_.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)
              .image(4, specular_.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)
              .image(5, sunShadow_.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)
              .push(frame.context, cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, meshLayout_);
          frame.scene.draw(cmd, meshLayout_.handle(), DrawFilter::Opaque);
          vkCmdEndRendering(cmd);
        });
  }

  PipelineLayout meshLayout_;
  PipelineLayout sunShadowLayout_;
  PipelineLayout lightLayout_;
  VkFormat depthStencilFormat_;
  Pipeline normalsPipeline_;
  Pipeline sunShadowPipeline_;
  Pipeline combinePipeline_;
  Pipeline smallPipeline_;
  Pipeline shadePipeline_;
  Pipeline markZPassPipeline_;
  Pipeline markZFailPipeline_;
  Image normals_;
  Image sunShadow_;
  Image diffuse_;
  Image specular_;
  Image depthStencil_;
  LightVolumeDraws volumes_;
  double pixels_;
  LightPassCounts counts_;
};

}  // namespace

std::unique_ptr<Technique> createPrepass(Context& context, const GpuScene& scene, const RenderSettings&,
                                         const FrameTargets& targets, const VisibilityBuffer*) {
  return std::make_unique<Prepass>(context, scene, targets);
}

}  // namespace lll
