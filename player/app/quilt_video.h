// Quilt videos: a numbered quilt sequence (quiltSequenceFileName) encoded by the ffmpeg
// command-line tool (Debian package `ffmpeg`), run as a child process with an argument
// vector - no shell, so no quoting or injection. The video is written to a temporary file
// beside the target and renamed, so a failed encode leaves nothing behind. Looking Glass
// players read the layout from the name, which carries the quilt suffix like the images:
// "clip.mp4" -> "clip_qs8x6a1.78.mp4".
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace lfd::player {

// One line naming the file and the problem: writing a quilt video, or reading one
// (quilt_video_reader.h).
class VideoError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// ".mp4" (H.264, yuv420p) or ".webm" (VP9); throws std::invalid_argument otherwise.
void checkVideoExtension(const std::filesystem::path& video);

// The first executable `name` on $PATH, or empty.
std::filesystem::path findOnPath(const std::string& name);

// ffmpeg's arguments (without argv[0]) for frames `pattern` (printf-style, numbered from
// `firstNumber`) at `fps` into `output` with the container given by `container` ("mp4" or
// "webm").
std::vector<std::string> ffmpegArguments(const std::filesystem::path& pattern, double fps,
                                         const std::filesystem::path& output, const std::string& container,
                                         uint32_t firstNumber = 0);

// Encodes the sequence into `video` (temporary file, then rename). Throws VideoError with
// one line: ffmpeg missing from $PATH, or its exit status and last message.
void encodeQuiltVideo(const std::filesystem::path& pattern, double fps, const std::filesystem::path& video,
                      uint32_t firstNumber = 0);

} // namespace lfd::player
