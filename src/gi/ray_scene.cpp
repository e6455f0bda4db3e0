#include "gi/ray_scene.h"

#include <embree3/rtcore.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "scene/srgb.h"

namespace lll::gi {

struct RayScene::State {
  const Scene* scene = nullptr;  // the caller's, or `owned`
  std::unique_ptr<Scene> owned;  // its materials and textures only
  RTCDevice device = nullptr;
  RTCScene rtcScene = nullptr;
  std::vector<uint32_t> triangleMaterial;  // per triangle
  std::vector<glm::vec2> cornerUv;         // 3 per triangle
  std::vector<glm::vec2> cornerUv1;        // 3 per triangle
  std::vector<glm::vec4> cornerColor;      // 3 per triangle
  std::vector<glm::vec3> cornerNormal;     // 3 per triangle, world space
  std::vector<float> materialCutoff;       // per material: the mask cutoff, or -1 when not masked

  float alphaAt(uint32_t triangle, float u, float v) const {
    const Material& m = scene->materials[triangleMaterial[triangle]];
    const size_t first = 3 * size_t(triangle);
    const auto at = [&](const auto* c) { return (1.0f - u - v) * c[0] + u * c[1] + v * c[2]; };
    return m.baseColorFactor.a * at(&cornerColor[first]).a *
           sampleMaterialTexture(*scene, m, kBaseColorSlot, at(&cornerUv[first]), at(&cornerUv1[first])).a;
  }

  ~State() {
    if (rtcScene) rtcReleaseScene(rtcScene);
    if (device) rtcReleaseDevice(device);
  }
};

namespace {

// Embree's filter callback: refuses hits on a masked material where its alpha is under the cutoff.
void alphaMaskFilter(const RTCFilterFunctionNArguments* args) {
  const auto* state = static_cast<const RayScene::State*>(args->geometryUserPtr);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] == 0) continue;
    const uint32_t triangle = RTCHitN_primID(args->hit, args->N, i);
    const float cutoff = state->materialCutoff[state->triangleMaterial[triangle]];
    if (cutoff < 0.0f) continue;
    if (state->alphaAt(triangle, RTCHitN_u(args->hit, args->N, i), RTCHitN_v(args->hit, args->N, i)) < cutoff)
      args->valid[i] = 0;
  }
}

float decodeSrgb(uint8_t value) {
  return srgbDecode(float(value) / 255.0f);
}

}  // namespace

glm::vec4 sampleMaterialTexture(const Scene& scene, const Material& m, TextureSlot slot, glm::vec2 uv,
                                glm::vec2 uv1) {
  const int texture = m.texture(slot);
  return texture >= 0 ? sampleTexture(scene.textures[size_t(texture)],
                                      m.transforms[slot].apply(m.texCoords[slot] == 1 ? uv1 : uv))
                      : glm::vec4(1.0f);
}

glm::vec4 sampleTexture(const Texture& texture, glm::vec2 uv) {
  if (texture.width == 0 || texture.height == 0) return glm::vec4(1.0f);
  const float x = uv.x * float(texture.width) - 0.5f, y = uv.y * float(texture.height) - 0.5f;
  // Texel i of a row or column of n, as the sampler's wrap mode addresses it.
  auto wrap = [](float i, uint32_t n, TextureWrap mode) {
    const int64_t m = int64_t(n);
    if (mode == TextureWrap::ClampToEdge) return uint32_t(std::clamp<double>(i, 0.0, double(m - 1)));
    const int64_t period = mode == TextureWrap::MirroredRepeat ? 2 * m : m;
    int64_t k = int64_t(std::fmod(double(i), double(period)));
    if (k < 0) k += period;
    return uint32_t(k < m ? k : period - 1 - k);
  };
  auto texel = [&](float ix, float iy) {
    const size_t at = (size_t(wrap(iy, texture.height, texture.sampler.wrapV)) * texture.width +
                       wrap(ix, texture.width, texture.sampler.wrapU)) *
                      4;
    const uint8_t* p = &texture.rgba[at];
    if (texture.srgb)
      return glm::vec4(decodeSrgb(p[0]), decodeSrgb(p[1]), decodeSrgb(p[2]), float(p[3]) / 255.0f);
    return glm::vec4(p[0], p[1], p[2], p[3]) / 255.0f;
  };
  // The base level, magnified: the sampler's magnification filter.
  if (texture.sampler.magnify == TextureFilter::Nearest)
    return texel(std::floor(x + 0.5f), std::floor(y + 0.5f));
  const float fx = std::floor(x), fy = std::floor(y);
  const float tx = x - fx, ty = y - fy;
  return glm::mix(glm::mix(texel(fx, fy), texel(fx + 1, fy), tx),
                  glm::mix(texel(fx, fy + 1), texel(fx + 1, fy + 1), tx), ty);
}

