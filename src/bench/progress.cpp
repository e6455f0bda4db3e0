#include "bench/progress.h"

#include <fmt/format.h>
#include <unistd.h>

namespace lll::bench {

namespace {

constexpr size_t kBarWidth = 20;
constexpr const char* kClearLine = "\r\033[K";

}  // namespace

ProgressBar::ProgressBar(size_t total, std::FILE* stream)
    : total_(total),
      stream_(stream),
      terminal_(isatty(fileno(stream)) != 0),
      begin_(std::chrono::steady_clock::now()) {}

std::string ProgressBar::bar(size_t done) const {
  const size_t filled = total_ ? done * kBarWidth / total_ : kBarWidth;
  return "[" + std::string(filled, '#') + std::string(kBarWidth - filled, '.') + "]";
}

void ProgressBar::start(size_t index, const std::string& label) {
  current_ = fmt::format("{} {}/{} {}", bar(index), index + 1, total_, label);
  if (terminal_)
    fmt::print(stream_, "{}{}", kClearLine, current_);
  else
    fmt::print(stream_, "{}\n", current_);
  std::fflush(stream_);
}

void ProgressBar::note(const std::string& message) {
  if (terminal_)
    fmt::print(stream_, "{}{}\n{}", kClearLine, message, current_);
  else
    fmt::print(stream_, "{}\n", message);
  std::fflush(stream_);
}

void ProgressBar::finish(size_t done) {
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin_).count();
  fmt::print(stream_, "{}{} {}/{} done in {:.1f} s\n", terminal_ ? kClearLine : "", bar(done), done, total_,
             seconds);
}

}  // namespace lll::bench
