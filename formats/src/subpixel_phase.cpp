// The fixed-point subpixel phase (subpixel_phase.h): the profile's increments converted to
// 2^-64 lens periods, and lfd::subpixelPhase / subpixelView on top of them.
#include "lfd/subpixel_phase.h"

#include <algorithm>
#include <stdexcept>

namespace lfd {

uint64_t fixedPhaseFromDouble(double x) {
    if (!std::isfinite(x))
        throw std::invalid_argument("subpixel phase: a mapping increment is not finite");
    if (x == 0.0)
        return 0;
    // x = mantissa * 2^(exponent - 53) with |mantissa| in [2^52, 2^53), both exact.
    int exponent = 0;
    const auto mantissa = int64_t(std::ldexp(std::frexp(x, &exponent), 53));
    // x * 2^64 = mantissa * 2^shift.
    const int shift = exponent + 11;
    if (shift >= 64)
        return 0; // a whole number of periods
    if (shift >= 0)
        return uint64_t(mantissa) << shift; // mod 2^64: negative x wraps to 1 - |x|
    if (shift < -54)
        return 0; // |x| * 2^64 < 1/4
    // Below 2^-64: round to nearest, ties to even (floor division by 2^s, then the rest).
    const int s = -shift;
    const int64_t unit = int64_t(1) << s;
    int64_t quotient = mantissa >> s; // arithmetic shift: floor
    const int64_t rest = mantissa - quotient * unit;
    if (2 * rest > unit || (2 * rest == unit && (quotient & 1) != 0))
        ++quotient;
    return uint64_t(quotient);
}

FixedSubpixelMapping fixedSubpixelMapping(const SubpixelMapping& mapping) {
    FixedSubpixelMapping fixed;
    fixed.perSubpixel = fixedPhaseFromDouble(mapping.perSubpixel);
    fixed.perRow = fixedPhaseFromDouble(mapping.perRow);
    fixed.offset = fixedPhaseFromDouble(mapping.offset);
    fixed.invert = mapping.invert;
    return fixed;
}

double subpixelPhase(const DisplayProfile& profile, uint32_t k, uint32_t l) {
    return fixedPhaseToDouble(fixedSubpixelPhase(fixedSubpixelMapping(profile.mapping), k, l));
}

uint32_t subpixelView(const DisplayProfile& profile, uint32_t k, uint32_t l) {
    return fixedPhaseView(fixedSubpixelPhase(fixedSubpixelMapping(profile.mapping), k, l), profile.viewCount);
}

uint32_t samePhasePixelStride(const DisplayProfile& profile, uint32_t maxStride, double maxDriftViews) {
    // In fixed point: the phase step of s pixels is 3 s perSubpixel mod 1; its distance
    // from a whole period is min(step, 2^64 - step).
    const uint64_t perPixel = 3 * fixedPhaseFromDouble(profile.mapping.perSubpixel);
    uint32_t best = 1;
    double bestDrift = 2.0;
    for (uint32_t s = 1; s <= maxStride; ++s) {
        const uint64_t step = perPixel * s;
        const double drift = std::ldexp(double(std::min(step, uint64_t(0) - step)), -64);
        if (drift < bestDrift) {
            best = s;
            bestDrift = drift;
        }
    }
    return bestDrift * double(profile.viewCount) <= maxDriftViews ? best : 1;
}

} // namespace lfd
