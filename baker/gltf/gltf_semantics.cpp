// glTF 2.0 semantic and data checks (see gltf_semantics.h). Section numbers are those of
// the glTF 2.0 specification; "MUST" rules are errors.
#include "gltf_semantics.h"

#include "bake_log.h"
#include "gltf_accessors.h"
#include "gltf_material_extensions.h"
#include "gltf_resources.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <optional>
#include <set>

namespace lfd::bake::gltf {
namespace {

using json = nlohmann::json;
using Severity = SchemaIssue::Severity;

std::string at(const std::string& path, const std::string& key) { return path + "." + key; }
std::string at(const std::string& path, size_t i) { return path + "[" + std::to_string(i) + "]"; }
std::string accessorPath(int a) { return "accessors[" + std::to_string(a) + "]"; }
std::string viewPath(int v) { return "bufferViews[" + std::to_string(v) + "]"; }

// Bytes of one component; 1 for an invalid componentType (reported by the schema check),
// so alignment arithmetic never divides by zero.
size_t componentBytes(int componentType) { return size_t(std::max(componentSize(componentType), 1)); }

// Bytes of one element (section 3.6.2.4: each matrix column starts on a 4-byte boundary).
size_t elementBytes(const tinygltf::Accessor& a)
{
    const size_t c = componentBytes(a.componentType);
    switch (a.type) {
    case TINYGLTF_TYPE_MAT2: return 2 * ((2 * c + 3) / 4 * 4);
    case TINYGLTF_TYPE_MAT3: return 3 * ((3 * c + 3) / 4 * 4);
    case TINYGLTF_TYPE_MAT4: return 16 * c;
    case TINYGLTF_TYPE_VEC2: return 2 * c;
    case TINYGLTF_TYPE_VEC3: return 3 * c;
    case TINYGLTF_TYPE_VEC4: return 4 * c;
    default: return c;
    }
}

// Bytes the last element of an accessor occupies: a matrix's last column ends after its
// components, without the padding to the next column.
size_t lastElementBytes(const tinygltf::Accessor& a)
{
    const size_t c = componentBytes(a.componentType);
    const size_t n = a.type == TINYGLTF_TYPE_MAT2 ? 2 : a.type == TINYGLTF_TYPE_MAT3 ? 3 : 0;
    return n > 0 ? (n - 1) * ((n * c + 3) / 4 * 4) + n * c : elementBytes(a);
}

// An accessor format: its type, and the component types (with `normalized`) allowed.
struct Format {
    int type;
    std::vector<std::pair<int, bool>> components; // (componentType, normalized)
};

std::string describe(const Format& f)
{
    std::string out;
    for (const auto& [c, n] : f.components)
        out += (out.empty() ? "" : ", ") + typeName(f.type) + "/" + componentName(c) + (n ? " normalized" : "");
    return out;
}

constexpr int kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT;
constexpr int kByte = TINYGLTF_COMPONENT_TYPE_BYTE, kUByte = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
constexpr int kShort = TINYGLTF_COMPONENT_TYPE_SHORT, kUShort = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
constexpr int kUInt = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;

// Section 3.7.2.1 "Overview", the table of attribute semantics.
std::optional<Format> attributeFormat(const std::string& name)
{
    const auto starts = [&](const char* prefix) { return name.rfind(prefix, 0) == 0; };
    if (name == "POSITION" || name == "NORMAL")
        return Format{TINYGLTF_TYPE_VEC3, {{kFloat, false}}};
    if (name == "TANGENT")
        return Format{TINYGLTF_TYPE_VEC4, {{kFloat, false}}};
    if (starts("TEXCOORD_"))
        return Format{TINYGLTF_TYPE_VEC2, {{kFloat, false}, {kUByte, true}, {kUShort, true}}};
    if (starts("COLOR_"))
        return std::nullopt; // VEC3 or VEC4: checked below
    if (starts("JOINTS_"))
        return Format{TINYGLTF_TYPE_VEC4, {{kUByte, false}, {kUShort, false}}};
    if (starts("WEIGHTS_"))
        return Format{TINYGLTF_TYPE_VEC4, {{kFloat, false}, {kUByte, true}, {kUShort, true}}};
    return std::nullopt;
}

bool matches(const tinygltf::Accessor& a, const Format& f)
{
    if (a.type != f.type)
        return false;
    for (const auto& [c, n] : f.components)
        if (a.componentType == c && a.normalized == n)
            return true;
    return false;
}

class Checker {
public:
    Checker(const tinygltf::Model& model, const json& document, const std::set<size_t>& withoutData,
            std::vector<SchemaIssue>& issues)
        : m_(model), doc_(document), withoutData_(withoutData), issues_(issues)
    {
        quantized_ = std::find(m_.extensionsUsed.begin(), m_.extensionsUsed.end(), "KHR_mesh_quantization") !=
                     m_.extensionsUsed.end();
        const json* accessors = member(doc_, "accessors");
        for (size_t a = 0; accessors && a < accessors->size(); ++a)
            originalView_.push_back((*accessors)[a].is_object() && (*accessors)[a].contains("bufferView"));
        for (int64_t a : accessorsReadByMeshesAndAnimations(doc_))
            used_.insert(int(a));
    }

    // Storage before its users, and the node forest before the scenes that list roots of
    // it: the first error reported is then the cause, not a consequence (an accessor that
    // overruns its view, not the attribute counts that differ because of it; a cycle, not
    // the scene root that is consequently a child).
    void run()
    {
        bufferViews();
        accessors();
        nodeHierarchy();
        scenes();
        nodes();
        meshes();
        animations();
        skins();
    }

private:
    // ---- Reporting and shared data -------------------------------------------------

    void report(Severity s, const std::string& path, const std::string& message)
    {
        issues_.push_back({s, path, message});
    }

    static const json* member(const json& o, const char* key)
    {
        if (!o.is_object())
            return nullptr;
        const auto it = o.find(key);
        return it == o.end() ? nullptr : &*it;
    }

