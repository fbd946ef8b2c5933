// Typed, bounds-checked accessor reads for the glTF import stage.
#include "gltf_accessors.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace lfd::bake::gltf {
namespace {

int typeComponents(int type)
{
    switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    // Inverse bind matrices (3.7.3.1): MAT4 FLOAT, whose columns need no padding (3.6.2.4
    // pads the columns of 1- and 2-byte MAT2 / MAT3 only, which the importer never reads).
    case TINYGLTF_TYPE_MAT4: return 16;
    default: return 0;
    }
}

bool isIndexComponent(int componentType)
{
    return componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
           componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
           componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
}

uint32_t decodeUnsigned(const uint8_t* p, int componentType)
{
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return *p;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        uint16_t v;
        std::memcpy(&v, p, sizeof v);
        return v;
    }
    default: {
        uint32_t v;
        std::memcpy(&v, p, sizeof v);
        return v;
    }
    }
}

// glTF 2.0 normalized-integer decoding: unsigned c / (2^n - 1), signed max(c / (2^(n-1) - 1), -1).
float decodeFloat(const uint8_t* p, int componentType, bool normalized)
{
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
        int8_t v;
        std::memcpy(&v, p, sizeof v);
        return normalized ? std::max(float(v) / 127.0f, -1.0f) : float(v);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? float(*p) / 255.0f : float(*p);
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
        int16_t v;
        std::memcpy(&v, p, sizeof v);
        return normalized ? std::max(float(v) / 32767.0f, -1.0f) : float(v);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        uint16_t v;
        std::memcpy(&v, p, sizeof v);
        return normalized ? float(v) / 65535.0f : float(v);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
        uint32_t v;
        std::memcpy(&v, p, sizeof v);
        return normalized ? float(double(v) / 4294967295.0) : float(v);
    }
    default: {
        float v;
        std::memcpy(&v, p, sizeof v);
        return v;
    }
    }
}

// `count` elements of `elementSize` bytes, `stride` apart, inside one buffer view.
struct Strided {
    const uint8_t* data = nullptr;
    size_t stride = 0;
    size_t count = 0;
};

Strided locate(const tinygltf::Model& model, int bufferViewIndex, size_t byteOffset, size_t count,
               size_t elementSize, bool allowStride, const std::string& file, const std::string& what)
{
    if (bufferViewIndex < 0 || size_t(bufferViewIndex) >= model.bufferViews.size())
        fail(file, what + ": bufferView " + std::to_string(bufferViewIndex) + " does not exist");
    const tinygltf::BufferView& view = model.bufferViews[size_t(bufferViewIndex)];
    const std::string viewName = "bufferView " + std::to_string(bufferViewIndex);
    if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size())
        fail(file, what + ": " + viewName + " refers to missing buffer " + std::to_string(view.buffer));
    const tinygltf::Buffer& buffer = model.buffers[size_t(view.buffer)];
    if (view.byteOffset > buffer.data.size() || view.byteLength > buffer.data.size() - view.byteOffset)
        fail(file, what + ": " + viewName + " (offset " + std::to_string(view.byteOffset) + ", length " +
                       std::to_string(view.byteLength) + ") exceeds buffer " +
                       std::to_string(view.buffer) + " (" + std::to_string(buffer.data.size()) +
                       " bytes)");

    size_t stride = elementSize;
    if (allowStride && view.byteStride != 0) {
        if (view.byteStride < elementSize)
            fail(file, what + ": " + viewName + " byteStride " + std::to_string(view.byteStride) +
                           " is smaller than the element size " + std::to_string(elementSize));
        stride = view.byteStride;
    }
    // Last element must end inside the view: byteOffset + (count-1)*stride + elementSize
    // <= byteLength, written so that nothing overflows.
    if (count > 0 &&
        (byteOffset > view.byteLength || elementSize > view.byteLength - byteOffset ||
         (count - 1) > (view.byteLength - byteOffset - elementSize) / stride))
        fail(file, what + ": " + std::to_string(count) + " elements at offset " +
                       std::to_string(byteOffset) + " overrun " + viewName + " (" +
                       std::to_string(view.byteLength) + " bytes)");
    return {buffer.data.data() + view.byteOffset + byteOffset, stride, count};
}

