// lfd-play: renders a packed scene (.lfdpack) as N light field views and the panel's EIA,
// headless (EGL) or in a window (GLFW). See `lfd-play --help`.
#include "cli_support.h"
#include "frame_stages.h"
#include "frame_stats.h"
#include "gl_context.h"
#include "player_session.h"
#include "window_app.h"

#include "lfd/display_profile.h"
#include "lfd/pack.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

namespace {

using lfd::cli::UsageError;
using lfd::cli::checkOutputPath;
using lfd::cli::parseSize;
using lfd::player::PlayOptions;

int runHeadless(const PlayOptions& options, const lfd::DisplayProfile& profile, lfd::Scene scene,
                const std::string& packName)
{
    using namespace lfd::player;
    std::unique_ptr<lfd::gl::GlContext> context = lfd::gl::GlContext::createHeadless();
    std::printf("lfd-play: %s\n", context->describeWithCodePaths().c_str());
    std::fflush(stdout);
    context->require(options.renderer == "mvr-layered");

    const uint64_t triangles = scene.triangleCount();
    const uint64_t drawnTriangles = scene.drawnTriangleCount();
    PlayerSession session(options, profile, std::move(scene), packName);

    // Render F frames of the rotating scene; read the outputs back right after frame K.
    const uint32_t outputFrame = options.outputFrame.value_or(options.frames - 1);
    const bool wantOutputs = !options.eiaOut.empty() || !options.quiltOut.empty() ||
                             !options.viewsOut.empty() || !options.viewerOut.empty();
    FrameOutputs outputs;
    for (uint32_t k = 0; k < options.frames; ++k) {
        session.renderFrame(double(k) / options.fps);
        if (k == outputFrame && wantOutputs)
            outputs = session.readOutputs(k);
    }
    session.timer().finish();
    const auto stages = session.timer().stages(); // timing frames only
    if (outputFrame >= options.frames && wantOutputs) {
        // Frame K after the timed frames: rendered once more, not counted in the stats.
        session.renderFrame(double(outputFrame) / options.fps);
        outputs = session.readOutputs(outputFrame);
        session.timer().finish();
    }

    // Outputs: each file atomic; if one fails, remove the others written by this run.
    std::vector<std::filesystem::path> written;
    try {
        if (wantOutputs)
            writeFrameOutputs(options, profile, outputs, written);
        if (!options.statsOut.empty()) {
            RunInfo info;
            info.renderer = session.renderer().name();
            info.gpu = context->caps().renderer + " / " + context->caps().version;
            info.profile = profile.name;
            info.pack = packName;
            info.reconstruction = options.reconstruction;
            info.supersampling = options.supersampling;
            info.views = profile.viewCount;
            info.viewWidth = profile.viewWidth;
            info.viewHeight = profile.viewHeight;
            info.frames = options.frames;
            info.panelWidth = profile.panelWidth;
            info.panelHeight = profile.panelHeight;
            info.viewBufferBytes = session.targets().bytes();
            info.sceneGpuBytes = session.scene().gpuBytes();
            info.triangles = triangles;
            info.drawnTriangles = drawnTriangles;
            info.extra = session.renderer().extraStats();
            writeStats(options.statsOut, info, stages);
            written.push_back(options.statsOut);
        }
    } catch (...) {
        for (const auto& path : written)
            std::filesystem::remove(path);
        throw;
    }

    std::string summary;
    // Pipeline order; a renderer's other stages (e.g. lfdpr's point_generation, resolve).
    for (const std::string_view stage : stage::kAll)
        if (auto it = stages.find(std::string(stage)); it != stages.end()) {
            char part[96];
            std::snprintf(part, sizeof(part), "%s%.*s %.2f ms", summary.empty() ? "" : ", ", int(stage.size()),
                          stage.data(), it->second.mean());
            summary += part;
        }
    for (const auto& [name, value] : session.renderer().extraStats())
        if (name == "points")
            summary += ", " + std::to_string(uint64_t(value)) + " points";
    std::printf("lfd-play: %s, %u views of %ux%u, %u frame(s), mean GPU time: %s\n",
                session.renderer().name().c_str(), profile.viewCount, profile.viewWidth,
                profile.viewHeight, options.frames, summary.c_str());
    return 0;
}

} // namespace

