// Display profiles: the prototype's van Berkel mapping against hand-worked values, the
// project JSON format, Looking Glass visual.json import against LG's own shader formula,
// validation and file errors.
#include "lfd/display_profile.h"
#include "lfd/looking_glass_devices.h"
#include "sample_profiles.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <unistd.h>

namespace {

using namespace lfd;
namespace fs = std::filesystem;


// Runs `f`, expects a DisplayProfileError, returns its message.
std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const DisplayProfileError& e) {
        return e.what();
    } catch (const std::exception& e) {
        ADD_FAILURE() << "wrong exception type: " << e.what();
        return {};
    }
    ADD_FAILURE() << "no exception thrown";
    return {};
}

// "<source>: <field>: <problem>" on one line.
void expectFieldError(const std::string& message, const std::string& source,
                      const std::string& field) {
    EXPECT_EQ(message.rfind(source + ": " + field + ": ", 0), 0u) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

// A temporary directory removed at the end of the test.
struct TempDir {
    fs::path path;
    TempDir() {
        path = fs::temp_directory_path() /
               ("lfd_profile_test_" + std::to_string(::getpid()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(path);
    }
    ~TempDir() {
        std::error_code ec;
        fs::permissions(path / "unreadable.json", fs::perms::owner_all, ec);
        fs::remove_all(path, ec);
    }
    fs::path write(const std::string& name, const std::string& text) const {
        std::ofstream(path / name, std::ios::binary) << text;
        return path / name;
    }
};

// A minimal valid project profile; tests splice keys in and out of it.
std::string minimalProfile(const std::string& extra = "", const std::string& drop = "") {
    const std::pair<const char*, const char*> keys[] = {
        {"panel_width", "3840"},     {"panel_height", "2160"},  {"screen_width_mm", "345.40"},
        {"screen_height_mm", "194.30"}, {"lens_width_mm", "0.72"}, {"lens_tilt_deg", "-9.66"},
        {"view_count", "48"},        {"view_width", "480"},     {"view_height", "360"},
    };
    std::string text = "{";
    bool first = true;
    for (const auto& [key, value] : keys) {
        if (drop == key)
            continue;
        text += std::string(first ? "" : ",") + "\"" + key + "\": " + value;
        first = false;
    }
    if (!extra.empty())
        text += std::string(first ? "" : ",") + extra;
    return text + "}";
}

// Shortest distance between two phases on the unit circle.
double phaseDistance(double a, double b) {
    const double d = std::fabs(a - b);
    return std::min(d, 1.0 - d);
}

// ---- the prototype -------------------------------------------------------------------

TEST(DisplayProfile, PrototypeIsThePapersPanel) {
    const DisplayProfile p = prototypeDisplayProfile();
    EXPECT_EQ(p.panelWidth, 3840u);
    EXPECT_EQ(p.panelHeight, 2160u);
    EXPECT_DOUBLE_EQ(p.screenWidthMm, 345.40);
    EXPECT_DOUBLE_EQ(p.screenHeightMm, 194.30);
    EXPECT_EQ(p.subpixelOrder, SubpixelOrder::RGB);
    EXPECT_DOUBLE_EQ(p.lensWidthMm, 0.72);
    EXPECT_DOUBLE_EQ(p.lensTiltDeg, -9.66);
    EXPECT_EQ(p.viewCount, 48u);
    EXPECT_EQ(p.viewWidth, 480u);
    EXPECT_EQ(p.viewHeight, 360u);
    EXPECT_DOUBLE_EQ(p.viewConeDeg, 40.0);
    EXPECT_DOUBLE_EQ(p.viewingDistanceMm, 600.0);
    EXPECT_FALSE(p.mapping.invert);
    // X = 3 * 3840 / 479.36 = 24.0320427 subpixels per lens (measured count, not 479.72):
    //   perSubpixel = 1/X = 479.36 / 11520 = 0.0416111111
    //   perRow = -3 tan(-9.66 deg) / X = 3 * 0.1702146862 / 24.0320427 = 0.0212484667
    //   offset = 0.5 / X = 0.0208055556
    EXPECT_NEAR(p.mapping.perSubpixel, 0.0416111111, 1e-10);
    EXPECT_NEAR(p.mapping.perRow, 0.0212484667, 1e-10);
    EXPECT_NEAR(p.mapping.offset, 0.0208055556, 1e-10);
    EXPECT_NO_THROW(validateDisplayProfile(p, "prototype"));
}

TEST(DisplayProfile, PrototypeSubpixelToViewHandWorked) {
    const DisplayProfile p = prototypeDisplayProfile();
    // phase = fract((k + 0.5 - 3 l tan(-9.66 deg)) / X), X = 24.0320427, 3 tan = -0.5106441,
    // view = floor(48 phase).
    struct Case {
        uint32_t k, l;
        double phase;
        uint32_t view;
    };
    const Case cases[] = {
        // 0.5 / X = 0.0208056; 48 * 0.0208056 = 0.99867 -> view 0 (just below 1)
        {0, 0, 0.0208055556, 0},
        // 1.5 / X = 0.0624167; * 48 = 2.996 -> view 2
        {1, 0, 0.0624166667, 2},
        // 24.5 / X = 1.0194722 -> 0.0194722; * 48 = 0.9347 -> view 0 (next lens)
        {24, 0, 0.0194722222, 0},
        // (0.5 + 0.5106441) / X = 0.0420540; * 48 = 2.0186 -> view 2
        {0, 1, 0.0420540222, 2},
        // (0.5 + 1079 * 0.5106441) / X = 551.48498 / 24.0320427 = 22.94790 -> 0.94790;
        // * 48 = 45.499 -> view 45
        {0, 1079, 0.9479010767, 45},
        // (5000.5 + 1000 * 0.5106441) / X = 5511.1441 / 24.0320427 = 229.32483 -> 0.32483;
        // * 48 = 15.592 -> view 15
        {5000, 1000, 0.3248277665, 15},
    };
    for (const Case& c : cases) {
        EXPECT_NEAR(subpixelPhase(p, c.k, c.l), c.phase, 1e-9) << "k=" << c.k << " l=" << c.l;
        EXPECT_EQ(subpixelView(p, c.k, c.l), c.view) << "k=" << c.k << " l=" << c.l;
    }
}

TEST(DisplayProfile, PrototypeJsonMatchesBuiltIn) {
    const DisplayProfile a = loadDisplayProfile(lfd::test::kSampleProfiles / "prototype.json");
    const DisplayProfile b = prototypeDisplayProfile();
    EXPECT_EQ(a.name, "prototype");
    EXPECT_EQ(a.panelWidth, b.panelWidth);
    EXPECT_EQ(a.panelHeight, b.panelHeight);
    EXPECT_DOUBLE_EQ(a.screenWidthMm, b.screenWidthMm);
    EXPECT_DOUBLE_EQ(a.screenHeightMm, b.screenHeightMm);
    EXPECT_EQ(a.subpixelOrder, b.subpixelOrder);
    EXPECT_DOUBLE_EQ(a.lensWidthMm, b.lensWidthMm);
    EXPECT_DOUBLE_EQ(a.lensTiltDeg, b.lensTiltDeg);
    EXPECT_DOUBLE_EQ(a.offsetSubpixels, b.offsetSubpixels);
    EXPECT_DOUBLE_EQ(a.mapping.perSubpixel, b.mapping.perSubpixel);
    EXPECT_DOUBLE_EQ(a.mapping.perRow, b.mapping.perRow);
    EXPECT_DOUBLE_EQ(a.mapping.offset, b.mapping.offset);
    EXPECT_EQ(a.mapping.invert, b.mapping.invert);
    EXPECT_EQ(a.viewCount, b.viewCount);
    EXPECT_EQ(a.viewWidth, b.viewWidth);
    EXPECT_EQ(a.viewHeight, b.viewHeight);
    EXPECT_DOUBLE_EQ(a.viewConeDeg, b.viewConeDeg);
    EXPECT_DOUBLE_EQ(a.viewingDistanceMm, b.viewingDistanceMm);
}

TEST(DisplayProfile, LensCountWinsOverLensWidth) {
    // Only lens_width_mm: lens count = 345.40 / 0.72 = 479.7222, 1/X = 479.7222 / 11520.
    const DisplayProfile byWidth = parseDisplayProfile(minimalProfile(), "w.json");
    EXPECT_NEAR(byWidth.mapping.perSubpixel, 479.7222222 / 11520.0, 1e-10);
    EXPECT_DOUBLE_EQ(byWidth.lensWidthMm, 0.72);
    // Both: the measured count drives the mapping, the width stays as given.
    const DisplayProfile both =
        parseDisplayProfile(minimalProfile("\"lens_count\": 479.36"), "b.json");
    EXPECT_NEAR(both.mapping.perSubpixel, 479.36 / 11520.0, 1e-15);
    EXPECT_DOUBLE_EQ(both.lensWidthMm, 0.72);
    // Only lens_count: the width is derived, 345.40 / 500 = 0.6908 mm.
    const DisplayProfile byCount = parseDisplayProfile(
        minimalProfile("\"lens_count\": 500", "lens_width_mm"), "c.json");
    EXPECT_NEAR(byCount.mapping.perSubpixel, 500.0 / 11520.0, 1e-15);
    EXPECT_NEAR(byCount.lensWidthMm, 0.6908, 1e-12);
}

TEST(DisplayProfile, OptionalKeysHaveDocumentedDefaults) {
    const DisplayProfile p = parseDisplayProfile(minimalProfile(), "some/dir/my_panel.json");
    EXPECT_EQ(p.name, "my_panel"); // file stem
    EXPECT_EQ(p.subpixelOrder, SubpixelOrder::RGB);
    EXPECT_DOUBLE_EQ(p.offsetSubpixels, 0.0);
    EXPECT_FALSE(p.mapping.invert);
    EXPECT_DOUBLE_EQ(p.viewConeDeg, 40.0);
    EXPECT_NEAR(p.viewingDistanceMm, 3.0 * 194.30, 1e-12);
    // An empty name also defaults to the stem.
    EXPECT_EQ(parseDisplayProfile(minimalProfile("\"name\": \"\""), "x/y.json").name, "y");
    // The format marker is accepted.
    EXPECT_NO_THROW(parseDisplayProfile(
        minimalProfile("\"format\": \"lfd-display-profile/1\""), "f.json"));
}

TEST(DisplayProfile, GenericExampleLoads) {
    const DisplayProfile p = loadDisplayProfile(lfd::test::kSampleProfiles / "generic_example.json");
    EXPECT_EQ(p.name, "generic-portrait-7.9in");
    EXPECT_EQ(p.panelWidth, 1536u);
    EXPECT_EQ(p.panelHeight, 2048u);
    EXPECT_EQ(p.subpixelOrder, SubpixelOrder::BGR);
    EXPECT_TRUE(p.mapping.invert);
    EXPECT_EQ(p.viewCount, 45u);
    EXPECT_EQ(p.viewWidth, 384u);
    EXPECT_EQ(p.viewHeight, 512u);
    EXPECT_DOUBLE_EQ(p.viewConeDeg, 35.0);
    EXPECT_NEAR(p.viewingDistanceMm, 3.0 * 160.56, 1e-12); // default: three screen heights
    EXPECT_NEAR(p.lensWidthMm, 120.42 / 246.9, 1e-12);     // derived from lens_count
    // X = 3 * 1536 / 246.9 = 18.6634265; tan(-7.9 deg) = -0.1387390; k_off = 3.25.
    // (k, l) = (0, 0): 3.75 / X = 0.2009277 -> inverted 0.7990723; * 45 = 35.958 -> 35
    // (10, 0): 13.75 / X = 0.7367350 -> 0.2632650; * 45 = 11.847 -> 11
    // (0, 100): (3.75 + 41.62171) / X = 2.4314099 -> 0.4314099 -> 0.5685901; * 45 = 25.59 -> 25
    EXPECT_NEAR(subpixelPhase(p, 0, 0), 0.7990722656, 1e-9);
    EXPECT_EQ(subpixelView(p, 0, 0), 35u);
    EXPECT_NEAR(subpixelPhase(p, 10, 0), 0.2632649740, 1e-9);
    EXPECT_EQ(subpixelView(p, 10, 0), 11u);
    EXPECT_NEAR(subpixelPhase(p, 0, 100), 0.5685900936, 1e-9);
    EXPECT_EQ(subpixelView(p, 0, 100), 25u);
}

// ---- Looking Glass -------------------------------------------------------------------

// Looking Glass' lenticular shader, written the way LG writes it (per pixel, texture
// coordinates with v = 0 at the bottom row), as the reference for the affine form.
double lookingGlassShaderPhase(double pitch, double slope, double center, double dpi, double W,
                               double H, bool invView, bool flipImageX, uint32_t x, uint32_t i,
                               uint32_t l) {
    const double pitchU = pitch * W / dpi * std::cos(std::atan(1.0 / slope));
    const double tilt = H / (W * slope) * (flipImageX ? -1.0 : 1.0);
    const double subp = 1.0 / (3.0 * W);
    const double u = (x + 0.5) / W;
    const double v = (H - 1.0 - l + 0.5) / H; // GL window row of our top-down row l
    double a = (u + i * subp + v * tilt) * pitchU - center;
    a -= std::floor(a);
    return invView ? 1.0 - a : a;
}

TEST(DisplayProfile, LookingGlassPortraitImport) {
    const DisplayProfile p = loadDisplayProfile(lfd::test::kSampleProfiles / "looking_glass_portrait_visual.json");
    EXPECT_EQ(p.name, "looking_glass_portrait_visual");
    EXPECT_EQ(p.panelWidth, 1536u);
    EXPECT_EQ(p.panelHeight, 2048u);
    // 1536 / 324 * 25.4 = 120.4148 mm, 2048 / 324 * 25.4 = 160.5531 mm
    EXPECT_NEAR(p.screenWidthMm, 120.4148148, 1e-6);
    EXPECT_NEAR(p.screenHeightMm, 160.5530864, 1e-6);
    EXPECT_EQ(p.subpixelOrder, SubpixelOrder::RGB);
    EXPECT_TRUE(p.mapping.invert);
    EXPECT_EQ(p.viewCount, 48u);
    EXPECT_EQ(p.viewWidth, 420u);
    EXPECT_EQ(p.viewHeight, 560u);
    EXPECT_DOUBLE_EQ(p.viewConeDeg, 40.0);
    EXPECT_NEAR(p.viewingDistanceMm, 3.0 * 160.5530864, 1e-6);
    // pitch_u = 52.58 * (1536 / 324) * cos(atan(-1 / 7.2)) = 52.58 * 4.7407407 * 0.9904930
    //         = 246.89817 lenses across; tilt = 2048 / (1536 * -7.2) = -0.1851852.
    EXPECT_NEAR(p.mapping.perSubpixel, 246.89817469 / 4608.0, 1e-10);
    EXPECT_NEAR(p.mapping.perRow, 246.89817469 * 0.18518518519 / 2048.0, 1e-10);
    EXPECT_NEAR(p.lensTiltDeg, -7.9071627, 1e-6); // atan(1 / slope)
    EXPECT_NEAR(p.lensWidthMm, 120.4148148 / 246.89817469, 1e-9);
    // Pixel (0, top row), subpixel 0: u = 0.5/1536 = 0.00032552, v = 1 - 0.5/2048 = 0.99975586
    //   a = fract((0.00032552 + 0.99975586 * -0.1851852) * 246.89817 - 0.56)
    //     = fract(-0.1848146 * 246.89817 - 0.56) = fract(-46.19035) = 0.80965
    //   invView: 0.19035; * 48 = 9.137 -> view 9.
    EXPECT_NEAR(subpixelPhase(p, 0, 0), 0.1903511329, 1e-8);
    EXPECT_EQ(subpixelView(p, 0, 0), 9u);
    // Subpixel 1 of the same pixel: a grows by subp * pitch_u = 246.89817 / 4608 = 0.0535804,
    // so the inverted phase drops to 0.1367708; * 48 = 6.565 -> view 6.
    EXPECT_NEAR(subpixelPhase(p, 1, 0), 0.1367707999, 1e-8);
    EXPECT_EQ(subpixelView(p, 1, 0), 6u);
    // Bottom row (l = 2047, v = 0.5/2048): the tilt term vanishes,
    //   a = fract((0.00032552 - 0.0000452) * 246.89817 - 0.56) = fract(-0.4907921) = 0.5092079
    //   invView: 0.4907921; * 48 = 23.558 -> view 23.
    EXPECT_NEAR(subpixelPhase(p, 0, 2047), 0.4907920698, 1e-8);
    EXPECT_EQ(subpixelView(p, 0, 2047), 23u);

    // The affine form equals LG's shader everywhere (this checks the v flip, the
    // subpixel offset and the constant term of the derivation).
    std::mt19937 rng(7);
    std::uniform_int_distribution<uint32_t> xs(0, 1535), ls(0, 2047), is(0, 2);
    for (int n = 0; n < 2000; ++n) {
        const uint32_t x = xs(rng), l = ls(rng), i = is(rng);
        const double expected = lookingGlassShaderPhase(52.58, -7.2, 0.56, 324.0, 1536.0,
                                                        2048.0, true, false, x, i, l);
        ASSERT_LT(phaseDistance(subpixelPhase(p, 3 * x + i, l), expected), 1e-9)
            << "x=" << x << " i=" << i << " l=" << l;
    }
}

TEST(DisplayProfile, LookingGlassBareNumbersAndFlags) {
    // Bare numbers, flipImageX (tilt negated), flipSubp (BGR), invView 0, no viewCone.
    const std::string text = R"({"pitch": 47.6, "slope": -5.48, "center": -0.4, "DPI": 338,
        "screenW": 2560, "screenH": 1600, "invView": 0, "flipImageX": 1, "flipSubp": 1,
        "serial": "ignored", "fringe": 0.0})";
    const DisplayProfile p = parseDisplayProfile(text, "lg.json");
    EXPECT_EQ(p.subpixelOrder, SubpixelOrder::BGR);
    EXPECT_FALSE(p.mapping.invert);
    EXPECT_DOUBLE_EQ(p.viewConeDeg, 40.0);
    EXPECT_GT(p.lensTiltDeg, 0.0); // atan(+1/5.48) = +10.34 deg after the flip
    EXPECT_NEAR(p.lensTiltDeg, 10.3421, 1e-3);
    EXPECT_EQ(p.viewWidth, 896u); // 560 * 2560 / 1600
    EXPECT_EQ(p.viewHeight, 560u);
    std::mt19937 rng(11);
    std::uniform_int_distribution<uint32_t> xs(0, 2559), ls(0, 1599), is(0, 2);
    for (int n = 0; n < 500; ++n) {
        const uint32_t x = xs(rng), l = ls(rng), i = is(rng);
        const double expected = lookingGlassShaderPhase(47.6, -5.48, -0.4, 338.0, 2560.0,
                                                        1600.0, false, true, x, i, l);
        ASSERT_LT(phaseDistance(subpixelPhase(p, 3 * x + i, l), expected), 1e-9);
    }
}

TEST(DisplayProfile, LookingGlassErrorsNameTheKey) {
    const std::string base = R"("pitch": {"value": 52.58}, "slope": {"value": -7.2}, "DPI": 324,
        "screenW": 1536, "screenH": 2048)";
    expectFieldError(errorOf([&] { parseDisplayProfile("{" + base + "}", "lg.json"); }),
                     "lg.json", "center");
    expectFieldError(errorOf([&] {
                         parseDisplayProfile("{" + base + R"(, "center": {"val": 1}})", "lg.json");
                     }),
                     "lg.json", "center");
    expectFieldError(errorOf([&] {
                         parseDisplayProfile("{" + base + R"(, "center": "0.5"})", "lg.json");
                     }),
                     "lg.json", "center");
    expectFieldError(errorOf([&] {
                         parseDisplayProfile(
                             "{" + base + R"(, "center": 0.5, "flipImageY": {"value": 1}})",
                             "lg.json");
                     }),
                     "lg.json", "flipImageY");
    expectFieldError(errorOf([&] {
                         parseDisplayProfile("{" + base + R"(, "center": 0.5, "invView": 2})",
                                             "lg.json");
                     }),
                     "lg.json", "invView");
    expectFieldError(errorOf([&] {
                         parseDisplayProfile(R"({"pitch": -1, "slope": -7.2, "center": 0.5,
                             "DPI": 324, "screenW": 1536, "screenH": 2048})",
                                             "lg.json");
                     }),
                     "lg.json", "pitch");
    expectFieldError(errorOf([&] {
                         parseDisplayProfile(R"({"pitch": 50, "slope": -7.2, "center": 0.5,
                             "DPI": 324, "screenW": 1536.5, "screenH": 2048})",
                                             "lg.json");
                     }),
                     "lg.json", "screenW");
    expectFieldError(errorOf([&] {
                         parseDisplayProfile("{" + base + R"(, "center": 0.5, "viewCone": 180})",
                                             "lg.json");
                     }),
                     "lg.json", "viewCone");
}

