// The lobe tap fit; see lobe_tap_fit.h.
#include "lobe_tap_fit.h"

#include "brdf.h"
#include "parallel.h"
#include "prefilter.h"
#include "sampling.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <numbers>
#include <utility>

namespace lfd::lighting {

namespace {

// Table resolution: log2 alpha' in eighth steps, the axis angle in 2-degree steps, t in
// steps of 1/512.
constexpr int kAlphaSteps = 41;
constexpr int kAngleSteps = 91;
constexpr int kOffsetSteps = 1025;
constexpr uint32_t kLookupSamples = 1u << 14;
constexpr uint32_t kLobeSamples = 1u << 13;
constexpr int kDirections = 100;
constexpr std::array<float, 7> kQuantiles = {0.05f, 0.2f, 0.35f, 0.5f, 0.65f, 0.8f, 0.95f};
constexpr float kMaxK = 1.5f;

using WeightedDirections = std::vector<std::pair<glm::vec3, double>>;

void normalise(WeightedDirections& samples)
{
    double total = 0.0;
    for (const auto& s : samples)
        total += s.second;
    for (auto& s : samples)
        s.second /= total;
}

// The GGX lobe at n = v = +Z, D Vis (n.l), as the prefilter stores it (weights sum to 1).
WeightedDirections ggxLookupLobe(float alpha)
{
    WeightedDirections lobe;
    for (uint32_t i = 0; i < kLookupSamples; ++i) {
        const glm::vec3 h = ggxHalfVector(hammersley(i, kLookupSamples), alpha);
        const glm::vec3 l = reflectAbout(glm::vec3(0.0f, 0.0f, 1.0f), h);
        // h has density D (n.h), l = reflect: density D (n.h) / (4 v.h) = D / 4 at n = v.
        if (l.z > 0.0f)
            lobe.push_back({l, double(smithVisibility(l.z, 1.0f, alpha)) * l.z});
    }
    normalise(lobe);
    return lobe;
}

// The wide level's lobe (prefilter.h), from cosine-distributed directions.
WeightedDirections wideLookupLobe()
{
    WeightedDirections lobe;
    for (uint32_t i = 0; i < kLookupSamples; ++i) {
        const glm::vec3 l = cosineDirection(hammersley(i, kLookupSamples));
        if (l.z > 0.0f)
            lobe.push_back({l, double(smithVisibility(l.z, kWideLobeNDotV, 1.0f))});
    }
    normalise(lobe);
    return lobe;
}

float log2AlphaOfStep(int step)
{
    return LookupLobeShares::kMinLog2Alpha +
           (LookupLobeShares::kMaxLog2Alpha - LookupLobeShares::kMinLog2Alpha) * float(step) / float(kAlphaSteps - 1);
}

// The two lookup directions in the lobe frame (n = +Z, R = (-sin, 0, n.v)).
glm::vec3 lookupDirection(float nDotV, float k)
{
    const glm::vec3 n(0.0f, 0.0f, 1.0f), r(-std::sqrt(std::max(0.0f, 1.0f - nDotV * nDotV)), 0.0f, nDotV);
    return glm::normalize(glm::mix(n, r, k));
}

// Nelder & Mead (1965) with the usual coefficients (reflection 1, expansion 2, contraction
// 1/2, shrink 1/2), a fixed number of iterations.
glm::vec4 nelderMead(const std::function<double(glm::vec4)>& f, glm::vec4 start, glm::vec4 step, int iterations)
{
    std::array<glm::vec4, 5> p;
    std::array<double, 5> value;
    for (int i = 0; i < 5; ++i) {
        p[size_t(i)] = start;
        if (i > 0)
            p[size_t(i)][i - 1] += step[i - 1];
        value[size_t(i)] = f(p[size_t(i)]);
    }
    for (int iteration = 0; iteration < iterations; ++iteration) {
        std::array<size_t, 5> order = {0, 1, 2, 3, 4};
        std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return value[a] < value[b]; });
        const auto sortedP = p;
        const auto sortedValue = value;
        for (size_t i = 0; i < 5; ++i) {
            p[i] = sortedP[order[i]];
            value[i] = sortedValue[order[i]];
        }
        const glm::vec4 centroid = (p[0] + p[1] + p[2] + p[3]) * 0.25f;
        const auto along = [&](float t) { return centroid + t * (p[4] - centroid); };
        const glm::vec4 reflected = along(-1.0f);
        const double reflectedValue = f(reflected);
        if (reflectedValue < value[0]) {
            const glm::vec4 expanded = along(-2.0f);
            const double expandedValue = f(expanded);
            p[4] = expandedValue < reflectedValue ? expanded : reflected;
            value[4] = std::min(expandedValue, reflectedValue);
        } else if (reflectedValue < value[3]) {
            p[4] = reflected;
            value[4] = reflectedValue;
        } else {
            const glm::vec4 contracted = along(reflectedValue < value[4] ? -0.5f : 0.5f);
            const double contractedValue = f(contracted);
            if (contractedValue < std::min(reflectedValue, value[4])) {
                p[4] = contracted;
                value[4] = contractedValue;
            } else {
                for (size_t i = 1; i < 5; ++i) {
                    p[i] = p[0] + 0.5f * (p[i] - p[0]);
                    value[i] = f(p[i]);
                }
            }
        }
    }
    return p[size_t(std::min_element(value.begin(), value.end()) - value.begin())];
}

} // namespace

