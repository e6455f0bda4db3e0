// Rebuilding a pixel's surface from the visibility buffer (render/visibility.h) in a compute pass:
// the id gives the surface record (primitive, instance) and the triangle; the triangle's three
// vertices are fetched and transformed, barycentrics come from intersecting the pixel's ray with
// the triangle (perspective-correct by construction), and the rays through the next pixel right
// and down give the derivatives that texture filtering and normal mapping need. The material is
// sampled with explicit gradients from one texture table (GpuScene::textureTable, set 1).
//
// Workgroups must be kVisibilityGroupSize x kVisibilityGroupSize and every invocation must call
// rebuildSurface (its material loop has barriers).
#ifndef LLL_VISIBILITY_SURFACE_GLSL
#define LLL_VISIBILITY_SURFACE_GLSL
#extension GL_EXT_control_flow_attributes : enable
#ifdef LLL_NONUNIFORM_TEXTURES
#extension GL_EXT_nonuniform_qualifier : require
#endif
#include "common/gbuffer.glsl"
#include "common/material_surface.glsl"

layout(constant_id = 20) const uint kTriangleBits = 16u;
layout(constant_id = 21) const uint kTextureCount = 2u;
// True on lavapipe, whose LLVM (Mesa 22.3) cannot compile textureGrad on an indexed sampler array
// ("Cannot emit physreg copy instruction"): there the level of detail is computed here as
// Vulkan's sampler defines it. Elsewhere textureGrad lets the texture unit pick it exactly as it
// does for a fragment shader (GPUs approximate the definition; the forward reference is drawn
// by fragments).
layout(constant_id = 22) const bool kComputedLevelOfDetail = false;

layout(std430, set = 0, binding = 16) readonly buffer SurfaceRecordBlock {
  SurfaceRecord surfaceRecords[];
};
layout(std430, set = 0, binding = 17) readonly buffer InstanceBlock {
  MeshInstance meshInstances[];
};
// lll::Vertex: position xyz, normal xyz, uv, tangent xyzw, uv1 (floats), colour as four half
// floats: 16 words, read as bits (a pair of halves can be a denormal float, which a float load
// might flush).
layout(std430, set = 0, binding = 18) readonly buffer VertexBlock {
  uint vertexData[];
};
layout(std430, set = 0, binding = 19) readonly buffer IndexBlock {
  uint sceneIndices[];
};
layout(set = 0, binding = 20, r32ui) uniform readonly uimage2D visibilityImage;
layout(set = 1, binding = 0) uniform sampler2D sceneTextures[kTextureCount];

const uint kVisibilityGroupSize = 8u;

// Whether any vertex of the scene has TEXCOORD_1 that a material reads, or a colour (COLOR_0)
// other than white (VisibilityBuffer::surfaceConstants): a pass that sets them false neither
// fetches nor interpolates them.
layout(constant_id = 23) const bool kSceneHasSecondTexCoords = true;
layout(constant_id = 24) const bool kSceneHasVertexColors = true;
// Whether a material of the scene has a texture transform (KHR_texture_transform): false compiles
// the transforms out of the rebuild (ThreeL's opaque shading on the H200, with the link format
// compiled in too: 0.216 -> 0.209 ms, registers 64 -> 56; bench/README.md, 2026-12-05 second).
layout(constant_id = 25) const bool kSceneHasTextureTransforms = true;

struct TriangleVertex {
  vec3 position;
  vec3 normal;
  vec2 uv;
  vec4 tangent;
  vec2 uv1;
  vec4 color;
};

float vertexFloat(uint word) {
  return uintBitsToFloat(vertexData[word]);
}

TriangleVertex fetchVertex(uint index) {
  uint b = index * 16u;
  TriangleVertex v;
  v.position = vec3(vertexFloat(b), vertexFloat(b + 1u), vertexFloat(b + 2u));
  v.normal = vec3(vertexFloat(b + 3u), vertexFloat(b + 4u), vertexFloat(b + 5u));
  v.uv = vec2(vertexFloat(b + 6u), vertexFloat(b + 7u));
  v.tangent = vec4(vertexFloat(b + 8u), vertexFloat(b + 9u), vertexFloat(b + 10u), vertexFloat(b + 11u));
  v.uv1 = kSceneHasSecondTexCoords ? vec2(vertexFloat(b + 12u), vertexFloat(b + 13u)) : vec2(0.0);
  v.color = kSceneHasVertexColors
                ? vec4(unpackHalf2x16(vertexData[b + 14u]), unpackHalf2x16(vertexData[b + 15u]))
                : vec4(1.0);
  return v;
}

