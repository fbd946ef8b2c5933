// lfd-play: renders a packed scene (.lfdpack), or plays quilts made elsewhere, as N light
// field views and the panel's EIA, headless (EGL), in a window or fullscreen on the panel's
// monitor (GLFW). See `lfd-play --help` and docs/player/display.md.
#include "camera_controls.h"
#include "cli_support.h"
#include "frame_stages.h"
#include "frame_stats.h"
#include "gl_context.h"
#include "gl_debug_output.h"
#include "image_file.h"
#include "player_session.h"
#include "quilt.h"
#include "quilt_input.h"
#include "quilt_video.h"
#include "tool_flags.h"
#include "window_app.h"
#include "window_key_help.h"

#include "lfd/display_profile.h"
#include "lfd/pack.h"
#include "lfd/pack_mapped.h"

#include <CLI/CLI.hpp>
#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;
using lfd::cli::UsageError;
using lfd::cli::checkOutputPath;
using lfd::cli::parseSize;
using lfd::player::PlayOptions;

// The window's keys come from window_key_help.h, the table the on-screen key help shows.
std::string footer()
{
    return "Window keys and mouse: " + lfd::player::keyBindingsSentence() +
           "\nWhile the camera moves the window renders a preview (every 2nd view at half size, --preview-*) and "
           "returns to full quality when input stops.";
}

// Flag values parsed after CLI11 (sizes, pairs, names).
struct RawFlags {
    std::string pack, windowSize, orbit, pan, preview;
    std::string quiltLayout;           // --quilt-layout
    lfd::player::SharedFlags shared;   // the flags lfd-bench takes too (--views, --frames, --aa, ...)
    uint32_t frame = 0;
    bool listMonitors = false;
    CLI::Option* frameOpt = nullptr;
    CLI::Option *monitorOpt = nullptr, *windowSizeOpt = nullptr;
    bool readout = false, noReadout = false;
};

std::string rendererList()
{
    std::string renderers;
    for (const std::string& name : lfd::player::allRendererNames())
        renderers += (renderers.empty() ? "" : "|") + name;
    return renderers;
}

void addRenderFlags(CLI::App& app, PlayOptions& o, RawFlags& f)
{
    app.add_option("PACK", f.pack, "packed scene from lfd-bake (or --quilt-in instead)");
    app.add_flag("--headless", o.headless, "render without a window (EGL)");
    f.shared.frames = o.frames;
    addSharedFlags(app, f.shared);
    app.add_option("--renderer", o.renderer, "renderer: " + rendererList())->capture_default_str();
    f.frameOpt = app.add_option("--frame", f.frame, "frame whose outputs are written (default: the last)");
    app.add_option("--first-frame", o.firstFrame,
                   "the first frame rendered (frame k is at time k / fps): --frames N renders frames F .. F + N - 1, "
                   "numbered outputs and --frame keep the frames' own numbers; windowed, the animation starts at "
                   "F's time (default: 0)");
}

void addOutputFlags(CLI::App& app, PlayOptions& o)
{
    app.add_option("--out", o.eiaOut,
                   "EIA PNG (panel resolution); a name with %d or %04d (eia_%04d.png) writes every rendered "
                   "frame's EIA under its frame number");
    app.add_option("--quilt", o.quiltOut,
                   "quilt PNG (a _qsCxRaA suffix is added); with --frames N > 1 and no --frame: one numbered "
                   "quilt per frame (NAME_0000_qs...png)");
    app.add_option("--quilt-video", o.quiltVideoOut,
                   "headless only (--headless): every frame's quilt as a video (.mp4 H.264 or .webm VP9, via "
                   "ffmpeg; a _qs suffix is added)");
    app.add_option("--views-out", o.viewsOut, "directory for view_000.png ... (view 0 = leftmost)");
    app.add_option("--stats", o.statsOut, "stats JSON (and a CSV beside it)");
    app.add_flag("!--no-streaming", o.streaming,
                 "read the whole pack and upload everything before the first frame (default: map the pack and "
                 "stream it in bounded chunks; headless runs still wait until all is resident before timing)");
    app.add_option("--gpu-memory-budget", o.gpuMemoryBudgetMiB,
                   "GPU memory for the scene in MiB: geometry must fit, textures lose top mips to fit (default: "
                   "the driver's available memory where GL_NVX_gpu_memory_info / GL_ATI_meminfo report it, else "
                   "unlimited)");
    app.add_option("--viewer-out", o.viewerOut, "simulated viewer PNG");
    app.add_option("--viewer-pos", o.viewerPosition, "simulated viewer position in views [0, N) (default N/2)");
}