LookupLobeShares::LookupLobeShares() : shares_(size_t(kAlphaSteps) * kAngleSteps * kOffsetSteps)
{
    const WeightedDirections wide = wideLookupLobe();
    const WeightedDirections widest = ggxLookupLobe(1.0f);
    forEachBand(size_t(kAlphaSteps), 1, [&](size_t, size_t begin, size_t end) {
        for (size_t a = begin; a < end; ++a) {
            const float log2Alpha = log2AlphaOfStep(int(a));
            WeightedDirections lobe;
            if (log2Alpha <= 0.0f) {
                lobe = ggxLookupLobe(std::exp2(log2Alpha));
            } else {
                // Between the alpha = 1 level and the wide level, as trilinear reads them.
                for (const auto& [l, w] : widest)
                    lobe.push_back({l, w * (1.0 - log2Alpha)});
                for (const auto& [l, w] : wide)
                    lobe.push_back({l, w * log2Alpha});
            }
            std::vector<double> bins(kOffsetSteps);
            for (int b = 0; b < kAngleSteps; ++b) {
                const float angle = std::numbers::pi_v<float> * float(b) / float(kAngleSteps - 1);
                const glm::vec3 e(std::sin(angle), 0.0f, std::cos(angle));
                std::fill(bins.begin(), bins.end(), 0.0);
                for (const auto& [l, w] : lobe) {
                    // Bin i holds the projections in [t_i, t_i+1).
                    const float x = (glm::dot(l, e) + 1.0f) * 0.5f * float(kOffsetSteps - 1);
                    bins[size_t(std::clamp(int(std::floor(x)), 0, kOffsetSteps - 1))] += w;
                }
                double above = 0.0;
                for (int t = kOffsetSteps - 1; t >= 0; --t) {
                    above += bins[size_t(t)];
                    shares_[(a * kAngleSteps + size_t(b)) * kOffsetSteps + size_t(t)] = float(above);
                }
            }
        }
    });
}

float LookupLobeShares::above(float log2Alpha, float cosAxis, float t) const
{
    const float a = std::clamp((log2Alpha - kMinLog2Alpha) / (kMaxLog2Alpha - kMinLog2Alpha), 0.0f, 1.0f) *
                    float(kAlphaSteps - 1);
    const float b = std::acos(std::clamp(cosAxis, -1.0f, 1.0f)) / std::numbers::pi_v<float> * float(kAngleSteps - 1);
    const float o = (std::clamp(t, -1.0f, 1.0f) + 1.0f) * 0.5f * float(kOffsetSteps - 1);
    const int a0 = std::min(int(a), kAlphaSteps - 2), b0 = std::min(int(b), kAngleSteps - 2),
              o0 = std::min(int(o), kOffsetSteps - 2);
    const float fa = a - float(a0), fb = b - float(b0), fo = o - float(o0);
    const auto at = [&](int ai, int bi) {
        const float* p = shares_.data() + (size_t(ai) * kAngleSteps + size_t(bi)) * kOffsetSteps + size_t(o0);
        return p[0] + fo * (p[1] - p[0]);
    };
    const auto alongAngle = [&](int ai) { return at(ai, b0) + fb * (at(ai, b0 + 1) - at(ai, b0)); };
    return alongAngle(a0) + fa * (alongAngle(a0 + 1) - alongAngle(a0));
}