// The ray through a point of the image (in pixels, y down), scaled to unit view depth: the hit at
// ray parameter t lies at linear depth t.
vec3 pixelRay(vec2 fragCoord) {
  return reconstructPosition(fragCoord, 1.0) - frame.cameraPosition.xyz;
}

// What the barycentrics of every ray against one triangle share: with the hit h relative to p0,
// the barycentric of p1 is n . (h x e2) / |n|^2 = h . (e2 x n) / |n|^2 and that of p2
// n . (e1 x h) / |n|^2 = h . (n x e1) / |n|^2, so each is one dot product with a vector made once.
struct TriangleRays {
  vec3 n;          // e1 x e2
  vec3 fromEye;    // p0 - the camera
  float distance;  // n . fromEye
  vec3 toB1, toB2;
};

TriangleRays triangleRays(vec3 p0, vec3 e1, vec3 e2) {
  TriangleRays r;
  r.n = cross(e1, e2);
  r.fromEye = p0 - frame.cameraPosition.xyz;
  r.distance = dot(r.fromEye, r.n);
  float inverseArea2 = 1.0 / max(dot(r.n, r.n), 1e-37);
  r.toB1 = cross(e2, r.n) * inverseArea2;
  r.toB2 = cross(r.n, e1) * inverseArea2;
  return r;
}

// Barycentrics (of p1 and p2) where `ray` from the eye meets the triangle's plane, and the ray
// parameter there.
vec3 rayBarycentrics(TriangleRays r, vec3 ray) {
  float along = dot(ray, r.n);
  float t = abs(along) > 1e-30 ? r.distance / along : 0.0;
  vec3 hit = t * ray - r.fromEye;
  return vec3(dot(hit, r.toB1), dot(hit, r.toB2), t);
}

// The geometry of the surface a pixel's id names.
struct SurfaceGeometry {
  vec3 position;
  vec3 normal;
  vec4 tangent;
  vec2 uv;
  SurfaceDerivatives d;
  vec2 uv1, duv1x, duv1y;  // TEXCOORD_1 and its derivatives
  vec4 color;              // COLOR_0
  bool frontFacing;
  float viewDepth;
};

SurfaceGeometry surfaceGeometry(uvec2 pixel, SurfaceRecord record, uint triangle) {
  MeshInstance instance = meshInstances[record.instance];
  uint first = record.firstIndex + 3u * triangle;
  TriangleVertex v0 = fetchVertex(sceneIndices[first] + record.vertexOffset);
  TriangleVertex v1 = fetchVertex(sceneIndices[first + 1u] + record.vertexOffset);
  TriangleVertex v2 = fetchVertex(sceneIndices[first + 2u] + record.vertexOffset);
  vec3 p0 = (instance.model * vec4(v0.position, 1.0)).xyz;
  vec3 e1 = (instance.model * vec4(v1.position, 1.0)).xyz - p0;
  vec3 e2 = (instance.model * vec4(v2.position, 1.0)).xyz - p0;
  TriangleRays rays = triangleRays(p0, e1, e2);  // n counter-clockwise: the rasterizer's front

  // Derivatives as a rasterizer takes them: across the pixel's 2x2 quad, right column minus left
  // and bottom row minus top, so texture levels of detail match a fragment shader's.
  vec2 center = vec2(pixel) + 0.5;
  vec2 side = vec2((pixel.x & 1u) == 0u ? 1.0 : -1.0, (pixel.y & 1u) == 0u ? 1.0 : -1.0);
  vec3 b = rayBarycentrics(rays, pixelRay(center));
  vec3 bx = rayBarycentrics(rays, pixelRay(center + vec2(side.x, 0.0)));
  vec3 by = rayBarycentrics(rays, pixelRay(center + vec2(0.0, side.y)));
  vec2 dbx = (bx.xy - b.xy) * side.x, dby = (by.xy - b.xy) * side.y;
  SurfaceGeometry g;
  g.position = p0 + b.x * e1 + b.y * e2;
  g.viewDepth = b.z;
  g.d.dpx = dbx.x * e1 + dbx.y * e2;
  g.d.dpy = dby.x * e1 + dby.y * e2;
  vec2 du1 = v1.uv - v0.uv, du2 = v2.uv - v0.uv;
  g.d.duvx = dbx.x * du1 + dbx.y * du2;
  g.d.duvy = dby.x * du1 + dby.y * du2;
  g.uv = v0.uv + b.x * du1 + b.y * du2;
  vec2 dv1 = v1.uv1 - v0.uv1, dv2 = v2.uv1 - v0.uv1;
  g.duv1x = dbx.x * dv1 + dbx.y * dv2;
  g.duv1y = dby.x * dv1 + dby.y * dv2;
  g.uv1 = v0.uv1 + b.x * dv1 + b.y * dv2;
  g.color = v0.color + b.x * (v1.color - v0.color) + b.y * (v2.color - v0.color);
  float w0 = 1.0 - b.x - b.y;
  mat3 normalMatrix =
      mat3(instance.normalMatrix[0].xyz, instance.normalMatrix[1].xyz, instance.normalMatrix[2].xyz);
  g.normal = normalMatrix * (w0 * v0.normal + b.x * v1.normal + b.y * v2.normal);
  mat3 linear = mat3(instance.model);
  vec3 objectTangent = w0 * v0.tangent.xyz + b.x * v1.tangent.xyz + b.y * v2.tangent.xyz;
  // A primitive's vertices all have tangents (w = +-1 each) or none do (w = 0); a mirroring
  // transform turns the bitangent (normalMatrix[0].w: the sign of the model's determinant).
  g.tangent = vec4(linear * objectTangent, v0.tangent.w * instance.normalMatrix[0].w);
  g.frontFacing = rays.distance < 0.0;  // n . (camera - p0) > 0
  return g;
}

