// Run statistics (paper section 5: time per stage): per-stage GPU milliseconds with mean / median /
// min / max, the run's configuration, view-buffer memory and renderer-specific numbers,
// written as JSON (--stats FILE.json) plus a CSV with one row per frame per stage next to
// it (same stem, .csv) for charts.
#pragma once

#include "gpu_timer.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace lfd::player {

struct RunInfo {
    std::string renderer, gpu, profile, pack, reconstruction, supersampling = "1";
    uint32_t views = 0, viewWidth = 0, viewHeight = 0, frames = 0;
    uint32_t panelWidth = 0, panelHeight = 0;
    uint64_t viewBufferBytes = 0, sceneGpuBytes = 0, triangles = 0, drawnTriangles = 0;
    double textureAnisotropy = 1.0; // --aniso as applied
    std::vector<std::pair<std::string, double>> extra; // Renderer::extraStats()
    // Loading (docs/player/streaming.md): wall milliseconds from the start of reading the pack to
    // the end of the first frame and to the whole scene resident on the GPU (< 0: not
    // measured, e.g. quilt input), and the process's peak resident set (getrusage).
    double timeToFirstFrameMs = -1.0, timeToResidentMs = -1.0, peakHostMemoryMiB = 0.0;
    bool streaming = false;
    // With work counters on (--lfdpr-work-counters): each timed frame's Renderer::extraStats()
    // entries named work_*, in frame order (written as the work CSV below).
    std::vector<std::vector<std::pair<std::string, double>>> workPerFrame;
};

// Keys: renderer, views, view_width, view_height, frames, gpu, <stage>_ms (means) for
// every stage (view_generation_ms, eia_ms, total_ms at least), stages {name: {mean,
// median, min, max, samples}}, view_buffer_bytes, scene_gpu_bytes, triangles, drawn_triangles,
// panel_width, panel_height, profile, pack, reconstruction, streaming, time_to_first_frame_ms,
// time_to_resident_ms, peak_host_memory_mib, gpu_scene_bytes (= scene_gpu_bytes), and the
// extra stats.
// ru_maxrss of this process in MiB.
double peakHostMemoryMiB();

nlohmann::json statsJson(const RunInfo& info, const std::map<std::string, StageTimes>& stages);
// "frame,stage,ms" header, then one row per recorded sample.
std::string statsCsv(const std::map<std::string, StageTimes>& stages);

// "frame,<counter>,..." header (the counters of the first frame, in its order), then one row
// per frame; empty when `workPerFrame` is.
std::string workCsv(const std::vector<std::vector<std::pair<std::string, double>>>& workPerFrame);

// Writes `jsonPath` and its .csv sibling atomically (atomic_file.h), and with per-frame work
// counters a second sibling, STEM.work.csv (workCsv). Throws
// AtomicWriteError (a std::runtime_error) naming the file.
void writeStats(const std::filesystem::path& jsonPath, const RunInfo& info,
                const std::map<std::string, StageTimes>& stages);

} // namespace lfd::player
