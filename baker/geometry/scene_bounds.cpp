// Scene-bounds stage: where the geometry can be, in scene space, over the rest pose and
// the node animation. The player frames the scene (and the baker's tessellation bound
// assumes that framing) from these bounds, so they must contain every animated pose.
#include "scene_bounds.h"

#include "bake_log.h"

#include "lfd/scene_animation.h"
#include "lfd/scene_pose.h"

#include <algorithm>
#include <cmath>

namespace lfd::bake {
namespace {

// Times at which the scene is evaluated: every distinct key time plus the midpoint of
// each key interval (a rotating part sweeps outside the chord of its keys; the midpoint
// sample shrinks that gap fourfold). The rest pose is evaluated separately.
std::vector<float> sampleTimes(const Scene& scene)
{
    std::vector<float> times;
    for (const Animation& animation : scene.animations)
        for (const AnimationChannel& channel : animation.channels)
            for (size_t k = 0; k < channel.times.size(); ++k) {
                times.push_back(channel.times[k]);
                if (k > 0)
                    times.push_back(0.5f * (channel.times[k - 1] + channel.times[k]));
            }
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end()), times.end());
    return times;
}

// sceneFromNode for the rest pose (node TRS, animations not applied) and at every sample
// time, rest pose first.
std::vector<std::vector<glm::mat4>> sampledWorldMatrices(const Scene& scene)
{
    Scene rest; // nodes only: cheap to copy, no animations
    rest.nodes = scene.nodes;
    std::vector<std::vector<glm::mat4>> poses{lfd::nodeWorldMatrices(rest, 0.0f)};
    for (float t : sampleTimes(scene))
        poses.push_back(lfd::nodeWorldMatrices(scene, t));
    return poses;
}

// Whether each mesh is posed by a deformer (its vertices move on their own).
std::vector<bool> deformedMeshes(const Scene& scene)
{
    std::vector<bool> deformed(scene.meshes.size(), false);
    for (const Deformer& d : scene.deformers)
        deformed[size_t(scene.nodes[d.node].mesh)] = true;
    return deformed;
}

// One sampled pose of the deformers: node matrices and posing inputs at a sample time.
struct DeformerPose {
    std::vector<glm::mat4> sceneFromNode;
    PoseInputs inputs;
};

// The deformers' poses at time 0 and every sample time (what the player can show: unlike
// rigid meshes, a deformer's bind pose need not be reachable, so it is not sampled).
std::vector<DeformerPose> deformerPoses(const Scene& scene)
{
    std::vector<DeformerPose> poses;
    if (scene.deformers.empty())
        return poses;
    std::vector<float> times = sampleTimes(scene);
    if (times.empty() || times.front() > 0.0f)
        times.insert(times.begin(), 0.0f);
    for (float t : times) {
        DeformerPose pose{lfd::nodeWorldMatrices(scene, t), {}};
        pose.inputs = poseInputs(scene, t, pose.sceneFromNode);
        poses.push_back(std::move(pose));
    }
    return poses;
}

// Calls fn(scenePoint) for every vertex of every deformer in every sampled pose.
template <class Fn>
void forEachPosedPoint(const Scene& scene, const std::vector<DeformerPose>& poses, Fn&& fn)
{
    for (const DeformerPose& pose : poses)
        for (size_t d = 0; d < scene.deformers.size(); ++d) {
            const glm::mat4& sceneFromNode = pose.sceneFromNode[scene.deformers[d].node];
            for (const glm::vec3& p : posedPositions(scene, pose.inputs, d))
                fn(glm::vec3(sceneFromNode * glm::vec4(p, 1.0f)));
        }
}

