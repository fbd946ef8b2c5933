// glTF 2.0 import stage: the file is loaded and checked by gltf_load (container, schema,
// resources, semantics and data, each finding with its JSON path), then this file turns
// the model into an lfd::Scene - object-space triangle lists, the node hierarchy (parents
// first), rigid node animation, metallic-roughness materials and the sources of the
// textures they use.
//
// Memory: no image is decoded here. External image files are not even read past their
// signature; bakeTexture decodes one texture at a time later.
#include "gltf_import.h"

#include "bake_log.h"
#include "deformers.h"
#include "gltf_accessors.h"
#include "gltf_deformation.h"
#include "gltf_lights.h"
#include "gltf_load.h"
#include "gltf_material_extensions.h"
#include "gltf_resources.h"
#include "gltf_texture_source.h"
#include "gltf_validation.h"
#include "texture_webp.h"

#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <span>

namespace lfd::bake {
namespace {

namespace fs = std::filesystem;
using gltf::fail;

// ---- Warnings ----------------------------------------------------------------------

// Warnings are held until the import has finished, then reported (flush): every error
// the import finds is reported first, so under --strict (where a reported warning refuses
// the input) the first line is the file's real defect, not an earlier warning.
class Warnings {
public:
    Warnings(const Log& log, std::vector<std::string>& out) : log_(log), out_(out) {}
    void add(const std::string& message) { out_.push_back(message); }
    void flush() const
    {
        for (const std::string& message : out_)
            log_.warn(message);
    }
    // One warning per `key`, however often the situation occurs.
    void once(const std::string& key, const std::string& message)
    {
        if (seen_.insert(key).second)
            add(message);
    }

private:
    const Log& log_;
    std::vector<std::string>& out_;
    std::set<std::string> seen_;
};

std::string quoted(const std::string& name) { return "'" + name + "'"; }

unsigned char uchar(char c) { return static_cast<unsigned char>(c); }

// Objects are named by their JSON path (as the validation names them) and their name.
std::string named(const std::string& path, const std::string& name)
{
    return name.empty() ? path : path + " " + quoted(name);
}

std::string meshLabel(const tinygltf::Model& model, size_t mesh)
{
    return named("meshes[" + std::to_string(mesh) + "]", model.meshes[mesh].name);
}

std::string primitiveLabel(const tinygltf::Model& model, size_t mesh, size_t primitive)
{
    return "meshes[" + std::to_string(mesh) + "].primitives[" + std::to_string(primitive) + "]" +
           (model.meshes[mesh].name.empty() ? "" : " (" + quoted(model.meshes[mesh].name) + ")");
}

std::string nodeLabel(const tinygltf::Model& model, size_t node)
{
    return named("nodes[" + std::to_string(node) + "]", model.nodes[node].name);
}

std::string materialLabel(const tinygltf::Model& model, size_t material)
{
    return named("materials[" + std::to_string(material) + "]", model.materials[material].name);
}

// ---- Extensions --------------------------------------------------------------------

// The optional extensions the baker ignores (gltf_load refused unsupported required ones).
void checkExtensions(const tinygltf::Model& model, Warnings& warnings)
{
    for (const std::string& name : model.extensionsUsed) {
        if (gltf::supportedExtensions().count(name))
            continue;
        if (name == "KHR_materials_pbrSpecularGlossiness")
            warnings.add("ignores optional extension " + name + " (uses the metallic-roughness data)");
        else if (name == "KHR_texture_basisu")
            warnings.add("ignores optional extension " + name + " (uses the textures' PNG or JPEG sources)");
        else
            warnings.add("ignores optional extension " + name);
    }
}

// ---- Node hierarchy ----------------------------------------------------------------

// The nodes of the imported scene in depth-first pre-order (parents before children).
struct NodeOrder {
    std::vector<size_t> sourceOf;   // new index -> glTF node
    std::vector<int32_t> parentOf;  // new index -> new parent index or kNone
    std::vector<int32_t> newIndex;  // glTF node -> new index or kNone (unreachable)
};

std::vector<int> sceneRoots(const tinygltf::Model& model, const std::string& file)
{
    if (model.defaultScene >= 0 && size_t(model.defaultScene) >= model.scenes.size())
        fail(file, "default scene " + std::to_string(model.defaultScene) + " does not exist");
    if (!model.scenes.empty())
        return model.scenes[model.defaultScene >= 0 ? size_t(model.defaultScene) : 0].nodes;

    // No scenes: every node that is nobody's child is a root.
    std::vector<bool> isChild(model.nodes.size(), false);
    for (size_t n = 0; n < model.nodes.size(); ++n)
        for (int child : model.nodes[n].children)
            if (child >= 0 && size_t(child) < model.nodes.size())
                isChild[size_t(child)] = true;
    std::vector<int> roots;
    for (size_t n = 0; n < model.nodes.size(); ++n)
        if (!isChild[n])
            roots.push_back(int(n));
    return roots;
}

NodeOrder orderNodes(const tinygltf::Model& model, const std::string& file)
{
    NodeOrder order;
    order.newIndex.assign(model.nodes.size(), kNone);
    enum class State : uint8_t { Unvisited, OnPath, Done };
    std::vector<State> state(model.nodes.size(), State::Unvisited);

    // Iterative DFS: a node met again while on the current path closes a cycle; one met
    // again after it was finished has two parents. glTF requires a strict forest.
    auto enter = [&](int node, int32_t parent) {
        if (node < 0 || size_t(node) >= model.nodes.size())
            fail(file, "node " + std::to_string(node) + " does not exist");
        const size_t n = size_t(node);
        if (state[n] == State::OnPath)
            fail(file, "node hierarchy has a cycle through " + nodeLabel(model, n));
        if (state[n] == State::Done)
            fail(file, nodeLabel(model, n) + " has more than one parent");
        state[n] = State::OnPath;
        order.newIndex[n] = int32_t(order.sourceOf.size());
        order.sourceOf.push_back(n);
        order.parentOf.push_back(parent);
    };

    struct Frame {
        size_t node;
        size_t nextChild;
    };
    for (int root : sceneRoots(model, file)) {
        enter(root, kNone);
        std::vector<Frame> stack{{size_t(root), 0}};
        while (!stack.empty()) {
            Frame& top = stack.back();
            const std::vector<int>& children = model.nodes[top.node].children;
            if (top.nextChild < children.size()) {
                const int child = children[top.nextChild++];
                const int32_t parent = order.newIndex[top.node];
                enter(child, parent);
                stack.push_back({size_t(child), 0});
            } else {
                state[top.node] = State::Done;
                stack.pop_back();
            }
        }
    }
    return order;
}

// Decomposes a glTF node matrix (column-major) into T * R * S. Only rigid transforms
// with per-axis scale can be stored, so shear and projective rows are errors.
void decomposeNodeMatrix(const std::vector<double>& m, Node& node, const std::string& file,
                         const std::string& label)
{
    for (double v : m)
        if (!std::isfinite(v))
            fail(file, label + " has a non-finite matrix");
    // Check the last row (0, 0, 0, 1): elements 3, 7, 11, 15 in column-major order.
    constexpr double kRowTolerance = 1e-6;
    if (std::abs(m[3]) > kRowTolerance || std::abs(m[7]) > kRowTolerance ||
        std::abs(m[11]) > kRowTolerance || std::abs(m[15] - 1.0) > kRowTolerance)
        fail(file, label + " matrix is not affine (last row is not 0 0 0 1)");

    node.translation = glm::vec3(float(m[12]), float(m[13]), float(m[14]));
    std::array<glm::dvec3, 3> axis = {glm::dvec3(m[0], m[1], m[2]), glm::dvec3(m[4], m[5], m[6]),
                                      glm::dvec3(m[8], m[9], m[10])};
    glm::dvec3 scale(glm::length(axis[0]), glm::length(axis[1]), glm::length(axis[2]));

    // Shear check: the columns of R * S are orthogonal (relative tolerance for float noise).
    constexpr double kShearTolerance = 1e-4;
    for (int i = 0; i < 3; ++i)
        for (int j = i + 1; j < 3; ++j)
            if (std::abs(glm::dot(axis[size_t(i)], axis[size_t(j)])) >
                kShearTolerance * scale[i] * scale[j])
                fail(file, label + " matrix has shear (cannot be decomposed into translation, "
                                   "rotation and scale)");

    // Orthonormal rotation basis; zero-scale axes get any direction completing the basis.
    constexpr double kZero = 1e-12;
    std::array<bool, 3> present{};
    for (size_t i = 0; i < 3; ++i) {
        present[i] = scale[int(i)] > kZero;
        if (present[i])
            axis[i] /= scale[int(i)];
    }
    const int presentCount = int(present[0]) + int(present[1]) + int(present[2]);
    if (presentCount == 0) {
        axis = {glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1)};
    } else if (presentCount == 1) {
        const size_t k = present[0] ? 0 : present[1] ? 1 : 2;
        const glm::dvec3 helper = std::abs(axis[k].x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
        axis[(k + 1) % 3] = glm::normalize(glm::cross(axis[k], helper));
        axis[(k + 2) % 3] = glm::cross(axis[k], axis[(k + 1) % 3]);
    } else if (presentCount == 2) {
        const size_t k = !present[0] ? 0 : !present[1] ? 1 : 2;
        axis[k] = glm::normalize(glm::cross(axis[(k + 1) % 3], axis[(k + 2) % 3]));
    }
    // A mirroring matrix becomes a negative x scale with a proper rotation.
    if (glm::dot(glm::cross(axis[0], axis[1]), axis[2]) < 0.0) {
        axis[0] = -axis[0];
        scale.x = -scale.x;
    }
    node.rotation = glm::normalize(glm::quat_cast(glm::mat3(glm::dmat3(axis[0], axis[1], axis[2]))));
    node.scale = glm::vec3(scale);
}

Node convertNode(const tinygltf::Model& model, size_t source, const std::string& file)
{
    const tinygltf::Node& in = model.nodes[source];
    const std::string label = nodeLabel(model, source);
    Node node;
    node.name = in.name;
    if (in.matrix.size() == 16) {
        decomposeNodeMatrix(in.matrix, node, file, label);
        return node;
    }
    if (!in.matrix.empty())
        fail(file, label + " matrix has " + std::to_string(in.matrix.size()) + " elements, not 16");
    for (const std::vector<double>* v : {&in.translation, &in.rotation, &in.scale})
        for (double x : *v)
            if (!std::isfinite(x))
                fail(file, label + " has a non-finite transform");
    if (in.translation.size() == 3)
        node.translation = glm::vec3(float(in.translation[0]), float(in.translation[1]), float(in.translation[2]));
    if (in.scale.size() == 3)
        node.scale = glm::vec3(float(in.scale[0]), float(in.scale[1]), float(in.scale[2]));
    if (in.rotation.size() == 4) {
        // glTF stores x, y, z, w; glm::quat's constructor takes w first.
        const glm::quat q(float(in.rotation[3]), float(in.rotation[0]), float(in.rotation[1]),
                          float(in.rotation[2]));
        if (glm::length(q) < 1e-6f)
            fail(file, label + " has a zero rotation quaternion");
        node.rotation = glm::normalize(q);
    }
    return node;
}

// ---- Materials and texture sources -----------------------------------------------

std::string mimeFromExtension(const fs::path& file, const std::string& fallback)
{
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (ext == ".png")
        return "image/png";
    if (ext == ".jpg" || ext == ".jpeg")
        return "image/jpeg";
    if (ext == ".webp")
        return "image/webp";
    return fallback;
}

// A data URI's image without "mimeType": named by its signature (validation has checked
// that the URI's media type is one the file may use: gltf_texture_source.h).
std::string mimeFromSignature(std::span<const uint8_t> bytes)
{
    if (bytes.size() >= 8 && bytes[0] == 0x89 && bytes[1] == 'P' && bytes[2] == 'N' && bytes[3] == 'G')
        return "image/png";
    if (bytes.size() >= 3 && bytes[0] == 0xff && bytes[1] == 0xd8 && bytes[2] == 0xff)
        return "image/jpeg";
    if (isWebp(bytes))
        return "image/webp";
    return {};
}

class TextureTable {
public:
    TextureTable(const gltf::LoadedGltf& loaded, const fs::path& gltfPath, const std::string& file,
                 Warnings& warnings)
        : model_(loaded.model), dataImages_(loaded.dataImages), baseDir_(gltfPath.parent_path()), file_(file),
          warnings_(warnings)
    {
    }

