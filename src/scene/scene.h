#pragma once
// The scene as the renderer sees it: one vertex and index array, meshes made of primitives,
// instances placing meshes in the world (the glTF node hierarchy already flattened), materials,
// textures, punctual lights and named cameras. Loaders (glTF, built-in scenes) fill it; the GPU
// layer uploads it; techniques only read it.
#include <array>
#include <cmath>
#include <compare>
#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/vertex.h"

namespace lll {

enum class AlphaMode : uint32_t { Opaque = 0, Mask = 1, Blend = 2 };

// glTF's sampler of a texture: how coordinates outside [0, 1] wrap and how texels are filtered
// when the texture is magnified and minified. The default is glTF's repeat with trilinear
// filtering (the renderer's choice where a file leaves filters undefined).
enum class TextureWrap : uint8_t { Repeat, ClampToEdge, MirroredRepeat };
enum class TextureFilter : uint8_t { Linear, Nearest };
// How a minified texture's mip levels are used: blended between the two nearest, the nearest one,
// or none (the base level only, glTF's NEAREST and LINEAR minification filters).
enum class MipFilter : uint8_t { Linear, Nearest, None };
struct TextureSampler {
  TextureWrap wrapU = TextureWrap::Repeat;
  TextureWrap wrapV = TextureWrap::Repeat;
  TextureFilter magnify = TextureFilter::Linear;
  TextureFilter minify = TextureFilter::Linear;
  MipFilter mip = MipFilter::Linear;
  bool operator==(const TextureSampler&) const = default;
  auto operator<=>(const TextureSampler&) const = default;
};

// Decoded 8-bit RGBA pixels; colour textures are sRGB-encoded, data textures linear.
struct Texture {
  std::string name;  // where it came from, for messages
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<uint8_t> rgba;  // width * height * 4
  bool srgb = false;
  TextureSampler sampler;
};

// KHR_texture_transform of one of a material's textures: the texture is sampled at
// offset + rotate(rotation) (scale * uv), glTF's Translation x Rotation x Scale, the rotation
// (radians) turning u towards -v, as the extension defines it.
struct TextureTransform {
  glm::vec2 offset{0.0f};
  float rotation = 0.0f;
  glm::vec2 scale{1.0f};
  bool identity() const { return offset == glm::vec2(0.0f) && rotation == 0.0f && scale == glm::vec2(1.0f); }
  // The 2x2 part as glm's column-major matrix: uv' = linear() * uv + offset.
  glm::mat2 linear() const {
    const float c = std::cos(rotation), s = std::sin(rotation);
    return glm::mat2(glm::vec2(c * scale.x, -s * scale.x), glm::vec2(s * scale.y, c * scale.y));
  }
  glm::vec2 apply(glm::vec2 uv) const {
    return rotation == 0.0f ? scale * uv + offset : linear() * uv + offset;
  }
};

// A material's texture slots, in the order of Material::transforms and GpuMaterial's arrays.
enum TextureSlot : uint32_t {
  kBaseColorSlot = 0,
  kMetallicRoughnessSlot,
  kNormalSlot,
  kEmissiveSlot,
  kOcclusionSlot,
  kTextureSlots
};

struct Material {
  std::string name;
  glm::vec4 baseColorFactor{1.0f};
  glm::vec3 emissiveFactor{0.0f};
  float emissiveStrength = 1.0f;  // KHR_materials_emissive_strength
  float metallic = 1.0f;
  float roughness = 1.0f;
  float normalScale = 1.0f;
  float occlusionStrength = 1.0f;
  float alphaCutoff = 0.5f;
  AlphaMode alphaMode = AlphaMode::Opaque;
  bool doubleSided = false;
  // Indices into Scene::textures, -1 when absent.
  int baseColorTexture = -1;
  int metallicRoughnessTexture = -1;
  int normalTexture = -1;
  int emissiveTexture = -1;
  int occlusionTexture = -1;
  // KHR_texture_transform of each slot (TextureSlot order).
  std::array<TextureTransform, kTextureSlots> transforms{};
  // Which texture coordinates each slot reads: 0 for TEXCOORD_0, 1 for TEXCOORD_1.
  std::array<uint8_t, kTextureSlots> texCoords{};