    bool validAccessor(int a) const { return a >= 0 && size_t(a) < m_.accessors.size(); }
    // A storage defect of an accessor no mesh or animation reads leaves the file usable: a
    // warning. In one that is read, an error.
    Severity storageSeverity(int a) const { return used_.count(a) ? kError : kWarn; }
    std::string unusable(int a) const { return used_.count(a) ? "" : ": unusable (nothing reads it)"; }
    // The document's own accessors (not the zero views made for accessors without one).
    bool hadBufferView(int a) const { return size_t(a) < originalView_.size() && originalView_[size_t(a)]; }

    // Whether accessor a's elements lie inside its buffer view (checked once, reported once).
    bool fits(int a)
    {
        if (!validAccessor(a))
            return false;
        if (auto it = fits_.find(a); it != fits_.end())
            return it->second;
        const tinygltf::Accessor& acc = m_.accessors[size_t(a)];
        bool ok = true;
        // `last`: the bytes of the last element (a matrix's last column needs no padding).
        auto view = [&](int v, size_t offset, size_t count, size_t element, size_t stride, size_t last,
                        const std::string& what) {
            if (v < 0 || size_t(v) >= m_.bufferViews.size())
                return;
            const tinygltf::BufferView& bv = m_.bufferViews[size_t(v)];
            const size_t step = std::max(stride, element);
            if (count > 0 && (offset > bv.byteLength || last > bv.byteLength - offset ||
                              (count - 1) > (bv.byteLength - offset - last) / step)) {
                report(storageSeverity(a), what,
                       std::to_string(count) + " elements of " + std::to_string(element) + " bytes at byteOffset " +
                           std::to_string(offset) + (stride > element ? " and byteStride " + std::to_string(stride) : "") +
                           " do not fit " + viewPath(v) + " (" + std::to_string(bv.byteLength) + " bytes)" + unusable(a));
                ok = false;
            }
        };
        if (hadBufferView(a)) {
            const size_t stride = m_.bufferViews.size() > size_t(acc.bufferView)
                                      ? size_t(m_.bufferViews[size_t(acc.bufferView)].byteStride)
                                      : 0;
            view(acc.bufferView, acc.byteOffset, acc.count, elementBytes(acc), stride, lastElementBytes(acc),
                 accessorPath(a));
        }
        if (acc.sparse.isSparse) {
            const size_t n = size_t(std::max(acc.sparse.count, 0));
            const size_t index = componentBytes(acc.sparse.indices.componentType);
            view(acc.sparse.indices.bufferView, size_t(std::max(acc.sparse.indices.byteOffset, 0)), n, index, 0, index,
                 at(at(accessorPath(a), "sparse"), "indices"));
            view(acc.sparse.values.bufferView, size_t(std::max(acc.sparse.values.byteOffset, 0)), n, elementBytes(acc),
                 0, lastElementBytes(acc), at(at(accessorPath(a), "sparse"), "values"));
        }
        fits_[a] = ok;
        return ok;
    }

    // Whether the file holds the bytes accessor a reads (a buffer without a uri does not:
    // no data check then).
    bool hasData(int a) const
    {
        // Section 3.6.2.3: without a bufferView an accessor is zeros "unless sparse or an
        // extension" overrides them; without sparse data, what it holds is up to an extension.
        if (!hadBufferView(a) && !m_.accessors[size_t(a)].sparse.isSparse)
            return false;
        return bytesNotInFile(m_, withoutData_, a).empty();
    }

    // The accessor's float values (normalized integers decoded, sparse applied), or nullopt
    // when it does not fit (reported), has another type or its bytes are not in the file.
    // Read once for all the checks of one accessor (finite values, unit vectors).
    const std::optional<FloatArray>& floats(int a, int type)
    {
        const auto [it, fresh] = floats_.try_emplace({a, type});
        if (!fresh || !fits(a) || m_.accessors[size_t(a)].type != type || !hasData(a))
            return it->second;
        try {
            it->second = readFloatAccessor(m_, a, {type}, "", accessorPath(a));
        } catch (const BakeError& e) {
            report(kError, accessorPath(a), std::string(e.what()).substr(2));
        }
        return it->second;
    }

    // ---- Scenes and nodes (sections 3.5.1, 3.5.2) ------------------------------------

    void scenes()
    {
        // A scene lists root nodes only ("MUST be root nodes", section 3.5.1).
        std::map<int, size_t> parent;
        for (size_t n = 0; n < m_.nodes.size(); ++n)
            for (int c : m_.nodes[n].children)
                parent.emplace(c, n);
        for (size_t s = 0; s < m_.scenes.size(); ++s)
            for (size_t i = 0; i < m_.scenes[s].nodes.size(); ++i)
                if (auto it = parent.find(m_.scenes[s].nodes[i]); it != parent.end())
                    report(kError, at(at(at("scenes", s), "nodes"), i),
                           "node " + std::to_string(m_.scenes[s].nodes[i]) + " is not a root node (it is a child of nodes[" +
                               std::to_string(it->second) + "])");
    }

    // Section 3.5.2: the nodes form a forest - no node is the child of two nodes or its
    // own ancestor.
    void nodeHierarchy()
    {
        std::map<int, size_t> parent;
        for (size_t n = 0; n < m_.nodes.size(); ++n)
            for (size_t i = 0; i < m_.nodes[n].children.size(); ++i) {
                const int c = m_.nodes[n].children[i];
                if (c < 0 || size_t(c) >= m_.nodes.size())
                    continue;
                const auto [it, fresh] = parent.emplace(c, n);
                if (!fresh && it->second != n)
                    report(kError, at(at(at("nodes", n), "children"), i),
                           "node " + std::to_string(c) + " is already a child of nodes[" + std::to_string(it->second) + "]");
            }
        for (size_t n = 0; n < m_.nodes.size(); ++n) {
            // Walk up at most as many parents as there are nodes: longer means a cycle.
            int current = int(n);
            for (size_t steps = 0; steps <= m_.nodes.size(); ++steps) {
                const auto it = parent.find(current);
                if (it == parent.end())
                    break;
                current = int(it->second);
                if (current == int(n)) {
                    report(kError, at("nodes", n), "is its own ancestor (the children form a cycle)");
                    break;
                }
            }
        }
    }

