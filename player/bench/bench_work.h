// lfd-bench's work counters (docs/player/8k-panels.md "Work counters"): the work_* stats
// each renderer reports (Renderer::extraStats; lfdpr's GPU counters with
// --lfdpr-work-counters), as one table of their own below the timing table and as the
// last columns of bench.csv. A renderer without a counter shows "-" (empty in the CSV).
#pragma once

#include "bench_runner.h"

#include <array>
#include <string>
#include <string_view>

namespace lfd::player {

// The counters in table and CSV order (their stat names).
inline constexpr std::array<std::string_view, 11> kWorkCounters = {
    "work_points",         "work_point_views",        "work_point_views_culled",
    "work_point_views_culled_by_centres",             "work_point_view_setups",
    "work_triangle_views", "work_samples",            "work_atomics",
    "work_words_lowered",  "work_shadings",           "work_bytes_cleared"};

// "work per frame" table (Markdown), one row per timed renderer; empty when no renderer
// reports a work counter.
std::string benchWorkTable(const BenchReport& report);
// ",work_points,...": the CSV header's work columns, and one row's values.
std::string benchWorkCsvHeader();
std::string benchWorkCsvRow(const RendererResult& r);

} // namespace lfd::player
