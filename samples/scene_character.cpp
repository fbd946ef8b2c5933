// The "character" and "crowd" samples: skinning and morph targets (glTF 2.0 sections
// 3.7.2.2 and 3.7.3). The character is a textured limb of four bones (a tapering tube
// with a head on top) that sways in a wave running up its bones, and a morph target that
// swells its middle and its head ("breathing", animated weights). The crowd is a grid of
// characters, each with its own skeleton and skin and its own phase of the same motion,
// all sharing one mesh (the baker gives each skinned instance its own copy to pose).
#include "gltf_builder.h"
#include "mesh_builder.h"
#include "procedural_textures.h"
#include "sample_scenes.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace lfd::samples {

namespace {

constexpr int kBones = 4;               // joints 0..4 along +y: base, three bends, head
constexpr float kBoneLength = 0.4f;     // metres between joints
constexpr float kPeriod = 2.0f;         // seconds per sway cycle
constexpr int kKeys = 25;               // keys per cycle (LINEAR)

// Tube radius at height y (tapering), and the bulge of the morph target there.
float radiusAt(float y) { return 0.13f - 0.035f * y; }
float bulgeAt(float y) { return std::exp(-std::pow((y - 0.7f) / 0.18f, 2.0f)); }

// Joint influences at height y: bone b (from joint b up) follows joint b; within a
// quarter bone of joint j the vertex blends joints j - 1 and j linearly, so the skin
// bends smoothly there (glTF 3.7.3.1: weights sum to 1).
void influencesAt(float y, glm::u16vec4& joints, glm::vec4& weights)
{
    const float s = std::clamp(y / kBoneLength, 0.0f, float(kBones) + 0.99f);
    const int j = int(std::round(s));
    const float d = s - float(j), h = 0.25f;
    if (j >= 1 && j <= kBones && std::abs(d) < h) {
        const float upper = (d + h) / (2.0f * h);
        joints = glm::u16vec4(uint16_t(j - 1), uint16_t(j), 0, 0);
        weights = glm::vec4(1.0f - upper, upper, 0.0f, 0.0f);
        return;
    }
    joints = glm::u16vec4(uint16_t(std::clamp(d < 0.0f ? j - 1 : j, 0, kBones)), 0, 0, 0);
    weights = glm::vec4(1.0f, 0.0f, 0.0f, 0.0f);
}

// The limb: a tube of `segments` x `rings` quads (u around, v up) from y = 0 to the top,
// capped by a sphere head; uvs wrap the texture once around and once up.
MeshData makeLimb(int segments, int rings)
{
    const float pi = glm::pi<float>();
    const float top = kBones * kBoneLength - 0.1f;
    MeshData mesh;
    mesh.morphPositions.resize(1);
    mesh.morphNormals.resize(1);
    auto addVertex = [&](glm::vec3 p, glm::vec3 n, glm::vec2 uv, float bulge) {
        mesh.positions.push_back(p);
        mesh.normals.push_back(n);
        mesh.uvs.push_back(uv);
        influencesAt(p.y, mesh.joints.emplace_back(), mesh.weights.emplace_back());
        mesh.morphPositions[0].push_back(glm::vec3(n.x, 0.0f, n.z) * (0.06f * bulge));
        mesh.morphNormals[0].push_back(glm::vec3(0.0f));
    };
    for (int r = 0; r <= rings; ++r)
        for (int s = 0; s <= segments; ++s) {
            const float u = float(s) / float(segments), v = float(r) / float(rings);
            const float y = v * top, a = 2.0f * pi * u;
            const glm::vec3 n(std::cos(a), 0.035f, -std::sin(a));
            addVertex({radiusAt(y) * std::cos(a), y, -radiusAt(y) * std::sin(a)}, glm::normalize(n), {u, 1.0f - v},
                      bulgeAt(y));
        }
    const auto at = [&](int r, int s) { return uint32_t(r * (segments + 1) + s); };
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const uint32_t a = at(r, s), b = at(r, s + 1), c = at(r + 1, s + 1), d = at(r + 1, s);
            mesh.indices.insert(mesh.indices.end(), {a, b, c, a, c, d});
        }
    // The head: a sphere on the top joint, swelling with the same target.
    const uint32_t base = uint32_t(mesh.positions.size());
    const int hs = segments / 2, hr = segments / 4;
    const glm::vec3 centre(0.0f, top + 0.12f, 0.0f);
    for (int r = 0; r <= hr; ++r)
        for (int s = 0; s <= hs; ++s) {
            const float theta = 2.0f * pi * float(s) / float(hs), phi = -0.5f * pi + pi * float(r) / float(hr);
            const glm::vec3 n(std::cos(phi) * std::cos(theta), std::sin(phi), -std::cos(phi) * std::sin(theta));
            addVertex(centre + 0.16f * n, n, {float(s) / float(hs), 0.5f * float(r) / float(hr)}, 1.0f);
            mesh.morphPositions[0].back() = n * 0.05f;
        }
    for (int r = 0; r < hr; ++r)
        for (int s = 0; s < hs; ++s) {
            const uint32_t a = base + uint32_t(r * (hs + 1) + s), b = a + 1, c = b + uint32_t(hs + 1), d = a + uint32_t(hs + 1);
            mesh.indices.insert(mesh.indices.end(), {a, b, c, a, c, d});
        }
    return mesh;
}

