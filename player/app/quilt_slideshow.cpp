#include "quilt_slideshow.h"

#include "frame_stages.h"
#include "quilt_input.h"

#include <cmath>

namespace lfd::player {

QuiltSlideshow::QuiltSlideshow(const DisplayProfile& panel, std::vector<std::filesystem::path> files,
                               uint32_t viewCount, double slideSeconds)
    : panel_(panel), files_(std::move(files)), viewCount_(viewCount), slideSeconds_(slideSeconds)
{
    if (files_.empty())
        throw QuiltInputError("no quilt to show");
    show(0); // fails early on a bad first quilt, and gives profile() a value
}

void QuiltSlideshow::show(size_t index)
{
    const double screenAspect = panel_.screenWidthMm / panel_.screenHeightMm;
    const QuiltViews views = loadQuiltViews(files_[index], viewCount_, screenAspect);
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
    current_ = index;
    loaded_ = true;
}

void QuiltSlideshow::renderFrame(double time, GpuTimer& timer, Reconstruction reconstruction)
{
    const size_t slide =
        slideSeconds_ > 0.0 ? size_t(std::floor(std::max(time, 0.0) / slideSeconds_)) % files_.size() : 0;
    if (!loaded_ || slide != current_)
        show(slide);
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