    // Index into Scene::textures for a material slot, or kNone when the slot is empty or
    // cannot be used (other texture coordinate set, no image source).
    int32_t resolve(int textureIndex, int texCoord, bool srgb, const std::string& slot)
    {
        if (textureIndex < 0)
            return kNone;
        if (size_t(textureIndex) >= model_.textures.size())
            fail(file_, slot + " refers to missing texture " + std::to_string(textureIndex));
        if (texCoord != 0) {
            warnings_.add(slot + " uses TEXCOORD_" + std::to_string(texCoord) +
                          " (only TEXCOORD_0 is supported): treated as untextured");
            return kNone;
        }
        // The EXT_texture_webp image where there is one, else the core source.
        const int image = gltf::textureImage(model_.textures[size_t(textureIndex)]);
        if (image < 0) {
            warnings_.add(slot + " texture " + std::to_string(textureIndex) +
                          " has no core or WebP image source: treated as untextured");
            return kNone;
        }
        if (size_t(image) >= model_.images.size())
            fail(file_, "texture " + std::to_string(textureIndex) + " refers to missing image " +
                            std::to_string(image));
        // One entry per (image, colour space): the same pixels used as sRGB colour and as
        // linear data are baked differently (mip filtering in linear light for sRGB).
        const auto key = std::make_pair(image, srgb);
        if (auto it = entries_.find(key); it != entries_.end())
            return it->second;
        const int32_t index = int32_t(sources_.size());
        sources_.push_back(makeSource(size_t(image), srgb, slot));
        entries_.emplace(key, index);
        return index;
    }

    std::vector<TextureSource>& sources() { return sources_; }

private:
    TextureSource makeSource(size_t imageIndex, bool srgb, const std::string& slot)
    {
        const tinygltf::Image& image = model_.images[imageIndex];
        TextureSource source;
        source.srgb = srgb;
        source.mimeType = image.mimeType;
        const std::string label = "images[" + std::to_string(imageIndex) + "]";
        if (image.bufferView >= 0) {
            const std::span<const uint8_t> bytes = gltf::bufferViewBytes(model_, image.bufferView, file_, label);
            source.encoded.assign(bytes.begin(), bytes.end());
        } else if (auto it = dataImages_.find(imageIndex); it != dataImages_.end()) {
            source.encoded = it->second; // copied: the image may also be used in the other colour space
            if (source.mimeType.empty())
                source.mimeType = mimeFromSignature(source.encoded);
        } else if (!image.uri.empty()) {
            source.file = baseDir_ / gltf::percentDecode(image.uri);
            std::error_code ec;
            if (!fs::is_regular_file(source.file, ec))
                fail(file_, label + ".uri: image file " + source.file.string() + " (used by " + slot + ") not found");
            source.mimeType = mimeFromExtension(source.file, image.mimeType);
        } else {
            fail(file_, label + " (used by " + slot + ") has no data");
        }
        source.name = !image.name.empty()      ? image.name
                      : !source.file.empty()    ? source.file.filename().string()
                                                : label;
        if (source.encoded.empty() && source.file.empty())
            fail(file_, label + " (used by " + slot + ") is empty");
        return source;
    }

