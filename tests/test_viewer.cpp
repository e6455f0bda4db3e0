// lll view: its camera and input replay as functions, then the viewer itself in a window on an
// X server of its own (Xvfb), driven through --frames, --screenshot and --script, its images
// compared with `lll render`'s.
#include <gtest/gtest.h>
#include <sys/socket.h>
#include <sys/un.h>

#include <cmath>
#include <glm/gtc/constants.hpp>

#include "cli_test_support.h"
#include "core/errors.h"
#include "image_bound.h"
#include "particles/presets.h"
#include "render/image_io.h"
#include "scene/camera.h"
#include "scene/scene_source.h"
#include "view/input_script.h"
#include "view/view_camera.h"

namespace lll {
namespace {

namespace fs = std::filesystem;

Camera startCamera() {
  Camera c;
  c.name = "start";
  c.eye = {1.0f, 2.0f, 3.0f};
  c.target = {1.0f, 2.0f, -7.0f};  // 10 m down -z
  return c;
}

TEST(ViewCamera, DrawsTheStartCameraExactlyUntilTheFirstInput) {
  view::ViewCamera camera(startCamera(), 50.0f);
  camera.update({}, 1.0f / 60.0f);
  const Camera c = camera.camera();
  EXPECT_EQ(c.name, "start");
  EXPECT_EQ(c.eye, startCamera().eye);
  EXPECT_EQ(c.target, startCamera().target);
  EXPECT_FLOAT_EQ(camera.speed(), 5.0f) << "a tenth of the scene's diagonal per second";
}

TEST(ViewCamera, FliesAlongWhereItLooksAndTurnsWithTheMouse) {
  view::ViewCamera camera(startCamera(), 10.0f);  // 1 m/s
  view::CameraInput in;
  in.forward = true;
  for (int i = 0; i < 60; ++i) camera.update(in, 1.0f / 60.0f);
  EXPECT_NEAR(camera.camera().eye.z, 2.0f, 1e-4f) << "one second forward at 1 m/s down -z";
  EXPECT_NEAR(camera.camera().eye.x, 1.0f, 1e-5f);
  in = {};
  in.right = true;
  in.fast = true;
  camera.update(in, 0.5f);
  EXPECT_NEAR(camera.camera().eye.x, 3.0f, 1e-4f) << "right of -z is +x; shift is 4x";
  // A quarter turn to the right: pi/2 over kRadiansPerPixel pixels of mouse movement.
  in = {};
  in.look.x = glm::half_pi<float>() / view::ViewCamera::kRadiansPerPixel;
  camera.update(in, 0.0f);
  EXPECT_NEAR(camera.forward().x, 1.0f, 1e-4f);
  EXPECT_NEAR(camera.forward().z, 0.0f, 1e-4f);
  in = {};
  in.look.y = -1e6f;  // far past straight up: held just short of it
  camera.update(in, 0.0f);
  EXPECT_GT(camera.forward().y, 0.999f);
  EXPECT_LT(camera.forward().y, 1.0f);
  in = {};
  in.wheel = 2.0f;
  camera.update(in, 0.0f);
  EXPECT_NEAR(camera.speed(), 1.5625f, 1e-5f) << "1.25 per wheel step";
}

TEST(ViewCamera, OrbitKeepsItsDistanceToTheTarget) {
  view::ViewCamera camera(startCamera(), 10.0f);
  camera.setMode(view::CameraMode::Orbit);
  const glm::vec3 target = startCamera().target;
  view::CameraInput in;
  in.look = {200.0f, -80.0f};
  camera.update(in, 1.0f / 60.0f);
  const Camera c = camera.camera();
  EXPECT_NEAR(glm::length(c.eye - target), 10.0f, 1e-3f);
  EXPECT_NEAR(glm::length(c.target - target), 0.0f, 1e-3f) << "the eye turns about the target";
  EXPECT_GT(glm::length(c.eye - startCamera().eye), 1.0f);
  in = {};
  in.wheel = 1.0f;  // closer by 1.25
  camera.update(in, 0.0f);
  EXPECT_NEAR(glm::length(camera.camera().eye - target), 8.0f, 1e-3f);
}

TEST(ViewCamera, ItsCameraStringIsTheSameViewForLllRender) {
  Camera start = startCamera();
  start.yfov = glm::radians(40.0f);
  view::ViewCamera camera(start, 10.0f);
  view::CameraInput in;
  in.forward = true;
  in.look = {33.0f, 12.0f};
  camera.update(in, 0.25f);
  const Camera flown = camera.camera();
  const Camera parsed = resolveCamera(Scene{}, camera.cameraString());
  EXPECT_NEAR(glm::length(parsed.eye - flown.eye), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::length(parsed.target - flown.target), 0.0f, 1e-5f);
  EXPECT_NEAR(parsed.yfov, flown.yfov, 1e-6f) << "the field of view travels as the seventh number";
  EXPECT_THROW(resolveCamera(Scene{}, "0,0,0,0,0,-1,180"), InputError);
}

TEST(InputScript, ParsesEventsInFrameOrder) {
  const auto events = view::parseInputScript(
      "# a comment\n\n5 key w up\n0 key w down\n3 look 10 -2.5\n3 drop /tmp/a file.gltf\n7 print-camera\n",
      "s.txt");
  ASSERT_EQ(events.size(), 5u);
  EXPECT_EQ(events[0].frame, 0u);
  EXPECT_EQ(events[0].verb, "key");
  EXPECT_EQ(events[1].verb, "look");
  EXPECT_FLOAT_EQ(view::scriptNumber(events[1], 1), -2.5f);
  EXPECT_EQ(events[2].args, std::vector<std::string>{"/tmp/a file.gltf"}) << "a path keeps its spaces";
  EXPECT_EQ(events[4].verb, "print-camera");
}

TEST(InputScript, NamesTheFileAndLineOfABadEvent) {
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"0 jump\n", "s.txt:1: unknown event 'jump'"},
      {"\n0 key x down\n", "s.txt:2: key 'x'"},
      {"0 look 1\n", "s.txt:1: look takes 2 argument(s), got 1"},
      {"0 look 1 nan\n", "'nan' is not a finite number"},
      {"x key w down\n", "expected a frame number"},
      {"0 resize 0 10\n", "sizes must be 1 to 8192"},
      {"0 set colour red\n", "set 'colour'"},
      {"0 set debug-view heat\n", "s.txt:1: set debug-view 'heat': expected none, heatmap, bounds or tiles"},
      {"0 key w sideways\n", "expected down or up"},
  };
  for (const auto& [text, message] : bad) {
    try {
      view::parseInputScript(text, "s.txt");
      ADD_FAILURE() << "accepted: " << text;
    } catch (const InputError& e) {
      EXPECT_TRUE(test::contains(e.what(), message)) << e.what();
    }
  }
}

