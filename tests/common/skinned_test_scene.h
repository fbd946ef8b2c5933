// A small skinned and morphed scene for the pack, baker and player tests: an "arm" strip
// along +x (2 x `columns` vertices) bound to three chained joints (shoulder, elbow, hand)
// whose weights blend across the elbow and the wrist, one morph target (a bulge in +y of
// the upper arm, normals tilted with it), an animation that bends the elbow and the wrist
// (linear rotation keys) and swells the bulge (weights channel), and a second, static
// node with a rigid mesh, so deformed and static vertices share the streams.
#pragma once

#include "lfd/scene.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

namespace lfd::test {

inline glm::vec4 quatXyzw(float angleRad, const glm::vec3& axis)
{
    const glm::quat q = glm::angleAxis(angleRad, axis);
    return {q.x, q.y, q.z, q.w};
}

// The arm's influences at x (0..2): shoulder (0) to elbow (1) across x = 1 +- 0.2, elbow to
// hand (2) across x = 1.7 +- 0.1.
inline void armInfluences(float x, glm::uvec4& joints, glm::vec4& weights)
{
    auto blend = [](float a, float b, float v) { return std::clamp((v - a) / (b - a), 0.0f, 1.0f); };
    if (x < 1.4f) {
        const float t = blend(0.8f, 1.2f, x);
        joints = {0, 1, 0, 0};
        weights = {1.0f - t, t, 0.0f, 0.0f};
    } else {
        const float t = blend(1.6f, 1.8f, x);
        joints = {1, 2, 0, 0};
        weights = {1.0f - t, t, 0.0f, 0.0f};
    }
}

inline void appendArmMesh(Scene& s, int columns)
{
    VertexStreams& v = s.vertices;
    const uint32_t base = uint32_t(v.positions.size());
    for (int c = 0; c < columns; ++c)
        for (int r = 0; r < 2; ++r) {
            const float x = 2.0f * float(c) / float(columns - 1);
            v.positions.push_back({x, r == 0 ? -0.15f : 0.15f, 0.0f});
            v.normals.push_back({0.0f, 0.0f, 1.0f});
            v.uvs.push_back({x / 2.0f, float(r)});
            armInfluences(x, v.deform.joints.emplace_back(), v.deform.weights.emplace_back());
            const float bulge = std::max(0.0f, 1.0f - std::abs(x - 0.5f) / 0.4f);
            v.deform.positions.push_back({0.0f, (r == 0 ? -0.2f : 0.2f) * bulge, 0.1f * bulge});
            v.deform.normals.push_back({0.0f, r == 0 ? -0.3f * bulge : 0.3f * bulge, 0.0f});
        }
    Primitive prim{uint32_t(s.indices.size()), 0, kNone};
    for (uint32_t c = 0; c + 1 < uint32_t(columns); ++c) {
        const uint32_t a = base + 2 * c, b = a + 1, d = a + 2, e = a + 3;
        s.indices.insert(s.indices.end(), {a, d, b, b, d, e});
    }
    prim.indexCount = uint32_t(s.indices.size()) - prim.firstIndex;
    s.primitives.push_back(prim);
    s.meshes.push_back(Mesh{"arm", uint32_t(s.primitives.size() - 1), 1});
}

inline void appendStaticQuad(Scene& s)
{
    VertexStreams& v = s.vertices;
    const uint32_t base = uint32_t(v.positions.size());
    for (const glm::vec2 p : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
        v.positions.push_back({p.x, p.y, -0.5f});
        v.normals.push_back({0.0f, 0.0f, 1.0f});
        v.uvs.push_back(p * 0.5f + 0.5f);
        v.deform.joints.emplace_back(0u);
        v.deform.weights.emplace_back(0.0f);
        v.deform.positions.emplace_back(0.0f);
        v.deform.normals.emplace_back(0.0f);
    }
    s.primitives.push_back(Primitive{uint32_t(s.indices.size()), 6, kNone});
    s.indices.insert(s.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    s.meshes.push_back(Mesh{"floor", uint32_t(s.primitives.size() - 1), 1});
}

// Nodes: 0 armature, 1 floor (static), 2 shoulder, 3 elbow, 4 hand, 5 arm mesh (skinned).
// Bind pose: the arm as stored (x 0..2), joints at x = 0, 1, 1.7.
inline Scene skinnedArmScene(int columns = 21)
{
    Scene s;
    s.vertices.deform.morphTargets = 1;
    appendStaticQuad(s);
    appendArmMesh(s, columns);
    auto node = [](const char* name, int32_t parent, int32_t mesh, glm::vec3 t) {
        Node n;
        n.name = name;
        n.parent = parent;
        n.mesh = mesh;
        n.translation = t;
        return n;
    };
    s.nodes = {node("armature", kNone, kNone, {0.0f, 0.0f, 0.0f}), node("floor", kNone, 0, {0, 0, 0}),
               node("shoulder", 0, kNone, {0, 0, 0}),            node("elbow", 2, kNone, {1, 0, 0}),
               node("hand", 3, kNone, {0.7f, 0, 0}),              node("arm", 0, 1, {5, 0, 0})}; // 3.7.3: a skinned node's own transform has no effect
    Skin skin;
    skin.name = "arm skin";
    skin.joints = {2, 3, 4};
    for (float x : {0.0f, 1.0f, 1.7f}) // bind pose: joints at x along the arm (armature space)
        skin.inverseBindMatrices.push_back(glm::translate(glm::mat4(1.0f), glm::vec3(-x, 0, 0)));
    s.skins = {skin};
    s.deformers = {Deformer{5, 0, 4, uint32_t(2 * columns), {0.25f}}};
    const glm::vec3 z(0, 0, 1);
    AnimationChannel elbow{3, AnimationPath::Rotation, Interpolation::Linear, {0.0f, 1.0f, 2.0f},
                           {quatXyzw(0.0f, z), quatXyzw(1.2f, z), quatXyzw(0.3f, z)}};
    AnimationChannel hand{4, AnimationPath::Rotation, Interpolation::Linear, {0.0f, 2.0f},
                          {quatXyzw(0.0f, z), quatXyzw(-0.9f, z)}};
    AnimationChannel bulge{5, AnimationPath::Weights, Interpolation::Linear, {0.0f, 1.0f, 2.0f},
                           {{0.25f, 0, 0, 0}, {1.0f, 0, 0, 0}, {0.0f, 0, 0, 0}}};
    s.animations.push_back({"wave", {elbow, hand, bulge}});
    return s;
}

} // namespace lfd::test
