// FFmpeg's decoding libraries (libavformat, libavcodec, libswscale, libavutil), loaded at
// run time with dlopen when a quilt video is first played, not linked: they and the codec
// libraries they pull in are ~120 shared objects and 167 MB on Debian, which would end
// lfd-play's portability (docs/player/another-machine.md: 17 libraries,
// a 9 MiB bundle). The headers come from the -dev packages at build time (CMake
// pkg_check_modules), so the calls are type-checked, and the sonames opened are the
// major versions of those headers.
#pragma once

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/log.h>
#include <libswscale/swscale.h>
}

namespace lfd::player {

// X(library, function) for every libav function the player calls.
#define LFD_LIBAV_FUNCTIONS(X)                                                                                          \
    X(avformat, avformat_open_input)                                                                                   \
    X(avformat, avformat_find_stream_info)                                                                             \
    X(avformat, av_find_best_stream)                                                                                   \
    X(avformat, av_guess_frame_rate)                                                                                   \
    X(avformat, av_read_frame)                                                                                         \
    X(avformat, av_seek_frame)                                                                                         \
    X(avformat, avformat_seek_file)                                                                                    \
    X(avformat, avformat_close_input)                                                                                  \
    X(avcodec, avcodec_alloc_context3)                                                                                 \
    X(avcodec, avcodec_parameters_to_context)                                                                          \
    X(avcodec, avcodec_open2)                                                                                          \
    X(avcodec, avcodec_flush_buffers)                                                                                  \
    X(avcodec, avcodec_receive_frame)                                                                                  \
    X(avcodec, avcodec_send_packet)                                                                                    \
    X(avcodec, avcodec_free_context)                                                                                   \
    X(avcodec, av_packet_alloc)                                                                                        \
    X(avcodec, av_packet_free)                                                                                         \
    X(avcodec, av_packet_unref)                                                                                        \
    X(avutil, av_frame_alloc)                                                                                          \
    X(avutil, av_frame_free)                                                                                           \
    X(avutil, av_frame_unref)                                                                                          \
    X(avutil, av_log_set_level)                                                                                        \
    X(avutil, av_strerror)                                                                                             \
    X(swscale, sws_getCachedContext)                                                                                   \
    X(swscale, sws_scale)                                                                                              \
    X(swscale, sws_freeContext)

struct LibAv {
#define LFD_LIBAV_POINTER(library, function) decltype(&::function) function = nullptr;
    LFD_LIBAV_FUNCTIONS(LFD_LIBAV_POINTER)
#undef LFD_LIBAV_POINTER
};

// The loaded libraries (loaded on the first call, kept for the process). Throws VideoError
// with one line naming the library that is missing and the Debian packages that hold it.
const LibAv& libAv();

} // namespace lfd::player
