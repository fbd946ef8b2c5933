#include "bench_runner.h"

#include "gl_call_counter.h"
#include "gl_debug_output.h"

#include "frame_pipeline.h"
#include "gpu_environment.h"
#include "frame_stages.h"
#include "gstd_cache.h"
#include "image_metrics.h"
#include "simulated_viewer.h"

#include "lfd/framing.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <limits>
#include <ostream>
#include <stdexcept>

namespace lfd::player {

namespace {

struct CapturedFrame {
    std::vector<metrics::Image> views; // image order
    metrics::Image eia;
};

CapturedFrame capture(const FramePipeline& pipeline)
{
    FrameOutputs frame = pipeline.read(0);
    const DisplayProfile& profile = pipeline.profile();
    CapturedFrame out;
    out.views.reserve(frame.views.size());
    for (std::vector<uint8_t>& view : frame.views)
        out.views.push_back({profile.viewWidth, profile.viewHeight, 4, std::move(view)});
    out.eia = {profile.panelWidth, profile.panelHeight, 4, std::move(frame.eia)};
    return out;
}

Quality compare(const metrics::Image& a, const metrics::Image& reference)
{
    const metrics::RgbImage test = metrics::rgbFromImage(a), ref = metrics::rgbFromImage(reference);
    const double rmse = metrics::rmse(ref, test);
    return {rmse, metrics::psnrFromRmse(rmse), metrics::ssim(ref, test), metrics::flip(ref, test)};
}

struct Config {
    std::string renderer;
    Reconstruction aa = Reconstruction::None;
    Supersampling ss = Supersampling::None;
    std::string name() const { return configName(renderer, reconstructionName(aa), supersamplingName(ss)); }
};

// Configuration lists and ordering.
struct ConfigPlan {
    std::vector<Config> configs; // the user's order: renderers, then supersampling, then reconstruction
    std::vector<Config> order;   // the run order: the reference first, then `configs` without it
    bool referenceTimed = false; // the reference is one of `configs` (else it is rendered untimed)
};

// Everything one benchmark run shares between its configurations.
struct BenchRun {
    const BenchOptions& options;
    const DisplayProfile& profile;
    const std::string& packName;
    std::ostream& progress;
    std::map<std::string, FrameImages>* images;
    FramePipeline& pipeline;
    ConfigPlan plan;
    double qualityTime;
    std::optional<GstdCache> gstdCache;
    std::string gstdKey;
    CapturedFrame reference;
    metrics::Image referenceLens;
    std::vector<metrics::Image> referenceSweep; // the reference's lens images at the sweep's positions
    std::vector<RendererResult> results;
    BenchReport& report;
    // The configurations timed round-robin (timeRoundRobin), by name: their stages and
    // stats, and their renderers, kept for the quality frame - a renderer's state after
    // its timed frames (grown buffers) is what the quality frame must see, as in
    // sequential runs.
    struct Timed {
        std::map<std::string, StageTimes> stages;
        std::vector<std::pair<std::string, double>> extra;
        std::unique_ptr<Renderer> renderer;
    };
    std::map<std::string, Timed> roundRobin = {};
};

using Say = std::function<void(const std::string&)>;

// The option checks lfd-bench also does on its flags (for callers filling BenchOptions themselves).
void validateOptions(const BenchOptions& options)
{
    if (options.frames == 0)
        throw std::invalid_argument("frames: must be at least 1");
    if (options.renderers.empty())
        throw std::invalid_argument("renderers: the list is empty");
    for (const std::string& name : options.renderers)
        if (!isKnownRenderer(name))
            createRenderer(name); // throws the one-line "unknown renderer" error
    if (!isKnownRenderer(options.reference))
        createRenderer(options.reference);
    if (options.lensPositions == 0 || options.lensPositions > 256)
        throw std::invalid_argument("lens-positions: expected 1..256, got " + std::to_string(options.lensPositions));
    validateGstdOptions(options.rendererOptions.gstd);
}

// The report's header: options, GL, pack, profile and scene sizes.
BenchReport startReport(const BenchOptions& options, const DisplayProfile& profile, const Scene& scene,
                        const std::string& packName, const std::string& glDescription)
{
    BenchReport report;
    report.options = options;
    report.gl = glDescription;
    report.packName = packName;
    report.profile = profile;
    report.triangles = scene.triangleCount();
    report.drawnTriangles = scene.drawnTriangleCount();
    return report;
}

// Step 2: the reference runs first so every other configuration is compared as soon
// as it has rendered (only the reference's frame is kept); the table keeps the user's
// order: renderers, then supersampling, then reconstruction.
ConfigPlan planConfigs(const BenchOptions& options)
{
    if (options.aa.empty() || options.ss.empty())
        throw std::invalid_argument("aa, ss: the lists must not be empty");
    ConfigPlan plan;
    for (const std::string& r : options.renderers)
        for (const Supersampling x : options.ss)
            for (const Reconstruction a : options.aa)
                plan.configs.push_back({r, a, x});
    const std::string referenceName = options.reference;
    plan.referenceTimed = std::any_of(plan.configs.begin(), plan.configs.end(), [&](const Config& c) {
        return c.name() == referenceName;
    });
    plan.order.push_back({options.reference, Reconstruction::None, Supersampling::None});
    for (const Config& c : plan.configs)
        if (c.name() != referenceName)
            plan.order.push_back(c);
    return plan;
}

// The report's results from the finished ones: the user's order, an untimed reference last.
void publish(BenchReport& report, const ConfigPlan& plan, const std::vector<RendererResult>& done, bool interrupted)
{
    report.results.clear();
    for (const Config& c : plan.configs)
        for (const RendererResult& r : done)
            if (r.name == c.name())
                report.results.push_back(r);
    if (!plan.referenceTimed && !done.empty())
        report.results.push_back(done.front());
    report.interrupted = interrupted;
}

// Whether the caller asked the run to stop.
bool stopRequested(const BenchOptions& options)
{
    return options.shouldStop && options.shouldStop();
}

// gstd's quality frame comes from the disk cache when the pack is a file (its content
// hash is part of the key); a failed cache write only costs the next run a re-render.
void openGstdCache(BenchRun& run, const std::string& glDescription)
{
    const BenchOptions& options = run.options;
    const std::vector<Config>& order = run.plan.order;
    if (options.gstdCacheEnabled &&
        std::any_of(order.begin(), order.end(), [](const Config& c) { return c.name() == "gstd"; }) &&
        std::filesystem::is_regular_file(options.pack)) {
        const std::filesystem::path dir = options.gstdCache.empty() ? defaultGstdCacheDir() : options.gstdCache;
        if (!dir.empty()) {
            run.gstdCache.emplace(dir);
            run.gstdKey = gstdCacheKey(hashFileContents(options.pack), run.qualityTime, options.turntablePeriod,
                                       run.profile, options.rendererOptions.gstd, glDescription) +
                          " " + frameLightingKey(run.pipeline.lighting(), run.pipeline.environment());
        }
    }
}

// An untimed gstd reference's options: its progress on stderr (issue 42: minutes without
// a line looked hung), the plan first with what the cost depends on and how to avoid it.
// Timed gstd frames report nothing: the wait after each batch would be timed too.
RendererOptions withReferenceProgress(const BenchRun& run)
{
    RendererOptions options = run.options.rendererOptions;
    if (run.options.quiet)
        return options;
    std::string hint;
    if (run.gstdCache)
        hint = "stored in the gstd cache " + run.gstdCache->entryPath(run.gstdKey).string() + " for the next run";
    else if (!run.options.gstdCacheEnabled)
        hint = "not cached (--no-gstd-cache)";
    hint += std::string(hint.empty() ? "" : "; ") +
            "faster: --reference mvr (the raster baseline, not the gold standard) or a smaller --gstd-factor / "
            "--gstd-sub-views; an estimate follows the first batches";
    const std::string prefix = "lfd-bench: " + run.packName + " " + std::to_string(run.profile.viewCount) + "x" +
                               std::to_string(run.profile.viewWidth) + "x" + std::to_string(run.profile.viewHeight) +
                               " ";
    options.gstd.progress = gstdProgressPrinter(std::cerr, prefix, hint);
    return options;
}

// The start of every progress line: pack and view layout.
std::ostream& progressLine(const BenchRun& run)
{
    return run.progress << "lfd-bench: " << run.packName << " " << run.profile.viewCount << "x"
                        << run.profile.viewWidth << "x" << run.profile.viewHeight << " ";
}

// A progress printer for configuration `i`: place in the run, name.
Say progressFor(const BenchRun& run, size_t i, const std::string& name)
{
    return [&run, i, name](const std::string& line) {
        if (!run.options.quiet)
            progressLine(run) << "[" << (i + 1) << "/" << run.plan.order.size() << "] " << name << ": " << line
                              << std::endl;
    };
}

// Step 3: warm-up frames (shader compilation, buffer growth), then timed frames;
// the warm-up replays the first timed frames' times and is timed separately.
// Returns false when a stop request cut the timing short.
bool timeFrames(BenchRun& run, Renderer& renderer, Reconstruction aa, RendererResult& result, const Say& say)
{
    const BenchOptions& options = run.options;
    say("warm-up " + std::to_string(options.warmup) + " frame(s), then " + std::to_string(options.frames) +
        " timed frame(s)");
    GpuTimer warmTimer;
    for (uint32_t k = 0; k < options.warmup && !stopRequested(options); ++k)
        run.pipeline.renderFrame(renderer, double(k % options.frames) / options.fps, warmTimer, aa);
    warmTimer.finish();
    GpuTimer timer;
    for (uint32_t k = 0; k < options.frames && !stopRequested(options); ++k)
        run.pipeline.renderFrame(renderer, double(k) / options.fps, timer, aa);
    timer.finish();
    if (stopRequested(options))
        return false;
    result.stages = timer.stages();
    renderer.settle(); // the stats of the last timed frame
    result.extra = renderer.extraStats();
    char line[128];
    std::snprintf(line, sizeof(line), "mean total %.2f ms", result.stageMean(std::string(stage::kTotal)));
    say(line);
    return true;
}

// Step 3, round-robin (BenchOptions::interleave): the timed configurations of each
// supersampling mode take turns, frame by frame - all warm up, then frame k of each, then
// frame k + 1 - each with its own renderer and timer. A shared machine's speed drifts
// over seconds and minutes (on a 2-core virtual machine about one frame in six took up to
// twice as long), and timing one configuration after the other let that drift land on one
// of them; taking turns spreads it over all, so the ratios within a run stay fair.
// Returns false when a stop request cut the timing short.
bool timeRoundRobin(BenchRun& run)
{
    const BenchOptions& options = run.options;
    std::vector<Supersampling> modes; // supersampling modes in run order (one target size at a time)
    for (const Config& c : run.plan.order)
        if (std::find(modes.begin(), modes.end(), c.ss) == modes.end())
            modes.push_back(c.ss);
    for (const Supersampling mode : modes) {
        struct Turn {
            Config config;
            Reconstruction aa;
            std::unique_ptr<Renderer> renderer;
            std::unique_ptr<GpuTimer> timer;
        };
        std::vector<Turn> turns;
        for (const Config& c : run.plan.order)
            if (c.ss == mode && (c.name() != options.reference || run.plan.referenceTimed))
                turns.push_back({c, c.aa, createRenderer(c.renderer, options.rendererOptions),
                                 std::make_unique<GpuTimer>()});
        if (turns.empty())
            continue;
        run.pipeline.setSupersampling(mode);
        if (!options.quiet)
            progressLine(run) << "--ss " << supersamplingName(mode) << ": " << turns.size()
                              << " configuration(s) taking turns: warm-up " << options.warmup << " frame(s), then "
                              << options.frames << " timed frame(s) each" << std::endl;
        GpuTimer warmTimer;
        for (uint32_t k = 0; k < options.warmup && !stopRequested(options); ++k)
            for (Turn& t : turns)
                run.pipeline.renderFrame(*t.renderer, double(k % options.frames) / options.fps, warmTimer, t.aa);
        warmTimer.finish();
        for (uint32_t k = 0; k < options.frames && !stopRequested(options); ++k)
            for (Turn& t : turns)
                run.pipeline.renderFrame(*t.renderer, double(k) / options.fps, *t.timer, t.aa);
        if (stopRequested(options))
            return false;
        gl::checkGlError("timing --ss " + supersamplingName(mode));
        for (Turn& t : turns) {
            t.timer->finish();
            BenchRun::Timed& timed = run.roundRobin[t.config.name()];
            timed.stages = t.timer->stages();
            t.renderer->settle(); // the stats of its last timed frame
            timed.extra = t.renderer->extraStats();
            timed.renderer = std::move(t.renderer);
        }
    }
    return true;
}

// Step 3b (timed configurations): the wall-clock time per frame - the timed frames again,
// back to back, submitted as fast as the CPU can and finished once at the end (glFinish
// before and after, outside the measurement's calls), so a frame that waits for the GPU,
// or a CPU that cannot keep the GPU busy, shows as wall time above the GPU total - with
// the GL calls those frames make (gl::GlCallCounter) and the GPU memory of a frame.
void measureWallClock(BenchRun& run, Renderer& renderer, Reconstruction aa, RendererResult& result)
{
    using Clock = std::chrono::steady_clock;
    const BenchOptions& options = run.options;
    {
        // One untimed frame first: the configuration before this one (its quality frame and
        // read-back) leaves state that the first frame after it pays for once (seen as 10 ms
        // more per frame of lfdpr's 20 back-to-back frames on an NVIDIA H200 after a
        // view-spatial configuration, and 20 ms once on llvmpipe); that is not a frame's cost.
        GpuTimer untimed;
        run.pipeline.renderFrame(renderer, 0.0, untimed, aa);
        untimed.finish();
    }
    GpuTimer timer; // the frames as they always run, timer queries included
    glFinish();
    gl::GlCallCounts calls;
    const Clock::time_point start = Clock::now();
    {
        gl::GlCallCounter counter;
        for (uint32_t k = 0; k < options.frames && !stopRequested(options); ++k)
            run.pipeline.renderFrame(renderer, double(k) / options.fps, timer, aa);
        calls = counter.counts();
    }
    glFinish();
    const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    timer.finish();
    const double frames = double(options.frames);
    result.wallMsPerFrame = ms / frames;
    result.callsPerFrame = {double(calls.dispatches) / frames, double(calls.draws) / frames,
                            double(calls.barriers) / frames, double(calls.syncs) / frames};
    result.frameGpuBytes = run.pipeline.frameGpuBytes(renderer);
}

// Step 4: the quality frame, untimed (gstd's views from the cache when it has them; the
// EIA is built from them as usual), left in the pipeline's targets.
void renderQualityFrame(BenchRun& run, Renderer& renderer, Reconstruction aa, RendererResult& result,
                        const Say& say)
{
    using Clock = std::chrono::steady_clock;
    const std::string& name = result.name;
    GpuTimer qualityTimer;
    const bool cacheable = name == "gstd" && run.gstdCache; // (gstd, none, 1) only
    // gstd's panel model integrates the EIA itself: it is cached with the views.
    const DisplayProfile& profile = run.pipeline.profile();
    const GstdCachePanel panelImage{run.pipeline.eia().texture(), profile.panelWidth, profile.panelHeight};
    const GstdCachePanel* panel =
        run.options.rendererOptions.gstd.model == GstdModel::Panel ? &panelImage : nullptr;
    if (cacheable) {
        run.pipeline.animate(run.qualityTime);
        result.fromCache = run.gstdCache->load(run.gstdKey, run.pipeline.targets(), panel);
        if (result.fromCache) {
            if (!panel)
                run.pipeline.buildEia(qualityTimer, aa);
            say("quality frame from the gstd cache " + run.gstdCache->entryPath(run.gstdKey).string());
        }
    }
    if (!result.fromCache) {
        const Clock::time_point qualityStart = Clock::now();
        run.pipeline.renderCompleteFrame(renderer, run.qualityTime, qualityTimer, aa);
        if (cacheable) {
            try {
                run.gstdCache->store(run.gstdKey, run.pipeline.targets(), panel);
            } catch (const std::exception& e) {
                run.progress << "lfd-bench: warning: gstd cache not written: " << e.what() << std::endl;
            }
        }
        char line[160];
        std::snprintf(line, sizeof(line), "quality frame rendered in %.2f s%s",
                      std::chrono::duration<double>(Clock::now() - qualityStart).count(),
                      cacheable ? " (stored in the gstd cache)" : "");
        if (name == "gstd")
            say(line);
    }
    qualityTimer.finish();
}

// Every view against the reference's: RMSE over all views' pixels and mean SSIM (no FLIP).
Quality compareAllViews(const CapturedFrame& frame, const CapturedFrame& reference)
{
    double mse = 0.0, ssim = 0.0;
    for (size_t v = 0; v < frame.views.size(); ++v) {
        const double e = metrics::rmse(frame.views[v], reference.views[v]);
        mse += e * e;
        ssim += metrics::ssim(frame.views[v], reference.views[v]);
    }
    const double n = double(frame.views.size());
    return {std::sqrt(mse / n), metrics::psnrFromRmse(std::sqrt(mse / n)), ssim / n, std::numeric_limits<double>::quiet_NaN()};
}

// The simulated viewer's images of an EIA at the sweep's K positions t_j = (j + 1/2) N / K.
std::vector<metrics::Image> lensSweepImages(const DisplayProfile& profile, const metrics::Image& eia, uint32_t k)
{
    std::vector<metrics::Image> images;
    for (uint32_t j = 0; j < k; ++j) {
        const double t = (double(j) + 0.5) * double(profile.viewCount) / double(k);
        images.push_back({profile.viewWidth, profile.viewHeight, 4, simulateViewer(profile, eia.pixels, t)});
    }
    return images;
}

RendererResult::LensSweep compareLensSweep(const std::vector<metrics::Image>& images,
                                           const std::vector<metrics::Image>& reference)
{
    RendererResult::LensSweep sweep;
    sweep.ssimMean = 0.0;
    for (size_t j = 0; j < images.size(); ++j) {
        const double rmse = metrics::rmse(images[j], reference[j]);
        const double ssim = metrics::ssim(images[j], reference[j]);
        sweep.positions.push_back({rmse, metrics::psnrFromRmse(rmse), ssim, std::numeric_limits<double>::quiet_NaN()});
        sweep.rmseMean += rmse / double(images.size());
        sweep.ssimMean += ssim / double(images.size());
        sweep.rmseWorst = std::max(sweep.rmseWorst, rmse);
        sweep.ssimWorst = std::min(sweep.ssimWorst, ssim);
    }
    return sweep;
}

// The captured frame's quality against the reference; configuration 0 is the reference
// and its frame (moved from `frame`) is kept for the others.
void compareWithReference(BenchRun& run, size_t i, CapturedFrame& frame, RendererResult& result, const Say& say)
{
    const DisplayProfile& profile = run.profile;
    // Through the lens: what an eye at the centre view position sees of this EIA.
    const double eyePosition = 0.5 * double(profile.viewCount);
    const metrics::Image lens{profile.viewWidth, profile.viewHeight, 4,
                     simulateViewer(profile, frame.eia.pixels, eyePosition)};
    std::vector<metrics::Image> sweep = lensSweepImages(profile, frame.eia, run.options.lensPositions);
    if (i == 0) {
        // The reference against itself: identical.
        const Quality identical{0.0, std::numeric_limits<double>::infinity(), 1.0, 0.0};
        result.eia = result.centreView = result.allViews = result.lens = identical;
        result.lensSweep = compareLensSweep(sweep, sweep);
        run.reference = std::move(frame);
        run.referenceLens = lens;
        run.referenceSweep = std::move(sweep);
        return;
    }
    result.lens = compare(lens, run.referenceLens);
    result.lensSweep = compareLensSweep(sweep, run.referenceSweep);
    result.eia = compare(frame.eia, run.reference.eia);
    const size_t centre = frame.views.size() / 2;
    result.centreView = compare(frame.views[centre], run.reference.views[centre]);
    result.allViews = compareAllViews(frame, run.reference);
    char line[200];
    std::snprintf(line, sizeof(line),
                  "vs %s: EIA RMSE %.2f SSIM %.4f FLIP %.4f, centre view RMSE %.2f SSIM %.4f FLIP %.4f",
                  run.options.reference.c_str(), result.eia.rmse, result.eia.ssim, result.eia.flip,
                  result.centreView.rmse, result.centreView.ssim, result.centreView.flip);
    say(line);
}

// One configuration: timed (unless it is an untimed reference), its quality frame compared
// and its result published. Returns false when a stop request cut it short.
bool runConfig(BenchRun& run, size_t i)
{
    using Clock = std::chrono::steady_clock;
    const BenchOptions& options = run.options;
    const Config& config = run.plan.order[i];
    const std::string name = config.name();
    const Reconstruction aa = config.aa;
    run.pipeline.setSupersampling(config.ss);
    const Clock::time_point start = Clock::now();
    RendererResult result;
    result.name = name;
    result.renderer = config.renderer;
    result.aa = reconstructionName(config.aa);
    result.ss = supersamplingName(config.ss);
    result.timed = name != options.reference || run.plan.referenceTimed;
    const Say say = progressFor(run, i, name);
    std::unique_ptr<Renderer> renderer;
    const auto timed = run.roundRobin.find(name);
    const bool timedTakingTurns = timed != run.roundRobin.end();
    if (timedTakingTurns) {
        renderer = std::move(timed->second.renderer); // the timed one: the quality frame sees its state
        result.stages = std::move(timed->second.stages);
        result.extra = std::move(timed->second.extra);
        run.roundRobin.erase(timed);
    } else if (!result.timed && config.renderer == "gstd") {
        renderer = createRenderer(config.renderer, withReferenceProgress(run));
    } else {
        renderer = createRenderer(config.renderer, options.rendererOptions);
    }

    if (timedTakingTurns) {
        char line[128];
        std::snprintf(line, sizeof(line), "mean total %.2f ms (timed taking turns)",
                      result.stageMean(std::string(stage::kTotal)));
        say(line);
    } else if (result.timed) {
        if (!timeFrames(run, *renderer, aa, result, say))
            return false;
    } else {
        say("reference only (not in --renderers): quality frame");
    }
    if (result.timed) {
        measureWallClock(run, *renderer, aa, result);
        if (stopRequested(options))
            return false;
        char line[160];
        std::snprintf(line, sizeof(line), "wall clock %.2f ms per frame (GPU total %.2f ms), %.1f dispatches, "
                      "%.1f draws, %.1f barriers, %.1f waits per frame",
                      result.wallMsPerFrame, result.stageMean(std::string(stage::kTotal)),
                      result.callsPerFrame.dispatches, result.callsPerFrame.draws, result.callsPerFrame.barriers,
                      result.callsPerFrame.syncs);
        say(line);
    }
    renderQualityFrame(run, *renderer, aa, result, say);
    if (!result.timed)
        result.extra = renderer->extraStats();
    gl::checkGlError("rendering with " + name);
    CapturedFrame frame = capture(run.pipeline);
    renderer.reset();

    compareWithReference(run, i, frame, result, say);
    const CapturedFrame& kept = i == 0 ? run.reference : frame;
    if (run.images)
        (*run.images)[name] = {kept.eia.pixels, kept.views[kept.views.size() / 2].pixels};
    result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    run.results.push_back(std::move(result));
    // Step 5: the report so far (the user's order, an untimed reference last).
    publish(run.report, run.plan, run.results, false);
    if (options.onResult)
        options.onResult(run.report);
    return true;
}

} // namespace

std::string configName(const std::string& renderer, const std::string& aa, const std::string& ss)
{
    std::string name = renderer;
    if (aa != "none")
        name += "+aa-" + aa;
    if (ss != "1")
        name += "+ss-" + ss;
    return name;
}

const RendererResult* BenchReport::mvrBaseline(const RendererResult& r) const
{
    // mvr with the same reconstruction and supersampling, else the same supersampling.
    if (const RendererResult* m = find(configName("mvr", r.aa, r.ss)); m && m->timed)
        return m;
    if (const RendererResult* m = find(configName("mvr", "none", r.ss)); m && m->timed)
        return m;
    const RendererResult* m = find("mvr");
    return m && m->timed ? m : nullptr;
}

double RendererResult::stageMean(const std::string& stage) const
{
    const auto it = stages.find(stage);
    return it == stages.end() ? 0.0 : it->second.mean();
}

std::optional<double> RendererResult::extraValue(const std::string& key) const
{
    for (const auto& [k, v] : extra)
        if (k == key)
            return v;
    return std::nullopt;
}

const RendererResult* BenchReport::find(const std::string& name) const
{
    for (const RendererResult& r : results)
        if (r.name == name)
            return &r;
    return nullptr;
}

std::optional<double> BenchReport::speedUp(const std::string& renderer, const std::string& other) const
{
    const RendererResult* a = find(renderer);
    const RendererResult* b = find(other);
    if (!a || !b || !a->timed || !b->timed)
        return std::nullopt;
    const double ta = a->stageMean(std::string(stage::kTotal)), tb = b->stageMean(std::string(stage::kTotal));
    if (!(ta > 0.0) || !(tb > 0.0))
        return std::nullopt;
    return tb / ta;
}

BenchReport runBenchmark(const BenchOptions& options, const DisplayProfile& profile, Scene scene,
                         const std::string& packName, const std::string& glDescription,
                         std::ostream& progress, std::map<std::string, FrameImages>* images)
{
    validateOptions(options);
    BenchReport report = startReport(options, profile, scene, packName, glDescription);

    // Step 1: upload once into the frame pipeline lfd-play uses too.
    GpuSceneOptions sceneOptions;
    sceneOptions.maxAnisotropy = options.aniso;
    FramePipeline pipeline(profile, scene, options.turntablePeriod, sceneOptions);
    pipeline.setLighting(options.lighting, uploadEnvironment(options.environment));
    scene = Scene{}; // the GPU copy is all that is needed from here on
    report.sceneGpuBytes = pipeline.scene().gpuBytes();
    report.textureAnisotropy = pipeline.scene().maxAnisotropy();

    BenchRun run{options, profile, packName, progress, images, pipeline, planConfigs(options),
                 double(options.qualityFrame) / options.fps, {}, {}, {}, {}, {}, {}, report};
    openGstdCache(run, glDescription);
    if (options.interleave && !timeRoundRobin(run)) {
        publish(report, run.plan, run.results, true);
        return report;
    }
    for (size_t i = 0; i < run.plan.order.size(); ++i) {
        if (stopRequested(options) || !runConfig(run, i)) {
            publish(report, run.plan, run.results, true);
            return report;
        }
    }
    publish(report, run.plan, run.results, false);
    return report;
}

} // namespace lfd::player
