// Heat maps of per-pixel errors in 0..1 with the magma colour map.
#include "image_metrics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace lfd::metrics {

namespace {

// Every 16th entry (and the last) of the 256-entry magma table of Smith & van der Walt's
// perceptually uniform colour maps (matplotlib, released CC0), as sRGB in [0, 1]; entry
// k sits at t = 16 k / 255, the last at t = 1. Linear interpolation between these 17
// anchors differs from the full table by at most a couple of 8-bit steps.
constexpr std::array<std::array<double, 3>, 17> kMagmaAnchors = {{
    {0.001462, 0.000466, 0.013866}, // 0
    {0.039608, 0.031090, 0.133515}, // 16
    {0.113094, 0.065492, 0.276784}, // 32
    {0.211718, 0.061992, 0.418647}, // 48
    {0.316654, 0.071690, 0.485380}, // 64
    {0.414709, 0.110431, 0.504662}, // 80
    {0.512831, 0.148179, 0.507648}, // 96
    {0.613617, 0.181811, 0.498536}, // 112
    {0.716387, 0.214982, 0.475290}, // 128
    {0.816914, 0.255895, 0.436461}, // 144
    {0.904281, 0.319610, 0.388137}, // 160
    {0.960949, 0.418323, 0.359630}, // 176
    {0.986700, 0.535582, 0.382210}, // 192
    {0.996096, 0.653659, 0.446213}, // 208
    {0.996898, 0.769591, 0.534892}, // 224
    {0.992440, 0.884330, 0.640099}, // 240
    {0.987053, 0.991438, 0.749504}, // 255
}};

uint8_t toByte(double v) { return uint8_t(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); }

} // namespace

Rgb8 magma(double t)
{
    t = std::isnan(t) ? 1.0 : std::clamp(t, 0.0, 1.0);
    const double index = t * 255.0; // position in the 256-entry table
    const size_t segment = std::min(size_t(index / 16.0), kMagmaAnchors.size() - 2);
    const double start = 16.0 * double(segment);
    const double end = segment + 1 == kMagmaAnchors.size() - 1 ? 255.0 : start + 16.0;
    const double f = (index - start) / (end - start);
    const auto& a = kMagmaAnchors[segment];
    const auto& b = kMagmaAnchors[segment + 1];
    return {toByte(a[0] + f * (b[0] - a[0])), toByte(a[1] + f * (b[1] - a[1])),
            toByte(a[2] + f * (b[2] - a[2]))};
}

std::vector<uint8_t> heatMapRgb8(std::span<const float> values)
{
    std::vector<uint8_t> rgb(values.size() * 3);
    for (size_t i = 0; i < values.size(); ++i) {
        const Rgb8 c = magma(values[i]);
        rgb[i * 3] = c.r;
        rgb[i * 3 + 1] = c.g;
        rgb[i * 3 + 2] = c.b;
    }
    return rgb;
}

void writeHeatMap(const std::filesystem::path& path, std::span<const float> values, int width,
                  int height)
{
    if (width <= 0 || height <= 0 || values.size() != size_t(width) * size_t(height))
        throw ImageError("'" + path.string() + "': heat map of " +
                             std::to_string(values.size()) + " values does not fill " +
                             std::to_string(width) + "x" + std::to_string(height));
    writeRgb8Image(path, heatMapRgb8(values), width, height);
}

} // namespace lfd::metrics
