// One lfd-play run, independent of how it is shown: the options, the frame pipeline (scene,
// view targets, EIA builder; frame_pipeline.h), the renderer built through the registry
// from the user's options, and the GPU timers (one for full-quality frames, one for the
// window's responsive preview). With --quilt-in the views come from quilt files
// (QuiltSlideshow) instead of a scene and a renderer. Headless main() and the interactive
// window both drive a PlayerSession.
#pragma once

#include "environment_choice.h"
#include "frame_pipeline.h"
#include "gpu_timer.h"
#include "quilt.h"
#include "quilt_slideshow.h"
#include "renderer_registry.h"
#include "texture_streamer.h"

#include "lfd/display_profile.h"
#include "lfd/pack_mapped.h"
#include "lfd/scene.h"

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace lfd::player {

// off: always full quality; auto: preview frames while the user drags, zooms or presses a
// camera key, full quality once input stops (the window's default); always: every frame
// at preview quality (headless timing of the preview).
enum class PreviewMode { Off, Auto, Always };
PreviewMode parsePreviewMode(const std::string& name); // throws std::invalid_argument

enum class FrameQuality { Full, Preview };

struct PlayOptions {
    float aniso = 1.0f;                    // --aniso: the scene textures' max anisotropy
    // Lighting (docs/lighting.md): exposure, tone mapping, the environment's rotation, and
    // the environment itself (neutral | none | FILE.hdr). The defaults are the look before
    // image-based lighting; lfd-play's flags choose the neutral studio and PBR Neutral.
    FrameLighting lighting;
    lighting::EnvironmentChoice environment;
    std::filesystem::path pack;
    bool headless = false;
    std::string renderer = "mvr";          // any name of allRendererNames()
    RendererOptions rendererOptions;       // --atomics, --no-lfd-sampling, --gstd-factor etc.
    std::filesystem::path displayProfile;  // empty: the paper's prototype
    std::optional<uint32_t> views;         // overrides the profile
    std::optional<uint32_t> viewWidth, viewHeight;
    uint32_t frames = 1;                   // frames rendered (timing)
    std::optional<uint32_t> outputFrame;   // frame whose outputs are written (default: last)
    std::optional<uint32_t> firstFrame;    // --first-frame F: a pack's frames F .. F + frames - 1 (windowed: from F's time)
    double fps = 60.0;                     // frame k is at time k / fps
    double turntablePeriod = 10.0;         // seconds per revolution, 0 = still
    Reconstruction reconstruction = Reconstruction::None; // --aa: none|spatial|view|view-spatial
    Supersampling supersampling = Supersampling::None;    // --ss: 1|2s|2v
    std::filesystem::path eiaOut, quiltOut, viewsOut, statsOut, viewerOut, screenshot;
    std::filesystem::path quiltVideoOut;   // --quilt-video: every frame's quilt encoded by ffmpeg
    double viewerPosition = -1.0;          // simulated viewer t in [0, N); < 0: centre
    uint32_t windowWidth = 1280, windowHeight = 800;
    std::string show = "eia";              // windowed: first output shown (eia|quilt|view|viewer)
    bool framesGiven = false;              // windowed: exit after `frames` frames
    std::optional<bool> readout;           // windowed: on-screen readout at start (--readout / --no-readout);
                                           // unset: shown in a desktop window, not fullscreen
    bool glDebug = false;                  // --gl-debug: debug context, KHR_debug messages printed

    // Driving a display (docs/player/display.md).
    bool fullscreen = false;               // borderless fullscreen, EIA 1:1 on the monitor
    std::string monitor;                   // --monitor INDEX|NAME; empty: the one matching the panel
    bool allowMismatch = false;            // centre the EIA unscaled on a monitor of another size
    ViewControls controls;                 // --orbit, --zoom, --pan, --focal-depth, --depthiness, --no-turntable
    std::optional<PreviewMode> preview;    // unset: auto in the window, off headless
    PreviewShape previewShape;             // --preview-view-step, --preview-size-divisor
    double previewHoldSeconds = 0.3;       // preview lasts this long after the last input

    // Streaming (docs/player/streaming.md): map the pack and upload it in bounded chunks; the
    // window shows frames while finer mip levels arrive, headless runs wait until all is
    // resident before the first timed frame. false (--no-streaming): readPack, everything
    // uploaded before the first frame.
    bool streaming = true;
    std::optional<uint64_t> gpuMemoryBudgetMiB; // unset: what the driver reports free, else unlimited
    size_t streamChunkBytes = kDefaultStreamChunkBytes;

    // Quilt input (--quilt-in FILE|DIR) instead of a pack.
    std::filesystem::path quiltIn;
    uint32_t quiltViews = 0;               // 0: every tile is a view
    double slideSeconds = 5.0;             // per quilt of a folder
    std::optional<uint32_t> quiltFrame;    // --quilt-frame K: a quilt video's frame K only (headless)
    // --quilt-layout CxR[aASPECT]: the layout quilts are written with, and read with
    // instead of their names' (which need not carry one then).
    std::optional<QuiltName> quiltLayout;
};

class PlayerSession {
public:
    // Needs a current GL context. The profile carries the overrides already.
    PlayerSession(const PlayOptions& options, const DisplayProfile& profile, Scene scene,
                  std::string packName);
    // Streaming: the scene is uploaded from the mapping by streamer() (GpuScene built with
    // GpuSceneOptions::streamed); nothing is resident until the streamer runs.
    PlayerSession(const PlayOptions& options, const DisplayProfile& profile, std::shared_ptr<MappedPack> pack,
                  std::string packName);
    // Quilt input: the views come from the files (a slideshow when more than one).
    PlayerSession(const PlayOptions& options, const DisplayProfile& profile,
                  std::vector<std::filesystem::path> quilts);

    const PlayOptions& options() const { return options_; }
    bool quiltInput() const { return quilts_ != nullptr; }
    // The views the last frame showed: the profile's (a preview frame's fewer, smaller
    // ones; a quilt's own). The panel and lens mapping are always the display's.
    const DisplayProfile& profile() const;
    const DisplayProfile& displayProfile() const { return displayProfile_; }
    const std::string& packName() const { return packName_; }
    // Scene input only (quiltInput() false).
    Renderer& renderer() { return *renderer_; }
    const std::string& rendererName() const { return rendererName_; }
    // Rebuilds the renderer as `name` with the session's renderer options (the window's R
    // key); on failure the current renderer stays and the exception propagates. A no-op
    // for quilt input.
    void switchRenderer(const std::string& name);
    void setReconstruction(Reconstruction mode) { reconstruction_ = mode; }
    void setViewControls(const ViewControls& controls);
    const GpuScene& scene() const { return pipeline_->scene(); }
    const FramePipeline& pipeline() const { return *pipeline_; }
    const QuiltSlideshow& quilts() const { return *quilts_; }
    // The streamer of a streaming session, else null (already resident).
    TextureStreamer* streamer() { return streamer_.get(); }
    const GpuMemoryPlan& memoryPlan() const { return plan_; }
    // Of the last frame (full or preview).
    const ViewTargets& targets() const;
    const EiaBuilder& eia() const;
    GpuTimer& timer() { return timer_; }               // full-quality frames
    GpuTimer& previewTimer() { return previewTimer_; } // preview frames
    FrameQuality lastQuality() const { return lastQuality_; }
    const FrameSetup& lastFrame() const { return pipeline_->lastFrame(); }

    // The time of frame k: k / fps, the video's rate for a quilt video, else --fps.
    double frameTime(uint32_t k) const;

    // Animates to `time`, renders the views and the EIA (timed: view stages, "eia",
    // "total" around both) on timer() or, for a preview frame, previewTimer(). Quilt
    // input has no preview (nothing to render).
    void renderFrame(double time, FrameQuality quality = FrameQuality::Full);
    // A full-quality frame on a scratch timer, not counted in timer()'s statistics (the
    // headless first frame while a streamed scene is not yet resident).
    void renderUntimedFrame(double time);
    // Makes the last frame whole before its outputs are read: waits for the renderer's
    // account of the frames so far and renders the last one again, untimed, if it
    // overflowed a buffer (FramePipeline::completeFrame). Also brings the renderer's stats
    // to the last frame. Blocking; a no-op for quilt input.
    void completeLastFrame();
    FrameOutputs readOutputs(uint32_t frameIndex) const;

private:
    // Scene input: reconstruction, supersampling, camera controls, preview shape and the
    // renderer from the options (the same for an eagerly loaded and a streamed pack).
    void applyRenderOptions(const PlayOptions& options);
    PlayOptions options_;
    DisplayProfile displayProfile_;
    std::string packName_;
    GpuMemoryPlan plan_;
    std::unique_ptr<FramePipeline> pipeline_;
    std::shared_ptr<MappedPack> mapped_;
    std::unique_ptr<TextureStreamer> streamer_;
    std::unique_ptr<QuiltSlideshow> quilts_;
    std::string rendererName_;
    std::unique_ptr<Renderer> renderer_;
    Reconstruction reconstruction_ = Reconstruction::None;
    FrameQuality lastQuality_ = FrameQuality::Full;
    double lastTime_ = 0.0;
    GpuTimer timer_, previewTimer_;
};

// The GPU memory plan for `scene` under the options' budget (MiB; unset: the driver's
// available memory where reported) and GL_MAX_TEXTURE_SIZE; warnings go to stderr as
// "lfd-play: warning: ...". Needs a current GL context.
GpuMemoryPlan planSceneMemory(const PlayOptions& options, const Scene& scene, const std::string& packName);

// One stderr warning when the pack's tessellation bound was made for another display than
// `profile` (its BakeSettings), or for smaller views of the same display, so its edges may
// exceed the bound here (the same display's views no larger keep it: no warning).
void warnIfBakedForAnotherDisplay(const Scene& scene, const DisplayProfile& profile, const std::string& packName);

// The renderers the window's R key cycles through, starting after `current`: the methods
// (rendererNames()), gstd only when the window was started with it (seconds to minutes per
// frame), and `current` itself if it is a variant (e.g. lfdpr-paper).
std::vector<std::string> windowRendererCycle(const std::string& current);

// Writes the requested files for one frame (EIA, quilt, views, simulated viewer); every
// file is written atomically and appended to `written` once complete, so a caller can
// remove them all if a later one fails. The quilt goes to its single-frame name
// (quiltFileName); sequences are written frame by frame with writeQuiltFrame.
void writeFrameOutputs(const PlayOptions& options, const DisplayProfile& profile,
                       const FrameOutputs& outputs, std::vector<std::filesystem::path>& written);
// One frame's quilt of a sequence (--quilt with --frames N, or --quilt-video) as
// `base`'s numbered name; returns the path written.
std::filesystem::path writeQuiltFrame(const PlayOptions& options, const std::filesystem::path& base,
                                      const DisplayProfile& profile, const FrameOutputs& outputs, uint32_t frame);

// The quilt layout written and shown for `views`: the profile's (chooseQuiltLayout), or
// --quilt-layout's tiles and aspect. Throws UsageError-worthy std::invalid_argument when
// the views do not fit it.
QuiltLayout quiltLayoutFor(const PlayOptions& options, const DisplayProfile& views);

// --out with a printf frame number ("eia_%04d.png"): one EIA per rendered frame.
bool isFramePattern(const std::filesystem::path& path);
std::filesystem::path framePatternName(const std::filesystem::path& pattern, uint32_t frame);

} // namespace lfd::player
