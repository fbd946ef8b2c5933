// Meshes and their primitives (glTF 2.0 section 3.7): the JSON of a mesh, its primitives
// and KHR_draco_mesh_compression; the formats, counts and contents of the accessors a
// primitive reads, its morph targets, and the buffer views its vertex and index data lie in.
#include "validation/checks.h"
#include "validation/model_context.h"

#include "bake_log.h"
#include "gltf_material_extensions.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <set>

namespace lfd::bake::gltf {
namespace {

// ---- Schema phase -----------------------------------------------------------------------

// Attribute semantics of glTF 2.0 section 3.7.2.1 "Overview"; application-specific ones
// start with an underscore.
bool knownAttributeName(const std::string& name)
{
    if (name == "POSITION" || name == "NORMAL" || name == "TANGENT" || (!name.empty() && name[0] == '_'))
        return true;
    for (const char* prefix : {"TEXCOORD_", "COLOR_", "JOINTS_", "WEIGHTS_"}) {
        const size_t n = std::strlen(prefix);
        if (name.size() > n && name.compare(0, n, prefix) == 0 &&
            std::all_of(name.begin() + std::ptrdiff_t(n), name.end(), [](char c) { return c >= '0' && c <= '9'; }))
            return true;
    }
    return false;
}

// KHR_draco_mesh_compression (its README, "glTF Schema Updates"): the view holding the
// stream, and the stream's id of each attribute, "a subset of the attributes of the
// primitive". The baker decodes it whether or not the file also has the uncompressed data.
void dracoExtension(ValidationContext& ctx, const json& d, const std::string& path, const json& primitive)
{
    ctx.indexMember(d, "bufferView", path, "bufferViews", kRead, true);
    const json* attributes = ctx.object(d, "attributes", path, kRead, true);
    if (attributes == nullptr)
        return;
    const json* own = member(primitive, "attributes");
    for (const auto& [name, id] : attributes->items()) {
        const std::string ap = at(at(path, "attributes"), name);
        if (!isInteger(id) || id.get<double>() < 0 || id.get<double>() > double(INT32_MAX))
            ctx.report(IssueCode::TYPE_MISMATCH, ap,
                       "expected a Draco attribute id (an integer >= 0), got " + describe(id));
        else if (own == nullptr || !own->is_object() || !own->contains(name))
            ctx.report(IssueCode::DRACO_ATTRIBUTE_UNKNOWN, ap,
                       "names an attribute the primitive does not have (the extension's attributes are a "
                       "subset of the primitive's)");
    }
}

void primitiveSchema(ValidationContext& ctx, const json& p, const std::string& path)
{
    if (const json* attributes = ctx.object(p, "attributes", path, kRead, true))
        for (const auto& [name, value] : attributes->items()) {
            const std::string ap = at(at(path, "attributes"), name);
            ctx.index(value, ap, "accessors", kRead);
            if (!knownAttributeName(name))
                ctx.report(IssueCode::UNKNOWN_ATTRIBUTE_SEMANTIC, ap,
                           "unknown attribute semantic (application-specific ones start with '_'): ignored");
        }
    ctx.indexMember(p, "indices", path, "accessors", kRead);
    ctx.indexMember(p, "material", path, "materials", kRead);
    ctx.integer(p, "mode", path, kRead, false, 0, 6);
    if (const json* targets = ctx.array(p, "targets", path, kIgnored))
        for (size_t i = 0; i < targets->size(); ++i) {
            const json& t = (*targets)[i];
            const std::string tp = at(at(path, "targets"), i);
            if (!t.is_object()) {
                ctx.report(IssueCode::TYPE_MISMATCH, tp, "expected an object, got " + describe(t) + ": ignored",
                           kIgnored);
                continue;
            }
            for (const auto& [name, value] : t.items())
                ctx.index(value, at(tp, name), "accessors", kIgnored);
        }
    ctx.common(p, path);
    if (const json* ext = member(p, "extensions"); ext != nullptr && ext->is_object())
        if (const json* draco = ctx.object(*ext, "KHR_draco_mesh_compression", at(path, "extensions"), kRead))
            dracoExtension(ctx, *draco, at(at(path, "extensions"), "KHR_draco_mesh_compression"), p);
}

// ---- Semantic phase ---------------------------------------------------------------------

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
        return std::nullopt; // VEC3 or VEC4: checked in checkAttributeFormat
    if (starts("JOINTS_"))
        return Format{TINYGLTF_TYPE_VEC4, {{kUByte, false}, {kUShort, false}}};
    if (starts("WEIGHTS_"))
        return Format{TINYGLTF_TYPE_VEC4, {{kFloat, false}, {kUByte, true}, {kUShort, true}}};
    return std::nullopt;
}

// What the mesh checks remember across primitives: each vertex attribute and index
// accessor's data is checked once, and the buffer views' uses are compared.
struct MeshState {
    std::map<int, std::pair<int, std::string>> viewUse; // buffer view -> (target of first use, its path)
    std::set<int> reportedTargets;
    std::map<int, std::set<int>> vertexViews;  // buffer view -> vertex attribute accessors in it
    std::map<int, std::string> attributePaths; // vertex attribute accessor -> a path using it
    std::set<int> alignedOnce, stridedOnce, checkedIndices, checkedUnit, checkedFinite;
};

// A buffer view's target (the schema's enum: vertex or index data) matches its use:
// vertex attributes from ARRAY_BUFFER views, indices from ELEMENT_ARRAY_BUFFER ones,
// and no view serves both.
void targetUse(ModelContext& mc, MeshState& st, int v, int target, const std::string& path)
{
    const int declared = mc.model.bufferViews[size_t(v)].target;
    const auto [it, fresh] = st.viewUse.emplace(v, std::make_pair(target, path));
    const char* name = target == TINYGLTF_TARGET_ARRAY_BUFFER ? "vertex attribute" : "index";
    if (declared != 0 && declared != target) {
        if (st.reportedTargets.insert(v).second)
            mc.report(IssueCode::BUFFER_VIEW_TARGET_MISMATCH, at(viewPath(v), "target"),
                      std::to_string(declared) + " does not fit its use as " + name + " data (" + path + ")");
    } else if (!fresh && it->second.first != target && st.reportedTargets.insert(v).second) {
        mc.report(IssueCode::BUFFER_VIEW_TARGET_MISMATCH, viewPath(v),
                  std::string("is used as ") + name + " data (" + path + ") and by " + it->second.second +
                      " for the other kind");
    }
}

// A vertex attribute's data: aligned to 4 bytes (section 3.6.2.4, "MUST be aligned to
// 4-byte boundaries"); its buffer view remembered for the shared-view check.
void attributeUse(ModelContext& mc, MeshState& st, int a, const std::string& path)
{
    const tinygltf::Accessor& acc = mc.model.accessors[size_t(a)];
    if (!mc.hadBufferView(a) || size_t(acc.bufferView) >= mc.model.bufferViews.size())
        return;
    st.vertexViews[acc.bufferView].insert(a);
    st.attributePaths.emplace(a, path);
    const tinygltf::BufferView& view = mc.model.bufferViews[size_t(acc.bufferView)];
    targetUse(mc, st, acc.bufferView, TINYGLTF_TARGET_ARRAY_BUFFER, path);
    if (acc.byteOffset % 4 != 0 && st.alignedOnce.insert(a).second)
        mc.report(IssueCode::VERTEX_ATTRIBUTE_MISALIGNED, at(accessorPath(a), "byteOffset"),
                  std::to_string(acc.byteOffset) + " is not a multiple of 4, as vertex attribute data must be (" +
                      path + ")");
    if (view.byteStride % 4 != 0 && st.stridedOnce.insert(acc.bufferView).second)
        mc.report(IssueCode::VERTEX_ATTRIBUTE_MISALIGNED, at(viewPath(acc.bufferView), "byteStride"),
                  std::to_string(view.byteStride) + " is not a multiple of 4, as vertex attribute data must be (" +
                      path + ")");
}

// Section 3.6.2.4: "When two or more vertex attribute accessors use the same
// bufferView, its byteStride MUST be defined".
void sharedVertexViews(ModelContext& mc, MeshState& st)
{
    for (const auto& [v, users] : st.vertexViews)
        if (users.size() > 1 && mc.model.bufferViews[size_t(v)].byteStride == 0) {
            const int first = *users.begin(), second = *std::next(users.begin());
            mc.report(IssueCode::BUFFER_VIEW_SHARED_WITHOUT_STRIDE, viewPath(v),
                      "has no byteStride but holds " + std::to_string(users.size()) + " vertex attribute accessors: " +
                          st.attributePaths[first] + " (" + accessorPath(first) + ") and " + st.attributePaths[second] +
                          " (" + accessorPath(second) + ")" + (users.size() > 2 ? ", ..." : ""));
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
double unitTolerance(const tinygltf::Accessor& acc)
{
    return acc.componentType == kFloat || !acc.normalized ? 5e-4 : 1.0 / 127.0;
}

// Section 3.7.2.1: NORMAL "normalized", TANGENT xyz normalized with w = +-1. The
// attribute table states this without a MUST, and the baker repairs it (renormalises;
// replaces zero-length normals by the smooth normal of the adjacent triangles), so it is
// a warning. The tolerance allows float rounding of a unit vector written in single
// precision, and for normalized integers (KHR_mesh_quantization) the quantisation error
// (unitTolerance). Non-finite values are left to finite(), which refuses them.
void unitVectors(ModelContext& mc, MeshState& st, int a, int type, const std::string& path)
{
    if (!st.checkedUnit.insert(a).second)
        return;
    const std::optional<FloatArray>& v = mc.floats(a, type);
    if (!v)
        return;
    const size_t c = size_t(v->components);
    const double tolerance = unitTolerance(mc.model.accessors[size_t(a)]);
    for (size_t e = 0; e < v->count; ++e) {
        const float* x = &v->values[e * c];
        const double length = std::sqrt(double(x[0]) * x[0] + double(x[1]) * x[1] + double(x[2]) * x[2]);
        if (!std::isfinite(length))
            return;
        if (!(std::abs(length - 1.0) <= tolerance)) {
            mc.report(IssueCode::ACCESSOR_NON_UNIT, accessorPath(a),
                      "element " + std::to_string(e) + " has length " + json(length).dump() + ", not 1 (" + path +
                          " holds unit vectors): renormalised" +
                          (c == 3 ? ", zero-length ones replaced by smooth normals" : ""));
            return;
        }
        if (c == 4 && x[3] != 1.0f && x[3] != -1.0f) {
            mc.report(IssueCode::ACCESSOR_INVALID_SIGN, accessorPath(a),
                      "element " + std::to_string(e) + " has w = " + json(x[3]).dump() + ", not 1 or -1 (" + path +
                          " handedness): its sign is used");
            return;
        }
    }
}

void finite(ModelContext& mc, MeshState& st, int a, int type, const std::string& path)
{
    if (!st.checkedFinite.insert(a).second)
        return;
    const std::optional<FloatArray>& v = mc.floats(a, type);
    if (!v)
        return;
    for (size_t i = 0; i < v->values.size(); ++i)
        if (!std::isfinite(v->values[i])) {
            mc.report(IssueCode::ACCESSOR_NON_FINITE, accessorPath(a),
                      "element " + std::to_string(i / size_t(v->components)) + " is not finite (NaN or infinity) (" +
                          path + ")");
            return;
        }
}

// Section 3.7.2.1: "indices MUST NOT contain the maximum possible value for the
// component type" (primitive restart); each index names an existing vertex.
void indexValues(ModelContext& mc, int a, const std::string& path, std::optional<size_t> vertexCount)
{
    const tinygltf::Accessor& acc = mc.model.accessors[size_t(a)];
    const std::string ap = accessorPath(a);
    std::vector<uint32_t> values;
    try {
        values = readIndexAccessor(mc.model, a, "", ap);
    } catch (const BakeError&) {
        return; // the bounds were checked: only a malformed sparse part gets here (reported there)
    }
    const uint32_t restart = acc.componentType == kUByte ? 0xFFu : acc.componentType == kUShort ? 0xFFFFu : 0xFFFFFFFFu;
    for (size_t i = 0; i < values.size(); ++i) {
        if (values[i] == restart) {
            mc.report(IssueCode::ACCESSOR_INDEX_PRIMITIVE_RESTART, path,
                      ap + " element " + std::to_string(i) + " is " + std::to_string(restart) +
                          ", the primitive-restart value, which glTF index data must not contain");
            return;
        }
        if (vertexCount && values[i] >= *vertexCount) {
            mc.report(IssueCode::ACCESSOR_INDEX_OOB, path,
                      ap + " element " + std::to_string(i) + " is " + std::to_string(values[i]) +
                          ", but the primitive has " + std::to_string(*vertexCount) + " vertices");
            return;
        }
    }
}

void indices(ModelContext& mc, MeshState& st, int a, const std::string& path, std::optional<size_t> vertexCount)
{
    const tinygltf::Accessor& acc = mc.model.accessors[size_t(a)];
    // Section 3.7.2.1: SCALAR of UNSIGNED_BYTE / SHORT / INT, not normalized.
    if (acc.type != TINYGLTF_TYPE_SCALAR ||
        (acc.componentType != kUByte && acc.componentType != kUShort && acc.componentType != kUInt) || acc.normalized) {
        mc.report(IssueCode::ACCESSOR_WRONG_FORMAT, path,
                  formatOf(a, acc) + ", not SCALAR of UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
        return;
    }
    if (mc.hadBufferView(a) && size_t(acc.bufferView) < mc.model.bufferViews.size())
        targetUse(mc, st, acc.bufferView, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER, path);
    // Section 3.6.2.3 / bufferView: "byteStride MUST NOT be defined" for indices.
    if (mc.viewStride(a) != 0)
        mc.report(IssueCode::BUFFER_VIEW_STRIDE_ON_INDEX_DATA, at(viewPath(acc.bufferView), "byteStride"),
                  "defined for the index data of " + path + " (" + accessorPath(a) + "), which must be tightly packed");
    if (!mc.fits(a) || !mc.hasData(a) || !st.checkedIndices.insert(a).second)
        return;
    indexValues(mc, a, path, vertexCount);
}

// An attribute's format (section 3.7.2.1), unless KHR_mesh_quantization widens them.
void checkAttributeFormat(ModelContext& mc, const std::string& name, int a, const std::string& path)
{
    const tinygltf::Accessor& acc = mc.model.accessors[size_t(a)];
    if (mc.quantized)
        return;
    std::optional<Format> f = attributeFormat(name);
    if (name.rfind("COLOR_", 0) == 0) {
        const std::vector<std::pair<int, bool>> colour = {{kFloat, false}, {kUByte, true}, {kUShort, true}};
        if (!matches(acc, {TINYGLTF_TYPE_VEC3, colour}) && !matches(acc, {TINYGLTF_TYPE_VEC4, colour}))
            mc.report(IssueCode::ACCESSOR_WRONG_FORMAT, path,
                      formatOf(a, acc, false) + ", not VEC3 or VEC4 of FLOAT, normalized UNSIGNED_BYTE or UNSIGNED_SHORT");
    } else if (f && !matches(acc, *f)) {
        mc.report(IssueCode::ACCESSOR_WRONG_FORMAT, path, formatOf(a, acc) + ", not " + describe(*f));
    }
}

// Step 1 of a primitive: each attribute's format, count and contents. Returns the vertex
// count, if any attribute gives one.
std::optional<size_t> attributes(ModelContext& mc, MeshState& st, const tinygltf::Primitive& prim,
                                 const std::string& path)
{
    std::optional<size_t> vertexCount;
    for (const auto& [name, a] : prim.attributes) {
        const std::string ap = at(at(path, "attributes"), name);
        if (!mc.validAccessor(a))
            continue; // reported by the schema phase
        const tinygltf::Accessor& acc = mc.model.accessors[size_t(a)];
        attributeUse(mc, st, a, ap);
        checkAttributeFormat(mc, name, a, ap);
        if (!vertexCount)
            vertexCount = acc.count;
        else if (acc.count != *vertexCount)
            mc.report(IssueCode::MESH_PRIMITIVE_UNEQUAL_ACCESSOR_COUNT, ap,
                      accessorPath(a) + " has " + std::to_string(acc.count) + " elements, another attribute of the primitive " +
                          std::to_string(*vertexCount) + " (all must have the same count)");
        if (name == "POSITION" || name == "NORMAL" || name == "TANGENT" || name.rfind("TEXCOORD_", 0) == 0)
            finite(mc, st, a, acc.type, ap);
        if (name == "POSITION" && (acc.minValues.size() != 3 || acc.maxValues.size() != 3))
            mc.report(IssueCode::ACCESSOR_BOUNDS_MISSING, accessorPath(a),
                      "is a POSITION accessor (" + ap + ") without min and max (both required)");
        if (name == "NORMAL")
            unitVectors(mc, st, a, TINYGLTF_TYPE_VEC3, ap);
        if (name == "TANGENT")
            unitVectors(mc, st, a, TINYGLTF_TYPE_VEC4, ap);
    }
    return vertexCount;
}

// Morph targets: the same attributes as the base, as many elements (section 3.7.2.2).
void morphTargets(ModelContext& mc, const tinygltf::Primitive& prim, const std::string& path,
                  std::optional<size_t> vertexCount)
{
    for (size_t t = 0; t < prim.targets.size(); ++t)
        for (const auto& [name, a] : prim.targets[t]) {
            const std::string tp = at(at(at(path, "targets"), t), name);
            if (!mc.validAccessor(a))
                continue;
            const tinygltf::Accessor& acc = mc.model.accessors[size_t(a)];
            if (name == "POSITION" && (acc.minValues.size() != 3 || acc.maxValues.size() != 3))
                mc.report(IssueCode::ACCESSOR_BOUNDS_MISSING, accessorPath(a),
                          "is a morph target POSITION accessor (" + tp + ") without min and max (both required)");
            if (!prim.attributes.count(name))
                mc.report(IssueCode::MORPH_TARGET_ATTRIBUTE_UNKNOWN, tp,
                          "morph target attribute without the same attribute in the primitive");
            else if (vertexCount && acc.count != *vertexCount)
                mc.report(IssueCode::MESH_PRIMITIVE_UNEQUAL_ACCESSOR_COUNT, tp,
                          accessorPath(a) + " has " + std::to_string(acc.count) + " elements, the primitive's attributes " +
                              std::to_string(*vertexCount));
        }
}

// Step 3 of a primitive: what the baker does not read, skinning sets in pairs (warnings).
void skinningAttributes(ModelContext& mc, const tinygltf::Primitive& prim, const std::string& path)
{
    size_t joints = 0, weights = 0;
    for (const auto& [name, a] : prim.attributes) {
        joints += name.rfind("JOINTS_", 0) == 0;
        weights += name.rfind("WEIGHTS_", 0) == 0;
        if (mc.validAccessor(a) && !attributeFormat(name) && name.rfind("COLOR_", 0) != 0 &&
            mc.model.accessors[size_t(a)].componentType == kUInt)
            mc.report(IssueCode::VERTEX_ATTRIBUTE_UNSIGNED_INT, at(at(path, "attributes"), name),
                      "UNSIGNED_INT is not allowed for vertex attributes: ignored");
    }
    if (joints != weights)
        mc.report(IssueCode::SKINNING_ATTRIBUTES_UNPAIRED, at(path, "attributes"),
                  std::to_string(joints) + " JOINTS_n but " + std::to_string(weights) +
                      " WEIGHTS_n attributes (an unpaired set is not read)");
}

// Section 3.9.2: a texture's texCoord n needs the primitive's TEXCOORD_n (a warning);
// n is KHR_texture_transform's texCoord where the extension overrides it.
void texCoords(ModelContext& mc, const tinygltf::Primitive& prim, const std::string& path)
{
    if (prim.material < 0 || size_t(prim.material) >= mc.model.materials.size())
        return;
    // "A mesh primitive MUST have the corresponding texture coordinate attributes for
    // the material to be applicable to it": the file is usable, the texture is not; the
    // baker samples it at uv (0, 0).
    for (const MaterialTextureInfo& info : materialTextureInfos(mc.model.materials[size_t(prim.material)]))
        if (info.index >= 0 && !prim.attributes.count("TEXCOORD_" + std::to_string(info.texCoord)))
            mc.report(IssueCode::TEXCOORD_MISSING, at(path, "material"),
                      "materials[" + std::to_string(prim.material) + "]." + info.path + " uses TEXCOORD_" +
                          std::to_string(info.texCoord) + ", which the primitive does not have: uvs set to zero");
}

void primitiveSemantics(ModelContext& mc, MeshState& st, const tinygltf::Primitive& prim, const std::string& path)
{
    const std::optional<size_t> vertexCount = attributes(mc, st, prim, path);
    morphTargets(mc, prim, path, vertexCount);
    // Step 2: the indices.
    if (prim.indices >= 0 && mc.validAccessor(prim.indices))
        indices(mc, st, prim.indices, at(path, "indices"), vertexCount);
    skinningAttributes(mc, prim, path);
    texCoords(mc, prim, path);
}

} // namespace

void checkMeshSchema(ValidationContext& ctx, const json& m, const std::string& path)
{
    if (const json* prims = ctx.array(m, "primitives", path, kRead, true))
        ctx.forEachObject(*prims, at(path, "primitives"), kRead, "empty array: the mesh has no geometry",
                          [&](const json& p, const std::string& pp) { primitiveSchema(ctx, p, pp); });
    ctx.numbers(m, "weights", path, 0, kIgnored);
    ctx.common(m, path);
}

void checkMeshSemantics(ModelContext& mc)
{
    MeshState st;
    for (size_t m = 0; m < mc.model.meshes.size(); ++m) {
        const tinygltf::Mesh& mesh = mc.model.meshes[m];
        const std::string path = at("meshes", m);
        const size_t targets = mc.morphTargets(int(m));
        if (!mesh.weights.empty() && mesh.weights.size() != targets)
            mc.report(IssueCode::WEIGHTS_COUNT_MISMATCH, at(path, "weights"),
                      std::to_string(mesh.weights.size()) + " weights, but " + std::to_string(targets) +
                          " morph targets");
        for (size_t p = 0; p < mesh.primitives.size(); ++p) {
            const std::string pp = at(at(path, "primitives"), p);
            if (mesh.primitives[p].targets.size() != targets)
                mc.report(IssueCode::MESH_PRIMITIVES_UNEQUAL_TARGETS_COUNT, at(pp, "targets"),
                          std::to_string(mesh.primitives[p].targets.size()) + " morph targets, but primitives[0] has " +
                              std::to_string(targets) + " (all primitives of a mesh must have the same number)");
            primitiveSemantics(mc, st, mesh.primitives[p], pp);
        }
    }
    sharedVertexViews(mc, st);
}

} // namespace lfd::bake::gltf
