// The light linked list's lighting interface (shaders/common/lighting.glsl says what an interface
// provides): the lights of the list of the pixel's tile (and depth slice, with --lll-slices) whose
// depth bounds hold the point, and the debug views (--debug-view heatmap | bounds | tiles).
#ifndef LLL_LIGHTING_INTERFACE_GLSL
#define LLL_LIGHTING_INTERFACE_GLSL
#include "common/debug_colors.glsl"
#include "common/lll_walk.glsl"

// The list's first head, then `headsLeft` more from nextHead on (the VPL classes with
// --vpl-interleave).
struct LightCursor {
  uint link;
  uint steps;
  float viewDepth;
  uint nextHead;
  uint headsLeft;
};

LightCursor lightsAt(uvec2 pixel, float viewDepth) {
  uint head = listIndexOf(tileIndexOf(pixel), viewDepth) * listClasses();
  return LightCursor(tileHeads[head], 0u, viewDepth, head + 1u, listClasses() - 1u);
}

// The lights a pixel that evaluates only VPL class `vplClass` needs (gi/interleaved_vpls.glsl;
// common/lighting.glsl's optional part of the interface): with class lists, the first head and that
// class's; without, the whole list (the shading pass skips the other classes by index).
#define LIGHTING_CLASS_LISTS
LightCursor lightsAtInClass(uvec2 pixel, float viewDepth, uint vplClass) {
  LightCursor cursor = lightsAt(pixel, viewDepth);
  if (listClasses() > 1u) {
    cursor.nextHead += vplClass;
    cursor.headsLeft = 1u;
  }
  return cursor;
}

// Each of a list's heads is a part (common/lighting.glsl; LightingInterface::listParts is
// listClasses()): the lights before the VPLs, then each class of VPLs with --vpl-interleave.
#define LIGHTING_LIST_PARTS
LightCursor lightsAtPart(uvec2 pixel, float viewDepth, uint part) {
  uint head = listIndexOf(tileIndexOf(pixel), viewDepth) * listClasses() + part;
  return LightCursor(tileHeads[head], 0u, viewDepth, head + 1u, 0u);
}

// One link at a time, each read where it is followed. Reading ahead was measured slower twice on
// the H200: three consecutive links with the current one (b19e4e6: 1M lights' shading 2.70 -> 2.77
// ms) and the next link loaded while a light is evaluated (2026-12-01: 12-25% slower, 5,144 VPLs
// 10.4 -> 13.0 ms; bench/README.md): the warps already hide the chain's latency.
bool nextLight(inout LightCursor cursor, out uint light) {
  while (!nextListedLight(cursor.link, cursor.steps, cursor.viewDepth, light)) {
    if (cursor.headsLeft == 0u) return false;
    --cursor.headsLeft;
    cursor.link = tileHeads[cursor.nextHead++];
  }
  return true;
}

// The same walk one link at a time (common/lighting.glsl's optional nextLink): every link of the
// cursor's lists is yielded, `listed` saying whether its depth bounds hold the point. A loop over
// links that evaluates a light only where listed runs as one loop for a workgroup that shares a
// list, instead of nextLight's loop inside a loop that each invocation leaves at its own link.
#define LIGHTING_LINK_WALK
bool nextLink(inout LightCursor cursor, out uint light, out bool listed) {
  while (isListEnd(cursor.link) || cursor.steps >= longestPossibleList()) {
    if (cursor.headsLeft == 0u) {
      light = 0u;
      listed = false;
      return false;
    }
    --cursor.headsLeft;
    cursor.link = tileHeads[cursor.nextHead++];
  }
  LightLink l = readLink(cursor.link);
  cursor.link = l.next;
  ++cursor.steps;
  light = l.light;
  listed = cursor.viewDepth >= l.minDepth && cursor.viewDepth <= l.maxDepth;
  return true;
}

// --lll-records (LightLinkedList::lightingConstants): where the opaque shading reads a listed
// light's record. A workgroup walking one list reads the same record in every invocation, which a
// GPU's constant cache serves in one read: ThreeL's opaque shading on the H100 (1080p) took 0.2041
// -> 0.1985 ms at 16 lights, 2.168 -> 2.107 at 256 (bench/README.md, 2026-12-06). std140 lays a
// GpuLight out as std430 does (four vec4).
layout(constant_id = 43) const bool kRecordsFromUniformBlock = false;
layout(std140, set = 0, binding = 51) uniform LightRecordBlock {
  GpuLight uniformLights[kUniformLightRecords];
};

#define LIGHTING_LIGHT_RECORD
GpuLight lightRecord(uint light) {
  if (!kRecordsFromUniformBlock) return lights[light];
  // Member by member: glslang types the uniform block's struct apart from the storage buffer's.
  GpuLight record;
  record.positionRange = uniformLights[light].positionRange;
  record.colorIntensity = uniformLights[light].colorIntensity;
  record.directionType = uniformLights[light].directionType;
  record.spotParams = uniformLights[light].spotParams;
  return record;
}

// As ThreeL's view: a listed light's colour where it reaches the surface, grey where the list has
// it but the surface is out of its range (the cost of a coarse shape), black with no list entry.
vec3 boundsView(Surface s, uvec2 pixel, float viewDepth) {
  vec3 reached = vec3(0.0);
  bool listed = false;
  LightCursor cursor = lightsAt(pixel, viewDepth);
  uint index;
  while (nextLight(cursor, index)) {
    listed = true;
    GpuLight light = lights[index];
    if (any(greaterThan(evaluateLight(light, s), vec3(0.0))))
      reached = max(reached, light.colorIntensity.rgb);
  }
  return any(greaterThan(reached, vec3(0.0))) ? reached : (listed ? vec3(0.25) : vec3(0.0));
}

// The heatmap and bounds views replace the surface (glass included); tiles draws the grid over it.
vec3 lightingView(Surface s, uvec2 pixel, float viewDepth, vec3 color, out bool replaced) {
  uint view = lll.params.z;
  replaced = view == kDebugHeatmap || view == kDebugBounds;
  if (view == kDebugHeatmap) {
    uint head = listIndexOf(tileIndexOf(pixel), viewDepth) * listClasses(), count = 0u;
    for (uint c = 0u; c < listClasses(); ++c) count += listLength(head + c);
    return count == 0u ? vec3(0.0) : heat(float(count) / float(frame.display.y));
  }
  if (view == kDebugBounds) return boundsView(s, pixel, viewDepth);
  if (view == kDebugTiles) {
    uvec2 inTile = pixel % frame.counts.y;
    if (inTile.x == 0u || inTile.y == 0u) return vec3(1.0, 1.0, 0.0);
  }
  return color;
}

#endif
