#include "quilt_slideshow.h"

#include "frame_stages.h"

#include <algorithm>
#include <cmath>

namespace lfd::player {

QuiltSlideshow::QuiltSlideshow(const DisplayProfile& panel, std::vector<std::filesystem::path> files,
                               uint32_t viewCount, double slideSeconds, std::optional<QuiltName> layout)
    : panel_(panel), files_(std::move(files)), viewCount_(viewCount), slideSeconds_(slideSeconds),
      layout_(std::move(layout))
{
    if (files_.empty())
        throw QuiltInputError("no quilt to show");
    if (files_.size() == 1 && isVideoFile(files_.front())) {
        video_ = std::make_unique<QuiltVideoReader>(files_.front());
        showVideoFrame(0);
        return;
    }
    show(0); // fails early on a bad first quilt, and gives profile() a value
}

QuiltSlideshow::~QuiltSlideshow() = default;

uint32_t QuiltSlideshow::videoFrameCount() const { return video_ ? video_->frameCount() : 0; }

double QuiltSlideshow::videoFps() const { return video_ ? video_->framesPerSecond() : 0.0; }

void QuiltSlideshow::upload(const QuiltViews& views)
{
    const DisplayProfile next =
        withViews(panel_, uint32_t(views.views.size()), views.width, views.height);
    // Targets and EIA builder follow the layout; quilts of one layout reuse them.
    if (!targets_ || next.viewCount != profile_.viewCount || next.viewWidth != profile_.viewWidth ||
        next.viewHeight != profile_.viewHeight) {
        targets_ = std::make_unique<ViewTargets>(next.viewCount, next.viewWidth, next.viewHeight);
        eia_ = std::make_unique<EiaBuilder>(next);
    }
    profile_ = next;
    uploadViews(*targets_, views);
    loaded_ = true;
}

void QuiltSlideshow::show(size_t index)
{
    const double screenAspect = panel_.screenWidthMm / panel_.screenHeightMm;
    upload(loadQuiltViews(files_[index], quiltNameOf(files_[index], layout_), viewCount_, screenAspect));
    current_ = index;
}

void QuiltSlideshow::showVideoFrame(uint32_t frame)
{
    const double screenAspect = panel_.screenWidthMm / panel_.screenHeightMm;
    const QuiltName name = quiltNameOf(video_->file(), layout_);
    try {
        upload(extractQuiltViews(video_->frame(frame), name, viewCount_, screenAspect));
    } catch (const QuiltInputError& e) {
        throw QuiltInputError(video_->file().string() + ": " + e.what());
    }
    videoFrame_ = frame;
}

void QuiltSlideshow::renderFrame(double time, GpuTimer& timer, Reconstruction reconstruction)
{
    if (video_) {
        // note: the epsilon keeps frame k at exactly k / fps from rounding down to k - 1.
        const double position = std::floor(std::max(time, 0.0) * video_->framesPerSecond() + 1e-6);
        const uint32_t frame = uint32_t(std::fmod(position, double(video_->frameCount())));
        if (!loaded_ || frame != videoFrame_)
            showVideoFrame(frame);
    } else {
        const size_t slide =
            slideSeconds_ > 0.0 ? size_t(std::floor(std::max(time, 0.0) / slideSeconds_)) % files_.size() : 0;
        if (!loaded_ || slide != current_)
            show(slide);
    }
    timer.begin(stage::kTotal);
    eia_->build(*targets_, reconstruction, timer);
    timer.end();
}

FrameOutputs QuiltSlideshow::read(uint32_t frameIndex) const
{
    FrameOutputs out;
    out.frame = frameIndex;
    for (uint32_t i = 0; i < targets_->viewCount(); ++i)
        out.views.push_back(targets_->readView(i));
    out.eia = eia_->read();
    return out;
}

} // namespace lfd::player