    const tinygltf::Model& model_;
    const std::map<size_t, std::vector<uint8_t>>& dataImages_;
    fs::path baseDir_;
    std::string file_;
    Warnings& warnings_;
    std::map<std::pair<int, bool>, int32_t> entries_;
    std::vector<TextureSource> sources_;
};

// The texture info's name for messages ("baseColorTexture").
std::string slotName(const gltf::MaterialTextureInfo& info)
{
    const std::string path = info.path;
    return path.substr(path.find_last_of('.') + 1);
}

// The pack's texture slot of a glTF texture info (the same five, in the same order).
TextureSlot slotOf(gltf::TextureInfoKind kind)
{
    static_assert(gltf::kTextureInfoCount == kTextureSlotCount);
    switch (kind) {
    case gltf::TextureInfoKind::BaseColor: return TextureSlot::BaseColor;
    case gltf::TextureInfoKind::MetallicRoughness: return TextureSlot::MetallicRoughness;
    case gltf::TextureInfoKind::Normal: return TextureSlot::Normal;
    case gltf::TextureInfoKind::Occlusion: return TextureSlot::Occlusion;
    case gltf::TextureInfoKind::Emissive: return TextureSlot::Emissive;
    }
    return TextureSlot::BaseColor;
}

int32_t& textureField(Material& m, TextureSlot slot)
{
    switch (slot) {
    case TextureSlot::BaseColor: return m.baseColorTexture;
    case TextureSlot::MetallicRoughness: return m.metallicRoughnessTexture;
    case TextureSlot::Normal: return m.normalTexture;
    case TextureSlot::Occlusion: return m.occlusionTexture;
    case TextureSlot::Emissive: break;
    }
    return m.emissiveTexture;
}

Material convertMaterial(const tinygltf::Model& model, size_t index, TextureTable& textures,
                         const std::string& file)
{
    const tinygltf::Material& in = model.materials[index];
    const tinygltf::PbrMetallicRoughness& pbr = in.pbrMetallicRoughness;
    const std::string label = materialLabel(model, index);
    Material m;
    m.name = in.name;
    if (pbr.baseColorFactor.size() == 4)
        m.baseColorFactor = glm::vec4(float(pbr.baseColorFactor[0]), float(pbr.baseColorFactor[1]),
                                      float(pbr.baseColorFactor[2]), float(pbr.baseColorFactor[3]));
    if (in.emissiveFactor.size() == 3)
        m.emissiveFactor = glm::clamp(glm::vec3(float(in.emissiveFactor[0]), float(in.emissiveFactor[1]),
                                                float(in.emissiveFactor[2])),
                                      0.0f, 1.0f);
    if (auto it = in.extensions.find("KHR_materials_emissive_strength"); it != in.extensions.end()) {
        const tinygltf::Value& strength = it->second.Get("emissiveStrength");
        if (strength.IsNumber())
            m.emissiveFactor *= std::max(float(strength.GetNumberAsDouble()), 0.0f);
    }
    m.metallicFactor = float(pbr.metallicFactor);
    m.roughnessFactor = float(pbr.roughnessFactor);
    m.normalScale = float(in.normalTexture.scale);
    m.occlusionStrength = float(in.occlusionTexture.strength);
    m.alphaCutoff = float(in.alphaCutoff);
    m.doubleSided = in.doubleSided;
    if (in.alphaMode == "MASK")
        m.alphaMode = AlphaMode::Mask;
    else if (in.alphaMode == "BLEND")
        m.alphaMode = AlphaMode::Blend;
    // Any other alphaMode was reported by the schema validation ("treated as OPAQUE").

    const std::array<float, 10> factors = {m.baseColorFactor.r, m.baseColorFactor.g, m.baseColorFactor.b,
                                           m.baseColorFactor.a, m.metallicFactor,    m.roughnessFactor,
                                           m.normalScale,       m.occlusionStrength, m.alphaCutoff,
                                           m.emissiveFactor.r};
    for (float f : factors)
        if (!std::isfinite(f))
            fail(file, label + " has a non-finite factor");
    // The schema bounds these factors; values outside were reported as clamped.
    auto unit = [](float f) { return std::clamp(f, 0.0f, 1.0f); };
    m.baseColorFactor = glm::clamp(m.baseColorFactor, 0.0f, 1.0f);
    m.emissiveFactor = glm::max(m.emissiveFactor, 0.0f); // emissiveStrength may raise it above 1
    m.metallicFactor = unit(m.metallicFactor);
    m.roughnessFactor = unit(m.roughnessFactor);
    m.occlusionStrength = unit(m.occlusionStrength);
    m.alphaCutoff = std::max(m.alphaCutoff, 0.0f);

    m.unlit = gltf::isUnlit(in);
    for (const gltf::MaterialTextureInfo& info : gltf::materialTextureInfos(in)) {
        const std::string slot = label + " " + slotName(info);
        const TextureSlot textureSlot = slotOf(info.kind);
        const int32_t texture = textures.resolve(info.index, info.texCoord, info.srgb, slot);
        textureField(m, textureSlot) = texture;
        if (texture == kNone)
            continue; // a transform of an unused slot would only make the pack larger
        // Without the extension the slot keeps the identity.
        const gltf::TextureInfoTransform& t = info.transform;
        TextureTransform& transform = m.textureTransforms[uint32_t(textureSlot)];
        if (t.present)
            transform = TextureTransform::fromOffsetRotationScale(t.offset, t.rotation, t.scale);
        if (!std::isfinite(transform.areaScale()) || !std::isfinite(transform.offset.x) ||
            !std::isfinite(transform.offset.y))
            fail(file, slot + " KHR_texture_transform is too large for 32-bit floats");
    }
    return m;
}

bool hasAnyTexture(const Material& m)
{
    return m.baseColorTexture != kNone || m.metallicRoughnessTexture != kNone || m.normalTexture != kNone ||
           m.occlusionTexture != kNone || m.emissiveTexture != kNone;
}

// ---- Primitives --------------------------------------------------------------------

// A primitive's vertices and local triangle list, attributes already in the streams the
// scene stores.
struct PrimitiveData {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> uvs;      // when the scene stores uvs
    std::vector<glm::vec4> tangents; // when the scene stores tangents
    std::vector<uint32_t> triangles; // local indices
    DeformationStreams deform;       // as the scene stores them (morphTargets slots per vertex)
};

struct StreamNeeds {
    bool uv = false;
    bool tangent = false;
    bool skin = false;          // some node of the scene is skinned
    uint32_t morphTargets = 0;  // the most targets of any mesh
    bool morphNormals = false;  // some target has NORMAL deltas
    bool morphTangents = false; // some target has TANGENT deltas (and tangents are stored)
};

// Gathers attribute `values` (components per element) through `vertexSource`.
template <class Vec>
std::vector<Vec> gather(const gltf::FloatArray& a, const std::vector<uint32_t>& vertexSource)
{
    std::vector<Vec> out(vertexSource.size());
    const size_t c = size_t(a.components);
    for (size_t v = 0; v < vertexSource.size(); ++v)
        for (size_t k = 0; k < c && k < size_t(Vec::length()); ++k)
            out[v][glm::length_t(k)] = a.values[size_t(vertexSource[v]) * c + k];
    return out;
}

// Whether the file holds accessor a's data (not: a buffer without a uri - valid glTF, its
// bytes "provided by other means", e.g. by an extension the baker does not read - or
// neither a bufferView nor sparse data).
bool hasData(const gltf::LoadedGltf& loaded, int a)
{
    if (a < 0 || size_t(a) >= loaded.model.accessors.size() || loaded.accessorsWithoutData.count(size_t(a)))
        return false;
    return gltf::bytesNotInFile(loaded.model, loaded.buffersWithoutData, a).empty();
}

// Where a primitive's data comes from, and the names its errors and warnings use.
struct PrimitiveSource {
    const tinygltf::Model& model;
    const tinygltf::Primitive& prim;
    const std::string& label;
    const std::string& file;
    size_t vertexCount = 0; // POSITION's count, once read
};

// The accessor of attribute `name`, or -1.
int attributeAccessor(const tinygltf::Primitive& prim, const char* name)
{
    auto it = prim.attributes.find(name);
    return it == prim.attributes.end() ? -1 : it->second;
}

// Step 1: positions (required, finite).
gltf::FloatArray readPositions(const PrimitiveSource& src)
{
    const int positionAccessor = attributeAccessor(src.prim, "POSITION");
    if (positionAccessor < 0)
        fail(src.file, src.label + " has no POSITION attribute");
    gltf::FloatArray positions = gltf::readFloatAccessor(src.model, positionAccessor, {TINYGLTF_TYPE_VEC3}, src.file,
                                                         src.label + ".attributes.POSITION");
    for (size_t i = 0; i < positions.values.size(); ++i)
        if (!std::isfinite(positions.values[i]))
            fail(src.file, src.label + " POSITION " + std::to_string(i / 3) + " is not finite (NaN or infinity)");
    return positions;
}

// Step 2: indices (sequential for non-indexed primitives), range-checked.
std::vector<uint32_t> readIndices(const PrimitiveSource& src)
{
    const size_t vertexCount = src.vertexCount;
    std::vector<uint32_t> indices;
    if (src.prim.indices >= 0) {
        indices = gltf::readIndexAccessor(src.model, src.prim.indices, src.file, src.label + ".indices");
        for (size_t i = 0; i < indices.size(); ++i)
            if (indices[i] >= vertexCount)
                fail(src.file, src.label + " index " + std::to_string(i) + " (value " + std::to_string(indices[i]) +
                                   ") out of range (" + std::to_string(vertexCount) + " vertices)");
    } else {
        if (vertexCount > UINT32_MAX)
            fail(src.file, src.label + " has too many vertices");
        indices.resize(vertexCount);
        std::iota(indices.begin(), indices.end(), 0u);
    }
    return indices;
}

// Step 3: triangle list in glTF vertex numbering (warns about a dangling partial triangle).
std::vector<uint32_t> readTriangles(const PrimitiveSource& src, const std::vector<uint32_t>& indices,
                                    Warnings& warnings)
{
    if (src.prim.mode == TINYGLTF_MODE_TRIANGLES && indices.size() % 3 != 0)
        warnings.add(src.label + " has " + std::to_string(indices.size()) +
                     " indices, not a multiple of 3: ignoring the last " + std::to_string(indices.size() % 3));
    return gltf::triangulate(indices, src.prim.mode);
}

// Step 4: which source vertex each output vertex copies (renumbering `triangles` to match).
// With normals: the vertices the triangles use, in source order (primitives sharing one
// large vertex buffer keep only their own). Without normals, glTF requires flat normals:
// one vertex per corner.
std::vector<uint32_t> selectVertices(bool hasNormals, size_t vertexCount, std::vector<uint32_t>& triangles)
{
    std::vector<uint32_t> vertexSource;
    if (hasNormals) {
        std::vector<uint32_t> remap(vertexCount, UINT32_MAX);
        for (uint32_t i : triangles)
            remap[i] = 0;
        for (size_t v = 0; v < vertexCount; ++v)
            if (remap[v] == 0) {
                remap[v] = uint32_t(vertexSource.size());
                vertexSource.push_back(uint32_t(v));
            }
        for (uint32_t& i : triangles)
            i = remap[i];
    } else {
        vertexSource = triangles;
        std::iota(triangles.begin(), triangles.end(), 0u);
    }
    return vertexSource;
}

// A per-vertex float attribute, which must have as many elements as POSITION.
gltf::FloatArray readAttribute(const PrimitiveSource& src, int accessor, int type, const char* name)
{
    gltf::FloatArray a =
        gltf::readFloatAccessor(src.model, accessor, {type}, src.file, src.label + ".attributes." + name);
    if (a.count != src.vertexCount)
        fail(src.file, src.label + ".attributes." + name + " has " + std::to_string(a.count) + " elements but POSITION has " +
                           std::to_string(src.vertexCount));
    return a;
}

// Given normals re-normalised; broken ones replaced by the smooth normal of the adjacent triangles.
void repairNormals(const PrimitiveSource& src, PrimitiveData& out, Warnings& warnings)
{
    std::vector<glm::vec3> smooth; // computed only if some normal is broken
    size_t repaired = 0;
    for (size_t v = 0; v < out.normals.size(); ++v) {
        const float len = glm::length(out.normals[v]);
        if (len > 1e-12f && std::isfinite(len)) {
            out.normals[v] /= len;
            continue;
        }
        if (smooth.empty())
            smooth = gltf::smoothNormals(out.positions, out.triangles);
        out.normals[v] = smooth[v];
        ++repaired;
    }
    if (repaired > 0)
        warnings.add(src.label + " has " + std::to_string(repaired) +
                     " zero or invalid normals: replaced by smooth normals");
}

// Step 5: normals - given (re-normalised; broken ones replaced by the smooth normal
// of the adjacent triangles) or flat.
void readNormals(const PrimitiveSource& src, const std::vector<uint32_t>& vertexSource, PrimitiveData& out,
                 Warnings& warnings)
{
    const int normalAccessor = attributeAccessor(src.prim, "NORMAL");
    if (normalAccessor >= 0) {
        out.normals = gather<glm::vec3>(readAttribute(src, normalAccessor, TINYGLTF_TYPE_VEC3, "NORMAL"), vertexSource);
        repairNormals(src, out, warnings);
    } else {
        warnings.add(src.label + " has no normals: computed flat normals");
        out.normals.resize(out.positions.size());
        for (size_t i = 0; i + 2 < out.positions.size(); i += 3) {
            const glm::vec3 n = gltf::faceNormal(out.positions[i], out.positions[i + 1], out.positions[i + 2]);
            out.normals[i] = out.normals[i + 1] = out.normals[i + 2] = n;
        }
    }
}

// Step 6: uvs, when the scene stores them (zeros for primitives that have none).
void readUvs(const PrimitiveSource& src, const std::vector<uint32_t>& vertexSource, PrimitiveData& out)
{
    const int uvAccessor = attributeAccessor(src.prim, "TEXCOORD_0");
    if (uvAccessor >= 0) {
        out.uvs = gather<glm::vec2>(readAttribute(src, uvAccessor, TINYGLTF_TYPE_VEC2, "TEXCOORD_0"), vertexSource);
        for (const glm::vec2& uv : out.uvs)
            if (!std::isfinite(uv.x) || !std::isfinite(uv.y))
                fail(src.file, src.label + " TEXCOORD_0 has a non-finite value");
    } else {
        // Without TEXCOORD_0 a textured material samples uv (0, 0); validation warned.
        out.uvs.assign(out.positions.size(), glm::vec2(0.0f));
    }
}

// Step 7: tangents, when the scene stores them: given, or generated from the uvs.
void readTangents(const PrimitiveSource& src, const std::vector<uint32_t>& vertexSource, const Material* material,
                  PrimitiveData& out, Warnings& warnings)
{
    const int tangentAccessor = attributeAccessor(src.prim, "TANGENT");
    if (tangentAccessor >= 0) {
        out.tangents =
            gather<glm::vec4>(readAttribute(src, tangentAccessor, TINYGLTF_TYPE_VEC4, "TANGENT"), vertexSource);
        for (size_t v = 0; v < out.tangents.size(); ++v) {
            glm::vec3 t(out.tangents[v]);
            const float len = glm::length(t);
            t = len > 1e-12f && std::isfinite(len) ? t / len : gltf::anyPerpendicular(out.normals[v]);
            out.tangents[v] = glm::vec4(t, out.tangents[v].w < 0.0f ? -1.0f : 1.0f);
        }
    } else {
        out.tangents = gltf::generateTangents(out.positions, out.normals, out.uvs, out.triangles);
        if (material != nullptr && material->normalTexture != kNone)
            warnings.add(src.label + " has a normal map but no TANGENT: generated tangents from TEXCOORD_0");
    }
}

// Step 8: skin influences and morph deltas, when the scene stores them.
void readDeformation(const PrimitiveSource& src, const std::vector<uint32_t>& vertexSource, StreamNeeds needs,
                     PrimitiveData& out, Warnings& warnings)
{
    const gltf::DeformationSource d{src.model, src.prim, vertexSource, src.vertexCount, src.label, src.file};
    if (needs.skin)
        gltf::readInfluences(d, out.deform.joints, out.deform.weights,
                             [&warnings](const std::string& key, const std::string& m) { warnings.once(key, m); });
    out.deform.morphTargets = needs.morphTargets;
    if (needs.morphTargets == 0)
        return;
    out.deform.positions = gltf::readMorphDeltas(d, "POSITION", needs.morphTargets);
    if (needs.morphNormals)
        out.deform.normals = gltf::readMorphDeltas(d, "NORMAL", needs.morphTargets);
    if (needs.morphTangents)
        out.deform.tangents = gltf::readMorphDeltas(d, "TANGENT", needs.morphTargets);
    for (const auto& target : src.prim.targets)
        for (const auto& [name, accessor] : target)
            if (name != "POSITION" && name != "NORMAL" && name != "TANGENT")
                warnings.once("morph " + name, "ignores morph target attribute " + name +
                                                   " (only POSITION, NORMAL and TANGENT deltas are posed)");
}

// Step 9: everything else is not used by the renderer (one warning per attribute kind).
void warnIgnoredAttributes(const tinygltf::Primitive& prim, bool skin, Warnings& warnings)
{
    for (const auto& [name, accessor] : prim.attributes) {
        (void)accessor;
        if (name == "POSITION" || name == "NORMAL" || name == "TEXCOORD_0" || name == "TANGENT")
            continue;
        if (skin && (name.rfind("JOINTS_", 0) == 0 || name.rfind("WEIGHTS_", 0) == 0))
            continue;
        std::string kind = name;
        while (!kind.empty() && std::isdigit(uchar(kind.back())))
            kind.pop_back();
        if (kind.size() < name.size())
            kind += "n";
        warnings.once("attribute " + kind, "ignores vertex attribute " + kind + " (not used by the renderer)");
    }
}

// One triangle primitive's streams, or nothing (with a warning) when it has no triangles.
std::optional<PrimitiveData> readPrimitive(const gltf::LoadedGltf& loaded, const tinygltf::Primitive& prim,
                                           const std::string& label, const Material* material, StreamNeeds needs,
                                           const std::string& file, Warnings& warnings)
{
    // A primitive whose geometry lies in a buffer without bytes is skipped, not refused: the
    // rest of the file still bakes.
    std::vector<std::pair<std::string, int>> streams{{".indices", prim.indices}};
    for (const auto& [name, accessor] : prim.attributes)
        streams.emplace_back(".attributes." + name, accessor);
    for (const auto& [what, accessor] : streams) {
        const std::string why = gltf::bytesNotInFile(loaded.model, loaded.buffersWithoutData, accessor);
        if (!why.empty()) {
            warnings.add(label + what + ": " + why + ": primitive skipped");
            return std::nullopt;
        }
    }
    PrimitiveSource src{loaded.model, prim, label, file};
    const gltf::FloatArray positions = readPositions(src);
    src.vertexCount = positions.count;
    const std::vector<uint32_t> indices = readIndices(src);
    std::vector<uint32_t> triangles = readTriangles(src, indices, warnings);
    if (triangles.empty()) {
        warnings.add(label + " has no triangles: skipped");
        return std::nullopt;
    }
    const bool hasNormals = attributeAccessor(prim, "NORMAL") >= 0;
    const std::vector<uint32_t> vertexSource = selectVertices(hasNormals, src.vertexCount, triangles);

    PrimitiveData out;
    out.positions = gather<glm::vec3>(positions, vertexSource);
    out.triangles = std::move(triangles);
    readNormals(src, vertexSource, out, warnings);
    if (needs.uv)
        readUvs(src, vertexSource, out);
    if (needs.tangent)
        readTangents(src, vertexSource, material, out, warnings);
    readDeformation(src, vertexSource, needs, out, warnings);
    warnIgnoredAttributes(prim, needs.skin, warnings);
    return out;
}

// ---- Animations --------------------------------------------------------------------

// The channel's target path, or nothing (with a warning) for paths not baked.
std::optional<AnimationPath> channelPath(const std::string& path, Warnings& warnings)
{
    if (path == "translation")
        return AnimationPath::Translation;
    if (path == "rotation")
        return AnimationPath::Rotation;
    if (path == "scale")
        return AnimationPath::Scale;
    if (path == "weights")
        return AnimationPath::Weights;
    warnings.once("path " + path, "ignores animation channels on path " + quoted(path));
    return std::nullopt;
}

// LINEAR and STEP as they are; CUBICSPLINE keeps each keyframe's value and drops its
// in/out tangents (a linear approximation; `cubic` tells the caller to skip them).
Interpolation channelInterpolation(const std::string& interpolation, const std::string& label,
                                   const std::string& file, bool& cubic)
{
    cubic = interpolation == "CUBICSPLINE";
    if (interpolation == "LINEAR" || cubic)
        return Interpolation::Linear;
    if (interpolation == "STEP")
        return Interpolation::Step;
    fail(file, label + " has unknown interpolation " + quoted(interpolation));
}

// Key times: finite, strictly increasing, at least one.
std::vector<float> readKeyTimes(const tinygltf::Model& model, int accessor, const std::string& label,
                                const std::string& file)
{
    const gltf::FloatArray input = gltf::readFloatAccessor(model, accessor, {TINYGLTF_TYPE_SCALAR}, file, label + " input");
    if (input.count == 0)
        fail(file, label + " has no keyframes");
    const std::vector<float>& times = input.values;
    for (size_t k = 0; k < times.size(); ++k) {
        if (!std::isfinite(times[k]))
            fail(file, label + " key time " + std::to_string(k) + " is not finite");
        if (k > 0 && !(times[k] > times[k - 1]))
            fail(file, label + " key times are not strictly increasing at key " + std::to_string(k));
    }
    return times;
}

// One value per key (the middle of each cubic-spline triple), finite; rotations normalised.
std::vector<glm::vec4> readKeyValues(const tinygltf::Model& model, int accessor, size_t keys, bool rotation,
                                     bool cubic, const std::string& label, const std::string& file)
{
    const gltf::FloatArray output = gltf::readFloatAccessor(
        model, accessor, {rotation ? TINYGLTF_TYPE_VEC4 : TINYGLTF_TYPE_VEC3}, file, label + " output");
    const size_t perKey = cubic ? 3 : 1; // cubic spline: in-tangent, value, out-tangent
    if (output.count != keys * perKey)
        fail(file, label + " has " + std::to_string(output.count) + " output values for " + std::to_string(keys) +
                       " keys");
    const size_t c = size_t(output.components);
    std::vector<glm::vec4> values(keys);
    for (size_t k = 0; k < keys; ++k) {
        const size_t e = k * perKey + (cubic ? 1 : 0);
        glm::vec4 v(0.0f);
        for (size_t i = 0; i < c; ++i)
            v[glm::length_t(i)] = output.values[e * c + i];
        if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z) || !std::isfinite(v.w))
            fail(file, label + " output value " + std::to_string(k) + " is not finite");
        if (rotation) {
            const float len = glm::length(v);
            if (len < 1e-6f)
                fail(file, label + " has a zero rotation quaternion at key " + std::to_string(k));
            v /= len;
        }
        values[k] = v;
    }
    return values;
}

