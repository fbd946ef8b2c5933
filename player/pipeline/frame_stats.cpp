#include "frame_stats.h"

#include "atomic_file.h"
#include "frame_stages.h"

#include <cstdio>
#include <sstream>
#include <sys/resource.h>

namespace lfd::player {

double peakHostMemoryMiB()
{
    struct rusage usage {};
    if (::getrusage(RUSAGE_SELF, &usage) != 0)
        return 0.0;
    return double(usage.ru_maxrss) / 1024.0; // Linux reports KiB
}

nlohmann::json statsJson(const RunInfo& info, const std::map<std::string, StageTimes>& stages)
{
    nlohmann::json j;
    j["renderer"] = info.renderer;
    j["views"] = info.views;
    j["view_width"] = info.viewWidth;
    j["view_height"] = info.viewHeight;
    j["frames"] = info.frames;
    j["gpu"] = info.gpu;
    j["profile"] = info.profile;
    j["pack"] = info.pack;
    j["reconstruction"] = info.reconstruction;
    j["supersampling"] = info.supersampling;
    j["panel_width"] = info.panelWidth;
    j["panel_height"] = info.panelHeight;
    j["view_buffer_bytes"] = info.viewBufferBytes;
    j["scene_gpu_bytes"] = info.sceneGpuBytes;
    j["gpu_scene_bytes"] = info.sceneGpuBytes;
    j["texture_anisotropy"] = info.textureAnisotropy;
    j["streaming"] = info.streaming;
    j["time_to_first_frame_ms"] = info.timeToFirstFrameMs;
    j["time_to_resident_ms"] = info.timeToResidentMs;
    j["peak_host_memory_mib"] = info.peakHostMemoryMiB;
    j["triangles"] = info.triangles;
    j["drawn_triangles"] = info.drawnTriangles;

    // Means at the top level (the numbers a reader wants first), details under "stages".
    nlohmann::json detail = nlohmann::json::object();
    for (const std::string_view required : stage::kRequired)
        j[std::string(required) + "_ms"] = 0.0; // present even if a stage did not run
    for (const auto& [name, times] : stages) {
        j[name + "_ms"] = times.mean();
        detail[name] = {{"mean", times.mean()},
                        {"median", times.median()},
                        {"min", times.min()},
                        {"max", times.max()},
                        {"samples", times.ms.size()}};
    }
    j["stages"] = detail;
    for (const auto& [key, value] : info.extra)
        if (!j.contains(key))
            j[key] = value;
    return j;
}

std::string statsCsv(const std::map<std::string, StageTimes>& stages)
{
    std::ostringstream csv;
    csv << "frame,stage,ms\n";
    size_t frames = 0;
    for (const auto& [name, times] : stages)
        frames = std::max(frames, times.ms.size());
    char value[64];
    for (size_t f = 0; f < frames; ++f)
        for (const auto& [name, times] : stages)
            if (f < times.ms.size()) {
                std::snprintf(value, sizeof(value), "%.6f", times.ms[f]);
                csv << f << ',' << name << ',' << value << '\n';
            }
    return csv.str();
}

std::string workCsv(const std::vector<std::vector<std::pair<std::string, double>>>& workPerFrame)
{
    if (workPerFrame.empty())
        return {};
    std::ostringstream csv;
    csv << "frame";
    for (const auto& [name, value] : workPerFrame.front())
        csv << ',' << name;
    csv << '\n';
    char text[64];
    for (size_t f = 0; f < workPerFrame.size(); ++f) {
        csv << f;
        for (const auto& [name, value] : workPerFrame[f]) {
            // Counts are integers; %.17g keeps any that are not (none today) exact.
            std::snprintf(text, sizeof(text), "%.17g", value);
            csv << ',' << text;
        }
        csv << '\n';
    }
    return csv.str();
}

void writeStats(const std::filesystem::path& jsonPath, const RunInfo& info,
                const std::map<std::string, StageTimes>& stages)
{
    std::filesystem::path csvPath = jsonPath;
    csvPath.replace_extension(".csv");
    if (csvPath == jsonPath)
        csvPath += ".csv";
    writeFileAtomically(jsonPath, statsJson(info, stages).dump(2) + "\n");
    writeFileAtomically(csvPath, statsCsv(stages));
    if (!info.workPerFrame.empty()) {
        std::filesystem::path workPath = csvPath;
        workPath.replace_extension(".work.csv");
        writeFileAtomically(workPath, workCsv(info.workPerFrame));
    }
}

} // namespace lfd::player
