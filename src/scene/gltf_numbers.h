#pragma once
// Private to the glTF loader: glTF's numbers (JSON doubles) turned into the floats the renderer
// uses. A value finite as a double can be infinite as a float (1e308) or round to zero (1e-300),
// and either one makes NaN pixels, so each conversion checks the float it produces.
#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace tinygltf {
class Value;
}

namespace lll::gltf_detail {

class NumberReader {
 public:
  // Messages start with `file`; warnings (values clamped into glTF's range) go to `warnings`.
  NumberReader(const std::string& file, std::vector<std::string>& warnings)
      : file_(file), warnings_(warnings) {}

  // The float of `value`; throws InputError naming `what` and the value unless it is finite.
  float finite(double value, const std::string& what) const;
  // finite(), then at least `lo`: below it is an error (a negative intensity has no meaning).
  float atLeast(double value, double lo, const std::string& what) const;
  // finite(), then clamped into [lo, hi] with a warning: glTF gives the range, and exporters write
  // values a rounding error outside it.
  float clamped(double value, double lo, double hi, const std::string& what) const;
  // An array of exactly `size` numbers (glTF's fixed-size factors), each clamped into [lo, hi].
  std::vector<float> clampedArray(const std::vector<double>& values, size_t size, double lo, double hi,
                                  const std::string& what) const;

 private:
  const std::string& file_;
  std::vector<std::string>& warnings_;
};

// Throws InputError unless every element of `m` is finite: the float matrix, not the double one
// it was computed in (a node scale of 1e39 is finite only as a double).
void checkFiniteMatrix(const glm::mat4& m, const std::string& file, const std::string& what);

// A non-negative integer member `name` of an extension's JSON object, or `fallback` where it is
// absent; InputError "<file>: <where>'s <name> ..." when it is not one.
uint64_t unsignedMember(const tinygltf::Value& object, const char* name, uint64_t fallback,
                        const std::string& file, const std::string& where);

}  // namespace lll::gltf_detail
