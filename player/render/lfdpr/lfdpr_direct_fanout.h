// The direct subpixel splat's inverse map (renderer lfdpr-direct, docs/player/direct-splat.md):
// for every view pixel, the panel subpixels that show it. The EIA's nearest mode maps each
// subpixel (k, l) forward to one view word - view floor(phase * N) by the exact fixed-point
// phase (lfd/subpixel_phase.h), texel viewColumnUnder / viewRowUnder (eia_builder.h) - so
// the inverse is a partition of the S = 3 W H subpixels by view word: a CSR table, built
// here from those same functions and read by shaders/lfdpr_direct_fanout.glsl.
#pragma once

#include "lfd/display_profile.h"

#include <cstdint>
#include <vector>

namespace lfd::player {

struct LfdprDirectFanout {
    // offsets[w] .. offsets[w + 1] - 1: the entries of view word w (lfdViewWord order:
    // (y * width + x) * N + view, y a GL row, 0 = bottom); N * width * height + 1 values.
    std::vector<uint32_t> offsets;
    // The subpixels, l * 3W + k (l = panel row from the top), grouped by view word, each
    // exactly once; within a word in increasing order.
    std::vector<uint32_t> subpixels;
};

// The table for `profile` at its view count and size. Throws std::invalid_argument when
// the subpixels or view words do not fit 32-bit indices.
LfdprDirectFanout buildLfdprDirectFanout(const DisplayProfile& profile);

// The view word subpixel (k, l) shows under the EIA's nearest mode (the forward map the
// table inverts).
uint32_t lfdprDirectViewWord(const DisplayProfile& profile, uint32_t k, uint32_t l);

} // namespace lfd::player
