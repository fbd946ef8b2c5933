// Direct cube convolution with a radial kernel; see cube_convolution.h.
#include "cube_convolution.h"

#include "parallel.h"

#include <algorithm>
#include <vector>

namespace lfd::lighting {

namespace {

constexpr int kKernelIntervals = 4096;

// The source texels as arrays (the inner loop runs over them, vectorised): direction,
// radiance times solid angle, solid angle.
struct SourceTexels {
    std::vector<float> x, y, z, r, g, b, omega;
};

SourceTexels sourceTexels(const CubeLevel& source)
{
    SourceTexels s;
    const size_t count = size_t(kCubeFaces) * source.size * source.size;
    for (std::vector<float>* v : {&s.x, &s.y, &s.z, &s.r, &s.g, &s.b, &s.omega})
        v->reserve(count);
    for (uint32_t face = 0; face < kCubeFaces; ++face)
        for (uint32_t ty = 0; ty < source.size; ++ty)
            for (uint32_t tx = 0; tx < source.size; ++tx) {
                const glm::vec3 d = cubeTexelDirection(face, tx, ty, source.size);
                const float omega = float(cubeTexelSolidAngle(tx, ty, source.size));
                const glm::vec3 weighted = source.texel(face, tx, ty) * omega;
                s.x.push_back(d.x);
                s.y.push_back(d.y);
                s.z.push_back(d.z);
                s.r.push_back(weighted.r);
                s.g.push_back(weighted.g);
                s.b.push_back(weighted.b);
                s.omega.push_back(omega);
            }
    return s;
}

// The convolution at one output direction.
glm::vec3 convolveAt(const SourceTexels& s, const std::vector<float>& table, glm::vec3 n)
{
    float r = 0.0f, g = 0.0f, b = 0.0f, total = 0.0f;
    const size_t count = s.x.size();
    for (size_t j = 0; j < count; ++j) {
        const float cosine = n.x * s.x[j] + n.y * s.y[j] + n.z * s.z[j];
        if (cosine <= 0.0f)
            continue;
        const float position = cosine * float(kKernelIntervals);
        const int i = std::min(int(position), kKernelIntervals - 1);
        const float w = table[size_t(i)] + (table[size_t(i) + 1] - table[size_t(i)]) * (position - float(i));
        r += w * s.r[j];
        g += w * s.g[j];
        b += w * s.b[j];
        total += w * s.omega[j];
    }
    return total > 0.0f ? glm::vec3(r, g, b) / total : glm::vec3(0.0f);
}

} // namespace

CubeLevel convolveCube(const CubeLevel& source, uint32_t size, const std::function<double(double cosine)>& kernel)
{
    std::vector<float> table(kKernelIntervals + 1);
    for (int i = 0; i <= kKernelIntervals; ++i)
        table[size_t(i)] = float(kernel(double(i) / kKernelIntervals));
    const SourceTexels texels = sourceTexels(source);
    CubeLevel out(size);
    forEachBand(size_t(kCubeFaces) * size, 1, [&](size_t, size_t begin, size_t end) {
        for (size_t row = begin; row < end; ++row) {
            const uint32_t face = uint32_t(row / size), y = uint32_t(row % size);
            for (uint32_t x = 0; x < size; ++x)
                out.setTexel(face, x, y, convolveAt(texels, table, cubeTexelDirection(face, x, y, size)));
        }
    });
    return out;
}

} // namespace lfd::lighting