// Morph targets of a glTF mesh (3.7.2.2: every primitive has as many as the first).
uint32_t meshMorphTargets(const tinygltf::Model& model, int mesh)
{
    if (mesh < 0 || size_t(mesh) >= model.meshes.size() || model.meshes[size_t(mesh)].primitives.empty())
        return 0;
    return uint32_t(model.meshes[size_t(mesh)].primitives[0].targets.size());
}

std::vector<AnimationChannel> convertChannel(const gltf::LoadedGltf& loaded, const tinygltf::Animation& anim,
                                               const tinygltf::AnimationChannel& ch, const std::string& animLabel,
                                               size_t channelIndex,
                                               const NodeOrder& order, const std::string& file,
                                               Warnings& warnings, const Log& log)
{
    const tinygltf::Model& model = loaded.model;
    const std::string label = animLabel + ".channels[" + std::to_string(channelIndex) + "]";
    AnimationChannel out;
    const std::optional<AnimationPath> path = channelPath(ch.target_path, warnings);
    if (!path)
        return {};
    out.path = *path;
    if (ch.target_node < 0)
        return {}; // targets something other than a node (extension)
    if (size_t(ch.target_node) >= model.nodes.size())
        fail(file, label + " targets missing node " + std::to_string(ch.target_node));
    if (order.newIndex[size_t(ch.target_node)] == kNone) {
        log.info("import: " + label + " targets " + nodeLabel(model, size_t(ch.target_node)) +
                 ", which is not in the scene: ignored");
        return {};
    }
    out.node = uint32_t(order.newIndex[size_t(ch.target_node)]);
    if (ch.sampler < 0 || size_t(ch.sampler) >= anim.samplers.size())
        fail(file, label + " refers to missing sampler " + std::to_string(ch.sampler));
    const tinygltf::AnimationSampler& sampler = anim.samplers[size_t(ch.sampler)];
    bool cubic = false;
    out.interpolation = channelInterpolation(sampler.interpolation, label, file, cubic);

    // An animation whose keys or values the file does not hold (a buffer without a uri, an
    // accessor without a bufferView or sparse data: an extension would supply them) is left
    // out rather than baked from zeros.
    for (const auto& [accessor, what] : {std::pair{sampler.input, "input"}, std::pair{sampler.output, "output"}})
        if (!hasData(loaded, accessor)) {
            warnings.add(label + ": its sampler's " + what + " (accessors[" + std::to_string(accessor) +
                         "]) has no data in the file: channel ignored");
            return {};
        }
    out.times = readKeyTimes(model, sampler.input, label, file);
    if (cubic)
        warnings.once("cubic " + animLabel,
                      animLabel + " uses CUBICSPLINE interpolation: linearised (keyframe values kept, tangents dropped)");
    if (out.path == AnimationPath::Weights)
        return gltf::weightChannels(model, sampler, out, meshMorphTargets(model, model.nodes[size_t(ch.target_node)].mesh),
                                    cubic, label, file);
    out.values = readKeyValues(model, sampler.output, out.times.size(), out.path == AnimationPath::Rotation, cubic,
                               label, file);
    return {out};
}

