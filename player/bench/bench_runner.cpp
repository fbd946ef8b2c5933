#include "bench_runner.h"

#include "gl_debug_output.h"

#include "frame_pipeline.h"
#include "frame_stages.h"
#include "gstd_cache.h"
#include "image_output.h"
#include "simulated_viewer.h"

#include "lfd/framing.h"

#include "image_metrics.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <ostream>
#include <stdexcept>

namespace lfd::player {

namespace {

struct CapturedFrame {
    std::vector<Image> views; // image order
    Image eia;
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

Quality compare(const Image& a, const Image& reference)
{
    const auto rgb = [](const Image& image) {
        return metrics::rgbFromPixels8(image.pixels.data(), int(image.width), int(image.height),
                                       int(image.channels));
    };
    return {rmse(a, reference), psnr(a, reference), ssimLuma(a, reference),
            metrics::flip(rgb(reference), rgb(a))};
}

double psnrFromRmse(double e)
{
    return e == 0.0 ? std::numeric_limits<double>::infinity() : 20.0 * std::log10(255.0 / e);
}

struct Config {
    std::string renderer, aa, ss;
    std::string name() const { return configName(renderer, aa, ss); }
};

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
    using Clock = std::chrono::steady_clock;
    if (options.frames == 0)
        throw std::invalid_argument("frames: must be at least 1");
    if (options.renderers.empty())
        throw std::invalid_argument("renderers: the list is empty");
    for (const std::string& name : options.renderers)
        if (!isKnownRenderer(name))
            createRenderer(name); // throws the one-line "unknown renderer" error
    if (!isKnownRenderer(options.reference))
        createRenderer(options.reference);
    validateGstdOptions(options.rendererOptions.gstd);

    BenchReport report;
    report.options = options;
    report.gl = glDescription;
    report.packName = packName;
    report.profile = profile;
    report.triangles = scene.triangleCount();
    report.drawnTriangles = scene.drawnTriangleCount();

    // Step 1: upload once into the frame pipeline lfd-play uses too.
    FramePipeline pipeline(profile, scene, options.turntablePeriod);
    scene = Scene{}; // the GPU copy is all that is needed from here on
    report.sceneGpuBytes = pipeline.scene().gpuBytes();

    // Step 2: the reference runs first so every other configuration is compared as soon
    // as it has rendered (only the reference's frame is kept); the table keeps the user's
    // order: renderers, then supersampling, then reconstruction.
    if (options.aa.empty() || options.ss.empty())
        throw std::invalid_argument("aa, ss: the lists must not be empty");
    for (const std::string& a : options.aa)
        parseReconstruction(a);
    for (const std::string& x : options.ss)
        parseSupersampling(x);
    std::vector<Config> configs;
    for (const std::string& r : options.renderers)
        for (const std::string& x : options.ss)
            for (const std::string& a : options.aa)
                configs.push_back({r, a, x});
    const std::string referenceName = options.reference;
    const bool referenceTimed = std::any_of(configs.begin(), configs.end(), [&](const Config& c) {
        return c.name() == referenceName;
    });
    std::vector<Config> order;
    order.push_back({options.reference, "none", "1"});
    for (const Config& c : configs)
        if (c.name() != referenceName)
            order.push_back(c);
    auto publish = [&](std::vector<RendererResult>& done, bool interrupted) {
        report.results.clear();
        for (const Config& c : configs)
            for (const RendererResult& r : done)
                if (r.name == c.name())
                    report.results.push_back(r);
        if (!referenceTimed && !done.empty())
            report.results.push_back(done.front());
        report.interrupted = interrupted;
    };

    CapturedFrame reference;
    Image referenceLens;
    std::vector<RendererResult> results;
    const double qualityTime = double(options.qualityFrame) / options.fps;

