// KHR_texture_transform (scene.h's TextureTransform, shaders/common/texture_transform.glsl), glTF's
// TEXCOORD_1 and COLOR_0: a material whose five textures share a transform (offset, rotation,
// scale) draws exactly what the same material draws with the transform baked into the mesh's UVs;
// textures that read TEXCOORD_1 (holding a transform baked in) draw what the transform draws on
// TEXCOORD_0; vertex colours draw what the same colours draw as base colour factors. Each through
// every way a surface is built: fragment shading (forward, lll and pre-pass on the geometry
// passes), the visibility buffer's compute rebuild (hardware and compute rasterizer), deferred's
// G-buffer, glass, and an alpha-masked material's coverage (the masked depth and visibility
// passes). And each matters: without it the image is another.
#include <gtest/gtest.h>

#include <fmt/format.h>
#include <cmath>
#include <string>
#include <vector>

#include "lighting/technique.h"
#include "test_support.h"

namespace lll {
namespace {

// A `size` x `size` RGBA texture whose texels come from `texel(x, y)`.
template <typename F>
Texture makeTexture(const std::string& name, uint32_t size, bool srgb, F texel) {
  Texture t;
  t.name = name;
  t.width = t.height = size;
  t.srgb = srgb;
  for (uint32_t y = 0; y < size; ++y)
    for (uint32_t x = 0; x < size; ++x) {
      const glm::u8vec4 c = texel(x, y);
      t.rgba.insert(t.rgba.end(), {c.r, c.g, c.b, c.a});
    }
  return t;
}

// How transformScene's textured, masked and glass quads read their textures and colours.
struct SceneVariant {
  // TEXCOORD_0 with the materials' transforms on `transformed` slots (bits of TextureSlot), all
  // slots' transforms baked into TEXCOORD_0 (`baked`), or the transforms baked into TEXCOORD_1,
  // which the `transformed` slots read (`secondSet`).
  uint32_t transformed = 0;
  bool baked = false;
  bool secondSet = false;
  // A colour for the three quads (alpha too), as COLOR_0 of their vertices or, without
  // `inVertices`, multiplied into their base colour factors; the masked material's cutoff.
  glm::vec4 color{1.0f};
  bool inVertices = false;
  float maskCutoff = 0.5f;
};

// A quad from `origin` along `u` and `v` (its normal u x v), UVs from `uv0` over `uvSize` (through
// `bake` into TEXCOORD_0, or into TEXCOORD_1 with `second`), with the tangent along u.
void addQuad(Scene& scene, uint32_t material, glm::vec3 origin, glm::vec3 u, glm::vec3 v, glm::vec2 uv0,
             glm::vec2 uvSize, const TextureTransform& bake, bool second = false,
             glm::vec4 color = glm::vec4(1.0f)) {
  const uint32_t first = uint32_t(scene.vertices.size());
  const glm::vec3 n = glm::normalize(glm::cross(u, v));
  for (const glm::vec2 c : {glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(1, 1), glm::vec2(0, 1)}) {
    Vertex vertex;
    vertex.position = origin + c.x * u + c.y * v;
    vertex.normal = n;
    vertex.uv = second ? uv0 + c * uvSize : bake.apply(uv0 + c * uvSize);
    if (second) vertex.uv1 = bake.apply(uv0 + c * uvSize);
    vertex.tangent = glm::vec4(glm::normalize(u), 1.0f);
    vertex.setColor(color);
    scene.vertices.push_back(vertex);
  }
  Mesh mesh;
  mesh.name = "quad";
  mesh.primitives.push_back({uint32_t(scene.indices.size()), 6, first, material});
  scene.indices.insert(scene.indices.end(), {0, 1, 2, 0, 2, 3});
  scene.meshes.push_back(mesh);
  scene.instances.push_back({uint32_t(scene.meshes.size() - 1), glm::mat4(1.0f)});
}

// Textured, masked and glass quads over a floor.
Scene transformScene(const SceneVariant& variant) {
  Scene scene;
  scene.name = "transforms";
  const auto pattern = [](uint32_t x, uint32_t y) {
    return glm::u8vec4(40 + 13 * x, 60 + 11 * y, ((x ^ y) & 1) ? 220 : 50, 255);
  };
  scene.textures.push_back(makeTexture("colour", 16, true, pattern));
  scene.textures.push_back(makeTexture("normal", 16, false, [](uint32_t x, uint32_t y) {
    return glm::u8vec4(128 + 90 * std::sin(0.8f * float(x)), 128 + 90 * std::cos(0.6f * float(y)), 200, 255);
  }));
  scene.textures.push_back(makeTexture("metallic-roughness", 16, false, [](uint32_t x, uint32_t y) {
    return glm::u8vec4(0, 40 + 12 * x, 15 * y, 255);
  }));
  scene.textures.push_back(makeTexture("emissive", 16, true, [](uint32_t x, uint32_t y) {
    return glm::u8vec4((x + y) % 5 == 0 ? 255 : 0, 0, 0, 255);
  }));
  scene.textures.push_back(makeTexture("mask", 16, true, [](uint32_t x, uint32_t y) {
    return glm::u8vec4(200, 120, 60, ((x / 4 + y / 4) & 1) ? 255 : 0);
  }));

  TextureTransform all;
  all.offset = glm::vec2(0.3f, -0.15f);
  all.rotation = 0.6f;
  all.scale = glm::vec2(1.7f, 0.8f);
  TextureTransform mask;
  mask.offset = glm::vec2(0.1f, 0.4f);
  mask.rotation = -1.1f;
  mask.scale = glm::vec2(2.5f, 2.5f);

  Material floor;
  floor.metallic = 0.0f;
  floor.roughness = 0.7f;
  Material textured;
  textured.baseColorTexture = 0;
  textured.normalTexture = 1;
  textured.metallicRoughnessTexture = 2;
  textured.emissiveTexture = 3;
  textured.occlusionTexture = 2;
  textured.emissiveFactor = glm::vec3(0.6f);
  textured.roughness = 0.8f;
  Material masked;
  masked.baseColorTexture = 4;
  masked.alphaMode = AlphaMode::Mask;
  masked.alphaCutoff = variant.maskCutoff;
  masked.doubleSided = true;
  masked.metallic = 0.0f;
  Material glass = textured;
  glass.baseColorFactor.a = 0.5f;
  glass.alphaMode = AlphaMode::Blend;
  for (uint32_t slot = 0; slot < kTextureSlots; ++slot) {
    if ((variant.transformed & (1u << slot)) == 0) continue;
    if (variant.secondSet) {
      textured.texCoords[slot] = glass.texCoords[slot] = 1;
    } else {
      textured.transforms[slot] = glass.transforms[slot] = all;
    }
  }
  if (variant.transformed & (1u << kBaseColorSlot)) {
    if (variant.secondSet)
      masked.texCoords[kBaseColorSlot] = 1;
    else
      masked.transforms[kBaseColorSlot] = mask;
  }
  const glm::vec4 vertexColor = variant.inVertices ? variant.color : glm::vec4(1.0f);
  if (!variant.inVertices)
    for (Material* m : {&textured, &masked, &glass}) m->baseColorFactor *= variant.color;
  scene.materials = {floor, textured, masked, glass};
  const TextureTransform none;
  const bool bakes = variant.baked || variant.secondSet;
  addQuad(scene, 0, glm::vec3(-4, 0, 4), glm::vec3(8, 0, 0), glm::vec3(0, 0, -8), glm::vec2(0), glm::vec2(1),
          none);
  addQuad(scene, 1, glm::vec3(-2.2f, 0.1f, -0.5f), glm::vec3(2, 0, 0.3f), glm::vec3(0, 2, 0), glm::vec2(0.1f),
          glm::vec2(1.3f), bakes ? all : none, variant.secondSet, vertexColor);
  addQuad(scene, 2, glm::vec3(0.3f, 0.1f, 0.2f), glm::vec3(1.8f, 0, -0.4f), glm::vec3(0, 1.8f, 0),
          glm::vec2(-0.2f, 0.3f), glm::vec2(1.0f), bakes ? mask : none, variant.secondSet, vertexColor);
  addQuad(scene, 3, glm::vec3(-1.0f, 0.2f, 1.2f), glm::vec3(2.2f, 0, 0), glm::vec3(0, 1.2f, 0.2f),
          glm::vec2(0.5f), glm::vec2(0.8f), bakes ? all : none, variant.secondSet, vertexColor);
  for (int i = 0; i < 3; ++i) {
    Light light;
    light.position = glm::vec3(-2.5f + 2.5f * float(i), 2.4f, 2.0f);
    light.color = glm::vec3(i == 0, i == 1, i == 2) * 0.6f + 0.4f;
    light.intensity = 8.0f;
    light.range = 9.0f;
    scene.lights.push_back(light);
  }
  Camera camera;
  camera.name = "view";
  camera.eye = glm::vec3(0.4f, 1.8f, 4.5f);
  camera.target = glm::vec3(-0.2f, 0.9f, 0.0f);
  scene.cameras.push_back(camera);
  return scene;
}

constexpr uint32_t kAllSlots = (1u << kTextureSlots) - 1;

struct Path {
  const char* name;
  const char* technique;
  SurfaceSource surfaces;
  RasterChoice raster;
};
constexpr Path kPaths[] = {
    {"forward", "forward", SurfaceSource::Gbuffer, RasterChoice::Hardware},
    {"forward visibility", "forward", SurfaceSource::Visibility, RasterChoice::Hardware},
    {"lll visibility", "lll", SurfaceSource::Visibility, RasterChoice::Hardware},
    {"lll compute raster", "lll", SurfaceSource::Visibility, RasterChoice::Compute},
    {"lll fragment", "lll", SurfaceSource::Gbuffer, RasterChoice::Hardware},
    {"deferred", "deferred", SurfaceSource::Visibility, RasterChoice::Hardware},
    {"prepass", "prepass", SurfaceSource::Gbuffer, RasterChoice::Hardware},
    {"tiled", "tiled", SurfaceSource::Visibility, RasterChoice::Hardware}};

// `a` and `b` draw the same image through every path (the last bits: the same texture
// coordinates or colours, one computed in a shader and one on the CPU).
void expectSameThroughEveryPath(const Scene& a, const Scene& b, const std::string& what,
                                const test::ImageBound& bound = test::kSameImage) {
  for (const Path& p : kPaths) {
    RenderSettings settings;
    settings.width = 160;
    settings.height = 90;
    settings.technique = p.technique;
    settings.surfaces = p.surfaces;
    settings.raster = p.raster;
    const test::Rendered x = test::render(a, settings), y = test::render(b, settings);
    test::expectWithinBound(x.ldr, y.ldr, bound, what + ", " + p.name);
    EXPECT_GT(test::shareAboveBlack(y.ldr), 0.4) << p.name;  // the upper half is sky
  }
}

double psnrOfDefaultRender(const Scene& a, const Scene& b) {
  RenderSettings settings;
  settings.width = 160;
  settings.height = 90;
  return test::psnr(test::render(a, settings).ldr, test::render(b, settings).ldr);
}

TEST(TextureTransform, DrawsWhatTheTransformBakedIntoTheUvsDraws) {
  const Scene transformed = transformScene({.transformed = kAllSlots});
  const Scene baked = transformScene({.baked = true});
  // On the H200 one pixel of 14,400, (94, 29) in every path, differs by 155 (48.6 dB, 99.99%
  // within 2; identical on lavapipe): the coordinates baked on the CPU and those transformed in
  // the shader round apart there, most likely onto two sides of the alpha mask's cutoff. So a few
  // pixels may differ by any amount.
  expectSameThroughEveryPath(transformed, baked, "transformed vs baked",
                             test::ImageBound{45.0, 2, 0.999, 255});
  // Without the transforms (the baked scene's materials on its original UVs) the image is another.
  EXPECT_LT(psnrOfDefaultRender(transformScene({}), baked), 30.0);
}

// glTF's TEXCOORD_1: the base colour, normal and occlusion textures read the second set (in which
// the transform is baked), the others the first, as a lightmapped asset's occlusion would.
TEST(TextureCoordinates, SecondSetDrawsWhatItsCoordinatesDraw) {
  const uint32_t slots = 1u << kBaseColorSlot | 1u << kNormalSlot | 1u << kOcclusionSlot;
  const Scene second = transformScene({.transformed = slots, .secondSet = true});
  const Scene transformed = transformScene({.transformed = slots});
  expectSameThroughEveryPath(second, transformed, "TEXCOORD_1 vs transformed TEXCOORD_0");
  // Reading TEXCOORD_0 instead draws another image.
  Scene first = second;
  for (Material& m : first.materials) m.texCoords.fill(0);
  EXPECT_LT(psnrOfDefaultRender(first, transformed), 30.0);
}

// glTF's COLOR_0 multiplies the base colour, its alpha the coverage: glass's blend and the masked
// material's cutoff (0.8 against the colour's alpha 0.75 cuts the whole quad out).
TEST(VertexColors, DrawWhatTheSameBaseColorFactorsDraw) {
  // Exact in half floats; green 0 makes the pair (red, green) a denormal as a 32-bit float.
  const glm::vec4 color(0.875f, 0.0f, 0.25f, 0.75f);
  const Scene vertices = transformScene({.color = color, .inVertices = true, .maskCutoff = 0.8f});
  const Scene factors = transformScene({.color = color, .maskCutoff = 0.8f});
  expectSameThroughEveryPath(vertices, factors, "COLOR_0 vs base colour factors");
  EXPECT_LT(psnrOfDefaultRender(transformScene({.maskCutoff = 0.8f}), factors), 30.0);
  // The masked quad's coverage alone: white vertices keep it (alpha 1 passes 0.8).
  EXPECT_LT(psnrOfDefaultRender(
                transformScene(
                    {.color = glm::vec4(glm::vec3(color), 1.0f), .inVertices = true, .maskCutoff = 0.8f}),
                factors),
            40.0);
}

// glTF's matrix: Translation x Rotation x Scale, with the rotation turning u towards -v.
TEST(TextureTransform, MatrixIsTheExtensions) {
  TextureTransform t;
  t.offset = glm::vec2(0.5f, -0.25f);
  t.rotation = 1.5707963f;
  t.scale = glm::vec2(2.0f, 3.0f);
  const glm::vec2 x = t.apply(glm::vec2(1, 0)), y = t.apply(glm::vec2(0, 1));
  EXPECT_NEAR(x.x, 0.5f, 1e-6f);
  EXPECT_NEAR(x.y, -2.25f, 1e-6f);
  EXPECT_NEAR(y.x, 3.5f, 1e-6f);
  EXPECT_NEAR(y.y, -0.25f, 1e-6f);
  // The extension's own example: "only the lower left quadrant of the source image, rotated
  // clockwise 90 degrees" (v runs down the image).
  TextureTransform quadrant;
  quadrant.offset = glm::vec2(0.0f, 1.0f);
  quadrant.rotation = 1.57079632679f;
  quadrant.scale = glm::vec2(0.5f);
  for (const glm::vec2 corner : {glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(0, 1), glm::vec2(1, 1)}) {
    const glm::vec2 uv = quadrant.apply(corner);
    EXPECT_TRUE(uv.x > -1e-6f && uv.x < 0.5f + 1e-6f && uv.y > 0.5f - 1e-6f && uv.y < 1.0f + 1e-6f)
        << corner.x << "," << corner.y << " -> " << uv.x << "," << uv.y;
  }
  EXPECT_TRUE(TextureTransform{}.identity());
  EXPECT_FALSE(t.identity());
}

}  // namespace
}  // namespace lll
