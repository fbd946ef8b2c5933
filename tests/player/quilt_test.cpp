// Quilt layout, tile placement and file naming (CPU only).
#include "quilt.h"

#include "lfd/display_profile.h"

#include <gtest/gtest.h>

#include <array>
#include <stdexcept>

using namespace lfd::player;

namespace {

// View v filled with a colour no other view has; pixel (0, 0) (top-left) marked white.
std::array<uint8_t, 4> viewColour(uint32_t v) {
    return {uint8_t(v * 5), uint8_t(250 - v * 5), uint8_t((v * 37) % 256), 255};
}

std::vector<std::vector<uint8_t>> colouredViews(uint32_t count, uint32_t w, uint32_t h) {
    std::vector<std::vector<uint8_t>> views;
    for (uint32_t v = 0; v < count; ++v) {
        std::vector<uint8_t> image(size_t(w) * h * 4);
        const auto c = viewColour(v);
        for (size_t i = 0; i < size_t(w) * h; ++i)
            std::copy(c.begin(), c.end(), &image[i * 4]);
        image[0] = image[1] = image[2] = 255; // top-left marker
        views.push_back(std::move(image));
    }
    return views;
}

std::array<uint8_t, 4> pixelAt(const std::vector<uint8_t>& image, uint32_t width, uint32_t x,
                               uint32_t y) {
    const uint8_t* p = &image[(size_t(y) * width + x) * 4];
    return {p[0], p[1], p[2], p[3]};
}

} // namespace

TEST(Quilt, PrototypeLayoutIs8x6AtPanelSize) {
    const QuiltLayout layout = chooseQuiltLayout(lfd::prototypeDisplayProfile());
    EXPECT_EQ(layout.cols, 8u);
    EXPECT_EQ(layout.rows, 6u);
    EXPECT_EQ(layout.width(), 3840u);
    EXPECT_EQ(layout.height(), 2160u);
    EXPECT_EQ(quiltSuffix(layout.cols, layout.rows, layout.aspect()), "_qs8x6a1.33");
}

TEST(Quilt, LayoutRule) {
    // 45 views of 480x360 on a 16:9 panel: 8x6 still has the panel's shape; the last 3
    // tiles stay empty (9x5 would be 2.4:1, 7x7 4:3).
    QuiltLayout l = chooseQuiltLayout(45, 480, 360, 16.0 / 9.0);
    EXPECT_EQ(l.cols, 8u);
    EXPECT_EQ(l.rows, 6u);
    // Looking Glass Portrait: 48 views of 420x560 into a square quilt -> 8x6 (3360x3360).
    l = chooseQuiltLayout(48, 420, 560, 1.0);
    EXPECT_EQ(l.cols, 8u);
    EXPECT_EQ(l.rows, 6u);
    EXPECT_EQ(quiltSuffix(l.cols, l.rows, l.aspect()), "_qs8x6a0.75");
    // One view: one tile.
    l = chooseQuiltLayout(1, 100, 50, 2.0);
    EXPECT_EQ(l.cols, 1u);
    EXPECT_EQ(l.rows, 1u);
    // Never a whole empty row: rows = ceil(N / cols).
    for (uint32_t n = 1; n <= 100; ++n) {
        l = chooseQuiltLayout(n, 480, 360, 16.0 / 9.0);
        EXPECT_GE(l.cols * l.rows, n);
        EXPECT_LT(l.cols * (l.rows - 1), n) << n;
    }
    EXPECT_THROW(chooseQuiltLayout(0, 480, 360, 1.0), std::invalid_argument);
    EXPECT_THROW(chooseQuiltLayout(8, 0, 360, 1.0), std::invalid_argument);
    EXPECT_THROW(chooseQuiltLayout(8, 480, 360, 0.0), std::invalid_argument);
}

TEST(Quilt, SuffixFormatting) {
    EXPECT_EQ(quiltSuffix(8, 6, 480.0 / 360.0), "_qs8x6a1.33");
    EXPECT_EQ(quiltSuffix(8, 6, 0.75), "_qs8x6a0.75");
    EXPECT_EQ(quiltSuffix(5, 9, 1.5), "_qs5x9a1.5");
    EXPECT_EQ(quiltSuffix(4, 4, 2.0), "_qs4x4a2");
    EXPECT_EQ(quiltSuffix(4, 4, 1.0), "_qs4x4a1");
    EXPECT_EQ(quiltSuffix(11, 1, 0.5625), "_qs11x1a0.56");
}

