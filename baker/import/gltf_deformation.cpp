// Skins and morph targets from glTF 2.0 (sections 3.7.2.2 and 3.7.3).
#include "gltf_deformation.h"

#include "gltf_accessors.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace lfd::bake::gltf {
namespace {

int attributeAccessor(const tinygltf::Primitive& prim, const std::string& name)
{
    const auto it = prim.attributes.find(name);
    return it == prim.attributes.end() ? -1 : it->second;
}

// The four largest (joint, weight) pairs, weights renormalised to sum 1 (3.7.3.1: "the
// sum of all vertex weights MUST be 1"; dropping small ones keeps the sum only this way).
void keepFourLargest(std::vector<std::pair<float, uint32_t>>& influences, glm::uvec4& joints, glm::vec4& weights)
{
    std::stable_sort(influences.begin(), influences.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    float sum = 0.0f;
    for (size_t k = 0; k < 4 && k < influences.size(); ++k)
        sum += influences[k].first;
    joints = glm::uvec4(0u);
    weights = glm::vec4(0.0f);
    for (size_t k = 0; k < 4 && k < influences.size() && sum > 0.0f; ++k) {
        joints[glm::length_t(k)] = influences[k].second;
        weights[glm::length_t(k)] = influences[k].first / sum;
    }
}

} // namespace

void readInfluences(const DeformationSource& src, std::vector<glm::uvec4>& joints, std::vector<glm::vec4>& weights,
                    const WarnOnce& warn)
{
    std::vector<FloatArray> jointSets, weightSets;
    for (int set = 0;; ++set) {
        const int j = attributeAccessor(src.prim, "JOINTS_" + std::to_string(set));
        const int w = attributeAccessor(src.prim, "WEIGHTS_" + std::to_string(set));
        if (j < 0 || w < 0)
            break;
        const std::string at = src.label + ".attributes.";
        jointSets.push_back(readFloatAccessor(src.model, j, {TINYGLTF_TYPE_VEC4}, src.file, at + "JOINTS_" + std::to_string(set)));
        weightSets.push_back(readFloatAccessor(src.model, w, {TINYGLTF_TYPE_VEC4}, src.file, at + "WEIGHTS_" + std::to_string(set)));
        if (jointSets.back().count != src.vertexCount || weightSets.back().count != src.vertexCount)
            fail(src.file, at + "JOINTS_" + std::to_string(set) + " / WEIGHTS_" + std::to_string(set) +
                               " do not have one element per vertex");
    }
    bool dropped = false;
    std::vector<std::pair<float, uint32_t>> influences;
    for (uint32_t source : src.vertexSource) {
        influences.clear();
        for (size_t s = 0; s < jointSets.size(); ++s)
            for (size_t k = 0; k < 4; ++k) {
                const float w = weightSets[s].values[source * 4 + k];
                const float j = jointSets[s].values[source * 4 + k];
                if (!std::isfinite(w) || !std::isfinite(j) || j < 0.0f)
                    fail(src.file, src.label + " has an invalid joint or weight at vertex " + std::to_string(source));
                if (w > 0.0f)
                    influences.emplace_back(w, uint32_t(j));
            }
        dropped = dropped || influences.size() > 4;
        keepFourLargest(influences, joints.emplace_back(), weights.emplace_back());
    }
    if (dropped)
        warn("influences " + src.label, src.label + " has vertices with more than four joint influences: the four "
                                                    "largest kept, renormalised");
}

std::vector<glm::vec3> readMorphDeltas(const DeformationSource& src, const char* attribute, uint32_t targets)
{
    std::vector<glm::vec3> deltas(src.vertexSource.size() * targets, glm::vec3(0.0f));
    for (size_t t = 0; t < src.prim.targets.size() && t < targets; ++t) {
        const auto it = src.prim.targets[t].find(attribute);
        if (it == src.prim.targets[t].end())
            continue;
        const std::string what = src.label + ".targets[" + std::to_string(t) + "]." + attribute;
        const FloatArray a = readFloatAccessor(src.model, it->second, {TINYGLTF_TYPE_VEC3}, src.file, what);
        if (a.count != src.vertexCount)
            fail(src.file, what + " has " + std::to_string(a.count) + " elements, POSITION " +
                               std::to_string(src.vertexCount));
        for (size_t v = 0; v < src.vertexSource.size(); ++v) {
            const float* d = &a.values[size_t(src.vertexSource[v]) * 3];
            const glm::vec3 delta(d[0], d[1], d[2]);
            if (!std::isfinite(delta.x) || !std::isfinite(delta.y) || !std::isfinite(delta.z))
                fail(src.file, what + " has a non-finite delta");
            deltas[v * targets + t] = delta;
        }
    }
    return deltas;
}

Skin convertSkin(const LoadedGltf& loaded, size_t k, const std::vector<int32_t>& newIndex, const std::string& file)
{
    const SkinJson& in = loaded.skins[k];
    const std::string label = "skins[" + std::to_string(k) + "]" + (in.name.empty() ? "" : " '" + in.name + "'");
    Skin skin;
    skin.name = in.name.empty() ? "skin " + std::to_string(k) : in.name;
    for (int j : in.joints) {
        if (newIndex[size_t(j)] == kNone)
            fail(file, label + " joint nodes[" + std::to_string(j) + "] is not in the scene");
        skin.joints.push_back(uint32_t(newIndex[size_t(j)]));
    }
    if (skin.joints.empty())
        fail(file, label + " has no joints");
    skin.inverseBindMatrices.assign(skin.joints.size(), glm::mat4(1.0f));
    if (in.inverseBindMatrices < 0)
        return skin;
    const FloatArray m = readFloatAccessor(loaded.model, in.inverseBindMatrices, {TINYGLTF_TYPE_MAT4}, file,
                                           label + ".inverseBindMatrices");
    if (m.count < skin.joints.size())
        fail(file, label + ".inverseBindMatrices has " + std::to_string(m.count) + " matrices for " +
                       std::to_string(skin.joints.size()) + " joints");
    for (size_t j = 0; j < skin.joints.size(); ++j)
        for (int e = 0; e < 16; ++e) {
            const float v = m.values[j * 16 + size_t(e)];
            if (!std::isfinite(v))
                fail(file, label + ".inverseBindMatrices[" + std::to_string(j) + "] is not finite");
            skin.inverseBindMatrices[j][e / 4][e % 4] = v; // column-major, as glTF stores it
        }
    return skin;
}

std::vector<AnimationChannel> weightChannels(const tinygltf::Model& model, const tinygltf::AnimationSampler& sampler,
                                             const AnimationChannel& prototype, uint32_t targets, bool cubic,
                                             const std::string& label, const std::string& file)
{
    const FloatArray out = readFloatAccessor(model, sampler.output, {TINYGLTF_TYPE_SCALAR}, file, label + " output");
    const size_t keys = prototype.times.size();
    const size_t perKey = (cubic ? 3 : 1) * targets; // cubic: in-tangents, values, out-tangents
    if (targets == 0 || out.count != keys * perKey)
        fail(file, label + " has " + std::to_string(out.count) + " output values for " + std::to_string(keys) +
                       " keys of " + std::to_string(targets) + " morph weights");
    std::vector<AnimationChannel> channels;
    for (uint32_t first = 0; first < targets; first += 4) {
        AnimationChannel c = prototype;
        c.path = AnimationPath::Weights;
        c.weightOffset = first;
        c.values.assign(keys, glm::vec4(0.0f));
        for (size_t k = 0; k < keys; ++k)
            for (uint32_t i = 0; i < 4 && first + i < targets; ++i) {
                const float v = out.values[k * perKey + (cubic ? targets : 0) + first + i];
                if (!std::isfinite(v))
                    fail(file, label + " output value " + std::to_string(k) + " is not finite");
                c.values[k][glm::length_t(i)] = v;
            }
        channels.push_back(std::move(c));
    }
    return channels;
}

} // namespace lfd::bake::gltf