RayScene::RayScene(const Scene& scene, Keep keep) : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.scene = &scene;
  if (keep == Keep::OwnMaterials) {
    s.owned = std::make_unique<Scene>();
    s.owned->materials = scene.materials;
    s.owned->textures = scene.textures;
    s.scene = s.owned.get();
  }
  s.device = rtcNewDevice(nullptr);
  if (!s.device) throw std::runtime_error("Embree: could not create a device");
  s.rtcScene = rtcNewScene(s.device);

  std::vector<glm::vec3> positions;
  std::vector<uint32_t> indices;
  for (const Instance& instance : scene.instances) {
    const Mesh& mesh = scene.meshes[instance.mesh];
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(instance.transform)));
    for (const Primitive& p : mesh.primitives) {
      for (uint32_t i = 0; i + 2 < p.indexCount; i += 3) {
        for (uint32_t corner = 0; corner < 3; ++corner) {
          const Vertex& v =
              scene.vertices[size_t(p.vertexOffset) + scene.indices[size_t(p.firstIndex) + i + corner]];
          indices.push_back(uint32_t(positions.size()));
          positions.push_back(glm::vec3(instance.transform * glm::vec4(v.position, 1.0f)));
          s.cornerUv.push_back(v.uv);
          s.cornerUv1.push_back(v.uv1);
          s.cornerColor.push_back(v.rgba());
          s.cornerNormal.push_back(normalMatrix * v.normal);
        }
        s.triangleMaterial.push_back(p.material);
        const glm::vec3* c = &positions[positions.size() - 3];
        surfaceArea_ += 0.5 * double(glm::length(glm::cross(c[1] - c[0], c[2] - c[0])));
      }
    }
  }
  bool anyMask = false;
  for (const Material& m : scene.materials) {
    const bool masked = m.alphaMode == AlphaMode::Mask;
    s.materialCutoff.push_back(masked ? m.alphaCutoff : -1.0f);
    anyMask |= masked;
  }

  const Bounds bounds = scene.worldBounds();
  if (bounds.valid()) surfaceOffset_ = std::max(1e-5f, 1e-5f * glm::length(bounds.extent()));

  if (!s.triangleMaterial.empty()) {
    RTCGeometry geometry = rtcNewGeometry(s.device, RTC_GEOMETRY_TYPE_TRIANGLE);
    // Embree reads vertex buffers 16 bytes at a time: one spare float3 pads the last one.
    auto* vb = static_cast<float*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, sizeof(glm::vec3), positions.size() + 1));
    auto* ib =
        static_cast<uint32_t*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                       3 * sizeof(uint32_t), s.triangleMaterial.size()));
    if (!vb || !ib) {
      rtcReleaseGeometry(geometry);
      throw std::runtime_error(
          fmt::format("Embree: could not allocate {} triangles", s.triangleMaterial.size()));
    }
    std::copy_n(&positions[0].x, positions.size() * 3, vb);
    std::copy(indices.begin(), indices.end(), ib);
    if (anyMask) {
      rtcSetGeometryUserData(geometry, &s);
      rtcSetGeometryIntersectFilterFunction(geometry, alphaMaskFilter);
      rtcSetGeometryOccludedFilterFunction(geometry, alphaMaskFilter);
    }
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(s.rtcScene, geometry);
    rtcReleaseGeometry(geometry);
  }
  rtcCommitScene(s.rtcScene);
  if (const RTCError error = rtcGetDeviceError(s.device); error != RTC_ERROR_NONE)
    throw std::runtime_error(fmt::format("Embree: building the scene's {} triangles failed (error {})",
                                         s.triangleMaterial.size(), int(error)));
}

RayScene::~RayScene() = default;

uint64_t RayScene::triangleCount() const {
  return state_->triangleMaterial.size();
}

