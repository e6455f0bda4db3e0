#include "render/image_io.h"

#include <fmt/format.h>

#include <cstdio>
#include <cstring>
#include <fstream>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image.h>  // declarations only: the decoder is compiled in the glTF loader's unit
#include <stb_image_write.h>
#include <tinyexr.h>

#include "core/errors.h"

namespace lll {

namespace {

std::string lowerExtension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

void writePfm(const std::filesystem::path& path, const HdrImage& image) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw InputError(fmt::format("{}: cannot open for writing", path.string()));
  // PFM: little-endian (negative scale), rows stored bottom to top.
  out << "PF\n" << image.width << " " << image.height << "\n-1.0\n";
  std::vector<float> row(size_t(image.width) * 3);
  for (uint32_t y = image.height; y-- > 0;) {
    for (uint32_t x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c) row[size_t(x) * 3 + c] = image.rgba[(size_t(y) * image.width + x) * 4 + c];
    out.write(reinterpret_cast<const char*>(row.data()), std::streamsize(row.size() * sizeof(float)));
  }
  out.close();
  if (!out) throw InputError(fmt::format("{}: write failed", path.string()));
}

void writeExr(const std::filesystem::path& path, const HdrImage& image) {
  const char* error = nullptr;
  const int result = SaveEXR(image.rgba.data(), int(image.width), int(image.height), 4, /*save_as_fp16=*/1,
                             path.string().c_str(), &error);
  if (result != TINYEXR_SUCCESS) {
    std::string message = error ? error : "unknown error";
    if (error) FreeEXRErrorMessage(error);
    throw InputError(fmt::format("{}: cannot write EXR: {}", path.string(), message));
  }
}

}  // namespace

void writePng(const std::filesystem::path& path, const LdrImage& image) {
  if (lowerExtension(path) != ".png")
    throw InputError(
        fmt::format("--out {}: the display image is written as PNG; use a .png name", path.string()));
  if (!stbi_write_png(path.string().c_str(), int(image.width), int(image.height), 4, image.rgba.data(),
                      int(image.width * 4)))
    throw InputError(
        fmt::format("{}: cannot write PNG (does the folder exist and is it writable?)", path.string()));
}

void writeHdr(const std::filesystem::path& path, const HdrImage& image) {
  const std::string ext = lowerExtension(path);
  if (ext == ".pfm")
    writePfm(path, image);
  else if (ext == ".exr")
    writeExr(path, image);
  else
    throw InputError(fmt::format("--hdr {}: unknown HDR format; use a .exr or .pfm name", path.string()));
}

LdrImage readPng(const std::filesystem::path& path) {
  int w = 0, h = 0, channels = 0;
  unsigned char* pixels = stbi_load(path.string().c_str(), &w, &h, &channels, 4);
  if (!pixels) throw InputError(fmt::format("{}: cannot read PNG", path.string()));
  LdrImage image{uint32_t(w), uint32_t(h), {}};
  image.rgba.assign(pixels, pixels + size_t(w) * h * 4);
  stbi_image_free(pixels);
  return image;
}

}  // namespace lll
