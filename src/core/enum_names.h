#pragma once
// Options that take one of a few names (--lll-fill ray, --shadows all) are enums whose names are
// written once, in an EnumNames<E> specialisation beside the enum. The CLI parses a name to the enum
// when it reads the option, the viewer's menus and the bench's reports show the names, and the
// library compares enums: no string is compared twice, and a misspelt name cannot reach a technique.
#include <fmt/format.h>

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lll {

// Specialise with `static constexpr std::array<std::string_view, N> names`, one per enumerator, in
// the enumerators' order (they count from 0).
template <class E>
struct EnumNames;

template <class E>
concept NamedEnum = requires {
  EnumNames<E>::names;
};

template <NamedEnum E>
constexpr std::string_view nameOf(E value) {
  return EnumNames<E>::names.at(static_cast<std::size_t>(value));
}

template <NamedEnum E>
constexpr std::optional<E> enumFromName(std::string_view name) {
  const auto& names = EnumNames<E>::names;
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return static_cast<E>(i);
  return std::nullopt;
}

// Every value of E, in the enumerators' order.
template <NamedEnum E>
std::vector<E> enumValues() {
  std::vector<E> values;
  for (std::size_t i = 0; i < EnumNames<E>::names.size(); ++i) values.push_back(static_cast<E>(i));
  return values;
}

template <NamedEnum E>
std::vector<std::string> enumNames() {
  const auto& names = EnumNames<E>::names;
  return {names.begin(), names.end()};
}

// "shells, ray or compute": the names for a message.
template <NamedEnum E>
std::string enumChoices() {
  const auto& names = EnumNames<E>::names;
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) text += i + 1 == names.size() ? " or " : ", ";
    text += names[i];
  }
  return text;
}

}  // namespace lll

// fmt::format("{}", LllFill::Ray) writes "ray".
template <lll::NamedEnum E>
struct fmt::formatter<E> : fmt::formatter<std::string_view> {
  template <class FormatContext>
  auto format(E value, FormatContext& context) const {
    return fmt::formatter<std::string_view>::format(lll::nameOf(value), context);
  }
};
