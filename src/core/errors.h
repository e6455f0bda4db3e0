#pragma once
// Errors caused by what the user gave us (a file, an option). The CLI prints the message and exits
// with code 2; everything else that throws is a bug or an environment failure (exit 1).
#include <stdexcept>
#include <string>

namespace lll {

class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace lll
