// lfd-bench: times every renderer on one pack in one process and GL context (same views,
// same frames of the rotating scene), measures each one's quality against a reference
// renderer, and prints the speed-up and error table. See `lfd-bench --help` and
// docs/bench/lfd-bench.md.
#include "bench_matrix.h"
#include "bench_report.h"
#include "bench_runner.h"
#include "cli_support.h"
#include "frame_pipeline.h"
#include "gl_context.h"
#include "gl_debug_output.h"
#include "tool_flags.h"

#include "lfd/display_profile.h"
#include "lfd/pack.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <csignal>
#include <cstdlib>
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

// Ctrl-C / SIGTERM: finish nothing more, keep (and write) what finished.
std::atomic<bool> gStop{false};
extern "C" void onSignal(int) { gStop = true; }

// Raw flag values as CLI11 fills them (options bound straight into BenchOptions are not here).
struct BenchFlags {
    std::vector<std::string> packs;
    std::string renderers = "mvr,mvr-layered,lfdpr";
    bool variants = false;
    std::string gstdCache;
    bool noGstdCache = false;
    std::string outDir;
    lfd::player::SharedFlags shared; // the flags lfd-play takes too (--views, --aa, --ss as lists)
};

// What the validated flags add to BenchOptions: the view counts and an optional view size.
struct MatrixShape {
    std::vector<uint32_t> viewCounts;
    std::optional<std::pair<uint32_t, uint32_t>> size;
};

// Declares every lfd-bench flag, bound to `flags` or straight into `options`.
void addBenchFlags(CLI::App& app, BenchFlags& flags, lfd::player::BenchOptions& options)
{
    app.add_option("PACK", flags.packs, "packed scenes from lfd-bake (one matrix run per pack and view count)")
        ->required();
    // --renderer: lfd-play's name for it (a list of one is a list).
    app.add_option("--renderers,--renderer", flags.renderers, "comma-separated renderers to time")
        ->capture_default_str();
    app.add_flag("--lfdpr-variants", flags.variants,
                 "also time the paper's pipeline (lfdpr-paper) and lfdpr with each innovation "
                 "disabled (lfdpr-no-lfd-sampling, lfdpr-no-texture-splatting, lfdpr-no-pixel-culling, "
                 "lfdpr-no-margin-trim, lfdpr-no-cell-scaling, lfdpr-no-mv-mipmapping)");
    flags.shared.fps = options.fps;
    flags.shared.turntablePeriod = options.turntablePeriod;
    flags.shared.gstdFactor = options.rendererOptions.gstd.factor;
    flags.shared.frames = options.frames;
    flags.shared.lists = true;
    addSharedFlags(app, flags.shared);
    app.add_option("--warmup", options.warmup, "untimed frames before them")->capture_default_str();
    app.add_flag("!--sequential", options.interleave,
                 "time each renderer's frames in one block, one renderer after the other (default: the "
                 "renderers take turns frame by frame, so a machine whose speed drifts slows them alike)");
    app.add_option("--lens-positions", options.lensPositions,
                   "through-the-lens sweep: the simulated viewer at this many positions across the viewing cone, "
                   "each against the reference's (mean and worst reported)")
        ->check(CLI::Range(1u, 256u))
        ->capture_default_str();
    app.add_option("--quality-frame", options.qualityFrame, "frame whose views and EIA are compared")
        ->capture_default_str();
    app.add_option("--reference", options.reference,
                   "quality reference renderer (rendered untimed if not in --renderers; gstd is the "
                   "slow gold standard, mvr the fast raster baseline)")
        ->capture_default_str();
    app.add_option("--gstd-cache", flags.gstdCache,
                   "directory caching gstd's quality-frame views (default $XDG_CACHE_HOME/lfdpr/gstd, "
                   "else ~/.cache/lfdpr/gstd)");
    app.add_flag("--no-gstd-cache", flags.noGstdCache, "render gstd every time (neither read nor write the cache)");
    app.add_option("--out", flags.outDir,
                   "directory for results.csv/json, table.md, chart.png/svg (the matrix), and per run bench.json, "
                   "bench.csv, speed_vs_error.svg and PNGs (in DIR itself for one pack and view count, else in "
                   "DIR/<scene>-<N>v/)");
    app.add_flag("--quiet", options.quiet, "no progress lines");
}

