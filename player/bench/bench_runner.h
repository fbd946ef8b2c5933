// lfd-bench's measurement (paper section 5; docs/bench/lfd-bench.md): every renderer runs in one
// process and one GL context on the same uploaded pack, the same views and the same frame times of
// the rotating scene; per-stage GPU times come from the renderers' own GpuTimer stages, and quality
// is measured at one fixed frame against a reference renderer (the gold standard gstd by default,
// paper section 5; its views are cached on disk, gstd_cache.h). Speed and error are reported
// together (bench_report.h formats them).
#pragma once

#include "eia_builder.h"    // Reconstruction
#include "environment_choice.h"
#include "frame_pipeline.h" // Supersampling
#include "gpu_timer.h"
#include "renderer_registry.h"

#include "lfd/display_profile.h"
#include "lfd/scene.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace lfd::player {

struct BenchOptions {
    std::filesystem::path pack;
    std::vector<std::string> renderers{"mvr", "mvr-layered", "lfdpr"};
    std::string reference = "gstd"; // quality reference (rendered untimed if not listed)
    RendererOptions rendererOptions; // every renderer is built with these (gstd: reference or timed)
    // Cache of gstd's quality-frame views: used when `pack` is a readable file; empty
    // gstdCache = defaultGstdCacheDir(); gstdCacheEnabled = false renders every time.
    std::filesystem::path gstdCache;
    bool gstdCacheEnabled = true;
    uint32_t frames = 100;          // timed frames
    uint32_t warmup = 3;            // untimed frames before them
    // Round-robin timing (default): the timed configurations of one supersampling mode take
    // turns frame by frame (frame k of each, then k + 1), so a machine whose speed drifts
    // over seconds or minutes (a shared virtual machine, a GPU's clocks) slows them alike
    // and their ratios stay fair. false: each configuration's frames in one block, one
    // configuration after the other.
    bool interleave = true;
    double fps = 60.0;              // frame k is at time k / fps
    double turntablePeriod = 10.0;  // seconds per revolution, 0 = still
    float aniso = 1.0f;             // --aniso: the scene textures' max anisotropy, every renderer
    // Lighting for every renderer (docs/lighting.md): exposure, tone mapping, rotation, and
    // the environment (neutral | none | FILE.hdr); the default is the look before
    // image-based lighting, lfd-bench's flags choose the tools' default (neutral).
    FrameLighting lighting;
    lighting::EnvironmentChoice environment;
    uint32_t qualityFrame = 0;      // frame whose views and EIA are compared
    uint32_t lensPositions = 9;     // --lens-positions: viewer positions of the through-the-lens sweep
    std::filesystem::path outDir;   // empty: nothing written
    bool quiet = false;             // no progress lines
    // The matrix (paper section 5, Tables 1 and 2): every renderer runs with every
    // reconstruction (--aa) and supersampling (--ss) listed; the reference runs once, with
    // neither. A configuration other than (none, 1) is named configName(...).
    std::vector<Reconstruction> aa{Reconstruction::None};
    std::vector<Supersampling> ss{Supersampling::None};
    // Called after each finished configuration with the report so far (incremental,
    // interrupt-safe outputs); checked before each configuration and frame: true stops
    // the run, keeping what finished.
    std::function<void(const struct BenchReport&)> onResult;
    std::function<bool()> shouldStop;
};

// "lfdpr" for (lfdpr, none, 1), else e.g. "lfdpr+aa-view-spatial+ss-2v".
std::string configName(const std::string& renderer, const std::string& aa, const std::string& ss);

// Quality of one image set against the reference's (image_metrics.h).
struct Quality {
    double rmse = 0.0; // 0..255
    double psnr = 0.0; // dB, +inf when identical
    double ssim = 1.0; // luma
    // LDR FLIP (lfd::metrics::flip, mean over pixels, 0 = identical) at FLIP's default
    // observer (about 67 pixels per degree, as lfd-compare), so the PNGs lfd-bench writes
    // give the same value in lfd-compare. NaN where not computed (all views).
    double flip = 0.0;
};

