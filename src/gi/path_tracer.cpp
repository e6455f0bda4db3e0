#include "gi/path_tracer.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "core/errors.h"
#include "gi/brdf.h"
#include "gi/light_falloff.h"
#include "gi/random.h"
#include "gi/ray_scene.h"
#include "gi/sampling.h"

namespace lll::gi {

PixelRays::PixelRays(const Camera& camera, uint32_t width, uint32_t height)
    : eye_(camera.eye),
      forward_(glm::normalize(camera.target - camera.eye)),
      invWidth_(1.0f / float(width)),
      invHeight_(1.0f / float(height)) {
  glm::vec3 up = camera.up;
  if (std::abs(glm::dot(glm::normalize(up), forward_)) > 0.999f) up = glm::vec3(0.0f, 0.0f, -1.0f);
  right_ = glm::normalize(glm::cross(forward_, up));
  up_ = glm::cross(right_, forward_);
  tanHalfY_ = std::tan(camera.yfov * 0.5f);
  tanHalfX_ = tanHalfY_ * float(width) / float(height);
}

glm::vec3 PixelRays::direction(uint32_t x, uint32_t y) const {
  const float ndcX = (float(x) + 0.5f) * invWidth_ * 2.0f - 1.0f;
  const float ndcDown = (float(y) + 0.5f) * invHeight_ * 2.0f - 1.0f;  // Vulkan's y points down
  return glm::normalize(forward_ + right_ * (ndcX * tanHalfX_) - up_ * (ndcDown * tanHalfY_));
}

void validateReferenceOptions(const ReferenceOptions& options) {
  if (options.spp == 0 || options.spp > kMaxReferenceSpp)
    throw InputError(
        fmt::format("--spp {}: expected 1 to {} samples per pixel", options.spp, kMaxReferenceSpp));
  if (options.bounces > kMaxBounces)
    throw InputError(fmt::format("--bounces {}: expected 0 to {}", options.bounces, kMaxBounces));
  if (options.indirectOnly && options.bounces == 0)
    throw InputError("--indirect with --bounces 0: there is no light left to render");
  if (options.vpls != VplGather::Off && options.bounces == 0)
    throw InputError("--vpls with --bounces 0: photons that deposit nothing leave no VPLs");
  if (options.vpls != VplGather::Off && options.indirectOnly)
    throw InputError("--vpls with --indirect: the VPLs' light is indirect light only already");
  if (options.threads > kMaxReferenceThreads)
    throw InputError(
        fmt::format("--threads {}: expected 0 (one per core) to {}", options.threads, kMaxReferenceThreads));
}

namespace {

// Power (in the photon tracer's sense) of each light that can light a surface; below
// kAllLightsLimit every light is sampled, so the probabilities are not needed.
struct LightSelection {
  std::vector<const Light*> lights;
  std::vector<float> cdf;  // empty: every light, each with weight 1
  std::vector<float> probability;
};

LightSelection selectLights(const std::vector<Light>& all) {
  LightSelection s;
  std::vector<double> power;
  double total = 0.0;
  for (const Light& light : all) {
    if (!emitsLight(light)) continue;
    const double p =
        double(light.intensity) * (light.color.r + light.color.g + light.color.b) * emissionSolidAngle(light);
    if (!(p > 0.0)) continue;
    s.lights.push_back(&light);
    power.push_back(p);
    total += p;
  }
  if (s.lights.size() <= kAllLightsLimit) return s;
  double running = 0.0;
  for (double p : power) {
    running += p;
    s.probability.push_back(float(p / total));
    s.cdf.push_back(float(running / total));
  }
  s.cdf.back() = 1.0f;
  return s;
}

// Glass crossings a ray may make before it is taken as absorbed: stacked panes, not a loop.
constexpr int kMaxCrossings = 64;

class PathTracer {
 public:
  PathTracer(const Scene& scene, const ReferenceOptions& options)
      : rays_(scene),
        options_(options),
        selection_(selectLights(scene.lights)),
        suns_(scene.directionalLights),
        glass_(rays_.hasBlendedMaterials()),
        offset_(rays_.surfaceOffset()) {
    if (options.vpls == VplGather::Off) return;
    for (const Light& light : scene.lights)
      if (light.type == LightType::Vpl && light.intensity > 0.0f) vpls_.push_back(&light);
  }

