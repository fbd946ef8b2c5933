// zstd payloads of format 2 (formats/README.md "Compression"): whole sections and RGBA8
// texture levels. Every frame is checked to hold exactly the bytes its record promises,
// and nothing is allocated beyond what the structural pass bounded.
#include "lfd/pack_mapped.h"

#include "pack_internal.h"

#include <zstd.h>

#include <algorithm>
#include <memory>

namespace lfd::pack {

namespace {

// Level 9: geometry compresses ~10% better than at the default level 3, still at
// ~80 MB/s per thread, and decompression speed does not depend on the level.
constexpr int kCompressionLevel = 9;

} // namespace

uint64_t maxInflatedBytes(uint64_t storedSize)
{
    const uint64_t ratioBound = storedSize > UINT64_MAX / kZstdMaxRatio ? UINT64_MAX : storedSize * kZstdMaxRatio;
    return std::max(ratioBound, kZstdSmallSectionBytes);
}

std::vector<uint8_t> compressLevel(const void* data, size_t size)
{
    std::vector<uint8_t> frame(ZSTD_compressBound(size));
    const size_t n = ZSTD_compress(frame.data(), frame.size(), data, size, kCompressionLevel);
    if (ZSTD_isError(n) || size > maxInflatedBytes(n))
        return {}; // a ratio the reader would refuse
    frame.resize(n);
    frame.shrink_to_fit();
    return frame;
}

std::vector<uint8_t> compressSection(const void* data, size_t size)
{
    if (size == 0)
        return {};
    std::vector<uint8_t> frame = compressLevel(data, size);
    if (frame.size() >= size)
        return {}; // raw: no gain
    return frame;
}

std::vector<uint8_t> inflate(const uint8_t* frame, size_t frameSize, uint64_t expectedSize, const std::string& name,
                             const std::string& what)
{
    const unsigned long long declared = ZSTD_getFrameContentSize(frame, frameSize);
    if (declared == ZSTD_CONTENTSIZE_ERROR || declared == ZSTD_CONTENTSIZE_UNKNOWN)
        fail(name, what + ": not a zstd frame with a content size (corrupt compressed payload)");
    if (declared != expectedSize)
        fail(name, what + ": zstd frame holds " + std::to_string(declared) + " bytes, expected " +
                       std::to_string(expectedSize));
    std::vector<uint8_t> out(static_cast<size_t>(expectedSize));
    const size_t n = ZSTD_decompress(out.data(), out.size(), frame, frameSize);
    if (ZSTD_isError(n) || n != expectedSize)
        fail(name, what + ": corrupt zstd payload (" +
                       (ZSTD_isError(n) ? std::string(ZSTD_getErrorName(n)) : std::to_string(n) + " bytes") + ")");
    return out;
}

} // namespace lfd::pack

namespace lfd {

struct LevelInflater::State {
    std::unique_ptr<ZSTD_DCtx, decltype(&ZSTD_freeDCtx)> ctx{ZSTD_createDCtx(), &ZSTD_freeDCtx};
};

LevelInflater::LevelInflater(std::span<const uint8_t> frame, uint64_t size, std::string name, std::string what)
    : frame_(frame), size_(size), name_(std::move(name)), what_(std::move(what)), state_(std::make_unique<State>())
{
    if (!state_->ctx)
        pack::fail(name_, what_ + ": cannot allocate a zstd decoder");
    const unsigned long long declared = ZSTD_getFrameContentSize(frame.data(), frame.size());
    if (declared == ZSTD_CONTENTSIZE_ERROR || declared == ZSTD_CONTENTSIZE_UNKNOWN || declared != size)
        pack::fail(name_, what_ + ": zstd frame does not hold the level's " + std::to_string(size) + " bytes");
}

LevelInflater::~LevelInflater() = default;

void LevelInflater::read(uint8_t* out, size_t n)
{
    if (n > size_ - produced_)
        pack::fail(name_, what_ + ": read past the end of the level");
    ZSTD_outBuffer output{out, n, 0};
    while (output.pos < output.size) {
        ZSTD_inBuffer input{frame_.data(), frame_.size(), consumed_};
        const size_t r = ZSTD_decompressStream(state_->ctx.get(), &output, &input);
        consumed_ = input.pos;
        if (ZSTD_isError(r))
            pack::fail(name_, what_ + ": corrupt zstd payload (" + ZSTD_getErrorName(r) + ")");
        if (r == 0 && output.pos < output.size)
            pack::fail(name_, what_ + ": zstd frame ends early");
        if (input.pos == input.size && output.pos < output.size && r != 0)
            pack::fail(name_, what_ + ": zstd frame is truncated");
    }
    produced_ += n;
    if (produced_ == size_ && consumed_ != frame_.size())
        pack::fail(name_, what_ + ": trailing bytes after the zstd frame");
}

void LevelInflater::skipAll()
{
    std::vector<uint8_t> scratch(size_t(std::min<uint64_t>(size_ - produced_, uint64_t(1) << 20)));
    while (produced_ < size_)
        read(scratch.data(), size_t(std::min<uint64_t>(scratch.size(), size_ - produced_)));
}

} // namespace lfd
