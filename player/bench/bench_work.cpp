#include "bench_work.h"

#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>

namespace lfd::player {

namespace {

// Counts as integers (they are exact: up to 2^53).
std::string countCell(const std::optional<double>& v)
{
    if (!v)
        return "-";
    char text[32];
    std::snprintf(text, sizeof(text), "%.0f", *v);
    return text;
}

bool reportsWork(const RendererResult& r)
{
    for (const std::string_view name : kWorkCounters)
        if (r.extraValue(std::string(name)))
            return true;
    return false;
}

} // namespace

std::string benchWorkTable(const BenchReport& report)
{
    bool any = false;
    for (const RendererResult& r : report.results)
        any = any || (r.timed && reportsWork(r));
    if (!any)
        return {};
    std::ostringstream s;
    s << "work per frame (last counted frame; docs/player/8k-panels.md \"Work counters\"):\n\n| renderer |";
    for (const std::string_view name : kWorkCounters)
        s << ' ' << name.substr(5) << " |"; // without "work_"
    s << "\n|---|";
    for (size_t i = 0; i < kWorkCounters.size(); ++i)
        s << "---:|";
    s << '\n';
    for (const RendererResult& r : report.results) {
        if (!r.timed || !reportsWork(r))
            continue;
        s << "| " << r.name << " |";
        for (const std::string_view name : kWorkCounters)
            s << ' ' << countCell(r.extraValue(std::string(name))) << " |";
        s << '\n';
    }
    return s.str();
}

std::string benchWorkCsvHeader()
{
    std::string header;
    for (const std::string_view name : kWorkCounters)
        header += "," + std::string(name);
    return header;
}

std::string benchWorkCsvRow(const RendererResult& r)
{
    std::string row;
    for (const std::string_view name : kWorkCounters) {
        const auto v = r.extraValue(std::string(name));
        row += "," + (v ? countCell(v) : std::string());
    }
    return row;
}

} // namespace lfd::player
