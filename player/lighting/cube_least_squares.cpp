// Least-squares texel values for bilinear reads; see cube_least_squares.h.
#include "cube_least_squares.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace lfd::lighting {

namespace {

// Solves the symmetric positive definite system a x = b (n x n, row-major) in place by
// Gaussian elimination with partial pivoting.
std::vector<double> solve(std::vector<double> a, std::vector<double> b, size_t n)
{
    for (size_t i = 0; i < n; ++i) {
        size_t pivot = i;
        for (size_t r = i + 1; r < n; ++r)
            if (std::abs(a[r * n + i]) > std::abs(a[pivot * n + i]))
                pivot = r;
        if (pivot != i) {
            for (size_t c = 0; c < n; ++c)
                std::swap(a[i * n + c], a[pivot * n + c]);
            std::swap(b[i], b[pivot]);
        }
        for (size_t r = i + 1; r < n; ++r) {
            const double f = a[r * n + i] / a[i * n + i];
            if (f == 0.0)
                continue;
            for (size_t c = i; c < n; ++c)
                a[r * n + c] -= f * a[i * n + c];
            b[r] -= f * b[i];
        }
    }
    std::vector<double> x(n);
    for (size_t i = n; i-- > 0;) {
        double s = b[i];
        for (size_t c = i + 1; c < n; ++c)
            s -= a[i * n + c] * x[c];
        x[i] = s / a[i * n + i];
    }
    return x;
}

} // namespace

CubeLevel leastSquaresCubeLevel(const CubeLevel& target, uint32_t size)
{
    if (size == 0 || size > 8)
        throw std::invalid_argument("leastSquaresCubeLevel: face size " + std::to_string(size) + " outside 1..8");
    const size_t unknowns = size_t(kCubeFaces) * size * size;
    // The bilinear weights of every sample on the unknowns: read a cube that is 1 at one
    // texel (red) and 0 elsewhere (reads are linear in the texels).
    struct Weight {
        size_t texel;
        double weight;
    };
    std::vector<glm::vec3> directions;
    for (uint32_t face = 0; face < kCubeFaces; ++face)
        for (uint32_t y = 0; y < target.size; ++y)
            for (uint32_t x = 0; x < target.size; ++x)
                directions.push_back(cubeTexelDirection(face, x, y, target.size));
    std::vector<std::vector<Weight>> weights(directions.size());
    CubeLevel basis(size);
    for (size_t t = 0; t < unknowns; ++t) {
        basis.rgb[t * 3] = 1.0f;
        for (size_t j = 0; j < directions.size(); ++j)
            if (const float w = sampleCubeBilinear(basis, directions[j]).r; w != 0.0f)
                weights[j].push_back({t, double(w)});
        basis.rgb[t * 3] = 0.0f;
    }
    CubeLevel out(size);
    for (int channel = 0; channel < 3; ++channel) {
        std::vector<double> normal(unknowns * unknowns, 0.0), rhs(unknowns, 0.0);
        for (size_t j = 0; j < directions.size(); ++j) {
            const double value = target.rgb[j * 3 + size_t(channel)];
            const double w = 1.0 / std::max(value * value, 1e-12);
            for (const Weight& a : weights[j]) {
                rhs[a.texel] += w * a.weight * value;
                for (const Weight& b : weights[j])
                    normal[a.texel * unknowns + b.texel] += w * a.weight * b.weight;
            }
        }
        const std::vector<double> x = solve(std::move(normal), std::move(rhs), unknowns);
        for (size_t t = 0; t < unknowns; ++t)
            out.rgb[t * 3 + size_t(channel)] = float(std::max(x[t], 0.0));
    }
    return out;
}

} // namespace lfd::lighting
