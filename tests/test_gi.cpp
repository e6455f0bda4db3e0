// Instant radiosity (gi/photons.h): the photon tracer's energy against the analytic sphere room,
// the merge's bounds, determinism, the Cornell room's colour bleeding, every technique against
// forward with the same VPLs, and bad --gi options on the command line.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "cli_test_support.h"
#include "gi/brdf.h"
#include "gi/path_tracer.h"
#include "gi/photons.h"
#include "gi/ray_scene.h"
#include "gi_test_support.h"
#include "render/image_compare.h"
#include "scene/builtin_gi_scenes.h"
#include "test_support.h"

namespace lll {
namespace {

using test::kPi;

float maxChannel(const glm::vec3& c) {
  return std::max({c.r, c.g, c.b});
}

gi::PhotonStats traceOnly(const Scene& scene, gi::VplOptions options,
                          std::vector<gi::PhotonDeposit>* out = nullptr) {
  const gi::RayScene rays(scene);
  gi::PhotonStats stats;
  auto deposits = gi::tracePhotons(rays, scene, options, &stats);
  if (out) *out = std::move(deposits);
  return stats;
}

// Inside the closed sphere every photon lands: the first deposits carry exactly rho times what the
// light emitted (its range window is 1 - 1e-10 at the wall); each later bounce rho times the one
// before, in expectation (Russian roulette).
TEST(Photons, SphereRoomDepositsTheAlbedoPerBounce) {
  const Scene scene = builtin::makeSphereRoom();
  const float rho = builtin::kSphereRoomAlbedo;
  gi::VplOptions options;
  options.photons = 20000;
  options.bounces = 1;
  const gi::PhotonStats one = traceOnly(scene, options);
  const float emitted = 4.0f * kPi * builtin::kSphereRoomIntensity;
  EXPECT_NEAR(one.emittedFlux.r, emitted, 1e-3f * emitted);
  EXPECT_EQ(one.deposits, options.photons);
  EXPECT_NEAR(one.depositedFlux.r, rho * emitted, 1e-3f * emitted);

  options.bounces = 3;
  const gi::PhotonStats three = traceOnly(scene, options);
  const float expected = (rho + rho * rho + rho * rho * rho) * emitted;
  // Survival is a coin of probability rho per bounce: with 20,000 photons the sum's standard error
  // is under 0.5% of it.
  EXPECT_NEAR(three.depositedFlux.r, expected, 0.02f * expected);
  std::printf("[ photons ] sphere room: 3 bounces deposit %.4f of the emitted flux (analytic %.4f)\n",
              three.depositedFlux.r / emitted, expected / emitted);
}

// The sun's photons: straight down on the 40 m plane (albedo 0.8), the first deposits carry
// albedo x illuminance x the plane's area, whichever of the disk's photons land on it.
TEST(Photons, SunDepositsItsIlluminanceTimesTheLitArea) {
  Scene scene = makeBuiltinScene("plane").value();
  scene.lights.clear();
  DirectionalLight sun;
  sun.direction = {0.0f, -1.0f, 0.0f};
  sun.illuminance = 2.0f;
  scene.directionalLights = {sun};
  gi::VplOptions options;
  options.photons = 40000;
  options.bounces = 1;
  const gi::PhotonStats s = traceOnly(scene, options);
  const float expected = 0.8f * 2.0f * 40.0f * 40.0f;
  // About 64% of the disk's photons land on the square: a binomial count's error is under 0.5%.
  EXPECT_NEAR(s.depositedFlux.r, expected, 0.02f * expected);
  std::printf("[ photons ] sun on the plane: %.1f deposited, analytic %.1f\n", s.depositedFlux.r, expected);
}

TEST(Photons, NoPhotonLeavesMoreThanTheAlbedoAllows) {
  const Scene scene = builtin::makeCornell();
  gi::VplOptions options;
  options.photons = 20000;
  options.bounces = 4;
  std::vector<gi::PhotonDeposit> deposits;
  const gi::PhotonStats s = traceOnly(scene, options, &deposits);
  ASSERT_GT(s.deposits, 0u);
  // Albedos are at most 0.75: each generation carries at most 0.75 of the one before, in expectation.
  const float bound = (0.75f + 0.5625f + 0.421875f + 0.31640625f) * maxChannel(s.emittedFlux);
  EXPECT_LE(maxChannel(s.depositedFlux), 1.05f * bound);
  // No light enters the sealed room behind the green wall (x > 5.6).
  for (const gi::PhotonDeposit& d : deposits) ASSERT_LT(d.position.x, 5.55f) << "a photon in the sealed room";
}

TEST(Photons, BlackSceneLeavesNoVpls) {
  Scene scene = builtin::makeCornell();
  for (Material& m : scene.materials) m.baseColorFactor = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  gi::VplOptions options;
  options.photons = 4000;
  const std::vector<Light> vpls = gi::makeVirtualPointLights(scene, options);
  EXPECT_TRUE(vpls.empty());
}

TEST(Photons, SameSeedSameVplsWhateverTheThreads) {
  const Scene scene = builtin::makeCornell();
  gi::VplOptions options;
  options.photons = 8000;
  options.vplCount = 500;
  options.threads = 1;
  const std::vector<Light> a = gi::makeVirtualPointLights(scene, options);
  options.threads = 3;
  const std::vector<Light> b = gi::makeVirtualPointLights(scene, options);
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a[i].position, b[i].position) << i;
    ASSERT_EQ(a[i].intensity, b[i].intensity) << i;
  }
  options.seed = 2;
  const std::vector<Light> c = gi::makeVirtualPointLights(scene, options);
  EXPECT_FALSE(c.size() == a.size() && c[0].position == a[0].position) << "another seed, the same VPLs";
}