const tinygltf::Accessor& accessorAt(const tinygltf::Model& model, int accessorIndex,
                                     const std::string& file, const std::string& what)
{
    if (accessorIndex < 0 || size_t(accessorIndex) >= model.accessors.size())
        fail(file, what + ": accessor " + std::to_string(accessorIndex) + " does not exist");
    return model.accessors[size_t(accessorIndex)];
}

// Calls store(element, component, bytes) for every component: the dense data (or nothing
// for an accessor without bufferView: the caller pre-fills zeros), then sparse patches.
template <class Store>
void visitComponents(const tinygltf::Model& model, const tinygltf::Accessor& accessor,
                     int components, const std::string& file, const std::string& what,
                     Store&& store)
{
    const size_t csize = size_t(componentSize(accessor.componentType));
    const size_t elementSize = csize * size_t(components);

    if (accessor.bufferView >= 0) {
        const Strided s = locate(model, accessor.bufferView, accessor.byteOffset, accessor.count,
                                 elementSize, true, file, what);
        for (size_t e = 0; e < s.count; ++e)
            for (int c = 0; c < components; ++c)
                store(e, c, s.data + e * s.stride + size_t(c) * csize);
    }

    if (!accessor.sparse.isSparse)
        return;
    const auto& sparse = accessor.sparse;
    if (sparse.count < 0 || size_t(sparse.count) > accessor.count)
        fail(file, what + ": sparse count " + std::to_string(sparse.count) + " exceeds accessor count " +
                       std::to_string(accessor.count));
    if (!isIndexComponent(sparse.indices.componentType))
        fail(file, what + ": sparse indices have invalid component type " +
                       std::to_string(sparse.indices.componentType));
    if (sparse.indices.byteOffset < 0 || sparse.values.byteOffset < 0)
        fail(file, what + ": negative sparse byteOffset");
    const size_t n = size_t(sparse.count);
    const Strided indices =
        locate(model, sparse.indices.bufferView, size_t(sparse.indices.byteOffset), n,
               size_t(componentSize(sparse.indices.componentType)), false, file, what + " sparse indices");
    const Strided values = locate(model, sparse.values.bufferView, size_t(sparse.values.byteOffset), n,
                                  elementSize, false, file, what + " sparse values");
    for (size_t k = 0; k < n; ++k) {
        const uint32_t e = decodeUnsigned(indices.data + k * indices.stride, sparse.indices.componentType);
        if (e >= accessor.count)
            fail(file, what + ": sparse index " + std::to_string(e) + " out of range (count " +
                           std::to_string(accessor.count) + ")");
        for (int c = 0; c < components; ++c)
            store(size_t(e), c, values.data + k * values.stride + size_t(c) * csize);
    }
}

} // namespace

int componentSize(int componentType)
{
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0; // INT and DOUBLE are not glTF 2.0 accessor types
    }
}

std::string typeName(int type)
{
    switch (type) {
    case TINYGLTF_TYPE_SCALAR: return "SCALAR";
    case TINYGLTF_TYPE_VEC2: return "VEC2";
    case TINYGLTF_TYPE_VEC3: return "VEC3";
    case TINYGLTF_TYPE_VEC4: return "VEC4";
    case TINYGLTF_TYPE_MAT2: return "MAT2";
    case TINYGLTF_TYPE_MAT3: return "MAT3";
    case TINYGLTF_TYPE_MAT4: return "MAT4";
    default: return "type " + std::to_string(type);
    }
}

std::string componentName(int componentType)
{
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return "BYTE";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "UNSIGNED_BYTE";
    case TINYGLTF_COMPONENT_TYPE_SHORT: return "SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "UNSIGNED_SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "UNSIGNED_INT";
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return "FLOAT";
    default: return "componentType " + std::to_string(componentType);
    }
}

std::string firstLine(const std::string& text)
{
    std::string line = text.substr(0, text.find('\n'));
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t'))
        line.pop_back();
    return line;
}

void fail(const std::string& file, const std::string& message)
{
    throw BakeError(file + ": " + firstLine(message));
}