std::vector<HalfSpaceShare> lobeHalfSpaces(float nDotV, float alpha)
{
    nDotV = std::clamp(nDotV, kMinNDotV, 1.0f);
    alpha = std::max(alpha, kMinAlpha);
    const glm::vec3 v(std::sqrt(1.0f - nDotV * nDotV), 0.0f, nDotV);
    WeightedDirections lobe;
    for (uint32_t i = 0; i < kLobeSamples; ++i) {
        const glm::vec3 h = ggxHalfVector(hammersley(i, kLobeSamples), alpha);
        const glm::vec3 l = reflectAbout(v, h);
        const float vDotH = glm::dot(v, h);
        // Density of l: D (n.h) / (4 v.h); the lobe D Vis (n.l) over it.
        if (l.z > 0.0f && vDotH > 0.0f)
            lobe.push_back({l, double(smithVisibility(l.z, nDotV, alpha)) * l.z * vDotH / h.z});
    }
    normalise(lobe);
    std::vector<HalfSpaceShare> halfSpaces;
    std::vector<std::pair<float, double>> projections(lobe.size());
    for (int j = 0; j < kDirections; ++j) {
        // Fibonacci directions (golden angle), those with e.y >= 0.
        const float z = 1.0f - 2.0f * (float(j) + 0.5f) / float(kDirections);
        const float phi = float(j) * 2.39996323f, r = std::sqrt(1.0f - z * z);
        const glm::vec3 e(r * std::cos(phi), r * std::sin(phi), z);
        if (e.y < 0.0f)
            continue;
        for (size_t i = 0; i < lobe.size(); ++i)
            projections[i] = {glm::dot(lobe[i].first, e), lobe[i].second};
        std::sort(projections.begin(), projections.end());
        double below = 0.0;
        size_t i = 0;
        for (const float q : kQuantiles) {
            while (i < projections.size() && below + projections[i].second < double(q))
                below += projections[i++].second;
            const float t = i < projections.size() ? projections[i].first : 1.0f;
            // The lobe's share strictly above t (ties at t count below, as the table's bins).
            double above = 0.0;
            for (size_t k = i; k < projections.size(); ++k)
                if (projections[k].first > t)
                    above += projections[k].second;
            halfSpaces.push_back({e, t, float(above)});
        }
    }
    return halfSpaces;
}

double lobeTapDistance(const LookupLobeShares& shares, const std::vector<HalfSpaceShare>& halfSpaces, float nDotV,
                       float alpha, LobeTaps taps)
{
    nDotV = std::clamp(nDotV, kMinNDotV, 1.0f);
    const float log2Alpha = std::log2(std::max(alpha, kMinAlpha));
    const std::array<glm::vec3, 2> axis = {lookupDirection(nDotV, taps[0]), lookupDirection(nDotV, taps[2])};
    const std::array<float, 2> width = {log2Alpha + taps[1], log2Alpha + taps[3]};
    double sum = 0.0;
    for (const HalfSpaceShare& h : halfSpaces) {
        const float share = 0.5f * (shares.above(width[0], glm::dot(h.e, axis[0]), h.t) +
                                    shares.above(width[1], glm::dot(h.e, axis[1]), h.t));
        sum += double(share - h.share) * double(share - h.share);
    }
    return std::sqrt(sum / double(halfSpaces.size()));
}

LobeTaps dominantDirectionTaps(float roughness)
{
    const float alpha = alphaFromRoughness(std::clamp(roughness, 0.0f, 1.0f));
    const float k = (1.0f - alpha) * (std::sqrt(1.0f - alpha) + alpha);
    return LobeTaps(k, 0.0f, k, 0.0f);
}