int main(int argc, char** argv)
{
    PlayOptions options;
    CLI::App app{"lfd-play: render a packed scene (.lfdpack) as light field views and the "
                 "panel's elemental image array (EIA)"};
    app.footer("Window keys: R renderer, C reconstruction, O output (EIA, quilt, single view, "
               "simulated viewer), space pause/resume, Left/Right move the viewer, Esc quit. "
               "Mouse: wheel moves the viewer, left click cycles the output.");
    std::string pack, viewSize, windowSize, renderers;
    for (const std::string& name : lfd::player::allRendererNames())
        renderers += (renderers.empty() ? "" : "|") + name;
    uint32_t views = 0, frame = 0;
    app.add_option("PACK", pack, "packed scene from lfd-bake")->required();
    app.add_flag("--headless", options.headless, "render without a window (EGL)");
    app.add_option("--renderer", options.renderer, "renderer: " + renderers)->capture_default_str();
    bool noLfdSampling = false, noTextureSplatting = false, noMvMipmapping = false;
    std::string atomics = "auto", pipeline = "visibility";
    app.add_flag("--no-lfd-sampling", noLfdSampling, "lfdpr: isotropic sampling at the finer density (iVIR)");
    app.add_flag("--no-texture-splatting", noTextureSplatting, "lfdpr: no density reduction by texture");
    app.add_flag("--no-mv-mipmapping", noMvMipmapping,
                 "lfdpr paper pipeline: texture values at LOD 0 (no multiview mipmapping)");
    app.add_option("--atomics", atomics, "lfdpr depth resolve: auto|64|32")->capture_default_str();
    app.add_option("--lfdpr-pipeline", pipeline,
                   "lfdpr: visibility (compute points, per-pixel shading) | paper (the paper's pipeline)")
        ->capture_default_str();
    app.add_option("--gstd-factor", options.rendererOptions.gstd.factor,
                   "gstd: sub-views render at this many times the view resolution (slow gold standard)")
        ->capture_default_str();
    app.add_option("--display", options.displayProfile, "display profile JSON (default: the paper's prototype)");
    auto* viewsOpt = app.add_option("--views", views, "number of views (overrides the profile)");
    auto* sizeOpt = app.add_option("--view-size", viewSize, "view size WxH (overrides the profile)");
    auto* framesOpt = app.add_option("--frames", options.frames, "frames to render (timing; windowed: exit after them)")
                          ->capture_default_str();
    auto* frameOpt = app.add_option("--frame", frame, "frame whose outputs are written (default: the last)");
    app.add_option("--fps", options.fps, "frame k is at time k / fps")->capture_default_str();
    app.add_option("--turntable-period", options.turntablePeriod, "seconds per turntable revolution (0 = still)")
        ->capture_default_str();
    app.add_option("--aa,--reconstruction", options.reconstruction,
                   "EIA reconstruction: none|spatial|view|view-spatial (Gaussian, 8 seeded samples)")
        ->capture_default_str();
    app.add_option("--ss", options.supersampling,
                   "supersampling: 1 | 2s (views at twice the resolution) | 2v (twice the views, random "
                   "angles in each view interval), averaged down")
        ->capture_default_str();
    app.add_option("--out", options.eiaOut, "EIA PNG (panel resolution)");
    app.add_option("--quilt", options.quiltOut, "quilt PNG (a _qsCxRaA suffix is added)");
    app.add_option("--views-out", options.viewsOut, "directory for view_000.png ... (view 0 = leftmost)");
    app.add_option("--stats", options.statsOut, "stats JSON (and a CSV beside it)");
    app.add_option("--viewer-out", options.viewerOut, "simulated viewer PNG");
    app.add_option("--viewer-pos", options.viewerPosition, "simulated viewer position in views [0, N) (default N/2)");
    app.add_option("--screenshot", options.screenshot, "windowed: save the window after the last frame and exit");
    app.add_option("--window-size", windowSize, "windowed: window size WxH (default 1280x800)");
    app.add_option("--show", options.show, "windowed: output shown first: eia|quilt|view|viewer")
        ->capture_default_str();

    if (const auto exit = lfd::cli::parseCommandLine(app, argc, argv, "lfd-play"))
        return *exit;

    return lfd::cli::runReportingErrors("lfd-play", [&] {
        // Step 1: validate flag values before touching files or the GPU.
        options.pack = pack;
        if (*viewsOpt) {
            if (views == 0 || views > 2048)
                throw UsageError("--views: expected 1..2048, got " + std::to_string(views));
            options.views = views;
        }
        if (*sizeOpt) {
            const auto [w, h] = parseSize("--view-size", viewSize);
            options.viewWidth = w;
            options.viewHeight = h;
        }
        if (!windowSize.empty())
            std::tie(options.windowWidth, options.windowHeight) = parseSize("--window-size", windowSize);
        if (options.frames == 0)
            throw UsageError("--frames: must be at least 1");
        options.framesGiven = bool(*framesOpt);
        if (*frameOpt)
            options.outputFrame = frame;
        if (!std::isfinite(options.fps) || options.fps <= 0.0)
            throw UsageError("--fps: must be a positive number");
        if (!std::isfinite(options.turntablePeriod) || options.turntablePeriod < 0.0)
            throw UsageError("--turntable-period: must be >= 0");
        if (options.show != "eia" && options.show != "quilt" && options.show != "view" && options.show != "viewer")
            throw UsageError("--show: expected eia, quilt, view or viewer, got '" + options.show + "'");
        lfd::player::LfdprOptions& lfdpr = options.rendererOptions.lfdpr;
        lfdpr.lfdBiasedSampling = !noLfdSampling;
        lfdpr.textureSplatting = !noTextureSplatting;
        lfdpr.multiviewMipmapping = !noMvMipmapping;
        try {
            lfdpr.atomics = lfd::player::parseLfdprAtomics(atomics);
            lfdpr.pipeline = lfd::player::parseLfdprPipeline(pipeline);
        } catch (const std::exception& e) {
            throw UsageError(e.what());
        }
        try {
            lfd::player::validateGstdOptions(options.rendererOptions.gstd);
        } catch (const std::exception& e) {
            throw UsageError(std::string("--gstd-factor: ") + e.what());
        }
        if (!lfd::player::isKnownRenderer(options.renderer))
            throw UsageError("--renderer: unknown renderer '" + options.renderer + "' (known: " + renderers + ")");
        try {
            lfd::player::parseReconstruction(options.reconstruction);
        } catch (const std::exception& e) {
            throw UsageError(std::string("--aa: ") + e.what());
        }
        try {
            lfd::player::parseSupersampling(options.supersampling);
        } catch (const std::exception& e) {
            throw UsageError(std::string("--ss: ") + e.what());
        }
        checkOutputPath("--out", options.eiaOut);
        checkOutputPath("--quilt", options.quiltOut);
        checkOutputPath("--stats", options.statsOut);
        checkOutputPath("--viewer-out", options.viewerOut);
        checkOutputPath("--screenshot", options.screenshot);
        if (!options.viewsOut.empty() && std::filesystem::exists(options.viewsOut) &&
            !std::filesystem::is_directory(options.viewsOut))
            throw UsageError("--views-out: '" + options.viewsOut.string() + "' is not a directory");

        // Step 2: the display profile with the command-line overrides.
        lfd::DisplayProfile profile = options.displayProfile.empty()
                                          ? lfd::prototypeDisplayProfile()
                                          : lfd::loadDisplayProfile(options.displayProfile);
        profile = lfd::withViews(profile, options.views.value_or(profile.viewCount),
                                 options.viewWidth.value_or(profile.viewWidth),
                                 options.viewHeight.value_or(profile.viewHeight));
        if (!options.viewerOut.empty() && options.viewerPosition >= double(profile.viewCount))
            throw UsageError("--viewer-pos: must be in [0, " + std::to_string(profile.viewCount) + ")");

        // Step 3: the pack (fully validated by readPack).
        if (!std::filesystem::is_regular_file(options.pack))
            throw UsageError(options.pack.string() + ": no such pack file");
        lfd::Scene scene = lfd::readPack(options.pack);
        const std::string packName = options.pack.filename().string();

        // Step 4: render.
        if (options.headless)
            return runHeadless(options, profile, std::move(scene), packName);
        return lfd::player::runWindowed(options, profile, std::move(scene), packName);
    });
}
