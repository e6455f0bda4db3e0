// summary.md: per suite, frame time and memory as technique x scenario tables, the per-pass
// breakdown, and what was skipped and why.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <map>

#include "bench/report.h"
#include "core/errors.h"
#include "render/output_files.h"

namespace lll::bench {

namespace {

using Results = std::vector<const ScenarioResult*>;
using Cell = std::function<std::string(const ScenarioResult&)>;

// Appends `value` unless present: tables keep the order in which the suite ran things.
void addUnique(std::vector<std::string>& list, const std::string& value) {
  if (std::find(list.begin(), list.end(), value) == list.end()) list.push_back(value);
}

std::string tableRow(const std::vector<std::string>& cells) {
  std::string row = "|";
  for (const std::string& c : cells) row += " " + c + " |";
  return row + "\n";
}

std::string tableHeader(const std::vector<std::string>& columns) {
  return tableRow(columns) + tableRow(std::vector<std::string>(columns.size(), "---"));
}

// Technique rows x scenario columns; a cell shows `cell` of the result, or why it did not run.
std::string pivot(const Results& results, const Cell& cell) {
  std::vector<std::string> rows, columns = {"technique"};
  for (const ScenarioResult* r : results) {
    addUnique(rows, techniqueLabel(r->scenario.settings));
    addUnique(columns, r->scenario.name);
  }
  std::string md = tableHeader(columns);
  for (const std::string& row : rows) {
    std::vector<std::string> cells = {row};
    for (size_t c = 1; c < columns.size(); ++c) {
      const auto it = std::find_if(results.begin(), results.end(), [&](const ScenarioResult* r) {
        return techniqueLabel(r->scenario.settings) == row && r->scenario.name == columns[c];
      });
      cells.push_back(it == results.end()           ? ""
                      : (*it)->status == Status::Ok ? cell(**it)
                                                    : statusName((*it)->status));
    }
    md += tableRow(cells);
  }
  return md;
}

std::string frameCell(const ScenarioResult& r) {
  const PassSummary* frame = r.pass("frame");
  return frame ? fmt::format("{:.2f} ({:.2f}–{:.2f})", frame->medianMs, frame->minMs, frame->maxMs) : "";
}

std::string memoryCell(const ScenarioResult& r) {
  return fmt::format("{:.2f}", r.memoryBytes() / (1024.0 * 1024.0));
}

// One row per scenario that ran, one column per pass name met in the suite: median ms.
std::string passTable(const Results& results) {
  const std::vector<std::string> passes = passOrder(results);
  std::vector<std::string> columns = {"scenario", "technique", "lights"};
  columns.insert(columns.end(), passes.begin(), passes.end());
  std::string md = tableHeader(columns);
  for (const ScenarioResult* r : results) {
    if (r->status != Status::Ok) continue;
    std::vector<std::string> cells = {r->scenario.name, techniqueLabel(r->scenario.settings),
                                      std::to_string(r->lightCount)};
    for (const std::string& name : passes) {
      const PassSummary* p = r->pass(name);
      cells.push_back(p ? fmt::format("{:.3f}", p->medianMs) : "");
    }
    md += tableRow(cells);
  }
  return md;
}

// What did not run, one line per distinct reason, naming the scenarios it concerns.
std::string notRun(const Results& results) {
  std::vector<std::string> reasons;
  std::map<std::string, std::vector<std::string>> who;
  for (const ScenarioResult* r : results) {
    if (r->status == Status::Ok) continue;
    const std::string reason = fmt::format("{}: {}", statusName(r->status), r->message);
    addUnique(reasons, reason);
    who[reason].push_back(techniqueLabel(r->scenario.settings) + " " + r->scenario.name);
  }
  std::string md;
  for (const std::string& reason : reasons)
    md += fmt::format("- {} ({})\n", reason, fmt::join(who[reason], ", "));
  return md.empty() ? md : "Not measured:\n\n" + md;
}

const double* statOf(const ScenarioResult& r, const std::string& key) {
  for (const auto& [name, value] : r.techniqueStats)
    if (name == key) return &value;
  return nullptr;
}

// Techniques drawing lights as volumes report their light pass's fragment count ("<technique>-
// lights" pass): overdraw (fragments per pixel) and the pass's time per fragment.
std::string overdrawCell(const ScenarioResult& r) {
  const double* fragments = statOf(r, "light-volume-fragments");
  const double* overdraw = statOf(r, "light-volume-overdraw");
  const PassSummary* lights = r.pass(r.scenario.settings.technique + "-lights");
  if (!fragments || !overdraw || !lights || *fragments <= 0.0) return "";
  return fmt::format("{:.1f} ({:.2f} ns/fragment)", *overdraw, lights->medianMs * 1e6 / *fragments);
}

std::string overdrawTable(const Results& results) {
  Results volumes;
  for (const ScenarioResult* r : results)
    if (r->status == Status::Ok && statOf(*r, "light-volume-fragments")) volumes.push_back(r);
  if (volumes.empty()) return "";
  return "\nLight-volume overdraw: fragments shaded by the light pass per pixel (its time per fragment)\n\n" +
         pivot(volumes, overdrawCell);
}

// The frame against forward's of the same scenario: PSNR and the largest pixel difference.
std::string forwardCell(const ScenarioResult& r) {
  if (!r.vsForward) return "";
  return fmt::format("{} ({})",
                     std::isinf(r.vsForward->psnr) ? "identical" : fmt::format("{:.1f}", r.vsForward->psnr),
                     r.vsForward->worst);
}

std::string forwardTable(const Results& results) {
  Results compared;
  for (const ScenarioResult* r : results)
    if (r->vsForward && r->scenario.settings.technique != "forward") compared.push_back(r);
  if (compared.empty()) return "";
  return "\nImage against forward's frame of the same scenario: PSNR, dB (largest pixel difference of "
         "255)\n\n" +
         pivot(compared, forwardCell);
}

// Opaque shading against the ALU probe timed beside it (bench/alu_probe.h): how many times the
// arithmetic of every light at every pixel it takes.
std::string rooflineCell(const ScenarioResult& r) {
  const PassSummary* shade = r.pass("shade-opaque");
  const PassSummary* probe = r.pass("alu-probe");
  if (!shade || !probe || probe->medianMs <= 0.0) return "";
  return fmt::format("{:.2f}x ({:.3f} / {:.3f})", shade->medianMs / probe->medianMs, shade->medianMs,
                     probe->medianMs);
}

std::string rooflineTable(const Results& results) {
  Results probed;
  for (const ScenarioResult* r : results)
    if (r->status == Status::Ok && r->pass("alu-probe") && r->pass("shade-opaque")) probed.push_back(r);
  if (probed.empty()) return "";
  return "\nOpaque shading against the ALU-only probe (every light at every pixel, no list, no memory): "
         "shade-opaque / alu-probe (ms / ms)\n\n" +
         pivot(probed, rooflineCell);
}

std::string suiteSection(const std::string& suite, const Results& results, uint32_t frames) {
  std::string md = fmt::format("## {}\n\n", suite);
  md += fmt::format("Frame time, ms: median of {} timed frames (min–max)\n\n", frames) +
        pivot(results, frameCell);
  md += "\nGPU memory of the lighting data, MiB (depth + the technique's buffers)\n\n" +
        pivot(results, memoryCell);
  md += forwardTable(results);
  md += overdrawTable(results);
  md += rooflineTable(results);
  md += "\nPer-pass GPU time, ms (median)\n\n" + passTable(results);
  const std::string skipped = notRun(results);
  return md + (skipped.empty() ? "" : "\n" + skipped) + "\n";
}

std::string header(const BenchReport& report) {
  std::string md = "# lll bench\n\n";
  md += tableHeader({"", ""});
  md += tableRow({"device", fmt::format("{} ({})", report.device.name, report.device.type)});
  md += tableRow({"driver", report.device.driver});
  md += tableRow({"Vulkan", report.device.apiVersion});
  md += tableRow({"commit", report.commit});
  md += tableRow({"date", report.date});
  md += tableRow({"frames", fmt::format("{} warm-up + {} timed per scenario{}", report.warmupFrames,
                                        report.timedFrames, report.quick ? " (--quick: tiny sizes)" : "")});
  if (!report.onlyTechniques.empty())
    md += tableRow(
        {"techniques", fmt::format("only {} (--technique)", fmt::join(report.onlyTechniques, ", "))});
  if (!report.timestamps) md += tableRow({"warning", "the device has no GPU timestamps: every time is 0"});
  if (report.interrupted)
    md += tableRow({"interrupted", fmt::format("stopped after {} scenarios: later ones are missing",
                                               report.results.size())});
  return md + "\n";
}

}  // namespace

void writeSummaryMarkdown(const BenchReport& report, const std::filesystem::path& path) {
  std::string md = header(report);
  for (const std::string& suite : report.suites) {
    Results results;
    for (const ScenarioResult& r : report.results)
      if (r.scenario.suite == suite) results.push_back(&r);
    md += suiteSection(suite, results, report.timedFrames);
  }
  writeAtomically(path, [&](const std::filesystem::path& temporary) {
    std::ofstream out(temporary);
    out << md;
    out.close();
    if (!out) throw InputError(fmt::format("--out: cannot write {}", path.string()));
  });
}

}  // namespace lll::bench
