// Simulated viewer (see simulated_viewer.h for the model).
#include "simulated_viewer.h"

#include "parallel.h"

#include "lfd/subpixel_phase.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace lfd::player {

namespace {

// Half-open index range of cells [i, i+1) whose centres i + 0.5 lie in [lo, hi),
// clamped to [0, count).
void centresInRange(double lo, double hi, uint32_t count, uint32_t& first, uint32_t& end) {
    const double a = std::ceil(lo - 0.5), b = std::ceil(hi - 0.5);
    first = uint32_t(std::clamp(a, 0.0, double(count)));
    end = uint32_t(std::clamp(b, double(first), double(count)));
}

struct ChannelGather {
    double inSum = 0.0; // subpixels within half a view interval of t
    uint32_t inCount = 0;
    // Fallback: the nearest subpixels below and above t (circular view distance).
    double below = 0.0, belowDistance = std::numeric_limits<double>::infinity();
    double above = 0.0, aboveDistance = std::numeric_limits<double>::infinity();

    void add(double value, double delta) {
        if (delta >= -0.5 && delta < 0.5) {
            inSum += value;
            ++inCount;
        }
        if (delta < 0.0 && -delta < belowDistance) {
            belowDistance = -delta;
            below = value;
        } else if (delta >= 0.0 && delta < aboveDistance) {
            aboveDistance = delta;
            above = value;
        }
    }
    uint8_t result() const {
        double v = 0.0;
        if (inCount > 0) {
            v = inSum / inCount;
        } else if (std::isfinite(belowDistance) && std::isfinite(aboveDistance)) {
            // No subpixel of this view here: the eye sits between the two nearest view
            // zones the footprint has, so interpolate linearly between them.
            v = (below * aboveDistance + above * belowDistance) / (belowDistance + aboveDistance);
        } else if (std::isfinite(belowDistance)) {
            v = below;
        } else if (std::isfinite(aboveDistance)) {
            v = above;
        }
        return uint8_t(std::clamp(std::lround(v), 0L, 255L));
    }
};

} // namespace

std::vector<uint8_t> simulateViewer(const DisplayProfile& profile,
                                    const std::vector<uint8_t>& eia, double t) {
    const uint32_t W = profile.panelWidth, H = profile.panelHeight;
    const uint32_t vw = profile.viewWidth, vh = profile.viewHeight;
    const double N = double(profile.viewCount);
    if (W == 0 || H == 0 || vw == 0 || vh == 0 || profile.viewCount == 0)
        throw std::invalid_argument("simulated viewer: profile '" + profile.name +
                                    "' has an empty panel or no views");
    if (eia.size() != size_t(W) * H * 4)
        throw std::invalid_argument("simulated viewer: EIA has " + std::to_string(eia.size()) +
                                    " bytes, expected " + std::to_string(size_t(W) * H * 4) +
                                    " for a " + std::to_string(W) + "x" + std::to_string(H) +
                                    " panel");
    if (!(t >= 0.0 && t < N))
        throw std::invalid_argument("simulated viewer: viewing position " + std::to_string(t) +
                                    " outside [0, " + std::to_string(profile.viewCount) + ")");
    if (!(std::abs(profile.mapping.perSubpixel) > 0.0))
        throw std::invalid_argument("simulated viewer: profile '" + profile.name +
                                    "' has no lens pitch");

    // Footprint half sizes in subpixel columns and pixel rows: one view pixel, but at
    // least one lens (X = 1 / perSubpixel subpixels) wide and one row high.
    const double subpixelsPerViewPixel = 3.0 * W / vw;
    const double X = 1.0 / std::abs(profile.mapping.perSubpixel);
    const double halfWidth = 0.5 * std::max(subpixelsPerViewPixel, X);
    const double rowsPerViewPixel = double(H) / vh;
    const double halfHeight = 0.5 * std::max(rowsPerViewPixel, 1.0);
    const bool bgr = profile.subpixelOrder == SubpixelOrder::BGR;
    const FixedSubpixelMapping fixed = fixedSubpixelMapping(profile.mapping);

    std::vector<uint8_t> image(size_t(vw) * vh * 4);
    auto reconstructRows = [&](uint32_t rowBegin, uint32_t rowEnd) {
        for (uint32_t y = rowBegin; y < rowEnd; ++y) {
            const double cy = (y + 0.5) * rowsPerViewPixel;
            uint32_t l0, l1;
            centresInRange(cy - halfHeight, cy + halfHeight, H, l0, l1);
            for (uint32_t x = 0; x < vw; ++x) {
                const double cx = (x + 0.5) * subpixelsPerViewPixel;
                uint32_t k0, k1;
                centresInRange(cx - halfWidth, cx + halfWidth, 3 * W, k0, k1);
                ChannelGather gather[3];
                for (uint32_t l = l0; l < l1; ++l)
                    for (uint32_t k = k0; k < k1; ++k) {
                        // Circular distance of the subpixel's view coordinate from t,
                        // wrapped into [-N/2, N/2).
                        double delta = fixedPhaseToDouble(fixedSubpixelPhase(fixed, k, l)) * N - t;
                        delta -= N * std::floor(delta / N + 0.5);
                        const uint32_t i = k % 3;
                        const uint32_t channel = bgr ? 2 - i : i;
                        gather[channel].add(eia[(size_t(l) * W + k / 3) * 4 + channel], delta);
                    }
                uint8_t* out = &image[(size_t(y) * vw + x) * 4];
                for (uint32_t c = 0; c < 3; ++c)
                    out[c] = gather[c].result();
                out[3] = 255;
            }
        }
    };

    // Rows are independent: bands of them over the cores.
    forEachBand(vh, 8, [&](size_t, size_t begin, size_t end) {
        reconstructRows(uint32_t(begin), uint32_t(end));
    });
    return image;
}

} // namespace lfd::player
