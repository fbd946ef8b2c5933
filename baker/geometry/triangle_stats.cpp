// Per-triangle texture statistics, paper section 3.1 "Determining Sampling Density":
//
//   n_tex   = max_{t in T} (A_ts * X_t * Y_t)        eq. texelCount
//   size_uv = A_ws / n_tex                           eq. lfd_UVSize
//
// and the ratio A_ts / A_ws that the player multiplies by a view pixel's projected area
// to get size_vpuv (eqs. minVPUVSize / maxVPUVSize). All of it is view independent, so
// the baker computes it once; A_ws is in object units^2 (the player applies the node's
// area scale). A_ts of texture t is the triangle's area in t's own uv space: TEXCOORD_0's
// area times the area scale of the slot's KHR_texture_transform (formats/README.md
// "TSTA"); the stored areaTexture and texPerWorld stay in TEXCOORD_0's space.

#include "triangle_stats.h"

#include "bake_log.h"
#include "parallel.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace lfd::bake {
namespace {

// Below this the triangle has no meaningful world area (collinear or coincident corners).
constexpr double kDegenerateArea = 1e-30;
// Triangles per work item: a few milliseconds each, so a thread start is amortised and
// small scenes stay on the calling thread.
constexpr size_t kTrianglesPerRange = size_t(1) << 16;

glm::dvec3 toDouble(const glm::vec3& v) { return glm::dvec3(v); }
glm::dvec2 toDouble(const glm::vec2& v) { return glm::dvec2(v); }

// The textures of a material as the statistics see them: one entry per slot that is set,
// with that slot's area scale (a texture in two slots counts once per distinct scale);
// textures whose size is still unknown (width or height 0) left out.
std::vector<TextureDensity> materialTextureDensities(const Scene& scene, int32_t materialIndex)
{
    std::vector<TextureDensity> densities;
    if (materialIndex == kNone)
        return densities;
    if (materialIndex < 0 || size_t(materialIndex) >= scene.materials.size())
        throw BakeError("triangle stats: material " + std::to_string(materialIndex) + " does not exist");
    const Material& material = scene.materials[size_t(materialIndex)];
    for (uint32_t s = 0; s < kTextureSlotCount; ++s) {
        const int32_t t = material.texture(TextureSlot(s));
        if (t == kNone)
            continue;
        if (t < 0 || size_t(t) >= scene.textures.size())
            throw BakeError("triangle stats: material '" + material.name + "' uses texture " + std::to_string(t) +
                            " which does not exist");
        const Texture& texture = scene.textures[size_t(t)];
        const TextureDensity density{{texture.width, texture.height}, double(material.textureTransforms[s].areaScale())};
        if (texture.width > 0 && texture.height > 0 &&
            std::find(densities.begin(), densities.end(), density) == densities.end())
            densities.push_back(density);
    }
    return densities;
}

} // namespace

TriangleStats triangleStats(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2,
                            const glm::vec2& uv0, const glm::vec2& uv1, const glm::vec2& uv2,
                            const std::vector<TextureDensity>& textures)
{
    TriangleStats stats;

    // Compute world-space area A_ws (double: large scenes with small triangles lose the
    // cross product to cancellation in float).
    const glm::dvec3 e1 = toDouble(p1) - toDouble(p0);
    const glm::dvec3 e2 = toDouble(p2) - toDouble(p0);
    const double areaWorld = 0.5 * glm::length(glm::cross(e1, e2));
    const bool degenerate = !(areaWorld > kDegenerateArea); // also catches NaN
    if (degenerate)
        stats.flags |= kTriangleDegenerate;
    else
        stats.areaWorld = float(areaWorld);

    if (textures.empty())
        return stats; // untextured: texture statistics stay 0
    stats.flags |= kTriangleTextured;

    // Compute texture-space area A_ts (uv units^2).
    const glm::dvec2 t1 = toDouble(uv1) - toDouble(uv0);
    const glm::dvec2 t2 = toDouble(uv2) - toDouble(uv0);
    double areaTexture = 0.5 * std::abs(t1.x * t2.y - t1.y * t2.x);
    if (!std::isfinite(areaTexture))
        areaTexture = 0.0;
    stats.areaTexture = float(areaTexture);

    // Compute n_tex = max_t A_ts * X_t * Y_t (eq. texelCount), A_ts in t's uv space.
    double texelCount = 0.0;
    for (const TextureDensity& t : textures)
        texelCount = std::max(texelCount, areaTexture * t.areaScale * double(t.size.x) * double(t.size.y));
    stats.texelCount = float(texelCount);

    if (degenerate)
        return stats; // no area to sample: size_uv and A_ts / A_ws stay 0

    // Compute size_uv = A_ws / n_tex (eq. lfd_UVSize).
    // note: n_tex is clamped to >= 1 texel. A triangle smaller than a texel still covers
    // (part of) one texel and shows one colour, so one splat of its whole area suffices;
    // dividing by n_tex < 1 would ask for splats larger than the triangle, and a triangle
    // whose uvs all coincide (A_ts = 0, n_tex = 0) would get an infinite size_uv.
    stats.sizeUv = float(areaWorld / std::max(texelCount, 1.0));
    // Ratio A_ts / A_ws, scaled by a view pixel's projected area to give size_vpuv.
    stats.texPerWorld = float(areaTexture / areaWorld);
    return stats;
}

