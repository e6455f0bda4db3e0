#pragma once
// The files `lll bench` writes; writeReport (bench.h) calls them all.
#include <filesystem>

#include "bench/bench.h"

namespace lll::bench {

// Every pass name of `results` in one order that keeps each result's own order (depth-prepass
// first; tonemap and frame last): the columns of per-pass tables and the segments of stacked bars.
std::vector<std::string> passOrder(const std::vector<const ScenarioResult*>& results);

// Everything: run metadata, and per scenario its settings, status, per-pass times and memory.
void writeResultsJson(const BenchReport& report, const std::filesystem::path& path);
// One row per scenario x technique x pass that ran, for spreadsheets and plotting tools.
void writeResultsCsv(const BenchReport& report, const std::filesystem::path& path);
// What writeResultsJson wrote, as far as the charts need it: run metadata and per scenario its
// suite, scene, settings, light count, status, passes and memory. Throws InputError naming the file and
// what is wrong when it cannot be read.
BenchReport readResultsJson(const std::filesystem::path& path);
// Markdown tables per suite, headed by device, driver, commit and date.
void writeSummaryMarkdown(const BenchReport& report, const std::filesystem::path& path);
// PNG charts drawn by gnuplot from data files and a script left in `dir`; returns the PNGs
// written, or none (with a warning on stderr) when gnuplot is missing or fails.
std::vector<std::filesystem::path> writeCharts(const BenchReport& report, const std::filesystem::path& dir);

}  // namespace lll::bench
