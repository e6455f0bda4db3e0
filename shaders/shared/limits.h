// Every fixed limit of lll in one place, shared by C++ and GLSL, each with its reason.
#ifndef LLL_LIMITS_H
#define LLL_LIMITS_H
#include "shared/shared.h"

LLL_NAMESPACE_BEGIN

// Compact 8-byte links keep the light index in 8 bits (Bezrati 1.2.2): beyond this many lights
// the 16-byte wide link is used.
LLL_CONST(uint, kCompactLinkMaxLights, 256u);
// Light records a uniform block holds (--lll-records uniform): 256 of 64 bytes, 16 KiB, the
// smallest maxUniformBufferRange Vulkan allows.
LLL_CONST(uint, kUniformLightRecords, 256u);
// Compact links keep "next" in 24 bits; 0xFFFFFF marks the end of a list.
LLL_CONST(uint, kCompactLinkEnd, 0xFFFFFFu);
LLL_CONST(uint, kLinkEnd, 0xFFFFFFFFu);
// lavapipe caps storage buffers at 128 MiB; the link pool is one storage buffer.
LLL_CONST(uint, kMaxStorageBufferBytes, 128u * 1024u * 1024u);
// The most lights a scene may hold: 16,777,216 (a 1 GiB light array of 64-byte lights). Where a
// device's largest storage buffer holds fewer (lavapipe: 128 MiB, 2,097,152 lights) the renderer
// refuses with the count that fits (requireStorageBufferFits).
LLL_CONST(uint, kMaxLights, 1u << 24);
// --vpl-interleave: the largest side of the interleaving pattern (render/interleaved_vpls.h).
LLL_CONST(uint, kMaxVplInterleave, 4u);
// 2D compute passes (linear depth, tonemap, tile reduction) use 8x8 groups: 64 invocations is a
// multiple of every subgroup size we meet (8 on lavapipe, 32 on NVIDIA).
LLL_CONST(uint, kTileGroupSize, 8u);
// Largest supported tile: the tile-depth reduction walks a tile with one 8x8 group.
LLL_CONST(uint, kMaxTileSize, 16u);
// Largest render target side; keeps every per-pixel buffer under the storage buffer cap.
LLL_CONST(uint, kMaxImageSide, 8192u);
// Light types, stored in GpuLight.directionType.w.
LLL_CONST(uint, kLightPoint, 0u);
LLL_CONST(uint, kLightSpot, 1u);
LLL_CONST(uint, kLightBox, 2u);
LLL_CONST(uint, kLightVpl, 3u);
// Directional lights (the sun, KHR_lights_punctual "directional") light every pixel and never
// enter the light lists: they travel in the frame's uniforms, this many at most.
LLL_CONST(uint, kMaxDirectionalLights, 4u);
// Material alpha modes, stored in GpuMaterial.flags.
LLL_CONST(uint, kAlphaOpaque, 0u);
LLL_CONST(uint, kAlphaMask, 1u);
LLL_CONST(uint, kAlphaBlend, 2u);
// The visibility buffer's value where no surface was drawn (a pixel id is a record index shifted
// over the triangle bits, or'ed with the triangle: never all ones while records fit).
LLL_CONST(uint, kNoSurface, 0xFFFFFFFFu);
// GpuMaterial.flags.z bits: which of the material's textures the file gave (the others are bound
// to 1x1 stand-ins: white, or the flat normal).
LLL_CONST(uint, kMaterialNormalTexture, 1u);
LLL_CONST(uint, kMaterialBaseColorTexture, 2u);
LLL_CONST(uint, kMaterialMetallicRoughnessTexture, 4u);
LLL_CONST(uint, kMaterialEmissiveTexture, 8u);
LLL_CONST(uint, kMaterialOcclusionTexture, 16u);
// GpuMaterial.flags.z: some texture of the material has a KHR_texture_transform.
LLL_CONST(uint, kMaterialTextureTransform, 256u);
// GpuMaterial.flags.z: bit kMaterialSecondTexCoord << slot (common/texture_transform.glsl's slots)
// where that texture reads TEXCOORD_1.
LLL_CONST(uint, kMaterialSecondTexCoord, 512u);

// FrameUniforms.display.x: how the tonemap pass treats the HDR image.
LLL_CONST(uint, kDisplayFilmic, 0u);
LLL_CONST(uint, kDisplayDebug, 1u);

LLL_NAMESPACE_END
#endif
