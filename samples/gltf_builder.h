// Assembles a glTF 2.0 document (one external .bin buffer, external PNG images) from
// MeshData parts, and writes it with tinygltf.
#pragma once

#include "mesh_builder.h"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <tiny_gltf.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lfd::samples {

struct MaterialSpec {
    std::string name;
    glm::vec4 baseColorFactor{1.0f};
    float metallic = 0.0f;
    float roughness = 1.0f;
    glm::vec3 emissive{0.0f};
    int baseColorTexture = -1;         // texture indices from GltfBuilder::addTexture
    int metallicRoughnessTexture = -1;
    int normalTexture = -1;
};

struct PrimitiveSpec {
    const MeshData* mesh = nullptr;
    int material = -1;
};

struct NodeSpec {
    std::string name;
    int mesh = -1;
    glm::vec3 translation{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
    std::vector<int> children;
    int skin = -1; // GltfBuilder::addSkin
};

// One animation channel: node, path ("rotation", "weights", ...), LINEAR keys; values
// hold `components` floats per key (4 for rotations as x, y, z, w; the target count for
// weights).
struct ChannelSpec {
    int node = -1;
    std::string path;
    std::vector<float> times;
    std::vector<float> values;
    int components = 4;
};

class GltfBuilder {
public:
    // `binName` is the file name of the single buffer (written next to the .gltf).
    explicit GltfBuilder(std::string binName);

    int addMaterial(const MaterialSpec& material);
    // An external image `uri` (relative to the .gltf); one shared sampler with
    // trilinear filtering and clamp-to-edge wrapping (sample uvs stay in [0, 1]).
    int addTexture(const std::string& uri);
    int addMesh(const std::string& name, const std::vector<PrimitiveSpec>& primitives);
    int addNode(const NodeSpec& node);
    // LINEAR rotation keys shared by all `nodes` (one sampler per channel, accessors
    // shared), as one animation.
    void addRotationAnimation(const std::string& name, const std::vector<int>& nodes,
                              const std::vector<float>& times,
                              const std::vector<glm::quat>& rotations);
    // A skin: joint nodes and their inverse bind matrices (column-major, glTF's layout).
    int addSkin(const std::vector<int>& joints, const std::vector<glm::mat4>& inverseBindMatrices);
    // One animation of several channels, each with its own sampler and accessors.
    void addAnimation(const std::string& name, const std::vector<ChannelSpec>& channels);
    // The default scene; `roots` are its root nodes.
    void setScene(const std::string& name, const std::vector<int>& roots);

    // Triangles drawn by the scene: each mesh's triangles times the nodes using it.
    size_t drawnTriangles() const;
    // Triangles stored in the buffer (each mesh once).
    size_t storedTriangles() const;

    // Writes `gltfPath` and the .bin beside it. Throws std::runtime_error on failure.
    void write(const std::filesystem::path& gltfPath);

private:
    int addAccessor(const void* data, size_t count, int componentType, int type,
                    size_t elementBytes, int target, const float* minValues = nullptr,
                    const float* maxValues = nullptr);

    // JOINTS_0 / WEIGHTS_0 and the morph targets of `data`, when it has them.
    void addDeformation(const MeshData& data, tinygltf::Primitive& primitive);

    tinygltf::Model model_;
    std::vector<size_t> meshTriangles_;
    int sampler_ = -1;
};

} // namespace lfd::samples