void computeTriangleStats(Scene& scene, unsigned threads)
{
    const VertexStreams& v = scene.vertices;
    if (scene.indices.size() % 3 != 0)
        throw BakeError("triangle stats: index count is not a multiple of 3");
    if (!v.uvs.empty() && v.uvs.size() != v.positions.size())
        throw BakeError("triangle stats: uv stream length differs from the position stream");
    for (size_t p = 0; p < scene.primitives.size(); ++p) {
        const Primitive& prim = scene.primitives[p];
        if (prim.firstIndex % 3 != 0 || prim.indexCount % 3 != 0 ||
            uint64_t(prim.firstIndex) + prim.indexCount > scene.indices.size())
            throw BakeError("triangle stats: primitive " + std::to_string(p) + " has an invalid index range");
    }

    // Texture densities per material (computed once; kNone maps to the last entry: none).
    std::vector<std::vector<TextureDensity>> sizesOf(scene.materials.size() + 1);
    for (size_t m = 0; m < scene.materials.size(); ++m)
        sizesOf[m] = materialTextureDensities(scene, int32_t(m));
    auto sizesFor = [&](int32_t material) -> const std::vector<TextureDensity>& {
        if (material == kNone)
            return sizesOf.back();
        if (material < 0 || size_t(material) >= scene.materials.size())
            throw BakeError("triangle stats: material " + std::to_string(material) + " does not exist");
        return v.uvs.empty() ? sizesOf.back() : sizesOf[size_t(material)]; // no uvs: untextured
    };

    // Every triangle's statistics depend on that triangle alone: ranges of triangles go to
    // the threads, each checking its own indices and writing its own slots (the error
    // reported is the first bad triangle's, as in a serial loop: parallel.h).
    const size_t triangleCount = scene.triangleCount();
    scene.triangleStats.resize(triangleCount);
    const glm::vec2 noUv(0.0f);
    const size_t ranges = (triangleCount + kTrianglesPerRange - 1) / kTrianglesPerRange;
    parallelFor(ranges, threads, [&](size_t r) {
        const size_t first = r * kTrianglesPerRange, end = std::min(triangleCount, first + kTrianglesPerRange);
        // Material of each triangle of the range: triangles outside every primitive use
        // the default material (untextured); where primitives overlap, the last one wins.
        std::vector<int32_t> materialOf(end - first, kNone);
        for (const Primitive& prim : scene.primitives) {
            const size_t a = std::max<size_t>(first, prim.firstIndex / 3);
            const size_t b = std::min<size_t>(end, (size_t(prim.firstIndex) + prim.indexCount) / 3);
            if (a < b)
                std::fill(materialOf.begin() + ptrdiff_t(a - first), materialOf.begin() + ptrdiff_t(b - first),
                          prim.material);
        }
        for (size_t t = first; t < end; ++t) {
            const uint32_t i0 = scene.indices[3 * t], i1 = scene.indices[3 * t + 1], i2 = scene.indices[3 * t + 2];
            for (uint32_t index : {i0, i1, i2})
                if (index >= v.positions.size())
                    throw BakeError("triangle stats: vertex index " + std::to_string(index) + " out of range (" +
                                    std::to_string(v.positions.size()) + " vertices)");
            const bool hasUv = !v.uvs.empty();
            scene.triangleStats[t] = triangleStats(v.positions[i0], v.positions[i1], v.positions[i2],
                                                   hasUv ? v.uvs[i0] : noUv, hasUv ? v.uvs[i1] : noUv,
                                                   hasUv ? v.uvs[i2] : noUv, sizesFor(materialOf[t - first]));
        }
    });
}

} // namespace lfd::bake
