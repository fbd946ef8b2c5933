// The EIA round trip: views -> EIA -> simulated viewer at each view centre -> views.
#include "simulated_viewer.h"

#include "display_test_profiles.h"
#include "eia_builder.h"
#include "image_metrics.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>

using namespace lfd;
using namespace lfd::player;
using namespace lfd::metrics;

namespace {

Image rgba(const std::vector<uint8_t>& pixels, uint32_t w, uint32_t h) {
    return Image{w, h, 4, pixels};
}

struct RoundTrip {
    double worstRmse = 0.0;    // reconstruction of view i vs view i, worst over views
    double worstPsnr = 1e9;    // dB
    double bestOtherRmse = 1e9; // reconstruction of view i vs view i + 2, best over views
};

// Reconstructs the listed views from `eia` at their centres t = i + 0.5 and compares them
// with the originals and with the views two steps away.
RoundTrip roundTrip(const DisplayProfile& profile, const std::vector<uint8_t>& eia,
                    const std::vector<std::vector<uint8_t>>& views,
                    const std::vector<uint32_t>& which) {
    RoundTrip r;
    const uint32_t w = profile.viewWidth, h = profile.viewHeight, N = profile.viewCount;
    for (uint32_t i : which) {
        const Image seen = rgba(simulateViewer(profile, eia, i + 0.5), w, h);
        const Image original = rgba(views[i], w, h);
        const Image other = rgba(views[(i + 2) % N], w, h);
        r.worstRmse = std::max(r.worstRmse, rmse(seen, original));
        r.worstPsnr = std::min(r.worstPsnr, psnr(seen, original));
        r.bestOtherRmse = std::min(r.bestOtherRmse, rmse(seen, other));
    }
    return r;
}

std::vector<uint32_t> allViews(const DisplayProfile& profile) {
    std::vector<uint32_t> all(profile.viewCount);
    for (uint32_t i = 0; i < profile.viewCount; ++i)
        all[i] = i;
    return all;
}

} // namespace

// Why the round trip is not exact: each view owns only ~1/N of the subpixels, spread
// along the slanted lenses. In one view pixel's footprint (one lens by 6 rows on both
// profiles used here) each colour of view i is present about once; where the pattern
// misses it, the eye at t = i + 0.5 sees the neighbouring view zones i - 1 and i + 1
// instead (interpolated), which differ from view i on view-dependent content; and every
// average is rounded to 8 bits. On the smooth test content this costs little: measured
// worst PSNR 57.9 dB (small profile) and 67.2 dB (prototype); the tolerance is 40 dB,
// and view i must be seen 10x closer (RMSE) than view i + 2, which differs by ~18-35 RMSE.
TEST(SimulatedViewer, SmallProfileRoundTrip) {
    const DisplayProfile profile = displaytest::smallProfile();
    const auto views = displaytest::smoothViews(profile);
    const auto eia = buildEiaCpu(profile, views, profile.viewWidth, profile.viewHeight);
    const RoundTrip r = roundTrip(profile, eia, views, allViews(profile));
    std::printf("[ numbers  ] small profile (24 views 120x45): worst RMSE %.2f, worst PSNR "
                "%.1f dB, RMSE to view i+2 at best %.1f\n",
                r.worstRmse, r.worstPsnr, r.bestOtherRmse);
    EXPECT_GT(r.worstPsnr, 40.0);
    // Discrimination: the eye at view i's centre sees view i, not a neighbour.
    EXPECT_GT(r.bestOtherRmse, 10.0 * r.worstRmse);
}

TEST(SimulatedViewer, BgrAndInvertedRoundTrip) {
    // The viewer reads the mapping the EIA was built with: order and inversion must cancel.
    for (const DisplayProfile& profile : {displaytest::smallProfile("BGR"), displaytest::smallProfile("RGB", true)}) {
        const auto views = displaytest::smoothViews(profile);
        const auto eia = buildEiaCpu(profile, views, profile.viewWidth, profile.viewHeight);
        const RoundTrip r = roundTrip(profile, eia, views, {0, 5, 11, 23});
        EXPECT_GT(r.worstPsnr, 40.0);
        EXPECT_GT(r.bestOtherRmse, 10.0 * r.worstRmse);
    }
}

TEST(SimulatedViewer, PrototypeRoundTrip) {
    // The real configuration on the CPU: 48 views of 480x360 onto 3840x2160. Six views
    // (both ends, the middle) are reconstructed to keep the test short.
    const DisplayProfile profile = prototypeDisplayProfile();
    const auto views = displaytest::smoothViews(profile);
    const auto start = std::chrono::steady_clock::now();
    const auto eia = buildEiaCpu(profile, views, profile.viewWidth, profile.viewHeight);
    const RoundTrip r = roundTrip(profile, eia, views, {0, 5, 23, 24, 42, 47});
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("[ numbers  ] prototype (48 views 480x360): worst RMSE %.2f, worst PSNR %.1f dB, "
                "RMSE to view i+2 at best %.1f (%.1f s)\n",
                r.worstRmse, r.worstPsnr, r.bestOtherRmse, seconds);
    EXPECT_GT(r.worstPsnr, 40.0);
    EXPECT_GT(r.bestOtherRmse, 10.0 * r.worstRmse);
}

TEST(SimulatedViewer, PrototypeSmallViewsRoundTrip) {
    // 48 views of 48x36 on the full panel: each view pixel covers 80x60 panel pixels, so
    // every channel of every view is present many times in every footprint, and the nearest
    // view EIA holds only that view pixel's value there: the round trip is exact.
    const DisplayProfile profile = withViews(prototypeDisplayProfile(), 48, 48, 36);
    const auto views = displaytest::smoothViews(profile);
    const auto eia = buildEiaCpu(profile, views, profile.viewWidth, profile.viewHeight);
    for (uint32_t i : {0u, 17u, 47u}) {
        const auto seen = simulateViewer(profile, eia, i + 0.5);
        EXPECT_EQ(seen, views[i]) << "view " << i;
    }
}

TEST(SimulatedViewer, BetweenViewsSeesANeighbour) {
    // At t = i (the boundary between views i - 1 and i) the eye sees a mix of both views:
    // closer to either than to a view far away.
    const DisplayProfile profile = displaytest::smallProfile();
    const auto views = displaytest::smoothViews(profile);
    const auto eia = buildEiaCpu(profile, views, profile.viewWidth, profile.viewHeight);
    const uint32_t w = profile.viewWidth, h = profile.viewHeight;
    const Image seen = rgba(simulateViewer(profile, eia, 12.0), w, h);
    const double toNeighbours =
        std::min(rmse(seen, rgba(views[11], w, h)), rmse(seen, rgba(views[12], w, h)));
    const double toFar = rmse(seen, rgba(views[6], w, h));
    EXPECT_LT(toNeighbours * 2.0, toFar);
}

TEST(SimulatedViewer, RejectsBadInput) {
    const DisplayProfile profile = displaytest::smallProfile();
    const std::vector<uint8_t> eia(size_t(profile.panelWidth) * profile.panelHeight * 4, 0);
    EXPECT_THROW(simulateViewer(profile, eia, -0.1), std::invalid_argument);
    EXPECT_THROW(simulateViewer(profile, eia, double(profile.viewCount)), std::invalid_argument);
    EXPECT_THROW(simulateViewer(profile, std::vector<uint8_t>(16), 0.5), std::invalid_argument);
    EXPECT_NO_THROW(simulateViewer(profile, eia, profile.viewCount - 0.01));
}
