// Interleaved sampling of the VPLs (--vpl-interleave, render/interleaved_vpls.h): each pixel of a
// K x K block evaluates one class of the VPLs, and the filter gathers the others from neighbours
// on the same surface.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <algorithm>
#include <vector>

#include "cli_test_support.h"
#include "lighting/lll.h"
#include "render/image_compare.h"
#include "scene/builtin_gi_scenes.h"
#include "test_support.h"

namespace lll {
namespace {

Scene cornellVpls(uint32_t count) {
  SceneRequest request{"cornell"};
  request.gi.mode = GiMode::VplOnly;
  request.gi.photons = 20000;
  request.gi.vplCount = count;
  return loadScene(request);
}

RenderSettings vplSettings(const char* technique, uint32_t interleave) {
  RenderSettings settings;
  settings.width = 190;  // sides no pattern divides: the last blocks are partial
  settings.height = 143;
  settings.ambient = 0.0f;
  settings.exposure = 16.0f;  // the indirect light fills the display range
  settings.technique = technique;
  settings.vplInterleave = interleave;
  return settings;
}

// The atrium's VPLs alone (Infinity's 5,144 asked for) at 320x180, default exposure and ambient.
Scene atriumVpls() {
  SceneRequest request{"atrium"};
  request.gi.mode = GiMode::VplOnly;
  return loadScene(request);
}

RenderSettings atriumSettings(const char* technique, uint32_t interleave) {
  RenderSettings settings;
  settings.width = 320;
  settings.height = 180;
  settings.technique = technique;
  settings.vplInterleave = interleave;
  return settings;
}

// The gather smooths the light over at most 2K-1 pixels of one surface: where it changes within a
// pixel or two (the room's corners at this size) the smoothing shows. A lost, doubled or unskipped
// class moves the whole image by a quarter or more.
constexpr test::ImageBound kGatherBound{45.0, 2, 0.95, 24};

double meanRed(const HdrImage& image) {
  double sum = 0.0;
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 0; x < image.width; ++x) sum += image.at(x, y).r;
  return sum / (double(image.width) * image.height);
}

bool hasStat(const test::Rendered& r, const std::string& name) {
  for (const auto& [key, value] : r.stats)
    if (key == name) return true;
  return false;
}

// Every VPL copied K*K times at a K*K-th of its intensity, the copies in consecutive places: every
// class then holds the same light, so a pixel's one class times K*K is the whole, and the gather
// must give back the image of every pixel evaluating every VPL. Were the classes not skipped, the
// image would be K*K times too bright; were a class lost or counted twice, a K*K-th too dark or
// bright. Through each lighting interface (lll's lists, tiled's and clustered's grid, forward's
// every light).
TEST(InterleavedVpls, IdenticalClassesGiveBackTheWholeImage) {
  const Scene base = cornellVpls(128);
  for (uint32_t side : {2u, 3u}) {
    Scene scene = base;
    scene.lights.clear();
    for (const Light& vpl : base.lights) {
      ASSERT_EQ(vpl.type, LightType::Vpl);
      Light copy = vpl;
      copy.intensity /= float(side * side);
      for (uint32_t c = 0; c < side * side; ++c) scene.lights.push_back(copy);
    }
    const test::Rendered whole = test::render(scene, vplSettings("forward", 1));
    EXPECT_GT(test::shareAboveBlack(whole.ldr), 0.9);
    for (const char* technique : {"forward", "lll", "tiled", "clustered"}) {
      if (side == 3 && std::string(technique) != "lll") continue;  // one interface is enough for 3
      const std::string label = std::string(technique) + " interleave " + std::to_string(side);
      SCOPED_TRACE(label);
      const test::Rendered r = test::render(scene, vplSettings(technique, side));
      EXPECT_EQ(test::stat(r, "vpl-interleave"), double(side));
      test::expectWithinBound(r.ldr, whole.ldr, kGatherBound, label);
      EXPECT_NEAR(meanRed(r.hdr) / meanRed(whole.hdr), 1.0, 0.01) << "the gather keeps the light's total";
    }
  }
}

// With the VPLs as the merge made them, each class is a different quarter (ninth) of them: the
// gathered image stays close to the whole one, and the K*K-th of the work shows as a difference
// (the classes are not the same light).
TEST(InterleavedVpls, StaysCloseToEveryPixelEvaluatingEveryVpl) {
  const Scene scene = cornellVpls(1024);
  const test::Rendered whole = test::render(scene, vplSettings("lll", 1));
  EXPECT_FALSE(hasStat(whole, "vpl-interleave")) << "off: no pass, no images";
  for (uint32_t side : {2u, 3u, 4u}) {
    const test::Rendered r = test::render(scene, vplSettings("lll", side));
    const ImageDifference d = compareImages(r.ldr, whole.ldr);
    std::printf("[ gi ] cornell, 1,024 VPLs, --vpl-interleave %u: %.2f dB against 1, worst %d, 99.9th %d\n",
                side, d.psnr, d.worst, d.p999);
    EXPECT_GT(d.psnr, 40.0) << side;
    EXPECT_TRUE(std::isfinite(d.psnr)) << side << ": identical images: were the VPLs split at all?";
  }
}

// The atrium's floor is a checkerboard of light and dark marble: the gather carries each lobe of
// the light over its own reflectance (the diffuse over the albedo, the specular over f0), so the
// tiles' edges do not show through the neighbours' light. Dividing the specular by the albedo too
// (as before) left 31.8 dB here at K = 4 on lavapipe; now 33.6, and 37.2 at 640x360 (34.7 before).
TEST(InterleavedVpls, TheGatherCarriesLightNotTexture) {
  const Scene scene = atriumVpls();
  const test::Rendered whole = test::render(scene, atriumSettings("lll", 1));
  const test::Rendered interleaved = test::render(scene, atriumSettings("lll", 4));
  const ImageDifference d = compareImages(interleaved.ldr, whole.ldr);
  std::printf("[ gi ] atrium, %u lights, --vpl-interleave 4: %.2f dB against 1, worst %d, 99.9th %d\n",
              uint32_t(scene.lights.size()), d.psnr, d.worst, d.p999);
  EXPECT_GT(d.psnr, 33.0);
}

// Where a pixel's surface is narrower than the pattern (a column's edge, a rim, a silhouette), no
// neighbour on it brings some classes: with lll's class lists the filter gives the pixel an edge slot
// and vpl-edges lights those classes on its own surface; tiled, whose grid does not keep the classes
// apart, stands the classes found for the missing ones. The same VPLs, and without interleaving the
// same image (Gi.EveryTechniqueMatchesForwardWithTheSameVpls): lll's interleaved image is nearer.
TEST(InterleavedVpls, EdgePixelsLightTheClassesTheyLack) {
  const Scene scene = atriumVpls();
  const test::Rendered whole = test::render(scene, atriumSettings("lll", 1));
  const test::Rendered lll = test::render(scene, atriumSettings("lll", 4));
  const test::Rendered tiled = test::render(scene, atriumSettings("tiled", 4));
  const ImageDifference withEdges = compareImages(lll.ldr, whole.ldr);
  const ImageDifference without = compareImages(tiled.ldr, whole.ldr);
  std::printf("[ gi ] atrium, --vpl-interleave 4 against 1: lll (edge slots) %.2f dB, tiled %.2f dB\n",
              withEdges.psnr, without.psnr);
  EXPECT_GT(withEdges.psnr, without.psnr + 1.0);
}

// A glossy metal's VPL light is a spray of sharp glints: its pixels have every class and the gather
// leaves them as they are. The Cornell room made of polished metal: the same image as without
// interleaving (the light summed in another order: 1/255 at most); the room made rougher, and the
// pattern's gather shows. With lll the first eighth of the metal pixels get vpl-classes' slots (their
// classes lit by a workgroup each) and the rest walk every class themselves: both ways here.
TEST(InterleavedVpls, GlossyMetalsEvaluateEveryVplThemselves) {
  for (const float roughness : {0.3f, 0.7f}) {
    Scene scene = cornellVpls(256);
    for (Material& m : scene.materials) {
      m.metallic = 1.0f;
      m.roughness = roughness;
    }
    const test::Rendered whole = test::render(scene, vplSettings("lll", 1));
    const test::Rendered interleaved = test::render(scene, vplSettings("lll", 2));
    const ImageDifference d = compareImages(interleaved.ldr, whole.ldr);
    std::printf("[ gi ] cornell of metal, roughness %.1f, --vpl-interleave 2: %.2f dB against 1, worst %d\n",
                roughness, d.psnr, d.worst);
    if (roughness < 0.5f)
      EXPECT_LE(d.worst, 1);
    else
      EXPECT_GT(d.worst, 1);
  }
}

// lll keeps each class of VPLs in a list of its own (and the other lights in one more), so that a
// pixel walks only its class: read back with a list's heads one after the other, every tile and
// slice lists the same lights as without interleaving.
TEST(InterleavedVpls, LllClassListsHoldTheSameLights) {
  SceneRequest request{"cornell"};
  request.gi.mode = GiMode::Vpl;  // the spot light first, then the VPLs
  request.gi.photons = 20000;
  request.gi.vplCount = 256;
  const Scene scene = loadScene(request);
  auto lists = [&](uint32_t side, double* headsPerList) {
    RenderSettings settings = vplSettings("lll", side);
    Renderer renderer(test::gpuContext(), scene, settings);
    renderer.renderFrame(false);
    for (const auto& [key, value] : renderer.technique().stats())
      if (key == "heads_per_list") *headsPerList = value;
    TileLightLists read = readTileLightLists(renderer.technique());
    std::vector<std::vector<uint32_t>> lights;
    for (const auto& list : read.lists) {
      lights.emplace_back();
      for (const LightLinkRecord& link : list) lights.back().push_back(link.light);
      std::sort(lights.back().begin(), lights.back().end());
    }
    return lights;
  };
  double plainHeads = 0.0, classHeads = 0.0;
  const auto plain = lists(1, &plainHeads);
  const auto classed = lists(2, &classHeads);
  EXPECT_EQ(plainHeads, 1.0);
  EXPECT_EQ(classHeads, 5.0) << "the lights before the VPLs, and four classes";
  ASSERT_EQ(plain.size(), classed.size());
  size_t links = 0;
  for (size_t i = 0; i < plain.size(); ++i) {
    EXPECT_EQ(plain[i], classed[i]) << "list " << i;
    links += plain[i].size();
  }
  EXPECT_GT(links, plain.size()) << "the lists should hold many VPLs";
}

// Without VPLs, or with surfaces that do not come from the visibility buffer, nothing changes: no
// filter pass, the same image.
TEST(InterleavedVpls, NothingToInterleaveChangesNothing) {
  const Scene scene = builtin::makeCornell();
  const test::Rendered plain = test::render(scene, vplSettings("lll", 1));
  const test::Rendered asked = test::render(scene, vplSettings("lll", 2));
  EXPECT_FALSE(hasStat(asked, "vpl-interleave"));
  EXPECT_EQ(compareImages(asked.ldr, plain.ldr).worst, 0);
  const Scene vpls = cornellVpls(256);
  RenderSettings gbuffer = vplSettings("lll", 2);
  gbuffer.surfaces = SurfaceSource::Gbuffer;
  const test::Rendered fromGbuffer = test::render(vpls, gbuffer);
  EXPECT_FALSE(hasStat(fromGbuffer, "vpl-interleave"));
  EXPECT_EQ(test::stat(fromGbuffer, "heads_per_list"), 1.0)
      << "lll splits its lists only for the pass that interleaves";
}

using test::CliTest;

TEST_F(CliTest, VplInterleaveOutOfRange) {
  expectBadInput(render("cornell", {"--gi", "vpl", "--vpl-interleave", "0"}), {"--vpl-interleave"});
  expectBadInput(render("cornell", {"--gi", "vpl", "--vpl-interleave", "5"}), {"--vpl-interleave"});
  expectBadInput(render("cornell", {"--gi", "vpl", "--vpl-interleave", "two"}), {"--vpl-interleave"});
}

}  // namespace
}  // namespace lll
