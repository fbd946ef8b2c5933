// lfd-bench's outputs: the console table, bench.json (every number), bench.csv (one row
// per renderer), the speed-versus-error chart (hand-written SVG: total GPU ms against EIA
// RMSE, one labelled point per renderer, since speed and error are always charted
// together) and the quality-frame PNGs.
#pragma once

#include "bench_runner.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace lfd::player {

// Header lines (GL, pack, views, frames), the table and the lfdpr ratio lines.
std::string benchTable(const BenchReport& report);
nlohmann::json benchJson(const BenchReport& report);
std::string benchCsv(const BenchReport& report);
std::string speedErrorSvg(const BenchReport& report);

// Writes DIR/bench.json, bench.csv, speed_vs_error.svg and, per renderer,
// <name>_eia.png, <name>_view_centre.png and (not for the reference) <name>_diff_eia.png.
// Each file is atomic; if one fails, the ones already written are removed and the
// exception (one line naming the file) propagates. Returns the files written.
std::vector<std::filesystem::path> writeBenchOutputs(const std::filesystem::path& dir,
                                                     const BenchReport& report,
                                                     const std::map<std::string, FrameImages>& images);

} // namespace lfd::player
