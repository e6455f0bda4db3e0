#include "scene/camera.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <vector>

#include "core/errors.h"

namespace lll {

Camera overviewCamera(const Bounds& bounds) {
  Camera camera;
  camera.name = "overview";
  const glm::vec3 extent = bounds.valid() ? bounds.extent() : glm::vec3(1.0f);
  const glm::vec3 center = bounds.valid() ? bounds.center() : glm::vec3(0.0f);
  camera.target = center;
  camera.eye =
      center + glm::vec3(0.55f * extent.x, 0.45f * extent.y + 0.1f * glm::length(extent), 0.55f * extent.z);
  return camera;
}

namespace {

std::vector<float> parseNumbers(const std::string& spec) {
  std::vector<float> numbers;
  size_t start = 0;
  while (start <= spec.size()) {
    const size_t comma = std::min(spec.find(',', start), spec.size());
    const char* first = spec.data() + start;
    const char* last = spec.data() + comma;
    while (first < last && *first == ' ') ++first;
    float value = 0.0f;
    auto [ptr, ec] = std::from_chars(first, last, value);
    if (ec != std::errc() || ptr != last || !std::isfinite(value)) return {};
    numbers.push_back(value);
    start = comma + 1;
  }
  return numbers;
}

}  // namespace

Camera resolveCamera(const Scene& scene, const std::string& spec) {
  if (spec.empty())
    return scene.cameras.empty() ? overviewCamera(scene.worldBounds()) : scene.cameras.front();
  for (const Camera& camera : scene.cameras)
    if (camera.name == spec) return camera;
  if (spec == "overview" && scene.cameras.empty()) return overviewCamera(scene.worldBounds());
  if (spec.find(',') != std::string::npos) {
    const std::vector<float> n = parseNumbers(spec);
    if (n.size() != 6 && n.size() != 7)
      throw InputError(fmt::format(
          "--camera {}: expected six numbers \"ex,ey,ez,tx,ty,tz\" (eye, target), or seven with the vertical "
          "field of view in degrees last",
          spec));
    Camera camera;
    camera.name = "custom";
    camera.eye = {n[0], n[1], n[2]};
    camera.target = {n[3], n[4], n[5]};
    if (n.size() == 7) {
      if (!(n[6] > 0.0f && n[6] < 180.0f))
        throw InputError(
            fmt::format("--camera {}: the field of view {} is not between 0 and 180 degrees", spec, n[6]));
      camera.yfov = glm::radians(n[6]);
    }
    if (glm::length(camera.target - camera.eye) < 1e-6f)
      throw InputError(fmt::format("--camera {}: eye and target are the same point", spec));
    return camera;
  }
  std::string names;
  for (const Camera& camera : scene.cameras) names += (names.empty() ? "" : ", ") + camera.name;
  if (names.empty()) names = "overview";
  throw InputError(
      fmt::format("--camera {}: scene '{}' has no such camera (cameras: {}; or give \"ex,ey,ez,tx,ty,tz\")",
                  spec, scene.name, names));
}

}  // namespace lll
