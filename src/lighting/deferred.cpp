// Technique "deferred": Infinity's deferred lighting (seeds/infinity-deferred-instant-radiosity.txt).
//   deferred-gbuffer      the shared thin G-buffer (render/gbuffer.h), in compute from the
//                         visibility buffer (or, with --surfaces gbuffer, the scene drawn again with
//                         depth EQUAL the prepass), with ambient and emission written straight into
//                         the accumulation target
//   deferred-lights       each visible light as a bounding volume, additively blended
//   deferred-sun          the directional lights over the G-buffer, the first shadowed through its
//                         cascades (shadows/sun_shadows.h): Infinity's sun pass, in compute
//   deferred-resolve      the fp32 accumulation into the HDR target; with --aa edge
//   (deferred-edge-aa)    blending pixels on depth or normal discontinuities on the way
// Glass and particles are the shared passes', lit through the forward lighting interface (every
// light per pixel, the separate forward pass engines add for them) or the unlit one
// (--deferred-translucent unlit: ambient and emission only, the seeds' Figure 1.1).
// G-buffer 12 B/px (RGBA8 base colour + metallic, RGBA16F normal + roughness); with the D32 depth
// and an RGBA32F accumulation, 32 B/px. The accumulation is fp32 because blending thousands of dim
// lights (instant radiosity's VPLs) into fp16 rounds every addition: 1,024 VPLs lost 12.6% of their
// light on lavapipe, whose fp16 conversion truncates, and moved pixels by 3 of 255 on the H200. Infinity used
// four RGBA16F targets, 32 B/px plus its Z buffer: depth again in a colour channel, velocity, extinction and
// a material id that lll does not need, fp16 for base colour, and a forward-lit colour that here is the
// accumulation target itself. Here depth is the prepass's, sampled directly.
#include "core/errors.h"
#include "gpu/context.h"
#include "gpu/fragment_counter.h"
#include "gpu/pipeline.h"
#include "lighting/technique.h"
#include "lighting/volume_lights.h"
#include "render/gbuffer.h"

namespace lll {

namespace {

constexpr VkFormat kAccumulationFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
constexpr double kDepthAndAccumulationBytesPerPixel = 4 + 16;

// Light-volume draw groups: which side of the volume the camera is on picks the pipeline.
constexpr uint32_t kOutside = 0;
constexpr uint32_t kInside = 1;

bool forwardLitTranslucents(const RenderSettings& settings) {
  return settings.deferredTranslucent == TranslucentLighting::Forward;
}

bool edgeAntiAliasing(const RenderSettings& settings) {
  return settings.antiAliasing == AntiAliasing::Edge;
}

class Deferred final : public Technique {
 public:
  Deferred(Context& context, const GpuScene& scene, const RenderSettings& settings,
           const FrameTargets& targets, const VisibilityBuffer* visibility)
      : lightLayout_(context, {"lighting/light_volume.vert", "lighting/deferred_light.frag"}),
        gbuffer_(context, scene, targets, kAccumulationFormat, false, visibility),
        volumes_(context, uint32_t(scene.scene().lights.size())),
        lightFragments_(context),
        pixels_(double(targets.width) * targets.height),
        edgeAa_(edgeAntiAliasing(settings)),
        litTranslucents_(forwardLitTranslucents(settings)) {
    const VkImageUsageFlags usage =
        VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT;
    accumulation_ = Image(context, targets.width, targets.height, kAccumulationFormat, usage, "accumulation");
    resolveLayout_ = PipelineLayout(context, {"lighting/deferred_edge_aa.comp"});
    resolvePipeline_ = Pipeline(context, resolveLayout_, "lighting/deferred_edge_aa.comp",
                                SpecializationConstants{{0, edgeAa_ ? 1u : 0u}});
    createLightPipelines(context);
    sunLayout_ = PipelineLayout(context, {"lighting/deferred_sun.comp"});
    sunPipeline_ = Pipeline(context, sunLayout_, "lighting/deferred_sun.comp");
  }

