// lfd-bench's matrix outputs (issue 8; paper section 5, Tables 1 and 2): one BenchReport
// per (pack, view count), each holding every configuration (renderer x --ss x --aa), all
// in one place:
//   results.csv   one row per configuration with every figure (and whether it is on its
//                 scene's Pareto front of total time against EIA RMSE);
//   results.json  the same reports in full (benchJson each), plus `interrupted`;
//   table.md      the paper's Table 1 layout: per-stage ms (point generation with the
//                 point count, view generation, EIA), total with the ratio to mvr, and RMSE /
//                 FLIP / SSIM against the reference for the EIA with the single (centre)
//                 view in parentheses, plus the through-the-lens figures;
//   chart.png/svg time per frame against EIA RMSE, one labelled point per configuration,
//                 the Pareto front drawn, one panel per scene - drawn by
//                 player/bench/bench_chart.py with matplotlib (python3-matplotlib); where no
//                 python3 has matplotlib the chart is skipped with a message saying so.
// Written after every finished configuration (each file atomically), so an interrupted run
// keeps everything it finished.
#pragma once

#include "bench_runner.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace lfd::player {

// Per report: true for each result on the Pareto front of (total ms, EIA RMSE) among the
// timed configurations (no other is at least as fast and as accurate, and better in one).
std::vector<bool> paretoFront(const BenchReport& report);

std::string matrixCsv(const std::vector<BenchReport>& reports);
nlohmann::json matrixJson(const std::vector<BenchReport>& reports);
std::string matrixTable(const std::vector<BenchReport>& reports);

// Writes DIR/results.csv, results.json and table.md (atomically).
void writeMatrixTables(const std::filesystem::path& dir, const std::vector<BenchReport>& reports);

// Draws DIR/chart.png and DIR/chart.svg from DIR/results.csv with bench_chart.py: tries
// `python3`, then /usr/bin/python3, each only if it imports matplotlib. Returns true if the
// chart was drawn; otherwise `why` says why not (no exception: the bench still succeeds).
bool drawMatrixChart(const std::filesystem::path& dir, std::string& why);

// The chart script: $LFD_BENCH_CHART_SCRIPT, else the source tree's player/bench/bench_chart.py.
std::filesystem::path chartScriptPath();

} // namespace lfd::player
