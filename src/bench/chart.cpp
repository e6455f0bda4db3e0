// PNG charts through gnuplot (Debian's gnuplot-nox, pngcairo terminal): each chart is a data file
// plus a section of charts.gp in the output directory, so a reader can restyle and redraw them.
#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>

#include "bench/report.h"
#include "core/errors.h"

extern char** environ;

namespace lll::bench {

namespace {

namespace fs = std::filesystem;
using Results = std::vector<const ScenarioResult*>;

// Twelve colours that stay apart (Tableau 10 and two more): a ThreeL frame has about ten passes.
const std::array<const char*, 12> kPalette = {"#4e79a7", "#f28e2b", "#e15759", "#76b7b2",
                                              "#59a14f", "#edc948", "#b07aa1", "#ff9da7",
                                              "#9c755f", "#bab0ac", "#1f3b5c", "#8cd17d"};

std::string terminal(int width, int height) {
  return fmt::format("set terminal pngcairo noenhanced size {},{} font 'sans,11'", width, height);
}

// A double-quoted gnuplot string: newlines become \n escapes, which only such strings expand.
std::string gnuplotString(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '\n')
      out += "\\n";
    else
      out += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
  }
  return out + "\"";
}

Results measured(const BenchReport& report, const std::string& suite) {
  Results results;
  for (const ScenarioResult& r : report.results)
    if (r.scenario.suite == suite && r.status == Status::Ok && r.pass("frame")) results.push_back(&r);
  return results;
}

std::vector<std::string> uniqueLabels(const Results& results) {
  std::vector<std::string> labels;
  for (const ScenarioResult* r : results) {
    const std::string label = seriesLabel(r->scenario);
    if (std::find(labels.begin(), labels.end(), label) == labels.end()) labels.push_back(label);
  }
  return labels;
}

std::string subtitle(const BenchReport& report) {
  return fmt::format("{}, {}, commit {}", report.device.name, report.device.driver, report.commit);
}

void writeFile(const fs::path& path, const std::string& text) {
  std::ofstream out(path);
  if (!out) throw InputError(fmt::format("--out: cannot write {}", path.string()));
  out << text;
}

// A technique's own passes: everything but the surfaces every technique draws (visibility buffer
// or depth prepass and G-buffer), the shading passes they share, tonemap and the frame itself.
// Light lists for lll, tiled and clustered; G-buffer and light volumes for deferred and pre-pass.
bool isOwnPass(const std::string& name) {
  return name != "visibility" && name != "visibility-resolve" && name != "depth-prepass" &&
         name != "gbuffer" && name != "shade-opaque" && name != "glass" && name != "tonemap" &&
         name != "frame" && !name.starts_with("particles") && !name.starts_with("alu-probe");
}

// A log-log chart of `suite`'s times against light count, one line per technique (with `perPass`
// two in the technique's colour: its own passes dashed, shade-opaque + glass solid), min-max as
// error bars on frame times.
enum class Measure { Frame, Passes, Memory, ReferenceError };

std::optional<double> techniqueStat(const ScenarioResult& r, const std::string& name) {
  for (const auto& [key, value] : r.techniqueStats)
    if (key == name) return value;
  return std::nullopt;
}