    // gstd's quality frame comes from the disk cache when the pack is a file (its content
    // hash is part of the key); a failed cache write only costs the next run a re-render.
    std::optional<GstdCache> gstdCache;
    std::string gstdKey;
    if (options.gstdCacheEnabled && std::any_of(order.begin(), order.end(), [](const Config& c) { return c.name() == "gstd"; }) &&
        std::filesystem::is_regular_file(options.pack)) {
        const std::filesystem::path dir = options.gstdCache.empty() ? defaultGstdCacheDir() : options.gstdCache;
        if (!dir.empty()) {
            gstdCache.emplace(dir);
            gstdKey = gstdCacheKey(hashFileContents(options.pack), qualityTime, options.turntablePeriod, profile,
                                   options.rendererOptions.gstd, glDescription);
        }
    }
    auto stopRequested = [&] { return options.shouldStop && options.shouldStop(); };
    for (size_t i = 0; i < order.size(); ++i) {
        if (stopRequested()) {
            publish(results, true);
            return report;
        }
        const Config& config = order[i];
        const std::string name = config.name();
        const Reconstruction aa = parseReconstruction(config.aa);
        pipeline.setSupersampling(parseSupersampling(config.ss));
        const Clock::time_point start = Clock::now();
        RendererResult result;
        result.name = name;
        result.renderer = config.renderer;
        result.aa = config.aa;
        result.ss = config.ss;
        result.timed = name != options.reference || referenceTimed;
        auto say = [&](const std::string& line) {
            if (!options.quiet)
                progress << "lfd-bench: " << packName << " " << profile.viewCount << "x" << profile.viewWidth << "x"
                         << profile.viewHeight << " [" << (i + 1) << "/" << order.size() << "] " << name << ": "
                         << line << std::endl;
        };
        std::unique_ptr<Renderer> renderer = createRenderer(config.renderer, options.rendererOptions);

        // Step 3: warm-up frames (shader compilation, buffer growth), then timed frames;
        // the warm-up replays the first timed frames' times and is timed separately.
        if (result.timed) {
            say("warm-up " + std::to_string(options.warmup) + " frame(s), then " +
                std::to_string(options.frames) + " timed frame(s)");
            GpuTimer warmTimer;
            for (uint32_t k = 0; k < options.warmup && !stopRequested(); ++k)
                pipeline.renderFrame(*renderer, double(k % options.frames) / options.fps, warmTimer, aa);
            warmTimer.finish();
            GpuTimer timer;
            for (uint32_t k = 0; k < options.frames && !stopRequested(); ++k)
                pipeline.renderFrame(*renderer, double(k) / options.fps, timer, aa);
            timer.finish();
            if (stopRequested()) {
                publish(results, true);
                return report;
            }
            result.stages = timer.stages();
            result.extra = renderer->extraStats();
            char line[128];
            std::snprintf(line, sizeof(line), "mean total %.2f ms", result.stageMean(std::string(stage::kTotal)));
            say(line);
        } else {
            say("reference only (not in --renderers): quality frame");
        }

        // Step 4: the quality frame, untimed, compared with the reference's (gstd's views
        // from the cache when it has them; the EIA is built from them as usual).
        GpuTimer qualityTimer;
        const bool cacheable = name == "gstd" && gstdCache; // (gstd, none, 1) only
        if (cacheable) {
            pipeline.animate(qualityTime);
            result.fromCache = gstdCache->load(gstdKey, pipeline.targets());
            if (result.fromCache) {
                pipeline.buildEia(qualityTimer, aa);
                say("quality frame from the gstd cache " + gstdCache->entryPath(gstdKey).string());
            }
        }
        if (!result.fromCache) {
            const Clock::time_point qualityStart = Clock::now();
            pipeline.renderFrame(*renderer, qualityTime, qualityTimer, aa);
            if (cacheable) {
                try {
                    gstdCache->store(gstdKey, pipeline.targets());
                } catch (const std::exception& e) {
                    progress << "lfd-bench: warning: gstd cache not written: " << e.what() << std::endl;
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
        if (!result.timed)
            result.extra = renderer->extraStats();
        gl::checkGlError("rendering with " + name);
        CapturedFrame frame = capture(pipeline);
        renderer.reset();

        // Through the lens: what an eye at the centre view position sees of this EIA.
        const double eyePosition = 0.5 * double(profile.viewCount);
        const Image lens{profile.viewWidth, profile.viewHeight, 4,
                         simulateViewer(profile, frame.eia.pixels, eyePosition)};
        if (i == 0) {
            // The reference against itself: identical.
            const Quality identical{0.0, std::numeric_limits<double>::infinity(), 1.0, 0.0};
            result.eia = result.centreView = result.allViews = result.lens = identical;
            reference = std::move(frame);
            referenceLens = lens;
        } else {
            result.lens = compare(lens, referenceLens);
            result.eia = compare(frame.eia, reference.eia);
            const size_t centre = frame.views.size() / 2;
            result.centreView = compare(frame.views[centre], reference.views[centre]);
            double mse = 0.0, ssim = 0.0;
            for (size_t v = 0; v < frame.views.size(); ++v) {
                const double e = rmse(frame.views[v], reference.views[v]);
                mse += e * e;
                ssim += ssimLuma(frame.views[v], reference.views[v]);
            }
            const double n = double(frame.views.size());
            result.allViews = {std::sqrt(mse / n), psnrFromRmse(std::sqrt(mse / n)), ssim / n,
                               std::numeric_limits<double>::quiet_NaN()};
            char line[200];
            std::snprintf(line, sizeof(line),
                          "vs %s: EIA RMSE %.2f SSIM %.4f FLIP %.4f, centre view RMSE %.2f SSIM %.4f FLIP %.4f",
                          options.reference.c_str(), result.eia.rmse, result.eia.ssim, result.eia.flip,
                          result.centreView.rmse, result.centreView.ssim, result.centreView.flip);
            say(line);
        }
        const CapturedFrame& kept = i == 0 ? reference : frame;
        if (images)
            (*images)[name] = {kept.eia.pixels, kept.views[kept.views.size() / 2].pixels};
        result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
        results.push_back(std::move(result));
        // Step 5: the report so far (the user's order, an untimed reference last).
        publish(results, false);
        if (options.onResult)
            options.onResult(report);
    }
    publish(results, false);
    return report;
}

} // namespace lfd::player
