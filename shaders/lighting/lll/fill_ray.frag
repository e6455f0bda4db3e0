#version 460
#define LLL_FILL_PASS
// ThreeL's refinement: back faces only. The eye ray through the tile centre is intersected with the
// light's exact sphere (and cone, for spots; box, for box lights), each grown by the tile inflation; a ray
// that misses adds no link, so the shell's corners cost nothing. The ray is rebuilt from the fragment
// position rather than interpolated from the vertices: the same ray, and it stays valid when shell vertices
// lie behind the eye (camera inside a light).
#include "lighting/lll/light_shape.glsl"

layout(location = 0) flat in uint inLight;
layout(location = 1) flat in uint inBatchId;
layout(location = 2) in float inDepth;

// Narrows [lo, hi] to where the ray p(t) = t * dir lies inside the cone (apex, axis, cos^2 angle).
void clipToCone(vec3 dir, vec3 apex, vec3 axis, float cos2, inout float lo, inout float hi) {
  vec3 co = -apex;
  float dw = dot(dir, axis), cw = dot(co, axis);
  // Forward nappe only: dot(p - apex, axis) >= 0.
  if (abs(dw) < 1e-8) {
    if (cw < 0.0) hi = lo - 1.0;
  } else if (dw > 0.0) {
    lo = max(lo, -cw / dw);
  } else {
    hi = min(hi, -cw / dw);
  }
  float a = dw * dw - cos2 * dot(dir, dir);
  float b = 2.0 * (dw * cw - cos2 * dot(dir, co));
  float c = cw * cw - cos2 * dot(co, co);
  if (abs(a) < 1e-10) {
    if (abs(b) < 1e-10) {
      if (c < 0.0) hi = lo - 1.0;
    } else if (b > 0.0) {
      lo = max(lo, -c / b);
    } else {
      hi = min(hi, -c / b);
    }
    return;
  }
  float disc = b * b - 4.0 * a * c;
  if (disc < 0.0) {
    if (a < 0.0) hi = lo - 1.0;  // q < 0 everywhere: never inside
    return;
  }
  float s = sqrt(disc);
  float r0 = min((-b - s) / (2.0 * a), (-b + s) / (2.0 * a));
  float r1 = max((-b - s) / (2.0 * a), (-b + s) / (2.0 * a));
  if (a < 0.0) {
    lo = max(lo, r0);
    hi = min(hi, r1);
    return;
  }
  // Inside on (-inf, r0] and [r1, inf): keep the hull of what remains of [lo, hi].
  bool first = lo <= min(hi, r0);
  bool second = max(lo, r1) <= hi;
  if (!first && !second) {
    hi = lo - 1.0;
  } else {
    if (!first) lo = max(lo, r1);
    if (!second) hi = min(hi, r0);
  }
}

// Where the ray p(t) = t * dir lies inside the box (centre, axes scaled by half extents, each half
// extent grown by `grow`): the slab intersection, or false when it misses.
bool rayBox(vec3 dir, vec3 center, vec3 axes[3], float grow, out float lo, out float hi) {
  lo = -1e30;
  hi = 1e30;
  for (int i = 0; i < 3; ++i) {
    float halfExtent = length(axes[i]);
    vec3 unit = axes[i] / halfExtent;
    float extent = halfExtent + grow;
    float o = dot(-center, unit), d = dot(dir, unit);
    if (abs(d) < 1e-12) {
      if (abs(o) > extent) return false;
      continue;
    }
    float t0 = (-extent - o) / d, t1 = (extent - o) / d;
    lo = max(lo, min(t0, t1));
    hi = min(hi, max(t0, t1));
  }
  return lo <= hi;
}

void main() {
  uvec2 tile = uvec2(gl_FragCoord.xy);
  if (tile.x >= frame.counts.z || tile.y >= frame.counts.w) return;
  uint tileIndex = tile.y * frame.counts.z + tile.x;
  vec2 gridNdc = gl_FragCoord.xy / vec2(frame.counts.zw) * 2.0 - 1.0;
  vec2 ndc = (gridNdc + 1.0) / lll.grid.xy - 1.0;
  // With dir.z = 1 the ray parameter is the linear depth itself.
  vec3 dir = vec3(ndc.x * frame.depthParams.z, -ndc.y * frame.depthParams.w, 1.0);
  GpuLight light = lights[inLight];
  vec3 center = toViewDepthSpace(light.positionRange.xyz);
  float inflation = tileInflation(center.z, light.positionRange.w);
  float radius = light.positionRange.w + inflation;
  float a = dot(dir, dir), b = dot(dir, center), c = dot(center, center) - radius * radius;
  float disc = b * b - a * c;
  if (disc < 0.0) return;
  float s = sqrt(disc);
  float lo = (b - s) / a, hi = (b + s) / a;
  if (isBox(light)) {
    vec3 axes[3];
    boxAxes(light, axes[0], axes[1], axes[2]);
    if (!rayBox(dir, center, axes, inflation, lo, hi)) return;
  } else if (usesCone(light)) {
    vec3 axis = directionToViewDepthSpace(light.directionType.xyz);
    float cosAngle = light.spotParams.x;
    float sinAngle = sqrt(max(1.0 - cosAngle * cosAngle, 1e-6));
    clipToCone(dir, center - axis * (inflation / sinAngle), axis, cosAngle * cosAngle, lo, hi);
  }
  if (hi < lo || hi <= 0.0) return;
  lo = max(lo, 0.0);                        // the eye is inside the light
  if (lo > tileRange[tileIndex].y) return;  // software depth test: behind the tile's farthest surface
  pushLink(tileIndex, inLight, lo, hi);
}