void addWindowFlags(CLI::App& app, PlayOptions& o, RawFlags& f)
{
    app.add_option("--screenshot", o.screenshot, "windowed: save the window after the last frame and exit");
    f.windowSizeOpt = app.add_option("--window-size", f.windowSize, "windowed: window size WxH (default 1280x800)");
    app.add_option("--show", o.show, "windowed: output shown first: eia|quilt|view|viewer")->capture_default_str();
    app.add_flag("--fullscreen", o.fullscreen,
                 "borderless fullscreen on the panel's monitor, the EIA pixel for pixel (vsync on)");
    f.monitorOpt = app.add_option("--monitor", o.monitor,
                                  "fullscreen monitor: INDEX or NAME (default: the one whose mode is the panel's)");
    app.add_flag("--allow-mismatch", o.allowMismatch,
                 "fullscreen on a monitor of another size: centre the EIA unscaled instead of refusing");
    app.add_flag("--readout", f.readout,
                 "windowed: start with the on-screen readout shown, also fullscreen (key I; default: shown in a "
                 "desktop window, not fullscreen on the panel)");
    app.add_flag("--no-readout", f.noReadout, "windowed: start with the on-screen readout hidden (key I)");
    app.add_flag("--list-monitors", f.listMonitors, "list the monitors and whether each matches the panel, then exit");
    app.add_option("--preview", f.preview,
                   "responsive preview: off|auto (while the camera moves; window default)|always (default headless: off)");
    app.add_option("--preview-view-step", o.previewShape.viewStep, "preview: every K-th view")->capture_default_str();
    app.add_option("--preview-size-divisor", o.previewShape.sizeDivisor, "preview: views at 1/D of the size")
        ->capture_default_str();
    app.add_option("--preview-hold", o.previewHoldSeconds, "preview: seconds after the last input")
        ->capture_default_str();
}

void addCameraFlags(CLI::App& app, PlayOptions& o, RawFlags& f)
{
    app.add_option("--orbit", f.orbit, "orbit YAW,PITCH in degrees (yaw: front turns right; pitch: front turns down)");
    app.add_option("--zoom", o.controls.zoom, "scene scale (2 = twice as large)")->capture_default_str();
    app.add_option("--pan", f.pan, "shift X,Y in mm along the screen (+x right, +y up)");
    app.add_option("--focal-depth", o.controls.focalDepthMm,
                   "depth in mm (+ toward the viewer, from the scene centre) shown at zero parallax")
        ->capture_default_str();
    app.add_option("--depthiness", o.controls.depthiness, "view-cone scale (0 flat, 1 the profile's cone)")
        ->capture_default_str();
}

void addQuiltInputFlags(CLI::App& app, PlayOptions& o, RawFlags& f)
{
    app.add_option("--quilt-in", o.quiltIn,
                   "play a quilt (FILE_qs{cols}x{rows}a{aspect}.png), a folder of them (slideshow) or a quilt video "
                   "(.mp4, .webm, .mkv, .mov, .m4v, .avi; at its own frame rate, looping) instead of a pack");
    app.add_option("--quilt-frame", o.quiltFrame, "headless, quilt video: render its frame K only (from 0)");
    app.add_option("--quilt-layout", f.quiltLayout,
                   "quilt layout CxR or CxRaASPECT (e.g. 8x6a0.75): written with --quilt / --quilt-video instead "
                   "of the profile's, and read with --quilt-in instead of the file name's");
    app.add_option("--quilt-views", o.quiltViews, "views in the quilt when its last tiles are empty (default: all)");
    app.add_option("--slide-seconds", o.slideSeconds, "seconds per quilt of a folder")->capture_default_str();
}

