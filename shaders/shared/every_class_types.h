// --vpl-interleave where the lighting interface keeps each class of VPLs apart (lll's class
// lists, LightingInterface::listParts > 1), shared by C++ and GLSL: pixels that need classes lit on
// their own surface take slots. shade-opaque places a glossy metal's pixel, which must have every
// class (gi/vpl_interleave_data.glsl), and lights it by the lights before the VPLs only; vpl-filter
// places, after them, a pixel none of whose neighbours on its surface brings some classes (an edge,
// a sliver narrower than the pattern), with those classes, after adding the ones it found.
// "vpl-classes" then lights each slot's classes on workgroups of their own (one class each) and
// adds them to the pixels. Written once here; see shared.h for the rules.
#ifndef LLL_EVERY_CLASS_TYPES_H
#define LLL_EVERY_CLASS_TYPES_H
#include "shared/shared.h"

LLL_NAMESPACE_BEGIN

// vpl-classes' indirect dispatch (x groups of 64 slots, y the classes, z 1), then the slots.
struct EveryClassHeader {
  uint groups;    // workgroups of 64 slots: one more each time a slot that is a multiple of 64 is taken
  uint classes;   // K*K
  uint one;       // 1
  uint pixels;    // slots asked for, also past `capacity` (such metals evaluate every class in place,
                  // such edge pixels stand the classes found for the rest)
  uint capacity;  // slots the buffers hold
  uint pad0;
  uint pad1;
  uint pad2;
};
LLL_CHECK_SIZE(EveryClassHeader, 32);

// A slot: the surface as the lights need it, and the classes to light.
struct EveryClassSurface {
  vec4 positionDepth;       // world position, view depth
  vec4 normalMetallic;      // shading normal, metallic
  vec4 baseColorRoughness;  // base colour, roughness
  uvec4 pixel;              // x: the pixel, x | y << 16; y: the classes to light, a bit each;
                            // z: those lit so far (vpl-classes), 0 when placed
};
LLL_CHECK_SIZE(EveryClassSurface, 64);

LLL_NAMESPACE_END

#endif
