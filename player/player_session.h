// One lfd-play run, independent of how it is shown: the options, the uploaded scene, the
// renderer, the view targets, the EIA builder and the GPU timer, and the per-frame step
// (animate -> N views -> EIA, bracketed by the "total" timer stage). Headless main() and
// the interactive window both drive a PlayerSession.
#pragma once

#include "eia_builder.h"
#include "frame.h"
#include "gpu_scene.h"
#include "gpu_timer.h"
#include "renderer.h"
#include "renderer_gstd.h"
#include "renderer_lfdpr.h"
#include "view_targets.h"

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
    std::string renderer = "mvr";
    LfdprOptions lfdpr;                    // --no-lfd-sampling etc. (renderer "lfdpr")
    GstdOptions gstd;                      // --gstd-factor (renderer "gstd")
    std::filesystem::path displayProfile;  // empty: the paper's prototype
    std::optional<uint32_t> views;         // overrides the profile
    std::optional<uint32_t> viewWidth, viewHeight;
    uint32_t frames = 1;                   // frames rendered (timing)
    std::optional<uint32_t> outputFrame;   // frame whose outputs are written (default: last)
    double fps = 60.0;                     // frame k is at time k / fps
    double turntablePeriod = 10.0;         // seconds per revolution, 0 = still
    std::string reconstruction = "none";
    std::filesystem::path eiaOut, quiltOut, viewsOut, statsOut, viewerOut, screenshot;
    double viewerPosition = -1.0;          // simulated viewer t in [0, N); < 0: centre
    uint32_t windowWidth = 1280, windowHeight = 800;
    std::string show = "eia";              // windowed: first output shown (eia|quilt|view|viewer)
    bool framesGiven = false;              // windowed: exit after `frames` frames
};

// The in-memory outputs of one frame (read back right after it was rendered).
struct FrameOutputs {
    uint32_t frame = 0;
    std::vector<std::vector<uint8_t>> views; // RGBA8, image order
    std::vector<uint8_t> eia;                // RGBA8, panel size, image order
};

class PlayerSession {
public:
    // Needs a current GL context. The profile carries the overrides already.
    PlayerSession(const PlayOptions& options, const DisplayProfile& profile, Scene scene,
                  std::string packName);

    const DisplayProfile& profile() const { return profile_; }
    const std::string& packName() const { return packName_; }
    Renderer& renderer() { return *renderer_; }
    void setRenderer(std::unique_ptr<Renderer> renderer) { renderer_ = std::move(renderer); }
    void setReconstruction(Reconstruction mode) { reconstruction_ = mode; }
    const GpuScene& scene() const { return *scene_; }
    const ViewTargets& targets() const { return *targets_; }
    const EiaBuilder& eia() const { return *eia_; }
    GpuTimer& timer() { return timer_; }
    const FrameSetup& lastFrame() const { return frame_; }

    // Animates to `time`, renders the views and the EIA (timed: view stages, "eia",
    // "total" around both).
    void renderFrame(double time);
    FrameOutputs readOutputs(uint32_t frameIndex) const;

private:
    PlayOptions options_;
    DisplayProfile profile_;
    std::string packName_;
    Framing framing_;
    std::unique_ptr<GpuScene> scene_;
    std::unique_ptr<Renderer> renderer_;
    std::unique_ptr<ViewTargets> targets_;
    std::unique_ptr<EiaBuilder> eia_;
    Reconstruction reconstruction_ = Reconstruction::None;
    GpuTimer timer_;
    FrameSetup frame_;
};

// Writes the requested files for one frame (EIA, quilt, views, simulated viewer); every
// file is written atomically and appended to `written` once complete, so a caller can
// remove them all if a later one fails.
void writeFrameOutputs(const PlayOptions& options, const DisplayProfile& profile,
                       const FrameOutputs& outputs, std::vector<std::filesystem::path>& written);

} // namespace lfd::player
