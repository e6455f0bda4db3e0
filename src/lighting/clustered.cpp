// Technique "clustered": clustered shading (Olsson, Billeter and Assarsson 2012) as one of lll's
// peers. Each tile is cut into depth slices, exponentially spaced between its nearest and farthest
// opaque surface (--cluster-slices), plus a front slice for glass and particles; each cluster keeps
// an array of the lights touching it, built in compute (lighting/light_grid.h). A point loops over
// the lights of its own cluster only, so lights far along the view ray from it cost nothing.
// Why clusters and not Drobot's z-binning (2017): z-binning keeps a bit per light per tile, which
// at a million lights is 128 KiB per tile; clusters keep only the lights that touch them.
#include <fmt/format.h>

#include "core/errors.h"
#include "lighting/light_grid.h"
#include "shared/grid_types.h"

namespace lll {

std::unique_ptr<Technique> createClustered(Context& context, const GpuScene& scene,
                                           const RenderSettings& settings, const FrameTargets& targets,
                                           const VisibilityBuffer* visibility) {
  if (settings.clusterSlices < 1 || settings.clusterSlices + 1 > gpu::kMaxGridSlices)
    throw InputError(fmt::format("--cluster-slices {}: expected 1 to {}", settings.clusterSlices,
                                 gpu::kMaxGridSlices - 1));
  return createLightGrid(context, scene, settings, targets, visibility, settings.clusterSlices + 1);
}

}  // namespace lll