// ---- Import steps ------------------------------------------------------------------

// The glTF meshes the scene's nodes instance, in source order.
struct MeshSelection {
    std::vector<int32_t> meshIndex; // glTF mesh -> lfd mesh or kNone
    std::vector<size_t> meshSources; // lfd mesh -> glTF mesh
};

// Step 2: the meshes the nodes of the scene (parents first) instance.
MeshSelection selectMeshes(const tinygltf::Model& model, const NodeOrder& order, const std::string& file)
{
    MeshSelection selection;
    std::vector<int32_t>& meshIndex = selection.meshIndex;
    meshIndex.assign(model.meshes.size(), kNone);
    for (size_t source : order.sourceOf) {
        const int mesh = model.nodes[source].mesh;
        if (mesh >= 0 && size_t(mesh) >= model.meshes.size())
            fail(file, nodeLabel(model, source) + " refers to missing mesh " + std::to_string(mesh));
        if (mesh >= 0)
            meshIndex[size_t(mesh)] = 0;
    }
    for (size_t m = 0; m < model.meshes.size(); ++m)
        if (meshIndex[m] != kNone) {
            meshIndex[m] = int32_t(selection.meshSources.size());
            selection.meshSources.push_back(m);
        }
    return selection;
}

// Whether a primitive is made of triangles (list, strip or fan).
bool isTriangles(const tinygltf::Primitive& p)
{
    return p.mode == TINYGLTF_MODE_TRIANGLES || p.mode == TINYGLTF_MODE_TRIANGLE_STRIP ||
           p.mode == TINYGLTF_MODE_TRIANGLE_FAN;
}

