// The "terrain" sample (issue 40): an over-dense, scanned-looking heightfield - 1023 x
// 1023 quads (2,093,058 triangles) of smooth hills with sub-millimetre scan noise, framed
// whole - whose triangles are far smaller than a view pixel of the display it is baked
// for (about a third of one on the prototype). It is what `lfd-bake --simplify` is for and
// is measured against: the same surface with a fraction of the triangles.
#include "gltf_builder.h"
#include "mesh_builder.h"
#include "procedural_textures.h"
#include "sample_scenes.h"

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <cstdint>
#include <string>

namespace lfd::samples {

namespace {

// Deterministic per-grid-point noise in [-1, 1] (an integer hash: the same file on every
// machine, unlike <random>'s distributions).
float hashNoise(uint32_t i, uint32_t j)
{
    uint32_t h = i * 0x8da6b343u ^ j * 0xd8163841u;
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    h ^= h >> 15;
    return float(h & 0xffffu) / 32767.5f - 1.0f;
}

// Height (metres) of the 2 x 2 m patch at (x, z) in [-1, 1]: a few octaves of smooth
// hills and ridges, the finest about 10 cm across.
float height(float x, float z)
{
    const float pi = glm::pi<float>();
    float h = 0.18f * std::sin(1.3f * pi * x + 0.4f) * std::cos(1.1f * pi * z - 0.3f);
    h += 0.07f * std::sin(3.7f * pi * (x + 0.6f * z)) * std::cos(2.9f * pi * z + 1.0f);
    h += 0.025f * std::sin(9.0f * pi * x - 0.5f) * std::sin(7.5f * pi * z + 0.2f);
    h += 0.01f * std::cos(19.0f * pi * (0.8f * x - z));
    return h;
}

} // namespace

SceneSummary writeTerrainScene(const std::filesystem::path& dir)
{
    constexpr int kQuads = 1023;
    constexpr float kNoise = 0.0002f; // 0.2 mm: scan noise, far below a view pixel
    MeshData terrain;
    const int n = kQuads + 1;
    terrain.positions.reserve(size_t(n) * n);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const float x = -1.0f + 2.0f * float(i) / float(kQuads), z = -1.0f + 2.0f * float(j) / float(kQuads);
            terrain.positions.emplace_back(x, height(x, z) + kNoise * hashNoise(uint32_t(i), uint32_t(j)), z);
            terrain.uvs.emplace_back(float(i) / float(kQuads), float(j) / float(kQuads));
        }
    // Smooth normals from central differences of the noiseless surface (a scanner's
    // normals are smoothed too).
    const float d = 2.0f / float(kQuads);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const glm::vec3& p = terrain.positions[size_t(j) * n + i];
            const float dx = height(p.x + d, p.z) - height(p.x - d, p.z);
            const float dz = height(p.x, p.z + d) - height(p.x, p.z - d);
            terrain.normals.push_back(glm::normalize(glm::vec3(-dx, 2.0f * d, -dz)));
        }
    terrain.indices.reserve(size_t(kQuads) * kQuads * 6);
    for (int j = 0; j < kQuads; ++j)
        for (int i = 0; i < kQuads; ++i) {
            const auto c = uint32_t(j * n + i);
            // Counter-clockwise seen from +y (the normals' side).
            terrain.indices.insert(terrain.indices.end(), {c, c + uint32_t(n), c + 1, c + 1, c + uint32_t(n), c + uint32_t(n) + 1});
        }

    GltfBuilder gltf("terrain.bin");
    writePlasterTexture(dir / "terrain_color.png", 1024);
    const int texture = gltf.addTexture("terrain_color.png");
    const int material = gltf.addMaterial(
        {.name = "terrain", .baseColorFactor = {0.75f, 0.85f, 0.65f, 1.0f}, .roughness = 0.9f, .baseColorTexture = texture});
    const int mesh = gltf.addMesh("terrain", {{&terrain, material}});
    gltf.setScene("terrain", {gltf.addNode({.name = "terrain", .mesh = mesh})});
    gltf.write(dir / "terrain.gltf");
    return {"terrain", gltf.storedTriangles(), gltf.drawnTriangles(), 1};
}

} // namespace lfd::samples
