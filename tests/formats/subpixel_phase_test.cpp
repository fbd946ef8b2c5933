// The fixed-point subpixel phase (lfd/subpixel_phase.h, formats/display_profiles.md
// section 2) on EVERY subpixel of every shipped profile - the built-in prototype, each
// samples/profiles/*.json and the 8K panels at their panel-matched view counts - against
// two references:
//  * exact: the same affine form of the profile's doubles evaluated in 128-bit integers at
//    2^-100 (doubles are dyadic rationals, so this is the exact phase wherever every
//    increment is a multiple of 2^-100, which the test checks): the fixed-point view must
//    equal it everywhere, and the fixed-point phase must be it, bit for bit, where the
//    increments are exact at 2^-64;
//  * double: the double-precision path the EIA pass used before (kept here): it may differ
//    only at subpixels whose exact phase lies within 1e-12 of a bin edge j / N. Those
//    near-edge subpixels are listed (printed) per profile.
// CPU only. docs/player/subpixel-phase.md records the counts.
#include "lfd/display_profile.h"
#include "lfd/subpixel_phase.h"
#include "sample_profiles.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace lfd;

namespace {

__extension__ typedef unsigned __int128 Exact; // 2^-100 lens periods, mod 2^100
constexpr int kExactBits = 100;
constexpr Exact kExactMask = (Exact(1) << kExactBits) - 1;
constexpr double kNearEdge = 1e-12; // phase units (lens periods)

struct NamedProfile {
    std::string name; // a gtest name: letters, digits, underscores
    DisplayProfile profile;
};

// The name, not the bytes, in test names and failure messages.
void PrintTo(const NamedProfile& p, std::ostream* os) { *os << p.name; }

// The built-in prototype, every shipped profile file, and the 8K panels at the
// panel-matched view counts (N * w * h = W * H; tests/formats/display_profile_8k_test.cpp).
std::vector<NamedProfile> shippedProfiles() {
    std::vector<NamedProfile> out{{"builtin_prototype", prototypeDisplayProfile()}};
    std::vector<fs::path> files;
    for (const fs::directory_entry& e : fs::directory_iterator(lfd::test::kSampleProfiles))
        if (e.path().extension() == ".json")
            files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (const fs::path& f : files)
        out.push_back({f.stem().string(), loadDisplayProfile(f)});
    for (const NamedProfile& p : std::vector<NamedProfile>(out)) {
        if (p.name == "looking_glass_65_8k")
            out.push_back({p.name + "_72x960x480", withViews(p.profile, 72, 960, 480)});
        if (p.name == "looking_glass_32_8k")
            out.push_back({p.name + "_48x960x720", withViews(p.profile, 48, 960, 720)});
    }
    return out;
}

// x * 2^100 mod 2^100, exactly; false where x has bits below 2^-100.
bool exactFraction(double x, Exact& out) {
    if (x == 0.0) {
        out = 0;
        return true;
    }
    int exponent = 0;
    const auto mantissa = int64_t(std::ldexp(std::frexp(x, &exponent), 53)); // x = m 2^(e - 53)
    const int shift = exponent - 53 + kExactBits;
    if (shift < 0 || shift >= 128)
        return false;
    out = (Exact(mantissa) << shift) & kExactMask; // negative: sign-extended, so mod 2^100 is 1 - |x|
    return true;
}

// The view and the distance to the nearest bin edge (lens periods) of an exact phase.
uint32_t exactView(Exact phase, uint32_t N, double& edgeDistance) {
    const Exact scaled = phase * N;
    const Exact fraction = scaled & kExactMask;
    const Exact toEdge = std::min(fraction, (Exact(1) << kExactBits) - fraction);
    edgeDistance = std::ldexp(double(toEdge), -kExactBits) / double(N);
    return uint32_t(scaled >> kExactBits);
}

// The double-precision phase and view as lfd::subpixelPhase computed them before the fixed point.
uint32_t doubleView(const SubpixelMapping& m, uint32_t k, uint32_t l, uint32_t N) {
    double phase = m.perSubpixel * double(k) + m.perRow * double(l) + m.offset;
    phase -= std::floor(phase);
    if (m.invert)
        phase = 1.0 - phase;
    if (phase >= 1.0)
        phase = 0.0;
    return std::min(uint32_t(std::floor(phase * double(N))), N - 1);
}

struct PanelCheck {
    uint64_t subpixels = 0, exactMismatches = 0, phaseMismatches = 0, doubleMismatches = 0;
    uint64_t doubleMismatchesAwayFromEdges = 0, nearEdge = 0;
    double closest = 1.0; // the smallest distance of an exact phase from a bin edge
    std::vector<std::string> listed; // near-edge subpixels and double-path disagreements
};

void listSubpixel(PanelCheck& c, uint32_t k, uint32_t l, double distance, uint32_t fixedView, uint32_t dblView) {
    if (c.listed.size() >= 50)
        return;
    char line[160];
    std::snprintf(line, sizeof(line), "k=%u l=%u: %.3g lens periods from a bin edge, view %u (double path %u)", k, l,
                  distance, fixedView, dblView);
    c.listed.emplace_back(line);
}

PanelCheck checkEverySubpixel(const DisplayProfile& p, bool phaseExactAt64, const Exact (&exact)[3]) {
    const FixedSubpixelMapping fixed = fixedSubpixelMapping(p.mapping);
    const uint32_t N = p.viewCount;
    PanelCheck c;
    for (uint32_t l = 0; l < p.panelHeight; ++l)
        for (uint32_t k = 0; k < 3 * p.panelWidth; ++k) {
            const uint64_t phase = fixedSubpixelPhase(fixed, k, l);
            const uint32_t view = fixedPhaseView(phase, N);
            Exact e = (exact[0] * k + exact[1] * l + exact[2]) & kExactMask;
            if (p.mapping.invert)
                e = (Exact(0) - e) & kExactMask;
            double distance = 0.0;
            const uint32_t reference = exactView(e, N, distance);
            c.exactMismatches += view != reference;
            c.phaseMismatches += phaseExactAt64 && e != (Exact(phase) << (kExactBits - 64));
            const uint32_t dbl = doubleView(p.mapping, k, l, N);
            const bool near = distance < kNearEdge;
            c.closest = std::min(c.closest, distance);
            c.nearEdge += near;
            c.doubleMismatches += dbl != view;
            c.doubleMismatchesAwayFromEdges += dbl != view && !near;
            if (near || dbl != view)
                listSubpixel(c, k, l, distance, view, dbl);
            ++c.subpixels;
        }
    return c;
}

class SubpixelPhaseEveryProfile : public ::testing::TestWithParam<NamedProfile> {};

} // namespace

