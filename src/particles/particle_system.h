#pragma once
// A GPU particle system (issue 4): compute shaders spawn, simulate and kill particles in fixed
// steps, sort them back to front and write indirect draw arguments; techniques then draw them as
// camera-facing quads lit like their own surfaces (the light linked list's tile lists, every light,
// or none). The renderer owns one system when --particles is given and records, each frame after
// the depth prepass:
//   particles-simulate  one fixed step (spawn, move, kill)
//   particles-sort      keys (view depth, frustum culling), then the bitonic sort
//   particles-indirect  visible count -> VkDrawIndirectCommand (+ the lighting pass's dispatch)
// and the renderer calls draw() after the technique's glass: particles-light (--particle-lighting
// vertex), then particles-draw (raster) or particles-bin and particles-composite (compute).
// Particles and glass are each sorted, but not against each other: glass is already in the frame
// when the particles are blended over it, so a particle behind a pane shows in front of it.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "gpu/pipeline.h"
#include "gpu/resources.h"
#include "particles/bitonic_sort.h"
#include "particles/presets.h"
#include "render/lighting_interface.h"
#include "render/settings.h"
#include "shared/light_bins_types.h"
#include "shared/particle_types.h"

namespace lll {

class Context;
struct FrameContext;
struct FrameTargets;

// Which particles a draw blends, by depth against the scene's glass (ParticleSystem::draw).
enum class ParticleLayer {
  All,             // no glass in the scene: every particle, after the glass pass (which draws nothing)
  BehindGlass,     // before the glass: particles behind the nearest glass at their pixel
  InFrontOfGlass,  // after the glass: the rest, depth-tested and faded against the glass
};
// constant_id of kBehindGlass in particles/draw_fragment.glsl (the draw before the glass) and
// lit/particles_tiles.comp.glsl (the composite that blends both layers, before the glass).
inline constexpr uint32_t kBehindGlassConstant = 50;
// The depth image a layer tests and fades against, the one it clips against (binding 25: the glass
// depth before the glass; the scene depth as a stand-in the shaders never read otherwise), and the
// suffix of its pass names.
const Image& particleSceneDepth(const FrameTargets& targets, ParticleLayer layer);
// The same depth for passes that only sample it (FrameTargets::sampledDepth: the compute
// rasterizer's own depth where it will do).
const Image& particleSampledDepth(const FrameTargets& targets, ParticleLayer layer);
const Image& particleGlassDepth(const FrameTargets& targets, ParticleLayer layer);
const char* particlePassSuffix(ParticleLayer layer);

// The compute renderer's workgroups a tile when --particle-tile-groups does not say: slabs x scale
// / 8, at least 4 (or one a slab) and at most kParticleMaxGroups, fitted on the H200
// (particle_tiles.cpp, bench/README.md).
uint32_t defaultParticleTileGroups(uint32_t slabs, uint32_t scale);

struct ParticleSystemOptions {
  ParticlePreset preset;
  glm::vec3 source{0.0f};  // the emitter's point: the scene's smoke source or --particle-emitter
  uint32_t count = 0;      // slots; 0: the preset's count
  uint32_t seed = 1;
  ParticleLighting lighting = ParticleLighting::Pixel;
  ParticleRender render = ParticleRender::Auto;
  uint32_t resolutionScale = 1;  // particleResolutionScale; above 1 needs the compute renderer
  uint32_t tileGroups = 0;       // the compute renderer's workgroups a tile (1 to 8); 0: its choice
};

class ParticleSystem {
 public:
  ParticleSystem(Context& context, const ParticleSystemOptions& options);
  ~ParticleSystem();
  ParticleSystem(const ParticleSystem&) = delete;
  ParticleSystem& operator=(const ParticleSystem&) = delete;

  // Records `steps` fixed steps without timing them (the steps before the drawn frame).
  void recordSteps(VkCommandBuffer cmd, uint32_t steps);
  // The frame's particle passes before the technique: simulate one step when `advance` (not when
  // the renderer records the same frame again), then sort for the frame's camera and build the
  // indirect arguments.
  void update(FrameContext& frame, bool advance);
  // The particle passes, lit by the technique's lighting interface (per particle in particles-light
  // with --particle-lighting vertex or atlas, per pixel in particles-draw otherwise). `layer`:
  // All after the glass in a scene without glass; with glass BehindGlass before the glass (only
  // what lies behind the nearest glass at each pixel, FrameTargets::glassDepth) and InFrontOfGlass
  // after it (tested against glassDepth). The first call of a frame lights and bins the particles.
  void draw(FrameContext& frame, const LightingInterface& lighting, ParticleLayer layer = ParticleLayer::All);

  // Once the frame completed: true when the compute renderer's tile entries did not fit, with a
  // larger array allocated; the frame must then be drawn again (without advancing).
  bool afterFrame();

  // Raster or Compute: what Auto became on this device.
  ParticleRender render() const { return render_; }
  uint64_t steps() const { return steps_; }
  const ParticlePreset& preset() const { return preset_; }
  std::vector<std::pair<std::string, double>> stats() const;