  OpaqueShading opaqueShading() const override { return OpaqueShading::Own; }

  void shadeOpaque(FrameContext& frame) override {
    geometryPass(frame);
    lightPass(frame);
    sunPass(frame);
    resolvePass(frame);
  }

  LightingInterface lighting() const override { return {litTranslucents_ ? "forward" : "unlit"}; }

  bool afterFrame() override {
    if (auto count = lightFragments_.read()) lastLightFragments_ = double(*count);
    return false;
  }

  std::vector<std::pair<std::string, double>> stats() const override {
    const LightVolumeCounts& c = volumes_.counts();
    std::vector<std::pair<std::string, double>> s = {
        {"gbuffer-bytes-per-pixel", GBuffer::kBytesPerPixel},
        {"gbuffer-with-depth-and-accumulation-bytes-per-pixel",
         GBuffer::kBytesPerPixel + kDepthAndAccumulationBytesPerPixel},
        {"gbuffer_bytes", GBuffer::kBytesPerPixel * pixels_},  // the bench's memory column
        {"lights-drawn", c.visible},
        {"lights-drawn-camera-inside", c.cameraInside},
        {"lights-drawn-as-cones", c.cones}};
    s.push_back({"accumulation_bytes", 16.0 * pixels_});
    if (lastLightFragments_ >= 0.0) {
      // Fragment shader invocations of the light volumes: Infinity's cost driver.
      s.push_back({"light-volume-fragments", lastLightFragments_});
      s.push_back({"light-volume-overdraw", lastLightFragments_ / pixels_});
    }
    return s;
  }

 private:
  // Infinity's states: depth test on, writes off, additive. Outside a volume its front faces are
  // drawn where they are nearer than the scene (reverse-Z GREATER_OR_EQUAL, Infinity's LESS);
  // with the camera inside, its back faces where they lie behind the scene (LESS_OR_EQUAL,
  // Infinity's GREATER) with front faces culled. Either way a convex shell covers each pixel once.
  void createLightPipelines(Context& context) {
    GraphicsPipelineDesc desc;
    desc.vertexShader = "lighting/light_volume.vert";
    desc.vertexInput = VertexInput::Vertices;
    desc.fragmentShader = "lighting/deferred_light.frag";
    desc.colorFormats = {kAccumulationFormat};
    desc.depthFormat = kDepthFormat;
    desc.depthWrite = false;
    desc.depthClamp = true;
    desc.blend = BlendMode::Additive;
    desc.cullMode = VK_CULL_MODE_BACK_BIT;
    desc.depthCompare = VK_COMPARE_OP_GREATER_OR_EQUAL;
    outsidePipeline_ = Pipeline(context, lightLayout_, desc);
    desc.cullMode = VK_CULL_MODE_FRONT_BIT;
    desc.depthCompare = VK_COMPARE_OP_LESS_OR_EQUAL;
    insidePipeline_ = Pipeline(context, lightLayout_, desc);
  }

  void geometryPass(FrameContext& frame) { gbuffer_.record(frame, "deferred-gbuffer", accumulation_); }

