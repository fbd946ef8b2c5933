#include "gltf_builder.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <map>
#include <stdexcept>

namespace lfd::samples {

namespace {

std::vector<double> toDoubles(const float* values, int count)
{
    return std::vector<double>(values, values + count);
}

} // namespace

GltfBuilder::GltfBuilder(std::string binName)
{
    model_.asset.version = "2.0";
    model_.asset.generator = "lfd-make-samples";
    model_.buffers.emplace_back();
    model_.buffers[0].uri = std::move(binName);
}

int GltfBuilder::addAccessor(const void* data, size_t count, int componentType, int type,
                             size_t elementBytes, int target, const float* minValues,
                             const float* maxValues)
{
    // Each accessor gets its own tightly packed view, 4-byte aligned as glTF requires.
    std::vector<unsigned char>& bytes = model_.buffers[0].data;
    bytes.resize((bytes.size() + 3) & ~size_t(3), 0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = bytes.size();
    view.byteLength = count * elementBytes;
    view.target = target;
    const auto* begin = static_cast<const unsigned char*>(data);
    bytes.insert(bytes.end(), begin, begin + view.byteLength);
    model_.bufferViews.push_back(view);

    tinygltf::Accessor accessor;
    accessor.bufferView = static_cast<int>(model_.bufferViews.size() - 1);
    accessor.componentType = componentType;
    accessor.type = type;
    accessor.count = count;
    const int components = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(type));
    if (minValues && maxValues) {
        accessor.minValues = toDoubles(minValues, components);
        accessor.maxValues = toDoubles(maxValues, components);
    }
    model_.accessors.push_back(accessor);
    return static_cast<int>(model_.accessors.size() - 1);
}

int GltfBuilder::addMaterial(const MaterialSpec& spec)
{
    tinygltf::Material material;
    material.name = spec.name;
    auto& pbr = material.pbrMetallicRoughness;
    pbr.baseColorFactor = {spec.baseColorFactor.r, spec.baseColorFactor.g,
                           spec.baseColorFactor.b, spec.baseColorFactor.a};
    pbr.metallicFactor = spec.metallic;
    pbr.roughnessFactor = spec.roughness;
    pbr.baseColorTexture.index = spec.baseColorTexture;
    pbr.metallicRoughnessTexture.index = spec.metallicRoughnessTexture;
    material.normalTexture.index = spec.normalTexture;
    material.emissiveFactor = {spec.emissive.r, spec.emissive.g, spec.emissive.b};
    model_.materials.push_back(material);
    return static_cast<int>(model_.materials.size() - 1);
}

int GltfBuilder::addTexture(const std::string& uri)
{
    if (sampler_ < 0) {
        tinygltf::Sampler sampler;
        sampler.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR;
        sampler.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
        sampler.wrapS = TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
        sampler.wrapT = TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
        model_.samplers.push_back(sampler);
        sampler_ = static_cast<int>(model_.samplers.size() - 1);
    }
    tinygltf::Image image;
    image.uri = uri;
    image.name = std::filesystem::path(uri).stem().string();
    model_.images.push_back(image);
    tinygltf::Texture texture;
    texture.name = image.name;
    texture.source = static_cast<int>(model_.images.size() - 1);
    texture.sampler = sampler_;
    model_.textures.push_back(texture);
    return static_cast<int>(model_.textures.size() - 1);
}

int GltfBuilder::addMesh(const std::string& name, const std::vector<PrimitiveSpec>& primitives)
{
    tinygltf::Mesh mesh;
    mesh.name = name;
    size_t triangles = 0;
    for (const PrimitiveSpec& spec : primitives) {
        const MeshData& data = *spec.mesh;
        const size_t n = data.positions.size();
        if (n == 0 || data.normals.size() != n || (!data.uvs.empty() && data.uvs.size() != n) ||
            (!data.tangents.empty() && data.tangents.size() != n))
            throw std::logic_error("addMesh: inconsistent vertex attributes in " + name);

        tinygltf::Primitive primitive;
        primitive.mode = TINYGLTF_MODE_TRIANGLES;
        primitive.material = spec.material;

        // POSITION needs min/max (glTF requirement).
        glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
        for (const glm::vec3& p : data.positions) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        primitive.attributes["POSITION"] =
            addAccessor(data.positions.data(), n, TINYGLTF_COMPONENT_TYPE_FLOAT,
                        TINYGLTF_TYPE_VEC3, sizeof(glm::vec3), TINYGLTF_TARGET_ARRAY_BUFFER,
                        &lo.x, &hi.x);
        primitive.attributes["NORMAL"] =
            addAccessor(data.normals.data(), n, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3,
                        sizeof(glm::vec3), TINYGLTF_TARGET_ARRAY_BUFFER);
        if (!data.tangents.empty())
            primitive.attributes["TANGENT"] = addAccessor(
                data.tangents.data(), n, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC4,
                sizeof(glm::vec4), TINYGLTF_TARGET_ARRAY_BUFFER);
        if (!data.uvs.empty())
            primitive.attributes["TEXCOORD_0"] =
                addAccessor(data.uvs.data(), n, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2,
                            sizeof(glm::vec2), TINYGLTF_TARGET_ARRAY_BUFFER);

        // 16-bit indices where they fit, as exporters do.
        if (n <= 65535) {
            std::vector<uint16_t> shortIndices(data.indices.begin(), data.indices.end());
            primitive.indices = addAccessor(shortIndices.data(), shortIndices.size(),
                                            TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                            TINYGLTF_TYPE_SCALAR, sizeof(uint16_t),
                                            TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
        } else {
            primitive.indices = addAccessor(data.indices.data(), data.indices.size(),
                                            TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                                            TINYGLTF_TYPE_SCALAR, sizeof(uint32_t),
                                            TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
        }
        addDeformation(data, primitive);
        mesh.primitives.push_back(primitive);
        triangles += data.triangleCount();
        mesh.weights.assign(data.morphPositions.size(), 0.0);
    }
    model_.meshes.push_back(mesh);
    meshTriangles_.push_back(triangles);
    return static_cast<int>(model_.meshes.size() - 1);
}

int GltfBuilder::addNode(const NodeSpec& spec)
{
    tinygltf::Node node;
    node.name = spec.name;
    node.mesh = spec.mesh;
    node.children = spec.children;
    node.skin = spec.skin;
    if (spec.translation != glm::vec3(0.0f))
        node.translation = {spec.translation.x, spec.translation.y, spec.translation.z};
    if (spec.rotation != glm::quat(1.0f, 0.0f, 0.0f, 0.0f)) {
        const glm::quat q = glm::normalize(spec.rotation);
        node.rotation = {q.x, q.y, q.z, q.w}; // glTF order: x, y, z, w
    }
    model_.nodes.push_back(node);
    return static_cast<int>(model_.nodes.size() - 1);
}

void GltfBuilder::addRotationAnimation(const std::string& name, const std::vector<int>& nodes,
                                       const std::vector<float>& times,
                                       const std::vector<glm::quat>& rotations)
{
    if (times.empty() || times.size() != rotations.size())
        throw std::logic_error("addRotationAnimation: times and rotations differ in length");
    // Sampler input needs min/max (glTF requirement).
    const float tMin = times.front(), tMax = times.back();
    const int input = addAccessor(times.data(), times.size(), TINYGLTF_COMPONENT_TYPE_FLOAT,
                                  TINYGLTF_TYPE_SCALAR, sizeof(float), 0, &tMin, &tMax);
    std::vector<float> xyzw;
    for (const glm::quat& q : rotations)
        xyzw.insert(xyzw.end(), {q.x, q.y, q.z, q.w});
    const int output = addAccessor(xyzw.data(), rotations.size(), TINYGLTF_COMPONENT_TYPE_FLOAT,
                                   TINYGLTF_TYPE_VEC4, 4 * sizeof(float), 0);

    tinygltf::Animation animation;
    animation.name = name;
    for (int node : nodes) {
        tinygltf::AnimationSampler sampler;
        sampler.input = input;
        sampler.output = output;
        sampler.interpolation = "LINEAR";
        animation.samplers.push_back(sampler);
        tinygltf::AnimationChannel channel;
        channel.sampler = static_cast<int>(animation.samplers.size() - 1);
        channel.target_node = node;
        channel.target_path = "rotation";
        animation.channels.push_back(channel);
    }
    model_.animations.push_back(animation);
}

void GltfBuilder::addDeformation(const MeshData& data, tinygltf::Primitive& primitive)
{
    const size_t n = data.positions.size();
    if (!data.joints.empty()) {
        if (data.joints.size() != n || data.weights.size() != n)
            throw std::logic_error("addMesh: joints and weights must have one entry per vertex");
        primitive.attributes["JOINTS_0"] = addAccessor(data.joints.data(), n, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                                       TINYGLTF_TYPE_VEC4, sizeof(glm::u16vec4),
                                                       TINYGLTF_TARGET_ARRAY_BUFFER);
        primitive.attributes["WEIGHTS_0"] = addAccessor(data.weights.data(), n, TINYGLTF_COMPONENT_TYPE_FLOAT,
                                                        TINYGLTF_TYPE_VEC4, sizeof(glm::vec4),
                                                        TINYGLTF_TARGET_ARRAY_BUFFER);
    }
    for (size_t t = 0; t < data.morphPositions.size(); ++t) {
        const std::vector<glm::vec3>& d = data.morphPositions[t];
        // A morph target's POSITION accessor needs min/max too (glTF 3.7.2.2).
        glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
        for (const glm::vec3& p : d) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        std::map<std::string, int> target;
        target["POSITION"] = addAccessor(d.data(), n, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3,
                                         sizeof(glm::vec3), TINYGLTF_TARGET_ARRAY_BUFFER, &lo.x, &hi.x);
        if (t < data.morphNormals.size())
            target["NORMAL"] = addAccessor(data.morphNormals[t].data(), n, TINYGLTF_COMPONENT_TYPE_FLOAT,
                                           TINYGLTF_TYPE_VEC3, sizeof(glm::vec3), TINYGLTF_TARGET_ARRAY_BUFFER);
        primitive.targets.push_back(target);
    }
}

int GltfBuilder::addSkin(const std::vector<int>& joints, const std::vector<glm::mat4>& inverseBindMatrices)
{
    tinygltf::Skin skin;
    skin.joints = joints;
    skin.inverseBindMatrices = addAccessor(inverseBindMatrices.data(), inverseBindMatrices.size(),
                                           TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_MAT4, sizeof(glm::mat4), 0);
    model_.skins.push_back(skin);
    return static_cast<int>(model_.skins.size() - 1);
}

void GltfBuilder::addAnimation(const std::string& name, const std::vector<ChannelSpec>& channels)
{
    tinygltf::Animation animation;
    animation.name = name;
    for (const ChannelSpec& c : channels) {
        const float tMin = c.times.front(), tMax = c.times.back();
        tinygltf::AnimationSampler sampler;
        sampler.input = addAccessor(c.times.data(), c.times.size(), TINYGLTF_COMPONENT_TYPE_FLOAT,
                                    TINYGLTF_TYPE_SCALAR, sizeof(float), 0, &tMin, &tMax);
        const bool rotation = c.path == "rotation";
        sampler.output = addAccessor(c.values.data(), rotation ? c.values.size() / 4 : c.values.size(),
                                     TINYGLTF_COMPONENT_TYPE_FLOAT, rotation ? TINYGLTF_TYPE_VEC4 : TINYGLTF_TYPE_SCALAR,
                                     rotation ? 4 * sizeof(float) : sizeof(float), 0);
        sampler.interpolation = "LINEAR";
        animation.samplers.push_back(sampler);
        tinygltf::AnimationChannel channel;
        channel.sampler = static_cast<int>(animation.samplers.size() - 1);
        channel.target_node = c.node;
        channel.target_path = c.path;
        animation.channels.push_back(channel);
    }
    model_.animations.push_back(animation);
}

void GltfBuilder::setScene(const std::string& name, const std::vector<int>& roots)
{
    tinygltf::Scene scene;
    scene.name = name;
    scene.nodes = roots;
    model_.scenes = {scene};
    model_.defaultScene = 0;
}

size_t GltfBuilder::drawnTriangles() const
{
    size_t total = 0;
    for (const tinygltf::Node& node : model_.nodes)
        if (node.mesh >= 0)
            total += meshTriangles_[static_cast<size_t>(node.mesh)];
    return total;
}

size_t GltfBuilder::storedTriangles() const
{
    size_t total = 0;
    for (size_t triangles : meshTriangles_)
        total += triangles;
    return total;
}

void GltfBuilder::write(const std::filesystem::path& gltfPath)
{
    tinygltf::TinyGLTF writer;
    // The images are already on disk beside the .gltf: keep their uris and write no
    // pixels (returning false makes tinygltf keep Image::uri).
    writer.SetImageWriter([](const std::string*, const std::string*, const tinygltf::Image*, bool,
                             std::string*, void*) { return false; },
                          nullptr);
    const bool ok = writer.WriteGltfSceneToFile(&model_, gltfPath.string(), /*embedImages=*/false,
                                                /*embedBuffers=*/false, /*prettyPrint=*/true,
                                                /*writeBinary=*/false);
    if (!ok)
        throw std::runtime_error(gltfPath.string() + ": cannot write glTF or its buffer");
}

} // namespace lfd::samples
