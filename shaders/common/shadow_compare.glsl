// Depth comparisons in a shadow atlas, by hand: the atlases are sampled as plain float textures
// (src/shadows/shadow_atlas.h), a D32 image where the hardware draws the casters and an R32F one
// that the compute rasterizer writes directly (a copy into a depth image cost more than the
// drawing on the H200). Reverse depth: a point is lit where its depth is >= the stored one.
#ifndef LLL_SHADOW_COMPARE_GLSL
#define LLL_SHADOW_COMPARE_GLSL

// Percentage-closer filtering at atlas uv `at`: the four texels around it compared with `depth`,
// blended bilinearly (as a linear comparison sampler does). The gather is taken at the corner its
// four texels share, so the texels it returns are the ones the weights are for, whatever the
// sampler's sub-texel precision.
float shadowCompareLinear(sampler2D atlas, vec2 at, float depth) {
  vec2 size = vec2(textureSize(atlas, 0));
  vec2 t = at * size - 0.5;
  vec2 base = floor(t);
  vec2 f = t - base;
  // x (u0, v1), y (u1, v1), z (u1, v0), w (u0, v0)
  vec4 lit = step(textureGather(atlas, (base + 1.0) / size, 0), vec4(depth));
  return mix(mix(lit.w, lit.z, f.x), mix(lit.x, lit.y, f.x), f.y);
}

// The comparison with the one texel holding atlas uv `at` (no filtering).
float shadowCompareTexel(sampler2D atlas, vec2 at, float depth) {
  ivec2 size = textureSize(atlas, 0);
  ivec2 texel = clamp(ivec2(floor(at * vec2(size))), ivec2(0), size - 1);
  return depth >= texelFetch(atlas, texel, 0).r ? 1.0 : 0.0;
}

#endif
