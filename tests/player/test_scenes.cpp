#include "test_scenes.h"

#include "scene_bounds.h"
#include "triangle_stats.h"

#include "lfd/framing.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lfd::test {

namespace {

// Appends a mesh of one primitive and a node instancing it.
void addInstancedMesh(Scene& scene, const std::vector<uint32_t>& indices, int32_t material, const glm::vec3& t,
                      const glm::quat& r, const glm::vec3& s)
{
    addNode(scene, addMesh(scene, indices, material), t, r, s);
}

// Cube of half size 0.5 with per-face normals, uvs (0..2 per face) and tangents.
std::vector<uint32_t> addCube(Scene& scene)
{
    VertexStreams& v = scene.vertices;
    std::vector<uint32_t> indices;
    const glm::vec3 normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (const glm::vec3& n : normals) {
        // Face basis: u along the tangent, w = n x u along the bitangent (right-handed).
        const glm::vec3 up = std::abs(n.y) > 0.5f ? glm::vec3(0, 0, -1) : glm::vec3(0, 1, 0);
        const glm::vec3 u = glm::normalize(glm::cross(up, n));
        const glm::vec3 w = glm::cross(n, u);
        const uint32_t base = uint32_t(v.positions.size());
        const glm::vec2 corners[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (const glm::vec2& c : corners) {
            v.positions.push_back(0.5f * (n + c.x * u + c.y * w));
            v.normals.push_back(n);
            v.tangents.push_back(glm::vec4(u, 1.0f));
            v.uvs.push_back(glm::vec2(c.x + 1.0f, 1.0f - c.y)); // 0..2: the checker repeats
        }
        for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u})
            indices.push_back(base + i);
    }
    return indices;
}

} // namespace

std::vector<uint32_t> addSphere(Scene& scene, float radius, uint32_t slices, uint32_t stacks)
{
    VertexStreams& v = scene.vertices;
    const uint32_t base = uint32_t(v.positions.size());
    const float pi = std::numbers::pi_v<float>;
    for (uint32_t j = 0; j <= stacks; ++j) {
        const float theta = pi * float(j) / float(stacks);
        for (uint32_t i = 0; i <= slices; ++i) {
            const float phi = 2.0f * pi * float(i) / float(slices);
            const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi));
            v.positions.push_back(radius * n);
            v.normals.push_back(n);
            v.tangents.push_back(glm::vec4(-std::sin(phi), 0.0f, -std::cos(phi), 1.0f));
            v.uvs.push_back(glm::vec2(float(i) / float(slices), float(j) / float(stacks)));
        }
    }
    std::vector<uint32_t> indices;
    for (uint32_t j = 0; j < stacks; ++j)
        for (uint32_t i = 0; i < slices; ++i) {
            const uint32_t a = base + j * (slices + 1) + i, b = a + slices + 1;
            for (uint32_t k : {a, b, a + 1, a + 1, b, b + 1})
                indices.push_back(k);
        }
    return indices;
}

std::vector<uint32_t> addGrid(Scene& scene, float h, uint32_t cells, float uvScale)
{
    VertexStreams& v = scene.vertices;
    const uint32_t base = uint32_t(v.positions.size());
    for (uint32_t y = 0; y <= cells; ++y)
        for (uint32_t x = 0; x <= cells; ++x) {
            const float u = float(x) / float(cells), w = float(y) / float(cells);
            v.positions.push_back({h * (2.0f * u - 1.0f), h * (2.0f * w - 1.0f), 0.0f});
            v.normals.push_back({0.0f, 0.0f, 1.0f});
            v.tangents.push_back({1.0f, 0.0f, 0.0f, 1.0f});
            v.uvs.push_back({uvScale * u, uvScale * (1.0f - w)});
        }
    std::vector<uint32_t> indices;
    for (uint32_t y = 0; y < cells; ++y)
        for (uint32_t x = 0; x < cells; ++x) {
            const uint32_t a = base + y * (cells + 1) + x, b = a + cells + 1;
            for (uint32_t k : {a, a + 1, b + 1, a, b + 1, b})
                indices.push_back(k);
        }
    return indices;
}

