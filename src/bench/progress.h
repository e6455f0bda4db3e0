#pragma once
// The bench's progress bar on stderr: redrawn in place on a terminal, one line per scenario when
// stderr is a file or a CI log.
#include <chrono>
#include <cstdio>
#include <string>

namespace lll::bench {

class ProgressBar {
 public:
  ProgressBar(size_t total, std::FILE* stream = stderr);

  // Shows that scenario `index` (0-based) is starting, described by `label`.
  void start(size_t index, const std::string& label);
  // Prints a message on a line of its own, above the bar.
  void note(const std::string& message);
  // Ends the bar with how many scenarios were done (fewer than the total when interrupted) and the
  // elapsed time.
  void finish(size_t done);

 private:
  std::string bar(size_t done) const;

  size_t total_;
  std::FILE* stream_;
  bool terminal_;
  std::string current_;
  std::chrono::steady_clock::time_point begin_;
};

}  // namespace lll::bench