size_t accessorCount(const tinygltf::Model& model, int accessorIndex, const std::string& file,
                     const std::string& what)
{
    return accessorAt(model, accessorIndex, file, what).count;
}

FloatArray readFloatAccessor(const tinygltf::Model& model, int accessorIndex,
                             std::initializer_list<int> allowedTypes, const std::string& file,
                             const std::string& what)
{
    const std::string where = what + " (accessor " + std::to_string(accessorIndex) + ")";
    const tinygltf::Accessor& accessor = accessorAt(model, accessorIndex, file, what);
    if (std::find(allowedTypes.begin(), allowedTypes.end(), accessor.type) == allowedTypes.end())
        fail(file, where + ": unexpected accessor type " + typeName(accessor.type));
    if (componentSize(accessor.componentType) == 0)
        fail(file, where + ": unsupported component type " + std::to_string(accessor.componentType));

    FloatArray out;
    out.components = typeComponents(accessor.type);
    out.count = accessor.count;
    out.values.assign(out.count * size_t(out.components), 0.0f);
    const int componentType = accessor.componentType;
    const bool normalized = accessor.normalized;
    const size_t components = size_t(out.components);
    visitComponents(model, accessor, out.components, file, where,
                    [&](size_t e, int c, const uint8_t* p) {
                        out.values[e * components + size_t(c)] = decodeFloat(p, componentType, normalized);
                    });
    return out;
}

std::vector<uint32_t> readIndexAccessor(const tinygltf::Model& model, int accessorIndex,
                                        const std::string& file, const std::string& what)
{
    const std::string where = what + " (accessor " + std::to_string(accessorIndex) + ")";
    const tinygltf::Accessor& accessor = accessorAt(model, accessorIndex, file, what);
    if (accessor.type != TINYGLTF_TYPE_SCALAR)
        fail(file, where + ": index accessor must be SCALAR, not " + typeName(accessor.type));
    if (!isIndexComponent(accessor.componentType))
        fail(file, where + ": index component type " + std::to_string(accessor.componentType) +
                       " is not unsigned byte/short/int");

    std::vector<uint32_t> out(accessor.count, 0u);
    const int componentType = accessor.componentType;
    visitComponents(model, accessor, 1, file, where,
                    [&](size_t e, int, const uint8_t* p) { out[e] = decodeUnsigned(p, componentType); });
    return out;
}

std::span<const uint8_t> bufferViewBytes(const tinygltf::Model& model, int bufferViewIndex,
                                         const std::string& file, const std::string& what)
{
    if (bufferViewIndex < 0 || size_t(bufferViewIndex) >= model.bufferViews.size())
        fail(file, what + ": bufferView " + std::to_string(bufferViewIndex) + " does not exist");
    const size_t length = model.bufferViews[size_t(bufferViewIndex)].byteLength;
    const Strided s = locate(model, bufferViewIndex, 0, length, 1, false, file, what);
    return {s.data, s.count};
}

// ---- Topology and generated attributes -------------------------------------------

// glTF 2.0 section 3.7.2.1 "Topology Types": strips and fans as triangle lists, with the
// same winding as the spec's per-triangle definitions. Degenerate stitching triangles
// (two equal indices) of strips and fans are dropped.
std::vector<uint32_t> triangulate(const std::vector<uint32_t>& idx, int mode)
{
    std::vector<uint32_t> out;
    const size_t n = idx.size();
    auto push = [&out](uint32_t a, uint32_t b, uint32_t c) {
        if (a == b || b == c || a == c)
            return;
        out.insert(out.end(), {a, b, c});
    };
    switch (mode) {
    case TINYGLTF_MODE_TRIANGLES:
        out.assign(idx.begin(), idx.begin() + std::ptrdiff_t(n - n % 3));
        break;
    case TINYGLTF_MODE_TRIANGLE_STRIP:
        // Triangle i = {v_i, v_(i+1+i%2), v_(i+2-i%2)}: odd triangles swap to keep the winding.
        for (size_t i = 0; i + 2 < n; ++i)
            push(idx[i], idx[i + 1 + i % 2], idx[i + 2 - i % 2]);
        break;
    case TINYGLTF_MODE_TRIANGLE_FAN:
        // Triangle i = {v_(i+1), v_(i+2), v_0}.
        for (size_t i = 0; i + 2 < n; ++i)
            push(idx[i + 1], idx[i + 2], idx[0]);
        break;
    default: break;
    }
    return out;
}

