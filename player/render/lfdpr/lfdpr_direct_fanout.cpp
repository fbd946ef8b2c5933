#include "lfdpr_direct_fanout.h"

#include "eia_builder.h"

#include "lfd/subpixel_phase.h"

#include <stdexcept>

namespace lfd::player {

namespace {

// The forward map with the fixed-point mapping converted once.
uint32_t viewWordOf(const DisplayProfile& p, const FixedSubpixelMapping& m, uint32_t k, uint32_t l)
{
    const uint32_t view = fixedPhaseView(fixedSubpixelPhase(m, k, l), p.viewCount);
    const uint32_t x = viewColumnUnder(k, p.panelWidth, p.viewWidth);
    const uint32_t y = p.viewHeight - 1 - viewRowUnder(l, p.panelHeight, p.viewHeight); // GL row
    return (y * p.viewWidth + x) * p.viewCount + view; // lfdViewWord (lfdpr_bindings.glsl)
}

} // namespace

uint32_t lfdprDirectViewWord(const DisplayProfile& profile, uint32_t k, uint32_t l)
{
    return viewWordOf(profile, fixedSubpixelMapping(profile.mapping), k, l);
}

LfdprDirectFanout buildLfdprDirectFanout(const DisplayProfile& profile)
{
    const uint64_t columns = 3ull * profile.panelWidth;
    const uint64_t subpixels = columns * profile.panelHeight;
    const uint64_t words = uint64_t(profile.viewCount) * profile.viewWidth * profile.viewHeight;
    if (subpixels >= (1ull << 32) || words >= (1ull << 32) - 1)
        throw std::invalid_argument("lfdpr-direct: the panel's subpixels or view pixels exceed 32-bit indices");
    const FixedSubpixelMapping m = fixedSubpixelMapping(profile.mapping);

    // A counting sort of the subpixels by view word: count, prefix sums, then place each
    // subpixel in increasing order (two passes over the forward map: no S-sized key array).
    LfdprDirectFanout table;
    table.offsets.assign(size_t(words) + 1, 0u);
    for (uint32_t l = 0; l < profile.panelHeight; ++l)
        for (uint32_t k = 0; k < columns; ++k)
            ++table.offsets[size_t(viewWordOf(profile, m, k, l)) + 1];
    for (size_t w = 1; w < table.offsets.size(); ++w)
        table.offsets[w] += table.offsets[w - 1];
    std::vector<uint32_t> next(table.offsets.begin(), table.offsets.end() - 1);
    table.subpixels.resize(size_t(subpixels));
    for (uint32_t l = 0; l < profile.panelHeight; ++l)
        for (uint32_t k = 0; k < columns; ++k)
            table.subpixels[next[viewWordOf(profile, m, k, l)]++] = uint32_t(l * columns + k);
    return table;
}

} // namespace lfd::player
