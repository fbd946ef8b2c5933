// The split-sum table; see brdf_table.h.
#include "brdf_table.h"

#include "brdf.h"
#include "parallel.h"
#include "sampling.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace lfd::lighting {

glm::vec3 splitSumTerms(float nDotV, float roughness, uint32_t samples)
{
    nDotV = std::clamp(nDotV, kMinNDotV, 1.0f);
    const float alpha = alphaFromRoughness(roughness);
    // Tangent space: n = +Z, v in the xz plane.
    const glm::vec3 v(std::sqrt(1.0f - nDotV * nDotV), 0.0f, nDotV);
    double a = 0.0, b = 0.0, c = 0.0;
    for (uint32_t i = 0; i < samples; ++i) {
        const glm::vec2 xi = hammersley(i, samples);
        // Specular: l from a GGX half vector, density D (n.h) / (4 v.h), so the estimate of
        // D Vis (n.l) is Vis (n.l) 4 (v.h) / (n.h).
        const glm::vec3 h = ggxHalfVector(xi, alpha);
        const glm::vec3 l = reflectAbout(v, h);
        const float vDotH = glm::dot(v, h);
        if (l.z > 0.0f && vDotH > 0.0f) {
            const double g = double(smithVisibility(l.z, nDotV, alpha)) * l.z * 4.0 * vDotH / h.z;
            const double fc = schlickWeight(vDotH);
            a += (1.0 - fc) * g;
            b += fc * g;
        }
        // Diffuse: l cosine-distributed, so C is the plain mean of Schlick's weight.
        const glm::vec3 ld = cosineDirection(xi);
        c += schlickWeight(std::max(glm::dot(v, glm::normalize(v + ld)), 0.0f));
    }
    return glm::vec3(glm::dvec3(a, b, c) / double(samples));
}

BrdfTable splitSumBrdfTable(uint32_t size, uint32_t samples)
{
    if (size < 2 || samples < 1)
        throw std::invalid_argument("split-sum table: size " + std::to_string(size) + " (>= 2) and samples " +
                                    std::to_string(samples) + " (>= 1)");
    BrdfTable table;
    table.size = size;
    table.abc.resize(size_t(size) * size * 3);
    const float last = float(size - 1);
    forEachBand(size, 1, [&](size_t, size_t begin, size_t end) {
        for (size_t row = begin; row < end; ++row)
            for (uint32_t column = 0; column < size; ++column) {
                const glm::vec3 t = splitSumTerms(float(column) / last, float(row) / last, samples);
                float* out = table.abc.data() + (row * size + column) * 3;
                out[0] = t.x;
                out[1] = t.y;
                out[2] = t.z;
            }
    });
    return table;
}

glm::vec2 brdfTableCoordinate(float nDotV, float roughness, uint32_t size)
{
    const float last = float(size - 1);
    return (glm::clamp(glm::vec2(nDotV, roughness), 0.0f, 1.0f) * last + 0.5f) / float(size);
}

glm::vec3 sampleBrdfTable(const BrdfTable& table, float nDotV, float roughness)
{
    return sampleSquareTableLinear(table, nDotV, roughness);
}

} // namespace lfd::lighting
