// lfd-bench: times every renderer on one pack in one process and GL context (same views,
// same frames of the rotating scene), measures each one's quality against a reference
// renderer, and prints the speed-up and error table. See `lfd-bench --help` and README.md
// ("Benchmarking: lfd-bench").
#include "bench_report.h"
#include "bench_runner.h"
#include "cli_support.h"
#include "gl_context.h"

#include "lfd/display_profile.h"
#include "lfd/pack.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

namespace {

using lfd::cli::UsageError;
using lfd::cli::joinNames;

// "mvr, lfdpr" -> {"mvr", "lfdpr"}: known names, no duplicates, order kept.
std::vector<std::string> parseRendererList(const std::string& text)
{
    const std::vector<std::string> names = lfd::cli::splitList(text);
    for (const std::string& item : names)
        if (!lfd::player::isKnownRenderer(item))
            throw UsageError("--renderers: unknown renderer '" + item + "' (known: " +
                             joinNames(lfd::player::allRendererNames()) + ")");
    if (names.empty())
        throw UsageError("--renderers: no renderer given");
    return names;
}

} // namespace

int main(int argc, char** argv)
{
    using namespace lfd::player;
    BenchOptions options;
    CLI::App app{"lfd-bench: time renderers on a packed scene (.lfdpack) in one GL context and "
                 "compare their views and EIA with a reference renderer"};
    std::string pack, renderers = "mvr,mvr-layered,lfdpr", viewSize, displayProfile;
    uint32_t views = 0;
    bool variants = false;
    app.add_option("PACK", pack, "packed scene from lfd-bake")->required();
    app.add_option("--renderers", renderers, "comma-separated renderers to time")->capture_default_str();
    app.add_flag("--lfdpr-variants", variants,
                 "also time the paper's pipeline (lfdpr-paper) and lfdpr with each innovation "
                 "disabled (lfdpr-no-lfd-sampling, lfdpr-no-texture-splatting, lfdpr-no-mv-mipmapping)");
    app.add_option("--display", displayProfile, "display profile JSON (default: the paper's prototype)");
    auto* viewsOpt = app.add_option("--views", views, "number of views (overrides the profile)");
    auto* sizeOpt = app.add_option("--view-size", viewSize, "view size WxH (overrides the profile)");
    app.add_option("--frames", options.frames, "timed frames per renderer")->capture_default_str();
    app.add_option("--warmup", options.warmup, "untimed frames before them")->capture_default_str();
    app.add_option("--fps", options.fps, "frame k is at time k / fps")->capture_default_str();
    app.add_option("--turntable-period", options.turntablePeriod, "seconds per turntable revolution (0 = still)")
        ->capture_default_str();
    app.add_option("--quality-frame", options.qualityFrame, "frame whose views and EIA are compared")
        ->capture_default_str();
    app.add_option("--reference", options.reference,
                   "quality reference renderer (rendered untimed if not in --renderers; gstd is the "
                   "slow gold standard, mvr the fast raster baseline)")
        ->capture_default_str();
    app.add_option("--gstd-factor", options.rendererOptions.gstd.factor,
                   "gstd: sub-views render at this many times the view resolution")
        ->capture_default_str();
    std::string gstdCache;
    bool noGstdCache = false;
    app.add_option("--gstd-cache", gstdCache,
                   "directory caching gstd's quality-frame views (default $XDG_CACHE_HOME/lfdpr/gstd, "
                   "else ~/.cache/lfdpr/gstd)");
    app.add_flag("--no-gstd-cache", noGstdCache, "render gstd every time (neither read nor write the cache)");
    std::string outDir;
    app.add_option("--out", outDir, "directory for bench.json, bench.csv, speed_vs_error.svg and PNGs");
    app.add_flag("--quiet", options.quiet, "no progress lines");

    if (const auto exit = lfd::cli::parseCommandLine(app, argc, argv, "lfd-bench"))
        return *exit;

    return lfd::cli::runReportingErrors("lfd-bench", [&] {
        // Step 1: validate flags before touching files or the GPU.
        options.pack = pack;
        options.renderers = parseRendererList(renderers);
        if (variants)
            for (const std::string& v : lfdprVariantNames())
                if (std::find(options.renderers.begin(), options.renderers.end(), v) == options.renderers.end())
                    options.renderers.push_back(v);
        if (!isKnownRenderer(options.reference))
            throw UsageError("--reference: unknown renderer '" + options.reference + "' (known: " +
                             joinNames(allRendererNames()) + ")");
        try {
            lfd::player::validateGstdOptions(options.rendererOptions.gstd);
        } catch (const std::exception& e) {
            throw UsageError(std::string("--gstd-factor: ") + e.what());
        }
        options.gstdCache = gstdCache;
        options.gstdCacheEnabled = !noGstdCache;
        if (options.frames == 0)
            throw UsageError("--frames: must be at least 1");
        if (!std::isfinite(options.fps) || options.fps <= 0.0)
            throw UsageError("--fps: must be a positive number");
        if (!std::isfinite(options.turntablePeriod) || options.turntablePeriod < 0.0)
            throw UsageError("--turntable-period: must be >= 0");
        if (*viewsOpt && (views == 0 || views > 2048))
            throw UsageError("--views: expected 1..2048, got " + std::to_string(views));
        std::optional<std::pair<uint32_t, uint32_t>> size;
        if (*sizeOpt)
            size = lfd::cli::parseSize("--view-size", viewSize);
        options.outDir = outDir;
        if (!options.outDir.empty() && std::filesystem::exists(options.outDir) &&
            !std::filesystem::is_directory(options.outDir))
            throw UsageError("--out: '" + outDir + "' exists and is not a directory");
        if (!options.outDir.empty()) {
            // Created now so an unwritable place fails before minutes of rendering.
            std::error_code ec;
            std::filesystem::create_directories(options.outDir, ec);
            if (ec)
                throw UsageError("--out: cannot create '" + outDir + "': " + ec.message());
        }

        // Step 2: the display profile with the overrides, then the pack.
        lfd::DisplayProfile profile = displayProfile.empty() ? lfd::prototypeDisplayProfile()
                                                             : lfd::loadDisplayProfile(displayProfile);
        profile = lfd::withViews(profile, *viewsOpt ? views : profile.viewCount,
                                 size ? size->first : profile.viewWidth, size ? size->second : profile.viewHeight);
        if (!std::filesystem::is_regular_file(options.pack))
            throw UsageError(pack + ": no such pack file");
        lfd::Scene scene = lfd::readPack(options.pack);

        // Step 3: one GL context for every renderer.
        std::unique_ptr<lfd::gl::GlContext> context = lfd::gl::GlContext::createHeadless();
        const bool layered = std::find(options.renderers.begin(), options.renderers.end(), "mvr-layered") !=
                                 options.renderers.end() ||
                             options.reference == "mvr-layered";
        context->require(layered);
        if (!options.quiet)
            std::cout << "lfd-bench: " << context->describeWithCodePaths() << std::endl;

        // Step 4: measure, then print and write.
        std::map<std::string, FrameImages> images;
        const BenchReport report =
            runBenchmark(options, profile, std::move(scene), options.pack.filename().string(),
                         context->describe(), std::cout, options.outDir.empty() ? nullptr : &images);
        std::cout << "\n" << benchTable(report) << std::flush;
        if (!options.outDir.empty()) {
            const auto written = writeBenchOutputs(options.outDir, report, images);
            if (!options.quiet)
                std::cout << "lfd-bench: wrote " << written.size() << " files to " << options.outDir.string()
                          << std::endl;
        }
        return 0;
    });
}