// Step 1: flag values, before touching files or the GPU.
void validateRenderFlags(PlayOptions& o, const RawFlags& f)
{
    lfd::player::SharedFlags shared = f.shared;
    lfd::player::finishSharedFlags(shared);
    if (!shared.viewCounts.empty())
        o.views = shared.viewCounts.front();
    if (shared.viewSize)
        std::tie(o.viewWidth, o.viewHeight) = *shared.viewSize;
    o.displayProfile = shared.displayProfile;
    o.fps = shared.fps;
    o.turntablePeriod = shared.turntablePeriod;
    o.glDebug = shared.glDebug;
    o.aniso = float(shared.aniso);
    o.lighting = lfd::player::frameLightingFromFlags(shared);
    o.environment = shared.environmentChoice;
    lfd::player::applySharedFlags(shared, o.rendererOptions);
    o.reconstruction = shared.aa.front(); // lfd-play takes one of each (finishSharedFlags)
    o.supersampling = shared.ss.front();
    o.frames = shared.frames;
    o.framesGiven = bool(*f.shared.framesOpt);
    o.controls.turntable = shared.turntable;
    if (*f.frameOpt)
        o.outputFrame = f.frame;
    if (!lfd::player::isKnownRenderer(o.renderer))
        throw UsageError("--renderer: unknown renderer '" + o.renderer + "' (known: " + rendererList() + ")");
}

void validateWindowFlags(PlayOptions& o, const RawFlags& f)
{
    if (!f.windowSize.empty())
        std::tie(o.windowWidth, o.windowHeight) = parseSize("--window-size", f.windowSize);
    if (o.show != "eia" && o.show != "quilt" && o.show != "view" && o.show != "viewer")
        throw UsageError("--show: expected eia, quilt, view or viewer, got '" + o.show + "'");
    if (o.fullscreen && o.headless)
        throw UsageError("--fullscreen: cannot be combined with --headless");
    if (o.fullscreen && *f.windowSizeOpt)
        throw UsageError("--window-size: a fullscreen window takes the monitor's size");
    if (f.readout && f.noReadout)
        throw UsageError("--readout: cannot be combined with --no-readout");
    if ((f.readout || f.noReadout) && o.headless)
        throw UsageError(std::string(f.readout ? "--readout" : "--no-readout") +
                         ": needs a window (headless images never carry the readout)");
    if (f.readout || f.noReadout)
        o.readout = f.readout;
    if ((*f.monitorOpt || o.allowMismatch) && !o.fullscreen)
        throw UsageError(std::string(*f.monitorOpt ? "--monitor" : "--allow-mismatch") + ": needs --fullscreen");
    if (!f.preview.empty()) {
        try {
            o.preview = lfd::player::parsePreviewMode(f.preview);
        } catch (const std::exception& e) {
            throw UsageError(std::string("--preview: ") + e.what());
        }
    }
    if (o.previewShape.viewStep == 0)
        throw UsageError("--preview-view-step: must be at least 1, got 0");
    if (o.previewShape.sizeDivisor == 0)
        throw UsageError("--preview-size-divisor: must be at least 1, got 0");
    if (!std::isfinite(o.previewHoldSeconds) || o.previewHoldSeconds < 0.0)
        throw UsageError("--preview-hold: must be >= 0 seconds, got " + lfd::cli::numberText(o.previewHoldSeconds));
}

void validateCameraFlags(PlayOptions& o, const RawFlags& f)
{
    auto pair = [](const char* flag, const std::string& text) {
        const auto value = lfd::player::parseNumberPair(text);
        if (!value)
            throw UsageError(std::string(flag) + ": expected two numbers A,B, got '" + text + "'");
        return *value;
    };
    if (!f.orbit.empty()) {
        const glm::dvec2 orbit = pair("--orbit", f.orbit);
        o.controls.yawDeg = orbit.x;
        o.controls.pitchDeg = orbit.y;
    }
    if (!f.pan.empty())
        o.controls.panMm = pair("--pan", f.pan);
}

