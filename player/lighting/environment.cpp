// Equirectangular mapping, bilinear lookup, box halving and rotation; see environment.h.
#include "environment.h"
#include "pi.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace lfd::lighting {

namespace {


// A row or column range [begin, end) of the source that one halved texel averages.
struct BoxRange {
    uint32_t begin;
    uint32_t end;
};

BoxRange halfBox(uint32_t index, uint32_t halvedSize, uint32_t sourceSize)
{
    const uint32_t begin = std::min(index * 2, sourceSize - 1);
    const uint32_t end = index + 1 == halvedSize ? sourceSize : std::min(begin + 2, sourceSize);
    return {begin, end};
}

} // namespace

glm::vec2 equirectFromDirection(glm::vec3 direction)
{
    const glm::vec3 d = glm::normalize(direction);
    const float azimuth = (d.x == 0.0f && d.z == 0.0f) ? 0.0f : std::atan2(d.z, d.x);
    return {0.5f + azimuth / (2.0f * kPi), std::acos(std::clamp(d.y, -1.0f, 1.0f)) / kPi};
}

glm::vec3 directionFromEquirect(glm::vec2 uv)
{
    const float azimuth = (uv.x - 0.5f) * 2.0f * kPi;
    const float polar = uv.y * kPi;
    const float sinPolar = std::sin(polar);
    return {sinPolar * std::cos(azimuth), std::cos(polar), sinPolar * std::sin(azimuth)};
}

glm::vec3 sampleEnvironment(const Environment& environment, glm::vec3 direction)
{
    return sampleEnvironmentUv(environment, equirectFromDirection(direction));
}

glm::vec3 sampleEnvironmentUv(const Environment& environment, glm::vec2 uv)
{
    const int w = int(environment.width), h = int(environment.height);
    // Texel coordinates with centres at integers; x wraps, y clamps.
    const float x = uv.x * float(w) - 0.5f;
    const float y = std::clamp(uv.y * float(h) - 0.5f, 0.0f, float(h - 1));
    const float x0f = std::floor(x), y0f = std::floor(y);
    const float fx = x - x0f, fy = y - y0f;
    const int x0 = ((int(x0f) % w) + w) % w, x1 = (x0 + 1) % w;
    const int y0 = int(y0f), y1 = std::min(y0 + 1, h - 1);
    const glm::vec3 top = glm::mix(environment.texel(uint32_t(x0), uint32_t(y0)),
                                   environment.texel(uint32_t(x1), uint32_t(y0)), fx);
    const glm::vec3 bottom = glm::mix(environment.texel(uint32_t(x0), uint32_t(y1)),
                                      environment.texel(uint32_t(x1), uint32_t(y1)), fx);
    return glm::mix(top, bottom, fy);
}

Environment halveEnvironment(const Environment& environment)
{
    Environment half;
    half.width = std::max(environment.width / 2, 1u);
    half.height = std::max(environment.height / 2, 1u);
    half.rgb.resize(size_t(half.width) * half.height * 3);
    for (uint32_t y = 0; y < half.height; ++y) {
        const BoxRange rows = halfBox(y, half.height, environment.height);
        for (uint32_t x = 0; x < half.width; ++x) {
            const BoxRange columns = halfBox(x, half.width, environment.width);
            glm::vec3 sum(0.0f);
            for (uint32_t sy = rows.begin; sy < rows.end; ++sy)
                for (uint32_t sx = columns.begin; sx < columns.end; ++sx)
                    sum += environment.texel(sx, sy);
            const glm::vec3 mean = sum / float((rows.end - rows.begin) * (columns.end - columns.begin));
            float* out = half.rgb.data() + (size_t(y) * half.width + x) * 3;
            out[0] = mean.r;
            out[1] = mean.g;
            out[2] = mean.b;
        }
    }
    return half;
}

glm::mat3 environmentFromScene(float rotationDegrees)
{
    // The environment turned by +angle about +Y is read at R_y(-angle) * d.
    const float angle = -rotationDegrees * kPi / 180.0f;
    const float c = std::cos(angle), s = std::sin(angle);
    // Columns of R_y(angle): x -> (c, 0, -s), y -> y, z -> (s, 0, c).
    return glm::mat3(glm::vec3(c, 0.0f, -s), glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(s, 0.0f, c));
}

void validateEnvironment(const Environment& environment, const std::string& name)
{
    if (environment.width < 2 || environment.height < 1)
        throw std::invalid_argument(name + ": an environment needs at least 2x1 pixels, not " +
                                    std::to_string(environment.width) + "x" + std::to_string(environment.height));
    if (environment.rgb.size() != size_t(environment.width) * environment.height * 3)
        throw std::invalid_argument(name + ": the pixel data does not hold width x height x 3 values");
    const auto bad = std::find_if(environment.rgb.begin(), environment.rgb.end(),
                                  [](float v) { return !std::isfinite(v) || v < 0.0f; });
    if (bad != environment.rgb.end()) {
        const size_t pixel = size_t(bad - environment.rgb.begin()) / 3;
        throw std::invalid_argument(name + ": radiance " + std::to_string(*bad) + " at pixel (" +
                                    std::to_string(pixel % environment.width) + ", " +
                                    std::to_string(pixel / environment.width) + ") is not finite and >= 0");
    }
}

} // namespace lfd::lighting
