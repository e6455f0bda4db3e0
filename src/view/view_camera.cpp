#include "view/view_camera.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace lll::view {

namespace {
constexpr float kMaxPitch = 1.5533430f;  // 89 degrees: looking straight up or down loses the yaw
}

ViewCamera::ViewCamera(const Camera& start, float sceneSize) {
  speed_ = std::max(0.1f * sceneSize, 0.01f);
  reset(start);
}

void ViewCamera::reset(const Camera& start) {
  start_ = start;
  moved_ = false;
  eye_ = start.eye;
  const glm::vec3 toTarget = start.target - start.eye;
  distance_ = std::max(glm::length(toTarget), 1e-3f);
  setDirection(glm::length(toTarget) > 0.0f ? toTarget / glm::length(toTarget) : glm::vec3(0, 0, -1));
}

void ViewCamera::setDirection(const glm::vec3& d) {
  pitch_ = std::clamp(std::asin(std::clamp(d.y, -1.0f, 1.0f)), -kMaxPitch, kMaxPitch);
  yaw_ = std::atan2(d.x, -d.z);
}

glm::vec3 ViewCamera::forward() const {
  return {std::sin(yaw_) * std::cos(pitch_), std::sin(pitch_), -std::cos(yaw_) * std::cos(pitch_)};
}

void ViewCamera::setMode(CameraMode mode) {
  mode_ = mode;
}

void ViewCamera::update(const CameraInput& in, float seconds) {
  if (!in.any()) return;
  moved_ = true;
  const glm::vec3 target = eye_ + forward() * distance_;
  yaw_ += in.look.x * kRadiansPerPixel;
  pitch_ = std::clamp(pitch_ - in.look.y * kRadiansPerPixel, -kMaxPitch, kMaxPitch);
  const glm::vec3 f = forward();
  const glm::vec3 right = glm::normalize(glm::vec3(-f.z, 0.0f, f.x));  // horizontal, as f has pitch < 90
  glm::vec3 move(0.0f);
  if (in.forward) move += f;
  if (in.back) move -= f;
  if (in.right) move += right;
  if (in.left) move -= right;
  if (in.up) move.y += 1.0f;
  if (in.down) move.y -= 1.0f;
  const float step = speed_ * (in.fast ? 4.0f : 1.0f) * seconds;
  if (mode_ == CameraMode::Fly) {
    if (in.wheel != 0.0f) speed_ *= std::pow(kWheelFactor, in.wheel);
    eye_ += move * step;
  } else {
    // Orbit: the eye turns about the target it looked at; moving keys pan the target.
    if (in.wheel != 0.0f) distance_ = std::max(distance_ * std::pow(kWheelFactor, -in.wheel), 1e-3f);
    eye_ = target + move * step - f * distance_;
  }
}

Camera ViewCamera::camera() const {
  if (!moved_) return start_;
  Camera c = start_;
  c.name = "view";
  c.eye = eye_;
  c.target = eye_ + forward() * distance_;
  c.up = glm::vec3(0.0f, 1.0f, 0.0f);
  return c;
}

std::string ViewCamera::cameraString() const {
  const Camera c = camera();
  std::string text = fmt::format("{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}", c.eye.x, c.eye.y, c.eye.z,
                                 c.target.x, c.target.y, c.target.z);
  if (c.yfov != Camera{}.yfov) text += fmt::format(",{:.9g}", glm::degrees(c.yfov));
  return text;
}

}  // namespace lll::view
