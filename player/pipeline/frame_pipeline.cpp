#include "frame_pipeline.h"

#include "frame_stages.h"

#include <algorithm>

namespace lfd::player {

FramePipeline::FramePipeline(const DisplayProfile& profile, const Scene& scene, double turntablePeriod)
    : profile_(profile), turntablePeriod_(turntablePeriod)
{
    const double fill = scene.settings.framingFill > 0.0f ? double(scene.settings.framingFill) : 1.0;
    framing_ = fitSceneToDisplay(profile_, scene.bounds, fill);
    scene_ = std::make_unique<GpuScene>(scene);
    targets_ = std::make_unique<ViewTargets>(profile_.viewCount, profile_.viewWidth, profile_.viewHeight);
    eia_ = std::make_unique<EiaBuilder>(profile_);
}

void FramePipeline::animate(double time)
{
    scene_->update(time);
    frame_ = makeFrameSetup(profile_, framing_, time, turntablePeriod_, controls_);
}

void FramePipeline::buildEia(GpuTimer& timer, Reconstruction reconstruction)
{
    eia_->build(*targets_, reconstruction, timer);
}

void FramePipeline::renderFrame(Renderer& renderer, double time, GpuTimer& timer, Reconstruction reconstruction)
{
    animate(time);
    timer.begin(stage::kTotal);
    renderer.render(*scene_, frame_, *targets_, timer);
    buildEia(timer, reconstruction);
    timer.end();
}

DisplayProfile previewProfile(const DisplayProfile& full, const PreviewShape& shape)
{
    const uint32_t step = std::max(shape.viewStep, 1u), divisor = std::max(shape.sizeDivisor, 1u);
    return withViews(full, (full.viewCount + step - 1) / step, std::max(full.viewWidth / divisor, 1u),
                     std::max(full.viewHeight / divisor, 1u));
}

void FramePipeline::setPreviewShape(const PreviewShape& shape)
{
    previewShape_ = shape;
    previewTargets_.reset();
    previewEia_.reset();
}

void FramePipeline::renderPreviewFrame(Renderer& renderer, double time, GpuTimer& timer, Reconstruction reconstruction)
{
    if (!previewTargets_) {
        previewProfile_ = previewProfile(profile_, previewShape_);
        previewTargets_ = std::make_unique<ViewTargets>(previewProfile_.viewCount, previewProfile_.viewWidth,
                                                        previewProfile_.viewHeight);
        previewEia_ = std::make_unique<EiaBuilder>(previewProfile_);
    }
    scene_->update(time);
    frame_ = makeFrameSetup(previewProfile_, framing_, time, turntablePeriod_, controls_);
    timer.begin(stage::kTotal);
    renderer.render(*scene_, frame_, *previewTargets_, timer);
    previewEia_->build(*previewTargets_, reconstruction, timer);
    timer.end();
}

FrameOutputs FramePipeline::read(uint32_t frameIndex) const
{
    FrameOutputs out;
    out.frame = frameIndex;
    out.views.reserve(targets_->viewCount());
    for (uint32_t i = 0; i < targets_->viewCount(); ++i)
        out.views.push_back(targets_->readView(i));
    out.eia = eia_->read();
    return out;
}

} // namespace lfd::player
