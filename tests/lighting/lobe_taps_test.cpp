// The lobe tap table and its fit: the table compiled in is the fit's optimum (refitting
// sampled texels finds nothing better), the two lookups follow the lobe several times
// closer than one lookup at the dominant direction, the table's bounds, n = v (both read
// alpha: the split sum's exact case), and its GL_LINEAR read.
#include "brdf.h"
#include "lobe_tap_fit.h"
#include "lobe_taps.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace lfd::lighting {
namespace {

const LookupLobeShares& shares()
{
    static const LookupLobeShares s;
    return s;
}

TEST(LobeTaps, TheTableIsTheFitsOptimum)
{
    // Texels across the table (column = n.v, row = roughness; 31 = 1): refitted from the
    // stored value and the generic start, the fit finds nothing better than the table.
    const LobeTapTable& table = lobeTapTable();
    ASSERT_EQ(table.size, 32u);
    for (const auto& [column, row] : {std::pair{6u, 16u}, std::pair{19u, 16u}, std::pair{12u, 8u}, std::pair{25u, 24u},
                                      std::pair{3u, 28u}}) {
        const float nDotV = float(column) / 31.0f, roughness = float(row) / 31.0f;
        const float alpha = alphaFromRoughness(roughness);
        const std::vector<HalfSpaceShare> halfSpaces = lobeHalfSpaces(nDotV, alpha);
        const LobeTaps stored = table.texel(column, row);
        const LobeTaps refit = fitLobeTaps(shares(), nDotV, roughness, {stored});
        const double storedDistance = lobeTapDistance(shares(), halfSpaces, nDotV, alpha, stored);
        const double refitDistance = lobeTapDistance(shares(), halfSpaces, nDotV, alpha, refit);
        const double oneDistance = lobeTapDistance(shares(), halfSpaces, nDotV, alpha, dominantDirectionTaps(roughness));
        std::printf("n.v %.2f roughness %.2f: stored %.4f refit %.4f one lookup %.4f\n", nDotV, roughness, storedDistance,
                    refitDistance, oneDistance);
        EXPECT_LE(storedDistance, refitDistance + 1e-4) << column << " " << row;
        EXPECT_LT(storedDistance, oneDistance) << column << " " << row;
    }
}

TEST(LobeTaps, TwoLookupsFollowTheLobeCloserThanOne)
{
    // Roughness 0.5 at grazing, middle and near-normal n.v: the lobe's shares of the
    // half-spaces are 3 to 5 times closer (fitted at texels, read here between them).
    const LobeTapTable& table = lobeTapTable();
    for (const float nDotV : {0.25f, 0.5f, 0.8f}) {
        const float alpha = 0.25f;
        const std::vector<HalfSpaceShare> halfSpaces = lobeHalfSpaces(nDotV, alpha);
        const double two = lobeTapDistance(shares(), halfSpaces, nDotV, alpha, sampleLobeTapTable(table, nDotV, 0.5f));
        const double one = lobeTapDistance(shares(), halfSpaces, nDotV, alpha, dominantDirectionTaps(0.5f));
        std::printf("roughness 0.5, n.v %.2f: two lookups %.4f, one %.4f\n", nDotV, two, one);
        EXPECT_LT(two, one / 3.0) << nDotV;
    }
}

TEST(LobeTaps, BoundsAndNormalIncidence)
{
    const LobeTapTable& table = lobeTapTable();
    for (uint32_t row = 0; row < table.size; ++row) {
        const float roughness = float(row) / float(table.size - 1);
        const float log2Alpha = std::log2(alphaFromRoughness(roughness));
        for (uint32_t column = 0; column < table.size; ++column) {
            const glm::vec4 t = table.texel(column, row);
            if (log2Alpha < LookupLobeShares::kMinLog2Alpha) {
                // Below the first GGX level: the one lookup, twice.
                for (int c = 0; c < 4; ++c)
                    EXPECT_NEAR(t[c], dominantDirectionTaps(roughness)[c], 1e-5f) << column << " " << row;
                continue;
            }
            for (const int k : {0, 2}) {
                EXPECT_GE(t[k], 0.0f);
                EXPECT_LE(t[k], 1.5f);
                EXPECT_GE(log2Alpha + t[k + 1], LookupLobeShares::kMinLog2Alpha - 1e-4f);
                EXPECT_LE(log2Alpha + t[k + 1], LookupLobeShares::kMaxLog2Alpha + 1e-4f);
            }
            EXPECT_GE(t[0], t[2]); // tap 0 is the one nearer R
        }
        // At n = v the lobe is the prefiltered one of alpha: the two read alpha (their mean
        // width within a quarter of a level).
        const glm::vec4 normal = table.texel(table.size - 1, row);
        EXPECT_NEAR(0.5f * (normal[1] + normal[3]), 0.0f, 0.25f) << row;
    }
}

TEST(LobeTaps, ReadsLikeGlLinear)
{
    const LobeTapTable& table = lobeTapTable();
    // Texel centres read back exactly; half way between two columns, the mean; clamped.
    EXPECT_EQ(sampleLobeTapTable(table, 7.0f / 31.0f, 12.0f / 31.0f), table.texel(7, 12));
    const glm::vec4 between = sampleLobeTapTable(table, 7.5f / 31.0f, 12.0f / 31.0f);
    const glm::vec4 mean = 0.5f * (table.texel(7, 12) + table.texel(8, 12));
    for (int c = 0; c < 4; ++c)
        EXPECT_NEAR(between[c], mean[c], 1e-5f);
    EXPECT_EQ(sampleLobeTapTable(table, 2.0f, -1.0f), table.texel(31, 0));
}

} // namespace
} // namespace lfd::lighting
