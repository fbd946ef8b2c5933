// The split-sum BRDF table (Karis 2013, "Real Shading in Unreal Engine 4": the environment
// BRDF), per n.v and roughness, for the glTF BRDF of brdf.h, plus a third channel for the
// diffuse lobe:
//   A = integral of D Vis (n.l) (1 - (1 - v.h)^5) dl,  B = integral of D Vis (n.l) (1 - v.h)^5 dl,
//       so that the specular lobe's integral against a white environment is F0 A + B;
//   C = (1 / pi) integral of (1 - v.h)^5 (n.l) dl, h = normalize(v + l): the cosine-weighted
//       average of Schlick's weight, so (1 - F0)(1 - C) is the exact average of (1 - F) over
//       a Lambert lobe (C does not depend on roughness; it shares the table for one fetch).
//
// Layout: `size` x `size` texels of (A, B, C), 3 floats each; column i holds
// n.v = i / (size - 1) (0 evaluated at the shader's floor kMinNDotV), row j holds
// roughness = j / (size - 1), row 0 first. The corner texels are the exact ends, so GL
// reads the table with GL_LINEAR, GL_CLAMP_TO_EDGE at brdfTableCoordinate:
//   uv = (vec2(n.v, roughness) * (size - 1) + 0.5) / size.
#pragma once

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace lfd::lighting {

struct BrdfTable {
    uint32_t size = 0;
    std::vector<float> abc; // size * size * 3: (A, B, C), row = roughness, column = n.v

    glm::vec3 texel(uint32_t column, uint32_t row) const
    {
        const float* p = abc.data() + (size_t(row) * size + column) * 3;
        return {p[0], p[1], p[2]};
    }
};

// The table at `size` (>= 2) points per axis, each texel integrated over `samples`
// (>= 1) Hammersley points: GGX half vectors for A and B, cosine-weighted directions for C.
// Deterministic; rows run on every core. 32 x 32 at 2048 samples (about 0.1 s) is within
// 2e-4 of the exact terms everywhere we looked once read with GL_LINEAR; the error comes
// from the sample count (512: A off by 0.008 at n.v 0.25, roughness 0.7), not the size
// (64 x 64 reads the same).
BrdfTable splitSumBrdfTable(uint32_t size, uint32_t samples);

// (A, B, C) at one (n.v, roughness), integrated as one texel of the table is.
glm::vec3 splitSumTerms(float nDotV, float roughness, uint32_t samples);

// The texture coordinate of (n.v, roughness) in a table of `size` (see the header comment).
glm::vec2 brdfTableCoordinate(float nDotV, float roughness, uint32_t size);
// (A, B, C) read as GL_LINEAR with GL_CLAMP_TO_EDGE reads it at brdfTableCoordinate.
glm::vec3 sampleBrdfTable(const BrdfTable& table, float nDotV, float roughness);

// GL_LINEAR with GL_CLAMP_TO_EDGE at brdfTableCoordinate of any square (n.v, roughness)
// table with a `size` and a `texel(x, y)` (the BRDF table, the lobe tap table): texel
// centres at (i + 0.5) / size.
template <class Table>
auto sampleSquareTableLinear(const Table& table, float nDotV, float roughness)
{
    const glm::vec2 texel = brdfTableCoordinate(nDotV, roughness, table.size) * float(table.size) - 0.5f;
    const int last = int(table.size) - 1;
    const float x0f = std::floor(texel.x), y0f = std::floor(texel.y);
    const float fx = texel.x - x0f, fy = texel.y - y0f;
    const auto at = [&](float x, float y) {
        return table.texel(uint32_t(std::clamp(int(x), 0, last)), uint32_t(std::clamp(int(y), 0, last)));
    };
    return glm::mix(glm::mix(at(x0f, y0f), at(x0f + 1.0f, y0f), fx),
                    glm::mix(at(x0f, y0f + 1.0f), at(x0f + 1.0f, y0f + 1.0f), fx), fy);
}

} // namespace lfd::lighting