  // The CPU culls the lights and groups them by shape (points, spots) and by camera side; each
  // group is one instanced draw with one pipeline, so no state changes between its lights.
  void lightPass(FrameContext& frame) {
    const FrameTargets& t = frame.targets;
    constexpr VkPipelineStageFlags2 kFragment = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
    lightFragments_.reset(frame.cmd);
    volumes_.prepare(frame.scene.scene().lights, frame.uniforms,
                     [](const PlacedLightVolume& v) { return v.cameraInside ? kInside : kOutside; });
    frame.graph.pass(
        "deferred-lights",
        {uses(accumulation_, Use::ColorBlend), uses(t.depth, Use::DepthTest),
         uses(t.depth, Use::Sampled, kFragment), uses(gbuffer_.target0(), Use::Sampled, kFragment),
         uses(gbuffer_.target1(), Use::Sampled, kFragment)},
        [&](VkCommandBuffer cmd) {
          beginRendering(cmd, t.width, t.height, {{accumulation_.view(), false}}, t.depth.view(),
                         VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL, false);
          DescriptorWriter writer;
          writer.image(6, gbuffer_.target0().view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)
              .image(7, gbuffer_.target1().view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
          volumes_.addBindings(writer, frame)
              .push(frame.context, cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, lightLayout_);
          volumes_.bindGeometry(cmd);
          lightFragments_.begin(cmd);
          for (const VolumeRun& run : volumes_.runs()) {
            (run.group == kInside ? insidePipeline_ : outsidePipeline_).bind(cmd);
            volumes_.draw(cmd, run.shape, run.first, run.count);
          }
          lightFragments_.end(cmd);
          vkCmdEndRendering(cmd);
        });
  }

  // The directional lights, in their own pass over the G-buffer (none: no pass).
  void sunPass(FrameContext& frame) {
    if (frame.uniforms.display.z == 0) return;
    const FrameTargets& t = frame.targets;
    frame.graph.pass(
        "deferred-sun",
        {uses(accumulation_, Use::StorageReadWrite, kCompute), uses(t.depth, Use::Sampled, kCompute),
         uses(gbuffer_.target0(), Use::Sampled, kCompute), uses(gbuffer_.target1(), Use::Sampled, kCompute)},
        [&](VkCommandBuffer cmd) {
          sunPipeline_.bind(cmd);
          meshPassDescriptors(frame)
              .image(5, t.depth.view(), VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL)
              .image(6, gbuffer_.target0().view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)
              .image(7, gbuffer_.target1().view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)
              .image(8, accumulation_.view(), VK_IMAGE_LAYOUT_GENERAL)
              .push(frame.context, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, sunLayout_);
          dispatchPerPixel(cmd, t);
        });
  }

  void resolvePass(FrameContext& frame) {
    const FrameTargets& t = frame.targets;
    frame.graph.pass(
        edgeAa_ ? "deferred-edge-aa" : "deferred-resolve",
        {uses(accumulation_, Use::Sampled, kCompute), uses(t.depth, Use::Sampled, kCompute),
         uses(gbuffer_.target1(), Use::Sampled, kCompute), uses(t.hdr, Use::StorageWrite, kCompute)},
        [&](VkCommandBuffer cmd) {
          resolvePipeline_.bind(cmd);
          DescriptorWriter()
              .storage(0, frame.uniformBuffer.handle())
              .image(5, t.depth.view(), VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL)
              .image(6, accumulation_.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)
              .image(7, gbuffer_.target1().view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)
              .image(8, t.hdr.view(), VK_IMAGE_LAYOUT_GENERAL)
              .push(frame.context, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, resolveLayout_);
          dispatchPerPixel(cmd, t);
        });
  }

  PipelineLayout lightLayout_;
  PipelineLayout resolveLayout_;
  PipelineLayout sunLayout_;
  Pipeline sunPipeline_;
  Pipeline outsidePipeline_;
  Pipeline insidePipeline_;
  Pipeline resolvePipeline_;
  GBuffer gbuffer_;
  Image accumulation_;
  LightVolumeDraws volumes_;
  FragmentCounter lightFragments_;
  double pixels_;
  double lastLightFragments_ = -1.0;
  bool edgeAa_;
  bool litTranslucents_;
};

}  // namespace

std::unique_ptr<Technique> createDeferred(Context& context, const GpuScene& scene,
                                          const RenderSettings& settings, const FrameTargets& targets,
                                          const VisibilityBuffer* visibility) {
  return std::make_unique<Deferred>(context, scene, settings, targets, visibility);
}

}  // namespace lll