  // Read back after a frame (for tests and tools): every slot, the sorted (key, slot) pairs of the
  // last frame (visible particles first, back to front), and the counters.
  std::vector<gpu::Particle> readParticles() const;
  std::vector<glm::uvec2> readDrawOrder() const;
  gpu::ParticleCounters readCounters() const;

 private:
  struct DrawPipelines {
    PipelineLayout drawLayout;
    Pipeline draw;
    Pipeline drawBehindGlass;  // with glass in the scene: the draw before it (constant 50)
    PipelineLayout lightLayout;
    Pipeline light;                  // the per-particle lighting pass (vertex lighting); empty otherwise
    PipelineLayout compositeLayout;  // --particle-render compute: particles-composite
    Pipeline composite;              // with glass in the scene: both layers about it (constant 50)
  };
  // The compute renderer's tiles (particle_tiles.cpp), made for the frame's size on first use.
  struct Tiles {
    uint32_t width = 0, height = 0;
    gpu::ParticleTileHeader header{};
    uint64_t maxEntries = 0;
    uint32_t lastRequested = 0;
    uint32_t longestCell = 0;    // the most particles one tile's slab held in the last frame
    uint32_t stoppedGroups = 0;  // groups that stopped at an opaque group in front, last frame
    uint32_t unusedGroups = 0;   // groups a tile did not need (too few particles), last frame
    uint32_t overflows = 0;
    Buffer headerBuffer;
    Buffer cells;
    Buffer entries;
    Buffer screen;
    Buffer layers;     // each tile group's colour and transmittance per particle pixel
    Buffer opaque;     // per tile and group: 1 once the group made every pixel of its tile opaque
    Image layerDepth;  // below full resolution: the view depth each particle pixel was blended against
    // With glass, the same for the particles behind the nearest glass (the composite writes both).
    Buffer layersBehind;
    Image layerDepthBehind;
    PipelineLayout binLayout;
    Pipeline count;
    Pipeline scatter;
    PipelineLayout scanLayout;
    Pipeline scan[3];  // particles/tile_scan.comp's steps
    uint32_t scanBlocks = 0;
    Buffer blockSums;
    PipelineLayout mergeLayout;
    Pipeline merge[2];  // particles/merge_groups.comp without and with glass (constant 0)
    PipelineLayout resolveLayout;
    Pipeline resolve;
  };
  void createBuffers();
  void createNoise();
  void uploadUniforms(const glm::vec3& source, uint32_t seed);
  uint64_t spawnedBefore(uint64_t step) const;
  gpu::ParticleStepPush stepPush(uint64_t step) const;
  void recordStep(VkCommandBuffer cmd);
  void sort(FrameContext& frame);
  void buildIndirect(VkCommandBuffer cmd);
  const DrawPipelines& pipelinesFor(const FrameContext& frame, const LightingInterface& lighting);
  // Set 0 of the particle passes: the frame, the lights, the system's buffers (11 to 15, 22) and the
  // puffs' noise (31)...
  DescriptorWriter systemDescriptors(const FrameContext& frame) const;
  // ... and the lighting interface's light data.
  DescriptorWriter descriptors(const FrameContext& frame, const LightingInterface& lighting) const;
  void lightParticles(FrameContext& frame, const DrawPipelines& pipelines, const LightingInterface& lighting);
  void drawRaster(FrameContext& frame, const DrawPipelines& pipelines, const LightingInterface& lighting,
                  ParticleLayer layer);
  // particle_tiles.cpp
  void prepareTiles(const FrameContext& frame);
  void allocateTileEntries(uint64_t entries);
  void binTiles(FrameContext& frame);
  // Every layer at once: with glass in the scene, the particles in front of it and behind it.
  void composite(FrameContext& frame, const DrawPipelines& pipelines, const LightingInterface& lighting);
  // More than one group a tile: the groups combined into group 0's layers.
  void mergeGroups(FrameContext& frame);
  void resolve(FrameContext& frame, ParticleLayer layer);

  Context& context_;
  ParticlePreset preset_;
  ParticleLighting lighting_;
  ParticleRender render_;
  uint32_t resolutionScale_ = 1;
  uint32_t tileGroups_ = 0;
  uint32_t capacity_ = 0;
  double stepsPerLifetime_ = 0.0;  // the preset's longest lifetime, in steps
  uint64_t steps_ = 0;
  BitonicSort sorter_;
  Buffer uniforms_;
  Buffer particles_;
  Buffer drawOrder_;
  Buffer counters_;
  Buffer radiance_;  // --particle-lighting vertex: each visible particle's light
  Buffer atlas_;     // --particle-lighting atlas: each visible particle's light atlas
  VkSampler depthSampler_ = VK_NULL_HANDLE;
  // The puffs' noise (puff_noise.h): sampled, in SHADER_READ_ONLY_OPTIMAL from creation on.
  Image noise_;
  VkSampler noiseSampler_ = VK_NULL_HANDLE;
  PipelineLayout layout_;
  Pipeline simulate_;
  Pipeline keys_;
  Pipeline indirect_;
  Tiles tiles_;
  std::map<std::string, DrawPipelines> drawPipelines_;  // by lighting interface, made on first use
};

}  // namespace lll
