#pragma once
// Lights drawn as geometry, shared by the techniques "deferred" (Infinity) and "prepass"
// (Resistance 2): the CPU culls every light against the view frustum, places a unit shell from
// lighting/light_volumes.h around it, decides whether its front faces can be trusted (the camera
// may be inside, or the near plane may cut it), and uploads the result for
// shaders/lighting/light_volume.vert.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

#include "gpu/pipeline.h"
#include "gpu/resources.h"
#include "scene/scene.h"
#include "shared/deferred_types.h"
#include "shared/gpu_types.h"

namespace lll {

class Context;
struct FrameContext;

enum class VolumeShape : uint32_t { Sphere, Cone };

struct PlacedLightVolume {
  gpu::LightVolume gpu;
  VolumeShape shape = VolumeShape::Sphere;
  // The shell reaches closer to the eye than the near-plane margin (twice the near distance, as
  // Infinity does): the camera may be inside it or its front faces may be clipped, so it has to be
  // drawn by its back faces (deferred) or marked with z-fail (prepass).
  bool cameraInside = false;
  // Area of the shell's screen-space bounding rectangle in pixels; the whole screen when inside.
  float screenPixels = 0.0f;
  // How the technique draws it (its pipeline), chosen by the technique in prepare().
  uint32_t group = 0;
};

// Consecutive volumes of prepare()'s list with the same group and shape: one instanced draw.
struct VolumeRun {
  uint32_t group;
  VolumeShape shape;
  uint32_t first;
  uint32_t count;
};

// Counts of the last prepare(), for Technique::stats().
struct LightVolumeCounts {
  uint32_t visible = 0;  // survived frustum culling, so drawn
  uint32_t cameraInside = 0;
  uint32_t cones = 0;
};

// Culls `lights` against the frustum in `frame` and places a shell around each visible light.
std::vector<PlacedLightVolume> placeLightVolumes(const std::vector<Light>& lights,
                                                 const gpu::FrameUniforms& frame);

// The unit shells and this frame's placed volumes on the GPU. Light-volume pipelines use the mesh
// vertex input and binding 3 for the volumes (see shaders/lighting/light_volume.vert).
class LightVolumeDraws {
 public:
  LightVolumeDraws(Context& context, uint32_t maxLights);

  // Places this frame's lights (see placeLightVolumes), gives each the group `drawGroup` picks,
  // orders them by group then shape, and uploads them; draw() indexes the returned list. Call
  // while recording: the previous frame has completed.
  const std::vector<PlacedLightVolume>& prepare(const std::vector<Light>& lights,
                                                const gpu::FrameUniforms& frame,
                                                uint32_t (*drawGroup)(const PlacedLightVolume&));
  const LightVolumeCounts& counts() const { return counts_; }
  std::vector<VolumeRun> runs() const;

  // The bindings every light-volume pass shares (shaders/lighting/light_volume.glsl: frame uniforms
  // 0, lights 1, the placed volumes 3, the depth 5, the local lights' shadows 28, 29) for `frame`;
  // a technique adds its own screen targets.
  DescriptorWriter& addBindings(DescriptorWriter& writer, const FrameContext& frame) const;
  void bindGeometry(VkCommandBuffer cmd) const;
  // Draws volumes [first, first + count) of prepare()'s list, which must all have `shape`.
  void draw(VkCommandBuffer cmd, VolumeShape shape, uint32_t first, uint32_t count) const;

 private:
  struct ShellRange {
    uint32_t firstIndex = 0;
    uint32_t indexCount = 0;
    int32_t vertexOffset = 0;
  };
  ShellRange ranges_[2];
  Buffer shellVertices_;
  Buffer shellIndices_;
  Buffer volumes_;
  std::vector<PlacedLightVolume> placed_;
  LightVolumeCounts counts_;
};

}  // namespace lll
