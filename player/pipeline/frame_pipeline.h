// One frame, written once: animate the scene to time t, render the N views with a
// renderer, build the EIA - timed as stage "total" around the renderer's stages and "eia"
// (frame_stages.h). lfd-play (headless and windowed, through PlayerSession) and lfd-bench
// both drive a FramePipeline, so what the bench times is exactly what the player runs.
// It owns what every renderer shares: the uploaded scene, the view targets and the EIA
// builder, created once so switching renderers (R key, bench) pays no upload.
#pragma once

#include "gl_handles.h"

#include "eia_builder.h"
#include "frame.h"
#include "gpu_scene.h"
#include "gpu_timer.h"
#include "renderer.h"
#include "view_targets.h"

#include "lfd/display_profile.h"
#include "lfd/framing.h"
#include "lfd/scene.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace lfd::player {

// Supersampling (paper section 4, `--ss`): the renderer draws more samples than the display
// has, averaged down (linear light, unweighted) to the display's views before the EIA.
//   None ("1"): the display's views;
//   Spatial2x ("2s"): the display's cameras at twice the view width and height;
//   Angular2x ("2v"): twice the views - view i's interval [i, i+1) / N of the cone gets two
//     cameras at random positions, one in each half, (i + (s + u) / 2) / N for s = 0, 1 and u
//     uniform in [0, 1) drawn per frame from the seed and the frame time (reproducible).
//     Point renderers sample the scene for the display's N views (FrameSetup::pointSampling),
//     so the point cloud does not grow; they only project it into more views.
enum class Supersampling : uint32_t { None = 0, Spatial2x = 1, Angular2x = 2 };
Supersampling parseSupersampling(const std::string& name); // "1" | "2s" | "2v"; throws invalid_argument
std::string supersamplingName(Supersampling ss);
std::vector<std::string> supersamplingNames(); // in enum order

inline constexpr uint64_t kSupersamplingSeed = 0x2f0a'7d1c'55aa'0002ull;

// The frame a renderer draws under `ss` (frame itself for None); see Supersampling.
FrameSetup supersampledFrame(const FrameSetup& frame, Supersampling ss, uint64_t seed = kSupersamplingSeed);
// A cheaper frame for interaction (the window's responsive preview): every `viewStep`-th
// view over the same cone (N / step cameras, each at the centre of `step` view intervals)
// at 1 / `sizeDivisor` of the view size; the EIA builder takes each subpixel's view from
// the coarser set and its view pixel under the subpixel (nearest), so the preview is
// upsampled into the same panel-size EIA.
struct PreviewShape {
    uint32_t viewStep = 2;
    uint32_t sizeDivisor = 2;
};
// The profile a preview frame renders: ceil(N / viewStep) views of
// max(1, w / sizeDivisor) x max(1, h / sizeDivisor).
DisplayProfile previewProfile(const DisplayProfile& full, const PreviewShape& shape);

// The in-memory outputs of one frame, read back right after it was rendered.
struct FrameOutputs {
    uint32_t frame = 0;
    std::vector<std::vector<uint8_t>> views; // RGBA8, image order, view 0 = leftmost camera
    std::vector<uint8_t> eia;                // RGBA8, panel size, image order
};

class FramePipeline {
public:
    // Needs a current GL context. The scene is framed as the baker assumed (its fill), so
    // pixel sizes agree with the pack; `turntablePeriod` seconds per revolution, 0 = still.
    FramePipeline(const DisplayProfile& profile, Scene scene, double turntablePeriod,
                  const GpuSceneOptions& sceneOptions = {});

    const DisplayProfile& profile() const { return profile_; }
    const Framing& framing() const { return framing_; }
    GpuScene& scene() { return *scene_; }
    const GpuScene& scene() const { return *scene_; }
    ViewTargets& targets() { return *targets_; }
    const ViewTargets& targets() const { return *targets_; }
    const EiaBuilder& eia() const { return *eia_; }
    const FrameSetup& lastFrame() const { return frame_; }

    // Supersampling of later frames (allocates the supersampled targets once per mode).
    void setSupersampling(Supersampling ss, uint64_t seed = kSupersamplingSeed);
    Supersampling supersampling() const { return ss_; }

