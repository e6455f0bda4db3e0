#include "view/input_script.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "core/errors.h"
#include "render/settings.h"

namespace lll::view {

namespace {

// Each verb's argument count and allowed first arguments (empty: any).
struct Verb {
  size_t args;
  std::vector<std::string> firstArgs;
};

const std::map<std::string, Verb>& verbs() {
  static const std::map<std::string, Verb> table = {
      {"key", {2, {"w", "a", "s", "d", "q", "e", "shift"}}},
      {"look", {2, {}}},
      {"wheel", {1, {}}},
      {"mode", {1, {"fly", "orbit"}}},
      {"resize", {2, {}}},
      {"drop", {1, {}}},
      {"set", {2, {"technique", "debug-view", "exposure", "lights", "tile"}}},
      {"preset-save", {1, {}}},
      {"print-camera", {0, {}}},
  };
  return table;
}

}  // namespace

float scriptNumber(const ScriptEvent& event, size_t arg) {
  const std::string& text = event.args.at(arg);
  float value = 0.0f;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || ptr != text.data() + text.size() || !std::isfinite(value))
    throw InputError(fmt::format("{}: {}: '{}' is not a finite number", event.where, event.verb, text));
  return value;
}

std::vector<ScriptEvent> parseInputScript(const std::string& text, const std::string& source) {
  std::vector<ScriptEvent> events;
  std::istringstream lines(text);
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) {
    std::istringstream words(line);
    std::vector<std::string> w;
    for (std::string word; words >> word;) w.push_back(word);
    if (w.empty() || w[0][0] == '#') continue;
    ScriptEvent e;
    e.where = fmt::format("{}:{}", source, number);
    uint64_t frame = 0;
    const auto [ptr, ec] = std::from_chars(w[0].data(), w[0].data() + w[0].size(), frame);
    if (ec != std::errc() || ptr != w[0].data() + w[0].size() || frame > 10'000'000)
      throw InputError(fmt::format("{}: expected a frame number first (got '{}')", e.where, w[0]));
    e.frame = uint32_t(frame);
    if (w.size() < 2)
      throw InputError(fmt::format("{}: an event is missing after the frame number", e.where));
    e.verb = w[1];
    const auto verb = verbs().find(e.verb);
    if (verb == verbs().end()) {
      std::vector<std::string> names;
      for (const auto& [name, _] : verbs()) names.push_back(name);
      throw InputError(
          fmt::format("{}: unknown event '{}' (events: {})", e.where, e.verb, fmt::join(names, ", ")));
    }
    e.args.assign(w.begin() + 2, w.end());
    if (e.verb == "drop" || e.verb == "preset-save") {
      // A path may contain spaces: the rest of the line after the verb.
      const size_t at = line.find(e.verb) + e.verb.size();
      const size_t start = line.find_first_not_of(" \t", at);
      e.args = {start == std::string::npos ? ""
                                           : line.substr(start, line.find_last_not_of(" \t\r") + 1 - start)};
      if (e.args[0].empty()) throw InputError(fmt::format("{}: {} needs a path", e.where, e.verb));
    }
    if (e.args.size() != verb->second.args)
      throw InputError(fmt::format("{}: {} takes {} argument(s), got {}", e.where, e.verb, verb->second.args,
                                   e.args.size()));
    const auto& firsts = verb->second.firstArgs;
    if (!firsts.empty() && std::find(firsts.begin(), firsts.end(), e.args[0]) == firsts.end())
      throw InputError(fmt::format("{}: {} '{}': expected one of {}", e.where, e.verb, e.args[0],
                                   fmt::join(firsts, ", ")));
    if (e.verb == "set" && e.args[0] == "debug-view" && !enumFromName<DebugView>(e.args[1]))
      throw InputError(
          fmt::format("{}: set debug-view '{}': expected {}", e.where, e.args[1], enumChoices<DebugView>()));
    if (e.verb == "key" && e.args[1] != "down" && e.args[1] != "up")
      throw InputError(fmt::format("{}: key {} '{}': expected down or up", e.where, e.args[0], e.args[1]));
    if (e.verb == "look" || e.verb == "wheel" || e.verb == "resize")
      for (size_t i = 0; i < e.args.size(); ++i) scriptNumber(e, i);
    if (e.verb == "resize" && (scriptNumber(e, 0) < 1 || scriptNumber(e, 1) < 1 ||
                               scriptNumber(e, 0) > 8192 || scriptNumber(e, 1) > 8192))
      throw InputError(fmt::format("{}: resize: sizes must be 1 to 8192 pixels", e.where));
    events.push_back(std::move(e));
  }
  std::stable_sort(events.begin(), events.end(),
                   [](const ScriptEvent& a, const ScriptEvent& b) { return a.frame < b.frame; });
  return events;
}

std::vector<ScriptEvent> loadInputScript(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(fmt::format("--script {}: cannot read the file", path));
  std::stringstream text;
  text << in.rdbuf();
  return parseInputScript(text.str(), path);
}

}  // namespace lll::view