std::optional<std::string> lightCountChart(const BenchReport& report, const fs::path& dir,
                                           const std::string& suite, const std::string& file, Measure measure,
                                           const std::string& what) {
  const bool perPass = measure == Measure::Passes;
  const Results results = measured(report, suite);
  if (results.empty()) return std::nullopt;
  const std::string stem = file.substr(0, file.size() - 4);
  std::string data, plots;
  int index = 0;
  int color = 0;
  auto addSeries = [&](const std::string& title, const std::string& style, auto value) {
    std::string points;
    for (const ScenarioResult* r : results)
      if (const auto v = value(*r))
        points += fmt::format("{} {} {} {}\n", r->lightCount, (*v)[0], (*v)[1], (*v)[2]);
    if (points.empty()) return;  // an empty block would shift gnuplot's indices
    data += fmt::format("# {}: lights ms min_ms max_ms\n{}\n\n", title, points);
    plots += fmt::format("{}'{}.dat' index {} using 1:2:3:4 with {} lc {} title {}", index ? ", " : "plot ",
                         stem, index, style, color, gnuplotString(title));
    ++index;
  };
  using Triple = std::optional<std::array<double, 3>>;
  for (const std::string& label : uniqueLabels(results)) {
    ++color;
    auto mine = [&](const ScenarioResult& r) { return seriesLabel(r.scenario) == label; };
    if (!perPass) {
      // gnuplot has eight line colours: lines past the eighth are dashed, with other points.
      const std::string style = color <= 8 ? "yerrorlines lw 2 pt 7"
                                           : fmt::format("yerrorlines lw 2 dt 2 pt {}", 4 + (color - 9) % 8);
      addSeries(label, style, [&](const ScenarioResult& r) -> Triple {
        if (!mine(r)) return std::nullopt;
        if (measure == Measure::Memory) {
          const double mib = r.memoryBytes() / (1024.0 * 1024.0);
          return std::array<double, 3>{mib, mib, mib};
        }
        if (measure == Measure::ReferenceError) {
          const std::optional<double> e = techniqueStat(r, "gi-error-vs-reference");
          if (!e) return std::nullopt;
          return std::array<double, 3>{*e, *e, *e};
        }
        const PassSummary& f = *r.pass("frame");
        return std::array<double, 3>{f.medianMs, f.minMs, f.maxMs};
      });
      continue;
    }
    auto sum = [&](const ScenarioResult& r, bool own) -> Triple {
      if (!mine(r)) return std::nullopt;
      double ms = 0.0;
      bool any = false;
      for (const PassSummary& p : r.passes)
        if (own ? isOwnPass(p.name) : (p.name == "shade-opaque" || p.name == "glass")) {
          ms += p.medianMs;
          any = true;
        }
      if (!any) return std::nullopt;
      return std::array<double, 3>{ms, ms, ms};
    };
    addSeries(label + ": own passes", "linespoints dt 2 lw 2 pt 6",
              [&](const ScenarioResult& r) { return sum(r, true); });
    addSeries(label + ": shade-opaque + glass", "linespoints lw 2 pt 7",
              [&](const ScenarioResult& r) { return sum(r, false); });
  }
  writeFile(dir / (stem + ".dat"), data);
  std::set<uint64_t> counts;  // ticks where the measurements are, a little room either side
  for (const ScenarioResult* r : results) counts.insert(r->lightCount);
  const RenderSettings& s = results.front()->scenario.settings;
  return fmt::format(
      "{}\nset output '{}'\n"
      "set title {}\nset xlabel {}\n"
      "set ylabel {}\nset logscale xy\nset format x '%.0f'\n"
      "set xrange [{}:{}]\nset xtics ({})\nset grid xtics ytics mytics\nset key top left box opaque\n{}\n",
      terminal(1280, 800), file,
      gnuplotString(fmt::format("{}: {}, {}x{}\n{}", what, results.front()->scenario.scene.scene, s.width,
                                s.height, subtitle(report))),
      gnuplotString(suite.starts_with("gi")
                        ? "virtual point lights (the scene's own lights left out: --gi vpl-only)"
                        : "lights in the scene (its own plus the random ones added)"),
      gnuplotString(measure == Measure::Passes
                        ? "GPU ms (median): the technique's own passes dashed, shade-opaque + glass solid"
                    : measure == Measure::Memory
                        ? "GPU memory of the lighting data, MiB (depth + the technique's buffers)"
                    : measure == Measure::ReferenceError
                        ? "relative RMS error against the path-traced reference (8x8-pixel block means)"
                        : "GPU frame time, ms (median; bars: min to max)"),
      double(*counts.begin()) / 1.25, double(*counts.rbegin()) * 1.25, fmt::join(counts, ", "), plots);
}

std::optional<std::string> scalingChart(const BenchReport& report, const fs::path& dir) {
  return lightCountChart(report, dir, "scaling", "scaling.png", Measure::Frame,
                         "Frame time against light count");
}

std::optional<std::string> densityChart(const BenchReport& report, const fs::path& dir) {
  return lightCountChart(report, dir, "density", "density.png", Measure::Frame,
                         "Frame time against light count at constant light density");
}

