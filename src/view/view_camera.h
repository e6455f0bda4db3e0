#pragma once
// The viewer's camera: fly (WASD/QE move, mouse look) or orbit (the mouse turns the eye about a
// target, the wheel moves it closer), starting from a scene or built-in camera. Pure math with no
// window: one frame's input in, a Camera out, so tests can drive it.
#include <glm/glm.hpp>
#include <string>

#include "scene/scene.h"

namespace lll::view {

// One frame's input, gathered from GLFW or from a replay script.
struct CameraInput {
  bool forward = false, back = false, left = false, right = false, up = false, down = false;
  bool fast = false;     // shift: 4x the speed
  glm::vec2 look{0.0f};  // mouse movement in pixels while the right button is held
  float wheel = 0.0f;    // scroll steps: fly speed (fly) or distance to the target (orbit)
  bool any() const {
    return forward || back || left || right || up || down || look != glm::vec2(0.0f) || wheel != 0.0f;
  }
};

enum class CameraMode { Fly, Orbit };

class ViewCamera {
 public:
  static constexpr float kRadiansPerPixel = 0.004f;
  static constexpr float kWheelFactor = 1.25f;  // per scroll step

  // `start` is drawn exactly as given until the first input; `sceneSize` sets the first fly speed
  // (a tenth of the scene's diagonal per second).
  ViewCamera(const Camera& start, float sceneSize);

  void reset(const Camera& start);
  void setMode(CameraMode mode);
  CameraMode mode() const { return mode_; }
  // Advances the camera by one frame of input lasting `seconds`.
  void update(const CameraInput& input, float seconds);
  Camera camera() const;
  // "ex,ey,ez,tx,ty,tz[,fov]": `lll render --camera` draws the same view (the scene camera's own
  // up vector aside: the viewer's is +y).
  std::string cameraString() const;
  float speed() const { return speed_; }
  void setSpeed(float metresPerSecond) { speed_ = metresPerSecond; }
  glm::vec3 forward() const;

 private:
  void setDirection(const glm::vec3& direction);

  Camera start_;
  bool moved_ = false;  // camera() returns start_ untouched until the first input
  CameraMode mode_ = CameraMode::Fly;
  glm::vec3 eye_{0.0f};
  float yaw_ = 0.0f;       // about +y; 0 looks down -z
  float pitch_ = 0.0f;     // up from the horizon, within +-89 degrees
  float distance_ = 1.0f;  // eye to target: the orbit's radius, the target the fly camera looks at
  float speed_ = 1.0f;     // fly speed, m/s
};

}  // namespace lll::view
