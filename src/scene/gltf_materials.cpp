// glTF materials for the loader (scene/gltf_importer.h): factors checked and clamped, textures
// and their KHR_texture_transform, images decoded on first use with stb_image, within a size bound.
#include <fmt/format.h>
#include <stb_image.h>  // its implementation is in gltf_loader.cpp, with tiny_gltf's
#include <webp/decode.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/gtc/type_ptr.hpp>

#include "scene/gltf_importer.h"
#include "scene/lights.h"

namespace lll::gltf_detail {
namespace {

// Beyond what any GPU we target samples; stops a forged image header from asking for gigabytes.
constexpr int kMaxTextureSide = 16384;

}  // namespace

Material GltfImporter::convertMaterial(const tinygltf::Material& in, int index) {
  Material out;
  out.name = in.name.empty() ? "material " + std::to_string(index) : in.name;
  const tinygltf::PbrMetallicRoughness& pbr = in.pbrMetallicRoughness;
  const std::string name = "material " + inQuotes(out.name);
  out.baseColorFactor = glm::make_vec4(
      numbers_.clampedArray(pbr.baseColorFactor, 4, 0.0, 1.0, name + " baseColorFactor").data());
  // Emissive factors above 1 are common in files older than KHR_materials_emissive_strength.
  out.emissiveFactor = glm::make_vec3(
      numbers_.clampedArray(in.emissiveFactor, 3, 0.0, kMaxEmissiveStrength, name + " emissiveFactor")
          .data());
  out.metallic = numbers_.clamped(pbr.metallicFactor, 0.0, 1.0, name + " metallicFactor");
  out.roughness = numbers_.clamped(pbr.roughnessFactor, 0.0, 1.0, name + " roughnessFactor");
  out.normalScale = numbers_.finite(in.normalTexture.scale, name + " normalTexture scale");
  out.occlusionStrength =
      numbers_.clamped(in.occlusionTexture.strength, 0.0, 1.0, name + " occlusion strength");
  out.alphaCutoff = numbers_.atLeast(in.alphaCutoff, 0.0, name + " alphaCutoff");
  out.doubleSided = in.doubleSided;
  if (in.alphaMode == "OPAQUE") {
    out.alphaMode = AlphaMode::Opaque;
  } else if (in.alphaMode == "MASK") {
    out.alphaMode = AlphaMode::Mask;
  } else if (in.alphaMode == "BLEND") {
    out.alphaMode = AlphaMode::Blend;
  } else {
    fail("material " + inQuotes(out.name) + " has alphaMode '" + in.alphaMode +
         "'; glTF allows OPAQUE, MASK or BLEND");
  }
  if (auto strength = in.extensions.find("KHR_materials_emissive_strength");
      strength != in.extensions.end()) {
    const tinygltf::Value& value = strength->second.Get("emissiveStrength");
    if (value.IsNumber())
      out.emissiveStrength = numbers_.atLeast(value.GetNumberAsDouble(), 0.0, name + " emissiveStrength");
  }
  const double emission =
      double(std::max({out.emissiveFactor.r, out.emissiveFactor.g, out.emissiveFactor.b})) *
      double(out.emissiveStrength);
  if (emission > double(kMaxEmissiveStrength))
    fail(name + " emits " + std::to_string(emission) + " (emissiveFactor x emissiveStrength), above the " +
         std::to_string(kMaxEmissiveStrength) + " the renderer's 32-bit shading takes without overflow");
  out.baseColorTexture = textureFor(pbr.baseColorTexture, true, "base colour", kBaseColorSlot, out);
  out.metallicRoughnessTexture =
      textureFor(pbr.metallicRoughnessTexture, false, "metallic-roughness", kMetallicRoughnessSlot, out);
  out.normalTexture = textureFor(in.normalTexture, false, "normal", kNormalSlot, out);
  out.occlusionTexture = textureFor(in.occlusionTexture, false, "occlusion", kOcclusionSlot, out);
  out.emissiveTexture = textureFor(in.emissiveTexture, true, "emissive", kEmissiveSlot, out);
  return out;
}

// A texture's KHR_texture_transform (identity without one); `what` names the texture.
TextureTransform GltfImporter::textureTransform(const tinygltf::ExtensionMap& extensions,
                                                const std::string& what, int& texCoord) {
  TextureTransform t;
  const auto found = extensions.find("KHR_texture_transform");
  if (found == extensions.end()) return t;
  const tinygltf::Value& e = found->second;
  const std::string name = what + " texture's KHR_texture_transform";
  const auto pair = [&](const char* field, glm::vec2 fallback) {
    if (!e.Has(field)) return fallback;
    const tinygltf::Value& v = e.Get(field);
    if (!v.IsArray() || v.ArrayLen() != 2 || !v.Get(0).IsNumber() || !v.Get(1).IsNumber())
      fail(name + "'s " + field + " is not two numbers");
    return glm::vec2(numbers_.finite(v.Get(0).GetNumberAsDouble(), name + " " + field + "[0]"),
                     numbers_.finite(v.Get(1).GetNumberAsDouble(), name + " " + field + "[1]"));
  };
  t.offset = pair("offset", glm::vec2(0.0f));
  t.scale = pair("scale", glm::vec2(1.0f));
  if (e.Has("rotation")) {
    if (!e.Get("rotation").IsNumber()) fail(name + " has a rotation that is not a number");
    t.rotation = numbers_.finite(e.Get("rotation").GetNumberAsDouble(), name + " rotation");
  }
  // Its texCoord replaces the texture's own.
  if (e.Has("texCoord")) {
    const tinygltf::Value& v = e.Get("texCoord");
    const double d = v.IsNumber() ? v.GetNumberAsDouble() : -1.0;
    if (!(d >= 0.0 && d <= 1e9) || d != std::floor(d))
      fail(name + "'s texCoord is not a non-negative integer");
    texCoord = int(d);
  }
  return t;
}

template <typename Info>
int GltfImporter::textureFor(const Info& info, bool srgb, const char* slot, TextureSlot slotIndex,
                             Material& out) {
  if (info.index < 0) return -1;
  const std::string& material = out.name;
  int texCoord = info.texCoord;
  out.transforms[slotIndex] =
      textureTransform(info.extensions, "material " + inQuotes(material) + " " + slot, texCoord);
  // TEXCOORD_0 and TEXCOORD_1 are kept (a primitive without the set reads zeros, as without
  // TEXCOORD_0); a later set is read as TEXCOORD_0, warned about at the end.
  if (texCoord < 0)
    fail("material " + inQuotes(material) + "'s " + slot + " texture has texCoord " +
         std::to_string(texCoord) + "; glTF's texture coordinate sets start at 0");
  if (texCoord == 1) out.texCoords[slotIndex] = 1;
  if (texCoord > 1) usesOtherTexCoords_ = true;
  if (size_t(info.index) >= model_.textures.size()) {
    fail("material " + inQuotes(material) + " uses texture " + std::to_string(info.index) + " as its " +
         slot + " texture, but the file has " + std::to_string(model_.textures.size()) + " textures");
  }
  const int image = textureSource(info.index);
  if (image < 0) {
    warn("material " + inQuotes(material) + ": its " + slot + " texture " + std::to_string(info.index) +
         " has no PNG, JPEG or WebP source (an image extension we do not support?); a neutral texture is "
         "used");
    return -1;
  }
  if (size_t(image) >= model_.images.size()) {
    fail("texture " + std::to_string(info.index) + " refers to image " + std::to_string(image) +
         ", but the file has " + std::to_string(model_.images.size()) + " images");
  }
  const int samplerIndex = model_.textures[size_t(info.index)].sampler;
  const TextureSampler sampler = textureSampler(samplerIndex);
  if (auto known = textureIndex_.find({image, srgb, samplerIndex}); known != textureIndex_.end())
    return known->second;

  decodeImage(image);
  DecodedImage& decoded = images_[size_t(image)];
  if (!decoded.failure.empty()) {
    warn("material " + inQuotes(material) + ": " + slot + " image " + inQuotes(imageName(image)) +
         " could not be loaded (" + decoded.failure + "); a neutral texture is used instead");
    return -1;
  }
  // The decode counted one copy of its texels; every further texture of the image (another
  // sampler, the other colour space) is another copy, counted too: one large image under a
  // thousand samplers is a thousand copies.
  const uint64_t texels = uint64_t(decoded.width) * decoded.height;
  if (decoded.textures > 0) {
    if (decodedTexels_ + texels > limits_.textureTexels) {
      warn("material " + inQuotes(material) + ": another copy of " + slot + " image " +
           inQuotes(imageName(image)) +
           " (for another sampler or colour space) would take the scene's textures past the " +
           std::to_string(limits_.textureTexels) + " texels accepted; a neutral texture is used instead");
      return -1;
    }
    decodedTexels_ += texels;
  }
  ++decoded.textures;
  Texture texture;
  texture.name = imageName(image);
  texture.width = decoded.width;
  texture.height = decoded.height;
  texture.rgba = decoded.rgba;
  texture.srgb = srgb;
  texture.sampler = sampler;
  scene_.textures.push_back(std::move(texture));
  const int index = int(scene_.textures.size() - 1);
  textureIndex_[{image, srgb, samplerIndex}] = index;
  return index;
}

int GltfImporter::textureSource(int texture) {
  const tinygltf::Texture& t = model_.textures[size_t(texture)];
  // EXT_texture_webp names the WebP image; the core source, where there is one, is the fallback
  // for viewers without the extension.
  const auto webp = t.extensions.find("EXT_texture_webp");
  if (webp == t.extensions.end()) return t.source;
  const tinygltf::Value& e = webp->second;
  const double source = e.IsObject() && e.Has("source") && e.Get("source").IsNumber()
                            ? e.Get("source").GetNumberAsDouble()
                            : -1.0;
  if (!(source >= 0.0 && source < 2147483648.0) || source != std::floor(source))
    fail("texture " + std::to_string(texture) + "'s EXT_texture_webp has no source image index");
  return int(source);
}

TextureSampler GltfImporter::textureSampler(int index) {
  TextureSampler out;
  if (index < 0) return out;
  if (size_t(index) >= model_.samplers.size())
    fail("a texture refers to sampler " + std::to_string(index) + ", but the file has " +
         std::to_string(model_.samplers.size()) + " samplers");
  const tinygltf::Sampler& in = model_.samplers[size_t(index)];
  const std::string where = "sampler " + std::to_string(index);
  const auto wrap = [&](int value, const char* field) {
    switch (value) {
      case TINYGLTF_TEXTURE_WRAP_REPEAT:
        return TextureWrap::Repeat;
      case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE:
        return TextureWrap::ClampToEdge;
      case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT:
        return TextureWrap::MirroredRepeat;
      default:
        fail(where + " has " + field + " " + std::to_string(value) +
             "; glTF allows 33071 (clamp to edge), 33648 (mirrored repeat) and 10497 (repeat)");
    }
  };
  out.wrapU = wrap(in.wrapS, "wrapS");
  out.wrapV = wrap(in.wrapT, "wrapT");
  if (in.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST) {
    out.magnify = TextureFilter::Nearest;
  } else if (in.magFilter != -1 && in.magFilter != TINYGLTF_TEXTURE_FILTER_LINEAR) {
    fail(where + " has magFilter " + std::to_string(in.magFilter) +
         "; glTF allows 9728 (nearest) and 9729 (linear)");
  }
  // minFilter: 9728 + (0 nearest, 1 linear), or 9984 + (nearest or linear texel) + 2 (linear mip).
  switch (in.minFilter) {
    case -1:
      break;
    case TINYGLTF_TEXTURE_FILTER_NEAREST:
      out.minify = TextureFilter::Nearest, out.mip = MipFilter::None;
      break;
    case TINYGLTF_TEXTURE_FILTER_LINEAR:
      out.mip = MipFilter::None;
      break;
    case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST:
      out.minify = TextureFilter::Nearest, out.mip = MipFilter::Nearest;
      break;
    case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_NEAREST:
      out.mip = MipFilter::Nearest;
      break;
    case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR:
      out.minify = TextureFilter::Nearest;
      break;
    case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR:
      break;
    default:
      fail(where + " has minFilter " + std::to_string(in.minFilter) +
           "; glTF allows 9728, 9729 and 9984 to 9987 (nearest, linear, and their mipmapped forms)");
  }
  return out;
}

bool GltfImporter::withinTextureBounds(int width, int height, DecodedImage& decoded) {
  const std::string size = std::to_string(width) + "x" + std::to_string(height);
  if (width > kMaxTextureSide || height > kMaxTextureSide) {
    decoded.failure =
        size + " is larger than the " + std::to_string(kMaxTextureSide) + " pixels per side we accept";
    return false;
  }
  const uint64_t texels = uint64_t(width) * uint64_t(height);
  if (decodedTexels_ + texels > limits_.textureTexels) {
    decoded.failure = size + " would take the scene's decoded textures past the " +
                      std::to_string(limits_.textureTexels) + " texels (" +
                      std::to_string((limits_.textureTexels * 4) >> 20) + " MiB) we accept in all";
    return false;
  }
  decodedTexels_ += texels;
  return true;
}

const GltfImporter::DecodedImage& GltfImporter::decodeImage(int index) {
  DecodedImage& decoded = images_[size_t(index)];
  if (decoded.attempted) return decoded;
  decoded.attempted = true;

  const tinygltf::Image& image = model_.images[size_t(index)];
  const unsigned char* bytes = image.image.data();
  size_t size = image.image.size();
  if (image.bufferView >= 0) {  // in range: tinygltf checked it; checkBufferViews() checked the view
    const tinygltf::BufferView& view = model_.bufferViews[size_t(image.bufferView)];
    bytes = model_.buffers[size_t(view.buffer)].data.data() + view.byteOffset;
    size = view.byteLength;
  }
  if (size == 0) {
    decoded.failure = image.uri.empty() ? "it has no data" : "the file is missing or unreadable";
    return decoded;
  }
  int width = 0;
  int height = 0;
  int channels = 0;
  // WebP (EXT_texture_webp): "RIFF", the chunk's size, "WEBP".
  if (size >= 12 && std::memcmp(bytes, "RIFF", 4) == 0 && std::memcmp(bytes + 8, "WEBP", 4) == 0) {
    if (!WebPGetInfo(bytes, size, &width, &height)) {
      decoded.failure = "not a decodable WebP image (its header is broken)";
      return decoded;
    }
    if (!withinTextureBounds(width, height, decoded)) return decoded;
    decoded.rgba.resize(size_t(width) * size_t(height) * 4);
    if (!WebPDecodeRGBAInto(bytes, size, decoded.rgba.data(), decoded.rgba.size(), width * 4)) {
      decoded.rgba.clear();
      decoded.failure = "WebP decoding failed: the image data is corrupt";
      return decoded;
    }
    decoded.width = uint32_t(width);
    decoded.height = uint32_t(height);
    return decoded;
  }
  if (!stbi_info_from_memory(bytes, int(size), &width, &height, &channels)) {
    decoded.failure = std::string("not a decodable PNG, JPEG or WebP: ") + stbi_failure_reason();
    return decoded;
  }
  if (!withinTextureBounds(width, height, decoded)) return decoded;
  stbi_uc* pixels = stbi_load_from_memory(bytes, int(size), &width, &height, &channels, 4);
  if (pixels == nullptr) {
    decoded.failure = std::string("decoding failed: ") + stbi_failure_reason();
    return decoded;
  }
  decoded.width = uint32_t(width);
  decoded.height = uint32_t(height);
  decoded.rgba.assign(pixels, pixels + size_t(width) * size_t(height) * 4);
  stbi_image_free(pixels);
  return decoded;
}

std::string GltfImporter::imageName(int index) const {
  const tinygltf::Image& image = model_.images[size_t(index)];
  if (!image.uri.empty()) return image.uri;
  if (!image.name.empty()) return "embedded image " + image.name;
  return "embedded image " + std::to_string(index);
}

}  // namespace lll::gltf_detail