TEST(Quilt, FileNameInsertsSuffixOnce) {
    const double a = 480.0 / 360.0;
    EXPECT_EQ(quiltFileName("out/quilt.png", 8, 6, a), "out/quilt_qs8x6a1.33.png");
    EXPECT_EQ(quiltFileName("quilt.png", 8, 6, a), "quilt_qs8x6a1.33.png");
    EXPECT_EQ(quiltFileName("a.b/quilt.png", 8, 6, a), "a.b/quilt_qs8x6a1.33.png");
    EXPECT_EQ(quiltFileName("quilt", 8, 6, a), "quilt_qs8x6a1.33.png");
    // Already named by the user: kept (even with a different layout in the name).
    EXPECT_EQ(quiltFileName("out/quilt_qs8x6a1.33.png", 8, 6, a), "out/quilt_qs8x6a1.33.png");
    EXPECT_EQ(quiltFileName("out/q_qs5x9a0.75.png", 8, 6, a), "out/q_qs5x9a0.75.png");
    EXPECT_EQ(quiltFileName("out/q_qs4x4a2.png", 8, 6, a), "out/q_qs4x4a2.png");
    EXPECT_EQ(quiltFileName("out/q_qs8x6a1.33", 8, 6, a), "out/q_qs8x6a1.33.png");
}

TEST(Quilt, TilePlacementBottomLeftFirstThenUpwards) {
    // 48 views of 8x6 pixels on a 16:9 target: 8x6 tiles, quilt 64x36.
    constexpr uint32_t w = 8, h = 6;
    const QuiltLayout layout = chooseQuiltLayout(48, w, h, 16.0 / 9.0);
    ASSERT_EQ(layout.cols, 8u);
    ASSERT_EQ(layout.rows, 6u);
    const auto quilt = assembleQuilt(layout, colouredViews(48, w, h));
    ASSERT_EQ(quilt.size(), size_t(64) * 36 * 4);
    const uint32_t W = layout.width();

    // Centre pixel of the tile at (column, row counted from the bottom).
    auto tileCentre = [&](uint32_t col, uint32_t rowFromBottom) {
        return pixelAt(quilt, W, col * w + w / 2, (5 - rowFromBottom) * h + h / 2);
    };
    EXPECT_EQ(tileCentre(0, 0), viewColour(0));  // view 0: bottom-left
    EXPECT_EQ(tileCentre(7, 0), viewColour(7));  // view 7: bottom-right
    EXPECT_EQ(tileCentre(0, 1), viewColour(8));  // view 8: above view 0
    EXPECT_EQ(tileCentre(3, 2), viewColour(19));
    EXPECT_EQ(tileCentre(7, 5), viewColour(47)); // last view: top-right
    // Every tile, every view.
    for (uint32_t v = 0; v < 48; ++v)
        EXPECT_EQ(tileCentre(v % 8, v / 8), viewColour(v)) << "view " << v;

    // Views keep their orientation: view 0's top-left marker is at the top-left of the
    // bottom-left tile (quilt image row 5 * h), not flipped to the tile's bottom.
    const std::array<uint8_t, 4> white{255, 255, 255, 255};
    EXPECT_EQ(pixelAt(quilt, W, 0, 5 * h), white);
    EXPECT_NE(pixelAt(quilt, W, 0, 6 * h - 1), white);
}

TEST(Quilt, UnusedTilesAreOpaqueBlack) {
    constexpr uint32_t w = 12, h = 9;
    const QuiltLayout layout = chooseQuiltLayout(45, w, h, 16.0 / 9.0);
    ASSERT_EQ(layout.cols, 8u);
    ASSERT_EQ(layout.rows, 6u);
    const auto quilt = assembleQuilt(layout, colouredViews(45, w, h));
    const std::array<uint8_t, 4> black{0, 0, 0, 255};
    // Views 45, 46, 47 would be the last three tiles of the top row.
    for (uint32_t col = 5; col < 8; ++col)
        for (uint32_t y = 0; y < h; ++y)
            for (uint32_t x = 0; x < w; ++x)
                ASSERT_EQ(pixelAt(quilt, layout.width(), col * w + x, y), black);
    EXPECT_EQ(pixelAt(quilt, layout.width(), 4 * w + w / 2, h / 2), viewColour(44));
}

TEST(Quilt, RejectsViewsThatDoNotFit) {
    const QuiltLayout layout{2, 2, 4, 4};
    EXPECT_THROW(assembleQuilt(layout, colouredViews(5, 4, 4)), std::invalid_argument);
    EXPECT_THROW(assembleQuilt(layout, colouredViews(3, 4, 3)), std::invalid_argument);
    EXPECT_NO_THROW(assembleQuilt(layout, colouredViews(3, 4, 4)));
}

