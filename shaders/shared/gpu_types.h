// Structs read by both the C++ host code and GLSL. Written once here; see shared.h for the rules.
#ifndef LLL_GPU_TYPES_H
#define LLL_GPU_TYPES_H
#include "shared/limits.h"

LLL_NAMESPACE_BEGIN

// One punctual light (KHR_lights_punctual), in world space.
struct GpuLight {
  vec4 positionRange;   // xyz position, w range (distance where the light is cut off; a box's
                        // bounding radius)
  vec4 colorIntensity;  // rgb linear colour, w intensity (candela)
  vec4 directionType;   // xyz spot: direction it points to (unit); box: its x axis over its half
                        // extent; w kLightPoint, kLightSpot or kLightBox
  vec4 spotParams;      // spot: x cos(outer cone), y cos(inner cone), z 1 / (y - x); spot and point: w
                        // the light's shadow views this frame (common/local_shadow.glsl; 0: none)
                        // VPL: x its near distance (the 1/d^2 clamp), y z the reciprocals of its hierarchy
                        // band's inner and outer radius (0: none; common/brdf.glsl); directionType.xyz
                        // its normal
                        // box: xyz its y axis over its half extent, w hx * hy / hz (so that
                        // cross(x, y) * w is its z axis over its half extent)
};
LLL_CHECK_SIZE(GpuLight, 64);

// A moving light's motion (scene/light_animation.h) as the GPU evaluates it each frame
// (render/moving_lights.h): position(t) = centre + (r cos 2 pi o, h sin 2 pi b, r sin 2 pi o), with
// o = orbit's turns a second x t + its phase in turns, b the same for the bob. A speed is split in
// two floats, the first of 12 significant bits, so that its product with the time (split alike)
// stays exact where it must: w t reaches 13,750 turns at a day's seconds.
struct GpuLightMotion {
  vec4 centerRadius;  // xyz the orbit's centre at the bob's middle height, w the orbit's radius
  vec4 orbit;         // x, y turns a second (x + y, x of 12 significant bits), z phase in turns, w unused
  vec4 bob;           // x, y the bob's frequency (split as orbit's), z phase in turns, w amplitude
};
LLL_CHECK_SIZE(GpuLightMotion, 48);

// Per-frame constants: camera, viewport and light count.
struct FrameUniforms {
  mat4 view;
  mat4 proj;
  mat4 viewProj;
  mat4 invViewProj;
  vec4 cameraPosition;  // xyz world, w unused
  vec4 viewport;        // width, height, 1/width, 1/height
  vec4 depthParams;     // near, far, tan(fovy/2) * aspect, tan(fovy/2)
  uvec4 counts;         // x light count, y tile size, z tiles x, w tiles y
  vec4 ambient;         // rgb constant ambient radiance, w exposure
  uvec4 display;        // x kDisplayFilmic or kDisplayDebug (skips the filmic curve), y heatmap scale,
                        // z directional lights in use, w the first of the VPLs that end the light
                        // array (the light count without): --vpl-interleave classes them by index
  vec4 sunDirection[kMaxDirectionalLights];    // xyz unit, towards the light; w unused
  vec4 sunIlluminance[kMaxDirectionalLights];  // rgb colour x illuminance (lux); w unused
};
LLL_CHECK_SIZE(FrameUniforms, 4 * 64 + 6 * 16 + 2 * 4 * 16);

// A metallic-roughness material (glTF 2.0).
struct GpuMaterial {
  vec4 baseColorFactor;
  vec4 emissive;   // rgb emissive factor * KHR_materials_emissive_strength, w unused
  vec4 params;     // x metallic, y roughness, z normal scale, w occlusion strength
  uvec4 flags;     // x alpha mode, y double sided, z kMaterial* bits, w occlusion texture
  vec4 alpha;      // x alpha cutoff, yzw unused
  uvec4 textures;  // in GpuScene's texture table (the visibility path): x base colour,
                   // y metallic-roughness, z normal, w emissive; flags.w the occlusion texture
  // KHR_texture_transform per texture (base colour, metallic-roughness, normal, emissive,
  // occlusion), read where flags.z has kMaterialTextureTransform: uv' = mat2(m.xy, m.zw) uv +
  // offset, the offsets two to a vec4 (texture 2i in xy, 2i + 1 in zw).
  vec4 uvMatrix[5];
  vec4 uvOffset[3];
};
LLL_CHECK_SIZE(GpuMaterial, 96 + 8 * 16);

// One placed copy of a mesh (a glTF node), read by the mesh vertex shader through the frame's draw
// order: a draw of a primitive covers every visible instance of its mesh.
struct MeshInstance {
  mat4 model;            // object to world
  vec4 normalMatrix[3];  // xyz: columns of the inverse transpose of model's 3x3 (its cofactors
                         // when singular), computed on the CPU in double precision; [0].w the
                         // sign of model's determinant (-1 mirrors, else 1), [1].w and [2].w 0
};
LLL_CHECK_SIZE(MeshInstance, 112);

// One (primitive, instance) pair the visibility pass drew this frame: what a compute pass needs to
// rebuild a pixel's surface from its id (render/visibility.h).
struct SurfaceRecord {
  uint firstIndex;    // the primitive's first index in the scene's index buffer
  uint vertexOffset;  // added to each of its indices
  uint material;
  uint instance;  // the instance's place in the frame's instance buffer (GpuScene::prepareFrame)
};
LLL_CHECK_SIZE(SurfaceRecord, 16);

// The visibility pass's push constants. Alpha-masked primitives are drawn one by one: x their first
// record, y their material. Opaque ones in indirect multi-draws: z the call's first command, whose
// record bases the vertex shader reads at z + gl_DrawID.
struct VisibilityPush {
  uvec4 ids;  // x first record, y material, z first command, w unused
};
LLL_CHECK_SIZE(VisibilityPush, 16);

// The compute rasterizer's push constants (render/compute_raster.h).
struct RasterPush {
  uvec4 counts;  // x triangles this frame, y opaque records, z of them single-sided (the first ones),
                 // w workgroups per row of the dispatch
  uvec4 large;   // x capacity of the large-triangle list, y largest bounding box (pixels) rasterized
                 // by one thread, z bins per row, w entries per bin
};
LLL_CHECK_SIZE(RasterPush, 32);

// A triangle whose bounding box is too large for one thread: the per-pixel pass tests it. Vertices
// snapped to 1/256 pixel and ordered so that the inside is positive; depth is z/w at each vertex.
struct RasterTriangle {
  ivec4 v01;     // x0 y0 x1 y1
  ivec4 v2;      // x2 y2, z the pixel id, w: bit k set when edge k (v1v2, v2v0, v0v1) is top or left
  vec4 depth;    // z0 z1 z2, w unused
  ivec4 bounds;  // first and last pixel covered: x0 y0 x1 y1
};
LLL_CHECK_SIZE(RasterTriangle, 64);

// Per-draw push constants of every mesh pass.
struct DrawPush {
  uvec4 ids;  // x material index, yzw unused
};
LLL_CHECK_SIZE(DrawPush, 16);

LLL_NAMESPACE_END
#endif
