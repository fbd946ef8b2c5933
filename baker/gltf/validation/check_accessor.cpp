// Accessors (glTF 2.0 sections 3.6.2, 5.1): the JSON of an accessor and its sparse
// storage; its element stride, alignment, bounds within its buffer view and sparse indices.
// (What the data of an accessor must hold for its use: check_mesh.cpp, check_animation.cpp.)
#include "validation/checks.h"
#include "validation/model_context.h"

#include <algorithm>
#include <array>
#include <cstring>

namespace lfd::bake::gltf {
namespace {

// glTF 2.0 section 3.6.2.2 "Accessor Data Types".
int componentCount(const std::string& type)
{
    static const std::array<std::pair<const char*, int>, 7> kTypes = {
        {{"SCALAR", 1}, {"VEC2", 2}, {"VEC3", 3}, {"VEC4", 4}, {"MAT2", 4}, {"MAT3", 9}, {"MAT4", 16}}};
    for (const auto& [name, n] : kTypes)
        if (type == name)
            return n;
    return 0;
}

void sparseSchema(ValidationContext& ctx, const json& s, const std::string& path, const json& accessor)
{
    if (auto count = ctx.integer(s, "count", path, kRead, true, 1)) {
        const json* total = member(accessor, "count");
        if (total != nullptr && total->is_number() && double(*count) > total->get<double>())
            ctx.report(IssueCode::ACCESSOR_SPARSE_COUNT_OUT_OF_RANGE, at(path, "count"),
                       std::to_string(*count) + " exceeds the accessor count " + describe(*total));
    }
    if (const json* indices = ctx.object(s, "indices", path, kRead, true)) {
        const std::string p = at(path, "indices");
        ctx.indexMember(*indices, "bufferView", p, "bufferViews", kRead, true);
        ctx.integer(*indices, "byteOffset", p, kRead, false, 0);
        ctx.enumInteger(*indices, "componentType", p, {5121, 5123, 5125}, kRead, true);
        ctx.common(*indices, p);
    }
    if (const json* values = ctx.object(s, "values", path, kRead, true)) {
        const std::string p = at(path, "values");
        ctx.indexMember(*values, "bufferView", p, "bufferViews", kRead, true);
        ctx.integer(*values, "byteOffset", p, kRead, false, 0);
        ctx.common(*values, p);
    }
    ctx.common(s, path);
}

// Section 3.6.2.4 "Data Alignment": the accessor's offset, and its offset within the
// buffer, are multiples of the component size; a matrix's are multiples of 4.
void alignment(ModelContext& mc, int a)
{
    const tinygltf::Accessor& acc = mc.model.accessors[size_t(a)];
    if (!mc.hadBufferView(a) || size_t(acc.bufferView) >= mc.model.bufferViews.size())
        return;
    const bool matrix =
        acc.type == TINYGLTF_TYPE_MAT2 || acc.type == TINYGLTF_TYPE_MAT3 || acc.type == TINYGLTF_TYPE_MAT4;
    const size_t component = componentBytes(acc.componentType);
    const size_t align = matrix ? 4 : component;
    const size_t total = mc.model.bufferViews[size_t(acc.bufferView)].byteOffset + acc.byteOffset;
    if (acc.byteOffset % align != 0)
        mc.report(IssueCode::ACCESSOR_OFFSET_ALIGNMENT, at(accessorPath(a), "byteOffset"),
                  std::to_string(acc.byteOffset) + " is not a multiple of " + std::to_string(align) +
                      (matrix ? " (matrix data is 4-byte aligned)" : " (the component size)") + mc.unusable(a),
                  mc.use(a));
    else if (total % component != 0)
        mc.report(IssueCode::ACCESSOR_TOTAL_OFFSET_ALIGNMENT, accessorPath(a),
                  "starts at byte " + std::to_string(total) + " of its buffer (" + viewPath(acc.bufferView) +
                      ".byteOffset + byteOffset), not a multiple of the component size " + std::to_string(component) +
                      mc.unusable(a),
                  mc.use(a));
}

// Section 3.6.2.3: sparse indices strictly increasing, each below the count.
void sparseIndices(ModelContext& mc, int a)
{
    const tinygltf::Accessor& acc = mc.model.accessors[size_t(a)];
    const auto& s = acc.sparse.indices;
    if (!mc.validView(s.bufferView))
        return;
    const tinygltf::BufferView& view = mc.model.bufferViews[size_t(s.bufferView)];
    if (view.buffer < 0 || size_t(view.buffer) >= mc.model.buffers.size())
        return;
    const std::vector<unsigned char>& bytes = mc.model.buffers[size_t(view.buffer)].data;
    const size_t size = componentBytes(s.componentType);
    const size_t base = view.byteOffset + size_t(std::max(s.byteOffset, 0));
    uint32_t previous = 0;
    for (size_t k = 0; k < size_t(std::max(acc.sparse.count, 0)); ++k) {
        if (base + (k + 1) * size > bytes.size())
            return;
        uint32_t v = 0;
        std::memcpy(&v, bytes.data() + base + k * size, size);
        if (v >= acc.count) {
            mc.report(IssueCode::ACCESSOR_SPARSE_INDEX_OOB, at(accessorPath(a), "sparse.indices"),
                      "element " + std::to_string(k) + " is " + std::to_string(v) + ", not below the count " +
                          std::to_string(acc.count));
            return;
        }
        if (k > 0 && v <= previous) {
            mc.report(IssueCode::ACCESSOR_SPARSE_INDICES_NON_INCREASING, at(accessorPath(a), "sparse.indices"),
                      "element " + std::to_string(k) + " (" + std::to_string(v) + ") does not increase strictly");
            return;
        }
        previous = v;
    }
}

} // namespace

void checkAccessorSchema(ValidationContext& ctx, const json& a, const std::string& path)
{
    ctx.indexMember(a, "bufferView", path, "bufferViews", kRead);
    const std::optional<int64_t> offset = ctx.integer(a, "byteOffset", path, kRead, false, 0);
    // An enum value the baker cannot interpret in an accessor a mesh or an animation reads
    // refuses the file; in any other (which nothing reads) it is a warning, as
    // glTF-Validator reports unknown enum values.
    const size_t index = size_t(std::stoul(path.substr(path.find('[') + 1)));
    const Use use = ctx.usedAccessors().count(int64_t(index)) ? kRead : kIgnored;
    const std::optional<int64_t> componentType =
        ctx.enumInteger(a, "componentType", path, {5120, 5121, 5122, 5123, 5125, 5126}, use, true);
    ctx.integer(a, "count", path, kRead, true, 1);
    const std::optional<std::string> type =
        ctx.enumString(a, "type", path, {"SCALAR", "VEC2", "VEC3", "VEC4", "MAT2", "MAT3", "MAT4"}, use, true,
                       use == kIgnored ? ": nothing reads the accessor" : "");
    if (const json* normalized = ctx.boolean(a, "normalized", path, kRead);
        normalized != nullptr && normalized->get<bool>() && componentType &&
        (*componentType == 5125 || *componentType == 5126))
        // Section 5.1.6 "accessor.normalized": MUST NOT be true for FLOAT or UNSIGNED_INT.
        ctx.report(IssueCode::ACCESSOR_NORMALIZED_INVALID, at(path, "normalized"),
                   "must not be true for componentType " + std::to_string(*componentType));
    // Section 5.1.2 "accessor.byteOffset": "MUST NOT be defined when bufferView is
    // undefined". (Its alignment: the semantic phase, with the buffer view's offset.)
    if (offset && !member(a, "bufferView"))
        ctx.report(IssueCode::ACCESSOR_OFFSET_WITHOUT_BUFFER_VIEW, at(path, "byteOffset"), "given without bufferView");
    const size_t components = type ? size_t(componentCount(*type)) : 0;
    for (const char* bound : {"min", "max"})
        ctx.numbers(a, bound, path, components, kIgnored);
    if (const json* sparse = ctx.object(a, "sparse", path, kRead))
        sparseSchema(ctx, *sparse, at(path, "sparse"), a);
    ctx.common(a, path);
}

void checkAccessorSemantics(ModelContext& mc)
{
    for (size_t a = 0; a < mc.model.accessors.size() && a < mc.documentAccessorCount(); ++a) {
        const tinygltf::Accessor& acc = mc.model.accessors[a];
        const std::string path = accessorPath(int(a));
        if (const size_t stride = mc.viewStride(int(a)); stride != 0 && stride < elementBytes(acc))
            mc.report(IssueCode::ACCESSOR_ELEMENT_LONGER_THAN_STRIDE, path,
                      "element of " + std::to_string(elementBytes(acc)) + " bytes is longer than " +
                          viewPath(acc.bufferView) + ".byteStride " + std::to_string(stride) + mc.unusable(int(a)),
                      mc.use(int(a)));
        alignment(mc, int(a));
        mc.fits(int(a));
        if (acc.sparse.isSparse && mc.fits(int(a)) && mc.hasData(int(a)))
            sparseIndices(mc, int(a));
    }
}

} // namespace lfd::bake::gltf

