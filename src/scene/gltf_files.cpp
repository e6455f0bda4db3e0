#include "scene/gltf_files.h"

#include <cctype>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <string_view>

namespace lll::gltf_detail {

namespace {
// tinygltf passes buffer and chunk sizes around as 32-bit ints.
constexpr uint64_t kMaxFileBytes = std::numeric_limits<int32_t>::max();
}  // namespace

bool readFileBytes(const std::filesystem::path& path, std::vector<unsigned char>& bytes, std::string& error) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status)) {
    error = "file not found";
    return false;
  }
  if (!std::filesystem::is_regular_file(status)) {
    error = "not a regular file";
    return false;
  }
  const uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) {
    error = ec.message();
    return false;
  }
  if (size == 0) {
    error = "file is empty";
    return false;
  }
  if (size > kMaxFileBytes) {
    error = "file is larger than 2 GiB";
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  bytes.resize(size_t(size));
  if (!in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(size))) {
    error = "read error (permissions?)";
    return false;
  }
  return true;
}

bool fileExistsBesideGltf(const std::string& path, void* user) {
  const auto* access = static_cast<const FileAccess*>(user);
  std::error_code ec;
  return path.compare(0, access->baseDir.size(), access->baseDir) == 0 &&
         std::filesystem::is_regular_file(path, ec);
}

std::string keepPath(const std::string& path, void*) {
  return path;
}

bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void*) {
  std::string error;
  if (readFileBytes(path, *out, error)) return true;
  *err += path + ": " + error + "\n";
  return false;
}

bool refuseWrite(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  *err += "writing is not supported\n";
  return false;
}

bool looksLikeJsonObject(const std::vector<unsigned char>& bytes) {
  size_t i = bytes.size() >= 3 && std::memcmp(bytes.data(), "\xEF\xBB\xBF", 3) == 0 ? 3 : 0;  // UTF-8 BOM
  while (i < bytes.size() && std::isspace(bytes[i])) ++i;
  return i < bytes.size() && bytes[i] == '{';
}

bool jsonNestingWithinLimit(const unsigned char* text, size_t size) {
  int depth = 0;
  bool inString = false;
  bool escaped = false;
  for (size_t i = 0; i < size; ++i) {
    const char c = char(text[i]);
    if (inString) {
      if (escaped) {
        escaped = false;
      } else if (c == '\\') {
        escaped = true;
      } else if (c == '"') {
        inString = false;
      }
    } else if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonNesting) return false;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return true;
}

std::string oneLine(std::string text) {
  while (!text.empty() && std::string_view("\n\r .").find(text.back()) != std::string_view::npos)
    text.pop_back();
  for (char& c : text) {
    if (c == '\n') {
      c = ';';
    } else if (c < ' ' || c > '~') {
      c = '?';
    }
  }
  return text;
}

}  // namespace lll::gltf_detail
