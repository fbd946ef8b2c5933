// Monte Carlo reference with three-strategy MIS; see reference_ibl.h.
#include "reference_ibl.h"
#include "pi.h"

#include "sampling.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lfd::lighting {

namespace {


// SplitMix64 (Steele, Lea & Flood 2014): the seed's stream of offsets.
uint64_t splitMix64(uint64_t& state)
{
    uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

float unitFloat(uint64_t bits)
{
    return float(double(bits >> 40) * 0x1p-24);
}

glm::vec2 shifted(glm::vec2 point, glm::vec2 offset)
{
    return glm::fract(point + offset);
}

enum Strategy { kGgx, kCosine, kEnvironment, kStrategies };

struct Integrand {
    const Environment& environment;
    const EnvironmentDistribution& distribution;
    const PbrMaterial& material;
    glm::vec3 n;
    glm::vec3 v;
    float alpha;

    // f L (n.l) over the sum of the three strategies' densities at l (each strategy draws
    // the same number of points: the balance heuristic's multi-sample estimator).
    glm::vec3 weighted(glm::vec3 l, glm::vec2 uv) const
    {
        const float nDotL = glm::dot(n, l);
        if (nDotL <= 0.0f)
            return glm::vec3(0.0f);
        const glm::vec3 h = glm::normalize(v + l);
        const float nDotH = std::max(glm::dot(n, h), 0.0f);
        const float vDotH = std::max(glm::dot(v, h), 1e-8f);
        const float ggxPdf = ggxDistribution(nDotH, alpha) * nDotH / (4.0f * vDotH);
        const float pdfSum = ggxPdf + nDotL / kPi + distribution.pdf(uv);
        return evaluateBrdf(material, n, v, l) * sampleEnvironmentUv(environment, uv) * (nDotL / pdfSum);
    }
};

glm::vec3 strategyDirection(Strategy strategy, const Integrand& f, const glm::mat3& worldFromNormal, glm::vec2 xi,
                            glm::vec2& uv)
{
    if (strategy == kEnvironment) {
        const EnvironmentDistribution::Sample s = f.distribution.sample(xi);
        uv = s.uv;
        return s.direction;
    }
    const glm::vec3 l = strategy == kGgx ? reflectAbout(f.v, worldFromNormal * ggxHalfVector(xi, f.alpha))
                                         : worldFromNormal * cosineDirection(xi);
    uv = equirectFromDirection(l);
    return l;
}

} // namespace

glm::vec3 referenceIbl(const Environment& environment, const EnvironmentDistribution& distribution,
                       const PbrMaterial& material, glm::vec3 n, glm::vec3 v, uint32_t samples, uint64_t seed)
{
    const Integrand f{environment, distribution, material, n, v, alphaFromRoughness(material.roughness)};
    const glm::mat3 worldFromNormal = worldFromTangent(n);
    uint64_t state = seed;
    glm::dvec3 sum(0.0);
    for (int strategy = 0; strategy < kStrategies; ++strategy) {
        const glm::vec2 offset(unitFloat(splitMix64(state)), unitFloat(splitMix64(state)));
        for (uint32_t i = 0; i < samples; ++i) {
            glm::vec2 uv;
            const glm::vec3 l = strategyDirection(Strategy(strategy), f, worldFromNormal,
                                                  shifted(hammersley(i, samples), offset), uv);
            sum += glm::dvec3(f.weighted(l, uv));
        }
    }
    return glm::vec3(sum / double(samples));
}

} // namespace lfd::lighting
