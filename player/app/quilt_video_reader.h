// Quilt videos as input (lfd-play --quilt-in clip_qs8x6a0.75.mp4): decoded with
// libavformat / libavcodec / libswscale one frame at a time, so a long clip never sits in
// memory - only the frame being shown. Frames are numbered from 0 in presentation order;
// asking for an earlier frame than the last one decoded (a loop, or a step back) rewinds
// to the start and decodes forward, which is exact for every codec (no keyframe guessing).
#pragma once

#include "image.h"
#include "quilt_video.h"

#include <cstdint>
#include <filesystem>
#include <memory>

namespace lfd::player {

// True for the container extensions read as videos (.mp4, .m4v, .mov, .mkv, .webm, .avi).
bool isVideoFile(const std::filesystem::path& path);

class QuiltVideoReader {
public:
    // Opens the file, finds its video stream and counts its frames (by demuxing, no
    // decoding). Throws VideoError for a missing, unreadable, corrupt or empty video.
    explicit QuiltVideoReader(const std::filesystem::path& file);
    ~QuiltVideoReader();
    QuiltVideoReader(const QuiltVideoReader&) = delete;
    QuiltVideoReader& operator=(const QuiltVideoReader&) = delete;

    const std::filesystem::path& file() const { return file_; }
    uint32_t frameCount() const { return frameCount_; }
    double framesPerSecond() const { return fps_; }
    // Frame `index` (< frameCount()) as RGBA8, row 0 = top. Throws VideoError when
    // the frame cannot be decoded.
    const metrics::Image& frame(uint32_t index);

private:
    struct Codec;
    void rewind();
    bool decodeNext(bool convert); // the next frame (into frame_ when `convert`); false at the end
    void convertPicture();         // the decoded picture into frame_ as RGBA8
    std::filesystem::path file_;
    std::unique_ptr<Codec> codec_;
    uint32_t frameCount_ = 0;
    double fps_ = 0.0;
    int64_t decoded_ = -1; // index held in frame_, -1: none
    metrics::Image frame_;
};

} // namespace lfd::player
