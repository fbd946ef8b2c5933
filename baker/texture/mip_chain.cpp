// Mip chain filter and codecs; see mip_chain.h for the filter definition.
#include "mip_chain.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>

namespace lfd::bake::mip {

namespace {

// Exact sRGB transfer functions (IEC 61966-2-1), evaluated in double.
double srgbEotf(double c)
{
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// Decode: the 256 possible byte values. Encode: byte b + 1 is the right answer exactly
// when linear >= EOTF((b + 0.5) / 255) (the OETF is monotonic), so the 255 thresholds
// give round(255 * OETF(x)) without evaluating pow; a 4096-cell grid over [0,1] gives a
// starting byte that is at most one threshold short (the steepest part of the curve,
// slope 12.92 near zero, moves 0.8 of a byte per cell).
struct SrgbTables {
    static constexpr int kGrid = 4096;
    std::array<float, 256> toLinear{};
    std::array<float, 255> threshold{};
    std::array<uint8_t, kGrid + 1> guess{};

    SrgbTables()
    {
        for (int b = 0; b < 256; ++b)
            toLinear[b] = float(srgbEotf(b / 255.0));
        for (int b = 0; b < 255; ++b)
            threshold[b] = float(srgbEotf((b + 0.5) / 255.0));
        int b = 0;
        for (int g = 0; g <= kGrid; ++g) {
            const float x = float(g) / kGrid;
            while (b < 255 && x >= threshold[b])
                ++b;
            guess[g] = uint8_t(b);
        }
    }
};

const SrgbTables& srgbTables()
{
    static const SrgbTables tables;
    return tables;
}

inline uint8_t encodeSrgb(const SrgbTables& t, float linear)
{
    // note: written so that NaN maps to 0.
    const float x = linear > 0.0f ? (linear < 1.0f ? linear : 1.0f) : 0.0f;
    uint32_t b = t.guess[uint32_t(x * SrgbTables::kGrid)];
    while (b < 255 && x >= t.threshold[b])
        ++b;
    return uint8_t(b);
}

inline uint8_t encodeByte(float v)
{
    const float x = v > 0.0f ? (v < 255.0f ? v : 255.0f) : 0.0f;
    return uint8_t(x + 0.5f); // round half up
}

} // namespace

std::vector<MipLevel> chainLayout(uint32_t width, uint32_t height)
{
    std::vector<MipLevel> levels;
    uint64_t offset = 0;
    uint32_t w = std::max(width, 1u), h = std::max(height, 1u);
    for (;;) {
        MipLevel level;
        level.width = w;
        level.height = h;
        level.offset = offset;
        level.size = uint64_t(w) * h * 4;
        offset += level.size;
        levels.push_back(level);
        if (w == 1 && h == 1)
            break;
        w = std::max(1u, w >> 1);
        h = std::max(1u, h >> 1);
    }
    return levels;
}

uint64_t chainBytes(const std::vector<MipLevel>& levels)
{
    return levels.empty() ? 0 : levels.back().offset + levels.back().size;
}

float srgb8ToLinear(uint8_t value) { return srgbTables().toLinear[value]; }

uint8_t linearToSrgb8(float linear) { return encodeSrgb(srgbTables(), linear); }

void decodeRow(const uint8_t* rgba, uint32_t width, bool srgb, float* out)
{
    const size_t n = size_t(width) * 4;
    if (!srgb) {
        for (size_t i = 0; i < n; ++i)
            out[i] = float(rgba[i]);
        return;
    }
    const float* lut = srgbTables().toLinear.data();
    for (size_t i = 0; i < n; i += 4) {
        out[i + 0] = lut[rgba[i + 0]];
        out[i + 1] = lut[rgba[i + 1]];
        out[i + 2] = lut[rgba[i + 2]];
        out[i + 3] = float(rgba[i + 3]);
    }
}

void encodeRow(const float* in, uint32_t width, bool srgb, uint8_t* rgba)
{
    const size_t n = size_t(width) * 4;
    if (!srgb) {
        for (size_t i = 0; i < n; ++i)
            rgba[i] = encodeByte(in[i]);
        return;
    }
    const SrgbTables& t = srgbTables();
    for (size_t i = 0; i < n; i += 4) {
        rgba[i + 0] = encodeSrgb(t, in[i + 0]);
        rgba[i + 1] = encodeSrgb(t, in[i + 1]);
        rgba[i + 2] = encodeSrgb(t, in[i + 2]);
        rgba[i + 3] = encodeByte(in[i + 3]);
    }
}

// ---- RowDownsampler --------------------------------------------------------------

RowDownsampler::RowDownsampler(uint32_t inWidth, uint32_t inHeight, uint32_t firstInputRow)
    : inWidth_(std::max(inWidth, 1u)), inHeight_(std::max(inHeight, 1u)),
      outWidth_(std::max(1u, inWidth_ >> 1)), outHeight_(std::max(1u, inHeight_ >> 1)),
      firstInputRow_(firstInputRow), nextInputRow_(firstInputRow)
{
    assert(firstInputRow % 2 == 0 && firstInputRow < inHeight_);
    // Odd widths: polyphase box weights ((m - x), m, (x + 1)) / n, see mip_chain.h.
    if (inWidth_ > 1 && inWidth_ % 2 == 1) {
        const uint32_t m = inWidth_ / 2;
        const float inv = 1.0f / float(inWidth_);
        columnTaps_.resize(outWidth_);
        for (uint32_t x = 0; x < outWidth_; ++x)
            columnTaps_[x] = {2 * x, {float(m - x) * inv, float(m) * inv, float(x + 1) * inv}, 3};
    }
    ring_.resize(size_t(outWidth_) * 4 * 3);
    out_.resize(size_t(outWidth_) * 4);
}

uint32_t RowDownsampler::inputRowsEnd(uint32_t outRowEnd) const
{
    if (inHeight_ == 1)
        return 1;
    return inHeight_ % 2 == 0 ? 2 * outRowEnd : 2 * outRowEnd + 1;
}

void RowDownsampler::reduceHorizontally(const float* in, float* out) const
{
    if (inWidth_ == 1) {
        std::copy(in, in + 4, out);
    } else if (inWidth_ % 2 == 0) {
        for (uint32_t x = 0; x < outWidth_; ++x) {
            const float* a = in + size_t(x) * 8;
            float* o = out + size_t(x) * 4;
            o[0] = 0.5f * (a[0] + a[4]);
            o[1] = 0.5f * (a[1] + a[5]);
            o[2] = 0.5f * (a[2] + a[6]);
            o[3] = 0.5f * (a[3] + a[7]);
        }
    } else {
        for (uint32_t x = 0; x < outWidth_; ++x) {
            const Taps& t = columnTaps_[x];
            const float* a = in + size_t(t.first) * 4;
            float* o = out + size_t(x) * 4;
            for (int c = 0; c < 4; ++c)
                o[c] = t.w[0] * a[c] + t.w[1] * a[4 + c] + t.w[2] * a[8 + c];
        }
    }
}

const float* RowDownsampler::push(const float* inRow)
{
    const size_t rowFloats = size_t(outWidth_) * 4;
    const uint32_t r = nextInputRow_++;
    assert(r < inHeight_);
    float* slot = ring_.data() + (r % 3) * rowFloats;
    reduceHorizontally(inRow, slot);

    // Combine vertically once the rows an output row needs are all here.
    if (inHeight_ == 1) {
        lastOut_ = 0;
        return slot;
    }
    auto row = [&](uint32_t k) { return ring_.data() + (k % 3) * rowFloats; };
    if (inHeight_ % 2 == 0) {
        if (r % 2 == 0)
            return nullptr;
        const float* a = row(r - 1);
        for (size_t i = 0; i < rowFloats; ++i)
            out_[i] = 0.5f * (a[i] + slot[i]);
        lastOut_ = (r - 1) / 2;
        return out_.data();
    }
    // note: the rows before r are only here if this stage was fed them (a stage may
    // start in the middle of the image).
    if (r % 2 == 1 || r < firstInputRow_ + 2)
        return nullptr;
    const uint32_t y = (r - 2) / 2, m = inHeight_ / 2;
    const float inv = 1.0f / float(inHeight_);
    const float w0 = float(m - y) * inv, w1 = float(m) * inv, w2 = float(y + 1) * inv;
    const float* a = row(r - 2);
    const float* b = row(r - 1);
    for (size_t i = 0; i < rowFloats; ++i)
        out_[i] = w0 * a[i] + w1 * b[i] + w2 * slot[i];
    lastOut_ = y;
    return out_.data();
}

// ---- chain -----------------------------------------------------------------------

namespace {

// Output rows [y0, y1) of `dst` from `src` (one level above).
void downsampleRows(const uint8_t* src, const MipLevel& srcLevel, uint8_t* dst,
                    const MipLevel& dstLevel, bool srgb, uint32_t y0, uint32_t y1)
{
    RowDownsampler stage(srcLevel.width, srcLevel.height, 2 * y0);
    std::vector<float> in(size_t(srcLevel.width) * 4);
    const size_t srcStride = size_t(srcLevel.width) * 4, dstStride = size_t(dstLevel.width) * 4;
    const uint32_t end = stage.inputRowsEnd(y1);
    for (uint32_t r = 2 * y0; r < end; ++r) {
        decodeRow(src + r * srcStride, srcLevel.width, srgb, in.data());
        if (const float* out = stage.push(in.data()))
            encodeRow(out, dstLevel.width, srgb, dst + stage.lastOutputRow() * dstStride);
    }
}

} // namespace

void buildChain(uint8_t* texels, const std::vector<MipLevel>& levels, bool srgb,
                unsigned threads)
{
    ThreadBudget budget(threads);
    buildChain(texels, levels, srgb, budget);
}

void buildChain(uint8_t* texels, const std::vector<MipLevel>& levels, bool srgb, ThreadBudget& budget)
{
    const unsigned threads = budget.size();
    for (size_t l = 1; l < levels.size(); ++l) {
        const MipLevel& s = levels[l - 1];
        const MipLevel& d = levels[l];
        const uint8_t* src = texels + s.offset;
        uint8_t* dst = texels + d.offset;
        // note: small levels are not worth a thread start (~64K output texels each).
        const uint64_t count = uint64_t(d.width) * d.height;
        const unsigned n = unsigned(
            std::min<uint64_t>({threads, d.height, std::max<uint64_t>(1, count >> 16)}));
        // Split the output rows into n bands; each band re-reads the input rows it needs,
        // so bands are independent (an odd-height level shares one input row per seam)
        // and the level is the same bytes for any n.
        parallelFor(n, budget, [&](size_t t) {
            const uint32_t y0 = uint32_t(uint64_t(d.height) * t / n);
            const uint32_t y1 = uint32_t(uint64_t(d.height) * (t + 1) / n);
            downsampleRows(src, s, dst, d, srgb, y0, y1);
        });
    }
}

} // namespace lfd::bake::mip
