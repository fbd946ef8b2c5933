// Small synthetic images for the metric tests: constant colours, gradients, seeded
// Gaussian noise and checkerboards.
#pragma once

#include "image_metrics.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>

namespace lfd::metrics::test {

inline RgbImage constantImage(int width, int height, float r, float g, float b)
{
    RgbImage image;
    image.width = width;
    image.height = height;
    image.rgb.resize(image.pixelCount() * 3);
    for (size_t i = 0; i < image.pixelCount(); ++i) {
        image.rgb[i * 3] = r;
        image.rgb[i * 3 + 1] = g;
        image.rgb[i * 3 + 2] = b;
    }
    return image;
}

inline RgbImage greyImage(int width, int height, float value)
{
    return constantImage(width, height, value, value, value);
}

// A smooth colour ramp with values in 20..230, so offsets of +-20 stay in range.
inline RgbImage gradientImage(int width, int height)
{
    RgbImage image = greyImage(width, height, 0.0f);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            float* p = &image.rgb[(size_t(y) * size_t(width) + size_t(x)) * 3];
            p[0] = 20.0f + 210.0f * float(x) / float(std::max(1, width - 1));
            p[1] = 20.0f + 210.0f * float(y) / float(std::max(1, height - 1));
            p[2] = 125.0f;
        }
    return image;
}

// Adds every channel of `image` and offset `delta` (no clamping: callers keep values in range).
inline RgbImage offsetImage(RgbImage image, float delta)
{
    for (float& v : image.rgb)
        v += delta;
    return image;
}

// Independent Gaussian noise of standard deviation `sigma` on every value, seeded, clamped
// to 0..255; rounded to whole 8-bit values when `round` is set.
inline RgbImage noisyImage(RgbImage image, double sigma, uint32_t seed, bool round = false)
{
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0.0, sigma);
    for (float& v : image.rgb) {
        double n = std::clamp(double(v) + noise(rng), 0.0, 255.0);
        v = float(round ? std::round(n) : n);
    }
    return image;
}

// Grey checkerboard of `cell`-pixel squares alternating between `low` and `high`.
inline RgbImage checkerboard(int width, int height, int cell, float low, float high)
{
    RgbImage image = greyImage(width, height, low);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            if ((x / cell + y / cell) % 2 == 1)
                for (int c = 0; c < 3; ++c)
                    image.rgb[(size_t(y) * size_t(width) + size_t(x)) * 3 + size_t(c)] = high;
    return image;
}

} // namespace lfd::metrics::test