void validateOutputFlags(PlayOptions& o)
{
    checkOutputPath("--out", o.eiaOut);
    checkOutputPath("--quilt", o.quiltOut);
    checkOutputPath("--stats", o.statsOut);
    checkOutputPath("--viewer-out", o.viewerOut);
    checkOutputPath("--screenshot", o.screenshot);
    checkOutputPath("--quilt-video", o.quiltVideoOut);
    // The image outputs' formats, checked before anything renders (an 8K frame takes
    // seconds, a --frames run many); --quilt as the name it is written under (with no
    // extension, .png).
    struct ImageOutput {
        const char* flag;
        fs::path given, written;
    };
    const ImageOutput images[] = {
        {"--out", o.eiaOut, o.eiaOut},
        {"--quilt", o.quiltOut, o.quiltOut.empty() ? fs::path() : lfd::player::quiltFileName(o.quiltOut, 1, 1, 1.0)},
        {"--viewer-out", o.viewerOut, o.viewerOut},
        {"--screenshot", o.screenshot, o.screenshot}};
    for (const ImageOutput& image : images)
        if (!image.written.empty())
            if (const std::string problem = lfd::metrics::imageFormatProblem(image.written); !problem.empty())
                throw UsageError(std::string(image.flag) + ": '" + image.given.string() + "': " + problem);
    if (!o.quiltVideoOut.empty()) {
        try {
            lfd::player::checkVideoExtension(o.quiltVideoOut);
        } catch (const std::exception& e) {
            throw UsageError(std::string("--quilt-video: ") + e.what());
        }
        if (!o.headless)
            throw UsageError("--quilt-video: needs --headless (a window shows the quilt with --show quilt)");
    }
    if (!o.eiaOut.empty() && o.eiaOut.filename().string().find('%') != std::string::npos &&
        !lfd::player::isFramePattern(o.eiaOut))
        throw UsageError("--out: a frame number pattern takes one %d (e.g. eia_%04d.png), got '" +
                         o.eiaOut.string() + "'");
    if (!o.viewsOut.empty() && fs::exists(o.viewsOut) && !fs::is_directory(o.viewsOut))
        throw UsageError("--views-out: '" + o.viewsOut.string() + "' is not a directory");
}

void validateInputFlags(PlayOptions& o, const RawFlags& f)
{
    o.pack = f.pack;
    if (f.listMonitors)
        return;
    if (o.quiltIn.empty() == o.pack.empty())
        throw UsageError(o.pack.empty() ? "PACK: give a pack file or --quilt-in (see --help)"
                                        : "--quilt-in: give either a pack or --quilt-in, not both");
    if (!f.quiltLayout.empty()) {
        try {
            o.quiltLayout = lfd::player::parseQuiltLayout(f.quiltLayout, "--quilt-layout");
        } catch (const std::exception& e) {
            throw UsageError(e.what());
        }
    }
    if (o.quiltFrame && (o.quiltIn.empty() || !o.headless))
        throw UsageError("--quilt-frame: needs --headless and a quilt video (--quilt-in)");
    if (o.firstFrame) {
        if (!o.quiltIn.empty())
            throw UsageError("--first-frame: needs a pack (a quilt video's frame: --quilt-frame)");
        if (*o.firstFrame > std::numeric_limits<uint32_t>::max() - o.frames)
            throw UsageError("--first-frame: " + std::to_string(*o.firstFrame) + " plus --frames " +
                             std::to_string(o.frames) + " is past the last frame number");
        if (o.outputFrame && *o.outputFrame < *o.firstFrame)
            throw UsageError("--frame: " + std::to_string(*o.outputFrame) + " is before --first-frame " +
                             std::to_string(*o.firstFrame));
    }
    if (!o.quiltIn.empty()) {
        if (*f.shared.viewsOpt || *f.shared.viewSizeOpt)
            throw UsageError(std::string(*f.shared.viewsOpt ? "--views" : "--view-size") +
                             ": the quilt's layout gives the views with --quilt-in");
        if (!std::isfinite(o.slideSeconds) || o.slideSeconds <= 0.0)
            throw UsageError("--slide-seconds: must be a positive number, got " +
                             lfd::cli::numberText(o.slideSeconds));
    }
}

// Step 2: the display profile with the command-line overrides.
lfd::DisplayProfile loadProfile(const PlayOptions& o)
{
    lfd::DisplayProfile profile =
        o.displayProfile.empty() ? lfd::prototypeDisplayProfile() : lfd::loadDisplayProfile(o.displayProfile);
    profile = lfd::withViews(profile, o.views.value_or(profile.viewCount), o.viewWidth.value_or(profile.viewWidth),
                             o.viewHeight.value_or(profile.viewHeight));
    if (!o.viewerOut.empty() && o.viewerPosition >= double(profile.viewCount))
        throw UsageError("--viewer-pos: must be in [0, " + std::to_string(profile.viewCount) + "), got " +
                         lfd::cli::numberText(o.viewerPosition));
    try {
        lfd::player::validateViewControls(o.controls, profile.viewConeDeg);
    } catch (const std::exception& e) {
        throw UsageError(e.what());
    }
    return profile;
}