// An X server of this test's own: Xvfb picks a free display and writes its number to a pipe.
class ViewerCli : public test::CliTest {
 protected:
  // Xvfb's -displayfd is not safe to run twice at once (ctest runs these tests in parallel): a
  // second server probing a number replaces the first one's socket before finding the number
  // locked, and the first server's clients then fail to connect. Each test process picks numbers
  // at random instead, skips those in use, and waits until its server accepts connections.
  static void SetUpTestSuite() {
    std::mt19937 rng(std::random_device{}() ^ uint32_t(getpid()));
    for (int attempt = 0; attempt < 20 && display_.empty(); ++attempt) {
      const std::string number = std::to_string(200 + rng() % 5000);
      const std::string socketPath = "/tmp/.X11-unix/X" + number;
      if (fs::exists(socketPath) || fs::exists("/tmp/.X" + number + "-lock")) continue;
      const std::string display = ":" + number;
      const pid_t pid = fork();
      ASSERT_GE(pid, 0);
      if (pid == 0) {
        const int null = open("/dev/null", O_WRONLY);
        dup2(null, STDOUT_FILENO);
        dup2(null, STDERR_FILENO);
        execlp("Xvfb", "Xvfb", display.c_str(), "-screen", "0", "1024x768x24", "-nolisten", "tcp",
               static_cast<char*>(nullptr));
        _exit(127);
      }
      for (int wait = 0; wait < 500; ++wait) {             // 10 s
        if (waitpid(pid, nullptr, WNOHANG) == pid) break;  // it exited: the number was taken, or no Xvfb
        if (acceptsConnections(socketPath)) {
          xvfb_ = pid;
          display_ = display;
          break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
      }
      if (display_.empty()) {
        kill(pid, SIGKILL);
        waitpid(pid, nullptr, 0);
      }
    }
    ASSERT_FALSE(display_.empty())
        << "Xvfb did not start: the viewer's tests need it (Debian: apt-get install "
           "xvfb; scripts/setup-debian.sh installs it)";
  }
  static bool acceptsConnections(const std::string& socketPath) {
    const int fd = socket(AF_UNIX, SOCK_STREAM, 0);
    if (fd < 0) return false;
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    std::strncpy(address.sun_path, socketPath.c_str(), sizeof(address.sun_path) - 1);
    const bool ok = connect(fd, reinterpret_cast<const sockaddr*>(&address), sizeof(address)) == 0;
    close(fd);
    return ok;
  }
  static void TearDownTestSuite() {
    if (xvfb_ > 0) {
      kill(xvfb_, SIGTERM);
      waitpid(xvfb_, nullptr, 0);
    }
    xvfb_ = -1;
  }

  test::CliResult lll(const std::vector<std::string>& args) const {
    return test::runLll(args, {{"DISPLAY", display_}, {"LLL_VALIDATE", "1"}}, std::chrono::seconds(120));
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::string script(const std::string& text) const {
    std::ofstream(dir_ / "input.txt") << text;
    return path("input.txt");
  }

  static pid_t xvfb_;
  static std::string display_;
};
pid_t ViewerCli::xvfb_ = -1;
std::string ViewerCli::display_;

const std::vector<std::string> kSmall = {"--width", "96", "--height", "64", "--device", "cpu"};

std::vector<std::string> operator+(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

TEST_F(ViewerCli, ItsScreenshotIsWhatLllRenderDraws) {
  for (const std::string technique : {"forward", "lll"}) {
    const std::vector<std::string> options =
        kSmall + std::vector<std::string>{"--technique", technique, "--lights", "64", "--frames", "3"};
    const auto viewed =
        lll(std::vector<std::string>{"view", "atrium", "--screenshot", path("view.png")} + options);
    ASSERT_EQ(viewed.exitCode, 0) << viewed;
    const auto rendered =
        lll(std::vector<std::string>{"render", "atrium", "--out", path("render.png")} + options);
    ASSERT_EQ(rendered.exitCode, 0) << rendered;
    test::expectWithinBound(readPng(path("view.png")), readPng(path("render.png")), test::kSameImage,
                            "lll view vs lll render, " + technique);
  }
}

TEST_F(ViewerCli, ScriptedKeysAndMouseMoveTheCameraAndPrintIt) {
  // Forward for 20 frames (1/60 s each), a turn to the right, then the camera printed.
  const std::string input =
      script("0 key w down\n0 key shift down\n20 key w up\n20 look 60 -20\n22 print-camera\n");
  const auto moved = lll(std::vector<std::string>{"view", "atrium", "--script", input, "--frames", "23",
                                                  "--screenshot", path("moved.png")} +
                         kSmall);
  ASSERT_EQ(moved.exitCode, 0) << moved;
  const std::string line = test::lineStartingWith(moved.output, "camera: ");
  ASSERT_FALSE(line.empty()) << moved;
  const std::string cameraText = line.substr(8);
  // The atrium's camera, from `lll render`'s own choice: the printed eye is ahead of it.
  const Camera start = resolveCamera(loadScene(SceneRequest{"atrium"}), "");
  const Camera flown = resolveCamera(Scene{}, cameraText);
  const glm::vec3 ahead = glm::normalize(start.target - start.eye);
  EXPECT_GT(glm::dot(flown.eye - start.eye, ahead), 0.5f) << cameraText;
  const glm::vec3 turned = glm::normalize(flown.target - flown.eye);
  EXPECT_LT(glm::dot(glm::cross(ahead, turned), glm::vec3(0, 1, 0)), 0.0f)
      << "turned right (clockwise from above)";
  EXPECT_GT(turned.y, ahead.y) << "looked up";
  // `lll render --camera` with the printed value draws what the window showed.
  const auto rendered = lll(
      std::vector<std::string>{"render", "atrium", "--camera=" + cameraText, "--out", path("render.png")} +
      kSmall);
  ASSERT_EQ(rendered.exitCode, 0) << rendered;
  test::expectWithinBound(readPng(path("moved.png")), readPng(path("render.png")), test::kSameImage,
                          "flown camera vs lll render --camera");
}

TEST_F(ViewerCli, KeepsRenderingThroughAResizeAndATechniqueChange) {
  const std::string input = script("1 resize 80 48\n2 set technique lll\n3 set exposure 2\n");
  const auto r = lll(std::vector<std::string>{"view", "atrium", "--script", input, "--frames", "5",
                                              "--screenshot", path("resized.png")} +
                     kSmall);
  ASSERT_EQ(r.exitCode, 0) << r;
  const LdrImage image = readPng(path("resized.png"));
  EXPECT_EQ(image.width, 80u);
  EXPECT_EQ(image.height, 48u);
  const auto rendered =
      lll(std::vector<std::string>{"render", "atrium", "--technique", "lll", "--exposure", "2", "--width",
                                   "80", "--height", "48", "--device", "cpu", "--out", path("render.png")});
  ASSERT_EQ(rendered.exitCode, 0) << rendered;
  test::expectWithinBound(image, readPng(path("render.png")), test::kSameImage, "resized, lll, exposure 2");
}

TEST_F(ViewerCli, ABrokenDroppedFileKeepsTheSceneAndAGoodOneReplacesIt) {
  std::ofstream(dir_ / "broken.gltf") << "{ \"asset\": { \"version\": \"2.0\" }, \"meshes\": [ {";
  const fs::path quad = test::QuadGltf().write(dir_, "quad");
  const std::string broken = script("1 drop " + path("broken.gltf") + "\n");
  const auto kept = lll(std::vector<std::string>{"view", "atrium", "--script", broken, "--frames", "3",
                                                 "--screenshot", path("kept.png")} +
                        kSmall);
  ASSERT_EQ(kept.exitCode, 0) << kept;
  EXPECT_TRUE(test::contains(kept.output, "broken.gltf")) << kept;
  EXPECT_TRUE(test::contains(kept.output, "the current scene stays")) << kept;
  const auto atrium = lll(std::vector<std::string>{"render", "atrium", "--out", path("atrium.png")} + kSmall);
  ASSERT_EQ(atrium.exitCode, 0) << atrium;
  test::expectWithinBound(readPng(path("kept.png")), readPng(path("atrium.png")), test::kSameImage,
                          "after a broken drop");

  const std::string good = script("1 drop " + quad.string() + "\n");
  const auto replaced = lll(std::vector<std::string>{"view", "atrium", "--script", good, "--frames", "3",
                                                     "--screenshot", path("quad-view.png")} +
                            kSmall);
  ASSERT_EQ(replaced.exitCode, 0) << replaced;
  const auto quadRender =
      lll(std::vector<std::string>{"render", quad.string(), "--out", path("quad.png")} + kSmall);
  ASSERT_EQ(quadRender.exitCode, 0) << quadRender;
  test::expectWithinBound(readPng(path("quad-view.png")), readPng(path("quad.png")), test::kSameImage,
                          "after dropping a glTF");
}

TEST_F(ViewerCli, ThePresetEditorSavesAFileLllRenderDrawsTheSame) {
  const std::string input = script("0 preset-save " + path("saved.json") + "\n");
  const std::vector<std::string> particles = {"--particles", "sparks", "--particle-count", "512"};
  const auto saved = lll(std::vector<std::string>{"view", "atrium", "--script", input, "--frames", "1"} +
                         particles + kSmall);
  ASSERT_EQ(saved.exitCode, 0) << saved;
  ASSERT_TRUE(fs::exists(path("saved.json"))) << saved;
  const std::vector<std::string> render = {"render", "atrium", "--frames", "20", "--particle-count", "512"};
  const auto fromFile =
      lll(render + kSmall +
          std::vector<std::string>{"--particles", path("saved.json"), "--out", path("file.png")});
  ASSERT_EQ(fromFile.exitCode, 0) << fromFile;
  const auto builtin =
      lll(render + kSmall + std::vector<std::string>{"--particles", "sparks", "--out", path("builtin.png")});
  ASSERT_EQ(builtin.exitCode, 0) << builtin;
  test::expectWithinBound(readPng(path("file.png")), readPng(path("builtin.png")), test::kSameImage,
                          "saved preset vs built-in sparks");
  const ParticlePreset file = loadParticlePreset(path("saved.json")), sparks = loadParticlePreset("sparks");
  EXPECT_EQ(file.count, sparks.count);
  EXPECT_EQ(file.size, sparks.size);
  EXPECT_EQ(file.opacity, sparks.opacity);
  EXPECT_EQ(file.direction, sparks.direction);
  EXPECT_EQ(file.floor, sparks.floor);
}

TEST_F(ViewerCli, BadInputExitsTwoAndNamesIt) {
  auto expectBad = [&](const std::vector<std::string>& args, const std::string& named,
                       const std::map<std::string, std::string>& env) {
    const auto r = test::runLll(args, env, std::chrono::seconds(60));
    EXPECT_EQ(r.exitCode, 2) << r;
    EXPECT_TRUE(test::contains(r.output, named)) << "'" << named << "' not named: " << r;
    EXPECT_FALSE(fs::exists(path("shot.png")));
  };
  const std::map<std::string, std::string> display = {{"DISPLAY", display_}};
  expectBad({"view", "--screenshot", path("shot.png")}, "--screenshot needs --frames", display);
  expectBad({"view", "--frames", "1", "--screenshot", path("shot.txt")},
            "expected a name ending in .png or .exr", display);
  expectBad(
      {"view", "--frames", "1", "--script", script("0 key w sideways\n"), "--screenshot", path("shot.png")},
      "input.txt:1", display);
  expectBad({"view", "--frames", "1", "--script", path("missing.txt")}, "missing.txt", display);
  expectBad({"view", "--frames", "1", "--device", "cpu", "--screenshot", path("shot.png")}, "needs a display",
            {{"DISPLAY", ":99999"}, {"WAYLAND_DISPLAY", ""}});
}

}  // namespace
}  // namespace lll
