#pragma once
// Shared by the instant-radiosity tests: the Cornell room's path-traced indirect light, and a
// scene's lit VPLs in an order that does not depend on the slots they sit in.
#include <algorithm>
#include <tuple>
#include <vector>

#include "gi/path_tracer.h"
#include "render/image_compare.h"
#include "scene/builtin_gi_scenes.h"

namespace lll::test {

// `lll reference cornell --indirect --spp 1024 --bounces 2` from the room's camera, as an image.
inline HdrImage cornellIndirectReference(uint32_t width, uint32_t height) {
  const Scene direct = builtin::makeCornell();
  gi::ReferenceOptions options;
  options.spp = 1024;
  options.bounces = 2;
  options.indirectOnly = true;
  const gi::RadianceImage radiance = gi::renderReference(direct, direct.cameras[0], width, height, options);
  return HdrImage::fromRgb(radiance.width, radiance.height, radiance.rgb);
}

// The VPLs with any intensity, by hierarchy band (outer radius), then position.
inline std::vector<Light> litVpls(const std::vector<Light>& vpls) {
  std::vector<Light> lit;
  for (const Light& l : vpls)
    if (l.intensity > 0.0f) lit.push_back(l);
  std::sort(lit.begin(), lit.end(), [](const Light& a, const Light& b) {
    return std::tie(a.bandOuter, a.position.x, a.position.y, a.position.z) <
           std::tie(b.bandOuter, b.position.x, b.position.y, b.position.z);
  });
  return lit;
}

}  // namespace lll::test
