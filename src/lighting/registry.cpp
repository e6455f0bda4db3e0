#include <fmt/format.h>

#include "core/errors.h"
#include "lighting/lll.h"
#include "lighting/technique.h"

namespace lll {

std::unique_ptr<Technique> createForward(Context&, const GpuScene&, const RenderSettings&,
                                         const FrameTargets&, const VisibilityBuffer*);
std::unique_ptr<Technique> createDeferred(Context&, const GpuScene&, const RenderSettings&,
                                          const FrameTargets&, const VisibilityBuffer*);
std::unique_ptr<Technique> createPrepass(Context&, const GpuScene&, const RenderSettings&,
                                         const FrameTargets&, const VisibilityBuffer*);
std::unique_ptr<Technique> createTiled(Context&, const GpuScene&, const RenderSettings&, const FrameTargets&,
                                       const VisibilityBuffer*);
std::unique_ptr<Technique> createClustered(Context&, const GpuScene&, const RenderSettings&,
                                           const FrameTargets&, const VisibilityBuffer*);

namespace {
bool always(const RenderSettings&) {
  return true;
}
bool lllFragmentShading(const RenderSettings& settings) {
  return settings.lllShade == LllShade::Fragment;
}
}  // namespace

const std::vector<TechniqueInfo>& techniques() {
  static const std::vector<TechniqueInfo> table = {
      {"forward", "brute force: every pixel evaluates every light (the reference)", &createForward},
      {"deferred", "Infinity's deferred lighting: G-buffer, then lights drawn as volumes", &createDeferred,
       nullptr, 8, /*readsLightsOnCpu=*/true},
      {"prepass", "Resistance 2's light pre-pass: normals, stencil-volume lights, material", &createPrepass,
       &always, 8, /*readsLightsOnCpu=*/true},
      {"lll", "light linked list: per-tile light lists built on the GPU (--lll-fill shells|ray|compute)",
       &createLightLinkedList, &lllFragmentShading, kLllDefaultTile},
      {"tiled", "tiled shading (Forward+): per-tile light index arrays between the tile's depth bounds",
       &createTiled},
      {"clustered", "clustered shading: light index arrays per tile x depth slice (--cluster-slices)",
       &createClustered},
  };
  return table;
}

uint32_t tileSizeFor(const RenderSettings& settings) {
  return settings.tileSize ? settings.tileSize : findTechnique(settings.technique).defaultTile;
}

const TechniqueInfo& findTechnique(const std::string& name) {
  std::string known;
  for (const TechniqueInfo& t : techniques()) {
    if (t.name == name) return t;
    known += (known.empty() ? "" : ", ") + t.name;
  }
  throw InputError(fmt::format("--technique {}: unknown technique (known: {})", name, known));
}

}  // namespace lll
