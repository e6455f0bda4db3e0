#pragma once
// Private to the glTF loader: reading its files as untrusted input. Whole files with a size bound
// and our error text, the filesystem callbacks tinygltf gets (referenced files from the glTF's
// folder only, nothing written), and cheap checks on the JSON before tinygltf parses it.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

namespace lll::gltf_detail {

// tinygltf copies "extras" and "extensions" into its own tree recursively: bounding the nesting
// keeps a hostile file from overflowing the stack. Real glTF files nest well under 20 deep.
inline constexpr int kMaxJsonNesting = 128;

// Reads a whole file for us and for tinygltf (its .bin and image references), with the size bound
// and error text we want. Returns false with `error` set when the file cannot be used.
bool readFileBytes(const std::filesystem::path& path, std::vector<unsigned char>& bytes, std::string& error);

// tinygltf looks for referenced files in the glTF's folder, then in the working directory. We
// accept only the glTF's folder, so whether a .bin is found does not depend on where we run.
struct FileAccess {
  std::string baseDir;
};

// tinygltf's filesystem callbacks; `user` is a FileAccess.
bool fileExistsBesideGltf(const std::string& path, void* user);
std::string keepPath(const std::string& path, void*);
bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void*);
bool refuseWrite(std::string* err, const std::string&, const std::vector<unsigned char>&, void*);

// Whether the bytes (after a UTF-8 BOM and white space) open a JSON object.
bool looksLikeJsonObject(const std::vector<unsigned char>& bytes);
// False when the JSON nests deeper than kMaxJsonNesting. Counts only brackets outside strings.
bool jsonNestingWithinLimit(const unsigned char* text, size_t size);
// The glTF's bytes (JSON, or a .glb) with its JSON rewritten by `edit`, where the JSON mentions
// `marker` and `edit` returns true (it changed something); the bytes unchanged otherwise, and where
// the JSON does not parse (tinygltf then says what is wrong with it). For what tinygltf would refuse
// in files that an extension makes valid (data-less buffers and accessors).
std::vector<unsigned char> withJsonEdited(const std::vector<unsigned char>& bytes, bool binary,
                                          const std::string& marker,
                                          const std::function<bool(nlohmann::json&)>& edit);
// tinygltf's error text on one line, in printable ASCII (parse errors quote the raw bytes they met).
std::string oneLine(std::string text);

}  // namespace lll::gltf_detail