// "view_generation 812.30 ms, eia 20.10 ms, total 832.50 ms" in pipeline order.
std::string stageSummary(const std::map<std::string, lfd::player::StageTimes>& stages)
{
    std::string summary;
    for (const std::string_view stage : lfd::player::stage::kAll)
        if (auto it = stages.find(std::string(stage)); it != stages.end()) {
            char part[96];
            std::snprintf(part, sizeof(part), "%s%.*s %.2f ms", summary.empty() ? "" : ", ", int(stage.size()),
                          stage.data(), it->second.mean());
            summary += part;
        }
    return summary;
}

// The numbered quilt sequence and video of a headless run: where the frames go, and
// whether they are kept (--quilt) or only feed the video (a temporary folder).
struct Sequence {
    bool active = false;
    fs::path base;       // quiltSequenceFileName's `requested`
    fs::path tempFolder; // set when only the video needs the frames
    std::vector<fs::path> frames;
    lfd::DisplayProfile profile; // of the frames written (a preview's views are fewer)
    double fps = 60.0;           // the video's rate: --fps, or a quilt video input's own
};

Sequence planSequence(const PlayOptions& o)
{
    Sequence s;
    const bool animatedQuilt = !o.quiltOut.empty() && o.frames > 1 && !o.outputFrame;
    s.active = animatedQuilt || !o.quiltVideoOut.empty();
    if (!s.active)
        return s;
    if (!o.quiltOut.empty()) {
        s.base = o.quiltOut;
        return s;
    }
    // Video only: frames in a temporary folder beside the video, removed afterwards.
    if (lfd::player::findOnPath("ffmpeg").empty())
        throw std::runtime_error("--quilt-video: ffmpeg is missing (not on PATH; install the Debian package "
                                 "'ffmpeg')");
    s.tempFolder = o.quiltVideoOut.parent_path() / (".lfd-quilt-frames-" + std::to_string(getpid()));
    fs::create_directories(s.tempFolder);
    s.base = s.tempFolder / "frame.png";
    return s;
}

// Encodes the sequence (numbered from `firstFrame`); a failure is reported but keeps the
// sequence (it is complete).
int encodeVideo(const PlayOptions& o, Sequence& s, uint32_t firstFrame)
{
    int status = 0;
    if (!o.quiltVideoOut.empty()) {
        const lfd::player::QuiltLayout layout = lfd::player::quiltLayoutFor(o, s.profile);
        const fs::path video = lfd::player::quiltFileName(o.quiltVideoOut, layout);
        try {
            lfd::player::encodeQuiltVideo(lfd::player::quiltSequencePattern(s.base, layout), s.fps, video, firstFrame);
            std::printf("lfd-play: quilt video %s (%zu frames)\n", video.string().c_str(), s.frames.size());
        } catch (const std::exception& e) {
            std::fprintf(stderr, "lfd-play: %s\n", lfd::cli::oneLine(e.what()).c_str());
            status = 1;
        }
    }
    if (!s.tempFolder.empty())
        fs::remove_all(s.tempFolder);
    return status;
}

lfd::player::RunInfo runInfo(lfd::player::PlayerSession& session, const PlayOptions& o, const lfd::gl::GlContext& c,
                             uint64_t triangles, uint64_t drawnTriangles)
{
    const lfd::DisplayProfile& profile = session.profile();
    lfd::player::RunInfo info;
    info.renderer = session.rendererName();
    info.gpu = c.caps().renderer + " / " + c.caps().version;
    info.profile = profile.name;
    info.pack = session.packName();
    info.reconstruction = lfd::player::reconstructionName(o.reconstruction);
    info.supersampling = lfd::player::supersamplingName(o.supersampling);
    info.views = profile.viewCount;
    info.viewWidth = profile.viewWidth;
    info.viewHeight = profile.viewHeight;
    info.frames = o.frames;
    info.panelWidth = profile.panelWidth;
    info.panelHeight = profile.panelHeight;
    info.viewBufferBytes = session.targets().bytes();
    info.sceneGpuBytes = session.quiltInput() ? 0 : session.scene().gpuBytes();
    info.textureAnisotropy = session.quiltInput() ? 1.0 : session.scene().maxAnisotropy();
    info.triangles = triangles;
    info.drawnTriangles = drawnTriangles;
    info.peakHostMemoryMiB = lfd::player::peakHostMemoryMiB();
    if (!session.quiltInput())
        info.extra = session.renderer().extraStats();
    return info;
}

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// The pack as read: the whole scene (--no-streaming) or its mapping (streaming).
struct PackInput {
    std::optional<lfd::Scene> scene;
    std::shared_ptr<lfd::MappedPack> mapped;
    Clock::time_point start; // before the pack was opened
    bool present() const { return scene || mapped; }
};

