// PNG output/input through the player's image codec (image_file.h) and the image
// metrics (RMSE, PSNR, SSIM).
#include "image_output.h"

#include "image_file.h"
#include "image_metrics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

namespace lfd::player {

namespace {

namespace fs = std::filesystem;

std::string oneLine(std::string text) {
    std::replace_if(text.begin(), text.end(), [](char c) { return c == '\n' || c == '\r'; },
                    ' ');
    while (!text.empty() && text.back() == ' ')
        text.pop_back();
    return text;
}

[[noreturn]] void fail(const fs::path& path, const std::string& problem) {
    throw ImageError(oneLine("'" + path.string() + "': " + problem));
}

void checkSameSize(const Image& a, const Image& b, const char* metric) {
    if (a.width != b.width || a.height != b.height)
        throw std::invalid_argument(std::string(metric) + ": image sizes differ (" +
                                    std::to_string(a.width) + "x" + std::to_string(a.height) +
                                    " vs " + std::to_string(b.width) + "x" +
                                    std::to_string(b.height) + ")");
    if (a.channels == 0 || b.channels == 0 ||
        a.pixels.size() != size_t(a.width) * a.height * a.channels ||
        b.pixels.size() != size_t(b.width) * b.height * b.channels)
        throw std::invalid_argument(std::string(metric) +
                                    ": pixel buffer does not match width x height x channels");
}

uint32_t colourChannels(const Image& a, const Image& b) {
    return std::min({3u, a.channels, b.channels});
}

// Rec. 601 luma (what MATLAB's rgb2gray, used by the SSIM reference code, computes).
std::vector<double> luma(const Image& image) {
    std::vector<double> y(size_t(image.width) * image.height);
    for (size_t i = 0; i < y.size(); ++i) {
        const uint8_t* p = &image.pixels[i * image.channels];
        y[i] = image.channels >= 3 ? 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2] : double(p[0]);
    }
    return y;
}

} // namespace

void writeImage(const fs::path& path, const uint8_t* pixels, uint32_t width, uint32_t height,
                uint32_t channels) {
    if (width == 0 || height == 0)
        fail(path, "cannot write an empty image (" + std::to_string(width) + "x" +
                       std::to_string(height) + ")");
    if (channels < 1 || channels > 4)
        fail(path, "cannot write " + std::to_string(channels) + " channels (1..4 supported)");
    if (pixels == nullptr)
        fail(path, "no pixel data");
    try {
        metrics::encodeImageFile(path, pixels, int(width), int(height), int(channels));
    } catch (const metrics::MetricsIoError& e) {
        throw ImageError(e.what());
    }
}

void writeImage(const fs::path& path, const Image& image) {
    if (image.pixels.size() != size_t(image.width) * image.height * image.channels)
        fail(path, "pixel buffer does not match " + std::to_string(image.width) + "x" +
                       std::to_string(image.height) + "x" + std::to_string(image.channels));
    writeImage(path, image.pixels.data(), image.width, image.height, image.channels);
}

Image readImage(const fs::path& path, uint32_t channels) {
    if (channels > 4 || channels == 1 || channels == 2)
        fail(path, "can only convert to 3 or 4 channels (0 keeps the file's)");
    metrics::DecodedImage decoded;
    try {
        decoded = metrics::decodeImageFile(path); // 8 bits per channel, straight alpha
    } catch (const metrics::MetricsIoError& e) {
        throw ImageError(e.what());
    }
    const uint32_t fileChannels = uint32_t(std::min(decoded.channels, 4));
    Image file;
    file.width = uint32_t(decoded.width);
    file.height = uint32_t(decoded.height);
    file.channels = fileChannels;
    file.pixels = std::move(decoded.u8);
    if (channels == 0 || channels == fileChannels)
        return file;

    // Convert: grey -> RGB, add opaque alpha or drop it.
    Image converted;
    converted.width = file.width;
    converted.height = file.height;
    converted.channels = channels;
    converted.pixels.resize(size_t(file.width) * file.height * channels);
    for (size_t i = 0; i < size_t(file.width) * file.height; ++i) {
        const uint8_t* src = &file.pixels[i * fileChannels];
        uint8_t* dst = &converted.pixels[i * channels];
        const bool grey = fileChannels <= 2;
        for (uint32_t c = 0; c < 3; ++c)
            dst[c] = grey ? src[0] : src[c];
        if (channels == 4) {
            const bool hasAlpha = fileChannels == 2 || fileChannels == 4;
            dst[3] = hasAlpha ? src[fileChannels - 1] : 255;
        }
    }
    return converted;
}

double rmse(const Image& a, const Image& b) {
    checkSameSize(a, b, "rmse");
    const uint32_t n = colourChannels(a, b);
    double sum = 0.0;
    for (size_t i = 0; i < size_t(a.width) * a.height; ++i)
        for (uint32_t c = 0; c < n; ++c) {
            const double d = double(a.pixels[i * a.channels + c]) - b.pixels[i * b.channels + c];
            sum += d * d;
        }
    return std::sqrt(sum / (double(a.width) * a.height * n));
}

