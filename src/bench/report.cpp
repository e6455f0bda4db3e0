#include "bench/report.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>

#include "core/errors.h"
#include "lighting/technique.h"
#include "render/output_files.h"

namespace lll::bench {

namespace {

// Writes `path` whole through a temporary beside it: a reader (or an interrupted run) never sees
// it half-written.
void writeText(const std::filesystem::path& path, const std::function<void(std::ostream&)>& print) {
  writeAtomically(path, [&](const std::filesystem::path& temporary) {
    std::ofstream out(temporary);
    print(out);
    out.close();
    if (!out) throw InputError(fmt::format("--out: cannot write {}", path.string()));
  });
}

nlohmann::json namedValues(const NamedValues& values) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [key, value] : values) j[key] = value;
  return j;
}

// An option's name in the results, "" where it does not apply.
std::string nameIf(bool applies, NamedEnum auto value) {
  return applies ? std::string(nameOf(value)) : std::string();
}

// The option named at `key` of a result read back from `path`.
template <NamedEnum E>
E enumAt(const nlohmann::json& result, const char* key, const std::filesystem::path& path) {
  const std::string name = result.at(key).get<std::string>();
  if (const std::optional<E> value = enumFromName<E>(name)) return *value;
  throw InputError(
      fmt::format("{}: \"{}\": \"{}\" is not one of {}", path.string(), key, name, enumChoices<E>()));
}

nlohmann::json resultJson(const BenchReport& report, const ScenarioResult& r) {
  const Scenario& s = r.scenario;
  nlohmann::json j = {
      {"suite", s.suite},
      {"scenario", s.name},
      {"scene", s.scene.scene},
      {"extra_lights", s.scene.extraLights},
      {"seed", s.scene.seed},
      {"lights", r.lightCount},
      {"width", s.settings.width},
      {"height", s.settings.height},
      {"camera", s.settings.camera},
      {"technique", s.settings.technique},
      {"label", techniqueLabel(s.settings)},
      {"series", seriesLabel(s)},
      {"fill", nameIf(s.settings.technique == "lll", s.settings.lllFill)},
      {"shade", nameIf(s.settings.technique == "lll", s.settings.lllShade)},
      {"surfaces", nameOf(s.settings.surfaces)},
      {"glass", nameOf(s.settings.glass)},
      {"raster", nameOf(s.settings.raster)},
      {"tile", tileSizeFor(s.settings)},  // the technique's default where the scenario names none
      {"moving_lights", s.settings.animateLights},
      {"particles", s.settings.particles},
      {"particle_count", s.settings.particleCount},
      {"particle_lighting", nameIf(!s.settings.particles.empty(), s.settings.particleLighting)},
      {"particle_render", nameIf(!s.settings.particles.empty(), s.settings.particleRender)},
      {"particle_resolution", nameIf(!s.settings.particles.empty(), s.settings.particleResolution)},
      {"status", statusName(r.status)},
      {"message", r.message},
      {"device", report.device.name},
      {"driver", report.device.driver},
      {"commit", report.commit},
      {"date", r.date},
  };
  nlohmann::json passes = nlohmann::json::array();
  for (const PassSummary& p : r.passes)
    passes.push_back({{"name", p.name}, {"median_ms", p.medianMs}, {"min_ms", p.minMs}, {"max_ms", p.maxMs}});
  j["passes"] = passes;
  j["memory_bytes"] = r.memoryBytes();
  j["memory"] = namedValues(r.memory);
  j["technique_stats"] = namedValues(r.techniqueStats);
  j["rerenders"] = r.rerenders;
  j["vs_forward"] = nullptr;
  if (r.vsForward)
    j["vs_forward"] = {{"psnr_db", std::isinf(r.vsForward->psnr) ? nlohmann::json("inf")
                                                                 : nlohmann::json(r.vsForward->psnr)},
                       {"p999", r.vsForward->p999},
                       {"max", r.vsForward->worst}};
  return j;
}

// RFC 4180: quote a field holding a comma, quote or newline (device names have commas).
std::string csvField(const std::string& value) {
  if (value.find_first_of(",\"\n") == std::string::npos) return value;
  std::string quoted = "\"";
  for (const char c : value) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

}  // namespace

std::vector<std::string> passOrder(const std::vector<const ScenarioResult*>& results) {
  std::vector<std::string> order;
  for (const ScenarioResult* r : results) {
    for (size_t i = 0; i < r->passes.size(); ++i) {
      if (std::find(order.begin(), order.end(), r->passes[i].name) != order.end()) continue;
      // Before the first later pass of this frame that is already placed, else last.
      auto at = order.end();
      for (size_t j = i + 1; j < r->passes.size() && at == order.end(); ++j)
        at = std::find(order.begin(), order.end(), r->passes[j].name);
      order.insert(at, r->passes[i].name);
    }
  }
  return order;
}

void writeResultsJson(const BenchReport& report, const std::filesystem::path& path) {
  nlohmann::json j = {
      {"device", report.device.name},
      {"device_type", report.device.type},
      {"driver", report.device.driver},
      {"vulkan", report.device.apiVersion},
      {"commit", report.commit},
      {"date", report.date},
      {"quick", report.quick},
      {"timestamps", report.timestamps},
      {"warmup_frames", report.warmupFrames},
      {"timed_frames", report.timedFrames},
      {"suites", report.suites},
      {"only_techniques", report.onlyTechniques},
      {"validation_messages", report.validationMessages},
      {"interrupted", report.interrupted},
  };
  nlohmann::json results = nlohmann::json::array();
  for (const ScenarioResult& r : report.results) results.push_back(resultJson(report, r));
  j["results"] = results;
  writeText(path, [&](std::ostream& out) { out << j.dump(2) << "\n"; });
}