std::optional<RayHit> RayScene::intersect(const glm::vec3& origin, const glm::vec3& direction, float tNear,
                                          float tFar) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh{};
  rh.ray.org_x = origin.x, rh.ray.org_y = origin.y, rh.ray.org_z = origin.z;
  rh.ray.dir_x = direction.x, rh.ray.dir_y = direction.y, rh.ray.dir_z = direction.z;
  rh.ray.tnear = tNear;
  rh.ray.tfar = tFar;
  rh.ray.mask = ~0u;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(state_->rtcScene, &context, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;

  RayHit hit;
  hit.distance = rh.ray.tfar;
  hit.position = origin + direction * rh.ray.tfar;
  glm::vec3 n(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z);
  const float length = glm::length(n);
  n = length > 0.0f ? n / length : -direction;
  hit.normal = glm::dot(n, direction) > 0.0f ? -n : n;
  const uint32_t triangle = rh.hit.primID;
  hit.material = state_->triangleMaterial[triangle];
  const size_t first = 3 * size_t(triangle);
  const auto at = [&](const auto* c) {
    return (1.0f - rh.hit.u - rh.hit.v) * c[0] + rh.hit.u * c[1] + rh.hit.v * c[2];
  };
  hit.uv = at(&state_->cornerUv[first]);
  hit.uv1 = at(&state_->cornerUv1[first]);
  hit.color = at(&state_->cornerColor[first]);
  const glm::vec3* cn = &state_->cornerNormal[3 * size_t(triangle)];
  const glm::vec3 shading = (1.0f - rh.hit.u - rh.hit.v) * cn[0] + rh.hit.u * cn[1] + rh.hit.v * cn[2];
  const float shadingLength = glm::length(shading);
  hit.shadingNormal =
      shadingLength > 0.0f && std::isfinite(shadingLength) ? shading / shadingLength : hit.normal;
  if (glm::dot(hit.shadingNormal, hit.normal) < 0.0f) hit.shadingNormal = -hit.shadingNormal;
  return hit;
}

bool RayScene::occluded(const glm::vec3& origin, const glm::vec3& direction, float tNear, float tFar) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray{};
  ray.org_x = origin.x, ray.org_y = origin.y, ray.org_z = origin.z;
  ray.dir_x = direction.x, ray.dir_y = direction.y, ray.dir_z = direction.z;
  ray.tnear = tNear;
  ray.tfar = tFar;
  ray.mask = ~0u;
  rtcOccluded1(state_->rtcScene, &context, &ray);
  return ray.tfar < 0.0f;  // Embree marks an occluded ray with tfar = -inf
}

MaterialSample RayScene::materialAt(const RayHit& hit) const {
  const Scene& scene = *state_->scene;
  const Material& m = scene.materials[hit.material];
  MaterialSample r;
  r.baseColor =
      m.baseColorFactor * hit.color * sampleMaterialTexture(scene, m, kBaseColorSlot, hit.uv, hit.uv1);
  const glm::vec4 metallicRoughness =
      sampleMaterialTexture(scene, m, kMetallicRoughnessSlot, hit.uv, hit.uv1);
  r.metallic = glm::clamp(m.metallic * metallicRoughness.b, 0.0f, 1.0f);
  r.roughness = glm::clamp(m.roughness * metallicRoughness.g, 0.0f, 1.0f);
  r.emissive = m.emissiveFactor * m.emissiveStrength *
               glm::vec3(sampleMaterialTexture(scene, m, kEmissiveSlot, hit.uv, hit.uv1));
  return r;
}

SurfaceResponse RayScene::surfaceAt(const RayHit& hit) const {
  const Scene& scene = *state_->scene;
  const Material& m = scene.materials[hit.material];
  const glm::vec4 base =
      m.baseColorFactor * hit.color * sampleMaterialTexture(scene, m, kBaseColorSlot, hit.uv, hit.uv1);
  const float metallic =
      m.metallic * sampleMaterialTexture(scene, m, kMetallicRoughnessSlot, hit.uv, hit.uv1).b;
  SurfaceResponse r;
  r.albedo = glm::clamp(glm::vec3(base) * (1.0f - glm::clamp(metallic, 0.0f, 1.0f)), 0.0f, 1.0f);
  r.coverage = m.alphaMode == AlphaMode::Blend ? glm::clamp(base.a, 0.0f, 1.0f) : 1.0f;
  return r;
}

bool RayScene::hasBlendedMaterials() const {
  for (const Material& m : state_->scene->materials)
    if (m.alphaMode == AlphaMode::Blend) return true;
  return false;
}

}  // namespace lll::gi