std::optional<std::string> giChart(const BenchReport& report, const fs::path& dir) {
  return lightCountChart(report, dir, "gi", "gi.png", Measure::Frame,
                         "Frame time against VPL count (the VPLs alone), two VPL cutoffs");
}

std::optional<std::string> giErrorChart(const BenchReport& report, const fs::path& dir) {
  return lightCountChart(report, dir, "gi-error", "gi-error.png", Measure::ReferenceError,
                         "Instant radiosity against the path-traced indirect light, per VPL cutoff");
}

std::optional<std::string> densityMemoryChart(const BenchReport& report, const fs::path& dir) {
  return lightCountChart(report, dir, "density", "density-memory.png", Measure::Memory,
                         "Lighting-data memory against light count at constant light density");
}

std::optional<std::string> densityPassesChart(const BenchReport& report, const fs::path& dir) {
  return lightCountChart(report, dir, "density", "density-passes.png", Measure::Passes,
                         "Light data and shading against light count at constant light density");
}

// The bars of the ThreeL chart: passes (the stacked segments, "frame" left out: it is their
// total) and groups (one panel each: scene and resolution), in the order they ran.
struct StackedBars {
  std::vector<std::string> passes;
  std::vector<std::string> groups;
};

StackedBars stackedBars(const Results& results) {
  StackedBars bars;
  for (const std::string& pass : passOrder(results))
    if (pass != "frame") bars.passes.push_back(pass);
  for (const ScenarioResult* r : results)
    if (std::find(bars.groups.begin(), bars.groups.end(), r->scenario.name) == bars.groups.end())
      bars.groups.push_back(r->scenario.name);
  return bars;
}

// One data block per group, one row per technique: its label, then each pass's median (0 if none).
std::string stackedData(const Results& results, const StackedBars& bars) {
  std::string data;
  for (const std::string& group : bars.groups) {
    data += fmt::format("# {}: technique {}\n", group, fmt::join(bars.passes, " "));
    for (const ScenarioResult* r : results) {
      if (r->scenario.name != group) continue;
      data += gnuplotString(techniqueLabel(r->scenario.settings));
      for (const std::string& name : bars.passes)
        data += fmt::format(" {}", r->pass(name) ? r->pass(name)->medianMs : 0.0);
      data += "\n";
    }
    data += "\n\n";
  }
  return data;
}

// Per-pass GPU time stacked into one bar per technique; one panel per scene and resolution, each
// with its own scale (4K with 256 lights would flatten 1080p with 16).
std::optional<std::string> threelChart(const BenchReport& report, const fs::path& dir) {
  const Results results = measured(report, "threel");
  if (results.empty()) return std::nullopt;
  const StackedBars bars = stackedBars(results);
  writeFile(dir / "threel.dat", stackedData(results, bars));
  const size_t columns = std::min<size_t>(bars.groups.size(), 2), rows = (bars.groups.size() + 1) / 2;
  std::string gp = fmt::format(
      "{}\nset output 'threel.png'\nset multiplot layout {},{} title {}\n"
      "set style data histograms\nset style histogram rowstacked\nset style fill solid 0.9 border -1\n"
      "set boxwidth 0.6\nset grid ytics\nset ylabel 'GPU time, ms (median)'\nset yrange [0:*]\n"
      "set key outside right top box\n",
      terminal(1600, 1000), rows, columns,
      gnuplotString(fmt::format("ThreeL benchmark: per-pass GPU time, all lights reach every pixel\n{}",
                                subtitle(report))));
  for (size_t g = 0; g < bars.groups.size(); ++g) {
    gp += fmt::format("set title {}\nplot ", gnuplotString(bars.groups[g]));
    for (size_t p = 0; p < bars.passes.size(); ++p)
      gp += fmt::format("{}'threel.dat' index {} using {}{} lc rgb '{}' title {}", p ? ", " : "", g, p + 2,
                        p ? "" : ":xtic(1)", kPalette[p % kPalette.size()], gnuplotString(bars.passes[p]));
    gp += "\n";
  }
  return gp + "unset multiplot\n";
}