// ---- validation ----------------------------------------------------------------------

TEST(DisplayProfile, ValidationRejectsEveryBadField) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    struct Case {
        const char* field;
        std::function<void(DisplayProfile&)> mutate;
    };
    const Case cases[] = {
        {"panel_width", [](DisplayProfile& p) { p.panelWidth = 0; }},
        {"panel_height", [](DisplayProfile& p) { p.panelHeight = 0; }},
        {"screen_width_mm", [](DisplayProfile& p) { p.screenWidthMm = 0.0; }},
        {"screen_width_mm", [](DisplayProfile& p) { p.screenWidthMm = -345.4; }},
        {"screen_width_mm", [&](DisplayProfile& p) { p.screenWidthMm = nan; }},
        {"screen_height_mm", [&](DisplayProfile& p) { p.screenHeightMm = inf; }},
        {"screen_height_mm", [](DisplayProfile& p) { p.screenHeightMm = -1.0; }},
        {"subpixel_order", [](DisplayProfile& p) { p.subpixelOrder = SubpixelOrder(7); }},
        {"lens_width_mm", [](DisplayProfile& p) { p.lensWidthMm = 0.0; }},
        {"lens_width_mm", [&](DisplayProfile& p) { p.lensWidthMm = nan; }},
        {"lens_tilt_deg", [](DisplayProfile& p) { p.lensTiltDeg = 60.0; }},
        {"lens_tilt_deg", [](DisplayProfile& p) { p.lensTiltDeg = -75.0; }},
        {"lens_tilt_deg", [&](DisplayProfile& p) { p.lensTiltDeg = nan; }},
        {"offset_subpixels", [&](DisplayProfile& p) { p.offsetSubpixels = inf; }},
        {"lens_count", [](DisplayProfile& p) { p.mapping.perSubpixel = 0.0; }},
        {"lens_count", [](DisplayProfile& p) { p.mapping.perSubpixel = -0.04; }},
        {"lens_count", [&](DisplayProfile& p) { p.mapping.perSubpixel = nan; }},
        {"mapping.per_row", [&](DisplayProfile& p) { p.mapping.perRow = inf; }},
        {"mapping.offset", [&](DisplayProfile& p) { p.mapping.offset = nan; }},
        {"view_count", [](DisplayProfile& p) { p.viewCount = 0; }},
        {"view_count", [](DisplayProfile& p) { p.viewCount = 2049; }},
        {"view_width", [](DisplayProfile& p) { p.viewWidth = 0; }},
        {"view_width", [](DisplayProfile& p) { p.viewWidth = 16385; }},
        {"view_height", [](DisplayProfile& p) { p.viewHeight = 0; }},
        {"view_height", [](DisplayProfile& p) { p.viewHeight = 16385; }},
        // 16 views of 8192 x 4097 x 8 bytes = 4.0005 GiB > 4 GiB.
        {"view_count",
         [](DisplayProfile& p) {
             p.viewCount = 16;
             p.viewWidth = 8192;
             p.viewHeight = 4097;
         }},
        {"view_cone_deg", [](DisplayProfile& p) { p.viewConeDeg = 0.0; }},
        {"view_cone_deg", [](DisplayProfile& p) { p.viewConeDeg = -10.0; }},
        {"view_cone_deg", [](DisplayProfile& p) { p.viewConeDeg = 170.0; }},
        {"view_cone_deg", [&](DisplayProfile& p) { p.viewConeDeg = nan; }},
        {"viewing_distance_mm", [](DisplayProfile& p) { p.viewingDistanceMm = 0.0; }},
        {"viewing_distance_mm", [&](DisplayProfile& p) { p.viewingDistanceMm = inf; }},
        // Half the smaller screen side is 194.30 / 2 = 97.15 mm.
        {"viewing_distance_mm", [](DisplayProfile& p) { p.viewingDistanceMm = 97.15; }},
    };
    for (const Case& c : cases) {
        DisplayProfile p = prototypeDisplayProfile();
        c.mutate(p);
        expectFieldError(errorOf([&] { validateDisplayProfile(p, "bad.json"); }), "bad.json",
                         c.field);
    }

    // The limits themselves are accepted.
    DisplayProfile p = prototypeDisplayProfile();
    p.viewCount = 16;
    p.viewWidth = 8192;
    p.viewHeight = 4096; // exactly 4 GiB
    EXPECT_NO_THROW(validateDisplayProfile(p, "ok"));
    p = prototypeDisplayProfile();
    p.viewingDistanceMm = 97.16;
    p.lensTiltDeg = 59.9;
    p.viewConeDeg = 169.9;
    p.name.clear(); // an empty name is fine
    EXPECT_NO_THROW(validateDisplayProfile(p, "ok"));
    p = prototypeDisplayProfile();
    p.viewCount = 2048;
    p.viewWidth = 16;
    p.viewHeight = 16384;
    EXPECT_NO_THROW(validateDisplayProfile(p, "ok"));
}