// The name carries the aspect each view is shown at - the screen's - so Looking Glass
// players stretch the prototype's 4:3 tiles over its 16:9 screen as the cameras did.
TEST(Quilt, NameAspectIsTheScreensAndSequencesNumberEachFrame) {
    const QuiltLayout layout = chooseQuiltLayout(lfd::prototypeDisplayProfile());
    EXPECT_NEAR(layout.nameAspect(), 345.40 / 194.30, 1e-12);
    EXPECT_EQ(quiltFileName("out/q.png", layout), "out/q_qs8x6a1.78.png");
    EXPECT_EQ(quiltSequenceFileName("out/q.png", layout, 7), "out/q_0007_qs8x6a1.78.png");
    EXPECT_EQ(quiltSequenceFileName("out/q_qs8x6a1.78.png", layout, 12), "out/q_0012_qs8x6a1.78.png");
    EXPECT_EQ(quiltSequenceFileName("q", layout, 12345), "q_12345_qs8x6a1.78.png");
    EXPECT_EQ(quiltSequencePattern("out/q.png", layout), "out/q_%04d_qs8x6a1.78.png");
    // ffmpeg reads a printf pattern: a '%' of the user's name is doubled.
    EXPECT_EQ(quiltSequencePattern("50%/q%d.png", layout), "50%%/q%%d_%04d_qs8x6a1.78.png");
    // Without a screen size the tile's aspect is used.
    EXPECT_DOUBLE_EQ(chooseQuiltLayout(48, 420, 560, 1.0).nameAspect(), 0.75);
}

// A known device's profile writes its vendor's standard quilt: the Looking Glass Portrait
// 8x6 tiles of 420x560 filling 3360x3360 (not the 7x7 of 2940x3920 the aspect rule picks).
TEST(Quilt, LookingGlassPortraitWritesItsStandard8x6Quilt) {
    const lfd::DisplayProfile portrait =
        lfd::loadDisplayProfile(std::filesystem::path(LFD_SOURCE_DIR) / "samples/profiles/looking_glass_portrait_visual.json");
    const QuiltLayout layout = chooseQuiltLayout(portrait);
    EXPECT_EQ(layout.cols, 8u);
    EXPECT_EQ(layout.rows, 6u);
    EXPECT_EQ(layout.width(), 3360u);
    EXPECT_EQ(layout.height(), 3360u);
    EXPECT_EQ(quiltFileName("portrait.png", layout).string(), "portrait_qs8x6a0.75.png");
    // More views than the device's tiles (--views 49): the aspect rule, 7x7 of the panel's shape.
    const QuiltLayout other = chooseQuiltLayout(lfd::withViews(portrait, 49, 0, 0));
    EXPECT_EQ(other.cols * 10 + other.rows, 77u);
    EXPECT_EQ(other.width(), 2940u);
}

// A standard quilt larger than its tiles (8192 for 9 rows of 910) keeps the tiles at the
// bottom-left and the spare pixels black.
TEST(Quilt, SpareStandardQuiltPixelsStayBlack) {
    const QuiltLayout layout{2, 1, 3, 2, 7, 3};
    EXPECT_EQ(layout.width(), 7u);
    EXPECT_EQ(layout.height(), 3u);
    const std::vector<uint8_t> quilt = assembleQuilt(layout, colouredViews(2, 3, 2));
    EXPECT_EQ(pixelAt(quilt, 7, 0, 1), (std::array<uint8_t, 4>{255, 255, 255, 255})); // view 0's marker
    EXPECT_EQ(pixelAt(quilt, 7, 4, 2), viewColour(1));
    EXPECT_EQ(pixelAt(quilt, 7, 6, 2), (std::array<uint8_t, 4>{0, 0, 0, 255}));
    EXPECT_EQ(pixelAt(quilt, 7, 1, 0), (std::array<uint8_t, 4>{0, 0, 0, 255}));
}

// --quilt-layout: other tiles and aspect; too few tiles are refused.
TEST(Quilt, LayoutOverride) {
    const QuiltLayout base = chooseQuiltLayout(lfd::prototypeDisplayProfile());
    const QuiltLayout wide = overrideQuiltLayout(base, 48, 12, 4, 2.0);
    EXPECT_EQ(wide.width(), 12u * 480u);
    EXPECT_EQ(wide.height(), 4u * 360u);
    EXPECT_DOUBLE_EQ(wide.nameAspect(), 2.0);
    EXPECT_DOUBLE_EQ(overrideQuiltLayout(base, 48, 7, 7, 0.0).nameAspect(), base.nameAspect());
    EXPECT_THROW(overrideQuiltLayout(base, 48, 5, 9, 0.0), std::invalid_argument); // 45 < 48
}
