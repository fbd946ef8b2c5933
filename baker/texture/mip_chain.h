// Mip chain construction for RGBA8 textures: the 2x reduction filter, the sRGB <-> linear
// codecs it averages in, and the layout of a full chain in one texel buffer.
//
// One filter serves both the mip chain and the reduction of oversized sources (which is
// just "take mip level k of the source"), so a reduced texture's level 0 is the level the
// unreduced chain would have had there.
//
// Filter (per dimension, separable): a level of size n has size max(1, n >> 1) below it.
//   n == 1          copy (the dimension no longer shrinks)
//   n even          2-tap box  [1/2, 1/2] over texels 2i, 2i+1
//   n odd (2m + 1)  3-tap polyphase box over texels 2i, 2i+1, 2i+2 with weights
//                   ((m - i), m, (i + 1)) / n: output texel i averages exactly the input
//                   interval [i n/m, (i+1) n/m), so no input texel is dropped or counted
//                   twice (a plain 2x2 box would lose the last row/column).
// Colour channels of sRGB textures are averaged in linear light (exact sRGB EOTF, and the
// result re-encoded with exact round-to-nearest); alpha and every channel of data
// textures are averaged in byte units and rounded half up.
#pragma once

#include "lfd/scene.h"
#include "parallel.h"

#include <cstdint>
#include <vector>

namespace lfd::bake::mip {

// Levels max(1, w >> l) x max(1, h >> l) down to 1x1, packed back to back from offset 0.
std::vector<MipLevel> chainLayout(uint32_t width, uint32_t height);
// Total bytes of a chain (sum of the levels' sizes).
uint64_t chainBytes(const std::vector<MipLevel>& levels);

// Byte -> filter space for one RGBA8 row: sRGB colour -> linear [0,1], everything else
// stays in byte units [0,255].
void decodeRow(const uint8_t* rgba, uint32_t width, bool srgb, float* out);
// Filter space -> bytes, clamped and rounded to nearest.
void encodeRow(const float* in, uint32_t width, bool srgb, uint8_t* rgba);
// Exact sRGB encode of one linear value: round(255 * OETF(linear)).
uint8_t linearToSrgb8(float linear);
float srgb8ToLinear(uint8_t value);

// Streaming 2x reduction of a float RGBA image, row by row: feed the input rows in order
// starting at `firstInputRow` (even; the stage then produces output rows from
// firstInputRow / 2 on); every completed output row is returned by push(). Holds at most
// three (horizontally reduced) input rows, so a cascade of stages reduces an image of
// any height with a few rows of memory each.
class RowDownsampler {
public:
    RowDownsampler(uint32_t inWidth, uint32_t inHeight, uint32_t firstInputRow = 0);

    uint32_t outWidth() const { return outWidth_; }
    uint32_t outHeight() const { return outHeight_; }
    // Input rows [firstInputRow, inputRowsEnd(end)) produce output rows [.., end).
    uint32_t inputRowsEnd(uint32_t outRowEnd) const;

    // Pushes the next input row (inWidth RGBA floats). Returns the completed output row
    // (outWidth RGBA floats, valid until the next push) or nullptr.
    const float* push(const float* inRow);
    // Index of the row push() last returned.
    uint32_t lastOutputRow() const { return lastOut_; }

private:
    struct Taps {
        uint32_t first;
        float w[3];
        uint32_t count;
    };
    void reduceHorizontally(const float* in, float* out) const;

    uint32_t inWidth_, inHeight_, outWidth_, outHeight_;
    uint32_t firstInputRow_;
    uint32_t nextInputRow_;
    uint32_t lastOut_ = 0;
    std::vector<Taps> columnTaps_;
    std::vector<float> ring_; // 3 horizontally reduced input rows
    std::vector<float> out_;
};

// Fills levels 1.. of `levels` in `texels` from level 0, each level from the one above.
// Rows of a level are split between up to `threads` threads (0: one per hardware thread);
// the bytes do not depend on the thread count.
void buildChain(uint8_t* texels, const std::vector<MipLevel>& levels, bool srgb,
                unsigned threads = 0);
// The same with the bands' threads taken from a budget shared with other work.
void buildChain(uint8_t* texels, const std::vector<MipLevel>& levels, bool srgb, ThreadBudget& threads);

} // namespace lfd::bake::mip
