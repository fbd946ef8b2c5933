// Test environments and the sphere view; see ibl_test_scenes.h.
#include "ibl_test_scenes.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

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

namespace {

// Each texel of a width x height panorama set to radiance(direction at its centre).
template <typename Radiance>
Environment paintedEnvironment(uint32_t width, uint32_t height, Radiance radiance)
{
    Environment e = constantEnvironment(glm::vec3(0.0f), width, height);
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x) {
            const glm::vec3 d = directionFromEquirect({(float(x) + 0.5f) / float(width), (float(y) + 0.5f) / float(height)});
            const glm::vec3 l = radiance(d);
            float* out = e.rgb.data() + (size_t(y) * width + x) * 3;
            out[0] = l.r;
            out[1] = l.g;
            out[2] = l.b;
        }
    return e;
}

} // namespace

Environment softLightsEnvironment(uint32_t seed)
{
    std::mt19937 random(seed);
    const auto uniform = [&] { return float(random() >> 8) * 0x1p-24f; };
    struct Light {
        glm::vec3 direction;
        float radius, soft;
        glm::vec3 radiance;
    };
    std::vector<Light> lights;
    for (int i = 0; i < 10; ++i) {
        const float z = uniform() * 2.0f - 1.0f, phi = uniform() * 2.0f * std::numbers::pi_v<float>;
        const float r = std::sqrt(1.0f - z * z);
        Light light;
        light.direction = glm::vec3(r * std::cos(phi), z, r * std::sin(phi));
        light.radius = (3.0f + 27.0f * uniform()) * kDegree;
        const float a = uniform(), b = uniform();
        const float luminance = 0.5f + 8.0f * a * b;
        const glm::vec3 tint(0.6f + 0.4f * uniform(), 0.6f + 0.4f * uniform(), 0.6f + 0.4f * uniform());
        light.soft = 0.15f + 0.5f * uniform();
        light.radiance = luminance * tint;
        lights.push_back(light);
    }
    return paintedEnvironment(1024, 512, [&](glm::vec3 d) {
        glm::vec3 l = d.y > 0.0f ? glm::mix(glm::vec3(0.3f, 0.32f, 0.35f), glm::vec3(0.08f, 0.12f, 0.25f), d.y)
                                 : glm::mix(glm::vec3(0.15f, 0.13f, 0.1f), glm::vec3(0.04f), -d.y);
        for (const Light& light : lights) {
            const float angle = std::acos(std::clamp(glm::dot(d, light.direction), -1.0f, 1.0f));
            const float t = std::clamp((angle - light.radius * (1.0f - light.soft)) / (2.0f * light.radius * light.soft), 0.0f, 1.0f);
            l += (1.0f - t * t * (3.0f - 2.0f * t)) * light.radiance;
        }
        return l;
    });
}

Environment outdoorEnvironment()
{
    const glm::vec3 sun = glm::normalize(glm::vec3(-0.6f, 0.35f, -0.3f));
    return paintedEnvironment(1024, 512, [&](glm::vec3 d) {
        const float azimuth = std::atan2(d.z, d.x);
        if (d.y <= 0.0f)
            return glm::vec3(0.1f, 0.12f, 0.06f) * (0.8f + 0.4f * std::sin(20.0f * azimuth) * std::sin(30.0f * d.y));
        const float treeLine = 0.08f + 0.06f * std::sin(13.0f * azimuth) + 0.03f * std::sin(37.0f * azimuth + 1.0f);
        if (d.y < treeLine)
            return glm::vec3(0.03f, 0.05f, 0.02f);
        glm::vec3 l = glm::mix(glm::vec3(0.7f, 0.75f, 0.8f), glm::vec3(0.15f, 0.3f, 0.7f), std::sqrt(d.y));
        const float clouds = 0.5f + 0.5f * std::sin(5.0f * azimuth + 8.0f * d.y) * std::sin(3.0f * azimuth - 2.0f + 11.0f * d.y);
        l = glm::mix(l, glm::vec3(1.1f), 0.6f * std::clamp((clouds - 0.55f) * 4.0f, 0.0f, 1.0f));
        const float c = std::max(glm::dot(d, sun), 0.0f);
        return l + glm::vec3(6.0f, 5.5f, 4.5f) * std::pow(c, 64.0f) + glm::vec3(0.6f, 0.5f, 0.35f) * std::pow(c, 6.0f);
    });
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