    size_t morphTargets(int mesh) const
    {
        if (mesh < 0 || size_t(mesh) >= m_.meshes.size() || m_.meshes[size_t(mesh)].primitives.empty())
            return 0;
        return m_.meshes[size_t(mesh)].primitives[0].targets.size();
    }

    void nodes()
    {
        for (size_t n = 0; n < m_.nodes.size(); ++n) {
            const tinygltf::Node& node = m_.nodes[n];
            const std::string path = at("nodes", n);
            // Section 3.5.2: "a matrix or any combination of TRS, not both".
            // (Matrix and TRS together: the schema check; tinygltf keeps only the matrix.)
            if (node.matrix.size() == 16)
                decomposable(node.matrix, at(path, "matrix"));
            // Section 3.7.2.2: node weights override the mesh's, one per morph target.
            if (!node.weights.empty() && node.weights.size() != morphTargets(node.mesh))
                report(kError, at(path, "weights"), std::to_string(node.weights.size()) + " weights, but meshes[" +
                                                        std::to_string(node.mesh) + "] has " +
                                                        std::to_string(morphTargets(node.mesh)) + " morph targets");
        }
    }

    // Section 3.5.3: "matrix MUST be decomposable to TRS": an affine matrix (last row
    // 0 0 0 1) whose 3x3 part is a rotation times a positive scale - orthogonal columns.
    void decomposable(const std::vector<double>& m, const std::string& path)
    {
        // Column-major: column c is m[4c..4c+3].
        const bool affine = std::abs(m[3]) < 1e-6 && std::abs(m[7]) < 1e-6 && std::abs(m[11]) < 1e-6 &&
                            std::abs(m[15] - 1.0) < 1e-6;
        double len[3];
        for (int c = 0; c < 3; ++c)
            len[c] = std::sqrt(m[4 * c] * m[4 * c] + m[4 * c + 1] * m[4 * c + 1] + m[4 * c + 2] * m[4 * c + 2]);
        // A zero column is a zero scale (valid: it hides the node); others are orthogonal.
        bool orthogonal = std::isfinite(len[0] + len[1] + len[2]);
        for (int a = 0; orthogonal && a < 3; ++a)
            for (int b = a + 1; b < 3 && len[a] > 0; ++b) {
                const double dot = m[4 * a] * m[4 * b] + m[4 * a + 1] * m[4 * b + 1] + m[4 * a + 2] * m[4 * b + 2];
                if (std::abs(dot) > 1e-4 * len[a] * len[b])
                    orthogonal = false;
            }
        if (!affine || !orthogonal)
            report(kError, path, affine ? "has shear: not decomposable into translation, rotation and scale"
                                        : "has a projective last row (expected 0, 0, 0, 1): not decomposable into "
                                          "translation, rotation and scale");
    }

    // ---- Meshes (section 3.7) -----------------------------------------------------

    void meshes()
    {
        for (size_t m = 0; m < m_.meshes.size(); ++m) {
            const tinygltf::Mesh& mesh = m_.meshes[m];
            const std::string path = at("meshes", m);
            const size_t targets = morphTargets(int(m));
            if (!mesh.weights.empty() && mesh.weights.size() != targets)
                report(kError, at(path, "weights"), std::to_string(mesh.weights.size()) + " weights, but " +
                                                        std::to_string(targets) + " morph targets");
            for (size_t p = 0; p < mesh.primitives.size(); ++p) {
                const std::string pp = at(at(path, "primitives"), p);
                if (mesh.primitives[p].targets.size() != targets)
                    report(kError, at(pp, "targets"), std::to_string(mesh.primitives[p].targets.size()) +
                                                          " morph targets, but primitives[0] has " + std::to_string(targets) +
                                                          " (all primitives of a mesh must have the same number)");
                primitive(mesh.primitives[p], pp);
            }
        }
        sharedVertexViews();
    }

