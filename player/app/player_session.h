// One lfd-play run, independent of how it is shown: the options, the frame pipeline (scene,
// view targets, EIA builder; frame_pipeline.h), the renderer built through the registry
// from the user's options, and the GPU timer. Headless main() and the interactive window
// both drive a PlayerSession.
#pragma once

#include "frame_pipeline.h"
#include "gpu_timer.h"
#include "renderer_registry.h"

#include "lfd/display_profile.h"
#include "lfd/scene.h"

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace lfd::player {

struct PlayOptions {
    std::filesystem::path pack;
    bool headless = false;
    std::string renderer = "mvr";          // any name of allRendererNames()
    RendererOptions rendererOptions;       // --atomics, --no-lfd-sampling, --gstd-factor etc.
    std::filesystem::path displayProfile;  // empty: the paper's prototype
    std::optional<uint32_t> views;         // overrides the profile
    std::optional<uint32_t> viewWidth, viewHeight;
    uint32_t frames = 1;                   // frames rendered (timing)
    std::optional<uint32_t> outputFrame;   // frame whose outputs are written (default: last)
    double fps = 60.0;                     // frame k is at time k / fps
    double turntablePeriod = 10.0;         // seconds per revolution, 0 = still
    std::string reconstruction = "none";   // --aa: none|spatial|view|view-spatial
    std::string supersampling = "1";       // --ss: 1|2s|2v
    std::filesystem::path eiaOut, quiltOut, viewsOut, statsOut, viewerOut, screenshot;
    double viewerPosition = -1.0;          // simulated viewer t in [0, N); < 0: centre
    uint32_t windowWidth = 1280, windowHeight = 800;
    std::string show = "eia";              // windowed: first output shown (eia|quilt|view|viewer)
    bool framesGiven = false;              // windowed: exit after `frames` frames
};

class PlayerSession {
public:
    // Needs a current GL context. The profile carries the overrides already.
    PlayerSession(const PlayOptions& options, const DisplayProfile& profile, Scene scene,
                  std::string packName);

    const PlayOptions& options() const { return options_; }
    const DisplayProfile& profile() const { return pipeline_.profile(); }
    const std::string& packName() const { return packName_; }
    Renderer& renderer() { return *renderer_; }
    const std::string& rendererName() const { return rendererName_; }
    // Rebuilds the renderer as `name` with the session's renderer options (the window's R
    // key); on failure the current renderer stays and the exception propagates.
    void switchRenderer(const std::string& name);
    void setReconstruction(Reconstruction mode) { reconstruction_ = mode; }
    const GpuScene& scene() const { return pipeline_.scene(); }
    const ViewTargets& targets() const { return pipeline_.targets(); }
    const EiaBuilder& eia() const { return pipeline_.eia(); }
    GpuTimer& timer() { return timer_; }
    const FrameSetup& lastFrame() const { return pipeline_.lastFrame(); }

    // Animates to `time`, renders the views and the EIA (timed: view stages, "eia",
    // "total" around both).
    void renderFrame(double time);
    FrameOutputs readOutputs(uint32_t frameIndex) const;

private:
    PlayOptions options_;
    std::string packName_;
    FramePipeline pipeline_;
    std::string rendererName_;
    std::unique_ptr<Renderer> renderer_;
    Reconstruction reconstruction_ = Reconstruction::None;
    GpuTimer timer_;
};

// The renderers the window's R key cycles through, starting after `current`: the methods
// (rendererNames()), gstd only when the window was started with it (seconds to minutes per
// frame), and `current` itself if it is a variant (e.g. lfdpr-paper).
std::vector<std::string> windowRendererCycle(const std::string& current);

// Writes the requested files for one frame (EIA, quilt, views, simulated viewer); every
// file is written atomically and appended to `written` once complete, so a caller can
// remove them all if a later one fails.
void writeFrameOutputs(const PlayOptions& options, const DisplayProfile& profile,
                       const FrameOutputs& outputs, std::vector<std::filesystem::path>& written);

} // namespace lfd::player