// Step 3a: the materials used by triangle primitives of the selected meshes (0 = used, else kNone).
std::vector<int32_t> usedMaterials(const tinygltf::Model& model, const std::vector<size_t>& meshSources,
                                   const std::string& file)
{
    std::vector<int32_t> materialIndex(model.materials.size(), kNone);
    for (size_t m : meshSources)
        for (const tinygltf::Primitive& p : model.meshes[m].primitives) {
            if (p.material >= 0 && size_t(p.material) >= model.materials.size())
                fail(file, meshLabel(model, m) + " refers to missing material " + std::to_string(p.material));
            if (p.material >= 0 && isTriangles(p))
                materialIndex[size_t(p.material)] = 0;
        }
    return materialIndex;
}

// Step 3b: the used materials converted into the scene; `materialIndex` becomes glTF -> lfd material.
void convertMaterials(const tinygltf::Model& model, std::vector<int32_t>& materialIndex, TextureTable& textures,
                      const std::string& file, Scene& scene)
{
    for (size_t m = 0; m < model.materials.size(); ++m)
        if (materialIndex[m] != kNone) {
            materialIndex[m] = int32_t(scene.materials.size());
            scene.materials.push_back(convertMaterial(model, m, textures, file));
        }
}

// Step 4: stored streams - uvs only if some material is textured, tangents only if
// some material has a normal map.
StreamNeeds streamNeeds(const std::vector<Material>& materials)
{
    StreamNeeds needs;
    for (const Material& m : materials) {
        needs.uv = needs.uv || hasAnyTexture(m);
        needs.tangent = needs.tangent || m.normalTexture != kNone;
    }
    return needs;
}