    void primitive(const tinygltf::Primitive& prim, const std::string& path)
    {
        // Step 1: each attribute's format and count (section 3.7.2.1).
        size_t vertexCount = 0;
        bool counted = false;
        for (const auto& [name, a] : prim.attributes) {
            const std::string ap = at(at(path, "attributes"), name);
            if (!validAccessor(a))
                continue; // reported by the schema check
            const tinygltf::Accessor& acc = m_.accessors[size_t(a)];
            attributeUse(a, ap);
            if (!quantized_) {
                std::optional<Format> f = attributeFormat(name);
                if (name.rfind("COLOR_", 0) == 0) {
                    const std::vector<std::pair<int, bool>> colour = {{kFloat, false}, {kUByte, true}, {kUShort, true}};
                    if (!matches(acc, {TINYGLTF_TYPE_VEC3, colour}) && !matches(acc, {TINYGLTF_TYPE_VEC4, colour}))
                        report(kError, ap, "accessors[" + std::to_string(a) + "] is " + typeName(acc.type) + "/" +
                                               componentName(acc.componentType) +
                                               ", not VEC3 or VEC4 of FLOAT, normalized UNSIGNED_BYTE or UNSIGNED_SHORT");
                } else if (f && !matches(acc, *f)) {
                    report(kError, ap, "accessors[" + std::to_string(a) + "] is " + typeName(acc.type) + "/" +
                                           componentName(acc.componentType) + (acc.normalized ? " normalized" : "") +
                                           ", not " + describe(*f));
                }
            }
            if (!counted) {
                vertexCount = acc.count;
                counted = true;
            } else if (acc.count != vertexCount) {
                report(kError, ap, "accessors[" + std::to_string(a) + "] has " + std::to_string(acc.count) +
                                       " elements, another attribute of the primitive " + std::to_string(vertexCount) +
                                       " (all must have the same count)");
            }
            if (name == "POSITION" || name == "NORMAL" || name == "TANGENT" || name.rfind("TEXCOORD_", 0) == 0)
                finite(a, acc.type, ap);
            if (name == "POSITION" && (acc.minValues.size() != 3 || acc.maxValues.size() != 3))
                report(kError, accessorPath(a), "is a POSITION accessor (" + ap + ") without min and max (both required)");
            if (name == "NORMAL")
                unitVectors(a, TINYGLTF_TYPE_VEC3, ap);
            if (name == "TANGENT")
                unitVectors(a, TINYGLTF_TYPE_VEC4, ap);
        }
        // Morph targets: the same attributes as the base, as many elements.
        for (size_t t = 0; t < prim.targets.size(); ++t)
            for (const auto& [name, a] : prim.targets[t]) {
                const std::string tp = at(at(at(path, "targets"), t), name);
                if (!validAccessor(a))
                    continue;
                if (name == "POSITION" && (m_.accessors[size_t(a)].minValues.size() != 3 ||
                                           m_.accessors[size_t(a)].maxValues.size() != 3))
                    report(kError, accessorPath(a), "is a morph target POSITION accessor (" + tp +
                                                        ") without min and max (both required)");
                if (!prim.attributes.count(name))
                    report(kError, tp, "morph target attribute without the same attribute in the primitive");
                else if (counted && m_.accessors[size_t(a)].count != vertexCount)
                    report(kError, tp, "accessors[" + std::to_string(a) + "] has " +
                                           std::to_string(m_.accessors[size_t(a)].count) + " elements, the primitive's attributes " +
                                           std::to_string(vertexCount));
            }
        // Step 2: the indices.
        if (prim.indices >= 0 && validAccessor(prim.indices))
            indices(prim.indices, at(path, "indices"), counted ? std::optional(vertexCount) : std::nullopt);
        // Step 3: what the baker does not read: skinning sets in pairs (warnings).
        size_t joints = 0, weights = 0;
        for (const auto& [name, a] : prim.attributes) {
            joints += name.rfind("JOINTS_", 0) == 0;
            weights += name.rfind("WEIGHTS_", 0) == 0;
            if (validAccessor(a) && !attributeFormat(name) && name.rfind("COLOR_", 0) != 0 &&
                m_.accessors[size_t(a)].componentType == kUInt)
                report(kWarn, at(at(path, "attributes"), name), "UNSIGNED_INT is not allowed for vertex attributes: ignored");
        }
        if (joints != weights)
            report(kWarn, at(path, "attributes"), std::to_string(joints) + " JOINTS_n but " + std::to_string(weights) +
                                                      " WEIGHTS_n attributes (an unpaired set is not read)");
        texCoords(prim, path);
    }

    // Section 3.9.2: a texture's texCoord n needs the primitive's TEXCOORD_n (a warning);
    // n is KHR_texture_transform's texCoord where the extension overrides it.
    void texCoords(const tinygltf::Primitive& prim, const std::string& path)
    {
        if (prim.material < 0 || size_t(prim.material) >= m_.materials.size())
            return;
        // "A mesh primitive MUST have the corresponding texture coordinate attributes for
        // the material to be applicable to it": the file is usable, the texture is not; the
        // baker samples it at uv (0, 0).
        for (const MaterialTextureInfo& info : materialTextureInfos(m_.materials[size_t(prim.material)]))
            if (info.index >= 0 && !prim.attributes.count("TEXCOORD_" + std::to_string(info.texCoord)))
                report(kWarn, at(path, "material"), "materials[" + std::to_string(prim.material) + "]." + info.path +
                                                        " uses TEXCOORD_" + std::to_string(info.texCoord) +
                                                        ", which the primitive does not have: uvs set to zero");
    }

    // A vertex attribute's data: aligned to 4 bytes (section 3.6.2.4, "MUST be aligned to
    // 4-byte boundaries"); its buffer view remembered for the shared-view check.
    void attributeUse(int a, const std::string& path)
    {
        const tinygltf::Accessor& acc = m_.accessors[size_t(a)];
        if (!hadBufferView(a) || size_t(acc.bufferView) >= m_.bufferViews.size())
            return;
        vertexViews_[acc.bufferView].insert(a);
        attributePaths_.emplace(a, path);
        const tinygltf::BufferView& view = m_.bufferViews[size_t(acc.bufferView)];
        targetUse(acc.bufferView, TINYGLTF_TARGET_ARRAY_BUFFER, path);
        if (acc.byteOffset % 4 != 0 && alignedOnce_.insert(a).second)
            report(kError, at(accessorPath(a), "byteOffset"),
                   std::to_string(acc.byteOffset) + " is not a multiple of 4, as vertex attribute data must be (" +
                       path + ")");
        if (view.byteStride % 4 != 0 && stridedOnce_.insert(acc.bufferView).second)
            report(kError, at(viewPath(acc.bufferView), "byteStride"),
                   std::to_string(view.byteStride) + " is not a multiple of 4, as vertex attribute data must be (" +
                       path + ")");
    }

    // A buffer view's target (the schema's enum: vertex or index data) matches its use:
    // vertex attributes from ARRAY_BUFFER views, indices from ELEMENT_ARRAY_BUFFER ones,
    // and no view serves both.
    void targetUse(int v, int target, const std::string& path)
    {
        const int declared = m_.bufferViews[size_t(v)].target;
        const auto [it, fresh] = viewUse_.emplace(v, std::make_pair(target, path));
        const char* name = target == TINYGLTF_TARGET_ARRAY_BUFFER ? "vertex attribute" : "index";
        if (declared != 0 && declared != target) {
            if (reportedTargets_.insert(v).second)
                report(kError, at(viewPath(v), "target"), std::to_string(declared) + " does not fit its use as " + name +
                                                              " data (" + path + ")");
        } else if (!fresh && it->second.first != target && reportedTargets_.insert(v).second) {
            report(kError, viewPath(v), std::string("is used as ") + name + " data (" + path + ") and by " +
                                            it->second.second + " for the other kind");
        }
    }

