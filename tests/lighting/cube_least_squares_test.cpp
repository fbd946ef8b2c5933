// Least-squares texel values for bilinear reads: a constant comes back, a smooth function
// is read back closer than from its values at the texel centres, sizes are checked.
#include "cube_least_squares.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace lfd::lighting {
namespace {

// A level of face `size` holding f(direction) at its texel centres.
template <typename F>
CubeLevel sampled(uint32_t size, F f)
{
    CubeLevel level(size);
    for (uint32_t face = 0; face < kCubeFaces; ++face)
        for (uint32_t y = 0; y < size; ++y)
            for (uint32_t x = 0; x < size; ++x)
                level.setTexel(face, x, y, f(cubeTexelDirection(face, x, y, size)));
    return level;
}

TEST(CubeLeastSquares, AConstantComesBack)
{
    const CubeLevel fitted = leastSquaresCubeLevel(sampled(16, [](glm::vec3) { return glm::vec3(0.5f, 2.0f, 3.0f); }), 4);
    for (size_t i = 0; i < fitted.rgb.size(); ++i)
        EXPECT_NEAR(fitted.rgb[i], (i % 3 == 0 ? 0.5f : i % 3 == 1 ? 2.0f : 3.0f), 1e-4f);
}

TEST(CubeLeastSquares, ReadsASmoothFunctionBackCloserThanCentreValues)
{
    // A wide bright lobe on a dim floor, like the prefilter's wide level under a sun.
    const glm::vec3 sun = glm::normalize(glm::vec3(0.4f, 0.6f, 0.7f));
    const auto f = [&](glm::vec3 d) {
        const float c = std::max(glm::dot(d, sun), 0.0f);
        return glm::vec3(0.05f + c / (c + 0.2f));
    };
    const CubeLevel centres = sampled(4, f), fitted = leastSquaresCubeLevel(sampled(16, f), 4);
    double centreError = 0.0, fittedError = 0.0;
    const CubeLevel probes = sampled(32, f);
    for (uint32_t face = 0; face < kCubeFaces; ++face)
        for (uint32_t y = 0; y < 32; ++y)
            for (uint32_t x = 0; x < 32; ++x) {
                const glm::vec3 d = cubeTexelDirection(face, x, y, 32);
                const float exact = probes.texel(face, x, y).g;
                centreError += std::abs(sampleCubeBilinear(centres, d).g / exact - 1.0f);
                fittedError += std::abs(sampleCubeBilinear(fitted, d).g / exact - 1.0f);
            }
    const double probesCount = 6.0 * 32.0 * 32.0;
    std::printf("relative error of bilinear reads, face 4: centre values %.2f%%, least squares %.2f%%\n",
                100.0 * centreError / probesCount, 100.0 * fittedError / probesCount);
    EXPECT_LT(fittedError, 0.8 * centreError);
}

TEST(CubeLeastSquares, SizesAreChecked)
{
    EXPECT_THROW(leastSquaresCubeLevel(CubeLevel(32), 0), std::invalid_argument);
    EXPECT_THROW(leastSquaresCubeLevel(CubeLevel(32), 16), std::invalid_argument);
}

} // namespace
} // namespace lfd::lighting
