// shade_visibility.comp with the VPLs split between the pixels of each k x k block
// (gi/interleaved_vpls.glsl, render/interleaved_vpls.h): the direct light goes to hdr, the pixel's
// class of VPLs to the images gi/vpl_filter.comp gathers from.
#define LLL_INTERLEAVED_VPLS
#include "lit/shade_visibility.comp.glsl"
