#pragma once
// Output files written all or none: a run checks every output path before its slow work, writes
// each file under a temporary name in the file's own folder, and renames them all into place only
// once every one was written, so a failed or interrupted run leaves no partial output behind.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace lll {

// Throws InputError naming `option` unless `path` can be written: not empty, not a folder, in a
// folder that exists and takes a new file (checked by creating and removing one).
void checkOutputPath(const std::string& option, const std::filesystem::path& path);

// The file name's extension in lower case, with its dot (".png"), or "" when it has none.
std::string lowercaseExtension(const std::string& path);

// Writes `path` through `write`, which is given a temporary path in the same folder; the
// temporary is renamed over `path` when `write` returns, and removed when it throws.
void writeAtomically(const std::filesystem::path& path,
                     const std::function<void(const std::filesystem::path& temporary)>& write);

// A run's outputs, committed together: add() each (checked at once), then write() each through
// its temporary, then commit(). Temporaries not committed are removed on destruction.
class PendingOutputs {
 public:
  PendingOutputs() = default;
  PendingOutputs(const PendingOutputs&) = delete;
  PendingOutputs& operator=(const PendingOutputs&) = delete;
  ~PendingOutputs();

  // Checks `path` (see checkOutputPath) and that no other output has the same path.
  void add(const std::string& option, const std::filesystem::path& path);
  // Writes the output added as `path` to its temporary through `write`.
  void write(const std::filesystem::path& path,
             const std::function<void(const std::filesystem::path& temporary)>& write);
  // Renames every written temporary over its output.
  void commit();

 private:
  struct Output {
    std::string option;
    std::filesystem::path path;
    std::filesystem::path temporary;  // empty until written
  };
  std::vector<Output> outputs_;
};

}  // namespace lll
