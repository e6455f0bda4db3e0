#include "scene/builtin_atrium.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <vector>

#include "scene/builtin_textures.h"
#include "scene/mesh_builder.h"

namespace lll::builtin {

using namespace atrium;

namespace {

constexpr float kPi = glm::pi<float>();
// Half the width of the ground and upper columns' abaci: the arches spring from their edges.
constexpr float kGroundAbacusHalf = 0.42f;
constexpr float kUpperAbacusHalf = 0.35f;
constexpr float kPedestalHeight = 1.1f;  // upper columns stand on pedestals as high as the rail
constexpr float kPlinthTop = 1.06f;      // the display plinths in the courtyard
constexpr float kBannerWidth = 1.3f;

struct AtriumMaterials {
  uint32_t floor, ashlar, trim, marble, plaster, wood, roof, darkMarble, medallion, bronze, gold;
  uint32_t clearGlass, greenGlass, blueGlass;
  std::array<uint32_t, 5> cloth;
};

glm::mat4 at(float x, float y, float z) {
  return glm::translate(glm::mat4(1.0f), glm::vec3(x, y, z));
}

int addTexture(Scene& scene, Texture texture) {
  scene.textures.push_back(std::move(texture));
  return int(scene.textures.size() - 1);
}

uint32_t addMaterial(Scene& scene, const char* name, const glm::vec4& color, float metallic, float roughness,
                     int texture = -1) {
  Material m;
  m.name = name;
  m.baseColorFactor = color;
  m.metallic = metallic;
  m.roughness = roughness;
  m.baseColorTexture = texture;
  scene.materials.push_back(m);
  return uint32_t(scene.materials.size() - 1);
}

uint32_t addGlass(Scene& scene, const char* name, const glm::vec3& tint, float alpha) {
  const uint32_t index = addMaterial(scene, name, glm::vec4(tint, alpha), 0.0f, 0.05f);
  scene.materials[index].alphaMode = AlphaMode::Blend;
  return index;
}

AtriumMaterials addMaterials(Scene& scene) {
  const int floorTiles = addTexture(scene, makeFloorTilesTexture());
  const int ashlar = addTexture(scene, makeAshlarTexture());
  const int plaster = addTexture(scene, makePlasterTexture());
  const int wood = addTexture(scene, makeWoodTexture());
  const int marble = addTexture(scene, makeMarbleTexture());
  const int banner = addTexture(scene, makeBannerTexture());
  AtriumMaterials m;
  m.floor = addMaterial(scene, "floor stone", glm::vec4(1.0f), 0.0f, 0.55f, floorTiles);
  m.ashlar = addMaterial(scene, "sandstone", glm::vec4(1.0f), 0.0f, 0.85f, ashlar);
  m.trim = addMaterial(scene, "trim stone", glm::vec4(1.0f, 0.93f, 0.8f, 1.0f), 0.0f, 0.6f, marble);
  m.marble = addMaterial(scene, "column marble", glm::vec4(1.0f), 0.0f, 0.3f, marble);
  m.plaster = addMaterial(scene, "plaster", glm::vec4(1.0f), 0.0f, 0.9f, plaster);
  m.wood = addMaterial(scene, "oak", glm::vec4(1.0f), 0.0f, 0.65f, wood);
  m.roof = addMaterial(scene, "roof tiles", glm::vec4(0.85f, 0.42f, 0.28f, 1.0f), 0.0f, 0.85f, plaster);
  m.darkMarble = addMaterial(scene, "dark marble", glm::vec4(0.3f, 0.3f, 0.34f, 1.0f), 0.0f, 0.2f, marble);
  m.medallion = addMaterial(scene, "red marble", glm::vec4(0.75f, 0.2f, 0.12f, 1.0f), 0.0f, 0.3f, marble);
  m.bronze = addMaterial(scene, "bronze", glm::vec4(0.70f, 0.45f, 0.20f, 1.0f), 1.0f, 0.35f);
  m.gold = addMaterial(scene, "gold", glm::vec4(1.0f, 0.76f, 0.33f, 1.0f), 1.0f, 0.2f);
  // Glass is mid-grey, not white: blended over what lies behind, a bright base colour lit by a
  // nearby light reads as frosted.
  m.clearGlass = addGlass(scene, "clear glass", glm::vec3(0.5f, 0.57f, 0.65f), 0.3f);
  m.greenGlass = addGlass(scene, "green glass", glm::vec3(0.18f, 0.6f, 0.3f), 0.35f);
  m.blueGlass = addGlass(scene, "blue glass", glm::vec3(0.18f, 0.32f, 0.8f), 0.3f);
  const std::array<std::pair<const char*, glm::vec3>, 5> cloths = {{
      {"red cloth", {0.80f, 0.05f, 0.04f}},
      {"green cloth", {0.05f, 0.50f, 0.10f}},
      {"blue cloth", {0.06f, 0.16f, 0.75f}},
      {"gold cloth", {0.85f, 0.55f, 0.06f}},
      {"purple cloth", {0.45f, 0.07f, 0.60f}},
  }};
  for (size_t i = 0; i < cloths.size(); ++i) {
    m.cloth[i] = addMaterial(scene, cloths[i].first, glm::vec4(cloths[i].second, 1.0f), 0.0f, 0.8f, banner);
  }
  return m;
}

// `count` + 1 lathe profile points from height y0 to y1 with radius(t), t in [0, 1].
template <typename RadiusFn>
std::vector<glm::vec2> profile(int count, float y0, float y1, RadiusFn radius) {
  std::vector<glm::vec2> points;
  for (int i = 0; i <= count; ++i) {
    const float t = float(i) / float(count);
    points.emplace_back(radius(t), y0 + (y1 - y0) * t);
  }
  return points;
}

struct ColumnSpec {
  const char* name;
  float height;  // floor to the top of the abacus, where the arches spring
  float radius;  // of the shaft at its foot
  float plinthWidth, plinthHeight;
  uint32_t plinthMaterial;
};

// A column: square plinth, moulded base, a shaft that narrows as it rises, a flared capital and
// the square abacus the arches stand on.
uint32_t buildColumn(Scene& scene, const AtriumMaterials& m, const ColumnSpec& c) {
  MeshBuilder b(c.name);
  const float hp = 0.5f * c.plinthWidth, r = c.radius, abacusHalf = r + 0.15f;
  const float baseTop = c.plinthHeight + 0.17f, capitalBottom = c.height - 0.45f;
  b.setMaterial(c.plinthMaterial);
  b.addBoxBetween({-hp, 0.0f, -hp}, {hp, c.plinthHeight, hp}, 0.5f);
  b.setMaterial(m.trim);
  b.addLathe(
      glm::mat4(1.0f),
      profile(6, c.plinthHeight, baseTop, [&](float t) { return r + 0.02f + 0.07f * std::sin(kPi * t); }), 20,
      false, false, 0.5f);
  b.addLathe(glm::mat4(1.0f),
             profile(5, capitalBottom, c.height - 0.2f,
                     [&](float t) { return 0.85f * r + (abacusHalf - 0.85f * r) * t * t; }),
             20, false, true, 0.5f);
  b.addBoxBetween({-abacusHalf, c.height - 0.2f, -abacusHalf}, {abacusHalf, c.height, abacusHalf}, 0.5f);
  b.setMaterial(m.marble);
  b.addLathe(
      glm::mat4(1.0f),
      profile(6, baseTop, capitalBottom, [&](float t) { return r * (1.0f - 0.15f * std::pow(t, 1.5f)); }), 20,
      false, false, 0.5f);
  return b.addTo(scene);
}

// One bay of an arcade between two column centres, built facing +z: the arched spandrel wall,
// an archivolt moulding and a keystone on the courtyard face.
uint32_t buildArcadeBay(Scene& scene, const AtriumMaterials& m, const char* name, float width, float height,
                        float radius) {
  MeshBuilder b(name);
  b.setMaterial(m.ashlar);
  ArchedWallShape wall;
  wall.width = width;
  wall.height = height;
  wall.thickness = kArcadeThickness;
  wall.archRadius = radius;
  wall.closedEnds = false;  // bays abut; the corner blocks close the ends of each row
  b.addArchedWall(glm::mat4(1.0f), wall, 24, 0.5f);
  const float face = 0.5f * kArcadeThickness;
  b.setMaterial(m.trim);
  b.addArch(at(0.0f, 0.0f, face + 0.05f), radius, radius + 0.2f, 0.1f, 24, 0.5f);
  b.addBoxBetween({-0.14f, radius + 0.02f, face - 0.05f}, {0.14f, radius + 0.34f, face + 0.13f}, 0.5f);
  return b.addTo(scene);
}

// The upper storey's balustrade between two pedestals: rails and turned balusters.
uint32_t buildBalustrade(Scene& scene, const AtriumMaterials& m, const char* name, float length) {
  MeshBuilder b(name);
  b.setMaterial(m.trim);
  const float half = 0.5f * length;
  b.addBoxBetween({-half, 0.0f, -0.15f}, {half, 0.15f, 0.15f}, 0.5f);
  b.addBoxBetween({-half, 0.95f, -0.18f}, {half, 1.07f, 0.18f}, 0.5f);
  static const glm::vec2 baluster[] = {{0.06f, 0.15f}, {0.06f, 0.2f},   {0.075f, 0.3f}, {0.085f, 0.4f},
                                       {0.07f, 0.52f}, {0.045f, 0.65f}, {0.04f, 0.75f}, {0.05f, 0.85f},
                                       {0.06f, 0.9f},  {0.06f, 0.95f}};
  const int count = int(length / 0.28f);
  for (int i = 0; i < count; ++i) {
    const float x = -half + length * (float(i) + 0.5f) / float(count);
    b.addLathe(at(x, 0.0f, 0.0f), baluster, 8, false, false, 0.5f);
  }
  return b.addTo(scene);
}

// A banner on a bronze rod, built hanging from y = 0 and facing +z; the rod's brackets reach
// back (-z) to the pedestal behind it.
uint32_t buildBanner(Scene& scene, const AtriumMaterials& m, uint32_t cloth) {
  MeshBuilder b(scene.materials[cloth].name + " banner");
  b.setMaterial(cloth);
  BannerShape shape;
  shape.width = kBannerWidth;
  shape.length = 3.9f;
  shape.foldAmplitude = 0.06f;
  shape.folds = 2.5f;
  shape.tail = 0.45f;
  b.addBanner(glm::mat4(1.0f), shape);
  const float rodHalf = 0.5f * kBannerWidth + 0.12f;
  b.setMaterial(m.bronze);
  b.addCylinder(at(-rodHalf, 0.03f, 0.0f) * glm::rotate(glm::mat4(1.0f), -0.5f * kPi, glm::vec3(0, 0, 1)),
                0.025f, 2.0f * rodHalf, 12);
  for (float x : {-0.25f, 0.25f}) b.addBoxBetween({x - 0.02f, 0.01f, -0.47f}, {x + 0.02f, 0.05f, 0.0f});
  b.setMaterial(m.gold);
  for (float x : {-rodHalf, rodHalf}) b.addSphere(at(x, 0.03f, 0.0f), 0.05f, 12, 6);
  return b.addTo(scene);
}

// A rectangular ring of four boxes between two centred rectangles (half extents), y0..y1. The
// long (z) sides own the corners, so no two boxes overlap and no faces fight.
void addFrame(MeshBuilder& b, const glm::vec2& inner, const glm::vec2& outer, float y0, float y1,
              float uvPerMetre) {
  b.addBoxBetween({-outer.x, y0, inner.y}, {outer.x, y1, outer.y}, uvPerMetre);
  b.addBoxBetween({-outer.x, y0, -outer.y}, {outer.x, y1, -inner.y}, uvPerMetre);
  b.addBoxBetween({inner.x, y0, -inner.y}, {outer.x, y1, inner.y}, uvPerMetre);
  b.addBoxBetween({-outer.x, y0, -inner.y}, {-inner.x, y1, inner.y}, uvPerMetre);
}

// Floors, roof, mouldings, outer walls and their pilasters, beams and the corner blocks: the
// parts that appear once, in world space.
uint32_t buildStructure(Scene& scene, const AtriumMaterials& m) {
  MeshBuilder b("atrium structure");
  const float face = 0.5f * kArcadeThickness;
  const glm::vec2 court(kCourtHalfX - face, kCourtHalfZ - face);  // the arcades' courtyard faces
  const glm::vec2 wall(kCourtHalfX + kAisleWidth, kCourtHalfZ + kAisleWidth);
  const glm::vec2 wallOut = wall + glm::vec2(kOuterWallThickness);
  b.setMaterial(m.floor);
  b.addQuad(glm::mat4(1.0f), 2.0f * wall, 0.25f);
  b.setMaterial(m.wood);
  addFrame(b, court, wall, kGalleryFloor - kSlabThickness, kGalleryFloor, 0.5f);
  addFrame(b, court, wall, kRoofBottom, kRoofBottom + 0.1f, 0.5f);
  b.setMaterial(m.roof);
  addFrame(b, court, wall, kRoofBottom + 0.1f, kRoofTop, 0.25f);
  b.setMaterial(m.plaster);
  addFrame(b, wall, wallOut, 0.0f, kRoofTop, 0.25f);
  b.setMaterial(m.trim);
  addFrame(b, court - glm::vec2(0.2f), court, kGalleryFloor - 0.4f, kGalleryFloor - 0.05f, 0.5f);
  addFrame(b, court - glm::vec2(0.4f), court, kRoofBottom, kRoofTop + 0.1f, 0.5f);
  b.setMaterial(m.ashlar);
  addFrame(b, wall - glm::vec2(0.08f), wall, 0.0f, 1.2f, 0.5f);
  addFrame(b, wall - glm::vec2(0.08f), wall, kGalleryFloor, kGalleryFloor + 0.9f, 0.5f);
  for (float sx : {-1.0f, 1.0f}) {
    for (float sz : {-1.0f, 1.0f}) {  // the outer quarter of each corner column's wall
      const glm::vec3 a(sx * kCourtHalfX, 0.0f, sz * kCourtHalfZ), d(sx * face, 0.0f, sz * face);
      for (auto [y0, y1] :
           {std::pair{kGroundSpring, kGalleryFloor - kSlabThickness}, std::pair{kUpperSpring, kRoofBottom}}) {
        b.addBoxBetween(glm::min(a, a + d) + glm::vec3(0, y0, 0), glm::max(a, a + d) + glm::vec3(0, y1, 0),
                        0.5f);
      }
    }
  }
  const float beamLength = kAisleWidth - face - 0.15f;
  for (const ArcadeRow& row : arcadeRows()) {
    for (int k = 0; k < row.bays; ++k) {
      const glm::vec3 column = row.column(k);
      b.setMaterial(m.ashlar);
      b.addBox(
          row.placement(column - kAisleWidth * row.towardsCourtyard()) * at(0.0f, 0.5f * kRoofBottom, 0.075f),
          {0.6f, kRoofBottom, 0.15f}, 0.5f);
      b.setMaterial(m.wood);
      for (float top : {kGalleryFloor - kSlabThickness, kRoofBottom}) {
        b.addBox(row.placement(column) * at(0.0f, top - 0.175f, -face - 0.5f * beamLength),
                 {0.3f, 0.35f, beamLength}, 0.5f);
      }
    }
  }
  return b.addTo(scene);
}

// A display plinth of dark marble with a pale top, kPlinthTop high.
void addPlinth(MeshBuilder& b, const AtriumMaterials& m) {
  b.setMaterial(m.darkMarble);
  b.addBoxBetween({-0.35f, 0.0f, -0.35f}, {0.35f, kPlinthTop - 0.06f, 0.35f}, 0.5f);
  b.setMaterial(m.trim);
  b.addBoxBetween({-0.4f, kPlinthTop - 0.06f, -0.4f}, {0.4f, kPlinthTop, 0.4f}, 0.5f);
}

void placeObject(Scene& scene, MeshBuilder& b, float x, float z) {
  addInstance(scene, b.addTo(scene), at(x, 0.0f, z));
}

void addGlassAndMetal(Scene& scene, const AtriumMaterials& m) {
  MeshBuilder b("glass sphere on a plinth");
  addPlinth(b, m);
  b.setMaterial(m.bronze);
  b.addCylinder(at(0.0f, kPlinthTop, 0.0f), 0.14f, 0.05f, 24);
  b.setMaterial(m.clearGlass);
  b.addSphere(at(0.0f, kPlinthTop + 0.35f, 0.0f), 0.32f, 32, 16);
  placeObject(scene, b, -8.0f, -3.2f);

  static const glm::vec2 vase[] = {{0.10f, 0.0f},  {0.16f, 0.08f}, {0.2f, 0.2f},   {0.19f, 0.32f},
                                   {0.13f, 0.44f}, {0.08f, 0.52f}, {0.075f, 0.6f}, {0.1f, 0.66f}};
  b = MeshBuilder("green glass vase on a plinth");
  addPlinth(b, m);
  b.setMaterial(m.greenGlass);
  b.addLathe(at(0.0f, kPlinthTop, 0.0f), vase, 32, true, true);
  placeObject(scene, b, -8.0f, 3.2f);

  b = MeshBuilder("tall glass vase on a plinth");
  addPlinth(b, m);
  b.setMaterial(m.clearGlass);
  b.addLathe(at(0.0f, kPlinthTop, 0.0f) * glm::scale(glm::mat4(1.0f), glm::vec3(1.0f, 1.6f, 1.0f)), vase, 32,
             true, true);
  placeObject(scene, b, 4.5f, -2.4f);

  b = MeshBuilder("glass case");
  b.setMaterial(m.darkMarble);
  b.addBoxBetween({-0.5f, 0.0f, -0.5f}, {0.5f, 0.4f, 0.5f}, 0.5f);
  b.setMaterial(m.gold);
  b.addSphere(at(0.0f, 0.62f, 0.0f), 0.2f, 24, 12);
  b.setMaterial(m.blueGlass);
  b.addBoxBetween({-0.4f, 0.4f, -0.4f}, {0.4f, 1.2f, 0.4f});
  placeObject(scene, b, -4.5f, -2.4f);

  b = MeshBuilder("glass spheres");
  b.setMaterial(m.clearGlass);
  b.addSphere(at(0.0f, 0.3f, 0.0f), 0.3f, 32, 16);
  b.setMaterial(m.blueGlass);
  b.addSphere(at(0.6f, 0.22f, 0.3f), 0.22f, 24, 12);
  b.setMaterial(m.greenGlass);
  b.addSphere(at(0.1f, 0.18f, 0.6f), 0.18f, 24, 12);
  placeObject(scene, b, -4.8f, 2.3f);

  static const glm::vec2 urn[] = {{0.16f, 0.0f},  {0.16f, 0.04f}, {0.09f, 0.08f}, {0.08f, 0.12f},
                                  {0.2f, 0.25f},  {0.27f, 0.4f},  {0.25f, 0.55f}, {0.15f, 0.68f},
                                  {0.11f, 0.74f}, {0.13f, 0.8f},  {0.16f, 0.83f}};
  b = MeshBuilder("bronze urn on a plinth");
  addPlinth(b, m);
  b.setMaterial(m.bronze);
  b.addLathe(at(0.0f, kPlinthTop, 0.0f), urn, 32, true, true);
  placeObject(scene, b, 8.0f, -3.2f);

  b = MeshBuilder("gold sphere on a plinth");
  addPlinth(b, m);
  b.setMaterial(m.bronze);
  b.addCylinder(at(0.0f, kPlinthTop, 0.0f), 0.14f, 0.05f, 24);
  b.setMaterial(m.gold);
  b.addSphere(at(0.0f, kPlinthTop + 0.33f, 0.0f), 0.3f, 32, 16);
  placeObject(scene, b, 8.0f, 3.2f);

  b = MeshBuilder("bronze globe");
  b.setMaterial(m.trim);
  b.addCylinder(glm::mat4(1.0f), 0.5f, 0.15f, 32, 0.5f);
  b.setMaterial(m.bronze);
  b.addSphere(at(0.0f, 0.68f, 0.0f), 0.55f, 40, 20);
  placeObject(scene, b, 4.5f, 2.4f);
}

void addCameras(Scene& scene) {
  const float fov = glm::radians(65.0f);
  scene.cameras = {
      Camera{"overview", {-14.0f, 2.5f, 0.0f}, {0.0f, 3.2f, 0.0f}, {0.0f, 1.0f, 0.0f}, fov},
      Camera{"gallery", {15.0f, 8.7f, -1.75f}, {0.0f, 0.5f, 0.8f}, {0.0f, 1.0f, 0.0f}, fov},
      Camera{"floor", {-8.6f, 0.9f, 0.0f}, {-4.6f, 0.9f, 0.0f}, {0.0f, 1.0f, 0.0f}, fov},
      Camera{"top", {0.0f, 13.5f, 0.01f}, {0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}, fov},
  };
}

}  // namespace

glm::mat4 ArcadeRow::placement(const glm::vec3& position) const {
  return glm::rotate(glm::translate(glm::mat4(1.0f), position), rotation, glm::vec3(0, 1, 0));
}

std::array<ArcadeRow, 4> arcadeRows() {
  const float longBay = 2.0f * kCourtHalfX / float(kLongBays);
  const float shortBay = 2.0f * kCourtHalfZ / float(kShortBays);
  return {{
      {{-kCourtHalfX, 0, -kCourtHalfZ}, {1, 0, 0}, 0.0f, kLongBays, longBay},
      {{kCourtHalfX, 0, kCourtHalfZ}, {-1, 0, 0}, kPi, kLongBays, longBay},
      {{kCourtHalfX, 0, -kCourtHalfZ}, {0, 0, 1}, -0.5f * kPi, kShortBays, shortBay},
      {{-kCourtHalfX, 0, kCourtHalfZ}, {0, 0, -1}, 0.5f * kPi, kShortBays, shortBay},
  }};
}

Scene makeAtriumGeometry() {
  Scene scene;
  const AtriumMaterials m = addMaterials(scene);
  addInstance(scene, buildStructure(scene, m));
  const uint32_t groundColumn =
      buildColumn(scene, m, {"ground column", kGroundSpring, 0.27f, 0.8f, 0.25f, m.trim});
  const uint32_t upperColumn = buildColumn(
      scene, m, {"upper column", kUpperSpring - kGalleryFloor, 0.2f, 0.6f, kPedestalHeight, m.ashlar});
  const float groundHeight = kGalleryFloor - kSlabThickness - kGroundSpring;
  const float upperHeight = kRoofBottom - kUpperSpring;
  std::array<uint32_t, 5> banners;
  for (size_t i = 0; i < banners.size(); ++i) banners[i] = buildBanner(scene, m, m.cloth[i]);
  int bannerCount = 0;
  for (const ArcadeRow& row : arcadeRows()) {
    const float w = row.bayWidth;
    const bool isLong = row.bays == kLongBays;
    const uint32_t groundBay = buildArcadeBay(scene, m, isLong ? "long ground bay" : "short ground bay", w,
                                              groundHeight, 0.5f * w - kGroundAbacusHalf);
    const uint32_t upperBay = buildArcadeBay(scene, m, isLong ? "long upper bay" : "short upper bay", w,
                                             upperHeight, 0.5f * w - kUpperAbacusHalf);
    const uint32_t rail =
        buildBalustrade(scene, m, isLong ? "long balustrade" : "short balustrade", w - 0.6f);
    for (int k = 0; k < row.bays; ++k) {
      const glm::vec3 column = row.column(k), bay = row.bayCentre(k);
      addInstance(scene, groundColumn, row.placement(column));
      addInstance(scene, upperColumn, row.placement(column + glm::vec3(0, kGalleryFloor, 0)));
      addInstance(scene, groundBay, row.placement(bay + glm::vec3(0, kGroundSpring, 0)));
      addInstance(scene, upperBay, row.placement(bay + glm::vec3(0, kUpperSpring, 0)));
      addInstance(scene, rail, row.placement(bay + glm::vec3(0, kGalleryFloor, 0)));
      // Banners hang in front of every other column from the gallery rail, over the arches' springs.
      const bool hasBanner = isLong ? k % 2 == 1 : k == row.bays / 2;
      if (!hasBanner) continue;
      const glm::vec3 rod = column + glm::vec3(0, kGalleryFloor + 0.85f, 0) + 0.75f * row.towardsCourtyard();
      addInstance(scene, banners[bannerCount++ % banners.size()], row.placement(rod));
    }
  }
  MeshBuilder medallion("floor medallion");
  medallion.setMaterial(m.trim);
  medallion.addCylinder(glm::mat4(1.0f), 2.3f, 0.015f, 64, 0.5f);
  medallion.setMaterial(m.medallion);
  medallion.addCylinder(glm::mat4(1.0f), 2.0f, 0.02f, 64, 0.5f);
  addInstance(scene, medallion.addTo(scene));
  addGlassAndMetal(scene, m);
  addCameras(scene);
  return scene;
}

Bounds atriumCourtyardVolume() {
  Bounds volume;
  volume.expand({-kCourtHalfX + 2.0f, 1.5f, -kCourtHalfZ + 1.5f});
  volume.expand({kCourtHalfX - 2.0f, kRoofBottom - 2.0f, kCourtHalfZ - 1.5f});
  return volume;
}

}  // namespace lll::builtin