// --renderers, --lfdpr-variants, --aa, --ss, --reference, --gstd-*: into `options`.
void validateRendererFlags(const BenchFlags& flags, lfd::player::BenchOptions& options)
{
    using namespace lfd::player;
    options.renderers = parseRendererList(flags.renderers);
    if (flags.variants)
        for (const std::string& v : lfdprVariantNames())
            if (std::find(options.renderers.begin(), options.renderers.end(), v) == options.renderers.end())
                options.renderers.push_back(v);
    if (!isKnownRenderer(options.reference))
        throw UsageError("--reference: unknown renderer '" + options.reference + "' (known: " +
                         joinNames(allRendererNames()) + ")");
    options.gstdCache = flags.gstdCache;
    options.gstdCacheEnabled = !flags.noGstdCache;
}

// The flags lfd-play takes too (tool_flags.h), typed, into `options` and `shape`.
void applyShared(const BenchFlags& flags, lfd::player::BenchOptions& options, MatrixShape& shape)
{
    lfd::player::SharedFlags shared = flags.shared;
    lfd::player::finishSharedFlags(shared);
    options.fps = shared.fps;
    // --no-turntable: a still scene, as --turntable-period 0 (also in the gstd cache key).
    options.turntablePeriod = shared.turntable ? shared.turntablePeriod : 0.0;
    options.frames = shared.frames;
    options.aa = shared.aa;
    options.ss = shared.ss;
    options.aniso = float(shared.aniso);
    options.lighting = lfd::player::frameLightingFromFlags(shared);
    options.environment = shared.environmentChoice;
    lfd::player::applySharedFlags(shared, options.rendererOptions);
    shape.size = shared.viewSize;
    shape.viewCounts = shared.viewCounts; // empty: the profile's count
}

// --out: not a file, and created now.
void prepareOutDir(const BenchFlags& flags, lfd::player::BenchOptions& options)
{
    options.outDir = flags.outDir;
    if (!options.outDir.empty() && std::filesystem::exists(options.outDir) &&
        !std::filesystem::is_directory(options.outDir))
        throw UsageError("--out: '" + flags.outDir + "' exists and is not a directory");
    if (!options.outDir.empty()) {
        // Created now so an unwritable place fails before minutes of rendering.
        std::error_code ec;
        std::filesystem::create_directories(options.outDir, ec);
        if (ec)
            throw UsageError("--out: cannot create '" + flags.outDir + "': " + ec.message());
    }
}

// Step 1: every flag checked (and --out created) before touching pack files or the GPU.
MatrixShape validateFlags(const BenchFlags& flags, lfd::player::BenchOptions& options)
{
    MatrixShape shape;
    applyShared(flags, options, shape);
    validateRendererFlags(flags, options);
    prepareOutDir(flags, options);
    return shape;
}

// Step 2: the display profile (filling in the default view count); every pack must exist.
lfd::DisplayProfile loadProfileAndCheckPacks(const BenchFlags& flags, MatrixShape& shape)
{
    const lfd::DisplayProfile baseProfile = flags.shared.displayProfile.empty()
                                                ? lfd::prototypeDisplayProfile()
                                                : lfd::loadDisplayProfile(flags.shared.displayProfile);
    if (shape.viewCounts.empty())
        shape.viewCounts.push_back(baseProfile.viewCount);
    for (const std::string& pack : flags.packs)
        if (!std::filesystem::is_regular_file(pack))
            throw UsageError(pack + ": no such pack file");
    return baseProfile;
}

// Step 3 (after the context exists): its features checked, described, and Ctrl-C hooked up.
void prepareContext(lfd::gl::GlContext& context, lfd::player::BenchOptions& options)
{
    const bool layered = std::find(options.renderers.begin(), options.renderers.end(), "mvr-layered") !=
                             options.renderers.end() ||
                         options.reference == "mvr-layered";
    context.require(layered);
    if (!options.quiet)
        std::cout << "lfd-bench: " << context.describeWithCodePaths() << std::endl;
    std::signal(SIGINT, onSignal);
    std::signal(SIGTERM, onSignal);
    options.shouldStop = [] { return gStop.load(); };
}