// The merge keeps the target, keeps the flux, and never mixes the two sides of a wall.
TEST(Photons, MergeMeetsTheTargetAndKeepsTheFlux) {
  const Scene scene = builtin::makeCornell();
  gi::VplOptions options;
  options.photons = 20000;
  std::vector<gi::PhotonDeposit> deposits;
  const gi::PhotonStats s = traceOnly(scene, options, &deposits);
  for (uint32_t target : {64u, 512u, 4096u}) {
    gi::PhotonStats merged;
    const std::vector<Light> vpls = gi::mergeDeposits(deposits, target, 0.01f, {1e-6f}, &merged);
    EXPECT_LE(vpls.size(), target);
    EXPECT_GT(vpls.size(), target / 2) << "the cell edge is the smallest that meets the target, within 1%";
    glm::vec3 flux(0.0f);
    for (const Light& v : vpls) {
      flux += v.color * v.intensity * kPi;
      EXPECT_EQ(v.type, LightType::Vpl);
      EXPECT_NEAR(glm::length(v.direction), 1.0f, 1e-4f);
      EXPECT_FLOAT_EQ(v.nearDistance, 0.5f * merged.cellSize);
      // Every deposit on a wall faces into the room: so must the merged normal.
      if (v.position.x < 0.01f) {
        EXPECT_GT(v.direction.x, 0.9f);
      }
    }
    EXPECT_NEAR(flux.r, s.depositedFlux.r, 1e-3f * s.depositedFlux.r);
    EXPECT_NEAR(flux.g, s.depositedFlux.g, 1e-3f * s.depositedFlux.g);
  }
}

// Irradiance the VPLs put on a point of a surface with normal n, as brdf.glsl's attenuation does.
glm::vec3 vplIrradiance(const std::vector<Light>& vpls, const glm::vec3& p, const glm::vec3& n) {
  glm::vec3 sum(0.0f);
  for (const Light& v : vpls) {
    const glm::vec3 toLight = v.position - p;
    const float d = glm::length(toLight);
    const glm::vec3 l = toLight / d;
    sum += v.color * v.intensity * gi::lightAttenuation(v, l, d) * std::max(glm::dot(n, l), 0.0f);
  }
  return sum;
}