// Distinct sceneFromObject matrices under which each mesh appears (a static node gives
// the same matrix at every time; evaluating it once keeps large static scenes cheap).
std::vector<std::vector<glm::mat4>> meshInstances(const Scene& scene)
{
    std::vector<std::vector<glm::mat4>> instances(scene.meshes.size());
    const std::vector<bool> deformed = deformedMeshes(scene);
    for (const std::vector<glm::mat4>& pose : sampledWorldMatrices(scene))
        for (size_t n = 0; n < scene.nodes.size(); ++n) {
            const int32_t mesh = scene.nodes[n].mesh;
            if (mesh < 0 || size_t(mesh) >= scene.meshes.size() || deformed[size_t(mesh)])
                continue;
            instances[size_t(mesh)].push_back(pose[n]);
        }
    auto less = [](const glm::mat4& a, const glm::mat4& b) {
        const float* x = &a[0][0];
        const float* y = &b[0][0];
        return std::lexicographical_compare(x, x + 16, y, y + 16);
    };
    for (std::vector<glm::mat4>& list : instances) {
        std::sort(list.begin(), list.end(), less);
        list.erase(std::unique(list.begin(), list.end()), list.end());
    }
    return instances;
}

// Vertices referenced by each mesh's primitives, each once.
std::vector<std::vector<uint32_t>> meshVertices(const Scene& scene)
{
    std::vector<std::vector<uint32_t>> result(scene.meshes.size());
    std::vector<uint32_t> seenBy(scene.vertices.size(), UINT32_MAX);
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
        const Mesh& mesh = scene.meshes[m];
        for (uint32_t p = mesh.firstPrimitive; p < mesh.firstPrimitive + mesh.primitiveCount; ++p) {
            if (p >= scene.primitives.size())
                break;
            const Primitive& prim = scene.primitives[p];
            const size_t end = std::min<size_t>(size_t(prim.firstIndex) + prim.indexCount, scene.indices.size());
            for (size_t i = prim.firstIndex; i < end; ++i) {
                const uint32_t v = scene.indices[i];
                if (v < seenBy.size() && seenBy[v] != uint32_t(m)) {
                    seenBy[v] = uint32_t(m);
                    result[m].push_back(v);
                }
            }
        }
    }
    return result;
}

// A deformed mesh's largest scene-space stretch in one pose: the largest joint scale
// times the node's (a piece of a split edge inside one joint's region stretches by
// that), and the largest ratio of an edge's posed to its rest length (morph deltas and
// blending between joints stretch whole edges beyond any one joint's scale).
float deformedScale(const Scene& scene, const std::vector<glm::mat4>& sceneFromNode, const PoseInputs& inputs, size_t d)
{
    const Deformer& deformer = scene.deformers[d];
    const glm::mat3 linear(sceneFromNode[deformer.node]);
    float nodeScale = 0.0f;
    for (int c = 0; c < 3; ++c)
        nodeScale = std::max(nodeScale, glm::length(linear[c]));
    float scale = nodeScale * maxJointScale(scene, inputs, d);
    const std::vector<glm::vec3> posed = posedPositions(scene, inputs, d);
    const Mesh& mesh = scene.meshes[size_t(scene.nodes[deformer.node].mesh)];
    const std::vector<glm::vec3>& rest = scene.vertices.positions;
    auto forEachEdge = [&](auto&& fn) {
        for (uint32_t p = mesh.firstPrimitive; p < mesh.firstPrimitive + mesh.primitiveCount; ++p) {
            const Primitive& prim = scene.primitives[p];
            for (uint32_t i = prim.firstIndex; i < prim.firstIndex + prim.indexCount; ++i)
                fn(scene.indices[i], scene.indices[i % 3 == 2 ? i - 2 : i + 1]);
        }
    };
    float longest = 0.0f;
    forEachEdge([&](uint32_t a, uint32_t b) { longest = std::max(longest, glm::length(rest[a] - rest[b])); });
    // Edges a thousand times shorter than the mesh's longest are left out: their posed
    // length is rounding noise (the coinciding vertices of a sphere's pole differ by
    // 1e-8), and no stretch the ratio could show would take them past the bound.
    forEachEdge([&](uint32_t a, uint32_t b) {
        const float restLength = glm::length(rest[a] - rest[b]);
        if (restLength > 1e-3f * longest)
            scale = std::max(scale, glm::length(linear * (posed[a - deformer.firstVertex] -
                                                          posed[b - deformer.firstVertex])) / restLength);
    });
    return scale;
}

} // namespace