    // Animates to `time`, renders the views with `renderer` (supersampled and averaged
    // down, stage "downsample", when set) and builds the EIA.
    void renderFrame(Renderer& renderer, double time, GpuTimer& timer,
                     Reconstruction reconstruction = Reconstruction::None);
    // renderFrame, then completeFrame.
    uint32_t renderCompleteFrame(Renderer& renderer, double time, GpuTimer& timer,
                                 Reconstruction reconstruction = Reconstruction::None);
    // Settles the renderer (Renderer::settle) after the frame at `time` (a preview frame if
    // `preview`): if that frame overflowed a buffer the renderer learns about only now, it
    // is rendered again, untimed, with the grown buffers, so the targets hold the whole
    // frame. Waits for the GPU: for frames whose outputs are read. Returns how many times
    // the frame was rendered again (0 almost always).
    uint32_t completeFrame(Renderer& renderer, double time, Reconstruction reconstruction = Reconstruction::None,
                           bool preview = false);
    // GPU memory of a frame: the view targets (and the supersampled ones), the EIA and what
    // the renderer holds for its frames (Renderer::frameGpuBytes), in bytes.
    uint64_t frameGpuBytes(const Renderer& renderer) const;
    // The two halves, for views that come from elsewhere (lfd-bench's gstd cache):
    // animate only, then interleave whatever the view targets hold.
    void animate(double time);
    void buildEia(GpuTimer& timer, Reconstruction reconstruction = Reconstruction::None);
    // The pose stage (skinned and morphed meshes at the animated time), inside "total";
    // nothing, not even the stage, for static scenes.
    void poseScene(GpuTimer& timer);

    // How later frames are lit (frame.h FrameLighting: exposure, tone mapping, the
    // environment's rotation; its lights are the scene's, evaluated per frame) and the
    // environment itself (null: the constant ambient term), kept alive by the pipeline.
    // The default: no environment, no tone mapping, the default light - the look before
    // image-based lighting; lfd-play and lfd-bench set their flags' choice.
    void setLighting(const FrameLighting& lighting, std::shared_ptr<const GpuEnvironment> environment);
    const FrameLighting& lighting() const { return lighting_; }
    const GpuEnvironment* environment() const { return environment_.get(); }

    // The viewer's camera controls (frame.h), applied from the next frame on.
    void setViewControls(const ViewControls& controls) { controls_ = controls; }
    const ViewControls& viewControls() const { return controls_; }

    // The same frame at preview quality into its own (smaller) view targets and EIA;
    // previewEia() holds the result. Its targets and EIA are made on first use.
    void setPreviewShape(const PreviewShape& shape);
    void renderPreviewFrame(Renderer& renderer, double time, GpuTimer& timer,
                            Reconstruction reconstruction = Reconstruction::None);
    const EiaBuilder& previewEia() const { return *previewEia_; }
    const ViewTargets& previewTargets() const { return *previewTargets_; }
    const DisplayProfile& previewProfileInUse() const { return previewProfile_; }

    FrameOutputs read(uint32_t frameIndex) const;

private:
    // The frame at `time` for `profile`: cameras, the scene's lights and the lighting.
    FrameSetup frameAt(const DisplayProfile& profile, double time) const;

    DisplayProfile profile_;
    Framing framing_;
    double turntablePeriod_;
    std::unique_ptr<GpuScene> scene_;
    std::unique_ptr<ViewTargets> targets_;
    std::unique_ptr<EiaBuilder> eia_;
    FrameSetup frame_;
    ViewControls controls_;
    FrameLighting lighting_;
    std::shared_ptr<const GpuEnvironment> environment_;
    PreviewShape previewShape_;
    DisplayProfile previewProfile_;
    std::unique_ptr<ViewTargets> previewTargets_;
    std::unique_ptr<EiaBuilder> previewEia_;
    Supersampling ss_ = Supersampling::None;
    uint64_t ssSeed_ = kSupersamplingSeed;
    std::unique_ptr<ViewTargets> ssTargets_; // the supersampled views
    gl::Program downsample_;                 // shaders/view_downsample.comp

public:
    ~FramePipeline();
    FramePipeline(const FramePipeline&) = delete;
    FramePipeline& operator=(const FramePipeline&) = delete;
};

} // namespace lfd::player