  // One sample of the radiance arriving at the eye along `direction`.
  glm::vec3 sample(const glm::vec3& eye, const glm::vec3& direction, Random& random) const {
    const std::optional<RayHit> hit = trace(eye, direction, 0.0f, random);
    if (!hit) return glm::vec3(0.0f);
    const MaterialSample m = rays_.materialAt(*hit);
    const BrdfSurface s{hit->shadingNormal, -direction, glm::vec3(m.baseColor), m.metallic, m.roughness};
    if (options_.vpls != VplGather::Off) return vplLight(*hit, s, random);
    glm::vec3 radiance(0.0f);
    if (!options_.indirectOnly) {
      radiance += m.emissive;
      forEachLight(*hit, random,
                   [&](const glm::vec3& l, const glm::vec3& e) { radiance += brdfCosine(s, l) * e; });
    }
    if (options_.bounces > 0) radiance += indirect(*hit, s, random);
    return radiance;
  }

 private:
  // The nearest hit that is not crossed: glass is crossed with probability 1 - coverage.
  std::optional<RayHit> trace(glm::vec3 origin, const glm::vec3& direction, float tNear,
                              Random& random) const {
    for (int crossing = 0; crossing <= kMaxCrossings; ++crossing) {
      std::optional<RayHit> hit =
          rays_.intersect(origin, direction, tNear, std::numeric_limits<float>::infinity());
      if (!hit || !glass_) return hit;
      const float coverage = rays_.surfaceAt(*hit).coverage;
      if (coverage >= 1.0f || random.uniform() < coverage) return hit;
      origin = hit->position + direction * offset_;
      tNear = offset_;
    }
    return std::nullopt;
  }

  // Whether light passes from `origin` along unit `l` for `distance`, crossing glass as trace does.
  bool visible(glm::vec3 origin, const glm::vec3& l, float distance, Random& random) const {
    if (!glass_) return !rays_.occluded(origin, l, 0.0f, distance);
    for (int crossing = 0; crossing <= kMaxCrossings; ++crossing) {
      const std::optional<RayHit> hit = rays_.intersect(origin, l, 0.0f, distance);
      if (!hit) return true;
      const float coverage = rays_.surfaceAt(*hit).coverage;
      if (coverage >= 1.0f || random.uniform() < coverage) return false;
      origin = hit->position + l * offset_;
      distance -= hit->distance + offset_;
      if (!(distance > 0.0f)) return true;
    }
    return false;
  }

  // Calls add(l, E) for the lights that reach `hit`: l the unit direction to the light, E the
  // light's colour x intensity x attenuation (irradiance on a surface facing it), divided by the
  // probability of picking it when one light is picked.
  template <typename Add>
  void forEachLight(const RayHit& hit, Random& random, Add&& add) const {
    const glm::vec3 origin = hit.position + hit.normal * offset_;
    auto one = [&](const Light& light, float weight) {
      const glm::vec3 toLight = light.position - hit.position;
      const float distance = glm::length(toLight);
      if (!(distance > 0.0f)) return;
      const glm::vec3 l = toLight / distance;
      const float attenuation = lightAttenuation(light, l, distance);
      if (!(attenuation > 0.0f) || glm::dot(l, hit.normal) <= 0.0f) return;
      if (!visible(origin, l, std::max(0.0f, distance - offset_), random)) return;
      add(l, light.color * (light.intensity * attenuation * weight));
    };
    // Directional lights: every one, each with a shadow ray to infinity.
    for (const DirectionalLight& sun : suns_) {
      const glm::vec3 l = -glm::normalize(sun.direction);
      if (glm::dot(l, hit.normal) <= 0.0f) continue;
      if (visible(origin, l, std::numeric_limits<float>::infinity(), random))
        add(l, sun.color * sun.illuminance);
    }
    if (selection_.lights.empty()) return;
    if (selection_.cdf.empty()) {
      for (const Light* light : selection_.lights) one(*light, 1.0f);
      return;
    }
    const size_t pick =
        std::min(size_t(std::lower_bound(selection_.cdf.begin(), selection_.cdf.end(), random.uniform()) -
                        selection_.cdf.begin()),
                 selection_.lights.size() - 1);
    one(*selection_.lights[pick], 1.0f / selection_.probability[pick]);
  }