TEST(DisplayProfile, JsonErrorsNameTheField) {
    const auto parse = [](const std::string& text) {
        return errorOf([&] { parseDisplayProfile(text, "p.json"); });
    };
    // Unknown key (typo protection).
    expectFieldError(parse(minimalProfile("\"lens_widht_mm\": 0.72")), "p.json", "lens_widht_mm");
    // Every required key.
    for (const char* key : {"panel_width", "panel_height", "screen_width_mm", "screen_height_mm",
                            "lens_tilt_deg", "view_count", "view_width", "view_height"})
        expectFieldError(parse(minimalProfile("", key)), "p.json", key);
    expectFieldError(parse(minimalProfile("", "lens_width_mm")), "p.json", "lens_width_mm");
    // Types and values.
    expectFieldError(parse(minimalProfile("\"format\": \"lfd-display-profile/2\"")), "p.json",
                     "format");
    expectFieldError(parse(minimalProfile("\"subpixel_order\": \"RBG\"")), "p.json",
                     "subpixel_order");
    expectFieldError(parse(minimalProfile("\"invert_views\": 1")), "p.json", "invert_views");
    expectFieldError(parse(minimalProfile("\"name\": 5")), "p.json", "name");
    expectFieldError(parse(minimalProfile("\"lens_count\": 0")), "p.json", "lens_count");
    expectFieldError(parse(minimalProfile("\"lens_count\": -479")), "p.json", "lens_count");
    expectFieldError(parse(minimalProfile("\"view_cone_deg\": \"wide\"")), "p.json",
                     "view_cone_deg");
    expectFieldError(parse(minimalProfile("\"viewing_distance_mm\": 50")), "p.json",
                     "viewing_distance_mm");
    expectFieldError(parse(minimalProfile("\"panel_width\": -3840", "panel_width")), "p.json",
                     "panel_width");
    expectFieldError(parse(minimalProfile("\"panel_width\": 3840.5", "panel_width")), "p.json",
                     "panel_width");
    expectFieldError(parse(minimalProfile("\"view_count\": 5000000000", "view_count")), "p.json",
                     "view_count");
    expectFieldError(parse(minimalProfile("\"view_count\": 0", "view_count")), "p.json",
                     "view_count");
    // Out-of-range numbers are a JSON-level error.
    expectFieldError(parse(minimalProfile("\"lens_width_mm\": 1e400", "lens_width_mm")),
                     "p.json", "invalid JSON");
    // Not an object.
    expectFieldError(parse("[1, 2, 3]"), "p.json", "top level");
}

