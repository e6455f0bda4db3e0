#version 460
// vpl-filter's first half where the pattern lies on one surface: for each pixel q, the tent-weighted
// sum (k - |dx|) of the class light of the 2k-1 pixels of its row centred on q, where every one of
// them lies on q's surface under the chained tests (gi/vpl_filter_common.glsl) and inside the image
// (w = 1); else w = 0. vpl-filter sums these down a column where every row centre lies on the pixel's
// surface: each class then counts at every offset, the class means' sum is the whole tent sum over
// k*k, and 2(2k-1) taps replace the (2k-1)^2 of the gather (49 at K = 4). Sums as halves: rgb, then
// the specular's rgb.
#include "gi/vpl_filter_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 50, rgba32ui) uniform writeonly uimage2D vplRowSums;

void main() {
  ivec2 q = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = ivec2(frame.viewport.xy);
  if (q.x >= size.x || q.y >= size.y) return;
  int k = int(kVplInterleave), reach = k - 1;
  vec4 centre = texelFetch(vplIndirect, q, 0);
  uvec4 key = texelFetch(vplSurfaceKey, q, 0);
  bool whole = centre.w >= 0.0 && key.w == 0u && q.x >= reach && q.x + reach < size.x;
  vec3 sum = vec3(0.0), specular = vec3(0.0);
  if (whole) {
    vec3 normal = octahedralDecode(unpackSnorm2x16(key.x));
    vec3 position = viewPosition(q, centre.w);
    float tolerance = kChainPlaneTolerance * centre.w;
    sum = float(k) * centre.rgb;
    specular = float(k) * specularOfKey(key);
    for (int dx = -reach; dx <= reach; ++dx) {
      if (dx == 0) continue;
      ivec2 s = q + ivec2(dx, 0);
      vec4 sample_ = texelFetch(vplIndirect, s, 0);
      uvec4 sKey = texelFetch(vplSurfaceKey, s, 0);
      if (!sampleOnSurface(s, sample_, sKey, normal, position, kChainNormalCos, tolerance)) {
        whole = false;
        break;
      }
      float w = float(k - abs(dx));
      sum += w * sample_.rgb;
      specular += w * specularOfKey(sKey);
    }
  }
  imageStore(vplRowSums, q,
             whole ? uvec4(packHalf2x16(sum.rg), packHalf2x16(vec2(sum.b, specular.r)),
                           packHalf2x16(specular.gb), 1u)
                   : uvec4(0u));
}
