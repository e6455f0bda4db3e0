#include "gi/moving_vpls.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <functional>

#include "core/errors.h"
#include "gi/photon_walk.h"
#include "gi/random.h"
#include "gi/ray_scene.h"
#include "gi/sampling.h"
#include "gi/vpl_hierarchy.h"
#include "scene/light_animation.h"

namespace lll {
namespace gi {
namespace {

using walk::millisecondsSince;

// Photons per task of a frame's parallel trace.
constexpr uint32_t kChunk = 256;

// Where traceInto looks up the cells of what it traced, on every level (read-only while the threads
// run).
struct CellLookup {
  const std::vector<std::unordered_map<uint64_t, uint32_t>>* cells = nullptr;  // per level
  const std::vector<VplLevel>* levels = nullptr;
  glm::vec3 origin{0.0f};
  uint32_t* out = nullptr;  // per deposit slot and level: its cell, or kNoCell when the cell is new
};
constexpr uint32_t kNoCell = ~0u;

// Traces photons[0 .. count) (indices of the whole trace, each from its own stream) into `slots`
// (options.bounces per photon) and `counts`, and looks up the cells their deposits land in.
void traceInto(const RayScene& rays, const walk::Emitters& emitters, const VplOptions& options,
               const uint32_t* photons, size_t count, PhotonDeposit* slots, uint8_t* counts,
               const CellLookup& lookup) {
  const uint32_t chunks = uint32_t((count + kChunk - 1) / kChunk);
  const size_t levels = lookup.levels->size();
  parallelFor(chunks, options.threads,
              [&](uint32_t c) {
                std::vector<PhotonDeposit> out;
                const size_t end = std::min(count, size_t(c + 1) * kChunk);
                for (size_t i = size_t(c) * kChunk; i < end; ++i) {
                  out.clear();
                  Random random(options.seed, photons[i]);
                  walk::tracePhoton(rays, emitters, options.photons, options.bounces, random, out);
                  counts[i] = uint8_t(out.size());
                  std::copy(out.begin(), out.end(), slots + i * options.bounces);
                  for (size_t k = 0; k < out.size(); ++k) {
                    for (size_t l = 0; l < levels; ++l) {
                      const auto& cells = (*lookup.cells)[l];
                      const auto found = cells.find(walk::cellKey(
                          out[k].position, out[k].normal, lookup.origin, (*lookup.levels)[l].cellEdge));
                      lookup.out[(i * options.bounces + k) * levels + l] =
                          found == cells.end() ? kNoCell : found->second;
                    }
                  }
                }
              },
              {});
}

bool sameDeposits(const PhotonDeposit* a, uint8_t countA, const PhotonDeposit* b, uint8_t countB) {
  return countA == countB && std::memcmp(a, b, sizeof(PhotonDeposit) * countA) == 0;
}

}  // namespace

MovingVpls::MovingVpls(const MovingVpls&) = default;
MovingVpls::~MovingVpls() = default;

std::shared_ptr<MovingVpls> cloneMovingVpls(const MovingVpls& vpls) {
  return std::make_shared<MovingVpls>(vpls);
}

MovingVpls::MovingVpls(const Scene& scene, const VplOptions& options, uint32_t retracePerFrame,
                       uint32_t maxSlots, std::vector<VplLevel> grids, PhotonStats* stats)
    : rays_(std::make_shared<const RayScene>(scene, RayScene::Keep::OwnMaterials)),
      lights_(scene.lights),
      suns_(scene.directionalLights),
      animation_(scene.lightAnimation),
      bounds_(scene.worldBounds()),
      options_(options),
      retracePerFrame_(retracePerFrame) {
  options_.progress = nullptr;  // the caller's progress bar is for the first trace only
  if (!bounds_.valid()) bounds_.expand(glm::vec3(0.0f));
  const float diagonal = std::max(glm::length(bounds_.extent()), 1e-6f);

  // The first trace, every photon, with the photon each deposit came from.
  PhotonStats traced;
  std::vector<uint32_t> owners;
  const std::vector<PhotonDeposit> all = tracePhotons(*rays_, scene, options, &traced, &owners);

  // Which photons leave a moving light: their stream's first draw picks it, wherever it is.
  const walk::Emitters emitters = walk::chooseEmitters(lights_, suns_, bounds_);
  const size_t firstMoving = animation_.first, endMoving = firstMoving + animation_.motions.size();
  for (uint32_t p = 0; p < traced.photons; ++p) {
    Random random(options.seed, p);
    const Light* light = emitters.sources[walk::pickEmitter(emitters, random)].light;
    const size_t index = light ? size_t(light - lights_.data()) : ~size_t(0);
    if (index >= firstMoving && index < endMoving) movingPhotons_.push_back(p);
  }
  const size_t slotsNeeded = movingPhotons_.size() * options.bounces;
  if (slotsNeeded > (size_t(1) << 26))
    throw InputError(
        fmt::format("--gi with moving lights: {} photons of the moving lights x {} bounces would hold {} "
                    "deposits to trace again (at most {}); lower --photons or --bounces",
                    movingPhotons_.size(), options.bounces, slotsNeeded, size_t(1) << 26));
  movingDeposits_.resize(slotsNeeded);
  movingCounts_.resize(movingPhotons_.size(), 0);
  // The moving photons' deposits, kept per photon (both lists ascend).
  for (size_t i = 0, k = 0; i < all.size(); ++i) {
    while (k < movingPhotons_.size() && movingPhotons_[k] < owners[i]) ++k;
    if (k < movingPhotons_.size() && movingPhotons_[k] == owners[i])
      movingDeposits_[k * options.bounces + movingCounts_[k]++] = all[i];
  }

  // The grids, fixed from now on: the merge's edge for the target, and with the hierarchy its levels
  // as the load's deposits give them (their bands too); without it one grid whose VPLs' ranges come
  // from the cutoff.
  const auto mergeBegin = std::chrono::steady_clock::now();
  const float minNear = 1e-3f * diagonal;
  if (!grids.empty()) {
    levels_ = std::move(grids);
  } else if (options.vplCount == 0) {
    throw InputError(
        "--vpl-count 0 keeps every deposit as its own light, but with moving lights (--animate, --time) the "
        "deposits are merged on a fixed grid: give a count, or --vpl-retrace 0 to leave the VPLs where they "
        "are first traced");
  } else {
    const float finest = walk::finestCellEdge(all, options.vplCount, bounds_.min, diagonal);
    if (options.hierarchy)
      levels_ = buildVplHierarchy(all, bounds_.min, finest, options.alpha, diagonal, minNear).levels;
    if (levels_.empty())
      levels_ = {
          VplLevel{finest, std::max(0.5f * finest, minNear), 0.0f, options.hierarchy ? diagonal : 0.0f}};
  }
  cellOf_.resize(levels_.size());
  reach_ = {vplCutoffIrradiance(rays_->surfaceArea(), all, options.cutoff), options.range};
  const uint32_t levels = uint32_t(levels_.size());
  for (const PhotonDeposit& d : all)
    for (uint32_t l = 0; l < levels; ++l) add(cellFor(d, l), d, 1.0);
  movingCells_.resize(movingDeposits_.size() * levels);
  for (size_t k = 0; k < movingCounts_.size(); ++k)
    for (size_t i = 0; i < movingCounts_[k]; ++i)
      for (uint32_t l = 0; l < levels; ++l)
        movingCells_[(k * options.bounces + i) * levels + l] =
            cellFor(movingDeposits_[k * options.bounces + i], l);

  // Slots: the load's lit cells in key order, then room for the cells the moving lights reach later.
  const uint32_t lit = uint32_t(cells_.size());
  if (lit > maxSlots)
    throw InputError(
        fmt::format("--gi: {} virtual point lights and the scene's other lights exceed the {} supported; "
                    "lower --vpl-count",
                    lit, maxSlots));
  const uint32_t capacity = uint32_t(std::min<uint64_t>(maxSlots, uint64_t(lit) + std::max(lit / 4, 64u)));
  vpls_.assign(capacity, darkVpl(bounds_.center()));
  std::vector<uint32_t> order(lit);
  for (uint32_t i = 0; i < lit; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
    return std::pair(cells_[a].level, cells_[a].key) < std::pair(cells_[b].level, cells_[b].key);
  });
  for (uint32_t i = 0; i < lit; ++i) cells_[order[i]].slot = int32_t(i);
  for (uint32_t slot = lit; slot < capacity; ++slot) freeSlots_.push_back(slot);
  std::make_heap(freeSlots_.begin(), freeSlots_.end(), std::greater<>());
  stats_.litSlots = lit;
  refreshDirtyCells();
  changedSlots_.clear();

