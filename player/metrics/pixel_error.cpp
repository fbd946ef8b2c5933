// RMSE (whole image or masked) and PSNR: the plain pixel-error measures, on the 0..255 scale
// over all R, G and B values.
#include "image_checks.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace lfd::metrics {

namespace {

// Sum of squared differences over the pixels `include(i)` accepts, and how many it accepted.
template <typename Include>
double meanSquaredError(const RgbImage& reference, const RgbImage& test, Include include,
                        const char* metric)
{
    double sum = 0.0;
    size_t count = 0;
    for (size_t i = 0; i < reference.pixelCount(); ++i) {
        if (!include(i))
            continue;
        for (size_t c = 0; c < 3; ++c) {
            const double d = double(reference.rgb[i * 3 + c]) - double(test.rgb[i * 3 + c]);
            sum += d * d;
        }
        count += 3;
    }
    if (count == 0)
        throw std::invalid_argument(std::string(metric) + ": the mask selects no pixel");
    return sum / double(count);
}

} // namespace

double rmse(const RgbImage& reference, const RgbImage& test)
{
    detail::requireSameSize(reference, test, "rmse");
    return std::sqrt(meanSquaredError(reference, test, [](size_t) { return true; }, "rmse"));
}

double rmse(const RgbImage& reference, const RgbImage& test, std::span<const uint8_t> mask)
{
    detail::requireSameSize(reference, test, "rmse");
    detail::requireMaskSize(reference, mask, "rmse");
    return std::sqrt(
        meanSquaredError(reference, test, [&](size_t i) { return mask[i] != 0; }, "rmse"));
}

double psnrFromRmse(double rmse)
{
    if (rmse == 0.0)
        return std::numeric_limits<double>::infinity();
    return 20.0 * std::log10(255.0 / rmse);
}

double psnr(const RgbImage& reference, const RgbImage& test)
{
    return psnrFromRmse(rmse(reference, test));
}

double rmse(const Image& reference, const Image& test)
{
    return rmse(rgbFromImage(reference), rgbFromImage(test));
}

double psnr(const Image& reference, const Image& test)
{
    return psnr(rgbFromImage(reference), rgbFromImage(test));
}

int maxAbsDiff(const Image& reference, const Image& test)
{
    const RgbImage a = rgbFromImage(reference), b = rgbFromImage(test);
    detail::requireSameSize(a, b, "maxAbsDiff");
    float worst = 0.0f;
    for (size_t i = 0; i < a.rgb.size(); ++i)
        worst = std::max(worst, std::abs(a.rgb[i] - b.rgb[i]));
    return int(worst); // exact: both hold whole 8-bit levels
}

void writeDiffImage(const std::filesystem::path& path, const Image& a, const Image& b, float gain)
{
    const RgbImage x = rgbFromImage(a), y = rgbFromImage(b);
    detail::requireSameSize(x, y, "writeDiffImage");
    std::vector<uint8_t> diff(x.rgb.size());
    for (size_t i = 0; i < diff.size(); ++i)
        diff[i] = uint8_t(std::min(255.0f, std::round(std::abs(x.rgb[i] - y.rgb[i]) * gain)));
    writeRgb8Image(path, diff, x.width, x.height);
}

} // namespace lfd::metrics
