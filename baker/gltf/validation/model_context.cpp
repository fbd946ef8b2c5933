// The semantic phase's view of a glTF file (model_context.h). Section numbers are those of
// the glTF 2.0 specification.
#include "validation/model_context.h"

#include "bake_log.h"
#include "gltf_resources.h"

#include <algorithm>

namespace lfd::bake::gltf {

std::string accessorPath(int a) { return "accessors[" + std::to_string(a) + "]"; }
std::string viewPath(int v) { return "bufferViews[" + std::to_string(v) + "]"; }

size_t componentBytes(int componentType) { return size_t(std::max(componentSize(componentType), 1)); }

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

size_t lastElementBytes(const tinygltf::Accessor& a)
{
    const size_t c = componentBytes(a.componentType);
    const size_t n = a.type == TINYGLTF_TYPE_MAT2 ? 2 : a.type == TINYGLTF_TYPE_MAT3 ? 3 : 0;
    return n > 0 ? (n - 1) * ((n * c + 3) / 4 * 4) + n * c : elementBytes(a);
}

std::string describe(const Format& f)
{
    std::string out;
    for (const auto& [c, n] : f.components)
        out += (out.empty() ? "" : ", ") + typeName(f.type) + "/" + componentName(c) + (n ? " normalized" : "");
    return out;
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

std::string formatOf(int a, const tinygltf::Accessor& acc, bool withNormalized)
{
    return accessorPath(a) + " is " + typeName(acc.type) + "/" + componentName(acc.componentType) +
           (withNormalized && acc.normalized ? " normalized" : "");
}

ModelContext::ModelContext(ValidationContext& context, const tinygltf::Model& m, const std::set<size_t>& withoutData)
    : ctx(context), model(m), doc(context.root()), withoutData_(withoutData)
{
    quantized = std::find(model.extensionsUsed.begin(), model.extensionsUsed.end(), "KHR_mesh_quantization") !=
                model.extensionsUsed.end();
    const json* accessors = member(doc, "accessors");
    for (size_t a = 0; accessors && a < accessors->size(); ++a)
        originalView_.push_back((*accessors)[a].is_object() && (*accessors)[a].contains("bufferView"));
    for (int64_t a : ctx.usedAccessors())
        used_.insert(int(a));
}

size_t ModelContext::viewStride(int a) const
{
    const int v = model.accessors[size_t(a)].bufferView;
    return hadBufferView(a) && validView(v) ? size_t(model.bufferViews[size_t(v)].byteStride) : 0;
}

// `last`: the bytes of the last element (a matrix's last column needs no padding).
bool ModelContext::viewFits(int a, int v, size_t offset, size_t count, size_t element, size_t stride, size_t last,
                            const std::string& what)
{
    if (!validView(v))
        return true;
    const tinygltf::BufferView& bv = model.bufferViews[size_t(v)];
    const size_t step = std::max(stride, element);
    if (count > 0 && (offset > bv.byteLength || last > bv.byteLength - offset ||
                      (count - 1) > (bv.byteLength - offset - last) / step)) {
        report(IssueCode::ACCESSOR_TOO_LONG, what,
               std::to_string(count) + " elements of " + std::to_string(element) + " bytes at byteOffset " +
                   std::to_string(offset) + (stride > element ? " and byteStride " + std::to_string(stride) : "") +
                   " do not fit " + viewPath(v) + " (" + std::to_string(bv.byteLength) + " bytes)" + unusable(a),
               use(a));
        return false;
    }
    return true;
}

bool ModelContext::fits(int a)
{
    if (!validAccessor(a))
        return false;
    if (auto it = fits_.find(a); it != fits_.end())
        return it->second;
    const tinygltf::Accessor& acc = model.accessors[size_t(a)];
    bool ok = true;
    if (hadBufferView(a)) {
        const size_t stride = model.bufferViews.size() > size_t(acc.bufferView)
                                  ? size_t(model.bufferViews[size_t(acc.bufferView)].byteStride)
                                  : 0;
        ok &= viewFits(a, acc.bufferView, acc.byteOffset, acc.count, elementBytes(acc), stride, lastElementBytes(acc),
                       accessorPath(a));
    }
    if (acc.sparse.isSparse) {
        const size_t n = size_t(std::max(acc.sparse.count, 0));
        const size_t index = componentBytes(acc.sparse.indices.componentType);
        ok &= viewFits(a, acc.sparse.indices.bufferView, size_t(std::max(acc.sparse.indices.byteOffset, 0)), n, index,
                       0, index, at(at(accessorPath(a), "sparse"), "indices"));
        ok &= viewFits(a, acc.sparse.values.bufferView, size_t(std::max(acc.sparse.values.byteOffset, 0)), n,
                       elementBytes(acc), 0, lastElementBytes(acc), at(at(accessorPath(a), "sparse"), "values"));
    }
    fits_[a] = ok;
    return ok;
}

bool ModelContext::hasData(int a) const
{
    // Section 3.6.2.3: without a bufferView an accessor is zeros "unless sparse or an
    // extension" overrides them; without sparse data, what it holds is up to an extension.
    if (!hadBufferView(a) && !model.accessors[size_t(a)].sparse.isSparse)
        return false;
    return bytesNotInFile(model, withoutData_, a).empty();
}

// Read once for all the checks of one accessor (finite values, unit vectors).
const std::optional<FloatArray>& ModelContext::floats(int a, int type)
{
    const auto [it, fresh] = floats_.try_emplace({a, type});
    if (!fresh || !fits(a) || model.accessors[size_t(a)].type != type || !hasData(a))
        return it->second;
    try {
        it->second = readFloatAccessor(model, a, {type}, "", accessorPath(a));
    } catch (const BakeError& e) {
        report(IssueCode::ACCESSOR_READ_FAILED, accessorPath(a), std::string(e.what()).substr(2));
    }
    return it->second;
}

size_t ModelContext::morphTargets(int mesh) const
{
    if (mesh < 0 || size_t(mesh) >= model.meshes.size() || model.meshes[size_t(mesh)].primitives.empty())
        return 0;
    return model.meshes[size_t(mesh)].primitives[0].targets.size();
}

} // namespace lfd::bake::gltf
