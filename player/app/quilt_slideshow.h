// lfd-play --quilt-in: quilts instead of a scene. One file, or a folder shown as a
// slideshow (file k at times [k S, (k + 1) S), S = --slide-seconds, looping). Each quilt's
// views are uploaded into view targets of its own layout and interleaved by an EIA builder
// for the panel with that many views, so they take the same path as rendered views.
#pragma once

#include "eia_builder.h"
#include "frame_pipeline.h"
#include "gpu_timer.h"
#include "view_targets.h"

#include "lfd/display_profile.h"

#include <filesystem>
#include <memory>
#include <vector>

namespace lfd::player {

class QuiltSlideshow {
public:
    // `panel`: the display profile (panel and lenticular mapping; its views are replaced
    // by each quilt's). `viewCount` 0: every tile of a quilt is a view.
    QuiltSlideshow(const DisplayProfile& panel, std::vector<std::filesystem::path> files, uint32_t viewCount,
                   double slideSeconds);

    // Shows the quilt of `time` (loading and uploading it when the slide changes) and
    // builds the EIA, timed as "eia" inside "total".
    void renderFrame(double time, GpuTimer& timer, Reconstruction reconstruction);

    const DisplayProfile& profile() const { return profile_; } // the current quilt's views
    const std::filesystem::path& currentFile() const { return files_[current_]; }
    size_t slideCount() const { return files_.size(); }
    const ViewTargets& targets() const { return *targets_; }
    const EiaBuilder& eia() const { return *eia_; }
    FrameOutputs read(uint32_t frameIndex) const;

private:
    void show(size_t index);

    DisplayProfile panel_, profile_;
    std::vector<std::filesystem::path> files_;
    uint32_t viewCount_;
    double slideSeconds_;
    size_t current_ = 0;
    bool loaded_ = false;
    std::unique_ptr<ViewTargets> targets_;
    std::unique_ptr<EiaBuilder> eia_;
};

} // namespace lfd::player