using StageMap = std::map<std::string, lfd::player::StageTimes>;

// One headless run's state, shared by its steps.
struct HeadlessRun {
    const PlayOptions& options;
    lfd::player::PlayerSession& session;
    lfd::gl::GlErrorWatch& glErrors;
    lfd::player::FrameQuality quality;
    Sequence sequence;
    PlayOptions single;      // the options of the one-frame outputs (no quilt for a sequence)
    bool wantOutputs = false, eiaSequence = false;
    uint32_t first = 0, frames = 1; // frames first .. first + frames - 1
    uint32_t outputFrame = 0;       // counted from `first`
    double firstFrameMs = -1.0, residentMs = -1.0; // loading figures (docs/player/streaming.md)
    lfd::player::FrameOutputs outputs;
    lfd::DisplayProfile outputProfile;
    std::vector<fs::path> written; // removed again if the run fails
    // --stats with --lfdpr-work-counters: each timed frame's work_* counters (the STEM.work.csv
    // of frame_stats.h). Reading them waits for the frame, once per frame, outside the GPU
    // timer's queries, so the stage times are still the GPU's.
    bool collectWork = false;
    std::vector<std::vector<std::pair<std::string, double>>> workPerFrame;
};

void collectFrameWork(HeadlessRun& run)
{
    run.session.completeLastFrame();
    std::vector<std::pair<std::string, double>> work;
    for (const auto& [name, value] : run.session.renderer().extraStats())
        if (name.rfind("work_", 0) == 0)
            work.emplace_back(name, value);
    run.workPerFrame.push_back(std::move(work));
}

// Streaming: one untimed frame as soon as the geometry and the coarsest mips are in (time
// to first frame), then everything is made resident before the timed frames, so no
// benchmark times a half-resident scene.
void measureLoading(HeadlessRun& run, const PackInput& input, const std::string& packName)
{
    if (!input.present())
        return;
    if (lfd::player::TextureStreamer* streamer = run.session.streamer()) {
        streamer->untilRenderable();
        run.session.renderUntimedFrame(0.0);
        run.firstFrameMs = msSince(input.start);
        streamer->untilResident();
    }
    glFinish();
    run.residentMs = msSince(input.start);
    run.glErrors.check("the streamed upload of " + packName);
}

void readOutputs(HeadlessRun& run, uint32_t frame)
{
    run.session.completeLastFrame();
    run.outputs = run.session.readOutputs(frame);
    run.outputProfile = run.session.profile();
}

// Every rendered frame's EIA under its number (--out eia_%04d.png).
void writeEiaFrame(HeadlessRun& run, uint32_t frame)
{
    const fs::path path = lfd::player::framePatternName(run.options.eiaOut, frame);
    const lfd::DisplayProfile& panel = run.session.displayProfile();
    run.session.completeLastFrame();
    lfd::metrics::writeImage(path, run.session.readOutputs(frame).eia.data(), panel.panelWidth, panel.panelHeight, 4);
    run.written.push_back(path);
}

// Renders F frames (from frame `first`: --quilt-frame), reads the outputs back right after
// frame K (K after the timed frames: rendered once more, not counted in the stats); a
// sequence keeps every quilt, a frame pattern every EIA. Returns the timed frames' stages.
StageMap renderFrames(HeadlessRun& run, lfd::player::GpuTimer& timer, const PackInput& input)
{
    for (uint32_t k = 0; k < run.frames; ++k) {
        const uint32_t frame = run.first + k;
        run.session.renderFrame(run.session.frameTime(frame), run.quality);
        run.glErrors.check("frame " + std::to_string(frame));
        if (run.collectWork)
            collectFrameWork(run);
        if (k == 0 && run.firstFrameMs < 0.0 && input.present()) {
            glFinish();
            run.firstFrameMs = msSince(input.start);
        }
        if (k == run.outputFrame && run.wantOutputs)
            readOutputs(run, frame);
        if (run.eiaSequence)
            writeEiaFrame(run, frame);
        if (run.sequence.active) {
            Sequence& sequence = run.sequence;
            run.session.completeLastFrame();
            sequence.profile = run.session.profile();
            sequence.frames.push_back(
                writeQuiltFrame(run.options, sequence.base, sequence.profile, run.session.readOutputs(frame), frame));
            if (sequence.tempFolder.empty())
                run.written.push_back(sequence.frames.back());
        }
    }
    timer.finish();
    run.session.completeLastFrame(); // the renderer's stats of the last frame
    StageMap stages = timer.stages();
    if (run.outputFrame >= run.frames && run.wantOutputs) {
        run.session.renderFrame(run.session.frameTime(run.first + run.outputFrame), run.quality);
        readOutputs(run, run.first + run.outputFrame);
        timer.finish();
    }
    return stages;
}

