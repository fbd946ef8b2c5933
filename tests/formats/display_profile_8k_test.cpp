// The shipped 8K profiles (samples/profiles/looking_glass_{32,65}_8k.json): they load, match
// their Looking Glass device's vendor quilt (formats/display_profiles.md section 3), and the
// panel-matched render sizes of docs/player/quilts.md "8K panels" have N * w * h = W * H.
#include "lfd/display_profile.h"
#include "lfd/looking_glass_devices.h"
#include "sample_profiles.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace fs = std::filesystem;
using namespace lfd;

namespace {

struct EightK {
    const char* file;
    uint32_t cols, rows, quiltWidth, quiltHeight; // the vendor's quilt
    uint32_t matchedViews, matchedWidth, matchedHeight; // the panel-matched render size
};

// Looking Glass' "Quilt Settings by Device" table (docs.lookingglassfactory.com/keyconcepts/quilts):
// 32" landscape 7x7 at 8190x8190, 65" 8x9 at 8192x8192.
constexpr EightK kEightK[] = {
    {"looking_glass_32_8k.json", 7, 7, 8190, 8190, 48, 960, 720},
    {"looking_glass_65_8k.json", 8, 9, 8192, 8192, 72, 960, 480},
};
} // namespace

TEST(EightKProfiles, LoadWithTheVendorQuiltAndAPanelMatchedSize)
{
    for (const EightK& e : kEightK) {
        SCOPED_TRACE(e.file);
        const DisplayProfile p = loadDisplayProfile(lfd::test::kSampleProfiles / e.file);
        EXPECT_EQ(p.panelWidth, 7680u);
        EXPECT_EQ(p.panelHeight, 4320u);
        const std::optional<StandardQuilt> quilt = standardQuiltFor(p.panelWidth, p.panelHeight, p.screenWidthMm);
        ASSERT_TRUE(quilt);
        EXPECT_EQ(quilt->cols, e.cols);
        EXPECT_EQ(quilt->rows, e.rows);
        EXPECT_EQ(quilt->width, e.quiltWidth);
        EXPECT_EQ(quilt->height, e.quiltHeight);
        // The shipped views are the vendor's tiles, so quilts export in the vendor layout.
        EXPECT_EQ(p.viewCount, e.cols * e.rows);
        EXPECT_EQ(p.viewWidth, quilt->tileWidth());
        EXPECT_EQ(p.viewHeight, quilt->tileHeight());
        // Panel-matched: one view pixel per panel pixel, and a valid override.
        EXPECT_EQ(uint64_t(e.matchedViews) * e.matchedWidth * e.matchedHeight, uint64_t(p.panelWidth) * p.panelHeight);
        const DisplayProfile matched = withViews(p, e.matchedViews, e.matchedWidth, e.matchedHeight);
        EXPECT_EQ(matched.viewCount, e.matchedViews);
    }
    // The 32" quilt's 7 tiles of 1170 fill 8190 exactly; the 65"'s 9 rows of 910 leave 2 pixels.
    EXPECT_EQ(7u * 1170u, 8190u);
    EXPECT_EQ(9u * 910u + 2u, 8192u);
}
