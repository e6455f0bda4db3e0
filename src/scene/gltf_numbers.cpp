#include "scene/gltf_numbers.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/errors.h"
#include "scene/gltf_accessors.h"  // tiny_gltf.h as the loader includes it

namespace lll::gltf_detail {

float NumberReader::finite(double value, const std::string& what) const {
  const float f = float(value);
  if (!std::isfinite(f))
    throw InputError(fmt::format("{}: {} is {}, which is not a finite 32-bit float", file_, what, value));
  return f;
}

float NumberReader::atLeast(double value, double lo, const std::string& what) const {
  const float f = finite(value, what);
  if (f < lo) throw InputError(fmt::format("{}: {} is {}; it must be at least {}", file_, what, value, lo));
  return f;
}

float NumberReader::clamped(double value, double lo, double hi, const std::string& what) const {
  const float f = finite(value, what);
  if (f >= lo && f <= hi) return f;
  warnings_.push_back(
      fmt::format("{}: {} is {}, outside glTF's [{}, {}]; clamped", file_, what, value, lo, hi));
  return std::clamp(f, float(lo), float(hi));
}

std::vector<float> NumberReader::clampedArray(const std::vector<double>& values, size_t size, double lo,
                                              double hi, const std::string& what) const {
  if (values.size() != size)
    throw InputError(
        fmt::format("{}: {} has {} numbers; glTF gives it {}", file_, what, values.size(), size));
  std::vector<float> out;
  for (size_t i = 0; i < size; ++i) out.push_back(clamped(values[i], lo, hi, fmt::format("{}[{}]", what, i)));
  return out;
}

void checkFiniteMatrix(const glm::mat4& m, const std::string& file, const std::string& what) {
  for (int column = 0; column < 4; ++column)
    for (int row = 0; row < 4; ++row)
      if (!std::isfinite(m[column][row]))
        throw InputError(
            fmt::format("{}: {} is not finite as 32-bit floats (element [{}][{}] is {}); a "
                        "scale or translation is out of range",
                        file, what, column, row, m[column][row]));
}

uint64_t unsignedMember(const tinygltf::Value& object, const char* name, uint64_t fallback,
                        const std::string& file, const std::string& where) {
  if (!object.Has(name)) return fallback;
  const tinygltf::Value& v = object.Get(name);
  if (!v.IsNumber()) throw InputError(fmt::format("{}: {}'s {} is not a number", file, where, name));
  const double d = v.GetNumberAsDouble();
  if (!(d >= 0.0 && d <= 9007199254740992.0) || d != double(uint64_t(d)))
    throw InputError(fmt::format("{}: {}'s {} is {}, not a non-negative integer", file, where, name, d));
  return uint64_t(d);
}

}  // namespace lll::gltf_detail