namespace {

void printResultsCsv(const BenchReport& report, std::ostream& out) {
  out << "suite,scenario,scene,lights,width,height,technique,fill,tile,pass,median_ms,min_ms,max_ms,"
         "memory_bytes,psnr_vs_forward_db,p999_vs_forward,max_vs_forward,device,driver,commit,date\n";
  for (const ScenarioResult& r : report.results) {
    const Scenario& s = r.scenario;
    const std::string fill = lllVariant(s.settings);  // "compute/fragment-shade" for fragment shading
    const std::string vsForward =
        r.vsForward ? fmt::format("{:.2f},{},{}", r.vsForward->psnr, r.vsForward->p999, r.vsForward->worst)
                    : ",,";
    for (const PassSummary& p : r.passes)
      out << fmt::format("{},{},{},{},{},{},{},{},{},{},{:.6f},{:.6f},{:.6f},{:.0f},{},{},{},{},{}\n",
                         s.suite, csvField(s.name), csvField(s.scene.scene), r.lightCount, s.settings.width,
                         s.settings.height, s.settings.technique, fill, tileSizeFor(s.settings),
                         csvField(p.name), p.medianMs, p.minMs, p.maxMs, r.memoryBytes(), vsForward,
                         csvField(report.device.name), csvField(report.device.driver), report.commit, r.date);
  }
}

}  // namespace

void writeResultsCsv(const BenchReport& report, const std::filesystem::path& path) {
  writeText(path, [&](std::ostream& out) { printResultsCsv(report, out); });
}

void checkOutputFolder(const std::filesystem::path& dir) {
  std::error_code error;
  if (std::filesystem::exists(dir, error) && !std::filesystem::is_directory(dir, error))
    throw InputError(fmt::format("--out {}: exists and is not a folder", dir.string()));
  std::filesystem::create_directories(dir, error);
  if (error)
    throw InputError(fmt::format("--out {}: cannot create the folder: {}", dir.string(), error.message()));
  checkOutputPath("--out", dir / "results.json");
}

void writeResults(const BenchReport& report, const std::filesystem::path& dir) {
  writeResultsJson(report, dir / "results.json");
  writeResultsCsv(report, dir / "results.csv");
}

void writeReport(const BenchReport& report, const std::filesystem::path& dir) {
  checkOutputFolder(dir);
  writeResults(report, dir);
  writeSummaryMarkdown(report, dir / "summary.md");
  writeCharts(report, dir);
}

BenchReport readResultsJson(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("{}: cannot read it", path.string()));
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    BenchReport report;
    report.device.name = j.at("device").get<std::string>();
    report.device.driver = j.at("driver").get<std::string>();
    report.commit = j.at("commit").get<std::string>();
    report.date = j.at("date").get<std::string>();
    report.quick = j.value("quick", false);
    report.timestamps = j.value("timestamps", true);
    report.suites = j.at("suites").get<std::vector<std::string>>();
    for (const nlohmann::json& r : j.at("results")) {
      ScenarioResult result;
      Scenario& s = result.scenario;
      s.suite = r.at("suite").get<std::string>();
      s.name = r.at("scenario").get<std::string>();
      s.scene.scene = r.at("scene").get<std::string>();
      s.scene.extraLights = r.at("extra_lights").get<uint32_t>();
      s.settings.width = r.at("width").get<uint32_t>();
      s.settings.height = r.at("height").get<uint32_t>();
      s.settings.technique = r.at("technique").get<std::string>();
      if (s.settings.technique == "lll") {
        s.settings.lllFill = enumAt<LllFill>(r, "fill", path);
        s.settings.lllShade = enumAt<LllShade>(r, "shade", path);
      }
      s.settings.surfaces = enumAt<SurfaceSource>(r, "surfaces", path);
      // Results from before --glass compute lit glass in the fragment shader.
      s.settings.glass =
          r.contains("glass") ? enumAt<GlassLighting>(r, "glass", path) : GlassLighting::Raster;
      s.settings.raster = enumAt<RasterChoice>(r, "raster", path);
      s.settings.tileSize = r.at("tile").get<uint32_t>();
      s.settings.animateLights = r.value("moving_lights", false);
      s.scene.movingLights = s.settings.animateLights;
      if (const std::string series = r.value("series", ""); series != techniqueLabel(s.settings))
        s.series = series;
      result.lightCount = r.at("lights").get<uint64_t>();
      const std::string status = r.at("status").get<std::string>();
      result.status = status == statusName(Status::Ok)        ? Status::Ok
                      : status == statusName(Status::Skipped) ? Status::Skipped
                                                              : Status::Failed;
      const nlohmann::json memory = r.value("memory", nlohmann::json::object());
      for (const auto& [key, value] : memory.items())
        if (value.is_number()) result.memory.emplace_back(key, value.get<double>());
      const nlohmann::json stats = r.value("technique_stats", nlohmann::json::object());
      for (const auto& [key, value] : stats.items())
        if (value.is_number()) result.techniqueStats.emplace_back(key, value.get<double>());
      for (const nlohmann::json& p : r.at("passes"))
        result.passes.push_back({p.at("name").get<std::string>(), p.at("median_ms").get<double>(),
                                 p.at("min_ms").get<double>(), p.at("max_ms").get<double>()});
      report.results.push_back(std::move(result));
    }
    return report;
  } catch (const nlohmann::json::exception& e) {
    throw InputError(fmt::format("{}: not the results.json of `lll bench`: {}", path.string(), e.what()));
  }
}

}  // namespace lll::bench
