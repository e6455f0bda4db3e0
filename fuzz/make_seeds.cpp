// Writes the fuzzer's seed corpus into a folder: each test scene of assets/ as a self-contained
// .glb (its .bin as the binary chunk; a .glb as it is), and a small lit, textured quad as .glb and as .gltf
// with its buffer in a data URI, so mutations start from files that load. Usage: make_seeds ASSETS_DIR
// OUT_DIR
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::vector<uint8_t> readBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void put32(std::vector<uint8_t>& out, uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(uint8_t(v >> (8 * i)));
}

// GLB 2.0: header, JSON chunk padded with spaces, BIN chunk padded with zeros.
void writeGlb(const fs::path& path, json doc, std::vector<uint8_t> bin) {
  doc["buffers"] = json::array({{{"byteLength", bin.size()}}});
  std::string text = doc.dump();
  while (text.size() % 4) text += ' ';
  while (bin.size() % 4) bin.push_back(0);
  std::vector<uint8_t> out = {'g', 'l', 'T', 'F'};
  put32(out, 2);
  put32(out, uint32_t(12 + 8 + text.size() + 8 + bin.size()));
  put32(out, uint32_t(text.size()));
  put32(out, 0x4E4F534A);  // "JSON"
  out.insert(out.end(), text.begin(), text.end());
  put32(out, uint32_t(bin.size()));
  put32(out, 0x004E4942);  // "BIN\0"
  out.insert(out.end(), bin.begin(), bin.end());
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(out.data()), std::streamsize(out.size()));
}

std::string base64(const std::vector<uint8_t>& bytes) {
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    const size_t left = bytes.size() - i;
    uint32_t n = uint32_t(bytes[i]) << 16;
    if (left > 1) n |= uint32_t(bytes[i + 1]) << 8;
    if (left > 2) n |= bytes[i + 2];
    out += digits[(n >> 18) & 63];
    out += digits[(n >> 12) & 63];
    out += left > 1 ? digits[(n >> 6) & 63] : '=';
    out += left > 2 ? digits[n & 63] : '=';
  }
  return out;
}

// A 2x2 RGBA PNG.
const std::vector<uint8_t> kPng = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52,
    0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x02, 0x08, 0x06, 0x00, 0x00, 0x00, 0x72, 0xb6, 0x0d,
    0x24, 0x00, 0x00, 0x00, 0x13, 0x49, 0x44, 0x41, 0x54, 0x78, 0xda, 0x63, 0xf8, 0xcf, 0xc0, 0xf0,
    0x1f, 0x0c, 0x81, 0x34, 0x08, 0x34, 0x00, 0x00, 0x49, 0x49, 0x09, 0x78, 0x9c, 0x51, 0x17, 0x92,
    0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};

// A 2x2 lossless WebP (EXT_texture_webp).
const std::vector<uint8_t> kWebp = {82, 73,  70, 70,  48, 0,   0,   0,   87,  69,  66,  80,  86,  80,
                                    56, 76,  35, 0,   0,  0,   47,  1,   64,  0,   16,  31,  48,  255,
                                    2,  130, 34, 255, 71, 219, 127, 129, 0,   193, 185, 115, 193, 141,
                                    42, 65,  77, 219, 6,  44,  126, 147, 142, 136, 254, 199, 1,   0};

