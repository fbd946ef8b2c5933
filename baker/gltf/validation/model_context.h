// The semantic phase's view of a glTF file (internal to the baker): tinygltf's model of the
// checked document, what of it is read and what lies in the file, and the layout of
// accessor data (glTF 2.0 section 3.6.2), shared by the object checks of validation/.
#pragma once

#include "gltf_accessors.h"
#include "validation/context.h"

#include <tiny_gltf.h>

#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace lfd::bake::gltf {

std::string accessorPath(int a);
std::string viewPath(int v);

// Bytes of one component; 1 for an invalid componentType (reported by the schema check),
// so alignment arithmetic never divides by zero.
size_t componentBytes(int componentType);
// Bytes of one element (section 3.6.2.4: each matrix column starts on a 4-byte boundary).
size_t elementBytes(const tinygltf::Accessor& a);
// Bytes the last element of an accessor occupies: a matrix's last column ends after its
// components, without the padding to the next column.
size_t lastElementBytes(const tinygltf::Accessor& a);

constexpr int kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT;
constexpr int kByte = TINYGLTF_COMPONENT_TYPE_BYTE, kUByte = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
constexpr int kShort = TINYGLTF_COMPONENT_TYPE_SHORT, kUShort = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
constexpr int kUInt = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;

// An accessor format: its type, and the component types (with `normalized`) allowed.
struct Format {
    int type;
    std::vector<std::pair<int, bool>> components; // (componentType, normalized)
};
std::string describe(const Format& f);
bool matches(const tinygltf::Accessor& a, const Format& f);
// "accessors[a] is VEC3/FLOAT" (+ " normalized" when `withNormalized` and it is).
std::string formatOf(int a, const tinygltf::Accessor& acc, bool withNormalized = true);

class ModelContext {
public:
    ModelContext(ValidationContext& ctx, const tinygltf::Model& model, const std::set<size_t>& withoutData);

    ValidationContext& ctx;
    const tinygltf::Model& model;
    const json& doc;
    bool quantized = false; // KHR_mesh_quantization: wider attribute formats

    void report(IssueCode code, const std::string& path, const std::string& message, Use use = kRead)
    {
        ctx.report(code, path, message, use);
    }

    bool validAccessor(int a) const { return a >= 0 && size_t(a) < model.accessors.size(); }
    bool validView(int v) const { return v >= 0 && size_t(v) < model.bufferViews.size(); }
    // Whether a mesh or an animation reads accessor a: a storage defect of an accessor
    // nothing reads leaves the file usable (a warning, "unusable (nothing reads it)").
    bool used(int a) const { return used_.count(a) != 0; }
    const std::set<int>& usedAccessors() const { return used_; }
    Use use(int a) const { return used(a) ? kRead : kIgnored; }
    std::string unusable(int a) const { return used(a) ? "" : ": unusable (nothing reads it)"; }
    // The document's own accessors (not the zero views made for accessors without one).
    bool hadBufferView(int a) const { return size_t(a) < originalView_.size() && originalView_[size_t(a)]; }
    size_t documentAccessorCount() const { return originalView_.size(); }
    // The byteStride of accessor a's own buffer view (0: none, or no view of its own).
    size_t viewStride(int a) const;

    // Whether accessor a's elements lie inside its buffer view (checked once, reported once).
    bool fits(int a);
    // Whether the file holds the bytes accessor a reads (no data check otherwise).
    bool hasData(int a) const;
    // The accessor's float values (normalized integers decoded, sparse applied), or nullopt
    // when it does not fit (reported), has another type or its bytes are not in the file.
    const std::optional<FloatArray>& floats(int a, int type);
    // The morph targets of a mesh (those of its first primitive).
    size_t morphTargets(int mesh) const;

private:
    bool viewFits(int a, int v, size_t offset, size_t count, size_t element, size_t stride, size_t last,
                  const std::string& what);

    const std::set<size_t>& withoutData_;
    std::set<int> used_;
    std::vector<bool> originalView_;
    std::map<int, bool> fits_;
    std::map<std::pair<int, int>, std::optional<FloatArray>> floats_; // (accessor, type)
};

} // namespace lfd::bake::gltf
