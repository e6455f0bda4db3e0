// Technique "tiled": tiled shading (Forward+, Harada et al. 2012) as users ship it, as one of lll's
// peers. Each tile keeps an array of the lights touching the volume between its nearest and
// farthest opaque surface, plus a second array of those in front of its nearest surface for glass
// and particles; both are built in compute (lighting/light_grid.h) and every shading pass loops over
// its tile's array.
#include "lighting/light_grid.h"

namespace lll {

std::unique_ptr<Technique> createTiled(Context& context, const GpuScene& scene,
                                       const RenderSettings& settings, const FrameTargets& targets,
                                       const VisibilityBuffer* visibility) {
  return createLightGrid(context, scene, settings, targets, visibility, 2);
}

}  // namespace lll
