// Renders a glTF file (or a built-in scene) with lll's public API and writes a PNG:
//   render_gltf SCENE OUT.png [TECHNIQUE] [DEVICE] [WIDTH HEIGHT]
// Exit codes as the lll command's: 0 done, 1 failure, 2 bad input.
#include <lll/lll.h>

#include <cstdio>
#include <exception>
#include <string>

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s SCENE OUT.png [TECHNIQUE] [DEVICE] [WIDTH HEIGHT]\n", argv[0]);
    return 2;
  }
  try {
    lll::SceneRequest request;
    request.scene = argv[1];
    const lll::Scene scene = lll::loadScene(request);

    lll::RenderSettings settings;
    if (argc > 3) settings.technique = argv[3];
    if (argc > 6) {
      settings.width = uint32_t(std::stoul(argv[5]));
      settings.height = uint32_t(std::stoul(argv[6]));
    }
    lll::validateResolution(settings.width, settings.height);
    lll::findTechnique(settings.technique);

    lll::ContextOptions device;
    device.device = argc > 4 ? argv[4] : "auto";
    lll::Context context(device);
    lll::Renderer renderer(context, scene, settings);
    const lll::FrameResult frame = renderer.renderFrame(/*capture=*/true);
    lll::writePng(argv[2], renderer.ldrImage());
    for (const lll::PassTime& pass : frame.passes)
      std::printf("%-24s %9.3f ms\n", pass.name.c_str(), pass.ms);
    return 0;
  } catch (const lll::InputError& e) {
    std::fprintf(stderr, "render_gltf: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "render_gltf: failure: %s\n", e.what());
    return 1;
  }
}