  // The texture of `slot` (an index into Scene::textures, -1 when absent).
  int texture(TextureSlot slot) const {
    const int slots[kTextureSlots] = {baseColorTexture, metallicRoughnessTexture, normalTexture,
                                      emissiveTexture, occlusionTexture};
    return slots[slot];
  }
};

// A contiguous run of triangles with one material. vertexOffset is added to every index.
struct Primitive {
  uint32_t firstIndex = 0;
  uint32_t indexCount = 0;
  uint32_t vertexOffset = 0;
  uint32_t material = 0;
};

struct Mesh {
  std::string name;
  std::vector<Primitive> primitives;
};

// Front faces are the triangles that wind counter-clockwise on screen after `transform`, as the
// rasterizer sees them, also where the transform mirrors (a negative determinant turns the mesh's
// fronts away). glTF instead lets a mirroring node's determinant flip the winding: its loader
// places such a node's mesh as the mesh's reversed copy (addReversedWindingMesh).
struct Instance {
  uint32_t mesh = 0;
  glm::mat4 transform{1.0f};  // object to world
};

// Point and Spot as KHR_lights_punctual. Box: Bezrati's box-shaped light volume (the chapter draws
// area lights as boxes): a point emitter at the box's centre whose influence is bounded by an
// oriented box instead of a sphere, fading smoothly to zero at the box's faces (brdf.glsl).
// Vpl: a virtual point light of instant radiosity (gi/photons.h): a Lambertian emitter, intensity
// times the cosine about `direction` (the surface normal it was deposited on), its 1/d^2 clamped
// at nearDistance; bounded by its range sphere like a point light.
enum class LightType : uint32_t { Point = 0, Spot = 1, Box = 2, Vpl = 3 };

// KHR_lights_punctual semantics: intensity in candela, colour linear, range finite (loaders turn
// an unbounded glTF light into a finite range, see lights.h), cone angles in radians. A box light's
// range is its bounding radius, length(halfExtents): makeBoxLight (lights.h) keeps them in step.
struct Light {
  LightType type = LightType::Point;
  glm::vec3 position{0.0f};
  glm::vec3 direction{0.0f, 0.0f, -1.0f};  // where a spot light points (a VPL: its normal), unit length
  glm::vec3 color{1.0f};
  float intensity = 1.0f;
  float range = 1.0f;
  float innerConeAngle = 0.0f;
  float outerConeAngle = 0.7853982f;  // pi / 4, the glTF default
  // Box lights: unit, orthogonal x and y axes (z = cross(x, y)) and half extents along them.
  glm::vec3 boxAxisX{1.0f, 0.0f, 0.0f};
  glm::vec3 boxAxisY{0.0f, 1.0f, 0.0f};
  glm::vec3 halfExtents{0.5f};
  float nearDistance = 0.0f;  // VPLs: 1/d^2 is taken as 1/max(d, nearDistance)^2
  // VPLs of the lighting grid hierarchy (gi/vpl_hierarchy.h): the band of distances they light,
  // rising from bandInner to 2 bandInner, falling from bandOuter to 2 bandOuter (the range) in
  // place of KHR's window. bandOuter 0: an ordinary VPL, KHR's window to its range.
  float bandInner = 0.0f;
  float bandOuter = 0.0f;
};

// KHR_lights_punctual's "directional" light (the sun): parallel light of `illuminance` lux along
// `direction`. It lights every point and never enters the light lists (FrameUniforms carries it).
struct DirectionalLight {
  std::string name;
  glm::vec3 direction{0.0f, -1.0f, 0.0f};  // where the light travels, unit length
  glm::vec3 color{1.0f};
  float illuminance = 1.0f;
};

// Moving lights (scene/light_animation.h). One light's motion, seconds t:
// position(t) = centre + (r cos(w t + a), h sin(2 pi f t + b), r sin(w t + a)), computed as
// origin + (offset(t) - offset(0)) so that position(0) is exactly `origin`.
struct LightMotion {
  glm::vec3 origin{0.0f};     // where the light is at time 0 (orbitCenter() gives the centre)
  float radius = 0.0f;        // of the orbit, metres
  float angularSpeed = 0.0f;  // radians per second, either sign
  float phase = 0.0f;         // radians
  float bobAmplitude = 0.0f;  // metres
  float bobFrequency = 0.0f;  // hertz
  float bobPhase = 0.0f;      // radians
};

// Lights first .. first + motions.size() - 1 of a scene move.
struct LightAnimation {
  uint32_t first = 0;
  std::vector<LightMotion> motions;
  bool empty() const { return motions.empty(); }
};

namespace gi {
class MovingVpls;
}

// --gi with moving lights: the virtual point lights that follow them (gi/moving_vpls.h), a block
// of the scene's lights from `first`. A copy of the scene copies it deeply (a scene's copy moves its
// lights on its own) through `clone`, which its maker sets: the scene's code needs nothing of gi/.
struct MovingIndirectLight {
  std::shared_ptr<gi::MovingVpls> vpls;
  std::shared_ptr<gi::MovingVpls> (*clone)(const gi::MovingVpls&) = nullptr;
  uint32_t first = 0;
  MovingIndirectLight() = default;
  MovingIndirectLight(const MovingIndirectLight& other)
      : vpls(other.vpls && other.clone ? other.clone(*other.vpls) : nullptr),
        clone(other.clone),
        first(other.first) {}
  MovingIndirectLight(MovingIndirectLight&& other) noexcept = default;
  MovingIndirectLight& operator=(const MovingIndirectLight& other) {
    if (this != &other) *this = MovingIndirectLight(other);
    return *this;
  }
  MovingIndirectLight& operator=(MovingIndirectLight&& other) noexcept = default;
  ~MovingIndirectLight() = default;
  explicit operator bool() const { return vpls != nullptr; }
};

struct Camera {
  std::string name;
  glm::vec3 eye{0.0f};
  glm::vec3 target{0.0f, 0.0f, -1.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float yfov = 1.0471976f;  // 60 degrees
};

struct Bounds {
  glm::vec3 min{1e30f};
  glm::vec3 max{-1e30f};
  void expand(const glm::vec3& p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
  bool valid() const { return min.x <= max.x; }
  glm::vec3 center() const { return 0.5f * (min + max); }
  glm::vec3 extent() const { return max - min; }
};

// The box around `bounds` transformed by `transform`: exact for transforms that keep the axes
// (translations, scales, quarter turns), a little larger than the transformed geometry otherwise.
Bounds transformBounds(const Bounds& bounds, const glm::mat4& transform);

struct Scene;
// Appends a copy of mesh `mesh` whose triangles wind the other way (each triangle's last two
// indices swapped, the same vertices and materials) and returns its index.
uint32_t addReversedWindingMesh(Scene& scene, uint32_t mesh);

// World coordinates beyond this are refused: squared distances must stay finite in 32-bit floats.
inline constexpr float kMaxWorldCoordinate = 1e18f;

struct Scene {
  std::string name;
  std::vector<Vertex> vertices;
  std::vector<uint32_t> indices;
  std::vector<Mesh> meshes;
  std::vector<Instance> instances;
  std::vector<Material> materials;
  std::vector<Texture> textures;
  std::vector<Light> lights;
  LightAnimation lightAnimation;       // which lights move, and how (--time, --animate); empty: none
  MovingIndirectLight movingIndirect;  // their VPLs, when --gi follows them
  std::vector<DirectionalLight> directionalLights;  // at most gpu::kMaxDirectionalLights
  std::vector<Camera> cameras;                      // the first one is the default
  // Where a particle emitter sits, when the scene has one (the default scene's smoke source).
  std::optional<glm::vec3> smokeSource;

  // Object-space bounds of a mesh's triangles.
  Bounds meshBounds(uint32_t mesh) const;
  // World-space bounds of all instanced geometry: each instance's transformBounds of its mesh's.
  Bounds worldBounds() const;
  uint64_t triangleCount() const;
};

}  // namespace lll
