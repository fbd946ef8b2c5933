// The triangle statistics stage (paper eqs. texelCount / lfd_UVSize).
#pragma once

#include "lfd/scene.h"

#include <glm/glm.hpp>

#include <vector>

namespace lfd::bake {

// Paper eqs. texelCount / lfd_UVSize for every triangle. Needs the final (stored) size of
// each texture (scene.textures[i].width/height set). Ranges of triangles are computed on
// up to `threads` threads (0: one per hardware thread); the result does not depend on it.
void computeTriangleStats(Scene& scene, unsigned threads = 0);
// One texture of a triangle's material: its stored size and the area scale of the slot's
// texture transform (TextureTransform::areaScale), so A_ts in the texture's own uv space
// is TEXCOORD_0's area times areaScale.
struct TextureDensity {
    glm::uvec2 size{0};
    double areaScale = 1.0;
    bool operator==(const TextureDensity&) const = default;
};
TriangleStats triangleStats(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2,
                            const glm::vec2& uv0, const glm::vec2& uv1, const glm::vec2& uv2,
                            const std::vector<TextureDensity>& textures);

} // namespace lfd::bake
