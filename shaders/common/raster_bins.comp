#version 460
// The compute rasterizer's binning pass (render/compute_raster.h), between the per-triangle pass
// and the per-pixel pass: every large triangle the first pass listed is appended to the
// 32x32-pixel bins it may cover a pixel centre of, each triangle by a whole workgroup. A floor or
// wall of the view touches up to all of the image's bins (2,040 at 1080p); binned serially by the
// thread that found it, with an atomic per bin, it held the whole first pass for 0.6 ms on the H200.
#include "common/frame.glsl"

layout(local_size_x = 64) in;

layout(push_constant) uniform RasterBlock {
  RasterPush raster;
};

#include "common/raster_triangle.glsl"

void main() {
  rasterBinListed(uint(frame.viewport.y));
}