// Step 4b: skin influences when some node of the scene is skinned; morph deltas for the
// most targets any instanced mesh has, normal / tangent deltas when some target has them.
void deformationNeeds(const gltf::LoadedGltf& loaded, const NodeOrder& order, const std::vector<size_t>& meshSources,
                      StreamNeeds& needs)
{
    const tinygltf::Model& model = loaded.model;
    for (size_t source : order.sourceOf)
        needs.skin = needs.skin || (model.nodes[source].skin >= 0 && model.nodes[source].mesh >= 0 &&
                                    size_t(model.nodes[source].skin) < loaded.skins.size());
    for (size_t m : meshSources)
        for (const tinygltf::Primitive& p : model.meshes[m].primitives) {
            needs.morphTargets = std::max(needs.morphTargets, uint32_t(p.targets.size()));
            for (const auto& target : p.targets) {
                needs.morphNormals = needs.morphNormals || target.count("NORMAL");
                needs.morphTangents = needs.morphTangents || (needs.tangent && target.count("TANGENT"));
            }
        }
}

// False (with a warning) for points and lines; fails on an invalid mode.
bool checkTriangleMode(const tinygltf::Primitive& prim, const std::string& label, const std::string& file,
                       Warnings& warnings)
{
    if (isTriangles(prim))
        return true;
    static const char* const kModeNames[] = {"POINTS", "LINES", "LINE_LOOP", "LINE_STRIP"};
    if (prim.mode < 0 || prim.mode > TINYGLTF_MODE_TRIANGLE_FAN)
        fail(file, label + " has invalid mode " + std::to_string(prim.mode));
    warnings.add(label + " is " + kModeNames[prim.mode] + ", not triangles: skipped");
    return false;
}

// Appends a primitive to the scene-wide streams; indices become absolute.
void appendPrimitive(const PrimitiveData& data, int32_t material, const std::string& file, Scene& scene)
{
    VertexStreams& vertices = scene.vertices;
    const size_t base = vertices.positions.size();
    if (base + data.positions.size() > UINT32_MAX || scene.indices.size() + data.triangles.size() > UINT32_MAX)
        fail(file, "scene has more than 2^32 vertices or indices");
    Primitive out;
    out.firstIndex = uint32_t(scene.indices.size());
    out.indexCount = uint32_t(data.triangles.size());
    out.material = material;
    for (uint32_t i : data.triangles)
        scene.indices.push_back(uint32_t(base) + i);
    vertices.positions.insert(vertices.positions.end(), data.positions.begin(), data.positions.end());
    vertices.normals.insert(vertices.normals.end(), data.normals.begin(), data.normals.end());
    vertices.uvs.insert(vertices.uvs.end(), data.uvs.begin(), data.uvs.end());
    vertices.tangents.insert(vertices.tangents.end(), data.tangents.begin(), data.tangents.end());
    DeformationStreams& deform = vertices.deform;
    for (auto [to, from] : {std::pair{&deform.positions, &data.deform.positions},
                            std::pair{&deform.normals, &data.deform.normals},
                            std::pair{&deform.tangents, &data.deform.tangents}})
        to->insert(to->end(), from->begin(), from->end());
    deform.joints.insert(deform.joints.end(), data.deform.joints.begin(), data.deform.joints.end());
    deform.weights.insert(deform.weights.end(), data.deform.weights.begin(), data.deform.weights.end());
    deform.morphTargets = data.deform.morphTargets;
    scene.primitives.push_back(out);
}

// Step 5 for one glTF mesh: one lfd::Mesh, its triangle primitives contiguous.
void importMesh(const gltf::LoadedGltf& loaded, size_t m, const std::vector<int32_t>& materialIndex,
                StreamNeeds needs, const std::string& file, Warnings& warnings, Scene& scene)
{
    const tinygltf::Model& model = loaded.model;
    const tinygltf::Mesh& gmesh = model.meshes[m];
    Mesh mesh;
    mesh.name = gmesh.name.empty() ? "mesh " + std::to_string(m) : gmesh.name;
    mesh.firstPrimitive = uint32_t(scene.primitives.size());
    for (size_t p = 0; p < gmesh.primitives.size(); ++p) {
        const tinygltf::Primitive& prim = gmesh.primitives[p];
        const std::string label = primitiveLabel(model, m, p);
        if (!checkTriangleMode(prim, label, file, warnings))
            continue;
        const int32_t material = prim.material >= 0 ? materialIndex[size_t(prim.material)] : kNone;
        const std::optional<PrimitiveData> data =
            readPrimitive(loaded, prim, label, material != kNone ? &scene.materials[size_t(material)] : nullptr,
                          needs, file, warnings);
        if (data)
            appendPrimitive(*data, material, file, scene);
    }
    mesh.primitiveCount = uint32_t(scene.primitives.size()) - mesh.firstPrimitive;
    scene.meshes.push_back(mesh);
}

// Step 6: nodes (parents first) and their meshes.
void importNodes(const tinygltf::Model& model, const NodeOrder& order, const std::vector<int32_t>& meshIndex,
                 const std::string& file, Scene& scene)
{
    for (size_t n = 0; n < order.sourceOf.size(); ++n) {
        const size_t source = order.sourceOf[n];
        Node node = convertNode(model, source, file);
        node.parent = order.parentOf[n];
        const int mesh = model.nodes[source].mesh;
        node.mesh = mesh >= 0 ? meshIndex[size_t(mesh)] : kNone;
        scene.nodes.push_back(std::move(node));
    }
}

// Step 6a: KHR_lights_punctual instances on the imported nodes.
void importLights(const tinygltf::Model& model, const NodeOrder& order, const std::string& file, Warnings& warnings,
                  Scene& scene)
{
    std::vector<std::string> dropped;
    scene.lights = gltf::convertLights(model, order.newIndex, file, dropped);
    for (std::string& warning : dropped)
        warnings.add(std::move(warning));
}

// The morph weights a node starts from (3.7.2.2: the node's, else the mesh's, else 0),
// one per target slot of the scene.
std::vector<float> defaultWeights(const tinygltf::Model& model, size_t source, uint32_t slots)
{
    const tinygltf::Node& node = model.nodes[source];
    const std::vector<double>& given = !node.weights.empty() ? node.weights : model.meshes[size_t(node.mesh)].weights;
    std::vector<float> weights(slots, 0.0f);
    for (size_t t = 0; t < given.size() && t < slots; ++t)
        weights[t] = std::isfinite(given[t]) ? float(given[t]) : 0.0f;
    return weights;
}

// Whether every triangle primitive of glTF mesh m has JOINTS_0 and WEIGHTS_0.
bool meshHasInfluences(const tinygltf::Model& model, int m)
{
    for (const tinygltf::Primitive& p : model.meshes[size_t(m)].primitives)
        if (isTriangles(p) && (!p.attributes.count("JOINTS_0") || !p.attributes.count("WEIGHTS_0")))
            return false;
    return true;
}

