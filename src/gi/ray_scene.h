#pragma once
// The scene's triangles in world space under Embree (Debian 12's libembree-dev 3.13), for the CPU
// work that needs rays: the photon tracer behind the virtual point lights and the path-traced
// reference. Embree is in this one translation unit; callers see plain glm types.
#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <vector>

#include "scene/scene.h"

namespace lll::gi {

struct RayHit {
  float distance = 0.0f;
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f, 0.0f, 1.0f};  // unit geometric normal, turned to face the ray's origin
  uint32_t material = 0;               // index into Scene::materials
  glm::vec2 uv{0.0f};                  // TEXCOORD_0 at the hit
  glm::vec2 uv1{0.0f};                 // TEXCOORD_1
  glm::vec4 color{1.0f};               // COLOR_0, multiplying the base colour
  // The interpolated vertex normal, on the geometric normal's side: the normal the renderer shades
  // with where a material has no normal map (the geometric normal where the mesh's is degenerate).
  glm::vec3 shadingNormal{0.0f, 0.0f, 1.0f};
};

// What a material does to light at a hit, as the photon tracer and the reference see it: the
// diffuse albedo of glTF's metallic-roughness model, (1 - metallic) * base colour (the metal lobe
// and the dielectric's specular are not bounced: instant radiosity is diffuse), and the coverage
// alpha of a blended surface (glass), which light crosses with probability 1 - coverage.
struct SurfaceResponse {
  glm::vec3 albedo{0.0f};
  float coverage = 1.0f;
};

// A material's glTF inputs at a hit, textures sampled: what the renderer's Surface is built from.
struct MaterialSample {
  glm::vec4 baseColor{1.0f};  // factor x texture, alpha included
  float metallic = 0.0f;      // clamped to [0, 1]
  float roughness = 1.0f;     // clamped to [0, 1]
  glm::vec3 emissive{0.0f};   // factor x strength x texture
};

class RayScene {
 public:
  // Whether the ray scene reads `scene`'s materials and textures, which must then outlive it, or
  // keeps copies (one that outlives its scene: gi/moving_vpls.h).
  enum class Keep { ReferToScene, OwnMaterials };
  // Throws std::runtime_error when Embree cannot build the scene (out of memory).
  explicit RayScene(const Scene& scene, Keep keep = Keep::ReferToScene);
  ~RayScene();
  RayScene(const RayScene&) = delete;
  RayScene& operator=(const RayScene&) = delete;

  // Nearest hit along origin + t * direction for t in (tNear, tFar); `direction` unit length.
  // Alpha-masked materials are crossed where their mask (factor x texture alpha) is below the
  // cutoff. Safe to call from many threads at once.
  std::optional<RayHit> intersect(const glm::vec3& origin, const glm::vec3& direction, float tNear,
                                  float tFar) const;
  // Whether anything blocks the segment; same masking rules.
  bool occluded(const glm::vec3& origin, const glm::vec3& direction, float tNear, float tFar) const;

  SurfaceResponse surfaceAt(const RayHit& hit) const;
  MaterialSample materialAt(const RayHit& hit) const;
  // Whether any material is blended (glass): rays may then have to cross surfaces.
  bool hasBlendedMaterials() const;

  uint64_t triangleCount() const;
  // Area of the scene's triangles in world space (one side each), m^2.
  double surfaceArea() const { return surfaceArea_; }
  struct State;  // Embree's handles and the per-triangle data (ray_scene.cpp)
  // A distance that lifts a ray's origin off the surface it leaves: relative to the scene's size.
  float surfaceOffset() const { return surfaceOffset_; }

 private:
  std::unique_ptr<State> state_;
  float surfaceOffset_ = 1e-4f;
  double surfaceArea_ = 0.0;
};

// Linear RGBA of a texture's base level at `uv`, wrapped and filtered (bilinear or nearest) as its
// sampler magnifies; sRGB-encoded textures are decoded.
glm::vec4 sampleTexture(const Texture& texture, glm::vec2 uv);
// Material `m`'s texture of `slot` at TEXCOORD_0 `uv` or TEXCOORD_1 `uv1` (the slot's
// Material::texCoords) through its KHR_texture_transform; white where the material has none (as
// the renderer's stand-ins).
glm::vec4 sampleMaterialTexture(const Scene& scene, const Material& m, TextureSlot slot, glm::vec2 uv,
                                glm::vec2 uv1);

}  // namespace lll::gi