    // Section 3.6.2.4: "When two or more vertex attribute accessors use the same
    // bufferView, its byteStride MUST be defined".
    void sharedVertexViews()
    {
        for (const auto& [v, users] : vertexViews_)
            if (users.size() > 1 && m_.bufferViews[size_t(v)].byteStride == 0) {
                const int first = *users.begin(), second = *std::next(users.begin());
                report(kError, viewPath(v), "has no byteStride but holds " + std::to_string(users.size()) +
                                                " vertex attribute accessors: " + attributePaths_[first] + " (" +
                                                accessorPath(first) + ") and " + attributePaths_[second] + " (" +
                                                accessorPath(second) + ")" + (users.size() > 2 ? ", ..." : ""));
            }
    }

    void indices(int a, const std::string& path, std::optional<size_t> vertexCount)
    {
        const tinygltf::Accessor& acc = m_.accessors[size_t(a)];
        const std::string ap = accessorPath(a);
        // Section 3.7.2.1: SCALAR of UNSIGNED_BYTE / SHORT / INT, not normalized.
        if (acc.type != TINYGLTF_TYPE_SCALAR ||
            (acc.componentType != kUByte && acc.componentType != kUShort && acc.componentType != kUInt) || acc.normalized) {
            report(kError, path, ap + " is " + typeName(acc.type) + "/" + componentName(acc.componentType) +
                                     (acc.normalized ? " normalized" : "") +
                                     ", not SCALAR of UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
            return;
        }
        if (hadBufferView(a) && size_t(acc.bufferView) < m_.bufferViews.size())
            targetUse(acc.bufferView, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER, path);
        // Section 3.6.2.3 / bufferView: "byteStride MUST NOT be defined" for indices.
        if (hadBufferView(a) && size_t(acc.bufferView) < m_.bufferViews.size() &&
            m_.bufferViews[size_t(acc.bufferView)].byteStride != 0)
            report(kError, at(viewPath(acc.bufferView), "byteStride"),
                   "defined for the index data of " + path + " (" + ap + "), which must be tightly packed");
        if (!fits(a) || !hasData(a) || !checkedIndices_.insert(a).second)
            return;
        std::vector<uint32_t> values;
        try {
            values = readIndexAccessor(m_, a, "", ap);
        } catch (const BakeError&) {
            return; // the bounds were checked: only a malformed sparse part gets here (reported there)
        }
        // Section 3.7.2.1: "indices MUST NOT contain the maximum possible value for the
        // component type" (primitive restart); each index names an existing vertex.
        const uint32_t restart = acc.componentType == kUByte ? 0xFFu : acc.componentType == kUShort ? 0xFFFFu : 0xFFFFFFFFu;
        for (size_t i = 0; i < values.size(); ++i) {
            if (values[i] == restart) {
                report(kError, path, ap + " element " + std::to_string(i) + " is " + std::to_string(restart) +
                                         ", the primitive-restart value, which glTF index data must not contain");
                return;
            }
            if (vertexCount && values[i] >= *vertexCount) {
                report(kError, path, ap + " element " + std::to_string(i) + " is " + std::to_string(values[i]) +
                                         ", but the primitive has " + std::to_string(*vertexCount) + " vertices");
                return;
            }
        }
    }

    // Section 3.7.2.1: NORMAL "normalized", TANGENT xyz normalized with w = +-1. The
    // attribute table states this without a MUST, and the baker repairs it (renormalises;
    // replaces zero-length normals by the smooth normal of the adjacent triangles), so it is
    // a warning. The tolerance allows float rounding of a unit vector written in single
    // precision, and for normalized integers (KHR_mesh_quantization) the quantisation error
    // (unitTolerance). Non-finite values are left to finite(), which refuses them.
    void unitVectors(int a, int type, const std::string& path)
    {
        if (!checkedUnit_.insert(a).second)
            return;
        const std::optional<FloatArray>& v = floats(a, type);
        if (!v)
            return;
        const size_t c = size_t(v->components);
        const double tolerance = unitTolerance(m_.accessors[size_t(a)]);
        for (size_t e = 0; e < v->count; ++e) {
            const float* x = &v->values[e * c];
            const double length = std::sqrt(double(x[0]) * x[0] + double(x[1]) * x[1] + double(x[2]) * x[2]);
            if (!std::isfinite(length))
                return;
            if (!(std::abs(length - 1.0) <= tolerance)) {
                report(kWarn, accessorPath(a), "element " + std::to_string(e) + " has length " + json(length).dump() +
                                                    ", not 1 (" + path + " holds unit vectors): renormalised" +
                                                    (c == 3 ? ", zero-length ones replaced by smooth normals" : ""));
                return;
            }
            if (c == 4 && x[3] != 1.0f && x[3] != -1.0f) {
                report(kWarn, accessorPath(a), "element " + std::to_string(e) + " has w = " + json(x[3]).dump() +
                                                    ", not 1 or -1 (" + path + " handedness): its sign is used");
                return;
            }
        }
    }

    // How far from 1 the length of a stored unit vector may be without a warning. FLOAT:
    // single-precision rounding. Normalized BYTE or SHORT (KHR_mesh_quantization): each
    // component is rounded to the grid of the encoder's precision, so the length is off by
    // up to half a grid step times sqrt(3) - and encoders quantise to fewer bits than the
    // component holds (gltf-transform's `quantize` writes 10-bit normals into SHORT, the
    // extension's "Implementation Note" says quantized normals "are typically not exactly
    // unit length"). The bound is one step of the coarsest grid the extension stores, BYTE's
    // 1/127, which covers any encoder using 8 bits or more in either type; a length further
    // off is a wrong vector, not a rounded one.
    static double unitTolerance(const tinygltf::Accessor& acc)
    {
        return acc.componentType == kFloat || !acc.normalized ? 5e-4 : 1.0 / 127.0;
    }

    void finite(int a, int type, const std::string& path)
    {
        if (!checkedFinite_.insert(a).second)
            return;
        const std::optional<FloatArray>& v = floats(a, type);
        if (!v)
            return;
        for (size_t i = 0; i < v->values.size(); ++i)
            if (!std::isfinite(v->values[i])) {
                report(kError, accessorPath(a), "element " + std::to_string(i / size_t(v->components)) +
                                                     " is not finite (NaN or infinity) (" + path + ")");
                return;
            }
    }

    // ---- Accessors and buffer views (sections 3.6.2, 3.6.1) ------------------------

    void accessors()
    {
        for (size_t a = 0; a < m_.accessors.size() && a < originalView_.size(); ++a) {
            const tinygltf::Accessor& acc = m_.accessors[a];
            const std::string path = accessorPath(int(a));
            if (hadBufferView(int(a)) && size_t(acc.bufferView) < m_.bufferViews.size()) {
                const size_t stride = m_.bufferViews[size_t(acc.bufferView)].byteStride;
                if (stride != 0 && stride < elementBytes(acc))
                    report(storageSeverity(int(a)), path,
                           "element of " + std::to_string(elementBytes(acc)) + " bytes is longer than " +
                               viewPath(acc.bufferView) + ".byteStride " + std::to_string(stride) + unusable(int(a)));
            }
            alignment(int(a));
            fits(int(a));
            if (acc.sparse.isSparse && fits(int(a)) && hasData(int(a)))
                sparseIndices(int(a));
        }
    }

    // Section 3.6.2.4 "Data Alignment": the accessor's offset, and its offset within the
    // buffer, are multiples of the component size; a matrix's are multiples of 4.
    void alignment(int a)
    {
        const tinygltf::Accessor& acc = m_.accessors[size_t(a)];
        if (!hadBufferView(a) || size_t(acc.bufferView) >= m_.bufferViews.size())
            return;
        const bool matrix = acc.type == TINYGLTF_TYPE_MAT2 || acc.type == TINYGLTF_TYPE_MAT3 || acc.type == TINYGLTF_TYPE_MAT4;
        const size_t component = componentBytes(acc.componentType);
        const size_t align = matrix ? 4 : component;
        const size_t total = m_.bufferViews[size_t(acc.bufferView)].byteOffset + acc.byteOffset;
        if (acc.byteOffset % align != 0)
            report(storageSeverity(a), at(accessorPath(a), "byteOffset"),
                   std::to_string(acc.byteOffset) + " is not a multiple of " + std::to_string(align) +
                       (matrix ? " (matrix data is 4-byte aligned)" : " (the component size)") + unusable(a));
        else if (total % component != 0)
            report(storageSeverity(a), accessorPath(a),
                   "starts at byte " + std::to_string(total) + " of its buffer (" + viewPath(acc.bufferView) +
                       ".byteOffset + byteOffset), not a multiple of the component size " + std::to_string(component) +
                       unusable(a));
    }

    // Section 3.6.2.3: sparse indices strictly increasing, each below the count.
    void sparseIndices(int a)
    {
        const tinygltf::Accessor& acc = m_.accessors[size_t(a)];
        const auto& s = acc.sparse.indices;
        if (s.bufferView < 0 || size_t(s.bufferView) >= m_.bufferViews.size())
            return;
        const tinygltf::BufferView& view = m_.bufferViews[size_t(s.bufferView)];
        if (view.buffer < 0 || size_t(view.buffer) >= m_.buffers.size())
            return;
        const std::vector<unsigned char>& bytes = m_.buffers[size_t(view.buffer)].data;
        const size_t size = componentBytes(s.componentType);
        const size_t base = view.byteOffset + size_t(std::max(s.byteOffset, 0));
        uint32_t previous = 0;
        for (size_t k = 0; k < size_t(std::max(acc.sparse.count, 0)); ++k) {
            if (base + (k + 1) * size > bytes.size())
                return;
            uint32_t v = 0;
            std::memcpy(&v, bytes.data() + base + k * size, size);
            if (v >= acc.count) {
                report(kError, at(accessorPath(a), "sparse.indices"),
                       "element " + std::to_string(k) + " is " + std::to_string(v) + ", not below the count " +
                           std::to_string(acc.count));
                return;
            }
            if (k > 0 && v <= previous) {
                report(kError, at(accessorPath(a), "sparse.indices"),
                       "element " + std::to_string(k) + " (" + std::to_string(v) + ") does not increase strictly");
                return;
            }
            previous = v;
        }
    }

    void bufferViews()
    {
        const json* views = member(doc_, "bufferViews");
        const size_t count = views ? views->size() : 0;
        // The views a used accessor or a texture's image reads.
        std::set<int> read;
        for (int a : used_) {
            if (!validAccessor(a))
                continue;
            const tinygltf::Accessor& acc = m_.accessors[size_t(a)];
            read.insert(acc.bufferView);
            if (acc.sparse.isSparse) {
                read.insert(acc.sparse.indices.bufferView);
                read.insert(acc.sparse.values.bufferView);
            }
        }
        std::set<int> textureImages;
        for (const tinygltf::Texture& t : m_.textures)
            textureImages.insert(t.source);
        for (size_t i = 0; i < m_.images.size(); ++i) {
            const int v = m_.images[i].bufferView;
            if (textureImages.count(int(i)))
                read.insert(v);
            if (v >= 0 && size_t(v) < m_.bufferViews.size() && m_.bufferViews[size_t(v)].byteStride != 0)
                report(kError, at(at("images", i), "bufferView"),
                       viewPath(v) + " has a byteStride (image data must be one contiguous range)");
        }
        for (size_t v = 0; v < count && v < m_.bufferViews.size(); ++v) {
            const tinygltf::BufferView& view = m_.bufferViews[v];
            const std::string path = viewPath(int(v));
            if (view.byteStride != 0 && view.byteStride > view.byteLength)
                report(kError, at(path, "byteStride"),
                       std::to_string(view.byteStride) + " exceeds byteLength " + std::to_string(view.byteLength));
            // Section 3.6.1: the view lies inside its buffer. Reading it would fail; a view
            // nothing reads leaves the file usable.
            if (view.buffer >= 0 && size_t(view.buffer) < m_.buffers.size()) {
                const size_t length = m_.buffers[size_t(view.buffer)].data.size();
                if (view.byteOffset > length || view.byteLength > length - view.byteOffset)
                    report(read.count(int(v)) ? kError : kWarn, path,
                           "byteOffset " + std::to_string(view.byteOffset) + " + byteLength " +
                               std::to_string(view.byteLength) + " exceeds buffers[" + std::to_string(view.buffer) +
                               "].byteLength " + std::to_string(length) + (read.count(int(v)) ? "" : ": unusable"));
            }
        }
    }

    // ---- Animations (section 3.11) ----------------------------------------------------

    void animations()
    {
        for (size_t a = 0; a < m_.animations.size(); ++a) {
            const tinygltf::Animation& anim = m_.animations[a];
            const std::string path = at("animations", a);
            std::map<std::pair<int, std::string>, size_t> targets;
            for (size_t c = 0; c < anim.channels.size(); ++c) {
                const tinygltf::AnimationChannel& ch = anim.channels[c];
                const std::string cp = at(at(path, "channels"), c);
                if (ch.target_node < 0 || size_t(ch.target_node) >= m_.nodes.size())
                    continue;
                // "Within one animation, each target MUST NOT be used more than once."
                const auto [it, fresh] = targets.emplace(std::make_pair(ch.target_node, ch.target_path), c);
                if (!fresh)
                    report(kError, at(cp, "target"), "targets node " + std::to_string(ch.target_node) + " " +
                                                         ch.target_path + ", as channels[" + std::to_string(it->second) +
                                                         "] does");
                const tinygltf::Node& node = m_.nodes[size_t(ch.target_node)];
                const bool trs = ch.target_path == "translation" || ch.target_path == "rotation" || ch.target_path == "scale";
                // "When a node is targeted for animation ... it MUST NOT have a matrix".
                if (trs && node.matrix.size() == 16)
                    report(kError, at(at(cp, "target"), "node"),
                           "nodes[" + std::to_string(ch.target_node) + "] has a matrix, so its " + ch.target_path +
                               " cannot be animated");
                if (ch.target_path == "weights" && morphTargets(node.mesh) == 0)
                    report(kError, at(at(cp, "target"), "path"),
                           "weights animated, but nodes[" + std::to_string(ch.target_node) + "] has no morph targets");
                if (ch.sampler >= 0 && size_t(ch.sampler) < anim.samplers.size())
                    sampler(anim.samplers[size_t(ch.sampler)], at(at(path, "samplers"), size_t(ch.sampler)), ch.target_path,
                            morphTargets(node.mesh));
            }
        }
    }

    // ---- Skins (section 3.7.3; what the baker cannot pose: warnings) --------------------

    void skins()
    {
        std::map<int, int> parent;
        for (size_t n = 0; n < m_.nodes.size(); ++n)
            for (int c : m_.nodes[n].children)
                parent.emplace(c, int(n));
        auto root = [&](int n) {
            for (size_t steps = 0; steps <= m_.nodes.size() && parent.count(n); ++steps)
                n = parent[n];
            return n;
        };
        auto isAncestor = [&](int ancestor, int n) {
            for (size_t steps = 0; steps <= m_.nodes.size(); ++steps) {
                if (n == ancestor)
                    return true;
                if (!parent.count(n))
                    return false;
                n = parent[n];
            }
            return false;
        };
        for (size_t n = 0; n < m_.nodes.size(); ++n)
            if (m_.nodes[n].skin >= 0 && m_.nodes[n].mesh < 0)
                report(kWarn, at(at("nodes", n), "skin"), "given for a node without a mesh: ignored");
        const json* skins = member(doc_, "skins");
        for (size_t k = 0; skins && skins->is_array() && k < skins->size(); ++k) {
            const json& skin = (*skins)[k];
            const std::string path = at("skins", k);
            std::vector<int> joints;
            if (const json* j = member(skin, "joints"); j && j->is_array())
                for (const json& v : *j)
                    if (v.is_number_integer() && v.get<int64_t>() >= 0 && size_t(v.get<int64_t>()) < m_.nodes.size())
                        joints.push_back(int(v.get<int64_t>()));
            if (const json* ibm = member(skin, "inverseBindMatrices"); ibm && ibm->is_number_integer() && validAccessor(int(ibm->get<int64_t>()))) {
                const int a = int(ibm->get<int64_t>());
                const tinygltf::Accessor& acc = m_.accessors[size_t(a)];
                if (acc.type != TINYGLTF_TYPE_MAT4 || acc.componentType != kFloat)
                    report(kWarn, at(path, "inverseBindMatrices"), accessorPath(a) + " is " + typeName(acc.type) + "/" +
                                                                   componentName(acc.componentType) + ", not MAT4/FLOAT");
                if (acc.count < joints.size())
                    report(kWarn, at(path, "inverseBindMatrices"), accessorPath(a) + " has " + std::to_string(acc.count) +
                                                                   " matrices for " + std::to_string(joints.size()) + " joints");
                if (hadBufferView(a) && size_t(acc.bufferView) < m_.bufferViews.size() &&
                    m_.bufferViews[size_t(acc.bufferView)].byteStride != 0)
                    report(kWarn, at(path, "inverseBindMatrices"), accessorPath(a) + " lies in a buffer view with a byteStride");
            }
            if (joints.empty())
                continue;
            const int common = root(joints[0]);
            for (size_t i = 1; i < joints.size(); ++i)
                if (root(joints[i]) != common) {
                    report(kWarn, at(path, "joints"), "the joints do not share a common root");
                    break;
                }
            if (const json* s = member(skin, "skeleton"); s && s->is_number_integer())
                for (int j : joints)
                    if (!isAncestor(int(s->get<int64_t>()), j)) {
                        report(kWarn, at(path, "skeleton"), "is not an ancestor of every joint (nodes[" + std::to_string(j) + "])");
                        break;
                    }
        }
    }

    void sampler(const tinygltf::AnimationSampler& s, const std::string& path, const std::string& targetPath,
                 size_t morphs)
    {
        if (!checkedSamplers_.insert(path + "/" + targetPath).second || !validAccessor(s.input) || !validAccessor(s.output))
            return;
        const tinygltf::Accessor& input = m_.accessors[size_t(s.input)];
        const std::string ip = at(path, "input");
        // Animation data is tightly packed: its buffer views have no byteStride.
        for (const auto& [a, where] : {std::pair{s.input, ip}, std::pair{s.output, at(path, "output")}})
            if (hadBufferView(a) && size_t(m_.accessors[size_t(a)].bufferView) < m_.bufferViews.size() &&
                m_.bufferViews[size_t(m_.accessors[size_t(a)].bufferView)].byteStride != 0)
                report(kError, where, accessorPath(a) + " lies in " + viewPath(m_.accessors[size_t(a)].bufferView) +
                                          ", which has a byteStride (animation data must be tightly packed)");
        // Key times: FLOAT SCALAR with min and max, non-negative, strictly increasing.
        if (input.type != TINYGLTF_TYPE_SCALAR || input.componentType != kFloat || input.normalized) {
            report(kError, ip, accessorPath(s.input) + " is " + typeName(input.type) + "/" +
                                   componentName(input.componentType) + ", not SCALAR/FLOAT (key times)");
            return;
        }
        if (input.minValues.size() != 1 || input.maxValues.size() != 1)
            report(kError, accessorPath(s.input), "is animation input (" + ip + ") without min and max (both required)");
        if (const std::optional<FloatArray>& times = floats(s.input, TINYGLTF_TYPE_SCALAR)) {
            for (size_t k = 0; k < times->count; ++k) {
                const float t = times->values[k];
                if (!std::isfinite(t) || t < 0.0f) {
                    report(kError, accessorPath(s.input), "key time " + std::to_string(k) + " is " + json(t).dump() +
                                                               " (key times are finite and >= 0; " + ip + ")");
                    break;
                }
                if (k > 0 && !(t > times->values[k - 1])) {
                    report(kError, accessorPath(s.input), "key time " + std::to_string(k) + " (" + json(t).dump() +
                                                               ") does not increase strictly (" + ip + ")");
                    break;
                }
            }
        }
        // Values: as many as keys (three per key for cubic splines, at least two keys).
        const tinygltf::Accessor& output = m_.accessors[size_t(s.output)];
        const std::string op = at(path, "output");
        const bool cubic = s.interpolation == "CUBICSPLINE";
        const size_t perKey = (targetPath == "weights" ? std::max<size_t>(morphs, 1) : 1) * (cubic ? 3 : 1);
        if (cubic && input.count < 2)
            report(kError, ip, "CUBICSPLINE needs at least 2 keys, " + accessorPath(s.input) + " has " +
                                   std::to_string(input.count));
        if (output.count != input.count * perKey)
            report(kError, op, accessorPath(s.output) + " has " + std::to_string(output.count) + " elements, " +
                                   std::to_string(input.count * perKey) + " expected (" + std::to_string(input.count) +
                                   " keys" + (cubic ? ", 3 values per key" : "") + ")");
        const std::vector<std::pair<int, bool>> floatOnly = {{kFloat, false}};
        const std::vector<std::pair<int, bool>> quantized = {
            {kFloat, false}, {kByte, true}, {kUByte, true}, {kShort, true}, {kUShort, true}};
        std::optional<Format> format;
        if (targetPath == "translation" || targetPath == "scale")
            format = Format{TINYGLTF_TYPE_VEC3, floatOnly};
        else if (targetPath == "rotation")
            format = Format{TINYGLTF_TYPE_VEC4, quantized};
        else if (targetPath == "weights")
            format = Format{TINYGLTF_TYPE_SCALAR, quantized};
        if (format && !matches(output, *format))
            report(kError, op, accessorPath(s.output) + " is " + typeName(output.type) + "/" +
                                   componentName(output.componentType) + (output.normalized ? " normalized" : "") +
                                   ", not " + describe(*format) + " (" + targetPath + ")");
    }

    const tinygltf::Model& m_;
    const json& doc_;
    const std::set<size_t>& withoutData_;
    std::vector<SchemaIssue>& issues_;
    std::map<int, std::pair<int, std::string>> viewUse_; // buffer view -> (target of first use, its path)
    std::set<int> reportedTargets_;
    bool quantized_ = false;
    std::vector<bool> originalView_;
    std::map<int, bool> fits_;
    std::set<int> used_; // accessors a mesh or an animation reads
    std::map<std::pair<int, int>, std::optional<FloatArray>> floats_; // (accessor, type)
    std::map<int, std::set<int>> vertexViews_; // buffer view -> vertex attribute accessors in it
    std::map<int, std::string> attributePaths_; // vertex attribute accessor -> a path using it
    std::set<int> alignedOnce_, stridedOnce_, checkedIndices_, checkedUnit_, checkedFinite_;
    std::set<std::string> checkedSamplers_;
};

} // namespace

void validateGltfSemantics(const tinygltf::Model& model, const nlohmann::json& document,
                           const std::set<size_t>& buffersWithoutData, std::vector<SchemaIssue>& issues)
{
    Checker(model, document, buffersWithoutData, issues).run();
}

} // namespace lfd::bake::gltf