// 3.7.3.1: a JOINTS_n value indexes the skin's joints; one past them has no matrix.
void checkJointIndices(const Scene& scene, const std::string& file)
{
    for (const Deformer& d : scene.deformers) {
        if (d.skin == kNone)
            continue;
        const size_t joints = scene.skins[size_t(d.skin)].joints.size();
        for (size_t v = d.firstVertex; v < size_t(d.firstVertex) + d.vertexCount; ++v)
            for (int k = 0; k < 4; ++k)
                if (scene.vertices.deform.joints[v][k] >= joints)
                    fail(file, "node '" + scene.nodes[d.node].name + "': a vertex of its mesh uses joint " +
                                   std::to_string(scene.vertices.deform.joints[v][k]) + ", but its skin '" +
                                   scene.skins[size_t(d.skin)].name + "' has " + std::to_string(joints) + " joints");
    }
}

// Step 6b: a deformer for each node instance of a skinned or morphed mesh (its skin
// converted once), each with a mesh of its own and one vertex range.
void importDeformers(const gltf::LoadedGltf& loaded, const NodeOrder& order, const std::string& file,
                     Warnings& warnings, Scene& scene)
{
    const tinygltf::Model& model = loaded.model;
    std::map<int, int32_t> skinIndex; // glTF skin -> scene skin
    for (size_t n = 0; n < order.sourceOf.size(); ++n) {
        const size_t source = order.sourceOf[n];
        const tinygltf::Node& node = model.nodes[source];
        if (node.mesh < 0 || scene.nodes[n].mesh == kNone)
            continue;
        bool skinned = node.skin >= 0 && size_t(node.skin) < loaded.skins.size();
        if (skinned && !meshHasInfluences(model, node.mesh)) {
            warnings.add(nodeLabel(model, source) + " is skinned but " + meshLabel(model, size_t(node.mesh)) +
                         " has no JOINTS_0 / WEIGHTS_0 on every primitive: skin not supported there, bind pose used");
            skinned = false;
        }
        if (!skinned && meshMorphTargets(model, node.mesh) == 0)
            continue;
        Deformer d;
        d.node = uint32_t(n);
        if (skinned) {
            auto [it, fresh] = skinIndex.emplace(node.skin, int32_t(scene.skins.size()));
            if (fresh)
                scene.skins.push_back(gltf::convertSkin(loaded, size_t(node.skin), order.newIndex, file));
            d.skin = it->second;
        }
        d.weights = defaultWeights(model, source, scene.vertices.deform.morphTargets);
        scene.deformers.push_back(std::move(d));
    }
    isolateDeformedMeshes(scene, file);
    assignDeformerVertices(scene);
    checkJointIndices(scene, file);
}

// Step 7: rigid node animation (animations left without a channel are dropped).
void importAnimations(const gltf::LoadedGltf& loaded, const NodeOrder& order, const std::string& file,
                      Warnings& warnings, const Log& log, Scene& scene)
{
    const tinygltf::Model& model = loaded.model;
    for (size_t a = 0; a < model.animations.size(); ++a) {
        const tinygltf::Animation& anim = model.animations[a];
        Animation out;
        out.name = anim.name.empty() ? "animation " + std::to_string(a) : anim.name;
        const std::string label = named("animations[" + std::to_string(a) + "]", anim.name);
        for (size_t c = 0; c < anim.channels.size(); ++c)
            for (AnimationChannel& channel :
                 convertChannel(loaded, anim, anim.channels[c], label, c, order, file, warnings, log))
                out.channels.push_back(std::move(channel));
        if (!out.channels.empty())
            scene.animations.push_back(std::move(out));
    }
}

// Step 8: texture list parallel to the sources (sizes are filled by the driver).
void addTextures(TextureTable& textures, ImportedScene& result)
{
    result.textureSources = std::move(textures.sources());
    for (const TextureSource& source : result.textureSources) {
        Texture texture;
        texture.name = source.name;
        texture.srgb = source.srgb;
        result.scene.textures.push_back(std::move(texture));
    }
}

// The one-line "import: N meshes, ..." summary.
void logImportSummary(const Scene& scene, const Log& log)
{
    size_t channels = 0;
    for (const Animation& a : scene.animations)
        channels += a.channels.size();
    log.info("import: " + std::to_string(scene.meshes.size()) + " meshes, " + std::to_string(scene.primitives.size()) +
             " primitives, " + std::to_string(scene.triangleCount()) + " triangles, " +
             std::to_string(scene.vertices.size()) + " vertices, " + std::to_string(scene.textures.size()) +
             " textures, " + std::to_string(scene.nodes.size()) + " nodes, " + std::to_string(channels) +
             " animation channels");
}

// Steps 1-8 of the import into result (warnings held in `warnings`).
void importInto(const std::filesystem::path& path, const std::string& file, const Log& log, unsigned threads,
                Warnings& warnings, ImportedScene& result)
{
    Scene& scene = result.scene;
    // Step 1: load and check the whole document (no image decoding); its warnings first.
    std::vector<gltf::SchemaIssue> issues;
    const gltf::LoadedGltf loaded = gltf::loadGltf(path, file, issues, threads);
    result.filesRead.push_back(path);
    result.filesRead.insert(result.filesRead.end(), loaded.bufferFiles.begin(), loaded.bufferFiles.end());
    for (const gltf::SchemaIssue& issue : issues)
        warnings.add(issue.text());
    const tinygltf::Model& model = loaded.model;
    checkExtensions(model, warnings);

    const NodeOrder order = orderNodes(model, file);
    const MeshSelection meshes = selectMeshes(model, order, file);

    // Step 3: materials used by triangle primitives of those meshes, and their textures.
    std::vector<int32_t> materialIndex = usedMaterials(model, meshes.meshSources, file);
    TextureTable textures(loaded, path, file, warnings);
    convertMaterials(model, materialIndex, textures, file, scene);

    StreamNeeds needs = streamNeeds(scene.materials);
    deformationNeeds(loaded, order, meshes.meshSources, needs);
    // Step 5: geometry, one lfd::Mesh per instanced glTF mesh, primitives contiguous.
    for (size_t m : meshes.meshSources)
        importMesh(loaded, m, materialIndex, needs, file, warnings, scene);
    if (scene.indices.empty())
        fail(file, "contains no triangles to import");

    importNodes(model, order, meshes.meshIndex, file, scene);
    importLights(model, order, file, warnings, scene);
    importDeformers(loaded, order, file, warnings, scene);
    importAnimations(loaded, order, file, warnings, log, scene);
    addTextures(textures, result);
    scene.triangleStats.clear();
    result.sourceTriangles = scene.triangleCount();
}

} // namespace

ImportedScene importGltf(const std::filesystem::path& path, const Log& log, unsigned threads)
{
    const std::string file = path.string();
    ImportedScene result;
    Scene& scene = result.scene;
    Warnings warnings(log, result.warnings);

    try {
        importInto(path, file, log, threads, warnings, result);
    } catch (const BakeError&) {
        // The warnings found before the error are reported with it - after it under
        // --strict, where reporting a warning refuses the input, so the error stays the
        // one named.
        try {
            warnings.flush();
        } catch (const BakeError&) {
        }
        throw;
    }
    warnings.flush();
    logImportSummary(scene, log);
    return result;
}

} // namespace lfd::bake
