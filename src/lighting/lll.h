#pragma once
// Technique "lll": the Light Linked List (Bezrati; ThreeL). Each frame the GPU builds, for every
// screen tile, a linked list of the lights that touch it, then every surface walks its tile's list.
// Frame: lll-clear -> lll-tile-depth -> lll-fill-{shells|ray|compute} -> lll-shade-opaque ->
//        lll-shade-blend (-> lll-stats on captured frames).
#include <memory>

#include "lighting/technique.h"

namespace lll {

enum class LllFill { Shells, Ray, Compute };

std::unique_ptr<Technique> createLightLinkedList(Context& context, const GpuScene& scene,
                                                 const RenderSettings& settings, const FrameTargets& targets);

}  // namespace lll