// One matrix run (one pack, one view count): benchmarked, its table printed, its files written.
lfd::player::BenchReport runOne(const lfd::player::BenchOptions& options, const lfd::DisplayProfile& profile,
                                lfd::Scene scene, uint32_t n, const std::vector<lfd::player::BenchReport>& reports,
                                bool single, const lfd::gl::GlContext& context)
{
    using namespace lfd::player;
    const size_t slot = reports.size();
    BenchOptions runOptions = options;
    if (!options.outDir.empty())
        runOptions.onResult = [&](const BenchReport& partial) {
            std::vector<BenchReport> all(reports.begin(), reports.begin() + long(slot));
            all.push_back(partial);
            writeMatrixTables(options.outDir, all);
        };
    std::map<std::string, FrameImages> images;
    BenchReport report = runBenchmark(runOptions, profile, std::move(scene), options.pack.filename().string(),
                                      context.describe(), std::cout, options.outDir.empty() ? nullptr : &images);
    std::cout << "\n" << benchTable(report) << std::flush;
    if (!options.outDir.empty()) {
        std::filesystem::path runDir = options.outDir;
        if (!single) {
            std::string stem = options.pack.stem().string();
            runDir /= stem + "-" + std::to_string(n) + "v";
        }
        const auto written = writeBenchOutputs(runDir, report, images);
        if (!options.quiet)
            std::cout << "lfd-bench: wrote " << written.size() << " files to " << runDir.string() << std::endl;
    }
    return report;
}

// Step 4: the matrix: per pack and view count one run of every configuration; the
// matrix files are rewritten after every finished configuration.
std::vector<lfd::player::BenchReport> runMatrix(lfd::player::BenchOptions& options,
                                                const lfd::DisplayProfile& baseProfile,
                                                const std::vector<std::string>& packs, const MatrixShape& shape,
                                                const lfd::gl::GlContext& context)
{
    const bool single = packs.size() == 1 && shape.viewCounts.size() == 1;
    std::vector<lfd::player::BenchReport> reports;
    const size_t runs = packs.size() * shape.viewCounts.size();
    for (const std::string& pack : packs) {
        for (const uint32_t n : shape.viewCounts) {
            if (gStop)
                break;
            const lfd::DisplayProfile profile =
                lfd::withViews(baseProfile, n, shape.size ? shape.size->first : baseProfile.viewWidth,
                               shape.size ? shape.size->second : baseProfile.viewHeight);
            options.pack = pack;
            lfd::Scene scene = lfd::readPack(options.pack);
            if (!options.quiet)
                std::cout << "lfd-bench: run " << (reports.size() + 1) << "/" << runs << ": " << pack << ", " << n
                          << " views" << std::endl;
            reports.push_back(runOne(options, profile, std::move(scene), n, reports, single, context));
        }
    }
    return reports;
}

// The matrix files (results.csv/json, table.md) once more with every run, and the chart.
void writeMatrixOutputs(const lfd::player::BenchOptions& options, const std::vector<lfd::player::BenchReport>& reports)
{
    if (options.outDir.empty())
        return;
    lfd::player::writeMatrixTables(options.outDir, reports);
    std::string why;
    if (lfd::player::drawMatrixChart(options.outDir, why)) {
        if (!options.quiet)
            std::cout << "lfd-bench: wrote results.csv, results.json, table.md, chart.png, chart.svg to "
                      << options.outDir.string() << std::endl;
    } else {
        std::cout << "lfd-bench: chart.png not drawn: " << why << "; results.csv, results.json and table.md are written"
                  << std::endl;
    }
}

} // namespace

int main(int argc, char** argv)
{
    using namespace lfd::player;
    BenchOptions options;
    CLI::App app{"lfd-bench: time renderers on a packed scene (.lfdpack) in one GL context and "
                 "compare their views and EIA with a reference renderer"};
    BenchFlags flags;
    addBenchFlags(app, flags, options);

    if (const auto exit = lfd::cli::parseCommandLine(app, argc, argv, "lfd-bench"))
        return *exit;

    return lfd::cli::runReportingErrors("lfd-bench", [&] {
        MatrixShape shape = validateFlags(flags, options);
        const lfd::DisplayProfile baseProfile = loadProfileAndCheckPacks(flags, shape);

        // Step 3: one GL context for every renderer and run.
        std::unique_ptr<lfd::gl::GlContext> context = lfd::gl::GlContext::createHeadless(flags.shared.glDebug);
        lfd::gl::GlErrorWatch glErrors("lfd-bench", flags.shared.glDebug); // messages printed as they arrive
        prepareContext(*context, options);

        const std::vector<BenchReport> reports = runMatrix(options, baseProfile, flags.packs, shape, *context);
        writeMatrixOutputs(options, reports);
        if (gStop) {
            std::cout << "lfd-bench: interrupted; kept the configurations that finished" << std::endl;
            return 130;
        }
        return 0;
    });
}