  // The scene's VPLs summed at the camera's hit `x` (ReferenceOptions::vpls).
  glm::vec3 vplLight(const RayHit& x, const BrdfSurface& s, Random& random) const {
    const glm::vec3 origin = x.position + x.normal * offset_;
    glm::vec3 radiance(0.0f);
    for (const Light* vpl : vpls_) {
      const glm::vec3 toLight = vpl->position - x.position;
      const float distance = glm::length(toLight);
      if (!(distance > 0.0f) || !(distance < vpl->range)) continue;
      const glm::vec3 l = toLight / distance;
      const float attenuation = lightAttenuation(*vpl, l, distance);
      if (!(attenuation > 0.0f)) continue;
      const glm::vec3 reflected = brdfCosine(s, l, lightDistributionAlpha(*vpl, s, distance));
      if (!(glm::dot(reflected, glm::vec3(1.0f)) > 0.0f)) continue;
      if (options_.vpls == VplGather::Shadowed) {
        // To the VPL lifted off the surface it was deposited on, so that its own surface does not
        // hide it.
        const glm::vec3 toTarget = vpl->position + vpl->direction * offset_ - origin;
        const float targetDistance = glm::length(toTarget);
        if (targetDistance > offset_ &&
            !visible(origin, toTarget / targetDistance, targetDistance - offset_, random))
          continue;
      }
      radiance += reflected * vpl->color * (vpl->intensity * attenuation);
    }
    return radiance;
  }

  // Indirect radiance towards the eye at the camera's hit: one path of options_.bounces diffuse
  // bounces, the light each bounce reflects gathered with shadow rays.
  glm::vec3 indirect(const RayHit& x, const BrdfSurface& s, Random& random) const {
    glm::vec3 direction = cosineAbout(s.normal, random);
    const float cosine = glm::dot(s.normal, direction);
    if (glm::dot(direction, x.normal) <= 0.0f || !(cosine > 0.0f)) return glm::vec3(0.0f);
    glm::vec3 throughput = brdfCosine(s, direction) * (kPi / cosine);
    glm::vec3 origin = x.position + x.normal * offset_;
    glm::vec3 radiance(0.0f);
    for (uint32_t bounce = 1; bounce <= options_.bounces; ++bounce) {
      const std::optional<RayHit> y = trace(origin, direction, offset_, random);
      if (!y) break;
      const glm::vec3 albedo = rays_.surfaceAt(*y).albedo;
      throughput *= albedo;
      if (!(glm::dot(throughput, glm::vec3(1.0f)) > 0.0f)) break;
      glm::vec3 irradiance(0.0f);
      forEachLight(*y, random, [&](const glm::vec3& l, const glm::vec3& e) {
        irradiance += e * std::max(glm::dot(y->shadingNormal, l), 0.0f);
      });
      radiance += throughput * irradiance / kPi;
      // The next bounce's cosine-sampled radiance times pi is its irradiance: the pi cancels the
      // albedo's 1 / pi, so the throughput carries only the albedo.
      direction = cosineAbout(y->shadingNormal, random);
      if (glm::dot(direction, y->normal) <= 0.0f) break;
      origin = y->position + y->normal * offset_;
    }
    return radiance;
  }

  RayScene rays_;
  const ReferenceOptions& options_;
  LightSelection selection_;
  std::vector<DirectionalLight> suns_;
  bool glass_;
  float offset_;
  std::vector<const Light*> vpls_;  // with options_.vpls
};

}  // namespace

RadianceImage renderReference(const Scene& scene, const Camera& camera, uint32_t width, uint32_t height,
                              const ReferenceOptions& options) {
  validateReferenceOptions(options);
  if (width == 0 || height == 0)
    throw InputError(fmt::format("resolution {}x{}: must not be empty", width, height));
  const PathTracer tracer(scene, options);
  const PixelRays pixels(camera, width, height);
  RadianceImage image{width, height, std::vector<glm::vec3>(size_t(width) * height, glm::vec3(0.0f))};
  parallelFor(
      height, options.threads,
      [&](uint32_t y) {
        for (uint32_t x = 0; x < width; ++x) {
          const size_t pixel = size_t(y) * width + x;
          Random random(options.seed, pixel);
          const glm::vec3 direction = pixels.direction(x, y);
          glm::vec3 sum(0.0f);
          for (uint32_t i = 0; i < options.spp; ++i) sum += tracer.sample(pixels.origin(), direction, random);
          image.rgb[pixel] = sum / float(options.spp);
        }
      },
      options.progress);
  return image;
}

}  // namespace lll::gi