TEST(DisplayProfile, FileErrorsAreOneLineNamingTheFile) {
    TempDir dir;
    // Malformed JSON: the parser's position is included.
    const fs::path bad = dir.write("bad.json", "{\n  \"panel_width\": 3840,\n  \"oops\"\n}\n");
    const std::string malformed = errorOf([&] { loadDisplayProfile(bad); });
    expectFieldError(malformed, bad.string(), "invalid JSON");
    EXPECT_NE(malformed.find("line 4"), std::string::npos) << malformed;
    // Empty file.
    const fs::path empty = dir.write("empty.json", "");
    expectFieldError(errorOf([&] { loadDisplayProfile(empty); }), empty.string(), "invalid JSON");
    // Missing file and a directory.
    const fs::path missing = dir.path / "missing.json";
    const std::string notFound = errorOf([&] { loadDisplayProfile(missing); });
    expectFieldError(notFound, missing.string(), "file");
    EXPECT_NE(notFound.find("not found"), std::string::npos) << notFound;
    expectFieldError(errorOf([&] { loadDisplayProfile(dir.path); }), dir.path.string(), "file");
    // Unreadable file (root reads everything, so only checked for other users).
    const fs::path locked = dir.write("unreadable.json", minimalProfile());
    fs::permissions(locked, fs::perms::none);
    if (::geteuid() != 0)
        expectFieldError(errorOf([&] { loadDisplayProfile(locked); }), locked.string(), "file");
    // A valid file through the same path works.
    const fs::path good = dir.write("good.json", minimalProfile());
    EXPECT_EQ(loadDisplayProfile(good).name, "good");
}

