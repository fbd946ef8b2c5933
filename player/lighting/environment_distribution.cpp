// Luminance-proportional direction sampling; see environment_distribution.h.
#include "environment_distribution.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lfd::lighting {

namespace {


// The index i with cdf[i] <= target < cdf[i + 1] (cdf ascending, cdf.front() = 0,
// target < cdf.back()), skipping empty intervals, and target's fraction inside it.
std::pair<uint32_t, double> invert(const double* cdf, uint32_t count, double target)
{
    const double* upper = std::upper_bound(cdf, cdf + count + 1, target);
    const uint32_t i = uint32_t(std::clamp<ptrdiff_t>(upper - cdf - 1, 0, ptrdiff_t(count) - 1));
    const double width = cdf[i + 1] - cdf[i];
    return {i, width > 0.0 ? std::clamp((target - cdf[i]) / width, 0.0, 1.0) : 0.5};
}

std::vector<double> luminances(const Environment& environment)
{
    std::vector<double> luminance(size_t(environment.width) * environment.height);
    for (uint32_t y = 0; y < environment.height; ++y)
        for (uint32_t x = 0; x < environment.width; ++x) {
            const glm::vec3 c = environment.texel(x, y);
            luminance[size_t(y) * environment.width + x] = 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
        }
    return luminance;
}

// The largest luminance around texel (x, y), columns wrapping, rows clamped.
double neighbourhoodMax(const std::vector<double>& luminance, uint32_t width, uint32_t height, uint32_t x, uint32_t y)
{
    double largest = 0.0;
    for (int dy = -1; dy <= 1; ++dy) {
        const uint32_t row = uint32_t(std::clamp(int(y) + dy, 0, int(height) - 1));
        for (int dx = -1; dx <= 1; ++dx) {
            const uint32_t column = uint32_t((int(x) + dx + int(width)) % int(width));
            largest = std::max(largest, luminance[size_t(row) * width + column]);
        }
    }
    return largest;
}

} // namespace

EnvironmentDistribution::EnvironmentDistribution(const Environment& environment)
    : width_(environment.width), height_(environment.height), rowCdf_(size_t(height_) + 1, 0.0),
      columnCdf_(size_t(height_) * (width_ + 1), 0.0)
{
    const std::vector<double> luminance = luminances(environment);
    const bool black = std::none_of(luminance.begin(), luminance.end(), [](double l) { return l > 0.0; });
    for (uint32_t y = 0; y < height_; ++y) {
        const double sinTheta = std::sin(std::numbers::pi * (y + 0.5) / height_);
        double* row = columnCdf_.data() + size_t(y) * (width_ + 1);
        for (uint32_t x = 0; x < width_; ++x) {
            const double weight = black ? 1.0 : neighbourhoodMax(luminance, width_, height_, x, y);
            row[x + 1] = row[x] + weight * sinTheta;
        }
        rowCdf_[y + 1] = rowCdf_[y] + row[width_];
    }
}

EnvironmentDistribution::Sample EnvironmentDistribution::sample(glm::vec2 xi) const
{
    const auto [y, dy] = invert(rowCdf_.data(), height_, double(xi.x) * rowCdf_.back());
    const double* row = columnCdf_.data() + size_t(y) * (width_ + 1);
    const auto [x, dx] = invert(row, width_, double(xi.y) * row[width_]);
    Sample s;
    s.uv = glm::vec2(float((x + dx) / width_), float((y + dy) / height_));
    s.direction = directionFromEquirect(s.uv);
    s.pdf = pdf(s.uv);
    return s;
}

float EnvironmentDistribution::pdf(glm::vec2 uv) const
{
    const uint32_t x = std::min(uint32_t(std::max(uv.x, 0.0f) * float(width_)), width_ - 1);
    const uint32_t y = std::min(uint32_t(std::max(uv.y, 0.0f) * float(height_)), height_ - 1);
    const double* row = columnCdf_.data() + size_t(y) * (width_ + 1);
    const double texelProbability = (row[x + 1] - row[x]) / rowCdf_.back();
    // Uniform inside the texel in (u, v); d omega = 2 pi^2 sin(theta) du dv.
    const double sinTheta = std::sin(std::numbers::pi * double(uv.y));
    if (sinTheta <= 1e-9)
        return 0.0f;
    return float(texelProbability * width_ * height_ / (2.0 * std::numbers::pi * std::numbers::pi * sinTheta));
}

} // namespace lfd::lighting