// Frame time and light-list memory against tile size, on two y axes.
std::optional<std::string> tilesChart(const BenchReport& report, const fs::path& dir) {
  const Results results = measured(report, "tiles");
  if (results.empty()) return std::nullopt;
  std::string data = "# tile median_ms min_ms max_ms memory_mib\n";
  for (const ScenarioResult* r : results) {
    const PassSummary& f = *r->pass("frame");
    data += fmt::format("{} {} {} {} {}\n", r->scenario.settings.tileSize, f.medianMs, f.minMs, f.maxMs,
                        r->memoryBytes() / (1024.0 * 1024.0));
  }
  writeFile(dir / "tiles.dat", data);
  const ScenarioResult& first = *results.front();
  return fmt::format(
      "{}\nset output 'tiles.png'\nset title {}\nset xlabel 'tile size, pixels'\nset logscale x 2\n"
      "set xrange [0.75:21]\nset xtics (1, 2, 4, 8, 16)\n"
      "set ylabel 'GPU frame time, ms (median; bars: min to max)'\n"
      "set y2label 'GPU memory of the lighting data, MiB'\nset ytics nomirror\nset y2tics\n"
      "set yrange [0:*]\nset y2range [0:*]\nset grid xtics ytics\nset key top center box opaque\n"
      "plot 'tiles.dat' using 1:2:3:4 with yerrorlines lw 2 pt 7 title 'frame time', "
      "'' using 1:5 axes x1y2 with linespoints lw 2 pt 5 dt 2 title 'memory'\n",
      terminal(1280, 800),
      gnuplotString(fmt::format("Tile size: {} with {} lights, {}x{}, {}\n{}", first.scenario.scene.scene,
                                first.lightCount, first.scenario.settings.width,
                                first.scenario.settings.height, techniqueLabel(first.scenario.settings),
                                subtitle(report))));
}

bool onPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');)
    if (!dir.empty() && ::access((fs::path(dir) / program).c_str(), X_OK) == 0) return true;
  return false;
}

// Runs gnuplot on the script with `dir` as its working directory; true when it exits with 0.
bool runGnuplot(const fs::path& dir) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addchdir_np(&actions, dir.c_str());
  char program[] = "gnuplot", script[] = "charts.gp";
  char* argv[] = {program, script, nullptr};
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, program, &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  int status = 0;
  return spawned == 0 && waitpid(pid, &status, 0) == pid && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

std::optional<std::string> giHierarchyChart(const BenchReport& report, const fs::path& dir) {
  return lightCountChart(report, dir, "gi-hierarchy", "gi-hierarchy.png", Measure::Frame,
                         "Frame time against VPL count (every level's), the lighting grid hierarchy");
}

}  // namespace

std::vector<fs::path> writeCharts(const BenchReport& report, const fs::path& dir) {
  std::string script;
  std::vector<fs::path> charts;
  using ChartFn = std::optional<std::string> (*)(const BenchReport&, const fs::path&);
  for (const auto& [name, chart] : {std::pair<const char*, ChartFn>{"scaling.png", scalingChart},
                                    {"density.png", densityChart},
                                    {"density-passes.png", densityPassesChart},
                                    {"density-memory.png", densityMemoryChart},
                                    {"gi.png", giChart},
                                    {"gi-error.png", giErrorChart},
                                    {"gi-hierarchy.png", giHierarchyChart},
                                    {"threel.png", threelChart},
                                    {"tiles.png", tilesChart}}) {
    if (const auto section = chart(report, dir)) {
      script += "reset\n" + *section;
      charts.push_back(dir / name);
    }
  }
  if (charts.empty()) return {};
  writeFile(dir / "charts.gp", script);
  if (!onPath("gnuplot")) {
    fmt::print(stderr, "lll: warning: gnuplot not found: no PNG charts (charts.gp and its data are in {})\n",
               dir.string());
    return {};
  }
  if (!runGnuplot(dir)) {
    fmt::print(stderr, "lll: warning: gnuplot failed on {}: some charts may be missing\n",
               (dir / "charts.gp").string());
    return {};
  }
  return charts;
}

}  // namespace lll::bench
