#include "scene/gltf_files.h"

#include <cctype>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
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

namespace {

uint32_t read32(const std::vector<unsigned char>& bytes, size_t at) {
  return uint32_t(bytes[at]) | uint32_t(bytes[at + 1]) << 8 | uint32_t(bytes[at + 2]) << 16 |
         uint32_t(bytes[at + 3]) << 24;
}

void put32(std::vector<unsigned char>& out, uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<unsigned char>(v >> (8 * i)));
}

}  // namespace

std::vector<unsigned char> withJsonEdited(const std::vector<unsigned char>& bytes, bool binary,
                                          const std::string& marker,
                                          const std::function<bool(nlohmann::json&)>& edit) {
  size_t begin = 0, size = bytes.size();
  if (binary) {
    if (bytes.size() < 20) return bytes;  // tinygltf says what is wrong with it
    begin = 20;
    size = std::min<size_t>(read32(bytes, 12), bytes.size() - 20);
  }
  const std::string text(reinterpret_cast<const char*>(bytes.data() + begin), size);
  if (text.find(marker) == std::string::npos) return bytes;
  nlohmann::json doc = nlohmann::json::parse(text, nullptr, false);
  if (doc.is_discarded() || !edit(doc)) return bytes;
  std::string json = doc.dump();
  if (!binary) return {json.begin(), json.end()};
  // The .glb again: header, the new JSON chunk (padded with spaces), then every chunk after the
  // old one as it was.
  while (json.size() % 4 != 0) json += ' ';
  const size_t rest = begin + size;
  std::vector<unsigned char> out(bytes.begin(), bytes.begin() + 12);
  put32(out, uint32_t(json.size()));
  put32(out, 0x4E4F534A);  // "JSON"
  out.insert(out.end(), json.begin(), json.end());
  const size_t restBegin = std::min(bytes.size(), (rest + 3) / 4 * 4);
  out.insert(out.end(), bytes.begin() + std::ptrdiff_t(restBegin), bytes.end());
  const uint32_t total = uint32_t(out.size());
  std::memcpy(out.data() + 8, &total, 4);  // little-endian, as the .glb header
  return out;
}

}  // namespace lll::gltf_detail
