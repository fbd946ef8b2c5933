// GL's cube-map face selection and seamless filtering on the CPU; see cube_map.h.
#include "cube_map.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lfd::lighting {

namespace {

// The texel a tap (x, y), possibly one texel beyond the face, reads with seamless
// filtering: inside the face itself, otherwise the texel of the face that holds the tap's
// centre continued across the edge.
glm::vec3 seamlessTexel(const CubeLevel& level, uint32_t face, int x, int y)
{
    const int n = int(level.size);
    if (x >= 0 && x < n && y >= 0 && y < n)
        return level.texel(face, uint32_t(x), uint32_t(y));
    const float size = float(n);
    const CubeCoordinate c = cubeCoordinateFromDirection(
        cubeDirection(face, (float(x) + 0.5f) / size, (float(y) + 0.5f) / size));
    const int cx = std::clamp(int(std::floor(c.s * size)), 0, n - 1);
    const int cy = std::clamp(int(std::floor(c.t * size)), 0, n - 1);
    return level.texel(c.face, uint32_t(cx), uint32_t(cy));
}

// The integral over the face plane's square [-1, 1]^2 corner (0, 0) to (x, y) of the solid
// angle element dA / (1 + x^2 + y^2)^(3/2).
double cornerSolidAngle(double x, double y)
{
    return std::atan2(x * y, std::sqrt(x * x + y * y + 1.0));
}

} // namespace

glm::vec3 cubeDirection(uint32_t face, float s, float t)
{
    const float sc = 2.0f * s - 1.0f, tc = 2.0f * t - 1.0f;
    glm::vec3 d;
    switch (face) {
    case 0: d = {1.0f, -tc, -sc}; break;
    case 1: d = {-1.0f, -tc, sc}; break;
    case 2: d = {sc, 1.0f, tc}; break;
    case 3: d = {sc, -1.0f, -tc}; break;
    case 4: d = {sc, -tc, 1.0f}; break;
    case 5: d = {-sc, -tc, -1.0f}; break;
    default: throw std::invalid_argument("cube face " + std::to_string(face) + " (0..5)");
    }
    return glm::normalize(d);
}

CubeCoordinate cubeCoordinateFromDirection(glm::vec3 r)
{
    const float ax = std::abs(r.x), ay = std::abs(r.y), az = std::abs(r.z);
    uint32_t face;
    float sc, tc, ma;
    if (ax >= ay && ax >= az) {
        face = r.x >= 0.0f ? 0 : 1;
        sc = r.x >= 0.0f ? -r.z : r.z;
        tc = -r.y;
        ma = ax;
    } else if (ay >= az) {
        face = r.y >= 0.0f ? 2 : 3;
        sc = r.x;
        tc = r.y >= 0.0f ? r.z : -r.z;
        ma = ay;
    } else {
        face = r.z >= 0.0f ? 4 : 5;
        sc = r.z >= 0.0f ? r.x : -r.x;
        tc = -r.y;
        ma = az;
    }
    return {face, 0.5f * (sc / ma + 1.0f), 0.5f * (tc / ma + 1.0f)};
}

glm::vec3 cubeTexelDirection(uint32_t face, uint32_t x, uint32_t y, uint32_t size)
{
    return cubeDirection(face, (float(x) + 0.5f) / float(size), (float(y) + 0.5f) / float(size));
}

double cubeTexelSolidAngle(uint32_t x, uint32_t y, uint32_t size)
{
    const double n = double(size);
    const double x0 = 2.0 * x / n - 1.0, x1 = 2.0 * (x + 1) / n - 1.0;
    const double y0 = 2.0 * y / n - 1.0, y1 = 2.0 * (y + 1) / n - 1.0;
    return cornerSolidAngle(x1, y1) - cornerSolidAngle(x0, y1) - cornerSolidAngle(x1, y0) +
           cornerSolidAngle(x0, y0);
}

namespace {

// Bilinear at an already selected face and (s, t), with seamless taps across edges.
glm::vec3 bilinearAt(const CubeLevel& level, const CubeCoordinate& c)
{
    const int n = int(level.size);
    const float x = c.s * float(n) - 0.5f, y = c.t * float(n) - 0.5f;
    const float x0f = std::floor(x), y0f = std::floor(y);
    const float fx = x - x0f, fy = y - y0f;
    const int x0 = int(x0f), y0 = int(y0f);
    glm::vec3 t00, t10, t01, t11;
    if (x0 >= 0 && y0 >= 0 && x0 + 1 < n && y0 + 1 < n) {
        t00 = level.texel(c.face, uint32_t(x0), uint32_t(y0));
        t10 = level.texel(c.face, uint32_t(x0 + 1), uint32_t(y0));
        t01 = level.texel(c.face, uint32_t(x0), uint32_t(y0 + 1));
        t11 = level.texel(c.face, uint32_t(x0 + 1), uint32_t(y0 + 1));
    } else {
        t00 = seamlessTexel(level, c.face, x0, y0);
        t10 = seamlessTexel(level, c.face, x0 + 1, y0);
        t01 = seamlessTexel(level, c.face, x0, y0 + 1);
        t11 = seamlessTexel(level, c.face, x0 + 1, y0 + 1);
    }
    return glm::mix(glm::mix(t00, t10, fx), glm::mix(t01, t11, fx), fy);
}

} // namespace

glm::vec3 sampleCubeBilinear(const CubeLevel& level, glm::vec3 direction)
{
    return bilinearAt(level, cubeCoordinateFromDirection(direction));
}

glm::vec3 sampleCubeTrilinear(const CubeMap& cube, glm::vec3 direction, float lod)
{
    const float last = float(cube.levels.size() - 1);
    lod = std::clamp(lod, 0.0f, last);
    const float lower = std::floor(lod);
    const float fraction = lod - lower;
    const CubeCoordinate c = cubeCoordinateFromDirection(direction);
    const glm::vec3 a = bilinearAt(cube.levels[size_t(lower)], c);
    if (fraction == 0.0f)
        return a;
    return glm::mix(a, bilinearAt(cube.levels[size_t(lower) + 1], c), fraction);
}

CubeLevel halveCubeLevel(const CubeLevel& level)
{
    if (level.size < 2 || level.size % 2 != 0)
        throw std::logic_error("halveCubeLevel: face size " + std::to_string(level.size) + " is not even");
    CubeLevel half(level.size / 2);
    for (uint32_t face = 0; face < kCubeFaces; ++face)
        for (uint32_t y = 0; y < half.size; ++y)
            for (uint32_t x = 0; x < half.size; ++x) {
                const glm::vec3 sum = level.texel(face, 2 * x, 2 * y) + level.texel(face, 2 * x + 1, 2 * y) +
                                      level.texel(face, 2 * x, 2 * y + 1) + level.texel(face, 2 * x + 1, 2 * y + 1);
                half.setTexel(face, x, y, 0.25f * sum);
            }
    return half;
}

} // namespace lfd::lighting
