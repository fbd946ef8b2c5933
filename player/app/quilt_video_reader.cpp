#include "quilt_video_reader.h"

#include "libav_library.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <string>

namespace lfd::player {

namespace fs = std::filesystem;

// The libav objects of one open file, freed in reverse order of creation.
struct QuiltVideoReader::Codec {
    AVFormatContext* format = nullptr;
    AVCodecContext* decoder = nullptr;
    SwsContext* scaler = nullptr;
    AVPacket* packet = nullptr;
    AVFrame* picture = nullptr;
    int stream = -1;
    bool draining = false; // the demuxer is at its end; the decoder gives its last frames

    ~Codec()
    {
        if (!format) // nothing was opened (and the libraries may not have loaded)
            return;
        libAv().sws_freeContext(scaler);
        libAv().av_frame_free(&picture);
        libAv().av_packet_free(&packet);
        libAv().avcodec_free_context(&decoder);
        libAv().avformat_close_input(&format);
    }
};

namespace {

std::string avMessage(int code)
{
    std::array<char, AV_ERROR_MAX_STRING_SIZE> text{};
    libAv().av_strerror(code, text.data(), text.size());
    return text.data();
}

} // namespace

bool isVideoFile(const fs::path& path)
{
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    static const std::array<const char*, 6> known = {".mp4", ".m4v", ".mov", ".mkv", ".webm", ".avi"};
    return std::find(known.begin(), known.end(), ext) != known.end();
}

QuiltVideoReader::QuiltVideoReader(const fs::path& file) : file_(file), codec_(std::make_unique<Codec>())
{
    // note: libav logs corrupt-stream details to stderr itself; the player reports one
    // line per problem, so its log stays quiet.
    auto fail = [&](const std::string& problem) { throw VideoError(file.string() + ": " + problem); };
    try {
        libAv();
    } catch (const VideoError& e) {
        fail(e.what());
    }
    libAv().av_log_set_level(AV_LOG_QUIET);
    Codec& c = *codec_;
    if (int r = libAv().avformat_open_input(&c.format, file.c_str(), nullptr, nullptr); r < 0)
        fail("cannot open the video (" + avMessage(r) + ")");
    if (int r = libAv().avformat_find_stream_info(c.format, nullptr); r < 0)
        fail("not a readable video (" + avMessage(r) + ")");
    const AVCodec* codec = nullptr;
    c.stream = libAv().av_find_best_stream(c.format, AVMEDIA_TYPE_VIDEO, -1, -1, &codec, 0);
    if (c.stream < 0 || !codec)
        fail("holds no decodable video stream");
    AVStream* stream = c.format->streams[c.stream];
    c.decoder = libAv().avcodec_alloc_context3(codec);
    c.packet = libAv().av_packet_alloc();
    c.picture = libAv().av_frame_alloc();
    if (!c.decoder || !c.packet || !c.picture)
        fail("out of memory opening the video");
    if (libAv().avcodec_parameters_to_context(c.decoder, stream->codecpar) < 0 || libAv().avcodec_open2(c.decoder, codec, nullptr) < 0)
        fail(std::string("cannot open the ") + codec->name + " decoder");
    const AVRational rate = libAv().av_guess_frame_rate(c.format, stream, nullptr);
    fps_ = rate.num > 0 && rate.den > 0 ? av_q2d(rate) : 0.0;
    if (!(fps_ > 0.0))
        fail("the video stream has no frame rate");
    // Count the frames by demuxing (containers' own counts are missing in WebM and can
    // be wrong); then back to the start.
    while (libAv().av_read_frame(c.format, c.packet) >= 0) {
        frameCount_ += c.packet->stream_index == c.stream ? 1 : 0;
        libAv().av_packet_unref(c.packet);
    }
    if (frameCount_ == 0)
        fail("the video stream has no frames");
    rewind();
    frame(0); // a file whose first frame does not decode fails here, before any output
}

QuiltVideoReader::~QuiltVideoReader() = default;

void QuiltVideoReader::rewind()
{
    Codec& c = *codec_;
    if (int r = libAv().av_seek_frame(c.format, c.stream, 0, AVSEEK_FLAG_BACKWARD); r < 0)
        if (int again = libAv().avformat_seek_file(c.format, -1, INT64_MIN, 0, INT64_MAX, 0); again < 0)
            throw VideoError(file_.string() + ": cannot seek to the start (" + avMessage(again) + ")");
    libAv().avcodec_flush_buffers(c.decoder);
    c.draining = false;
    decoded_ = -1;
}

bool QuiltVideoReader::decodeNext(bool convert)
{
    Codec& c = *codec_;
    for (;;) {
        const int received = libAv().avcodec_receive_frame(c.decoder, c.picture);
        if (received == 0)
            break;
        if (received == AVERROR_EOF || (received == AVERROR(EAGAIN) && c.draining))
            return false;
        if (received != AVERROR(EAGAIN))
            throw VideoError(file_.string() + ": frame " + std::to_string(decoded_ + 1) +
                                  " does not decode (" + avMessage(received) + ")");
        if (libAv().av_read_frame(c.format, c.packet) < 0) {
            libAv().avcodec_send_packet(c.decoder, nullptr); // end of file: drain the decoder
            c.draining = true;
            continue;
        }
        if (c.packet->stream_index == c.stream) {
            const int sent = libAv().avcodec_send_packet(c.decoder, c.packet);
            if (sent < 0 && sent != AVERROR(EAGAIN)) {
                libAv().av_packet_unref(c.packet);
                throw VideoError(file_.string() + ": corrupt video data at frame " +
                                      std::to_string(decoded_ + 1) + " (" + avMessage(sent) + ")");
            }
        }
        libAv().av_packet_unref(c.packet);
    }
    ++decoded_;
    if (convert)
        convertPicture();
    libAv().av_frame_unref(c.picture);
    return true;
}

void QuiltVideoReader::convertPicture()
{
    Codec& c = *codec_;
    const AVFrame& p = *c.picture;
    c.scaler = libAv().sws_getCachedContext(c.scaler, p.width, p.height, AVPixelFormat(p.format), p.width, p.height,
                                    AV_PIX_FMT_RGBA, SWS_BILINEAR | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INT, nullptr,
                                    nullptr, nullptr);
    if (!c.scaler)
        throw VideoError(file_.string() + ": cannot convert its pixel format to RGBA");
    frame_ = metrics::Image{uint32_t(p.width), uint32_t(p.height), 4,
                            std::vector<uint8_t>(size_t(p.width) * size_t(p.height) * 4)};
    uint8_t* planes[4] = {frame_.pixels.data(), nullptr, nullptr, nullptr};
    const int strides[4] = {p.width * 4, 0, 0, 0};
    libAv().sws_scale(c.scaler, p.data, p.linesize, 0, p.height, planes, strides);
}

const metrics::Image& QuiltVideoReader::frame(uint32_t index)
{
    if (index >= frameCount_)
        throw VideoError(file_.string() + ": has " + std::to_string(frameCount_) + " frames, frame " +
                              std::to_string(index) + " asked");
    if (int64_t(index) < decoded_)
        rewind();
    // Frames before the one asked are decoded (the codec needs them) but not converted.
    while (decoded_ < int64_t(index))
        if (!decodeNext(decoded_ + 1 == int64_t(index)))
            throw VideoError(file_.string() + ": ends after " + std::to_string(decoded_ + 1) +
                                  " decodable frames, frame " + std::to_string(index) + " asked");
    return frame_;
}

} // namespace lfd::player