  stats_.movingPhotons = movingPhotons_.size();
  stats_.slots = capacity;
  if (stats) {
    *stats = traced;
    stats->mergeMs = millisecondsSince(mergeBegin);
    stats->cellSize = levels_[0].cellEdge;
    stats->levels = banded() ? levels : 0;
    stats->vpls = stats_.litSlots;
  }
}

Light MovingVpls::darkVpl(const glm::vec3& position) const {
  Light dark;
  dark.type = LightType::Vpl;
  dark.position = position;
  dark.direction = glm::vec3(0.0f, 1.0f, 0.0f);
  dark.color = glm::vec3(0.0f);
  dark.intensity = 0.0f;
  dark.nearDistance = levels_[0].nearDistance;
  dark.range = 2.0f * dark.nearDistance;
  return dark;
}

uint32_t MovingVpls::cellFor(const PhotonDeposit& d, uint32_t level) {
  const uint64_t key = walk::cellKey(d.position, d.normal, bounds_.min, levels_[level].cellEdge);
  const auto [it, inserted] = cellOf_[level].try_emplace(key, uint32_t(cells_.size()));
  if (inserted) cells_.push_back(Cell{.key = key, .level = level});
  return it->second;
}

void MovingVpls::add(uint32_t index, const PhotonDeposit& d, double sign) {
  Cell& c = cells_[index];
  const double w = walk::depositWeight(d.flux);
  if (sign > 0.0) {
    ++c.deposits;
    c.lastPosition = d.position;
  } else {
    --c.deposits;
  }
  if (c.deposits == 0) {  // no residue of the sums' rounding in an empty cell
    c.flux = c.position = c.normal = glm::dvec3(0.0);
    c.weight = 0.0;
  } else {
    c.flux += sign * glm::dvec3(d.flux);
    c.position += (sign * w) * glm::dvec3(d.position);
    c.normal += (sign * w) * glm::dvec3(d.normal);
    c.weight += sign * w;
  }
  if (!c.dirty) {
    c.dirty = true;
    dirty_.push_back(index);
  }
}

void MovingVpls::refresh(uint32_t index) {
  Cell& c = cells_[index];
  const bool wasDropped = c.dropped;
  c.dropped = false;
  if (c.deposits == 0) {
    if (c.slot >= 0) {
      vpls_[size_t(c.slot)] = darkVpl(c.lastPosition);
      changedSlots_.push_back(uint32_t(c.slot));
      freeSlots_.push_back(uint32_t(c.slot));
      std::push_heap(freeSlots_.begin(), freeSlots_.end(), std::greater<>());
      c.slot = -1;
      --stats_.litSlots;
    }
  } else if (c.slot < 0 && freeSlots_.empty()) {
    c.dropped = true;  // until a slot frees and the cell changes again
  } else {
    if (c.slot < 0) {
      std::pop_heap(freeSlots_.begin(), freeSlots_.end(), std::greater<>());
      c.slot = int32_t(freeSlots_.back());
      freeSlots_.pop_back();
      ++stats_.litSlots;
    }
    const double n = glm::length(c.normal);
    glm::vec3 normal(0.0f);
    if (n > 0.0) {
      normal = glm::vec3(c.normal / n);
    } else {  // opposite normals cancelled: the way the cell's bucket leans
      const uint64_t bucket = c.key & 7u;
      normal[int(bucket / 2)] = bucket & 1u ? -1.0f : 1.0f;
    }
    const glm::vec3 position = c.weight > 0.0 ? glm::vec3(c.position / c.weight) : c.lastPosition;
    const VplLevel& level = levels_[c.level];
    Light& vpl = vpls_[size_t(c.slot)];
    vpl = makeVpl(position, normal, glm::max(glm::vec3(c.flux), glm::vec3(0.0f)), level.nearDistance, reach_);
    if (banded()) setVplBand(vpl, level);
    changedSlots_.push_back(uint32_t(c.slot));
  }
  stats_.droppedCells = stats_.droppedCells + (c.dropped ? 1u : 0u) - (wasDropped ? 1u : 0u);
}

void MovingVpls::refreshDirtyCells() {
  // The emptied cells first: the slots they free go to the cells lit in the same update.
  std::stable_partition(dirty_.begin(), dirty_.end(),
                        [&](uint32_t cell) { return cells_[cell].deposits == 0; });
  for (const uint32_t cell : dirty_) {
    refresh(cell);
    cells_[cell].dirty = false;
  }
  dirty_.clear();
}

void MovingVpls::moveTo(float seconds, std::vector<Light>& lights, uint32_t first) {
  const auto begin = std::chrono::steady_clock::now();
  if (uint64_t(first) + vpls_.size() > lights.size())
    throw InputError(fmt::format("moving VPLs: {} slots from light {}, but the scene has {} lights",
                                 vpls_.size(), first, lights.size()));
  if (!animation_.empty()) placeLightsAt(lights_, animation_, seconds);
  stats_.retraced = 0;
  changedSlots_.clear();
  const size_t moving = movingPhotons_.size();
  if (moving > 0 && retracePerFrame_ > 0) {
    const walk::Emitters emitters = walk::chooseEmitters(lights_, suns_, bounds_);
    const size_t count = std::min<size_t>(retracePerFrame_, moving);
    std::vector<uint32_t> photons(count), which(count);
    for (size_t k = 0; k < count; ++k) {
      which[k] = uint32_t((cursor_ + k) % moving);
      photons[k] = movingPhotons_[which[k]];
    }
    const uint32_t bounces = options_.bounces;
    std::vector<PhotonDeposit> slots(count * bounces);
    std::vector<uint8_t> counts(count);
    const auto traceBegin = std::chrono::steady_clock::now();
    const uint32_t levels = uint32_t(levels_.size());
    std::vector<uint32_t> cells(count * bounces * levels);
    const CellLookup lookup{&cellOf_, &levels_, bounds_.min, cells.data()};
    traceInto(*rays_, emitters, options_, photons.data(), count, slots.data(), counts.data(), lookup);
    stats_.traceMs = millisecondsSince(traceBegin);
    const auto mergeBegin = std::chrono::steady_clock::now();
    // In photon order, so that the sums do not depend on the threads. A photon that lands where it
    // did (its light did not move) changes nothing, not even the sums' rounding.
    for (size_t k = 0; k < count; ++k) {
      const size_t stored = size_t(which[k]) * bounces;
      PhotonDeposit* old = movingDeposits_.data() + stored;
      uint32_t* oldCells = movingCells_.data() + stored * levels;
      const PhotonDeposit* fresh = slots.data() + k * bounces;
      if (sameDeposits(old, movingCounts_[which[k]], fresh, counts[k])) continue;
      for (uint8_t i = 0; i < movingCounts_[which[k]]; ++i)
        for (uint32_t l = 0; l < levels; ++l) add(oldCells[i * levels + l], old[i], -1.0);
      for (uint8_t i = 0; i < counts[k]; ++i) {
        for (uint32_t l = 0; l < levels; ++l) {
          const uint32_t found = cells[(k * bounces + i) * levels + l];
          uint32_t& cell = oldCells[i * levels + l];
          cell = found != kNoCell ? found : cellFor(fresh[i], l);
          add(cell, fresh[i], 1.0);
        }
      }
      std::copy(fresh, fresh + counts[k], old);
      movingCounts_[which[k]] = counts[k];
    }
    cursor_ = (cursor_ + count) % moving;
    stats_.retraced = count;
    refreshDirtyCells();
    stats_.mergeMs = millisecondsSince(mergeBegin);
  }
  for (const uint32_t slot : changedSlots_) lights[first + slot] = vpls_[slot];
  changedSlots_.clear();
  stats_.retraceMs = millisecondsSince(begin);
}

}  // namespace gi
}  // namespace lll