SceneBounds computeBounds(const Scene& scene)
{
    const std::vector<std::vector<glm::mat4>> instances = meshInstances(scene);
    const std::vector<std::vector<uint32_t>> vertices = meshVertices(scene);
    const std::vector<glm::vec3>& p = scene.vertices.positions;

    const std::vector<DeformerPose> poses = deformerPoses(scene);
    auto forEachPoint = [&](auto&& fn) {
        for (size_t m = 0; m < instances.size(); ++m)
            for (const glm::mat4& sceneFromObject : instances[m])
                for (uint32_t v : vertices[m])
                    fn(glm::vec3(sceneFromObject * glm::vec4(p[v], 1.0f)));
        forEachPosedPoint(scene, poses, fn);
    };

    // Pass 1: AABB of every vertex under every instance matrix and every sampled pose.
    glm::vec3 lo(INFINITY);
    glm::vec3 hi(-INFINITY);
    bool any = false;
    forEachPoint([&](const glm::vec3& q) {
        lo = glm::min(lo, q);
        hi = glm::max(hi, q);
        any = true;
    });
    if (!any)
        return SceneBounds{};

    // Pass 2: sphere about the AABB centre through the farthest vertex, so it contains all
    // geometry at all sampled times (not merely the AABB's corners).
    SceneBounds bounds;
    bounds.min = lo;
    bounds.max = hi;
    bounds.center = 0.5f * (lo + hi);
    // Squared distances in double: a float overflows from about 1.8e19 on, which would
    // turn a large but finite scene into an infinite radius.
    double radius2 = 0.0;
    forEachPoint([&](const glm::vec3& q) {
        const glm::dvec3 d = glm::dvec3(q) - glm::dvec3(bounds.center);
        radius2 = std::max(radius2, glm::dot(d, d));
    });
    bounds.radius = float(std::sqrt(radius2));
    // Positions are finite (import checks them), but node transforms can carry them past
    // the float range; such a scene cannot be framed.
    if (!std::isfinite(bounds.radius) || !std::isfinite(bounds.center.x) || !std::isfinite(bounds.center.y) ||
        !std::isfinite(bounds.center.z))
        throw BakeError("bounds: the scene extends beyond the single-precision range (positions times node "
                        "transforms overflow)");
    // The later stages square scene-space lengths in float (edge lengths, triangle areas):
    // past about 1.8e19 those overflow to infinity and, for example, every edge looks
    // oversized forever (a glTF fuzzer out-of-memory). Such scenes are refused.
    constexpr float kMaxSceneRadius = 1e18f;
    if (bounds.radius > kMaxSceneRadius)
        throw BakeError("bounds: the scene's bounding radius " + std::to_string(bounds.radius) +
                        " exceeds 1e18 units, where squared lengths overflow single precision; rescale the scene");
    return bounds;
}

std::vector<float> meshMaxWorldScale(const Scene& scene)
{
    std::vector<float> scale(scene.meshes.size(), 0.0f);
    const std::vector<std::vector<glm::mat4>> instances = meshInstances(scene);
    for (size_t m = 0; m < instances.size(); ++m)
        for (const glm::mat4& sceneFromObject : instances[m])
            for (int c = 0; c < 3; ++c)
                scale[m] = std::max(scale[m], glm::length(glm::vec3(sceneFromObject[c])));
    for (const DeformerPose& pose : deformerPoses(scene))
        for (size_t d = 0; d < scene.deformers.size(); ++d) {
            const size_t m = size_t(scene.nodes[scene.deformers[d].node].mesh);
            scale[m] = std::max(scale[m], deformedScale(scene, pose.sceneFromNode, pose.inputs, d));
        }
    return scale;
}

} // namespace lfd::bake
