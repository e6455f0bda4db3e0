#include "gi/photons.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <execution>

#include "gi/light_falloff.h"
#include "gi/photon_walk.h"
#include "gi/random.h"
#include "gi/ray_scene.h"
#include "gi/vpl_hierarchy.h"

namespace lll::gi {
namespace {

float channelMean(const glm::vec3& c) {
  return (c.r + c.g + c.b) / 3.0f;
}

}  // namespace

namespace walk {

Emitters chooseEmitters(const std::vector<Light>& lights, const std::vector<DirectionalLight>& suns,
                        const Bounds& bounds) {
  Emitters e;
  if (bounds.valid()) {
    e.sceneCenter = bounds.center();
    e.sceneRadius = std::max(0.5f * glm::length(bounds.extent()), 1e-3f);
  }
  std::vector<double> power;
  for (const Light& light : lights) {
    if (!emitsLight(light)) continue;
    power.push_back(double(light.intensity) * channelMean(light.color) * emissionSolidAngle(light));
    e.sources.push_back({&light, nullptr});
  }
  if (bounds.valid()) {
    for (const DirectionalLight& sun : suns) {
      power.push_back(double(sun.illuminance) * channelMean(sun.color) * kPi * e.sceneRadius * e.sceneRadius);
      e.sources.push_back({nullptr, &sun});
    }
  }
  double total = 0.0;
  for (size_t i = 0; i < power.size();) {  // drop the dark ones
    if (power[i] > 0.0) {
      total += power[i++];
    } else {
      power.erase(power.begin() + ptrdiff_t(i));
      e.sources.erase(e.sources.begin() + ptrdiff_t(i));
    }
  }
  double running = 0.0;
  for (const double p : power) {
    running += p;
    e.probability.push_back(float(p / total));
    e.cdf.push_back(float(running / total));
  }
  if (!e.cdf.empty()) e.cdf.back() = 1.0f;
  return e;
}

size_t pickEmitter(const Emitters& emitters, Random& random) {
  const size_t pick = size_t(std::lower_bound(emitters.cdf.begin(), emitters.cdf.end(), random.uniform()) -
                             emitters.cdf.begin());
  return std::min(pick, emitters.sources.size() - 1);
}

}  // namespace walk

namespace {

using walk::Emitters;

// Where a photon starts and where it goes, with the flux it carries (before its light's window).
struct Emission {
  glm::vec3 origin, direction, flux;
};

Emission emitFromLight(const Light& light, float share, Random& random) {
  Emission e;
  e.origin = light.position;
  float angular = 1.0f;
  if (light.type == LightType::Spot) {
    const float cosOuter = std::cos(light.outerConeAngle);
    const float cosTheta = 1.0f - random.uniform() * (1.0f - cosOuter);
    e.direction = aroundAxis(glm::normalize(light.direction), cosTheta, 2.0f * kPi * random.uniform());
    angular = spotFalloff(light, cosTheta);
  } else {
    e.direction =
        aroundAxis(glm::vec3(0, 0, 1), 1.0f - 2.0f * random.uniform(), 2.0f * kPi * random.uniform());
  }
  e.flux = light.color * (light.intensity * emissionSolidAngle(light) * angular * share);
  return e;
}

Emission emitFromSun(const DirectionalLight& sun, const Emitters& emitters, float share, Random& random) {
  const glm::vec3 d = glm::normalize(sun.direction);
  glm::vec3 t, b;
  perpendiculars(d, t, b);
  const float r = emitters.sceneRadius * std::sqrt(random.uniform()), phi = 2.0f * kPi * random.uniform();
  Emission e;
  e.origin =
      emitters.sceneCenter - d * (2.0f * emitters.sceneRadius) + (t * std::cos(phi) + b * std::sin(phi)) * r;
  e.direction = d;
  e.flux = sun.color * (sun.illuminance * kPi * emitters.sceneRadius * emitters.sceneRadius * share);
  return e;
}

}  // namespace

glm::vec3 walk::tracePhoton(const RayScene& rays, const Emitters& emitters, uint32_t photonCount,
                            uint32_t bounces, Random& random, std::vector<PhotonDeposit>& out) {
  const size_t chosen = pickEmitter(emitters, random);
  const float share = 1.0f / (float(photonCount) * emitters.probability[chosen]);
  const Light* light = emitters.sources[chosen].light;
  const Emission emission = light ? emitFromLight(*light, share, random)
                                  : emitFromSun(*emitters.sources[chosen].sun, emitters, share, random);
  glm::vec3 flux = emission.flux, origin = emission.origin, direction = emission.direction;
  const float offset = rays.surfaceOffset();
  bool fromLight = true;
  for (uint32_t deposits = 0; deposits < bounces;) {
    // Beyond its range (its bounding radius for a box) a light's window is zero; the sun has none.
    const float reach = fromLight && light ? light->range - glm::distance(origin, light->position)
                                           : std::numeric_limits<float>::infinity();
    if (!(reach > 0.0f)) break;
    const std::optional<RayHit> hit = rays.intersect(origin, direction, fromLight ? 0.0f : offset, reach);
    if (!hit) break;
    const SurfaceResponse surface = rays.surfaceAt(*hit);
    if (surface.coverage < 1.0f && random.uniform() >= surface.coverage) {
      origin = hit->position + direction * offset;  // through the glass, unchanged
      continue;
    }
    if (fromLight && light) {
      flux *= light->type == LightType::Box
                  ? boxWindow(*light, hit->position - light->position)
                  : rangeWindow(glm::distance(hit->position, light->position), light->range);
    }
    fromLight = false;
    const glm::vec3 reflected = flux * surface.albedo;
    if (glm::dot(reflected, glm::vec3(1.0f)) <= 0.0f) break;
    out.push_back({hit->position, hit->normal, reflected});
    ++deposits;
    const float survival = std::min(1.0f, std::max({surface.albedo.r, surface.albedo.g, surface.albedo.b}));
    if (random.uniform() >= survival) break;
    flux = reflected / survival;
    origin = hit->position + hit->normal * offset;
    direction = cosineAbout(hit->normal, random);
  }
  return emission.flux;
}

Light makeVpl(const glm::vec3& position, const glm::vec3& normal, const glm::vec3& flux, float nearDistance,
              const VplReach& reach) {
  Light vpl;
  vpl.type = LightType::Vpl;
  vpl.position = position;
  vpl.direction = glm::normalize(normal);
  const float peak = std::max({flux.r, flux.g, flux.b});
  vpl.color = peak > 0.0f ? flux / peak : glm::vec3(0.0f);
  vpl.intensity = peak / kPi;
  const float range = reach.range > 0.0f ? reach.range : std::sqrt(vpl.intensity / reach.cutoffIrradiance);
  vpl.range = std::max(range, 2.0f * nearDistance);
  vpl.nearDistance = nearDistance;
  return vpl;
}

std::vector<PhotonDeposit> tracePhotons(const RayScene& rays, const Scene& scene, const VplOptions& options,
                                        PhotonStats* stats, std::vector<uint32_t>* owners) {
  const auto begin = std::chrono::steady_clock::now();
  const Emitters emitters = walk::chooseEmitters(scene.lights, scene.directionalLights, scene.worldBounds());
  std::vector<PhotonDeposit> deposits;
  glm::vec3 emitted(0.0f);
  if (!emitters.sources.empty() && options.photons > 0 && options.bounces > 0) {
    // Fixed chunks in photon order, each with its own output.
    constexpr uint32_t kChunk = 1024;
    const uint32_t chunks = (options.photons + kChunk - 1) / kChunk;
    std::vector<std::vector<PhotonDeposit>> perChunk(chunks);
    std::vector<std::vector<uint32_t>> ownersPerChunk(owners ? chunks : 0);
    std::vector<glm::vec3> emittedPerChunk(chunks, glm::vec3(0.0f));
    parallelFor(
        chunks, options.threads,
        [&](uint32_t c) {
          const uint32_t end = std::min(options.photons, (c + 1) * kChunk);
          for (uint32_t p = c * kChunk; p < end; ++p) {
            Random random(options.seed, p);
            emittedPerChunk[c] +=
                walk::tracePhoton(rays, emitters, options.photons, options.bounces, random, perChunk[c]);
            if (owners) ownersPerChunk[c].resize(perChunk[c].size(), p);
          }
        },
        options.progress);
    size_t total = 0;
    for (const auto& chunk : perChunk) total += chunk.size();
    deposits.reserve(total);
    if (owners) owners->reserve(total);
    for (uint32_t c = 0; c < chunks; ++c) {
      deposits.insert(deposits.end(), perChunk[c].begin(), perChunk[c].end());
      if (owners) owners->insert(owners->end(), ownersPerChunk[c].begin(), ownersPerChunk[c].end());
      emitted += emittedPerChunk[c];
    }
  }
  if (stats) {
    stats->photons = emitters.sources.empty() ? 0 : options.photons;
    stats->deposits = deposits.size();
    stats->emittedFlux = emitted;
    stats->depositedFlux = glm::vec3(0.0f);
    for (const PhotonDeposit& d : deposits) stats->depositedFlux += d.flux;
    stats->traceMs = walk::millisecondsSince(begin);
  }
  return deposits;
}

uint64_t walk::normalBucket(const glm::vec3& n) {
  const glm::vec3 a = glm::abs(n);
  const uint64_t axis = a.x >= a.y && a.x >= a.z ? 0 : a.y >= a.z ? 1 : 2;
  return axis * 2 + (n[int(axis)] < 0.0f ? 1 : 0);
}

uint64_t walk::cellKey(const glm::vec3& position, const glm::vec3& normal, const glm::vec3& origin,
                       float cell) {
  const glm::uvec3 c = glm::uvec3(glm::clamp((position - origin) / cell, 0.0f, kCellSteps));
  return (uint64_t(c.x) << 43) | (uint64_t(c.y) << 23) | (uint64_t(c.z) << 3) | normalBucket(normal);
}

namespace {

std::vector<std::pair<uint64_t, uint32_t>> keyDeposits(const std::vector<PhotonDeposit>& deposits,
                                                       const glm::vec3& origin, float cell) {
  std::vector<std::pair<uint64_t, uint32_t>> keys(deposits.size());
  for (uint32_t i = 0; i < deposits.size(); ++i)
    keys[i] = {walk::cellKey(deposits[i].position, deposits[i].normal, origin, cell), i};
  // On every core (TBB through the standard's parallel algorithms): the bisection sorts the deposits
  // about a dozen times, 4.4 s for 2.2 million on one H200 host core.
  std::sort(std::execution::par_unseq, keys.begin(), keys.end());
  return keys;
}

size_t countCells(const std::vector<std::pair<uint64_t, uint32_t>>& keys) {
  size_t count = 0;
  for (size_t i = 0; i < keys.size(); ++i) count += i == 0 || keys[i].first != keys[i - 1].first;
  return count;
}

}  // namespace

float walk::finestCellEdge(const std::vector<PhotonDeposit>& deposits, uint32_t target,
                           const glm::vec3& origin, float diagonal) {
  return deposits.size() <= target ? diagonal / kCellSteps
                                   : mergeCellEdge(deposits, target, origin, diagonal);
}

Bounds walk::depositBounds(const std::vector<PhotonDeposit>& deposits) {
  Bounds bounds;
  for (const PhotonDeposit& d : deposits) bounds.expand(d.position);
  return bounds;
}

float walk::mergeCellEdge(const std::vector<PhotonDeposit>& deposits, uint32_t target,
                          const glm::vec3& origin, float diagonal) {
  // Bisect the cell edge in log space: the largest is one cell over everything (at most six
  // buckets, under any target >= 6), the smallest the key's resolution.
  float lo = diagonal / kCellSteps, hi = 2.0f * diagonal;
  while (hi / lo > 1.01f) {
    const float mid = std::sqrt(lo * hi);
    (countCells(keyDeposits(deposits, origin, mid)) <= target ? hi : lo) = mid;
  }
  return hi;
}

float vplCutoffIrradiance(double surfaceArea, const std::vector<PhotonDeposit>& deposits, float cutoff) {
  double flux = 0.0;
  for (const PhotonDeposit& d : deposits) flux += std::max({d.flux.r, d.flux.g, d.flux.b});
  const double area = std::max(2.0 * surfaceArea, 1e-12);
  return float(std::max(double(cutoff) * flux / area, 1e-30));
}

std::vector<Light> walk::mergeOnGrid(const std::vector<PhotonDeposit>& deposits, const glm::vec3& origin,
                                     float cell, float nearDistance, const VplReach& reach) {
  std::vector<Light> vpls;
  const auto keys = keyDeposits(deposits, origin, cell);
  for (size_t first = 0; first < keys.size();) {
    size_t last = first;
    glm::vec3 flux(0.0f), position(0.0f), normal(0.0f);
    float weight = 0.0f;
    for (; last < keys.size() && keys[last].first == keys[first].first; ++last) {
      const PhotonDeposit& d = deposits[keys[last].second];
      const float w = depositWeight(d.flux);
      flux += d.flux;
      position += d.position * w;
      normal += d.normal * w;
      weight += w;
    }
    const float n = glm::length(normal);
    vpls.push_back(makeVpl(position / weight, n > 0.0f ? normal / n : deposits[keys[first].second].normal,
                           flux, nearDistance, reach));
    first = last;
  }
  return vpls;
}

std::vector<Light> mergeDeposits(const std::vector<PhotonDeposit>& deposits, uint32_t target,
                                 float unmergedNearDistance, const VplReach& reach, PhotonStats* stats) {
  const auto begin = std::chrono::steady_clock::now();
  std::vector<Light> vpls;
  auto finish = [&](float cell) {
    if (stats) {
      stats->cellSize = cell;
      stats->vpls = vpls.size();
      stats->mergeMs = walk::millisecondsSince(begin);
    }
    return vpls;
  };
  if (target == 0 || deposits.size() <= target) {
    vpls.reserve(deposits.size());
    for (const PhotonDeposit& d : deposits)
      vpls.push_back(makeVpl(d.position, d.normal, d.flux, unmergedNearDistance, reach));
    return finish(0.0f);
  }
  const Bounds bounds = walk::depositBounds(deposits);
  const float hi = walk::mergeCellEdge(deposits, target, bounds.min, walk::boundsDiagonal(bounds));
  vpls = walk::mergeOnGrid(deposits, bounds.min, hi, 0.5f * hi, reach);
  return finish(hi);
}

namespace {

// The lighting grid hierarchy over the deposits, its finest level's edge the merge's for the target
// (every deposit apart when there are no more of them than that).
std::vector<Light> hierarchyOver(const std::vector<PhotonDeposit>& deposits, const Bounds& sceneBounds,
                                 const VplOptions& options, float minNear, PhotonStats* stats) {
  const auto begin = std::chrono::steady_clock::now();
  const Bounds bounds = walk::depositBounds(deposits);
  const float diagonal = walk::boundsDiagonal(bounds);
  const float finest = walk::finestCellEdge(deposits, options.vplCount, bounds.min, diagonal);
  const float reach = sceneBounds.valid() ? std::max(glm::length(sceneBounds.extent()), diagonal) : diagonal;
  VplHierarchy h = buildVplHierarchy(deposits, bounds.min, finest, options.alpha, reach, minNear);
  if (stats) {
    stats->cellSize = finest;
    stats->levels = uint32_t(h.levels.size());
    stats->vpls = h.lights.size();
    stats->mergeMs = walk::millisecondsSince(begin);
  }
  return std::move(h.lights);
}

}  // namespace

std::vector<Light> makeVirtualPointLights(const Scene& scene, const VplOptions& options, PhotonStats* stats) {
  const RayScene rays(scene);
  const std::vector<PhotonDeposit> deposits = tracePhotons(rays, scene, options, stats);
  const Bounds bounds = scene.worldBounds();
  const float unmergedNear = bounds.valid() ? 1e-3f * glm::length(bounds.extent()) : 1e-3f;
  if (options.hierarchy) return hierarchyOver(deposits, bounds, options, unmergedNear, stats);
  const VplReach reach{vplCutoffIrradiance(rays.surfaceArea(), deposits, options.cutoff), options.range};
  return mergeDeposits(deposits, options.vplCount, unmergedNear, reach, stats);
}

}  // namespace lll::gi
