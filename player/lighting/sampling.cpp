// Sample points and directions; see sampling.h.
#include "sampling.h"
#include "pi.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lfd::lighting {

namespace {
}

glm::vec2 hammersley(uint32_t i, uint32_t n)
{
    // Radical inverse in base 2: the bits of i mirrored about the binary point.
    uint32_t bits = i;
    bits = (bits << 16u) | (bits >> 16u);
    bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
    bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
    bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
    bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
    return {float(i) / float(n), float(double(bits) * 0x1p-32)};
}

glm::vec3 ggxHalfVector(glm::vec2 xi, float alpha)
{
    // Invert GGX's cumulative distribution in cos(theta_h) (Walter et al. 2007, eq. 35).
    const float a2 = alpha * alpha;
    const float cosTheta = std::sqrt(std::max(0.0f, (1.0f - xi.x) / (1.0f + (a2 - 1.0f) * xi.x)));
    const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
    const float phi = 2.0f * kPi * xi.y;
    return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

glm::vec3 cosineDirection(glm::vec2 xi)
{
    const float r = std::sqrt(xi.x);
    const float phi = 2.0f * kPi * xi.y;
    return {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0f, 1.0f - xi.x))};
}

glm::mat3 worldFromTangent(glm::vec3 n)
{
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float b = n.x * n.y * a;
    const glm::vec3 tangent(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
    const glm::vec3 bitangent(b, sign + n.y * n.y * a, -n.y);
    return glm::mat3(tangent, bitangent, n);
}

} // namespace lfd::lighting