TEST(SubpixelPhaseFixedPoint, IncrementsConvertExactlyAboveTwoToTheMinus12) {
    EXPECT_EQ(fixedPhaseFromDouble(0.0), 0u);
    EXPECT_EQ(fixedPhaseFromDouble(0.5), uint64_t(1) << 63);
    EXPECT_EQ(fixedPhaseFromDouble(0.25), uint64_t(1) << 62);
    EXPECT_EQ(fixedPhaseFromDouble(-0.25), uint64_t(3) << 62); // fract(-1/4) = 3/4
    EXPECT_EQ(fixedPhaseFromDouble(3.75), uint64_t(3) << 62);  // whole periods drop out
    EXPECT_EQ(fixedPhaseFromDouble(std::ldexp(1.0, -64)), 1u);
    EXPECT_EQ(fixedPhaseFromDouble(std::ldexp(1.0, -65)), 0u); // a tie: to even
    EXPECT_EQ(fixedPhaseFromDouble(std::ldexp(3.0, -65)), 2u); // a tie: to even
    EXPECT_EQ(fixedPhaseFromDouble(std::ldexp(1.0, -70)), 0u);
    // 1/3 has 53 significant bits from 2^-2: exact, and 3 of them sum to 1 - 2^-54 (the double's own error).
    const uint64_t third = fixedPhaseFromDouble(1.0 / 3.0);
    EXPECT_EQ(third, uint64_t(std::ldexp(1.0 / 3.0, 64)));
    EXPECT_THROW(fixedPhaseFromDouble(std::nan("")), std::invalid_argument);
}