// Which frames a headless run renders: --frames N from 0; a quilt video without --frames
// all of its frames, with --quilt-frame K frame K only. Throws UsageError for a frame the
// video does not have.
void planFrames(HeadlessRun& run)
{
    const PlayOptions& options = run.options;
    const uint32_t videoFrames = run.session.quiltInput() ? run.session.quilts().videoFrameCount() : 0;
    run.frames = options.frames;
    if (options.quiltFrame) {
        if (videoFrames == 0)
            throw UsageError("--quilt-frame: " + options.quiltIn.string() + " is not a quilt video");
        if (*options.quiltFrame >= videoFrames)
            throw UsageError("--quilt-frame: " + options.quiltIn.string() + " has " + std::to_string(videoFrames) +
                             " frames (0.." + std::to_string(videoFrames - 1) + "), got " +
                             std::to_string(*options.quiltFrame));
        run.first = *options.quiltFrame;
    } else if (videoFrames > 0 && !options.framesGiven) {
        run.frames = videoFrames;
    } else if (options.firstFrame) {
        run.first = *options.firstFrame;
    }
    // --frame K names a frame by its number with --first-frame (validateInputFlags: K >= F);
    // with --quilt-frame it counts from the video frame rendered.
    run.outputFrame = options.firstFrame && options.outputFrame ? *options.outputFrame - run.first
                                                                : options.outputFrame.value_or(run.frames - 1);
}

void printSummary(const HeadlessRun& run, const StageMap& stages)
{
    std::string summary = stageSummary(stages);
    if (!run.session.quiltInput())
        for (const auto& [name, value] : run.session.renderer().extraStats())
            if (name == "points")
                summary += ", " + std::to_string(uint64_t(value)) + " points";
    const lfd::DisplayProfile& shown = run.session.profile();
    std::printf("lfd-play: %s%s, %u views of %ux%u, %u frame(s), mean GPU time: %s\n",
                run.session.rendererName().c_str(), run.quality == lfd::player::FrameQuality::Preview ? " (preview)" : "",
                shown.viewCount, shown.viewWidth, shown.viewHeight, run.frames, summary.c_str());
    if (run.written.empty() && !run.sequence.active)
        std::printf("lfd-play: no output written (timing only; --out, --quilt, --quilt-video, --views-out, "
                    "--viewer-out and --stats write files)\n");
}

lfd::player::PlayerSession openSession(const PlayOptions& options, const lfd::DisplayProfile& profile,
                                       PackInput& input, std::vector<fs::path> quilts)
{
    using lfd::player::PlayerSession;
    const std::string packName = options.pack.filename().string();
    if (input.mapped)
        return PlayerSession(options, profile, input.mapped, packName);
    if (input.scene)
        return PlayerSession(options, profile, std::move(*input.scene), packName);
    return PlayerSession(options, profile, std::move(quilts));
}