LobeTaps fitLobeTaps(const LookupLobeShares& shares, float nDotV, float roughness, const std::vector<LobeTaps>& starts)
{
    const float alpha = alphaFromRoughness(std::clamp(roughness, 0.0f, 1.0f));
    const float log2Alpha = std::log2(alpha);
    if (log2Alpha < LookupLobeShares::kMinLog2Alpha)
        return dominantDirectionTaps(roughness);
    const std::vector<HalfSpaceShare> halfSpaces = lobeHalfSpaces(nDotV, alpha);
    const float minD = LookupLobeShares::kMinLog2Alpha - log2Alpha, maxD = LookupLobeShares::kMaxLog2Alpha - log2Alpha;
    const auto clamped = [&](LobeTaps x) {
        return LobeTaps(std::clamp(x[0], 0.0f, kMaxK), std::clamp(x[1], minD, maxD), std::clamp(x[2], 0.0f, kMaxK),
                        std::clamp(x[3], minD, maxD));
    };
    // Outside the bounds: the clamped value plus the distance out, so the search turns back.
    const auto objective = [&](LobeTaps x) {
        const LobeTaps inside = clamped(x);
        const glm::vec4 out = glm::abs(x - inside);
        return lobeTapDistance(shares, halfSpaces, nDotV, alpha, inside) + double(out.x + out.y + out.z + out.w);
    };
    std::vector<LobeTaps> all = starts;
    all.push_back(LobeTaps(1.0f, -1.0f, 0.45f, 0.0f)); // a core at R, a halo half way to n
    LobeTaps best = clamped(all.front());
    double bestValue = objective(best);
    for (const LobeTaps& start : all) {
        const LobeTaps x = clamped(nelderMead(objective, clamped(start), glm::vec4(0.1f, 0.3f, 0.1f, 0.3f), 400));
        const double value = objective(x);
        if (value < bestValue) {
            best = x;
            bestValue = value;
        }
    }
    if (best[2] > best[0] || (best[2] == best[0] && best[3] < best[1]))
        best = LobeTaps(best[2], best[3], best[0], best[1]);
    return best;
}

std::vector<float> fitLobeTapTable(uint32_t size)
{
    const LookupLobeShares shares;
    const float last = float(size - 1);
    const auto texel = [&](std::vector<LobeTaps>& table, uint32_t column, uint32_t row) -> LobeTaps& {
        return table[size_t(row) * size + column];
    };
    const auto fit = [&](uint32_t column, uint32_t row, const std::vector<LobeTaps>& starts) {
        return fitLobeTaps(shares, float(column) / last, float(row) / last, starts);
    };
    // Pass 1: each row from n.v = 0.6 outwards, each texel from its neighbour's solution.
    std::vector<LobeTaps> first(size_t(size) * size);
    const uint32_t middle = uint32_t(std::lround(0.6f * last));
    forEachBand(size, 1, [&](size_t, size_t begin, size_t end) {
        for (uint32_t row = uint32_t(begin); row < uint32_t(end); ++row) {
            texel(first, middle, row) = fit(middle, row, {});
            for (uint32_t column = middle + 1; column < size; ++column)
                texel(first, column, row) = fit(column, row, {texel(first, column - 1, row)});
            for (uint32_t column = middle; column-- > 0;)
                texel(first, column, row) = fit(column, row, {texel(first, column + 1, row)});
        }
    });
    // Pass 2: every texel from itself and its four neighbours.
    std::vector<LobeTaps> second = first;
    forEachBand(size, 1, [&](size_t, size_t begin, size_t end) {
        for (uint32_t row = uint32_t(begin); row < uint32_t(end); ++row)
            for (uint32_t column = 0; column < size; ++column) {
                std::vector<LobeTaps> starts = {texel(first, column, row)};
                if (column > 0)
                    starts.push_back(texel(first, column - 1, row));
                if (column + 1 < size)
                    starts.push_back(texel(first, column + 1, row));
                if (row > 0)
                    starts.push_back(texel(first, column, row - 1));
                if (row + 1 < size)
                    starts.push_back(texel(first, column, row + 1));
                texel(second, column, row) = fit(column, row, starts);
            }
    });
    // At n.v = 1 (R = n) the directions do not matter: take the neighbour's, so the table
    // interpolates smoothly into the last column.
    for (uint32_t row = 0; row < size; ++row) {
        texel(second, size - 1, row)[0] = texel(second, size - 2, row)[0];
        texel(second, size - 1, row)[2] = texel(second, size - 2, row)[2];
    }
    std::vector<float> out;
    out.reserve(second.size() * 4);
    for (const LobeTaps& t : second)
        out.insert(out.end(), {t[0], t[1], t[2], t[3]});
    return out;
}

} // namespace lfd::lighting
