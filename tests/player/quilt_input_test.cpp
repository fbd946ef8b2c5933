// Quilt input (--quilt-in): layout from the file name, views cut from the tiles (exactly,
// or resampled when the image is not a multiple of the grid), letter- and pillarboxing
// for another aspect, and the EIA of a quilt of another layout (5x9) against the CPU
// reference for that many views.
#include "display_test_profiles.h"
#include "gl_test_support.h"

#include "eia_builder.h"
#include "gpu_timer.h"
#include "image_metrics.h"
#include "quilt.h"
#include "quilt_input.h"
#include "quilt_slideshow.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

namespace lfd::test {
namespace {

namespace fs = std::filesystem;
using player::QuiltInputError;
using player::QuiltLayout;

std::string errorOf(const std::function<void()>& f)
{
    try {
        f();
    } catch (const QuiltInputError& e) {
        return e.what();
    }
    return {};
}

TEST(QuiltInput, LayoutFromTheFileName)
{
    player::QuiltName q = player::parseQuiltName("dir/scene_qs8x6a0.75.png");
    EXPECT_EQ(q.cols, 8u);
    EXPECT_EQ(q.rows, 6u);
    EXPECT_DOUBLE_EQ(q.aspect, 0.75);
    q = player::parseQuiltName("clip_0003_qs5x9a1.78.jpg");
    EXPECT_EQ(q.cols, 5u);
    EXPECT_EQ(q.rows, 9u);
    EXPECT_DOUBLE_EQ(q.aspect, 1.78);
    EXPECT_DOUBLE_EQ(player::parseQuiltName("a_qs4x4a2.png").aspect, 2.0);
    q = player::parseQuiltName("old_qs2x2a1_qs8x6a0.75.png"); // the last suffix counts
    EXPECT_EQ(q.cols, 8u);

    // No aspect (older tools): 0, the views are shown at the screen's aspect.
    q = player::parseQuiltName("old_qs4x3.png");
    EXPECT_EQ(q.cols, 4u);
    EXPECT_EQ(q.rows, 3u);
    EXPECT_EQ(q.aspect, 0.0);

    for (const char* bad : {"scene.png", "scene_qs8x6a.png", "scene_qs0x6a0.75.png", "scene_qs8x6a0.png",
                            "scene_qsAx6a1.png", "scene_qs8x6a.5.png"}) {
        const std::string e = errorOf([&] { player::parseQuiltName(bad); });
        EXPECT_NE(e.find(bad), std::string::npos) << "names the file: " << e;
        EXPECT_EQ(e.find('\n'), std::string::npos);
    }
}

// --quilt-layout CxR[aASPECT]: read instead of the name's; an aspect it lacks comes from
// the name.
TEST(QuiltInput, LayoutFlagReplacesTheName)
{
    const player::QuiltName flag = player::parseQuiltLayout("5x9a1.78", "--quilt-layout");
    EXPECT_EQ(flag.cols * 10 + flag.rows, 59u);
    EXPECT_DOUBLE_EQ(flag.aspect, 1.78);
    EXPECT_EQ(player::parseQuiltLayout("4x3", "--quilt-layout").aspect, 0.0);
    for (const char* bad : {"4x", "4x3a", "0x3", "4x3a0", "x", "4x3a1.5junk"}) {
        const std::string e = errorOf([&] { player::parseQuiltLayout(bad, "--quilt-layout"); });
        EXPECT_NE(e.find("--quilt-layout"), std::string::npos) << bad << ": " << e;
    }
    player::QuiltName q = player::quiltNameOf("plain.png", player::QuiltName{4, 3, 1.5});
    EXPECT_EQ(q.cols, 4u);
    q = player::quiltNameOf("x_qs8x6a0.75.png", player::QuiltName{4, 3, 0.0});
    EXPECT_EQ(q.cols, 4u);
    EXPECT_DOUBLE_EQ(q.aspect, 0.75);
    EXPECT_EQ(player::quiltNameOf("x_qs8x6a0.75.png", std::nullopt).cols, 8u);
    EXPECT_EQ(player::listQuiltFiles(fs::path(LFD_SOURCE_DIR) / "README.md", true).size(), 1u);
}

TEST(QuiltInput, FolderIsASortedSlideshowOfQuiltImages)
{
    const fs::path dir = testOutputDir("quilt_input_folder");
    for (const char* name : {"b_qs2x2a1.png", "a_qs2x2a1.png", "notes_qs2x2a1.txt", "plain.png"})
        std::ofstream(dir / name) << "x";
    const std::vector<fs::path> files = player::listQuiltFiles(dir);
    ASSERT_EQ(files.size(), 2u);
    EXPECT_EQ(files[0].filename(), "a_qs2x2a1.png");
    EXPECT_EQ(files[1].filename(), "b_qs2x2a1.png");
    EXPECT_EQ(player::listQuiltFiles(dir / "a_qs2x2a1.png").size(), 1u);
    EXPECT_NE(errorOf([&] { player::listQuiltFiles(dir / "plain.png"); }).find("no quilt layout"), std::string::npos);
    EXPECT_NE(errorOf([&] { player::listQuiltFiles(dir / "missing"); }).find("no such"), std::string::npos);
    const fs::path empty = testOutputDir("quilt_input_empty");
    EXPECT_NE(errorOf([&] { player::listQuiltFiles(empty); }).find("holds no quilt"), std::string::npos);
}

// View v: a ramp in x and y with a per-view offset, so every pixel of every view differs.
std::vector<std::vector<uint8_t>> rampViews(uint32_t count, uint32_t w, uint32_t h)
{
    std::vector<std::vector<uint8_t>> views;
    for (uint32_t v = 0; v < count; ++v) {
        std::vector<uint8_t> image(size_t(w) * h * 4);
        for (uint32_t y = 0; y < h; ++y)
            for (uint32_t x = 0; x < w; ++x) {
                uint8_t* p = &image[(size_t(y) * w + x) * 4];
                p[0] = uint8_t(x * 7 + v);
                p[1] = uint8_t(y * 11 + 3 * v);
                p[2] = uint8_t(v * 9);
                p[3] = 255;
            }
        views.push_back(std::move(image));
    }
    return views;
}

metrics::Image quiltImage(const QuiltLayout& layout, const std::vector<std::vector<uint8_t>>& views)
{
    return {layout.width(), layout.height(), 4, player::assembleQuilt(layout, views)};
}

TEST(QuiltInput, TilesAreCutExactlyWhenTheImageIsAMultipleOfTheGrid)
{
    const QuiltLayout layout{3, 2, 5, 4};
    const auto views = rampViews(6, 5, 4);
    const player::QuiltViews cut = player::extractQuiltViews(quiltImage(layout, views), {3, 2, 1.25}, 0, 1.25);
    EXPECT_EQ(cut.width, 5u);
    EXPECT_EQ(cut.height, 4u);
    EXPECT_EQ(cut.views, views); // view 0 bottom-left, then right and upwards
    // Fewer views than tiles: the trailing (empty) tiles are skipped.
    EXPECT_EQ(player::extractQuiltViews(quiltImage(layout, views), {3, 2, 1.25}, 5, 1.25).views.size(), 5u);
    EXPECT_FALSE(errorOf([&] { player::extractQuiltViews(quiltImage(layout, views), {3, 2, 1.25}, 7, 1.25); }).empty());
}

// A 10x4 quilt of 3x2 tiles: tiles are 3x2 pixels but span 3.33 x 2 quilt pixels, so each
// view pixel centre is resampled bilinearly. On a horizontal ramp (20 per quilt pixel)
// bilinear interpolation is exact: view x of tile column c samples the quilt at
// qx = (3c + x + 0.5) * 10 / 9 - 0.5, clamped to the tile's pixels.
TEST(QuiltInput, TilesAreResampledWhenTheImageIsNotAMultipleOfTheGrid)
{
    metrics::Image q{10, 4, 4, std::vector<uint8_t>(10 * 4 * 4)};
    for (uint32_t y = 0; y < 4; ++y)
        for (uint32_t x = 0; x < 10; ++x) {
            uint8_t* p = &q.pixels[(y * 10 + x) * 4];
            p[0] = uint8_t(20 * x);
            p[1] = uint8_t(50 * y);
            p[2] = 0;
            p[3] = 255;
        }
    const player::QuiltViews cut = player::extractQuiltViews(q, {3, 2, 1.0}, 0, 0.0);
    ASSERT_EQ(cut.width, 3u);
    ASSERT_EQ(cut.height, 2u);
    // Tile column 1 covers quilt x in [3.33, 6.67): pixels 3..6. qx = 3.389, 4.5, 5.611.
    const uint8_t expected[3] = {68, 90, 112};
    for (uint32_t x = 0; x < 3; ++x)
        EXPECT_EQ(cut.views[1][x * 4], expected[x]) << x; // view 1: bottom row, column 1
    // Tile column 0 (pixels 0..2): qx = 0.056 -> 1, 1.167 -> 23, and 2.278 is clamped to
    // pixel 2 -> 40: pixel 3 is two thirds tile 1, so it is never read for tile 0.
    EXPECT_EQ(cut.views[0][0], 1);
    EXPECT_EQ(cut.views[0][4], 23);
    EXPECT_EQ(cut.views[0][8], 40);
    // Rows: view 0 is the bottom tile row (quilt rows 2, 3): exact, 100 and 150.
    EXPECT_EQ(cut.views[0][1], 100);
    EXPECT_EQ(cut.views[0][3 * 4 + 1], 150);
}

TEST(QuiltInput, AnotherAspectIsBoxedNotStretched)
{
    const QuiltLayout layout{2, 1, 4, 4};
    const auto views = rampViews(2, 4, 4);
    // Square views on a 2:1 screen: pillarbox to 8x4, the view in columns 2..5.
    player::QuiltViews cut = player::extractQuiltViews(quiltImage(layout, views), {2, 1, 1.0}, 0, 2.0);
    ASSERT_EQ(cut.width, 8u);
    ASSERT_EQ(cut.height, 4u);
    for (uint32_t y = 0; y < 4; ++y)
        for (uint32_t x = 0; x < 8; ++x) {
            const uint8_t* p = &cut.views[1][(y * 8 + x) * 4];
            if (x < 2 || x >= 6)
                EXPECT_EQ(p[0] + p[1] + p[2], 0) << x << "," << y;
            else
                EXPECT_EQ(p[0], views[1][(y * 4 + x - 2) * 4]) << x << "," << y;
            EXPECT_EQ(p[3], 255);
        }
    // 2:1 views on a square screen: letterbox to 4x8.
    cut = player::extractQuiltViews(quiltImage(layout, views), {2, 1, 2.0}, 0, 1.0);
    EXPECT_EQ(cut.width, 4u);
    EXPECT_EQ(cut.height, 8u);
    // 1.78 in the name on a 16:9 screen (1.7778): within 1%, stretched over the screen.
    cut = player::extractQuiltViews(quiltImage(layout, views), {2, 1, 1.78}, 0, 16.0 / 9.0);
    EXPECT_EQ(cut.width, 4u);
    EXPECT_EQ(cut.height, 4u);
}

class QuiltInputGl : public GlTest {};

// A 5x9 quilt (45 views, e.g. a Looking Glass 16" quilt) on a 24-view panel: the EIA is
// built from the 45 views - each subpixel takes view floor(phase * 45) at its screen
// position - exactly as the CPU reference does for a 45-view profile.
TEST_F(QuiltInputGl, QuiltOfAnotherLayoutIsInterleavedFromItsOwnViews)
{
    const DisplayProfile panel = player::displaytest::smallProfile(); // 480x270, 24 views
    const uint32_t w = 24, h = 16;
    std::vector<std::vector<uint8_t>> views;
    for (uint32_t v = 0; v < 45; ++v)
        views.push_back(player::displaytest::smoothView(v, 45, w, h));
    const fs::path dir = testOutputDir("quilt_input_5x9");
    const fs::path file = dir / "other_qs5x9a1.78.png";
    const QuiltLayout layout{5, 9, w, h};
    metrics::writeImage(file, player::assembleQuilt(layout, views).data(), layout.width(), layout.height(), 4);

    player::QuiltSlideshow show(panel, {file}, 0, 5.0);
    EXPECT_EQ(show.profile().viewCount, 45u);
    EXPECT_EQ(show.profile().viewWidth, w);
    player::GpuTimer timer;
    show.renderFrame(0.0, timer, player::Reconstruction::None);
    const std::vector<uint8_t> gpu = show.eia().read();
    const std::vector<uint8_t> cpu = player::buildEiaCpu(withViews(panel, 45, w, h), views, w, h);
    EXPECT_TRUE(gpu == cpu) << "EIA of the 5x9 quilt differs from the 45-view reference";
    // And it is not the 24-view interleaving of the first 24 views.
    const std::vector<std::vector<uint8_t>> first24(views.begin(), views.begin() + 24);
    EXPECT_FALSE(gpu == player::buildEiaCpu(withViews(panel, 24, w, h), first24, w, h));
}

// A folder plays as a slideshow: frame times pick the quilt, layouts may differ.
TEST_F(QuiltInputGl, FolderSlideshowFollowsTheClock)
{
    const DisplayProfile panel = player::displaytest::smallProfile();
    const fs::path dir = testOutputDir("quilt_input_slides");
    const auto views = rampViews(6, 16, 9);
    const QuiltLayout a{3, 2, 16, 9}, b{2, 3, 16, 9};
    metrics::writeImage(dir / "1_qs3x2a1.78.png", player::assembleQuilt(a, views).data(), a.width(), a.height(), 4);
    metrics::writeImage(dir / "2_qs2x3a1.78.png", player::assembleQuilt(b, views).data(), b.width(), b.height(), 4);
    player::QuiltSlideshow show(panel, player::listQuiltFiles(dir), 0, 2.0);
    player::GpuTimer timer;
    show.renderFrame(1.9, timer, player::Reconstruction::None);
    EXPECT_EQ(show.currentFile().filename(), "1_qs3x2a1.78.png");
    show.renderFrame(2.0, timer, player::Reconstruction::None);
    EXPECT_EQ(show.currentFile().filename(), "2_qs2x3a1.78.png");
    show.renderFrame(4.5, timer, player::Reconstruction::None); // loops
    EXPECT_EQ(show.currentFile().filename(), "1_qs3x2a1.78.png");
    // Both layouts hold the same 6 views: the same EIA.
    const auto eiaA = show.eia().read();
    show.renderFrame(3.0, timer, player::Reconstruction::None);
    EXPECT_TRUE(show.eia().read() == eiaA);
}

} // namespace
} // namespace lfd::test