struct RendererResult {
    std::string name;     // configName(renderer, aa, ss)
    std::string renderer; // registry name
    std::string aa = "none", ss = "1";
    bool timed = true;  // false: the reference, rendered only for quality
    std::map<std::string, StageTimes> stages; // timed frames only
    std::vector<std::pair<std::string, double>> extra; // Renderer::extraStats() after the run
    Quality eia, centreView, allViews; // allViews: RMSE from the mean MSE, SSIM averaged
    // Through the lens: the simulated viewer's image at the centre view position
    // (simulated_viewer.h) of this EIA against that of the reference's EIA.
    Quality lens;
    // The sweep (--lens-positions K): the simulated viewer at K positions across the
    // viewing cone, t_j = (j + 1/2) N / K, each against the reference's at t_j: the mean
    // and the worst RMSE and SSIM over the positions (FLIP not computed), and each one.
    struct LensSweep {
        double rmseMean = 0.0, rmseWorst = 0.0, ssimMean = 1.0, ssimWorst = 1.0;
        std::vector<Quality> positions;
    } lensSweep;
    // Wall-clock time per frame (docs/bench/lfd-bench.md "Honest frame rates"): the timed frame
    // count again, back to back as fast as the CPU submits them, finished once at the end; above
    // the GPU total where a frame waits for the GPU or the CPU cannot keep it busy. 0 untimed.
    double wallMsPerFrame = 0.0;
    // The GL calls of those frames, per frame (gl::GlCallCounter): compute dispatches,
    // draws, memory barriers and calls that wait for the GPU (0 in a steady state).
    struct Calls {
        double dispatches = 0.0, draws = 0.0, barriers = 0.0, syncs = 0.0;
    } callsPerFrame;
    // GPU memory of a frame (FramePipeline::frameGpuBytes): view targets, EIA and the
    // renderer's per-frame buffers; the scene is BenchReport::sceneGpuBytes.
    uint64_t frameGpuBytes = 0;
    double seconds = 0.0; // wall time of this renderer's run (timing + quality frame)
    bool fromCache = false; // the quality frame's views came from the gstd cache

    double stageMean(const std::string& stage) const; // 0 when absent
    std::optional<double> extraValue(const std::string& key) const;
};

struct BenchReport {
    BenchOptions options;
    std::string gl;        // GlContext::describe()
    std::string packName;
    DisplayProfile profile;
    uint64_t triangles = 0;
    uint64_t drawnTriangles = 0; // with every node instance counted
    uint64_t sceneGpuBytes = 0;
    float textureAnisotropy = 1.0f; // options.aniso as the driver applied it
    std::vector<RendererResult> results; // in options.renderers order, reference last if untimed
    bool interrupted = false;            // options.shouldStop ended the run early

    const RendererResult* find(const std::string& name) const;
    // The configuration the paper's ratio compares `r` with: mvr with r's reconstruction and
    // supersampling, else mvr with its supersampling, else plain mvr; null when not run.
    const RendererResult* mvrBaseline(const RendererResult& r) const;
    // other's total / renderer's total (> 1: `renderer` is faster); empty if either is
    // missing or untimed.
    std::optional<double> speedUp(const std::string& renderer, const std::string& other) const;
};

// The reference renderer's outputs at the quality frame and each renderer's own, kept so
// the caller can write the PNGs (image order, RGBA8).
struct FrameImages {
    std::vector<uint8_t> eia;    // panel size
    std::vector<uint8_t> centre; // view viewCount / 2
};

// Runs the benchmark. Needs a current GL 4.5 context (`glDescription` is recorded as is).
// Progress lines go to `progress` unless options.quiet. `images` (optional) receives each
// renderer's quality-frame EIA and centre view, keyed by renderer name.
BenchReport runBenchmark(const BenchOptions& options, const DisplayProfile& profile, Scene scene,
                         const std::string& packName, const std::string& glDescription,
                         std::ostream& progress,
                         std::map<std::string, FrameImages>* images = nullptr);

} // namespace lfd::player
