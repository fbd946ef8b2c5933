// Mean SSIM (Wang, Bovik, Sheikh & Simoncelli 2004, IEEE TIP 13(4)) on Rec. 601 luma, whole
// image or over a mask. The window, constants and colour handling are documented in
// image_metrics.h.
#include "image_checks.h"
#include "parallel.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace lfd::metrics {

namespace {

// The paper's parameters: 11x11 Gaussian window, sigma 1.5, K1 = 0.01,
// K2 = 0.03, dynamic range L = 255 for 8-bit images.
constexpr int kWindowSize = 11;
constexpr double kWindowSigma = 1.5;
constexpr double kDynamicRange = 255.0;
constexpr double kC1 = (0.01 * kDynamicRange) * (0.01 * kDynamicRange);
constexpr double kC2 = (0.03 * kDynamicRange) * (0.03 * kDynamicRange);

std::vector<double> luma(const RgbImage& image)
{
    std::vector<double> y(image.pixelCount());
    for (size_t i = 0; i < y.size(); ++i)
        y[i] = 0.299 * image.rgb[i * 3] + 0.587 * image.rgb[i * 3 + 1] +
               0.114 * image.rgb[i * 3 + 2];
    return y;
}

// The 2D window is separable: w(i, j) = g(i) g(j) with g normalised to sum 1, so the 2D
// weights sum to 1 as the paper requires.
std::vector<double> gaussianTaps(int size)
{
    const int r = size / 2;
    std::vector<double> g(static_cast<size_t>(size));
    double sum = 0.0;
    for (int i = 0; i < size; ++i) {
        g[size_t(i)] = std::exp(-double((i - r) * (i - r)) / (2.0 * kWindowSigma * kWindowSigma));
        sum += g[size_t(i)];
    }
    for (double& w : g)
        w /= sum;
    return g;
}

// Window rows per band: the bands run on the cores (common/parallel.h), each filtering
// the `size` - 1 rows above its first window row again (a sixth more work at 64).
constexpr size_t kBandWindowRows = 64;

// The window's side: the paper's 11, or the largest odd size the image holds.
int windowSize(int width, int height)
{
    const int size = std::min({kWindowSize, width, height});
    return size % 2 == 0 ? size - 1 : size;
}

// The bands of window rows forEachWindow visits for an image of this size.
size_t windowBands(int width, int height)
{
    return bandCount(size_t(height - windowSize(width, height) + 1), kBandWindowRows);
}

// Calls visit(band, centreX, centreY, ssim) for every window position that lies wholly
// inside the image, from several threads: the windows of one band (a run of window rows,
// 0 .. windowBands() - 1) from one thread, in row order. The weighted moments (mu_x, mu_y,
// E[x^2], E[y^2], E[xy]) are filtered separably; horizontal results are kept for the last
// `size` rows only, so memory stays at a few rows per band even for panel-size EIAs.
template <typename Visit>
void forEachWindow(const RgbImage& reference, const RgbImage& test, Visit visit)
{
    const std::vector<double> x = luma(reference);
    const std::vector<double> y = luma(test);
    const int width = reference.width, height = reference.height;

    const int size = windowSize(width, height);
    const int radius = size / 2;
    const std::vector<double> g = gaussianTaps(size);

    constexpr size_t kMoments = 5;
    const int outWidth = width - size + 1;
    forEachBand(size_t(height - size + 1), kBandWindowRows, [&](size_t band, size_t topBegin, size_t topEnd) {
        std::vector<double> ring(size_t(size) * size_t(outWidth) * kMoments);
        auto ringAt = [&](int row, int col) {
            return &ring[(size_t(row % size) * size_t(outWidth) + size_t(col)) * kMoments];
        };

        for (int row = int(topBegin); row < int(topEnd) + size - 1; ++row) {
            for (int col = 0; col < outWidth; ++col) {
                std::array<double, kMoments> s{};
                for (int i = 0; i < size; ++i) {
                    const size_t p = size_t(row) * size_t(width) + size_t(col + i);
                    const double w = g[size_t(i)];
                    s[0] += w * x[p];
                    s[1] += w * y[p];
                    s[2] += w * x[p] * x[p];
                    s[3] += w * y[p] * y[p];
                    s[4] += w * x[p] * y[p];
                }
                std::copy(s.begin(), s.end(), ringAt(row, col));
            }
            const int top = row - size + 1;
            if (top < int(topBegin))
                continue;
            for (int col = 0; col < outWidth; ++col) {
                std::array<double, kMoments> s{};
                for (int i = 0; i < size; ++i) {
                    const double* h = ringAt(top + i, col);
                    for (size_t m = 0; m < kMoments; ++m)
                        s[m] += g[size_t(i)] * h[m];
                }
                const double muX = s[0], muY = s[1];
                const double varX = s[2] - muX * muX;
                const double varY = s[3] - muY * muY;
                const double covXY = s[4] - muX * muY;
                // Wang et al. 2004, eq. 13.
                const double value = ((2.0 * muX * muY + kC1) * (2.0 * covXY + kC2)) /
                                     ((muX * muX + muY * muY + kC1) * (varX + varY + kC2));
                visit(band, col + radius, top + radius, value);
            }
        }
    });
}

// The sum and count of the windows' SSIM whose centre `keep(x, y)` accepts, summed per
// band and then in band order: the same sum whatever the number of threads.
struct WindowSum {
    double sum = 0.0;
    size_t count = 0;
};
template <typename Keep>
WindowSum sumWindows(const RgbImage& reference, const RgbImage& test, Keep keep)
{
    std::vector<WindowSum> bands(windowBands(reference.width, reference.height));
    forEachWindow(reference, test, [&](size_t band, int cx, int cy, double value) {
        if (!keep(cx, cy))
            return;
        bands[band].sum += value;
        ++bands[band].count;
    });
    WindowSum total;
    for (const WindowSum& band : bands) {
        total.sum += band.sum;
        total.count += band.count;
    }
    return total;
}

} // namespace

double ssim(const RgbImage& reference, const RgbImage& test)
{
    detail::requireSameSize(reference, test, "ssim");
    const WindowSum total = sumWindows(reference, test, [](int, int) { return true; });
    return total.sum / double(total.count);
}

double ssim(const RgbImage& reference, const RgbImage& test, std::span<const uint8_t> mask)
{
    detail::requireSameSize(reference, test, "ssim");
    detail::requireMaskSize(reference, mask, "ssim");
    const WindowSum total = sumWindows(reference, test, [&](int cx, int cy) {
        return mask[size_t(cy) * size_t(reference.width) + size_t(cx)] != 0;
    });
    if (total.count == 0)
        throw std::invalid_argument(
            "ssim: no window that fits inside the image is centred on a masked pixel");
    return total.sum / double(total.count);
}

double ssim(const Image& reference, const Image& test)
{
    return ssim(rgbFromImage(reference), rgbFromImage(test));
}

} // namespace lfd::metrics