int32_t addMesh(Scene& scene, const std::vector<uint32_t>& indices, int32_t material)
{
    Primitive prim;
    prim.firstIndex = uint32_t(scene.indices.size());
    prim.indexCount = uint32_t(indices.size());
    prim.material = material;
    scene.indices.insert(scene.indices.end(), indices.begin(), indices.end());
    Mesh mesh;
    mesh.name = "mesh" + std::to_string(scene.meshes.size());
    mesh.firstPrimitive = uint32_t(scene.primitives.size());
    mesh.primitiveCount = 1;
    scene.primitives.push_back(prim);
    scene.meshes.push_back(mesh);
    return int32_t(scene.meshes.size() - 1);
}

void addNode(Scene& scene, int32_t mesh, const glm::vec3& t, const glm::quat& r, const glm::vec3& s)
{
    Node node;
    node.name = "node" + std::to_string(scene.nodes.size());
    node.mesh = mesh;
    node.translation = t;
    node.rotation = r;
    node.scale = s;
    scene.nodes.push_back(node);
}

void finishScene(Scene& scene)
{
    bake::computeTriangleStats(scene);
    scene.bounds = bake::computeBounds(scene);
}

SceneBounds unitBounds()
{
    SceneBounds b;
    b.min = glm::vec3(-1.0f);
    b.max = glm::vec3(1.0f);
    b.center = glm::vec3(0.0f);
    b.radius = 1.0f;
    return b;
}

glm::dvec2 pixelUnits(const DisplayProfile& profile)
{
    return viewPixelSizeMm(profile) / fitSceneToDisplay(profile, unitBounds()).mmPerUnit;
}

uint32_t addVertex(Scene& scene, glm::vec3 p, glm::vec3 n, glm::vec2 uv)
{
    scene.vertices.positions.push_back(p);
    scene.vertices.normals.push_back(n);
    scene.vertices.uvs.push_back(uv);
    return uint32_t(scene.vertices.positions.size() - 1);
}

Texture checkerTexture(uint32_t size, uint32_t square, glm::u8vec4 a, glm::u8vec4 b, bool srgb)
{
    Texture tex;
    tex.name = "checker";
    tex.width = tex.height = tex.sourceWidth = tex.sourceHeight = size;
    tex.srgb = srgb;
    // Level 0, then 2x2 box filtered levels down to 1x1 (plain byte averages are enough
    // for a test texture).
    std::vector<uint8_t> level(size_t(size) * size * 4);
    for (uint32_t y = 0; y < size; ++y)
        for (uint32_t x = 0; x < size; ++x) {
            const glm::u8vec4 c = ((x / square + y / square) % 2) ? b : a;
            std::copy(&c[0], &c[0] + 4, &level[(size_t(y) * size + x) * 4]);
        }
    uint32_t w = size;
    while (true) {
        MipLevel mip{w, w, tex.texels.size(), level.size()};
        tex.mips.push_back(mip);
        tex.texels.insert(tex.texels.end(), level.begin(), level.end());
        if (w == 1)
            break;
        const uint32_t h = w / 2;
        std::vector<uint8_t> next(size_t(h) * h * 4);
        for (uint32_t y = 0; y < h; ++y)
            for (uint32_t x = 0; x < h; ++x)
                for (uint32_t ch = 0; ch < 4; ++ch) {
                    uint32_t sum = 0;
                    for (uint32_t dy = 0; dy < 2; ++dy)
                        for (uint32_t dx = 0; dx < 2; ++dx)
                            sum += level[((size_t(2 * y + dy) * w) + 2 * x + dx) * 4 + ch];
                    next[(size_t(y) * h + x) * 4 + ch] = uint8_t((sum + 2) / 4);
                }
        level.swap(next);
        w = h;
    }
    return tex;
}