// Colour bleeding: no direct light reaches the floor beside the red wall, the VPLs make it red.
TEST(Gi, CornellFloorBesideTheRedWallIsRed) {
  SceneRequest request{"cornell"};
  request.gi.mode = GiMode::VplOnly;
  const Scene scene = loadScene(request);
  const glm::vec3 floor(0.4f, 0.0f, 2.75f), up(0.0f, 1.0f, 0.0f);
  const glm::vec3 e = vplIrradiance(scene.lights, floor, up);
  std::printf("[ gi ] cornell floor beside the red wall: irradiance %.4f %.4f %.4f\n", e.r, e.g, e.b);
  EXPECT_GT(e.r, 0.01f);
  EXPECT_GT(e.r, 3.0f * e.g);
  EXPECT_GT(e.r, 3.0f * e.b);
  // The spot's cone misses it: the light there is indirect only.
  const Light spot = builtin::makeCornell().lights[0];
  const glm::vec3 l = glm::normalize(floor - spot.position);
  EXPECT_LT(glm::dot(l, spot.direction), std::cos(spot.outerConeAngle));
}

// The analytic sphere room rendered: indirect irradiance rho * I / R^2 after one bounce and
// (rho + rho^2 + rho^3) * I / R^2 after three, uniform over the sphere. The renderer's BRDF is
// glTF's (a Fresnel-weighted diffuse and a GGX lobe), not Lambert: the scale is taken from a render
// of a uniform ambient of the same irradiance (ambient radiance times base colour), so the test
// checks the VPLs' energy and its uniformity, within 5% on average and 10% per pixel: one grid whose
// VPLs reach across the sphere, and the lighting grid hierarchy (gi/vpl_hierarchy.h).
TEST(Gi, SphereRoomMatchesTheAnalyticBounces) {
  const float rho = builtin::kSphereRoomAlbedo;
  const float direct =
      builtin::kSphereRoomIntensity / (builtin::kSphereRoomRadius * builtin::kSphereRoomRadius);
  RenderSettings settings;
  settings.width = 48;
  settings.height = 36;
  settings.technique = "forward";
  using enum GiHierarchy;
  for (const auto& [hierarchy, bounces] : {std::pair{None, 1u}, {None, 3u}, {Grid, 1u}, {Grid, 3u}}) {
    SCOPED_TRACE(fmt::format("{}, {} bounces", hierarchy, bounces));
    SceneRequest request{"sphere-room"};
    request.gi.mode = GiMode::VplOnly;
    request.gi.bounces = bounces;
    request.gi.photons = 50000;
    request.gi.vplCount = 2048;
    request.gi.hierarchy = hierarchy;
    request.gi.vplCutoff = 1e-6f;  // one grid: every VPL reaches across the sphere
    const Scene scene = loadScene(request);
    float geometric = 0.0f;
    for (uint32_t b = 1; b <= bounces; ++b) geometric += std::pow(rho, float(b));
    const float irradiance = direct * geometric;

    Scene ambientOnly = scene;
    ambientOnly.lights.clear();
    RenderSettings ambient = settings;
    ambient.ambient = irradiance / kPi;  // uniform radiance L gives irradiance pi * L
    const HdrImage expected = test::render(ambientOnly, ambient).hdr;
    settings.ambient = 0.0f;
    const HdrImage got = test::render(scene, settings).hdr;
    double sumRatio = 0.0, worst = 0.0;
    for (uint32_t y = 0; y < settings.height; ++y) {
      for (uint32_t x = 0; x < settings.width; ++x) {
        const double ratio = double(got.at(x, y).r) / double(expected.at(x, y).r);
        sumRatio += ratio;
        worst = std::max(worst, std::abs(ratio - 1.0));
      }
    }
    const double mean = sumRatio / double(settings.width * settings.height);
    std::printf(
        "[ gi ] sphere room, hierarchy %s, %u bounces: VPL render / analytic = %.4f on average, %.4f off at "
        "worst\n",
        std::string(nameOf(hierarchy)).c_str(), bounces, mean, worst);
    EXPECT_NEAR(mean, 1.0, 0.05);
    EXPECT_LT(worst, 0.10);
  }
}

