// lfd-play --quilt-in: quilts instead of a scene. One file, a folder shown as a slideshow
// (file k at times [k S, (k + 1) S), S = --slide-seconds, looping), or a quilt video
// (frame k at times [k / fps, (k + 1) / fps) of the video's own rate, looping; decoded as
// it plays, quilt_video_reader.h). Each quilt's views are uploaded into view targets of
// its own layout and interleaved by an EIA builder for the panel with that many views, so
// they take the same path as rendered views.
#pragma once

#include "eia_builder.h"
#include "frame_pipeline.h"
#include "gpu_timer.h"
#include "quilt_input.h"
#include "quilt_video_reader.h"
#include "view_targets.h"

#include "lfd/display_profile.h"

#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

namespace lfd::player {

class QuiltSlideshow {
public:
    // `panel`: the display profile (panel and lenticular mapping; its views are replaced
    // by each quilt's). `viewCount` 0: every tile of a quilt is a view.
    // `layout`: --quilt-layout, read instead of the names' layout. One video file plays
    // as a video.
    QuiltSlideshow(const DisplayProfile& panel, std::vector<std::filesystem::path> files, uint32_t viewCount,
                   double slideSeconds, std::optional<QuiltName> layout = std::nullopt);
    ~QuiltSlideshow();

    // Shows the quilt of `time` (loading and uploading it when the slide changes) and
    // builds the EIA, timed as "eia" inside "total".
    void renderFrame(double time, GpuTimer& timer, Reconstruction reconstruction);

    const DisplayProfile& profile() const { return profile_; } // the current quilt's views
    // Video input: its frame count and rate, and the frame shown; 0 for images.
    uint32_t videoFrameCount() const;
    double videoFps() const;
    uint32_t videoFrame() const { return videoFrame_; }
    const std::filesystem::path& currentFile() const { return files_[current_]; }
    size_t slideCount() const { return files_.size(); }
    const ViewTargets& targets() const { return *targets_; }
    const EiaBuilder& eia() const { return *eia_; }
    FrameOutputs read(uint32_t frameIndex) const;

private:
    void show(size_t index);
    void showVideoFrame(uint32_t frame);
    void upload(const QuiltViews& views);

    DisplayProfile panel_, profile_;
    std::vector<std::filesystem::path> files_;
    uint32_t viewCount_;
    double slideSeconds_;
    std::optional<QuiltName> layout_;
    std::unique_ptr<QuiltVideoReader> video_;
    uint32_t videoFrame_ = 0;
    size_t current_ = 0;
    bool loaded_ = false;
    std::unique_ptr<ViewTargets> targets_;
    std::unique_ptr<EiaBuilder> eia_;
};

} // namespace lfd::player
