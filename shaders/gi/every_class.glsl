// VPL classes lit elsewhere (shared/every_class_types.h): shade-opaque (the glossy metals) and
// vpl-filter (the edge pixels) take the slots (EVERY_CLASS_PLACE), vpl-classes lights them and adds
// them to their pixels (EVERY_CLASS_LIGHT).
#ifndef LLL_EVERY_CLASS_GLSL
#define LLL_EVERY_CLASS_GLSL
#include "shared/every_class_types.h"

// Whether vpl-classes lights the slots' classes (else a glossy metal's pixel walks them all and an
// edge pixel stands the classes found for the rest).
layout(constant_id = 62) const bool kVplClassesPass = false;

#if defined(EVERY_CLASS_PLACE)
#define EVERY_CLASS_HEADER_ACCESS
#define EVERY_CLASS_SURFACE_ACCESS writeonly
#elif defined(EVERY_CLASS_LIGHT)
#define EVERY_CLASS_HEADER_ACCESS readonly
#define EVERY_CLASS_SURFACE_ACCESS  // each slot's count of classes lit (pixel.z)
#else
#define EVERY_CLASS_HEADER_ACCESS readonly
#define EVERY_CLASS_SURFACE_ACCESS readonly
#endif
#if defined(EVERY_CLASS_LIGHT)
#define EVERY_CLASS_LIGHT_ACCESS coherent  // the slot's last class reads the others'
#else
#define EVERY_CLASS_LIGHT_ACCESS readonly
#endif

#if defined(EVERY_CLASS_PLACE) || defined(EVERY_CLASS_LIGHT)
layout(std430, set = 0, binding = 44) EVERY_CLASS_HEADER_ACCESS buffer EveryClassHeaderBlock {
  EveryClassHeader everyClass;
};
layout(std430, set = 0, binding = 45) EVERY_CLASS_SURFACE_ACCESS buffer EveryClassSurfaceBlock {
  EveryClassSurface everyClassSurfaces[];
};
#endif
#if !defined(EVERY_CLASS_PLACE)
// Each slot's light per class (slot * K*K + class), rgb as halves.
layout(std430, set = 0, binding = 46) EVERY_CLASS_LIGHT_ACCESS buffer EveryClassLightBlock {
  uvec2 everyClassLight[];
};
#endif

#endif