glm::vec3 anyPerpendicular(const glm::vec3& n)
{
    const glm::vec3 helper = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    return glm::normalize(glm::cross(n, helper));
}

glm::vec3 faceNormal(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2)
{
    const glm::vec3 n = glm::cross(p1 - p0, p2 - p0);
    const float len = glm::length(n);
    return len > 0.0f && std::isfinite(len) ? n / len : glm::vec3(0.0f, 0.0f, 1.0f);
}

// Per-vertex tangents from uv gradients (Lengyel's accumulation, the usual MikkTSpace
// approximation): each triangle adds dP/du and dP/dv to its corners; the tangent is dP/du
// made orthogonal to the normal (Gram-Schmidt). glTF's bitangent is
// cross(normal, tangent.xyz) * w and points "up" in the normal map, i.e. towards
// decreasing v (glTF's uv origin is the top-left corner), so w = +-1 follows -dP/dv.
// note: this matches the authored (MikkTSpace) tangents of the BoomBox sample.
std::vector<glm::vec4> generateTangents(const std::vector<glm::vec3>& p, const std::vector<glm::vec3>& n,
                                        const std::vector<glm::vec2>& uv, const std::vector<uint32_t>& tris)
{
    std::vector<glm::vec3> dpdu(p.size(), glm::vec3(0.0f));
    std::vector<glm::vec3> dpdv(p.size(), glm::vec3(0.0f));
    for (size_t t = 0; t + 2 < tris.size(); t += 3) {
        const uint32_t i0 = tris[t], i1 = tris[t + 1], i2 = tris[t + 2];
        const glm::vec3 e1 = p[i1] - p[i0], e2 = p[i2] - p[i0];
        const glm::vec2 d1 = uv[i1] - uv[i0], d2 = uv[i2] - uv[i0];
        const float det = d1.x * d2.y - d2.x * d1.y;
        if (std::abs(det) < 1e-20f || !std::isfinite(det))
            continue; // no uv parameterisation on this triangle
        const glm::vec3 su = (e1 * d2.y - e2 * d1.y) / det;
        const glm::vec3 sv = (e2 * d1.x - e1 * d2.x) / det;
        for (uint32_t i : {i0, i1, i2}) {
            dpdu[i] += su;
            dpdv[i] += sv;
        }
    }
    std::vector<glm::vec4> tangents(p.size());
    for (size_t i = 0; i < p.size(); ++i) {
        glm::vec3 t = dpdu[i] - n[i] * glm::dot(n[i], dpdu[i]);
        const float len = glm::length(t);
        t = len > 1e-12f && std::isfinite(len) ? t / len : anyPerpendicular(n[i]);
        const float w = glm::dot(glm::cross(n[i], t), -dpdv[i]) < 0.0f ? -1.0f : 1.0f;
        tangents[i] = glm::vec4(t, w);
    }
    return tangents;
}

std::vector<glm::vec3> smoothNormals(const std::vector<glm::vec3>& p, const std::vector<uint32_t>& tris)
{
    // Area-weighted: each triangle adds its unnormalised cross product to its corners.
    std::vector<glm::vec3> sum(p.size(), glm::vec3(0.0f));
    for (size_t t = 0; t + 2 < tris.size(); t += 3) {
        const glm::vec3 n = glm::cross(p[tris[t + 1]] - p[tris[t]], p[tris[t + 2]] - p[tris[t]]);
        for (size_t k = 0; k < 3; ++k)
            sum[tris[t + k]] += n;
    }
    for (glm::vec3& n : sum) {
        const float len = glm::length(n);
        n = len > 0.0f && std::isfinite(len) ? n / len : glm::vec3(0.0f, 0.0f, 1.0f);
    }
    return sum;
}

} // namespace lfd::bake::gltf