Scene cubeAndSphereScene()
{
    Scene scene;
    scene.textures.push_back(checkerTexture(128, 8, {230, 200, 60, 255}, {40, 60, 160, 255}, true));

    Material cube;
    cube.name = "checker";
    cube.baseColorTexture = 0;
    cube.metallicFactor = 0.0f;
    cube.roughnessFactor = 0.5f;
    Material red;
    red.name = "red";
    red.baseColorFactor = {0.8f, 0.1f, 0.08f, 1.0f};
    red.metallicFactor = 0.1f;
    red.roughnessFactor = 0.35f;
    scene.materials = {cube, red};

    const std::vector<uint32_t> cubeIndices = addCube(scene);
    const std::vector<uint32_t> sphereIndices = addSphere(scene, 0.5f, 24, 16);
    addInstancedMesh(scene, cubeIndices, 0, {-0.6f, 0.0f, 0.0f},
            glm::angleAxis(0.5f, glm::normalize(glm::vec3(1.0f, 1.0f, 0.0f))), glm::vec3(1.0f));
    addInstancedMesh(scene, sphereIndices, 1, {0.7f, 0.05f, -0.1f}, glm::quat(1, 0, 0, 0), glm::vec3(0.9f));
    // A small default-material box in front: material -1 must render with glTF defaults.
    addInstancedMesh(scene, cubeIndices, kNone, {0.1f, -0.45f, 0.55f}, glm::quat(1, 0, 0, 0), glm::vec3(0.25f));
    finishScene(scene);
    return scene;
}

Scene positionsOnlyScene()
{
    Scene scene;
    scene.vertices.positions = {{-0.5f, -0.4f, 0.3f}, {0.5f, -0.4f, 0.3f}, {0.0f, -0.4f, -0.5f}, {0.0f, 0.5f, 0.0f}};
    addInstancedMesh(scene, {0, 1, 3, 1, 2, 3, 2, 0, 3, 0, 2, 1}, kNone, glm::vec3(0.0f), glm::quat(1, 0, 0, 0),
            glm::vec3(1.0f));
    finishScene(scene);
    return scene;
}

Material emissiveOnlyMaterial(const glm::vec3& emissive)
{
    Material m;
    m.baseColorFactor = {0.0f, 0.0f, 0.0f, 1.0f};
    m.metallicFactor = 1.0f;
    m.roughnessFactor = 1.0f;
    m.emissiveFactor = emissive;
    return m;
}

EmissiveQuads emissiveQuadsScene(float radius, float zBack)
{
    EmissiveQuads q;
    Scene& scene = q.scene;
    q.frontEmissive = {0.2f, 0.9f, 0.3f};
    q.backEmissive = {0.9f, 0.25f, 0.6f};
    q.frontCenter = {-0.3f * radius, 0.25f * radius, 0.0f};
    q.backCenter = {0.3f * radius, 0.0f, zBack};
    for (const glm::vec3& e : {q.frontEmissive, q.backEmissive})
        scene.materials.push_back(emissiveOnlyMaterial(e));
    const float h = 0.1f * radius; // quads of 0.2 r x 0.2 r
    for (int k = 0; k < 2; ++k) {
        const uint32_t base = uint32_t(scene.vertices.positions.size());
        for (const glm::vec2& c : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
            scene.vertices.positions.push_back(glm::vec3(h * c, 0.0f));
            scene.vertices.normals.push_back({0.0f, 0.0f, 1.0f});
        }
        addInstancedMesh(scene, {base, base + 1, base + 2, base, base + 2, base + 3}, k,
                k == 0 ? q.frontCenter : q.backCenter, glm::quat(1, 0, 0, 0), glm::vec3(1.0f));
    }
    bake::computeTriangleStats(scene);
    scene.bounds.min = glm::vec3(-radius);
    scene.bounds.max = glm::vec3(radius);
    scene.bounds.center = glm::vec3(0.0f);
    scene.bounds.radius = radius;
    return q;
}

// A block of rotated instances of the test cube and sphere: many small triangles, depth
// and occlusion (a miniature of the dense benchmark sample).
Scene denseTestScene()
{
    Scene scene = cubeAndSphereScene();
    const std::vector<Node> originals = scene.nodes;
    scene.nodes.clear();
    for (int i = 0; i < 12; ++i) {
        for (Node node : originals) {
            if (node.mesh == kNone)
                continue;
            node.translation += glm::vec3(float(i % 4) - 1.5f, float(i / 4) - 1.0f, float(i % 3) - 1.0f) * 1.2f;
            node.rotation = glm::angleAxis(0.7f * float(i), glm::vec3(0.3f, 1.0f, 0.2f)) * node.rotation;
            node.parent = kNone;
            scene.nodes.push_back(node);
        }
    }
    finishScene(scene);
    return scene;
}

} // namespace lfd::test