std::set<int64_t> lfd::bake::gltf::accessorsReadByMeshesAndAnimations(const nlohmann::json& document)
{
    std::set<int64_t> used;
    auto add = [&](const json& v) {
        if (v.is_number_integer() || v.is_number_unsigned())
            used.insert(v.get<int64_t>());
    };
    auto list = [&](const char* key) -> const json& {
        static const json empty = json::array();
        const json* v = member(document, key);
        return v != nullptr && v->is_array() ? *v : empty;
    };
    for (const json& m : list("meshes"))
        if (const json* prims = member(m, "primitives"); prims && prims->is_array())
            for (const json& p : *prims) {
                if (!p.is_object())
                    continue;
                for (const char* key : {"attributes", "indices"})
                    if (const json* v = member(p, key))
                        for (const json& a : v->is_object() ? *v : json::array({*v}))
                            add(a);
                if (const json* targets = member(p, "targets"); targets && targets->is_array())
                    for (const json& t : *targets)
                        if (t.is_object())
                            for (const auto& [name, a] : t.items())
                                add(a);
            }
    for (const json& anim : list("animations"))
        if (const json* samplers = member(anim, "samplers"); samplers && samplers->is_array())
            for (const json& smp : *samplers)
                for (const char* key : {"input", "output"})
                    if (const json* v = member(smp, key))
                        add(*v);
    return used;
}
