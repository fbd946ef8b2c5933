// Small display profiles and synthetic views shared by the EIA, quilt and simulated-viewer
// tests (CPU only; no GL).
#pragma once

#include "lfd/display_profile.h"

#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

namespace lfd::player::displaytest {

// A 480x270 panel (0.1 mm pixels) built like the prototype, scaled down by 8 x 8:
//  * 119.84 lenses across (prototype: 479.36 for 480 view columns), so X = 1440 / 119.84
//    = 12.016 subpixels per lens (prototype 24.03) and N = 24 views = 2X, as there;
//  * 24 views of 120x45 = 480x270 samples: view pixels one lens wide and 6 panel rows
//    high (prototype: 2160 / 360) with the prototype's tilt. Along a row, subpixels of one
//    colour step 3N/X = 6 views apart and each row moves the phase by
//    3 tan(9.66 deg) N / X = 1.02 views, so the 4 x 6 subpixels of one colour in a view
//    pixel's footprint meet each of the 24 views about once (prototype: 8 x 6 for 48).
// Parsed from JSON so the mapping is derived and validated by the formats library.
inline DisplayProfile smallProfile(const std::string& subpixelOrder = "RGB", bool invert = false) {
    const std::string json = R"({
        "format": "lfd-display-profile/1",
        "name": "small-test",
        "panel_width": 480, "panel_height": 270,
        "screen_width_mm": 48.0, "screen_height_mm": 27.0,
        "subpixel_order": ")" + subpixelOrder + R"(",
        "lens_count": 119.84, "lens_tilt_deg": -9.66,
        "invert_views": )" + std::string(invert ? "true" : "false") + R"(,
        "view_count": 24, "view_width": 120, "view_height": 45,
        "view_cone_deg": 40.0, "viewing_distance_mm": 300.0
    })";
    return parseDisplayProfile(json, "small-test.json");
}

// Smooth, view-dependent RGBA8 content (image order): each channel a low-frequency
// sinusoid whose phase moves by one period across the N views (periodic, like the
// lenticular's view zones, so view N - 1 blends smoothly into view 0), so views i and
// i + 2 differ by up to 2 * 100 * sin(2 pi / N) levels while neighbouring pixels of one
// view differ by a few levels.
inline std::vector<uint8_t> smoothView(uint32_t view, uint32_t viewCount, uint32_t width,
                                       uint32_t height) {
    constexpr double twoPi = 2.0 * std::numbers::pi;
    std::vector<uint8_t> image(size_t(width) * height * 4);
    const double s = double(view) / viewCount;
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x) {
            const double u = (x + 0.5) / width, v = (y + 0.5) / height;
            uint8_t* p = &image[(size_t(y) * width + x) * 4];
            p[0] = uint8_t(std::lround(128.0 + 100.0 * std::sin(twoPi * (u + s))));
            p[1] = uint8_t(std::lround(128.0 + 100.0 * std::cos(twoPi * (0.7 * v + 0.4 * u + s))));
            p[2] = uint8_t(std::lround(128.0 + 90.0 * std::sin(twoPi * (u - v + s))));
            p[3] = 255;
        }
    return image;
}

inline std::vector<std::vector<uint8_t>> smoothViews(const DisplayProfile& profile) {
    std::vector<std::vector<uint8_t>> views;
    for (uint32_t v = 0; v < profile.viewCount; ++v)
        views.push_back(smoothView(v, profile.viewCount, profile.viewWidth, profile.viewHeight));
    return views;
}

} // namespace lfd::player::displaytest
