#include "player_session.h"

#include "image_output.h"
#include "quilt.h"
#include "simulated_viewer.h"

#include "lfd/framing.h"

#include <cstdio>

namespace lfd::player {

PlayerSession::PlayerSession(const PlayOptions& options, const DisplayProfile& profile, Scene scene,
                             std::string packName)
    : options_(options), profile_(profile), packName_(std::move(packName))
{
    // Framing as the baker assumed it (its fill), so pixel sizes agree with the pack.
    const double fill = scene.settings.framingFill > 0.0f ? double(scene.settings.framingFill) : 1.0;
    framing_ = fitSceneToDisplay(profile_, scene.bounds, fill);
    reconstruction_ = parseReconstruction(options.reconstruction);
    renderer_ = options.renderer == "lfdpr"  ? createLfdprRenderer(options.lfdpr)
                : options.renderer == "gstd" ? createGstdRenderer(options.gstd)
                                             : createRenderer(options.renderer);
    scene_ = std::make_unique<GpuScene>(scene);
    targets_ = std::make_unique<ViewTargets>(profile_.viewCount, profile_.viewWidth, profile_.viewHeight);
    eia_ = std::make_unique<EiaBuilder>(profile_);
}

void PlayerSession::renderFrame(double time)
{
    scene_->update(time);
    frame_ = makeFrameSetup(profile_, framing_, time, options_.turntablePeriod);
    timer_.begin("total");
    renderer_->render(*scene_, frame_, *targets_, timer_);
    eia_->build(*targets_, reconstruction_, timer_);
    timer_.end();
}

FrameOutputs PlayerSession::readOutputs(uint32_t frameIndex) const
{
    FrameOutputs out;
    out.frame = frameIndex;
    out.views.reserve(targets_->viewCount());
    for (uint32_t i = 0; i < targets_->viewCount(); ++i)
        out.views.push_back(targets_->readView(i));
    out.eia = eia_->read();
    return out;
}

void writeFrameOutputs(const PlayOptions& options, const DisplayProfile& profile,
                       const FrameOutputs& outputs, std::vector<std::filesystem::path>& written)
{
    if (!options.eiaOut.empty()) {
        writeImage(options.eiaOut, outputs.eia.data(), profile.panelWidth, profile.panelHeight, 4);
        written.push_back(options.eiaOut);
    }
    if (!options.quiltOut.empty()) {
        const QuiltLayout layout = chooseQuiltLayout(profile);
        const std::vector<uint8_t> quilt = assembleQuilt(layout, outputs.views);
        const std::filesystem::path path =
            quiltFileName(options.quiltOut, layout.cols, layout.rows, layout.aspect());
        writeImage(path, quilt.data(), layout.width(), layout.height(), 4);
        written.push_back(path);
    }
    if (!options.viewsOut.empty()) {
        std::filesystem::create_directories(options.viewsOut);
        for (size_t i = 0; i < outputs.views.size(); ++i) {
            char name[32];
            std::snprintf(name, sizeof(name), "view_%03zu.png", i);
            writeImage(options.viewsOut / name, outputs.views[i].data(), profile.viewWidth,
                       profile.viewHeight, 4);
            written.push_back(options.viewsOut / name);
        }
    }
    if (!options.viewerOut.empty()) {
        const double t = options.viewerPosition >= 0.0 ? options.viewerPosition : 0.5 * profile.viewCount;
        const std::vector<uint8_t> seen = simulateViewer(profile, outputs.eia, t);
        writeImage(options.viewerOut, seen.data(), profile.viewWidth, profile.viewHeight, 4);
        written.push_back(options.viewerOut);
    }
}

} // namespace lfd::player
