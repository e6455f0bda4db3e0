#include "lighting/volume_lights.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "gpu/context.h"
#include "lighting/light_volumes.h"
#include "render/frame.h"
#include "render/gpu_scene.h"

namespace lll {

namespace {

// A spot whose cone is wider than this (tan of the outer angle, about 63 degrees) gets the sphere
// shell: beyond it the cone shell's volume exceeds the sphere shell's and it only costs more pixels.
constexpr float kMaxConeSlope = 2.0f;

const VolumeMesh& shell(VolumeShape shape) {
  static const VolumeMesh sphere = sphereShell();
  static const VolumeMesh cone = coneShell();
  return shape == VolumeShape::Sphere ? sphere : cone;
}

VolumeShape shapeFor(const Light& light) {
  if (light.type == LightType::Spot && std::tan(light.outerConeAngle) <= kMaxConeSlope)
    return VolumeShape::Cone;
  return VolumeShape::Sphere;
}

// Unit shell -> world. The cone's frame is right-handed so the shell keeps its outward winding.
glm::mat4 shellModel(const Light& light, VolumeShape shape) {
  if (shape == VolumeShape::Sphere)
    return glm::scale(glm::translate(glm::mat4(1.0f), light.position), glm::vec3(light.range));
  const glm::vec3 axis = glm::normalize(light.direction);
  const glm::vec3 helper = std::abs(axis.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  const glm::vec3 x = glm::normalize(glm::cross(helper, axis));
  const glm::vec3 y = glm::cross(axis, x);
  const float radius = light.range * std::tan(light.outerConeAngle);
  return glm::mat4(glm::vec4(x * radius, 0.0f), glm::vec4(y * radius, 0.0f),
                   glm::vec4(axis * light.range, 0.0f), glm::vec4(light.position, 1.0f));
}

// Which of the six clip-space half-spaces (Vulkan, reverse-Z: 0 <= z <= w) a point lies outside.
uint32_t outcode(const glm::vec4& c) {
  return (c.x < -c.w ? 1u : 0u) | (c.x > c.w ? 2u : 0u) | (c.y < -c.w ? 4u : 0u) | (c.y > c.w ? 8u : 0u) |
         (c.z < 0.0f ? 16u : 0u) | (c.z > c.w ? 32u : 0u);
}

// Places one light; false when its shell lies wholly outside one frustum plane. The shell is the
// convex hull of its vertices, so testing the vertices is exact for the shell.
bool placeLight(const Light& light, uint32_t index, const gpu::FrameUniforms& frame, PlacedLightVolume& out) {
  out.shape = shapeFor(light);
  out.gpu.model = shellModel(light, out.shape);
  const glm::mat4 toClip = frame.viewProj * out.gpu.model;
  uint32_t outside = ~0u;
  float nearest = INFINITY, farthest = -INFINITY;
  glm::vec2 ndcMin(INFINITY), ndcMax(-INFINITY);
  for (const glm::vec3& p : shell(out.shape).positions) {
    const glm::vec4 c = toClip * glm::vec4(p, 1.0f);
    outside &= outcode(c);
    nearest = std::min(nearest, c.w);  // clip w is the view depth for a perspective projection
    farthest = std::max(farthest, c.w);
    if (c.w > 0.0f) {
      ndcMin = glm::min(ndcMin, glm::vec2(c) / c.w);
      ndcMax = glm::max(ndcMax, glm::vec2(c) / c.w);
    }
  }
  if (outside != 0) return false;
  const float near = frame.depthParams.x;
  const float centerDepth = (frame.viewProj * glm::vec4(light.position, 1.0f)).w;
  // The shader's depth discard: the light reaches no farther than its range from its position.
  out.gpu.depthRange = glm::vec4(std::max(nearest, centerDepth - light.range),
                                 std::min(farthest, centerDepth + light.range), 0.0f, 0.0f);
  out.gpu.light = glm::uvec4(index, 0u, 0u, 0u);
  out.cameraInside = nearest < 2.0f * near;
  const glm::vec2 extent = glm::clamp(ndcMax, -1.0f, 1.0f) - glm::clamp(ndcMin, -1.0f, 1.0f);
  out.screenPixels = out.cameraInside ? frame.viewport.x * frame.viewport.y
                                      : 0.25f * extent.x * extent.y * frame.viewport.x * frame.viewport.y;
  return true;
}

}  // namespace

std::vector<PlacedLightVolume> placeLightVolumes(const std::vector<Light>& lights,
                                                 const gpu::FrameUniforms& frame) {
  std::vector<PlacedLightVolume> placed;
  placed.reserve(lights.size());
  for (uint32_t i = 0; i < lights.size(); ++i) {
    PlacedLightVolume volume;
    if (placeLight(lights[i], i, frame, volume)) placed.push_back(volume);
  }
  return placed;
}

LightVolumeDraws::LightVolumeDraws(Context& context, uint32_t maxLights) {
  requireStorageBufferFits(context, maxLights, sizeof(gpu::LightVolume), "the light-volume array");
  VkPhysicalDeviceFeatures features{};
  vkGetPhysicalDeviceFeatures(context.physicalDevice(), &features);
  if (!features.depthClamp)
    throw std::runtime_error(
        context.info().name +
        " lacks depthClamp: light volumes beyond the far plane would lose their back faces");
  // Shells use the scene's vertex layout so light-volume pipelines share the mesh vertex input;
  // normals and UVs stay zero and unread.
  std::vector<Vertex> vertices;
  std::vector<uint32_t> indices;
  for (VolumeShape shape : {VolumeShape::Sphere, VolumeShape::Cone}) {
    const VolumeMesh& mesh = shell(shape);
    ranges_[uint32_t(shape)] = {uint32_t(indices.size()), uint32_t(mesh.indices.size()),
                                int32_t(vertices.size())};
    for (const glm::vec3& p : mesh.positions) vertices.push_back(Vertex{p, glm::vec3(0.0f), glm::vec2(0.0f)});
    indices.insert(indices.end(), mesh.indices.begin(), mesh.indices.end());
  }
  shellVertices_ = Buffer(context, vertices.size() * sizeof(Vertex), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT,
                          MemoryUse::Device, "light-shell-vertices");
  shellVertices_.upload(std::span<const Vertex>(vertices));
  shellIndices_ = Buffer(context, indices.size() * sizeof(uint32_t), VK_BUFFER_USAGE_INDEX_BUFFER_BIT,
                         MemoryUse::Device, "light-shell-indices");
  shellIndices_.upload(std::span<const uint32_t>(indices));
  volumes_ = Buffer(context, std::max<VkDeviceSize>(1, maxLights) * sizeof(gpu::LightVolume),
                    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::Upload, "light-volumes");
}

const std::vector<PlacedLightVolume>& LightVolumeDraws::prepare(
    const std::vector<Light>& lights, const gpu::FrameUniforms& frame,
    uint32_t (*drawGroup)(const PlacedLightVolume&)) {
  placed_ = placeLightVolumes(lights, frame);
  for (PlacedLightVolume& v : placed_) v.group = drawGroup(v);
  std::stable_sort(placed_.begin(), placed_.end(),
                   [](const PlacedLightVolume& a, const PlacedLightVolume& b) {
                     return std::make_pair(a.group, a.shape) < std::make_pair(b.group, b.shape);
                   });
  std::vector<gpu::LightVolume> gpuVolumes;
  gpuVolumes.reserve(placed_.size());
  counts_ = {};
  for (const PlacedLightVolume& v : placed_) {
    gpuVolumes.push_back(v.gpu);
    counts_.cameraInside += v.cameraInside ? 1 : 0;
    counts_.cones += v.shape == VolumeShape::Cone ? 1 : 0;
  }
  counts_.visible = uint32_t(placed_.size());
  volumes_.upload(std::span<const gpu::LightVolume>(gpuVolumes));
  return placed_;
}

std::vector<VolumeRun> LightVolumeDraws::runs() const {
  std::vector<VolumeRun> runs;
  for (uint32_t i = 0; i < placed_.size(); ++i) {
    const PlacedLightVolume& v = placed_[i];
    if (!runs.empty() && runs.back().group == v.group && runs.back().shape == v.shape)
      ++runs.back().count;
    else
      runs.push_back({v.group, v.shape, i, 1});
  }
  return runs;
}

DescriptorWriter& LightVolumeDraws::addBindings(DescriptorWriter& writer, const FrameContext& frame) const {
  writer.storage(0, frame.uniformBuffer.handle())
      .storage(1, frame.scene.lightBuffer().handle())
      .storage(3, volumes_.handle())
      .image(5, frame.targets.depth.view(), VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL);
  if (frame.lightShadows) frame.lightShadows->bind(writer);
  return writer;
}

void LightVolumeDraws::bindGeometry(VkCommandBuffer cmd) const {
  const VkDeviceSize offset = 0;
  VkBuffer vertices = shellVertices_.handle();
  vkCmdBindVertexBuffers(cmd, 0, 1, &vertices, &offset);
  vkCmdBindIndexBuffer(cmd, shellIndices_.handle(), 0, VK_INDEX_TYPE_UINT32);
}

void LightVolumeDraws::draw(VkCommandBuffer cmd, VolumeShape shape, uint32_t first, uint32_t count) const {
  if (count == 0) return;
  const ShellRange& r = ranges_[uint32_t(shape)];
  vkCmdDrawIndexed(cmd, r.indexCount, count, r.firstIndex, r.vertexOffset, first);
}

}  // namespace lll