// One character at `at`: a root node with the joint chain and the skinned limb; its
// channels sway the joints (a wave up the bones) and breathe the morph weight, offset by
// `phase` (0..1 of a cycle).
struct Character {
    int root = -1;
    std::vector<ChannelSpec> channels;
};

Character addCharacter(GltfBuilder& gltf, int mesh, const std::string& name, glm::vec3 at, float yaw, float phase)
{
    std::vector<int> joints(kBones + 1);
    for (int j = kBones; j >= 0; --j) {
        NodeSpec spec{.name = name + "_joint" + std::to_string(j), .translation = {0.0f, j == 0 ? 0.0f : kBoneLength, 0.0f}};
        if (j < kBones)
            spec.children = {joints[size_t(j + 1)]};
        joints[size_t(j)] = gltf.addNode(spec);
    }
    std::vector<glm::mat4> inverseBind; // bind pose: joint j at (0, j * length, 0) of the character
    for (int j = 0; j <= kBones; ++j)
        inverseBind.push_back(glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, -float(j) * kBoneLength, 0.0f)));
    const int skin = gltf.addSkin(joints, inverseBind);
    const int limb = gltf.addNode({.name = name + "_limb", .mesh = mesh, .skin = skin});
    Character c;
    c.root = gltf.addNode({.name = name, .translation = at,
                           .rotation = glm::angleAxis(yaw, glm::vec3(0.0f, 1.0f, 0.0f)), .children = {joints[0], limb}});
    std::vector<float> times;
    for (int k = 0; k < kKeys; ++k)
        times.push_back(kPeriod * float(k) / float(kKeys - 1));
    const float pi = glm::pi<float>();
    for (int j = 1; j < kBones; ++j) {
        ChannelSpec sway{.node = joints[size_t(j)], .path = "rotation", .times = times};
        for (float t : times) {
            const float w = 2.0f * pi * (t / kPeriod + phase) - 0.9f * float(j);
            const glm::quat q = glm::angleAxis(0.45f * std::sin(w), glm::vec3(0.0f, 0.0f, 1.0f)) *
                                glm::angleAxis(0.25f * std::cos(w), glm::vec3(1.0f, 0.0f, 0.0f));
            sway.values.insert(sway.values.end(), {q.x, q.y, q.z, q.w});
        }
        c.channels.push_back(sway);
    }
    ChannelSpec breathe{.node = limb, .path = "weights", .times = times, .components = 1};
    for (float t : times)
        breathe.values.push_back(0.5f + 0.5f * std::sin(2.0f * pi * (2.0f * t / kPeriod + phase)));
    c.channels.push_back(breathe);
    return c;
}

SceneSummary writeCharacters(const std::filesystem::path& dir, const std::string& name, int instances, int segments,
                             int rings)
{
    writePaintingTexture(dir / (name + "_skin.png"), 512);
    GltfBuilder gltf(name + ".bin");
    MaterialSpec material{.name = "skin", .roughness = 0.55f};
    material.baseColorTexture = gltf.addTexture(name + "_skin.png");
    const int skinMaterial = gltf.addMaterial(material);
    const MeshData limb = makeLimb(segments, rings);
    const int mesh = gltf.addMesh("limb", {{&limb, skinMaterial}});
    const int columns = std::max(1, int(std::ceil(std::sqrt(double(instances)))));
    std::vector<int> roots;
    std::vector<ChannelSpec> channels;
    for (int i = 0; i < instances; ++i) {
        const int row = i / columns, column = i % columns;
        const glm::vec3 at(0.6f * (float(column) - 0.5f * float(columns - 1)), 0.0f,
                           -0.6f * float(row) + (row % 2 ? 0.3f : 0.0f));
        const float phase = std::fmod(0.137f * float(i), 1.0f);
        Character c = addCharacter(gltf, mesh, name + "_" + std::to_string(i), at, 0.7f * float(i), phase);
        roots.push_back(c.root);
        channels.insert(channels.end(), c.channels.begin(), c.channels.end());
    }
    gltf.addAnimation("sway", channels);
    gltf.setScene(name, roots);
    gltf.write(dir / (name + ".gltf"));
    return {name, gltf.storedTriangles(), gltf.drawnTriangles(), 1};
}

} // namespace

SceneSummary writeCharacterScene(const std::filesystem::path& dir)
{
    return writeCharacters(dir, "character", 1, 48, 96);
}

SceneSummary writeCrowdScene(const std::filesystem::path& dir, int instances)
{
    return writeCharacters(dir, "crowd", instances, 48, 96);
}

} // namespace lfd::samples
