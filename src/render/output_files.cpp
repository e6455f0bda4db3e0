#include "render/output_files.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <random>

#include "core/errors.h"

namespace lll {

namespace fs = std::filesystem;

namespace {

// Tries a few random names: another process may have taken one. Keeps the extension, which the
// image writers read to choose the format.
fs::path createTemporaryBeside(const fs::path& path, std::string& error) {
  const fs::path folder = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  std::random_device random;
  for (int attempt = 0; attempt < 16; ++attempt) {
    const fs::path candidate =
        folder / fmt::format(".{}.lll-{:08x}{}", path.stem().string(), random(), path.extension().string());
    const int fd = ::open(candidate.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) {
      ::close(fd);
      return candidate;
    }
    error = std::strerror(errno);
    if (errno != EEXIST) break;
  }
  return {};
}

}  // namespace

std::string lowercaseExtension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

void checkOutputPath(const std::string& option, const fs::path& path) {
  if (path.empty()) throw InputError(fmt::format("{}: the path is empty", option));
  const fs::path folder = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  std::error_code ec;
  if (!fs::is_directory(folder, ec))
    throw InputError(
        fmt::format("{} {}: the folder {} does not exist", option, path.string(), folder.string()));
  if (fs::is_directory(path, ec))
    throw InputError(fmt::format("{} {}: is a folder, not a file", option, path.string()));
  std::string error;
  const fs::path probe = createTemporaryBeside(path, error);
  if (probe.empty())
    throw InputError(
        fmt::format("{} {}: cannot create a file in {}: {}", option, path.string(), folder.string(), error));
  fs::remove(probe, ec);
}

void writeAtomically(const fs::path& path, const std::function<void(const fs::path& temporary)>& write) {
  std::string error;
  const fs::path temporary = createTemporaryBeside(path, error);
  if (temporary.empty())
    throw InputError(fmt::format("{}: cannot create a file beside it: {}", path.string(), error));
  try {
    write(temporary);
    fs::rename(temporary, path);
  } catch (...) {
    std::error_code ec;
    fs::remove(temporary, ec);
    throw;
  }
}

PendingOutputs::~PendingOutputs() {
  for (const Output& output : outputs_) {
    std::error_code ec;
    if (!output.temporary.empty()) fs::remove(output.temporary, ec);
  }
}

void PendingOutputs::add(const std::string& option, const fs::path& path) {
  checkOutputPath(option, path);
  std::error_code ec;
  for (const Output& other : outputs_) {
    if (other.path == path || fs::equivalent(other.path, path, ec))
      throw InputError(fmt::format("{} {}: the same file as {}", option, path.string(), other.option));
  }
  outputs_.push_back({option, path, {}});
}

void PendingOutputs::write(const fs::path& path,
                           const std::function<void(const fs::path& temporary)>& write) {
  for (Output& output : outputs_) {
    if (output.path != path) continue;
    std::string error;
    output.temporary = createTemporaryBeside(path, error);
    if (output.temporary.empty())
      throw InputError(
          fmt::format("{} {}: cannot create a file beside it: {}", output.option, path.string(), error));
    write(output.temporary);
    return;
  }
  throw std::logic_error("PendingOutputs::write: " + path.string() + " was not added");
}

void PendingOutputs::commit() {
  for (Output& output : outputs_) {
    if (output.temporary.empty()) continue;
    std::error_code ec;
    fs::rename(output.temporary, output.path, ec);
    if (ec)
      throw InputError(fmt::format("{} {}: cannot move the finished file into place: {}", output.option,
                                   output.path.string(), ec.message()));
    output.temporary.clear();
  }
}

}  // namespace lll