TEST(DisplayProfile, WithViewsOverridesAndRevalidates) {
    const DisplayProfile base = prototypeDisplayProfile();
    const DisplayProfile a = withViews(base, 8, 0, 0);
    EXPECT_EQ(a.viewCount, 8u);
    EXPECT_EQ(a.viewWidth, 480u);
    EXPECT_EQ(a.viewHeight, 360u);
    const DisplayProfile b = withViews(base, 0, 96, 72);
    EXPECT_EQ(b.viewCount, 48u);
    EXPECT_EQ(b.viewWidth, 96u);
    EXPECT_EQ(b.viewHeight, 72u);
    EXPECT_DOUBLE_EQ(b.mapping.perSubpixel, base.mapping.perSubpixel);
    const std::string message = errorOf([&] { withViews(base, 4096, 0, 0); });
    EXPECT_NE(message.find("view_count: "), std::string::npos) << message;
    EXPECT_NE(message.find("prototype"), std::string::npos) << message;
    EXPECT_NE(errorOf([&] { withViews(base, 0, 20000, 0); }).find("view_width: "),
              std::string::npos);
}

TEST(DisplayProfile, PhaseStaysInUnitInterval) {
    // Inverted phase 0 is 1 - 0 = 1, which is lens position 0 again: wrap, do not return 1.
    DisplayProfile p = prototypeDisplayProfile();
    p.mapping = {0.25, 0.0, 0.0, true};
    p.viewCount = 4;
    EXPECT_EQ(subpixelPhase(p, 0, 0), 0.0);
    EXPECT_EQ(subpixelView(p, 0, 0), 0u);
    EXPECT_DOUBLE_EQ(subpixelPhase(p, 1, 0), 0.75);
    EXPECT_EQ(subpixelView(p, 1, 0), 3u);
    EXPECT_EQ(subpixelPhase(p, 4, 0), 0.0);
    // Every subpixel of the prototype and of an inverted profile maps into [0, N).
    for (bool invert : {false, true}) {
        DisplayProfile q = prototypeDisplayProfile();
        q.mapping.invert = invert;
        for (uint32_t l = 0; l < q.panelHeight; l += 37)
            for (uint32_t k = 0; k < 3 * q.panelWidth; k += 7) {
                const double phase = subpixelPhase(q, k, l);
                ASSERT_GE(phase, 0.0);
                ASSERT_LT(phase, 1.0);
                ASSERT_LT(subpixelView(q, k, l), q.viewCount);
            }
    }
}

} // namespace

