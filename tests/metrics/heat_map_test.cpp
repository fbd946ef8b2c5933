// The magma heat map: its end colours, clamping, increasing lightness, and the atomic PNG
// writer (size, no leftovers, errors).
#include "metric_test_images.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <unistd.h>

namespace fs = std::filesystem;

namespace lfd::metrics {
namespace {

TEST(HeatMap, MagmaEndsAtNearBlackAndPaleYellow)
{
    // magma's first entry (0.001462, 0.000466, 0.013866) and last (0.987053, 0.991438,
    // 0.749504), times 255 and rounded.
    EXPECT_EQ(magma(0.0), (Rgb8{0, 0, 4}));
    EXPECT_EQ(magma(1.0), (Rgb8{252, 253, 191}));
    // The table's middle entry 128 (at t = 128/255) is an anchor: (0.716387, 0.214982, 0.475290).
    EXPECT_EQ(magma(128.0 / 255.0), (Rgb8{183, 55, 121}));
}

TEST(HeatMap, ClampsOutOfRangeValuesAndShowsNaNAsTheTop)
{
    EXPECT_EQ(magma(-3.0), magma(0.0));
    EXPECT_EQ(magma(7.0), magma(1.0));
    EXPECT_EQ(magma(std::nan("")), magma(1.0));
}

TEST(HeatMap, LightnessIncreasesAlongTheMap)
{
    double previous = -1.0;
    for (int i = 0; i <= 20; ++i) {
        const Rgb8 c = magma(i / 20.0);
        const double luma = 0.299 * c.r + 0.587 * c.g + 0.114 * c.b;
        EXPECT_GT(luma, previous) << i;
        previous = luma;
    }
}

TEST(HeatMap, OneColourPerValue)
{
    const std::vector<float> values = {0.0f, 1.0f, 0.5f};
    const std::vector<uint8_t> rgb = heatMapRgb8(values);
    ASSERT_EQ(rgb.size(), 9u);
    EXPECT_EQ((Rgb8{rgb[0], rgb[1], rgb[2]}), magma(0.0));
    EXPECT_EQ((Rgb8{rgb[3], rgb[4], rgb[5]}), magma(1.0));
    EXPECT_EQ((Rgb8{rgb[6], rgb[7], rgb[8]}), magma(0.5));
}

TEST(HeatMap, WritesAPngOfTheMapSizeAtomically)
{
    const fs::path dir = fs::temp_directory_path() / ("lfd_heat_map_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::vector<float> values(7 * 3);
    for (size_t i = 0; i < values.size(); ++i)
        values[i] = float(i) / float(values.size() - 1);
    writeHeatMap(dir / "map.png", values, 7, 3);

    const RgbImage back = readRgbImage(dir / "map.png");
    EXPECT_EQ(back.width, 7);
    EXPECT_EQ(back.height, 3);
    EXPECT_EQ(back.rgb[0], 0.0f);
    EXPECT_EQ(back.rgb[2], 4.0f);
    EXPECT_EQ(back.rgb[20 * 3 + 1], 253.0f);
    // Only the target: the temporary file was renamed, not left beside it.
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);

    EXPECT_THROW(writeHeatMap(dir / "bad.png", values, 7, 4), ImageError);
    EXPECT_THROW(writeHeatMap(dir / "missing_dir" / "map.png", values, 7, 3), ImageError);
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
    fs::remove_all(dir);
}

} // namespace
} // namespace lfd::metrics
