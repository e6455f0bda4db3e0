#pragma once
// What a technique gives the passes every technique shares (opaque shading, for techniques without
// their own; glass; particles): the GLSL lighting interface those passes are compiled with
// (shaders/lighting/<name>/lighting.glsl, see shaders/common/lighting.glsl) and the light data
// they read through it.
#include <functional>
#include <string>
#include <vector>

#include "gpu/pipeline.h"
#include "render/frame_graph.h"

namespace lll {

struct LightingInterface {
  std::string name;  // "forward", "lll", "unlit", ...: the shaders/lighting/<name> folder
  // Writes the interface's light data into a lit pass's descriptors (set 0, bindings 3 to 10).
  std::function<void(DescriptorWriter&)> bind = [](DescriptorWriter&) {};
  // The buffers it reads, for the frame graph.
  std::vector<const Buffer*> buffers;
  // How many parts a point's lights split into (lightsAtPart() in shaders/common/lighting.glsl:
  // lll's heads with --vpl-interleave): glass-light lights them and vpl-classes the glossy metals'
  // VPL classes on a workgroup each (render/lit_passes.h).
  uint32_t listParts = 1;
  // Specialization constants of the interface's GLSL (lll: its link format), set on every pass
  // compiled with it. They may change between frames (lll moves from compact to wide links when a
  // pool outgrows 24-bit links): the renderer then builds the lit passes again.
  SpecializationConstants constants;

  // Names the pipelines built with this interface: its folder and its constants.
  std::string key() const {
    std::string k = name;
    for (const auto& [id, value] : constants) k += "/" + std::to_string(id) + "=" + std::to_string(value);
    return k;
  }
  // `base` with this interface's constants added.
  SpecializationConstants with(SpecializationConstants base) const {
    for (const auto& [id, value] : constants) base[id] = value;
    return base;
  }

  // What a lit pass reading the light data in `stages` declares.
  std::vector<ResourceUse> reads(VkPipelineStageFlags2 stages) const {
    std::vector<ResourceUse> out;
    for (const Buffer* b : buffers) out.push_back(uses(*b, Use::StorageRead, stages));
    return out;
  }
};

// The shared shader `templateName` (shaders/lit/<templateName>.glsl) compiled with `lighting`'s
// interface, as cmake/EmbedShaders.cmake registers it.
inline std::string litShader(const LightingInterface& lighting, const std::string& templateName) {
  return "lit/" + lighting.name + "/" + templateName;
}

// How a technique's opaque surfaces are lit.
enum class OpaqueShading {
  Own,         // by the technique's own passes (deferred's light volumes, the pre-pass)
  Visibility,  // the shared compute pass, surfaces rebuilt from the visibility buffer
  GBuffer,     // the shared compute pass over the thin G-buffer, drawn from the geometry
  Geometry,    // a geometry pass lighting each fragment (forward on the geometry, lll fragment)
};

}  // namespace lll
