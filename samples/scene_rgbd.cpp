// The RGB-D sample: what a phone's portrait mode or a depth estimator gives - a photo, its
// depth map (white = near) and the same pair side by side - of a small scene with every
// case the RGB-D import must handle: a flat background (simplified to few triangles), a
// sphere (smooth depth), a box floating in front (depth discontinuities at its rim) and
// fine texture detail.
#include "procedural_textures.h"
#include "sample_scenes.h"

#include <algorithm>
#include <cmath>

namespace lfd::samples {

namespace {

constexpr int kPhotoWidth = 512;
constexpr int kPhotoHeight = 384;

// Nearness (0 far .. 1 near) and colour of pixel (x, y) of the photo.
struct RgbdPixel {
    float nearness;
    uint8_t rgb[3];
};

RgbdPixel rgbdPixel(int x, int y)
{
    const float u = (float(x) + 0.5f) / kPhotoWidth, v = (float(y) + 0.5f) / kPhotoHeight;
    // Background: a wall 0.1 near, warm stripes with a fine checker.
    const bool checker = ((x / 4) + (y / 4)) % 2 == 0;
    RgbdPixel p{0.1f, {uint8_t(checker ? 200 : 170), uint8_t(120 + 60 * (int(u * 8) % 2)), 90}};
    // Sphere, centre right: smooth depth up to 0.8 at its centre.
    const float dx = (u - 0.62f) * float(kPhotoWidth) / kPhotoHeight, dy = v - 0.5f, r = 0.3f;
    const float d2 = (dx * dx + dy * dy) / (r * r);
    if (d2 < 1.0f) {
        const float z = std::sqrt(1.0f - d2);
        p.nearness = 0.3f + 0.5f * z;
        const float band = std::fmod(std::atan2(dy, dx) * 3.0f + 10.0f, 1.0f);
        p.rgb[0] = uint8_t(40 + 150 * z);
        p.rgb[1] = uint8_t(band < 0.5f ? 90 : 160);
        p.rgb[2] = uint8_t(200 * z + 40);
    }
    // Box, left, floating in front: a flat face at 0.9 with a printed grid.
    if (u > 0.08f && u < 0.34f && v > 0.3f && v < 0.72f) {
        p.nearness = 0.9f;
        const bool line = x % 16 < 2 || y % 16 < 2;
        p.rgb[0] = line ? 20 : 230;
        p.rgb[1] = line ? 20 : 220;
        p.rgb[2] = line ? 20 : 60;
    }
    return p;
}

void writeRgbd(const std::filesystem::path& path, bool colour, bool depth)
{
    const int width = colour && depth ? 2 * kPhotoWidth : kPhotoWidth;
    writePngRgb8(path, width, kPhotoHeight, [&](int y0, int rows, uint8_t* pixels) {
        for (int y = y0; y < y0 + rows; ++y)
            for (int x = 0; x < width; ++x) {
                const bool depthHalf = depth && (!colour || x >= kPhotoWidth);
                const RgbdPixel p = rgbdPixel(x % kPhotoWidth, y);
                uint8_t* out = pixels + (size_t(y - y0) * size_t(width) + size_t(x)) * 3;
                for (int c = 0; c < 3; ++c)
                    out[c] = depthHalf ? uint8_t(std::lround(p.nearness * 255.0f)) : p.rgb[c];
            }
    });
}

} // namespace

SceneSummary writeRgbdSample(const std::filesystem::path& dir)
{
    writeRgbd(dir / "photo.png", true, false);
    writeRgbd(dir / "depth.png", false, true);
    writeRgbd(dir / "photo_rgbd.png", true, true);
    return {"rgbd", 0, 0, 2};
}

} // namespace lfd::samples