// A quad with normals, two UV sets, vertex colours, 16-bit indices, a sparse accessor, a textured
// material with every extension the loader reads (a WebP image, a sampler, a texture transform),
// a point and a spot light and a camera.
void writeQuad(const fs::path& dir) {
  std::vector<uint8_t> bin;
  auto append = [&](const void* data, size_t size) {
    const size_t at = bin.size();
    bin.insert(bin.end(), static_cast<const uint8_t*>(data), static_cast<const uint8_t*>(data) + size);
    while (bin.size() % 4) bin.push_back(0);
    return at;
  };
  const float positions[] = {-1, 0, -1, 1, 0, -1, 1, 0, 1, -1, 0, 1};
  const float normals[] = {0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0};
  const float uvs[] = {0, 0, 1, 0, 1, 1, 0, 1};
  const float uvs1[] = {0, 0, 2, 0, 2, 2, 0, 2};
  const uint8_t colors[] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 128, 255, 255, 255, 255};
  const uint8_t joints[] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0};
  const float skinWeights[] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0.5f, 0.5f, 0, 0};
  const float inverseBinds[] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0,  0, 1,
                                1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1, 0, 1};
  const float morph[] = {0, 0.5f, 0, 0, 0, 0, 0, 0.25f, 0, 0, 0, 0};
  const uint16_t indices[] = {0, 2, 1, 0, 3, 2};
  const uint8_t sparseIndex[] = {1};
  const float sparseValue[] = {1, 0.2f, -1};
  const size_t p = append(positions, sizeof positions), n = append(normals, sizeof normals),
               u = append(uvs, sizeof uvs), i = append(indices, sizeof indices),
               si = append(sparseIndex, sizeof sparseIndex), sv = append(sparseValue, sizeof sparseValue),
               png = append(kPng.data(), kPng.size()), u1 = append(uvs1, sizeof uvs1),
               c = append(colors, sizeof colors), webp = append(kWebp.data(), kWebp.size()),
               j = append(joints, sizeof joints), w = append(skinWeights, sizeof skinWeights),
               ib = append(inverseBinds, sizeof inverseBinds), m = append(morph, sizeof morph);
  auto view = [](size_t offset, size_t length) {
    return json{{"buffer", 0}, {"byteOffset", offset}, {"byteLength", length}};
  };
  json doc = {
      {"asset", {{"version", "2.0"}}},
      {"extensionsUsed",
       {"KHR_lights_punctual", "KHR_materials_emissive_strength", "EXT_texture_webp", "KHR_texture_transform",
        "EXT_mesh_gpu_instancing"}},
      {"bufferViews",
       {view(p, sizeof positions), view(n, sizeof normals), view(u, sizeof uvs), view(i, sizeof indices),
        view(si, sizeof sparseIndex), view(sv, sizeof sparseValue), view(png, kPng.size()),
        view(u1, sizeof uvs1), view(c, sizeof colors), view(webp, kWebp.size()), view(j, sizeof joints),
        view(w, sizeof skinWeights), view(ib, sizeof inverseBinds), view(m, sizeof morph)}},
      {"accessors",
       {{{"bufferView", 0},
         {"componentType", 5126},
         {"count", 4},
         {"type", "VEC3"},
         {"min", {-1, 0, -1}},
         {"max", {1, 0.2, 1}},
         {"sparse",
          {{"count", 1},
           {"indices", {{"bufferView", 4}, {"componentType", 5121}}},
           {"values", {{"bufferView", 5}}}}}},
        {{"bufferView", 1}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
        {{"bufferView", 2}, {"componentType", 5126}, {"count", 4}, {"type", "VEC2"}},
        {{"bufferView", 3}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}},
        {{"bufferView", 7}, {"componentType", 5126}, {"count", 4}, {"type", "VEC2"}},
        {{"bufferView", 8}, {"componentType", 5121}, {"normalized", true}, {"count", 4}, {"type", "VEC4"}},
        {{"bufferView", 10}, {"componentType", 5121}, {"count", 4}, {"type", "VEC4"}},
        {{"bufferView", 11}, {"componentType", 5126}, {"count", 4}, {"type", "VEC4"}},
        {{"bufferView", 12}, {"componentType", 5126}, {"count", 2}, {"type", "MAT4"}},
        {{"bufferView", 13}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}}}},
      {"images",
       {{{"bufferView", 6}, {"mimeType", "image/png"}}, {{"bufferView", 9}, {"mimeType", "image/webp"}}}},
      {"samplers", {{{"wrapS", 33071}, {"wrapT", 33648}, {"magFilter", 9728}, {"minFilter", 9986}}}},
      {"textures",
       {{{"source", 0}},
        {{"source", 0}, {"sampler", 0}, {"extensions", {{"EXT_texture_webp", {{"source", 1}}}}}}}},
      {"materials",
       {{{"name", "tile"},
         {"pbrMetallicRoughness",
          {{"baseColorFactor", {1, 0.8, 0.6, 1}},
           {"metallicFactor", 0.1},
           {"baseColorTexture", {{"index", 0}}}}},
         {"normalTexture", {{"index", 0}, {"scale", 0.5}}},
         {"occlusionTexture",
          {{"index", 1},
           {"texCoord", 1},
           {"extensions", {{"KHR_texture_transform", {{"offset", {0.5, 0}}, {"rotation", 0.3}}}}}}},
         {"emissiveFactor", {0.1, 0, 0}},
         {"alphaMode", "MASK"},
         {"alphaCutoff", 0.3},
         {"doubleSided", true},
         {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 2.0}}}}}}}},
      {"meshes",
       {{{"primitives",
          {{{"attributes",
             {{"POSITION", 0},
              {"NORMAL", 1},
              {"TEXCOORD_0", 2},
              {"TEXCOORD_1", 4},
              {"COLOR_0", 5},
              {"JOINTS_0", 6},
              {"WEIGHTS_0", 7}}},
            {"targets", {{{"POSITION", 9}}}},
            {"indices", 3},
            {"material", 0}}}},
         {"weights", {0.5}}}}},
      {"skins", {{{"joints", {2, 3}}, {"inverseBindMatrices", 8}}}},
      {"extensions",
       {{"KHR_lights_punctual",
         {{"lights",
           {{{"type", "point"}, {"color", {1, 0.9, 0.8}}, {"intensity", 5.0}, {"range", 6.0}},
            {{"type", "spot"},
             {"intensity", 20.0},
             {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.5}}}}}}}}}},
      {"cameras", {{{"type", "perspective"}, {"perspective", {{"yfov", 0.9}, {"znear", 0.01}}}}}},
      {"nodes",
       {{{"mesh", 0}, {"children", {1}}, {"scale", {2, 1, 2}}, {"skin", 0}},
        {{"translation", {0, 1, 0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}},
        {{"rotation", {-0.7071068, 0, 0, 0.7071068}}, {"translation", {0, 3, 0}}, {"camera", 0}},
        {{"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0.5, 2, 0, 1}},
         {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}},
        {{"mesh", 0},
         {"weights", {1.0}},
         {"translation", {3, 0, 0}},
         {"extensions", {{"EXT_mesh_gpu_instancing", {{"attributes", {{"TRANSLATION", 9}}}}}}}}}},
      {"scenes", {{{"nodes", {0, 2, 3, 4}}}}},
      {"scene", 0}};
  writeGlb(dir / "quad.glb", doc, bin);
  doc["buffers"] = json::array(
      {{{"byteLength", bin.size()}, {"uri", "data:application/octet-stream;base64," + base64(bin)}}});
  std::ofstream(dir / "quad.gltf") << doc.dump();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: make_seeds ASSETS_DIR OUT_DIR\n");
    return 2;
  }
  const fs::path assets = argv[1], out = argv[2];
  fs::create_directories(out);
  int written = 0;
  for (const auto& entry : fs::recursive_directory_iterator(assets)) {
    // Named by folder and file: two folders may hold files of one name (cave/, cave-quantized/).
    const std::string name =
        entry.path().parent_path().filename().string() + "-" + entry.path().stem().string();
    if (entry.path().extension() == ".glb") {
      fs::copy_file(entry.path(), out / (name + ".glb"), fs::copy_options::overwrite_existing);
      ++written;
      continue;
    }
    if (entry.path().extension() != ".gltf") continue;
    json doc = json::parse(std::ifstream(entry.path()));
    const fs::path bin = entry.path().parent_path() / doc["buffers"][0]["uri"].get<std::string>();
    writeGlb(out / (name + ".glb"), doc, readBytes(bin));
    ++written;
  }
  writeQuad(out);
  std::printf("make_seeds: %d scenes and a quad (.glb, .gltf) in %s\n", written, out.c_str());
  return written > 0 ? 0 : 1;
}
