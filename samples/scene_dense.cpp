// The "dense" sample: a paper-scale benchmark scene (about 1M drawn triangles by default)
// that stresses what LFDPR is for - many small triangles, depth and occlusion, textures
// and normal maps. One detailed object (a bumpy, textured, normal-mapped shell of about
// 4.5K triangles) is instanced in a block that fills the views, rows behind rows.
#include "gltf_builder.h"
#include "mesh_builder.h"
#include "procedural_textures.h"
#include "sample_scenes.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace lfd::samples {

namespace {

// The shell: a superellipsoid with a ripple, parameterised by (u, v) in [0, 1]^2 (uv =
// (u, 1 - v): the samples' sampler clamps to the edge), tangents along +u, a seam
// column of duplicated vertices. 76 x 30 quads = 4,560 triangles.
MeshData makeShell()
{
    const int segments = 76, rings = 30;
    const float pi = glm::pi<float>();
    auto position = [&](float u, float v) {
        const float theta = 2.0f * pi * u, phi = -0.5f * pi + pi * v;
        const glm::vec3 base = superellipsoidPoint({0.5f, 0.5f, 0.5f}, 0.7f, 0.8f, theta, phi);
        const float ripple = 1.0f + 0.06f * std::sin(9.0f * theta) * std::cos(phi) * std::sin(7.0f * phi);
        return base * ripple;
    };
    MeshData mesh;
    for (int r = 0; r <= rings; ++r) {
        for (int s = 0; s <= segments; ++s) {
            const float u = float(s) / float(segments), v = float(r) / float(rings);
            const glm::vec3 p = position(u, v);
            // Normal and tangent by central differences (the poles take the neighbour ring's).
            const float du = 0.5f / float(segments), dv = 0.5f / float(rings);
            const float vc = std::clamp(v, dv, 1.0f - dv);
            const glm::vec3 tu = position(u + du, vc) - position(u - du, vc);
            const glm::vec3 tv = position(u, vc + dv) - position(u, vc - dv);
            glm::vec3 n = glm::cross(tu, tv);
            n = glm::dot(n, n) > 0.0f ? glm::normalize(n) : glm::vec3(0.0f, v < 0.5f ? -1.0f : 1.0f, 0.0f);
            mesh.positions.push_back(p);
            mesh.normals.push_back(n);
            mesh.uvs.push_back({u, 1.0f - v});
            mesh.tangents.push_back(glm::vec4(glm::normalize(tu), 1.0f));
        }
    }
    const auto at = [&](int r, int s) { return uint32_t(r * (segments + 1) + s); };
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const uint32_t a = at(r, s), b = at(r, s + 1), c = at(r + 1, s + 1), d = at(r + 1, s);
            mesh.indices.insert(mesh.indices.end(), {a, b, c, a, c, d});
        }
    return mesh;
}

} // namespace

SceneSummary writeDenseScene(const std::filesystem::path& dir, int instances)
{
    // Step 1: textures (tiles with a normal map and a metallic-roughness map).
    const int textureSize = 512;
    writeFloorBaseColor(dir / "dense_basecolor.png", textureSize);
    writeFloorNormal(dir / "dense_normal.png", textureSize);
    writeFloorMetallicRoughness(dir / "dense_metallic_roughness.png", textureSize);
    GltfBuilder gltf("dense.bin");
    MaterialSpec material{.name = "tiles", .metallic = 1.0f, .roughness = 1.0f};
    material.baseColorTexture = gltf.addTexture("dense_basecolor.png");
    material.normalTexture = gltf.addTexture("dense_normal.png");
    material.metallicRoughnessTexture = gltf.addTexture("dense_metallic_roughness.png");
    const int tiles = gltf.addMaterial(material);
    const MeshData shell = makeShell();
    const int mesh = gltf.addMesh("shell", {{&shell, tiles}});

    // Step 2: a block of columns x rows x layers instances, wider than deep, 1.1 m apart,
    // every other layer offset by half a pitch so back layers show between front ones;
    // each instance turned by a different yaw and pitch.
    const int layers = std::max(1, int(std::round(std::cbrt(double(instances) / 4.0))));
    const int perLayer = (instances + layers - 1) / layers;
    const int columns = std::max(1, int(std::ceil(std::sqrt(double(perLayer) * 1.6))));
    const int rows = (perLayer + columns - 1) / columns;
    const float pitch = 1.1f;
    std::vector<int> children;
    for (int i = 0; i < instances; ++i) {
        const int layer = i / perLayer, k = i % perLayer;
        const int row = k / columns, column = k % columns;
        const float offset = (layer % 2) ? 0.5f * pitch : 0.0f;
        const glm::vec3 at(pitch * (float(column) - 0.5f * float(columns - 1)) + offset,
                           pitch * (float(row) - 0.5f * float(rows - 1)) + offset,
                           pitch * (float(layer) - 0.5f * float(layers - 1)));
        const glm::quat rotation = glm::angleAxis(float(i * 37 % 360) * glm::pi<float>() / 180.0f,
                                                  glm::vec3(0.0f, 1.0f, 0.0f)) *
                                   glm::angleAxis(float(i * 53 % 90 - 45) * glm::pi<float>() / 180.0f,
                                                  glm::vec3(1.0f, 0.0f, 0.0f));
        children.push_back(gltf.addNode({.name = "shell_" + std::to_string(i), .mesh = mesh,
                                         .translation = at, .rotation = rotation}));
    }
    const int root = gltf.addNode({.name = "dense", .children = children});
    gltf.setScene("dense", {root});
    gltf.write(dir / "dense.gltf");
    return {"dense", gltf.storedTriangles(), gltf.drawnTriangles(), 3};
}

} // namespace lfd::samples