// Every technique lights the Cornell room's VPLs as forward does (the indirect light alone, exposed
// so that it fills the display range): one grid with ranges from the cutoff, and the lighting grid
// hierarchy's bands.
TEST(Gi, EveryTechniqueMatchesForwardWithTheSameVpls) {
  for (const GiHierarchy hierarchy : {GiHierarchy::None, GiHierarchy::Grid}) {
    SCOPED_TRACE(nameOf(hierarchy));
    SceneRequest request{"cornell"};
    request.gi.mode = GiMode::VplOnly;
    request.gi.hierarchy = hierarchy;
    request.gi.photons = 20000;
    request.gi.vplCount = 1024;
    const Scene scene = loadScene(request);
    RenderSettings settings;
    settings.width = 96;
    settings.height = 72;
    settings.ambient = 0.0f;
    settings.exposure = 16.0f;
    const test::Rendered reference = test::render(scene, test::reference(settings));
    EXPECT_GT(test::shareAboveBlack(reference.ldr), 0.9) << "the indirect light should show everywhere";
    for (const char* technique : {"lll", "tiled", "clustered", "deferred", "prepass"}) {
      settings.technique = technique;
      const test::ImageBound bound = settings.technique == "prepass" ? test::kPrepassBound : test::kSameImage;
      test::expectWithinBound(test::render(scene, settings).ldr, reference.ldr, bound,
                              fmt::format("cornell VPLs, hierarchy {}, {}", hierarchy, technique));
    }
  }
}

// The block error: 0 for the same image, exactly the scale for a scaled one, and blind to noise
// that averages out inside a block (as a reference's does, nearly).
TEST(Gi, RelativeBlockErrorMeasuresWhatBlocksShow) {
  std::vector<glm::vec3> rgb(8 * 4);
  for (size_t i = 0; i < rgb.size(); ++i) rgb[i] = glm::vec3(1.0f + 0.1f * float(i % 5), 0.5f, 0.25f);
  const HdrImage reference = HdrImage::fromRgb(8, 4, rgb);
  EXPECT_DOUBLE_EQ(relativeBlockError(reference, reference, 4), 0.0);
  std::vector<glm::vec3> scaled = rgb, noisy = rgb;
  for (glm::vec3& c : scaled) c *= 1.1f;
  for (size_t i = 0; i < noisy.size(); ++i)
    noisy[i] += glm::vec3((i % 2 == 0) ? 0.2f : -0.2f);  // +- in every row
  EXPECT_NEAR(relativeBlockError(HdrImage::fromRgb(8, 4, scaled), reference, 4), 0.1, 1e-6);
  EXPECT_NEAR(relativeBlockError(HdrImage::fromRgb(8, 4, noisy), reference, 2), 0.0, 1e-6);
  EXPECT_GT(relativeBlockError(HdrImage::fromRgb(8, 4, noisy), reference, 1), 0.1);
  EXPECT_THROW(relativeBlockError(reference, reference, 5), std::invalid_argument);
}

