// zstd payloads of format 2 (formats/README.md "Compression"): whole sections and
// texture levels. Every frame is checked to hold exactly the bytes its record promises,
// and nothing is allocated beyond what the structural pass bounded.
#include "lfd/pack_mapped.h"

#include "pack_internal.h"

#include <zstd.h>

#include <algorithm>
#include <memory>
#include <new>

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

uint64_t compressLevel(const void* data, size_t size, const ByteSink& write)
{
    // Streamed in ZSTD_CStreamOutSize() pieces: a 16384² level is never held compressed.
    std::unique_ptr<ZSTD_CCtx, decltype(&ZSTD_freeCCtx)> ctx(ZSTD_createCCtx(), &ZSTD_freeCCtx);
    if (!ctx || ZSTD_isError(ZSTD_CCtx_setParameter(ctx.get(), ZSTD_c_compressionLevel, kCompressionLevel)) ||
        ZSTD_isError(ZSTD_CCtx_setPledgedSrcSize(ctx.get(), size))) // the content size goes in the header
        throw std::bad_alloc();
    std::vector<uint8_t> piece(ZSTD_CStreamOutSize());
    ZSTD_inBuffer input{data, size, 0};
    uint64_t written = 0;
    for (size_t left = 1; left != 0;) {
        ZSTD_outBuffer output{piece.data(), piece.size(), 0};
        left = ZSTD_compressStream2(ctx.get(), &output, &input, ZSTD_e_end);
        if (ZSTD_isError(left))
            throw std::bad_alloc(); // in-memory input and output: only allocation can fail
        write(piece.data(), output.pos);
        written += output.pos;
    }
    if (size > maxInflatedBytes(written)) {
        // A skippable frame (magic 0x184D2A50, u32 length, payload ignored by decoders)
        // pads the stored size up to the reader's expansion bound.
        const uint64_t needed = (uint64_t(size) + kZstdMaxRatio - 1) / kZstdMaxRatio;
        const uint32_t payload = uint32_t(std::max<uint64_t>(needed, written + 8) - written - 8);
        const uint8_t header[8] = {0x50, 0x2A, 0x4D, 0x18, uint8_t(payload), uint8_t(payload >> 8),
                                   uint8_t(payload >> 16), uint8_t(payload >> 24)};
        write(header, sizeof header);
        const std::vector<uint8_t> zeros(std::min<size_t>(payload, 1 << 16), 0);
        for (uint32_t left = payload; left > 0;) {
            const uint32_t n = std::min<uint32_t>(left, uint32_t(zeros.size()));
            write(zeros.data(), n);
            left -= n;
        }
        written += sizeof header + payload;
    }
    return written;
}

std::vector<uint8_t> compressSection(const void* data, size_t size)
{
    if (size == 0)
        return {};
    std::vector<uint8_t> frame;
    compressLevel(data, size, [&](const void* bytes, size_t n) {
        const auto* p = static_cast<const uint8_t*>(bytes);
        frame.insert(frame.end(), p, p + n);
    });
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
    if (produced_ == size_)
        consumeTail();
}

// After the level's last byte only skippable frames may follow (the writer's padding):
// they are consumed without output; anything that would produce more is an error.
void LevelInflater::consumeTail()
{
    while (consumed_ < frame_.size()) {
        uint8_t none = 0;
        ZSTD_outBuffer output{&none, 0, 0};
        ZSTD_inBuffer input{frame_.data(), frame_.size(), consumed_};
        const size_t r = ZSTD_decompressStream(state_->ctx.get(), &output, &input);
        if (ZSTD_isError(r) || input.pos == consumed_)
            pack::fail(name_, what_ + ": trailing bytes after the zstd frame");
        consumed_ = input.pos;
    }
}

void LevelInflater::skipAll()
{
    std::vector<uint8_t> scratch(size_t(std::min<uint64_t>(size_ - produced_, uint64_t(1) << 20)));
    while (produced_ < size_)
        read(scratch.data(), size_t(std::min<uint64_t>(scratch.size(), size_ - produced_)));
}

} // namespace lfd
