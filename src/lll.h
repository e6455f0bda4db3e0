#pragma once
// lll's public API: everything a program needs to render with the library, and all that `lll view`
// uses. Installed with the library (`cmake --install`); a program finds it with find_package(lll)
// and links lll::lll (examples/render_gltf/ shows the whole round trip).
//
//   lll::Context context({.device = "auto"});                         // Vulkan instance and device
//   lll::Scene scene = lll::loadScene({.scene = "model.gltf"});        // glTF or a built-in scene
//   lll::RenderSettings settings;  settings.technique = "lll";          // what `lll render` takes
//   lll::Renderer renderer(context, scene, settings);
//   renderer.renderFrame(true);                                         // one frame, read back
//   lll::writePng("out.png", renderer.ldrImage());
//
// Errors in the input (a broken file, a bad option) are lll::InputError; Vulkan failures
// lll::VulkanError.
#include "core/errors.h"
#include "gpu/context.h"
#include "gpu/resources.h"
#include "gpu/vk_check.h"
#include "lighting/technique.h"
#include "particles/particle_setup.h"
#include "particles/presets.h"
#include "render/image_io.h"
#include "render/output_files.h"
#include "render/settings.h"
#include "render/stats.h"
#include "renderer/renderer.h"
#include "scene/builtin_scenes.h"
#include "scene/camera.h"
#include "scene/light_animation.h"
#include "scene/scene.h"
#include "scene/scene_source.h"