// Instant radiosity converges to the path-traced indirect light as the VPLs grow in number: in the
// Cornell room (convex: every surface sees every other, so unshadowed VPLs lose nothing) the
// error against `lll reference` (6x6-pixel blocks) falls from 32 to 256 to 2,048 VPLs.
TEST(Gi, ErrorAgainstTheReferenceFallsAsTheVplCountRises) {
  RenderSettings settings;
  settings.width = 48;
  settings.height = 36;
  settings.technique = "forward";
  settings.ambient = 0.0f;
  const HdrImage reference = test::cornellIndirectReference(settings.width, settings.height);
  double previous = 1e30;
  for (uint32_t count : {32u, 256u, 2048u}) {
    SceneRequest request{"cornell"};
    request.gi.mode = GiMode::VplOnly;
    request.gi.vplCount = count;
    request.gi.hierarchy = GiHierarchy::None;
    request.gi.vplCutoff = 1e-6f;  // every VPL reaches the whole room: only their number varies
    // 6x6-pixel blocks: the reference's per-pixel noise (13% at 1,024 samples) would hide the VPLs'
    // error, which varies slowly across the image; a block's mean has a sixth of it.
    const double error = relativeBlockError(test::render(loadScene(request), settings).hdr, reference, 6);
    std::printf("[ gi ] cornell, %u VPLs: %.4f relative RMS error against the path-traced reference\n", count,
                error);
    EXPECT_LT(error, previous) << count << " VPLs";
    previous = error;
  }
  // The reference's own noise over a block is ~2.2% (13% / 6): 2,048 VPLs measured 2.0%.
  EXPECT_LT(previous, 0.04) << "2,048 VPLs should be within the reference's noise";
}

// --vpl-range gives every VPL the same range, whatever its flux or the count.
TEST(Photons, FixedRangeOverridesTheCutoff) {
  const Scene scene = builtin::makeCornell();
  gi::VplOptions options;
  options.photons = 8000;
  options.vplCount = 256;
  options.range = 3.0f;
  for (const Light& v : gi::makeVirtualPointLights(scene, options))
    EXPECT_FLOAT_EQ(v.range, std::max(3.0f, 2.0f * v.nearDistance));
}

// ---- the command line ----

using test::CliTest;

TEST_F(CliTest, GiOptionsOutOfRange) {
  expectBadInput(render("cornell", {"--gi", "radiosity"}), {"--gi"});
  expectBadInput(render("cornell", {"--gi", "vpl", "--bounces", "0"}), {"--bounces"});
  expectBadInput(render("cornell", {"--gi", "vpl", "--bounces", "17"}), {"--bounces"});
  expectBadInput(render("cornell", {"--gi", "vpl", "--photons", "0"}), {"--photons"});
  expectBadInput(render("cornell", {"--gi", "vpl", "--vpl-count", "3"}), {"--vpl-count 3"});
  expectBadInput(render("cornell", {"--gi", "vpl", "--vpl-cutoff", "0"}), {"--vpl-cutoff"});
  expectBadInput(render("cornell", {"--gi", "vpl", "--vpl-cutoff", "nan"}), {"--vpl-cutoff"});
  expectBadInput(render("cornell", {"--gi", "vpl", "--vpl-range", "-1"}), {"--vpl-range"});
  expectBadInput(render("cornell", {"--gi", "vpl", "--vpl-hierarchy", "none", "--vpl-alpha", "2"}),
                 {"--vpl-alpha"});
  expectBadInput(render("cornell", {"--gi", "vpl", "--vpl-cutoff", "0.01", "--vpl-alpha", "2"}),
                 {"--vpl-alpha", "--vpl-cutoff"});
}

// The single grid's options (a cutoff, a fixed range, every deposit its own light) ask for the single
// grid when --vpl-hierarchy is not given; the hierarchy is the default otherwise.
TEST_F(CliTest, SingleGridOptionsAskForTheSingleGrid) {
  for (const std::vector<std::string>& single :
       {std::vector<std::string>{"--vpl-cutoff", "0.01"}, {"--vpl-range", "3"}, {"--vpl-count", "0"}, {}}) {
    std::vector<std::string> args = {"--gi", "vpl-only", "--photons", "3000"};
    args.insert(args.end(), single.begin(), single.end());
    const test::CliResult r = render("cornell", args);
    EXPECT_EQ(r.exitCode, 0) << r;
    EXPECT_EQ(test::contains(r.output, "hierarchy levels"), single.empty()) << r;
    std::filesystem::remove(outPng());
  }
}

}  // namespace
}  // namespace lll
