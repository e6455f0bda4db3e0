#pragma once
// Writing rendered images: PNG (display-encoded, via stb_image_write), EXR (linear half-float
// RGBA, via tinyexr) and PFM (linear float RGB, a trivial format written by hand).
#include <filesystem>

#include "render/images.h"

namespace lll {

// Throws InputError when the file cannot be written (naming the path).
void writePng(const std::filesystem::path& path, const LdrImage& image);
// .exr or .pfm, chosen by extension; throws InputError for any other extension.
void writeHdr(const std::filesystem::path& path, const HdrImage& image);
// Reads back a PNG written by writePng (for tests and image comparisons).
LdrImage readPng(const std::filesystem::path& path);

}  // namespace lll