// A known Looking Glass device gets the views of its standard quilt (looking_glass_devices.h):
// the Go's 11x6 tiles of a 4092x4092 quilt are 66 views of 372x682; a panel no device has
// keeps the default 48 views 560 pixels high.
TEST(DisplayProfile, LookingGlassDevicesGetTheirStandardQuiltViews) {
    const std::string go = R"({"pitch": 80.0, "slope": -6.0, "center": 0.1, "DPI": 491,
        "screenW": 1440, "screenH": 2560})";
    const DisplayProfile p = parseDisplayProfile(go, "go.json");
    EXPECT_EQ(p.viewCount, 66u);
    EXPECT_EQ(p.viewWidth, 372u);
    EXPECT_EQ(p.viewHeight, 682u);
    const auto portrait = standardQuiltFor(1536, 2048, 120.41);
    ASSERT_TRUE(portrait.has_value());
    EXPECT_EQ(portrait->cols * 100 + portrait->rows, 806u);
    EXPECT_EQ(portrait->width, 3360u);
    // Equal pixels, other size: the 32" and the 65" are told apart by their width.
    EXPECT_EQ(standardQuiltFor(7680, 4320, 697.0)->rows, 7u);
    EXPECT_EQ(standardQuiltFor(7680, 4320, 1430.0)->rows, 9u);
    EXPECT_FALSE(standardQuiltFor(1536, 2048, 200.0).has_value());
}
