// Test environments and the sphere view; see ibl_test_scenes.h.
#include "ibl_test_scenes.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lfd::lighting {

namespace {
constexpr float kDegree = std::numbers::pi_v<float> / 180.0f;
}

Environment constantEnvironment(glm::vec3 radiance, uint32_t width, uint32_t height)
{
    Environment e;
    e.width = width;
    e.height = height;
    e.rgb.resize(size_t(width) * height * 3);
    for (size_t i = 0; i < e.rgb.size(); i += 3) {
        e.rgb[i] = radiance.r;
        e.rgb[i + 1] = radiance.g;
        e.rgb[i + 2] = radiance.b;
    }
    return e;
}

glm::vec3 sunDirection()
{
    const float elevation = 40.0f * kDegree, azimuth = 30.0f * kDegree;
    return {std::cos(elevation) * std::sin(azimuth), std::sin(elevation), std::cos(elevation) * std::cos(azimuth)};
}

Environment sunAndSkyEnvironment()
{
    Environment e = constantEnvironment(glm::vec3(0.0f), 1024, 512);
    const glm::vec3 sun = sunDirection();
    for (uint32_t y = 0; y < e.height; ++y)
        for (uint32_t x = 0; x < e.width; ++x) {
            const glm::vec3 d = directionFromEquirect({(float(x) + 0.5f) / float(e.width), (float(y) + 0.5f) / float(e.height)});
            glm::vec3 radiance = d.y > 0.0f ? glm::mix(glm::vec3(0.45f, 0.5f, 0.55f), glm::vec3(0.12f, 0.22f, 0.45f), std::sqrt(d.y))
                                            : glm::vec3(0.12f, 0.1f, 0.08f);
            const float angle = std::acos(std::min(1.0f, glm::dot(d, sun))) / kDegree;
            radiance += (1.0f - std::clamp((angle - 1.35f) / 0.3f, 0.0f, 1.0f)) * glm::vec3(2000.0f, 1900.0f, 1700.0f);
            float* out = e.rgb.data() + (size_t(y) * e.width + x) * 3;
            out[0] = radiance.r;
            out[1] = radiance.g;
            out[2] = radiance.b;
        }
    return e;
}

void forEachSpherePixel(uint32_t pixels, float minNDotV, const std::function<void(glm::vec3 n)>& visit)
{
    for (uint32_t py = 0; py < pixels; ++py)
        for (uint32_t px = 0; px < pixels; ++px) {
            const float x = (float(px) + 0.5f) / float(pixels) * 2.0f - 1.0f;
            const float y = 1.0f - (float(py) + 0.5f) / float(pixels) * 2.0f;
            const float z2 = 1.0f - x * x - y * y;
            if (z2 > 0.0f && std::sqrt(z2) >= minNDotV)
                visit(glm::vec3(x, y, std::sqrt(z2)));
        }
}

} // namespace lfd::lighting