#ifdef LLL_NONUNIFORM_TEXTURES
// Any index: the device samples a sampler array with indices that differ between invocations
// (Context::nonUniformTextureFeatures; the shaders' _nonuniform variants).
#define TEXTURE_TABLE(index) sceneTextures[nonuniformEXT(index)]
#else
shared uint visibilityNextMaterial;
// The index must be uniform across the workgroup.
#define TEXTURE_TABLE(index) sceneTextures[index]
#endif

// A texture of the table with these gradients.
vec4 sampleTextureTable(uint index, vec2 uv, SurfaceDerivatives d) {
  if (!kComputedLevelOfDetail) return textureGrad(TEXTURE_TABLE(index), uv, d.duvx, d.duvy);
  // Vulkan's isotropic level of detail: the longer of the two gradients, in texels.
  vec2 size = vec2(textureSize(TEXTURE_TABLE(index), 0));
  vec2 dx = d.duvx * size, dy = d.duvy * size;
  float lod = 0.5 * log2(max(max(dot(dx, dx), dot(dy, dy)), 1e-20));
  return textureLod(TEXTURE_TABLE(index), uv, lod);
}

// Texture `slot` of material `m` (texture table entry `index`) at the surface's texture coordinates
// (`g`: its TEXCOORD_0 or TEXCOORD_1), through its KHR_texture_transform (explicit gradients: the
// tests of the material's flags cost no helper invocation here).
vec4 sampleMaterialTexture(GpuMaterial m, uint slot, uint index, SurfaceGeometry g) {
  bool second = kSceneHasSecondTexCoords && usesSecondTexCoord(m, slot);
  vec2 uv = second ? g.uv1 : g.uv;
  SurfaceDerivatives d = g.d;
  if (second) {
    d.duvx = g.duv1x;
    d.duvy = g.duv1y;
  }
  if (kSceneHasTextureTransforms && hasTextureTransform(m)) {
    uv = textureCoordinates(m, slot, uv);
    d.duvx = textureCoordinatesDerivative(m, slot, d.duvx);
    d.duvy = textureCoordinatesDerivative(m, slot, d.duvy);
  }
  return sampleTextureTable(index, uv, d);
}

