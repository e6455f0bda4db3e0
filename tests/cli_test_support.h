#pragma once
// Running the `lll` binary as a child process, for the tests of its command line: exit code and
// output of a run, a minimal glTF to bend, and a fixture with a scratch folder per test.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

extern char** environ;

namespace lll::test {

namespace fs = std::filesystem;
using nlohmann::json;

struct CliResult {
  int exitCode = -1;  // 128 + signal when the child was killed, as a shell reports it
  bool timedOut = false;
  std::string output;  // stdout and stderr, interleaved
};

inline std::ostream& operator<<(std::ostream& os, const CliResult& r) {
  return os << "exit " << r.exitCode << (r.timedOut ? " (timed out)" : "") << ", output:\n" << r.output;
}

inline std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Runs the lll binary with `args` and extra environment variables (set in the child only). A child
// still running after `timeout` is killed, so a hang fails the test instead of blocking the suite.
// `whileRunning`, when given, is called with the child's pid every 10 ms until the child ends.
inline CliResult runLll(const std::vector<std::string>& args,
                        const std::map<std::string, std::string>& env = {},
                        std::chrono::seconds timeout = std::chrono::seconds(60),
                        const std::function<void(pid_t)>& whileRunning = {}) {
  // Output goes to a file rather than a pipe: a chatty child can never block on a full pipe.
  const fs::path log =
      fs::temp_directory_path() / ("lll-cli-" + std::to_string(std::random_device{}()) + ".log");
  // Everything the child needs is built before fork(): the GPU tests leave driver threads behind,
  // and after fork() only async-signal-safe calls are allowed.
  std::vector<std::string> argStrings = {LLL_BINARY};
  argStrings.insert(argStrings.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : argStrings) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::vector<std::string> envStrings;
  for (char** e = environ; *e; ++e) {
    const std::string entry = *e;
    if (!env.count(entry.substr(0, entry.find('=')))) envStrings.push_back(entry);
  }
  for (const auto& [name, value] : env) envStrings.push_back(name + "=" + value);
  std::vector<char*> envp;
  for (std::string& e : envStrings) envp.push_back(e.data());
  envp.push_back(nullptr);
  const std::string logPath = log.string();

  CliResult result;
  const pid_t pid = fork();
  if (pid < 0) {
    ADD_FAILURE() << "fork failed: " << std::strerror(errno);
    return result;
  }
  if (pid == 0) {
    const int fd = open(logPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd < 0) _exit(126);
    dup2(fd, STDOUT_FILENO);
    dup2(fd, STDERR_FILENO);
    close(fd);
    execve(argv[0], argv.data(), envp.data());
    _exit(127);
  }
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  int status = 0;
  while (waitpid(pid, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() > deadline) {
      result.timedOut = true;
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      break;
    }
    if (whileRunning) whileRunning(pid);
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  result.output = readFile(log);
  fs::remove(log);
  return result;
}

inline bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// The first line of `text` that starts with `prefix`, or "" when none does.
inline std::string lineStartingWith(const std::string& text, const std::string& prefix) {
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind(prefix, 0) == 0) return line;
  return "";
}

// A minimal valid glTF: one quad (4 positions, 6 16-bit indices) in <dir>/<name>.gltf + .bin.
struct QuadGltf {
  json doc;
  std::vector<uint8_t> bin;

  QuadGltf() {
    const float positions[] = {-1, 0, -1, 1, 0, -1, 1, 0, 1, -1, 0, 1};
    const uint16_t indices[] = {0, 2, 1, 0, 3, 2};
    bin.resize(sizeof(positions) + sizeof(indices));
    std::memcpy(bin.data(), positions, sizeof(positions));
    std::memcpy(bin.data() + sizeof(positions), indices, sizeof(indices));
    doc = {{"asset", {{"version", "2.0"}}},
           {"buffers", {{{"uri", "quad.bin"}, {"byteLength", bin.size()}}}},
           {"bufferViews",
            {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", sizeof(positions)}},
             {{"buffer", 0}, {"byteOffset", sizeof(positions)}, {"byteLength", sizeof(indices)}}}},
           {"accessors",
            {{{"bufferView", 0},
              {"componentType", 5126},
              {"count", 4},
              {"type", "VEC3"},
              {"min", {-1, 0, -1}},
              {"max", {1, 0, 1}}},
             {{"bufferView", 1}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}}}},
           {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}}}}}}},
           {"nodes", {{{"mesh", 0}}}},
           {"scenes", {{{"nodes", {0}}}}},
           {"scene", 0}};
  }

  // Writes quad.bin (the first `binBytes` bytes of it; all when npos) and <name>.gltf.
  fs::path write(const fs::path& dir, const std::string& name, size_t binBytes = std::string::npos) const {
    std::ofstream(dir / "quad.bin", std::ios::binary)
        .write(reinterpret_cast<const char*>(bin.data()), std::streamsize(std::min(binBytes, bin.size())));
    std::ofstream(dir / (name + ".gltf")) << doc.dump(1);
    return dir / (name + ".gltf");
  }
};

class CliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    dir_ = fs::temp_directory_path() / ("lll-cli-" + test + "-" + std::to_string(std::random_device{}()));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }

  std::string outPng() const { return (dir_ / "out.png").string(); }

  // `lll render SCENE --width 32 --height 18 --out out.png EXTRA...`
  CliResult render(const std::string& scene, const std::vector<std::string>& extra = {}) const {
    std::vector<std::string> args = {"render", scene, "--width", "32", "--height", "18", "--out", outPng()};
    args.insert(args.end(), extra.begin(), extra.end());
    return runLll(args);
  }

  // Exit code 2, every one of `named` in the message, and no image left behind.
  void expectBadInput(const CliResult& r, const std::vector<std::string>& named) const {
    EXPECT_EQ(r.exitCode, 2) << r;
    EXPECT_FALSE(r.timedOut);
    for (const std::string& n : named) EXPECT_TRUE(contains(r.output, n)) << "'" << n << "' not named: " << r;
    EXPECT_FALSE(fs::exists(outPng())) << "an image was written despite the error";
  }

  fs::path dir_;
};

}  // namespace lll::test
