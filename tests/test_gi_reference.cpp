// The path-traced reference of indirect light (gi/path_tracer.h, `lll reference`): against the
// closed form of the sphere room, the colour bleeding and the sealed room of the Cornell scene, the
// renderer's own direct light and tonemap, thread-count determinism, and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "app/commands.h"
#include "cli_test_support.h"
#include "core/errors.h"
#include "gi/brdf.h"
#include "gi/path_tracer.h"
#include "gi/ray_scene.h"
#include "render/tonemap.h"
#include "scene/builtin_gi_scenes.h"
#include "scene/camera.h"
#include "scene/scene_source.h"
#include "test_support.h"

namespace lll {
namespace {

using test::kPi;

gi::RadianceImage renderBuiltin(const Scene& scene, const std::string& camera, gi::ReferenceOptions options,
                                uint32_t width = 32, uint32_t height = 24) {
  return gi::renderReference(scene, resolveCamera(scene, camera), width, height, options);
}

gi::ReferenceOptions indirectOnly(uint32_t bounces, uint32_t spp) {
  gi::ReferenceOptions options;
  options.indirectOnly = true;
  options.bounces = bounces;
  options.spp = spp;
  return options;
}

// The hemisphere integral of brdfCosine: the radiance a surface sends towards `s.view` under unit
// incoming radiance from every direction. Midpoint rule in (cos theta, phi): the integrand is
// smooth at roughness 1, and 64 x 64 cells are within 1e-4 of it.
glm::vec3 directionalAlbedo(const gi::BrdfSurface& s) {
  constexpr int kSteps = 64;
  const glm::vec3 helper = std::abs(s.normal.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  const glm::vec3 t = glm::normalize(glm::cross(helper, s.normal)), b = glm::cross(s.normal, t);
  glm::vec3 sum(0.0f);
  for (int i = 0; i < kSteps; ++i) {
    const float cosTheta = (float(i) + 0.5f) / kSteps, sinTheta = std::sqrt(1.0f - cosTheta * cosTheta);
    for (int j = 0; j < kSteps; ++j) {
      const float phi = 2.0f * kPi * (float(j) + 0.5f) / kSteps;
      sum += gi::brdfCosine(
          s, t * (sinTheta * std::cos(phi)) + b * (sinTheta * std::sin(phi)) + s.normal * cosTheta);
    }
  }
  return sum * (2.0f * kPi / (kSteps * kSteps));
}

TEST(GiReferenceBrdf, MatchesTheGltfFormulasAtNormalIncidence) {
  // l = v = n: F = 0.04, D = 1 / pi and V = 1 / 4 at roughness 1, so
  // f cos = (0.96 * 0.5 + 0.04 / 4) / pi = 0.49 / pi.
  const gi::BrdfSurface s{{0, 0, 1}, {0, 0, 1}, glm::vec3(0.5f), 0.0f, 1.0f};
  const glm::vec3 value = gi::brdfCosine(s, {0, 0, 1});
  EXPECT_NEAR(value.g, 0.49f / kPi, 1e-6f);
  EXPECT_EQ(gi::brdfCosine(s, {0, 0, -1}), glm::vec3(0.0f));
  // A white Lambertian-like surface reflects most, not more, of what arrives.
  const glm::vec3 albedo = directionalAlbedo({{0, 0, 1}, {0, 0, 1}, glm::vec3(1.0f), 0.0f, 1.0f});
  EXPECT_GT(albedo.g, 0.9f);
  EXPECT_LT(albedo.g, 1.0f);
}

TEST(GiReferenceBrdf, AttenuationIsTheRenderersWindowedInverseSquare) {
  Light point;
  point.intensity = 1.0f;
  point.range = 10.0f;
  const float window = std::pow(1.0f - std::pow(0.2f, 4.0f), 2.0f);
  EXPECT_NEAR(gi::lightAttenuation(point, {0, 1, 0}, 2.0f), window / 4.0f, 1e-6f);
  EXPECT_EQ(gi::lightAttenuation(point, {0, 1, 0}, 10.0f), 0.0f);
  Light spot = point;
  spot.type = LightType::Spot;
  spot.direction = {0, -1, 0};  // l points from the surface to the light: the light is above
  EXPECT_NEAR(gi::lightAttenuation(spot, {0, 1, 0}, 2.0f), window / 4.0f, 1e-6f);
  EXPECT_EQ(gi::lightAttenuation(spot, {1, 0, 0}, 2.0f), 0.0f);  // outside the cone
  Light vpl = point;
  vpl.type = LightType::Vpl;
  EXPECT_EQ(gi::lightAttenuation(vpl, {0, 1, 0}, 2.0f), 0.0f);
}

TEST(GiReferenceCamera, RaysGoThroughTheRenderersPixelCentres) {
  const Camera camera{"c", {1, 2, 3}, {-2, 0.5f, -1}, {0, 1, 0}, 1.1f};
  const uint32_t width = 40, height = 30;
  // renderer/renderer.cpp's matrices: lookAt, reverse-Z perspective, Vulkan's y down.
  glm::mat4 proj = glm::perspectiveRH_ZO(camera.yfov, float(width) / float(height), 100.0f, 0.01f);
  proj[1][1] *= -1.0f;
  const glm::mat4 inverse = glm::inverse(proj * glm::lookAt(camera.eye, camera.target, camera.up));
  const gi::PixelRays rays(camera, width, height);
  for (uint32_t y : {0u, 7u, 29u}) {
    for (uint32_t x : {0u, 13u, 39u}) {
      const glm::vec2 ndc((x + 0.5f) / width * 2.0f - 1.0f, (y + 0.5f) / height * 2.0f - 1.0f);
      const glm::vec4 far = inverse * glm::vec4(ndc, 0.0f, 1.0f);  // reverse-Z: depth 0 is far
      const glm::vec3 expected = glm::normalize(glm::vec3(far) / far.w - camera.eye);
      const glm::vec3 got = rays.direction(x, y);
      EXPECT_NEAR(glm::distance(got, expected), 0.0f, 1e-5f) << x << ", " << y;
    }
  }
}

// The sphere room's closed form: every point receives direct irradiance I / R^2, and after B
// bounces indirect irradiance I / R^2 (rho + ... + rho^B): the radiance arriving at any point from
// any direction is L = rho / pi * I / R^2 * (1 + ... + rho^(B-1)), and a pixel shows L times the
// directional albedo of the renderer's BRDF for its view (computed here by quadrature).
//
// Tolerance: the estimator's only randomness is the BRDF's shape against the cosine it is sampled
// with (the incoming radiance is the same everywhere), so pixels scatter about their expected value
// independently; the mean ratio image / expected must lie within 4 standard errors of that scatter,
// plus 0.5% for the tessellation: 96 x 48 flat facets lie inside the sphere by up to
// R (1 - cos(pi / 48)) = 0.1% of R, which raises 1/d^2 by up to 0.2%. Measured: 1.0012 (1 bounce)
// and 1.0010 (3 bounces), standard errors under 1e-4.
void expectSphereRoomClosedForm(uint32_t bounces) {
  const Scene scene = builtin::makeSphereRoom();
  const Camera camera = resolveCamera(scene, "");
  const uint32_t width = 32, height = 24;
  const gi::RadianceImage image = renderBuiltin(scene, "", indirectOnly(bounces, 8), width, height);

  const float rho = builtin::kSphereRoomAlbedo;
  float geometric = 0.0f;
  for (uint32_t b = 0; b < bounces; ++b) geometric += std::pow(rho, float(b));
  const float incoming = rho / kPi * builtin::kSphereRoomIntensity /
                         (builtin::kSphereRoomRadius * builtin::kSphereRoomRadius) * geometric;
  const gi::RayScene rays(scene);
  const gi::PixelRays pixels(camera, width, height);
  std::vector<double> ratios;
  for (uint32_t y = 0; y < height; ++y) {
    for (uint32_t x = 0; x < width; ++x) {
      const glm::vec3 direction = pixels.direction(x, y);
      const auto hit = rays.intersect(pixels.origin(), direction, 0.0f, INFINITY);
      ASSERT_TRUE(hit) << "the camera is inside a closed sphere";
      const gi::BrdfSurface s{hit->shadingNormal, -direction, glm::vec3(rho), 0.0f, 1.0f};
      ratios.push_back(image.at(x, y).g / (incoming * directionalAlbedo(s).g));
    }
  }
  double mean = 0.0, variance = 0.0;
  for (double r : ratios) mean += r / double(ratios.size());
  for (double r : ratios) variance += (r - mean) * (r - mean) / double(ratios.size() - 1);
  const double standardError = std::sqrt(variance / double(ratios.size()));
  EXPECT_NEAR(mean, 1.0, 4.0 * standardError + 0.005)
      << bounces << " bounces, standard error " << standardError;
  EXPECT_LT(standardError, 0.01) << "too noisy to test anything";
}

TEST(GiReference, SphereRoomOneBounceIsTheClosedForm) {
  expectSphereRoomClosedForm(1);
}

TEST(GiReference, SphereRoomThreeBouncesIsTheClosedForm) {
  expectSphereRoomClosedForm(3);
}

TEST(GiReference, CornellFloorBesideTheRedWallIsRed) {
  const Scene scene = builtin::makeCornell();
  const uint32_t width = 32, height = 24;
  const gi::RadianceImage image = renderBuiltin(scene, "room", indirectOnly(2, 16), width, height);
  // Which pixels see the floor within 1.5 m of the red wall (x = 0).
  const gi::RayScene rays(scene);
  const gi::PixelRays pixels(resolveCamera(scene, "room"), width, height);
  glm::vec3 sum(0.0f);
  int count = 0;
  for (uint32_t y = 0; y < height; ++y) {
    for (uint32_t x = 0; x < width; ++x) {
      const auto hit = rays.intersect(pixels.origin(), pixels.direction(x, y), 0.0f, INFINITY);
      if (hit && hit->position.y < 1e-3f && hit->normal.y > 0.9f && hit->position.x < 1.5f) {
        sum += image.at(x, y);
        ++count;
      }
    }
  }
  ASSERT_GT(count, 4);
  const glm::vec3 mean = sum / float(count);
  EXPECT_GT(mean.r, 1e-3f);
  EXPECT_GT(mean.r, 2.0f * mean.g) << mean.r << " " << mean.g << " " << mean.b;
}

TEST(GiReference, CornellSealedRoomIsExactlyBlack) {
  const Scene scene = builtin::makeCornell();
  const gi::RadianceImage image = renderBuiltin(scene, "sealed", indirectOnly(3, 8));
  for (const glm::vec3& c : image.rgb) ASSERT_EQ(c, glm::vec3(0.0f));
}

TEST(GiReference, SameSeedSameImageWithOneOrTwoThreads) {
  const Scene scene = builtin::makeCornell();
  gi::ReferenceOptions options = indirectOnly(2, 4);
  options.threads = 1;
  const gi::RadianceImage one = renderBuiltin(scene, "room", options);
  options.threads = 2;
  const gi::RadianceImage two = renderBuiltin(scene, "room", options);
  EXPECT_TRUE(one.rgb == two.rgb);
  options.seed = 2;
  EXPECT_FALSE(renderBuiltin(scene, "room", options).rgb == two.rgb) << "the seed changes nothing";
}

HdrImage toHdr(const gi::RadianceImage& image) {
  return HdrImage::fromRgb(image.width, image.height, image.rgb);
}

// Renders `scene` with forward (no ambient) and the reference's direct light (one sample at each
// pixel centre, no bounce), and compares them through the CPU twin of the tonemap.
test::Rendered expectDirectLightMatchesForward(const Scene& scene, float exposure,
                                               const test::ImageBound& bound, const std::string& label) {
  RenderSettings settings = test::reference({});
  settings.width = 64;
  settings.height = 48;
  settings.ambient = 0.0f;
  settings.exposure = exposure;
  const test::Rendered rendered = test::render(scene, settings);
  gi::ReferenceOptions options;
  options.bounces = 0;
  options.spp = 1;
  const gi::RadianceImage image = renderBuiltin(scene, "", options, settings.width, settings.height);
  test::expectWithinBound(tonemapFilmic(toHdr(image), exposure), rendered.ldr, bound, label);
  return rendered;
}

// The Cornell room has no occluder in the spot's cone, so the shadow rays change nothing; where
// pixels differ, a rasterized edge went the other way.
TEST(GiReference, DirectLightAndTonemapMatchTheRenderer) {
  const test::Rendered rendered = expectDirectLightMatchesForward(
      builtin::makeCornell(), 2.0f, test::kRasterBound, "reference direct cornell");
  // The tonemap alone, on the renderer's own radiance: the same bytes up to rounding.
  test::expectWithinBound(tonemapFilmic(rendered.hdr, 2.0f), rendered.ldr, test::ImageBound{60.0, 1, 1.0, 1},
                          "tonemap cpu");
}

// The sun in the reference: the plane under a directional light 40 degrees off the zenith gives
// forward's image (nothing casts a shadow on it).
TEST(GiReference, SunMatchesTheRenderer) {
  Scene scene = makeBuiltinScene("plane").value();
  scene.lights.clear();
  DirectionalLight sun;
  sun.direction = -glm::normalize(glm::vec3(0.6f, 1.0f, 0.3f));
  sun.illuminance = 1.5f;
  scene.directionalLights = {sun};
  expectDirectLightMatchesForward(scene, 1.0f, test::kSameImage, "reference sun plane");
}

Scene cornellVplsOnly() {
  SceneRequest request{"cornell"};
  request.gi.mode = GiMode::VplOnly;
  return loadScene(request);
}

// The sum of every pixel's r + g + b.
double radianceSum(const gi::RadianceImage& image) {
  double sum = 0.0;
  for (const glm::vec3& c : image.rgb) sum += double(c.r) + c.g + c.b;
  return sum;
}

gi::ReferenceOptions vplGather(gi::VplGather gather) {
  gi::ReferenceOptions options;
  options.vpls = gather;
  options.spp = 1;  // no glass: every sample sees the same point
  return options;
}

// `lll reference --vpls unshadowed` is the renderer's VPL light computed on the CPU (formula for
// formula: the band, the clamp, the cosine, the widened lobe): forward's image of the Cornell room's
// VPLs, through the tonemap's CPU twin, within the bound the direct light meets; and its mean within
// 1%. This is what lets the shadowed sum say how much of the renderer's VPL light passes through
// walls.
TEST(GiReference, UnshadowedVplsAreTheRenderersVplLight) {
  const Scene scene = cornellVplsOnly();
  RenderSettings settings = test::reference({});
  settings.width = 64;
  settings.height = 48;
  settings.ambient = 0.0f;
  settings.exposure = 16.0f;
  const test::Rendered rendered = test::render(scene, settings);
  const gi::RadianceImage image =
      renderBuiltin(scene, "", vplGather(gi::VplGather::Unshadowed), settings.width, settings.height);
  test::expectWithinBound(tonemapFilmic(toHdr(image), settings.exposure), rendered.ldr, test::kRasterBound,
                          "reference unshadowed VPLs cornell");
  const double cpu = radianceSum(image);
  double gpu = 0.0;
  for (size_t i = 0; i < image.rgb.size(); ++i)
    gpu += double(rendered.hdr.rgba[i * 4]) + rendered.hdr.rgba[i * 4 + 1] + rendered.hdr.rgba[i * 4 + 2];
  std::printf("[ gi ] cornell VPL light, mean over the image: renderer %.6f, CPU sum %.6f\n",
              gpu / image.rgb.size(), cpu / image.rgb.size());
  EXPECT_GT(cpu, 0.0);
  EXPECT_NEAR(gpu / cpu, 1.0, 0.01);
}

// The Cornell room's sealed half receives no photon, but the VPLs beside its walls light it through
// them; with a shadow ray each, nothing.
TEST(GiReference, ShadowedVplsLeaveTheSealedRoomBlack) {
  const Scene scene = cornellVplsOnly();
  const gi::RadianceImage through = renderBuiltin(scene, "sealed", vplGather(gi::VplGather::Unshadowed));
  EXPECT_GT(radianceSum(through), 0.0) << "no VPL light leaks into the sealed room: the test shows nothing";
  const gi::RadianceImage shadowed = renderBuiltin(scene, "sealed", vplGather(gi::VplGather::Shadowed));
  for (const glm::vec3& c : shadowed.rgb) ASSERT_EQ(c, glm::vec3(0.0f));
  // In the open room nothing stands between a wall and another: the shadow rays take nothing away.
  const gi::RadianceImage open = renderBuiltin(scene, "room", vplGather(gi::VplGather::Unshadowed));
  const gi::RadianceImage openShadowed = renderBuiltin(scene, "room", vplGather(gi::VplGather::Shadowed));
  const double a = radianceSum(open), b = radianceSum(openShadowed);
  EXPECT_GT(b, 0.99 * a);
  EXPECT_LE(b, a);
}

class GiReferenceCli : public test::CliTest {};

TEST_F(GiReferenceCli, BadInputToTheCommandFunctionNamesTheInputAndWritesNothing) {
  const test::fs::path dir = dir_;
  ReferenceJob job;
  job.scene.scene = "cornell";
  job.width = 8;
  job.height = 6;
  job.options.spp = 1;
  job.out = (dir / "ref.exr").string();
  auto expectRefused = [&](ReferenceJob bad, const std::string& named) {
    try {
      runReference(bad);
      ADD_FAILURE() << "accepted; expected a refusal naming " << named;
    } catch (const InputError& e) {
      EXPECT_TRUE(test::contains(e.what(), named)) << e.what();
    }
    EXPECT_TRUE(test::fs::is_empty(dir)) << "a file was left behind refusing " << named;
  };
  ReferenceJob bad = job;
  bad.scene.scene = "no-such-scene";
  expectRefused(bad, "no-such-scene");
  bad = job;
  bad.camera = "nowhere";
  expectRefused(bad, "nowhere");
  bad = job;
  bad.camera = "1,2,3";
  expectRefused(bad, "1,2,3");
  bad = job;
  bad.options.spp = 0;
  expectRefused(bad, "--spp 0");
  bad.options.spp = gi::kMaxReferenceSpp + 1;
  expectRefused(bad, "--spp");
  bad = job;
  bad.options.bounces = gi::kMaxBounces + 1;
  expectRefused(bad, "--bounces");
  bad = job;
  bad.out = (dir / "missing-folder" / "ref.exr").string();
  expectRefused(bad, "missing-folder");
  bad = job;
  bad.out = (dir / "ref.jpg").string();
  expectRefused(bad, "ref.jpg");
  bad = job;
  bad.out.reset();
  expectRefused(bad, "--out");
  bad = job;
  bad.options.vpls = gi::VplGather::Shadowed;
  bad.options.indirectOnly = true;
  expectRefused(bad, "--indirect");
  bad.options.indirectOnly = false;
  bad.options.bounces = 0;
  expectRefused(bad, "--bounces 0");
}

TEST_F(GiReferenceCli, WritesRadianceOrTonemappedImagesAndTheTime) {
  for (const char* name : {"ref.pfm", "ref.exr", "ref.png"}) {
    const std::string out = (dir_ / name).string();
    const test::CliResult r = test::runLll({"reference", "cornell", "--indirect", "--width", "16", "--height",
                                            "12", "--spp", "2", "--out", out});
    EXPECT_EQ(r.exitCode, 0) << r;
    EXPECT_TRUE(test::fs::exists(out)) << name;
    EXPECT_TRUE(test::contains(r.output, "16x12, 2 spp")) << r;
  }
}

TEST_F(GiReferenceCli, BadInputExitsWithTwoAndNoFile) {
  const std::string out = outPng();
  auto run = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = {"reference", "cornell", "--width", "8", "--height", "6", "--out", out};
    args.insert(args.end(), extra.begin(), extra.end());
    return test::runLll(args);
  };
  expectBadInput(run({"--spp", "0"}), {"--spp"});
  expectBadInput(run({"--spp", "1e9"}), {"--spp"});
  expectBadInput(run({"--camera", "nowhere"}), {"nowhere"});
  expectBadInput(test::runLll({"reference", "no-such-scene", "--out", out}), {"no-such-scene"});
  expectBadInput(test::runLll({"reference", "cornell"}), {"--out"});
  expectBadInput(run({"--bounces", "17"}), {"--bounces"});
  expectBadInput(run({"--vpls", "sideways"}), {"--vpls"});
  expectBadInput(run({"--vpls", "shadowed", "--indirect"}), {"--vpls", "--indirect"});
  expectBadInput(run({"--photons", "1000"}), {"--photons", "--vpls"});
}

TEST_F(GiReferenceCli, VplsReportTheirCount) {
  const std::string out = (dir_ / "vpls.pfm").string();
  const test::CliResult r = test::runLll({"reference", "cornell", "--vpls", "shadowed", "--photons", "4000",
                                          "--width", "16", "--height", "12", "--spp", "1", "--out", out});
  EXPECT_EQ(r.exitCode, 0) << r;
  EXPECT_TRUE(test::fs::exists(out));
  EXPECT_TRUE(test::contains(r.output, "4000 photons")) << r;
  EXPECT_TRUE(test::contains(r.output, "virtual point lights")) << r;
  EXPECT_TRUE(test::contains(r.output, "the VPLs shadowed")) << r;
}

}  // namespace
}  // namespace lll
