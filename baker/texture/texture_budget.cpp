// Texture budget: drop mip levels finer than any view can resolve (docs/baker/lfd-bake.md "What a
// bake does", step 6: texture levels finer than any view can resolve are never sampled, so they are
// not stored).

#include "texture_budget.h"

#include <algorithm>
#include <cmath>

namespace lfd::bake {
namespace {

// The smallest area scale (KHR_texture_transform, TextureTransform::areaScale) of the
// slots of `m` that sample texture `t`, or a negative value when none does: the slot that
// spreads the texture over the most uv area puts the fewest texels on a triangle, so it
// decides how many the texture needs.
double smallestAreaScale(const Material& m, int32_t t)
{
    double smallest = -1.0;
    for (uint32_t s = 0; s < kTextureSlotCount; ++s)
        if (m.texture(TextureSlot(s)) == t) {
            const double scale = double(m.textureTransforms[s].areaScale());
            smallest = smallest < 0.0 ? scale : std::min(smallest, scale);
        }
    return smallest;
}

} // namespace

glm::uvec2 resolvableTextureSize(const Scene& scene, uint32_t textureIndex, glm::uvec2 sourceSize,
                                 double viewPixelWorld, const std::vector<float>& meshScale,
                                 double detail)
{
    if (scene.vertices.uvs.empty() || viewPixelWorld <= 0.0 || sourceSize.x == 0 || sourceSize.y == 0)
        return sourceSize;

    // On a triangle of world area A (object area * scale^2) the finest view pixels cover
    // at most A / viewPixelWorld^2 pixels; the texture puts A_ts * X * Y texels on it.
    // The texture can shrink by f while texels still outnumber detail^2 * pixels on every
    // triangle: f^2 = max_tri detail^2 * pixels / texels (paper eq. texelCount's n_tex, A_ts
    // in the texture's own uv space: TEXCOORD_0's area times the slot's transform's area
    // scale, the smallest where several slots sample the texture).
    const double pixelArea = viewPixelWorld * viewPixelWorld;
    const double texelsAtSource = double(sourceSize.x) * double(sourceSize.y);
    double neededFraction = 0.0; // of the source's texel count
    bool used = false;
    for (size_t mi = 0; mi < scene.meshes.size(); ++mi) {
        const Mesh& mesh = scene.meshes[mi];
        const double scale = mi < meshScale.size() ? double(meshScale[mi]) : 1.0;
        if (scale <= 0.0)
            continue; // instanced by no node: never drawn
        for (uint32_t p = mesh.firstPrimitive; p < mesh.firstPrimitive + mesh.primitiveCount; ++p) {
            const Primitive& prim = scene.primitives[p];
            const double areaScale =
                prim.material < 0 ? -1.0 : smallestAreaScale(scene.materials[size_t(prim.material)], int32_t(textureIndex));
            if (areaScale < 0.0)
                continue;
            used = true;
            for (uint32_t i = prim.firstIndex; i < prim.firstIndex + prim.indexCount; i += 3) {
                const glm::dvec3 p0 = scene.vertices.positions[scene.indices[i]];
                const glm::dvec3 p1 = scene.vertices.positions[scene.indices[i + 1]];
                const glm::dvec3 p2 = scene.vertices.positions[scene.indices[i + 2]];
                const glm::dvec2 t0 = scene.vertices.uvs[scene.indices[i]];
                const glm::dvec2 t1 = scene.vertices.uvs[scene.indices[i + 1]];
                const glm::dvec2 t2 = scene.vertices.uvs[scene.indices[i + 2]];
                const double areaWorld = 0.5 * glm::length(glm::cross(p1 - p0, p2 - p0)) * scale * scale;
                const glm::dvec2 e1 = t1 - t0, e2 = t2 - t0;
                const double areaTexture = 0.5 * std::abs(e1.x * e2.y - e1.y * e2.x) * areaScale;
                if (areaTexture <= 0.0 || !std::isfinite(areaWorld))
                    continue;
                const double pixels = areaWorld / pixelArea;
                const double texels = areaTexture * texelsAtSource;
                neededFraction = std::max(neededFraction, detail * detail * pixels / texels);
                if (neededFraction >= 1.0)
                    return sourceSize; // some triangle needs full resolution: stop early
            }
        }
    }
    if (!used || neededFraction <= 0.0)
        return sourceSize;

    // Halve both dimensions while the reduced texture still carries enough texels.
    glm::uvec2 size = sourceSize;
    double fraction = 1.0;
    while ((size.x > 1 || size.y > 1) && fraction * 0.25 >= neededFraction) {
        size = glm::max(size / 2u, glm::uvec2(1));
        fraction *= 0.25;
    }
    return size;
}

} // namespace lfd::bake