// The textures material `m` has at the surface; `t` keeps what the 1x1 stand-ins of the others
// would give (white, the flat normal).
void sampleMaterial(GpuMaterial m, SurfaceGeometry g, inout MaterialSamples t) {
  uint has = m.flags.z;
  if ((has & kMaterialBaseColorTexture) != 0u) t.baseColor = sampleMaterialTexture(m, 0u, m.textures.x, g);
  if ((has & kMaterialMetallicRoughnessTexture) != 0u)
    t.metallicRoughness = sampleMaterialTexture(m, 1u, m.textures.y, g);
  if ((has & kMaterialNormalTexture) != 0u) t.normal = sampleMaterialTexture(m, 2u, m.textures.z, g).xyz;
  if ((has & kMaterialEmissiveTexture) != 0u) t.emissive = sampleMaterialTexture(m, 3u, m.textures.w, g).rgb;
  if ((has & kMaterialOcclusionTexture) != 0u) t.occlusion = sampleMaterialTexture(m, 4u, m.flags.w, g).r;
}

// The surface at `pixel`, or false where the visibility pass drew nothing (or `inside` is false:
// the workgroup's invocations beyond the image, which must call this too). `viewDepth` is the
// linear depth of the rebuilt point.
bool rebuildSurface(uvec2 pixel, bool inside, out Surface s, out float viewDepth) {
  uint id = inside ? imageLoad(visibilityImage, ivec2(pixel)).r : kNoSurface;
  bool covered = id != kNoSurface;
  SurfaceRecord record = SurfaceRecord(0u, 0u, 0u, 0u);
  SurfaceGeometry g;
  g.position = frame.cameraPosition.xyz;
  g.normal = vec3(0.0, 0.0, 1.0);
  g.tangent = vec4(0.0);
  g.uv = vec2(0.0);
  g.d = SurfaceDerivatives(vec3(0.0), vec3(0.0), vec2(0.0), vec2(0.0));
  g.uv1 = g.duv1x = g.duv1y = vec2(0.0);
  g.color = vec4(1.0);
  g.frontFacing = true;
  g.viewDepth = 0.0;
  if (covered) {
    record = surfaceRecords[id >> kTriangleBits];
    g = surfaceGeometry(pixel, record, id & ((1u << kTriangleBits) - 1u));
  }
  viewDepth = g.viewDepth;
  SurfaceDerivatives d = g.d;

  // Levels of detail come from the rays' derivatives: in compute there are no quads.
  GpuMaterial m = materials[record.material];
  MaterialSamples t;
  t.baseColor = vec4(1.0);
  t.metallicRoughness = vec4(1.0);
  t.normal = vec3(0.5, 0.5, 1.0);
  t.emissive = vec3(1.0);
  t.occlusion = 1.0;
#ifdef LLL_NONUNIFORM_TEXTURES
  if (covered) sampleMaterial(m, g, t);
#else
  // Without non-uniform indexing (lavapipe), a loop over the materials the workgroup sees: each
  // round takes the smallest material not yet done, so the texture index is the same for the
  // whole workgroup (a subgroup-uniform index is not enough by the spec). On the H200 (1080p)
  // the non-uniform path shades ThreeL's 16 lights in 0.237 ms against this loop's 0.242 (forward
  // 0.173 against 0.183, the atrium + 1,024 lights with lll 0.478 against 0.488).
  uint mine = covered ? record.material : 0xFFFFFFFFu;
  for (;;) {
    if (gl_LocalInvocationIndex == 0u) visibilityNextMaterial = 0xFFFFFFFFu;
    barrier();
    if (mine != 0xFFFFFFFFu) atomicMin(visibilityNextMaterial, mine);
    barrier();
    uint chosen = visibilityNextMaterial;
    barrier();
    if (chosen == 0xFFFFFFFFu) break;
    if (mine == chosen) {
      sampleMaterial(materials[chosen], g, t);
      mine = 0xFFFFFFFFu;
    }
  }
#endif
  // The derivative tangent frame follows the normal texture's coordinates (material.glsl).
  if (kSceneHasSecondTexCoords && usesSecondTexCoord(m, 2u)) {
    d.duvx = g.duv1x;
    d.duvy = g.duv1y;
  }
  if (kSceneHasTextureTransforms && hasTextureTransform(m)) {
    d.duvx = textureCoordinatesDerivative(m, 2u, d.duvx);
    d.duvy = textureCoordinatesDerivative(m, 2u, d.duvy);
  }
  t.baseColor *= g.color;
  s = assembleSurface(m, t, g.position, g.normal, g.tangent, d, g.frontFacing);
  return covered;
}

#endif
