// Shadow maps: the sun's cascades and the local lights' views, as the passes that light surfaces
// read them (common/sun_shadow.glsl, common/local_shadow.glsl) and src/shadows/ fits them. Written once here;
// see shared.h for the rules.
#ifndef LLL_SHADOW_TYPES_H
#define LLL_SHADOW_TYPES_H
#include "shared/shared.h"

LLL_NAMESPACE_BEGIN

LLL_CONST(uint, kMaxCascades, 4u);
// Cascades sit in the shadow atlas in rows of this many cells, each shadowResolution square.
LLL_CONST(uint, kCascadeColumns, 2u);
// Lookup biases of every shadow map (SunShadow::bias, LocalShadowView::params): the normal offset in
// texels, the slope bias in texels per unit of tan(theta) (2: the PCF taps reach the surface up to
// 2 texels away, whose depth differs by that much).
LLL_CONST(float, kShadowNormalOffsetTexels, 1.0f);
LLL_CONST(float, kShadowSlopeBiasTexels, 2.0f);
// The most local lights (--shadow-lights) that may cast each frame.
LLL_CONST(uint, kMaxShadowLights, 1024u);
LLL_CONST(uint, kShadowFilterNone, 0u);  // one texel, nearest: edges where geometry puts them
LLL_CONST(uint, kShadowFilterPcf, 1u);   // 3x3 bilinear comparisons: a 4x4-texel tent

struct SunShadow {
  // World to a cascade's light clip space: x, y in [-1, 1] across its square, z in [0, 1] from the
  // scene's nearest point towards the sun to its farthest.
  mat4 cascadeViewProj[kMaxCascades];
  vec4 splits;      // view depth (along the camera axis) where each cascade ends
  vec4 texelWorld;  // the world size of one texel of each cascade
  vec4 bias;        // x normal offset (texels), y slope bias (texels of depth per unit tan(theta)),
                    // z constant bias (world units), w world units per unit of shadow depth
  vec4 atlas;       // x 1 / resolution, y resolution, z 1 / columns, w 1 / rows
  uvec4 config;     // x cascades in use (0: the sun casts no shadow), y unused, z kShadowFilter*,
                    // w unused. The frame's first directional light casts it (the renderer puts the
                    // brightest first).
};
LLL_CHECK_SIZE(SunShadow, kMaxCascades * 64 + 5 * 16);

// One view a local light's shadow is drawn from (src/shadows/local_shadows.h): a spot light's
// cone, or one face of a point light's cube, in its cell of the local shadow atlas.
struct LocalShadowView {
  mat4 viewProj;  // world to the view's clip space: reverse depth (1 at the near plane), y down
  vec4 cell;      // xy the cell's corner in atlas uv, zw its size in atlas uv
  vec4 params;    // x the world size of a texel per unit of distance from the light, y normal offset
                  // (texels), z slope bias (texels per unit of tan(theta)), w 1 / texels along a side
  uvec4 config;   // x kShadowFilter*, yzw unused
};
LLL_CHECK_SIZE(LocalShadowView, 64 + 3 * 16);

// One view the shadow casters' compute rasterizer draws (src/shadows/shadow_raster.h): a sun
// cascade or a local light's view, and its cell of the atlas. The views buffer holds a uvec4 header
// (x views, y atlas width, z atlas height) and then the views.
struct ShadowRasterView {
  mat4 viewProj;  // world to the view's clip space
  vec4 reach;     // xyz the light's position, w its range: triangles beyond it are skipped; w 0: none
  uvec4 cell;     // xy the cell's first texel, z its side in texels
};
LLL_CHECK_SIZE(ShadowRasterView, 96);

// The shadow caster pass's push constants: the draw's (DrawPush) and the view being drawn.
struct CasterPush {
  uvec4 ids;      // x material index, yzw unused (as DrawPush)
  mat4 viewProj;  // world to the view's clip space, for a viewport over its cell of the atlas
};
LLL_CHECK_SIZE(CasterPush, 80);

LLL_NAMESPACE_END
#endif