int maxAbsDiff(const Image& a, const Image& b) {
    checkSameSize(a, b, "maxAbsDiff");
    const uint32_t n = colourChannels(a, b);
    int worst = 0;
    for (size_t i = 0; i < size_t(a.width) * a.height; ++i)
        for (uint32_t c = 0; c < n; ++c)
            worst = std::max(worst, std::abs(int(a.pixels[i * a.channels + c]) -
                                             int(b.pixels[i * b.channels + c])));
    return worst;
}

double psnr(const Image& a, const Image& b) {
    const double e = rmse(a, b);
    if (e == 0.0)
        return std::numeric_limits<double>::infinity();
    return 20.0 * std::log10(255.0 / e);
}

double ssimLuma(const Image& a, const Image& b) {
    checkSameSize(a, b, "ssimLuma");
    // Wang et al. 2004 constants.
    constexpr double L = 255.0;
    constexpr double C1 = (0.01 * L) * (0.01 * L);
    constexpr double C2 = (0.03 * L) * (0.03 * L);
    constexpr double sigma = 1.5;

    const std::vector<double> x = luma(a);
    const std::vector<double> y = luma(b);
    const int W = int(a.width), H = int(a.height);

    // Step 1: normalised separable Gaussian window, at most 11 taps, odd, fitting the image.
    int size = std::min({11, W, H});
    if (size % 2 == 0)
        --size;
    const int r = size / 2;
    std::vector<double> g(static_cast<size_t>(size));
    double gSum = 0.0;
    for (int i = 0; i < size; ++i) {
        g[size_t(i)] = std::exp(-double((i - r) * (i - r)) / (2.0 * sigma * sigma));
        gSum += g[size_t(i)];
    }
    for (double& w : g)
        w /= gSum;

    // Step 2: horizontal pass of the five moments (x, y, x^2, y^2, xy) at valid columns,
    // kept in a ring of `size` rows so memory stays small for panel-size images.
    const int outW = W - size + 1, outH = H - size + 1;
    constexpr int kMoments = 5;
    std::vector<double> ring(size_t(size) * size_t(outW) * kMoments, 0.0);
    auto ringAt = [&](int row, int col) {
        return &ring[(size_t(row % size) * size_t(outW) + size_t(col)) * kMoments];
    };
    double total = 0.0;
    for (int row = 0; row < H; ++row) {
        for (int col = 0; col < outW; ++col) {
            double* s = ringAt(row, col);
            std::fill(s, s + kMoments, 0.0);
            for (int i = 0; i < size; ++i) {
                const size_t p = size_t(row) * W + size_t(col + i);
                const double w = g[size_t(i)];
                s[0] += w * x[p];
                s[1] += w * y[p];
                s[2] += w * x[p] * x[p];
                s[3] += w * y[p] * y[p];
                s[4] += w * x[p] * y[p];
            }
        }
        const int outRow = row - size + 1;
        if (outRow < 0)
            continue;

        // Step 3: vertical pass and the SSIM index per window position (Wang et al. eq. 13).
        for (int col = 0; col < outW; ++col) {
            std::array<double, kMoments> s{};
            for (int i = 0; i < size; ++i) {
                const double* h = ringAt(outRow + i, col);
                for (int m = 0; m < kMoments; ++m)
                    s[size_t(m)] += g[size_t(i)] * h[m];
            }
            const double muX = s[0], muY = s[1];
            const double varX = s[2] - muX * muX, varY = s[3] - muY * muY;
            const double covXY = s[4] - muX * muY;
            total += ((2.0 * muX * muY + C1) * (2.0 * covXY + C2)) /
                     ((muX * muX + muY * muY + C1) * (varX + varY + C2));
        }
    }
    return total / (double(outW) * outH);
}

void writeDiffImage(const fs::path& path, const Image& a, const Image& b, float gain) {
    checkSameSize(a, b, "writeDiffImage");
    const uint32_t n = colourChannels(a, b);
    Image diff;
    diff.width = a.width;
    diff.height = a.height;
    diff.channels = 3;
    diff.pixels.assign(size_t(a.width) * a.height * 3, 0);
    for (size_t i = 0; i < size_t(a.width) * a.height; ++i)
        for (uint32_t c = 0; c < 3; ++c) {
            const uint32_t sc = std::min(c, n - 1); // grey images fill all three channels
            const float d = std::abs(float(a.pixels[i * a.channels + sc]) -
                                     float(b.pixels[i * b.channels + sc]));
            diff.pixels[i * 3 + c] = uint8_t(std::min(255.0f, std::round(d * gain)));
        }
    writeImage(path, diff);
}

} // namespace lfd::player
