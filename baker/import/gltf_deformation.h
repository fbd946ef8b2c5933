// Import of skins and morph targets (glTF 2.0 sections 3.7.2.2 and 3.7.3): influences
// and deltas per primitive vertex, skins, morph-weight channels. gltf_import.cpp calls
// these; the streams end up in lfd::DeformationStreams.
#pragma once

#include "gltf_load.h"

#include "lfd/scene.h"

#include <functional>
#include <string>
#include <vector>

namespace lfd::bake::gltf {

// Warning sink: key (reported once per key), message.
using WarnOnce = std::function<void(const std::string&, const std::string&)>;

// Where one primitive's attributes come from and the output vertices' sources.
struct DeformationSource {
    const tinygltf::Model& model;
    const tinygltf::Primitive& prim;
    const std::vector<uint32_t>& vertexSource; // output vertex -> glTF vertex
    size_t vertexCount;                       // POSITION's count
    const std::string& label;
    const std::string& file;
};

// JOINTS_n / WEIGHTS_n (3.7.3.1): per output vertex the four largest influences,
// renormalised to sum 1 (more than four non-zero ones: a warning naming the primitive).
// A primitive without them gets zero weights (never posed by a skin).
void readInfluences(const DeformationSource& src, std::vector<glm::uvec4>& joints, std::vector<glm::vec4>& weights,
                    const WarnOnce& warn);

// One morph attribute's deltas (3.7.2.2), vertex-major with `targets` slots per vertex:
// [v * targets + t]; targets the primitive has not (or that lack the attribute) are zero.
std::vector<glm::vec3> readMorphDeltas(const DeformationSource& src, const char* attribute, uint32_t targets);

// Skin k of the document: its joints (as lfd node indices, newIndex) and inverse bind
// matrices (identity when absent, 3.7.3.1). Fails (BakeError) on a joint outside the
// scene or a bad matrix accessor.
Skin convertSkin(const LoadedGltf& loaded, size_t k, const std::vector<int32_t>& newIndex, const std::string& file);

// A glTF "weights" channel's keys as ceil(targets / 4) Weights channels of four weights
// each (cubic spline: the keyframe values, tangents dropped as for T/R/S).
std::vector<AnimationChannel> weightChannels(const tinygltf::Model& model, const tinygltf::AnimationSampler& sampler,
                                             const AnimationChannel& prototype, uint32_t targets, bool cubic,
                                             const std::string& label, const std::string& file);

} // namespace lfd::bake::gltf