int runHeadless(const PlayOptions& options, const lfd::DisplayProfile& profile, PackInput input,
                std::vector<fs::path> quilts)
{
    using namespace lfd::player;
    std::unique_ptr<lfd::gl::GlContext> context = lfd::gl::GlContext::createHeadless(options.glDebug);
    std::printf("lfd-play: %s\n", context->describeWithCodePaths().c_str());
    std::fflush(stdout);
    context->require(options.renderer == "mvr-layered" && input.present());
    lfd::gl::GlErrorWatch glErrors("lfd-play", options.glDebug);

    const lfd::Scene* cpuScene = input.mapped ? &input.mapped->scene() : input.scene ? &*input.scene : nullptr;
    const uint64_t triangles = cpuScene ? cpuScene->triangleCount() : 0;
    const uint64_t drawnTriangles = cpuScene ? cpuScene->drawnTriangleCount() : 0;
    const std::string packName = options.pack.filename().string();
    PlayerSession session = openSession(options, profile, input, std::move(quilts));
    glErrors.check("the upload of " + (input.present() ? packName : std::string("the quilts")));

    HeadlessRun run{options, session, glErrors,
                    options.preview == PreviewMode::Always ? FrameQuality::Preview : FrameQuality::Full,
                    planSequence(options), options};
    measureLoading(run, input, packName);
    GpuTimer& timer = run.quality == FrameQuality::Preview ? session.previewTimer() : session.timer();
    planFrames(run);
    run.sequence.fps = 1.0 / session.frameTime(1);
    if (run.sequence.active)
        run.single.quiltOut.clear();
    run.eiaSequence = !options.eiaOut.empty() && isFramePattern(options.eiaOut);
    if (run.eiaSequence)
        run.single.eiaOut.clear();
    run.wantOutputs = !run.single.eiaOut.empty() || !run.single.quiltOut.empty() || !run.single.viewsOut.empty() ||
                      !run.single.viewerOut.empty();
    run.outputProfile = profile;
    run.collectWork = !options.statsOut.empty() && options.rendererOptions.lfdpr.countWork && !session.quiltInput();
    try {
        const StageMap stages = renderFrames(run, timer, input);
        // Outputs: each file atomic; if one fails, remove the others written by this run.
        if (run.wantOutputs)
            writeFrameOutputs(run.single, run.outputProfile, run.outputs, run.written);
        if (!options.statsOut.empty()) {
            RunInfo info = runInfo(session, options, *context, triangles, drawnTriangles);
            info.streaming = input.mapped != nullptr;
            info.timeToFirstFrameMs = run.firstFrameMs;
            info.timeToResidentMs = run.residentMs;
            info.frames = run.frames; // a quilt video's own frame count when --frames was not given
            info.workPerFrame = std::move(run.workPerFrame);
            writeStats(options.statsOut, info, stages);
            run.written.push_back(options.statsOut);
        }
        printSummary(run, stages);
    } catch (...) {
        for (const auto& path : run.written)
            fs::remove(path);
        if (!run.sequence.tempFolder.empty())
            fs::remove_all(run.sequence.tempFolder);
        throw;
    }
    return encodeVideo(options, run.sequence, run.first); // the sequence is numbered by frame
}

} // namespace

int main(int argc, char** argv)
{
    PlayOptions options;
    RawFlags flags;
    CLI::App app{"lfd-play: render a packed scene (.lfdpack), or play quilts, as light field views and the "
                 "panel's elemental image array (EIA)"};
    app.footer(footer());
    addRenderFlags(app, options, flags);
    addOutputFlags(app, options);
    addWindowFlags(app, options, flags);
    addCameraFlags(app, options, flags);
    addQuiltInputFlags(app, options, flags);

    if (const auto exit = lfd::cli::parseCommandLine(app, argc, argv, "lfd-play"))
        return *exit;

    return lfd::cli::runReportingErrors("lfd-play", [&] {
        // Step 1: validate flag values before touching files or the GPU.
        validateRenderFlags(options, flags);
        validateWindowFlags(options, flags);
        validateCameraFlags(options, flags);
        validateOutputFlags(options);
        validateInputFlags(options, flags);

        // Step 2: the display profile with the command-line overrides.
        const lfd::DisplayProfile profile = loadProfile(options);
        if (flags.listMonitors)
            return lfd::player::listMonitorsCommand(profile);

        // Step 3: the input - the pack (fully validated by readPack, or mapped with its texels
        // verified as they stream) or the quilt files.
        PackInput input;
        std::vector<fs::path> quilts;
        if (!options.quiltIn.empty()) {
            try {
                quilts = lfd::player::listQuiltFiles(options.quiltIn, options.quiltLayout.has_value());
            } catch (const lfd::player::QuiltInputError& e) {
                throw UsageError(e.what()); // like a missing pack: the user names another file
            }
        } else {
            if (!fs::is_regular_file(options.pack))
                throw UsageError(options.pack.string() + ": no such pack file");
            input.start = Clock::now();
            if (options.streaming)
                input.mapped = std::make_shared<lfd::MappedPack>(options.pack);
            else
                input.scene = lfd::readPack(options.pack);
        }

        // Step 4: render.
        if (options.headless)
            return runHeadless(options, profile, std::move(input), std::move(quilts));
        if (input.mapped)
            return lfd::player::runWindowedStreamed(options, profile, input.mapped, options.pack.filename().string());
        if (input.scene)
            return lfd::player::runWindowed(options, profile, std::move(*input.scene),
                                            options.pack.filename().string());
        return lfd::player::runWindowedQuilts(options, profile, std::move(quilts));
    });
}