TEST(SubpixelPhaseFixedPoint, ViewIsTheHighWordOfPhaseTimesN) {
    for (uint32_t N : {1u, 2u, 3u, 45u, 48u, 72u, 2048u}) {
        EXPECT_EQ(fixedPhaseView(0, N), 0u);
        EXPECT_EQ(fixedPhaseView(~uint64_t(0), N), N - 1);
        for (uint32_t j = 1; j < std::min(N, 50u); ++j) {
            // The first phase of bin j: ceil(j 2^64 / N).
            const Exact edge = ((Exact(j) << 64) + N - 1) / N;
            EXPECT_EQ(fixedPhaseView(uint64_t(edge), N), j) << N;
            EXPECT_EQ(fixedPhaseView(uint64_t(edge) - 1, N), j - 1) << N;
        }
    }
    // Inversion: 0 stays 0, the rest is 1 - phase.
    FixedSubpixelMapping m;
    m.invert = true;
    EXPECT_EQ(fixedSubpixelPhase(m, 0, 0), 0u);
    m.offset = uint64_t(1) << 62;
    EXPECT_EQ(fixedSubpixelPhase(m, 0, 0), uint64_t(3) << 62);
}

TEST(SubpixelPhaseFixedPoint, SamePhaseStrideIsOneLensOnThePrototypeAndThe8KPanels) {
    // Prototype: 3 / X = 0.12483 per pixel, 8 pixels = 0.99867 periods: 0.064 views off at 48.
    EXPECT_EQ(samePhasePixelStride(prototypeDisplayProfile(), 16, 0.5), 8u);
    const fs::path dir = lfd::test::kSampleProfiles;
    EXPECT_EQ(samePhasePixelStride(loadDisplayProfile(dir / "looking_glass_65_8k.json"), 16, 0.5), 8u);
    EXPECT_EQ(samePhasePixelStride(loadDisplayProfile(dir / "looking_glass_32_8k.json"), 16, 0.5), 8u);
    // About 6.22 pixels per lens: no stride up to 16 comes within half a view; plain order.
    EXPECT_EQ(samePhasePixelStride(loadDisplayProfile(dir / "looking_glass_portrait_visual.json"), 16, 0.5), 1u);
    EXPECT_EQ(samePhasePixelStride(prototypeDisplayProfile(), 4, 0.5), 1u);
}

TEST_P(SubpixelPhaseEveryProfile, FixedPointViewIsExactOnEverySubpixel) {
    const DisplayProfile& p = GetParam().profile;
    Exact exact[3] = {0, 0, 0};
    const double increments[3] = {p.mapping.perSubpixel, p.mapping.perRow, p.mapping.offset};
    bool phaseExactAt64 = true;
    for (int i = 0; i < 3; ++i) {
        ASSERT_TRUE(exactFraction(increments[i], exact[i])) << "increment " << i << " has bits below 2^-100";
        phaseExactAt64 = phaseExactAt64 && (exact[i] & ((Exact(1) << (kExactBits - 64)) - 1)) == 0;
    }
    const PanelCheck c = checkEverySubpixel(p, phaseExactAt64, exact);
    EXPECT_EQ(c.subpixels, uint64_t(3) * p.panelWidth * p.panelHeight);
    EXPECT_EQ(c.exactMismatches, 0u);
    EXPECT_EQ(c.phaseMismatches, 0u);
    EXPECT_EQ(c.doubleMismatchesAwayFromEdges, 0u);
    std::printf("[ phase    ] %s: %ux%u, %u views: %llu subpixels; fixed point = exact%s; %llu within %g of a "
                "bin edge (closest %.3g); double path differs at %llu\n",
                GetParam().name.c_str(), p.panelWidth, p.panelHeight, p.viewCount,
                static_cast<unsigned long long>(c.subpixels),
                phaseExactAt64 ? " (phase bit for bit)" : " (view)", static_cast<unsigned long long>(c.nearEdge),
                kNearEdge, c.closest, static_cast<unsigned long long>(c.doubleMismatches));
    for (const std::string& line : c.listed)
        std::printf("[ phase    ]   %s\n", line.c_str());
    RecordProperty("subpixels", std::to_string(c.subpixels));
    RecordProperty("near_edge", std::to_string(c.nearEdge));
    RecordProperty("double_mismatches", std::to_string(c.doubleMismatches));
}

INSTANTIATE_TEST_SUITE_P(Shipped, SubpixelPhaseEveryProfile, ::testing::ValuesIn(shippedProfiles()),
                         [](const ::testing::TestParamInfo<NamedProfile>& param) { return param.param.name; });
