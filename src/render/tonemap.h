#pragma once
// shaders/post/tonemap.comp's display path on the CPU, for images made without the GPU (the
// path-traced reference): a PNG of the same radiance then matches `lll render --out` at the same
// exposure, so the two can be compared side by side.
#include "render/images.h"

namespace lll {

// Radiance rounded to half floats (the renderer's HDR target), times exposure, through the filmic
// curve (Narkowicz's ACES fit), sRGB-encoded to 8 bits. A NaN stays NaN through the curve and
// becomes 0, as a GPU's UNORM conversion makes it.
LdrImage tonemapFilmic(const HdrImage& hdr, float exposure);

}  // namespace lll
