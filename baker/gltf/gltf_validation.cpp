// Strict glTF 2.0 schema validation: see gltf_validation.h for what is an error and what
// is a warning. Property rules follow the glTF 2.0 specification, section 5 ("Properties
// Reference"); section numbers are cited where a rule is not a plain JSON-schema type.
#include "gltf_validation.h"

#include "gltf_texture_source.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <optional>
#include <set>

namespace lfd::bake::gltf {
namespace {

using json = nlohmann::json;
using Severity = SchemaIssue::Severity;

// How a value looks in a message: its JSON kind, and short scalars verbatim.
std::string describe(const json& v)
{
    switch (v.type()) {
    case json::value_t::object: return "an object";
    case json::value_t::array: return "an array";
    case json::value_t::string: {
        const std::string& s = v.get_ref<const std::string&>();
        return "the string \"" + (s.size() > 32 ? s.substr(0, 32) + "..." : s) + "\"";
    }
    case json::value_t::boolean: return v.get<bool>() ? "true" : "false";
    case json::value_t::null: return "null";
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
    case json::value_t::number_float: return v.dump();
    default: return "an invalid value";
    }
}

std::string join(std::initializer_list<const char*> names)
{
    std::string out;
    for (const char* n : names)
        out += (out.empty() ? "" : ", ") + std::string(n);
    return out;
}

std::string join(std::initializer_list<int> values)
{
    std::string out;
    for (int v : values)
        out += (out.empty() ? "" : ", ") + std::to_string(v);
    return out;
}

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

class Validator {
public:
    // An enum value the baker cannot interpret in an accessor a mesh or an animation reads
    // refuses the file; in any other (which nothing reads) it is a warning, as glTF-Validator
    // reports unknown enum values.
    explicit Validator(const json& root) : root_(root), usedAccessors_(accessorsReadByMeshesAndAnimations(root)) {}

    std::vector<SchemaIssue> run()
    {
        if (!root_.is_object()) {
            report(kError, "(top level)", "expected a JSON object, got " + describe(root_));
            return std::move(issues_);
        }
        asset();
        extensionLists();
        if (const json* v = member(root_, "scene"))
            index(*v, "scene", "scenes", kError);
        forEach("scenes", kError, [this](const json& s, const std::string& p) { scene(s, p); });
        punctualLights(); // before the nodes that refer to them
        forEach("nodes", kError, [this](const json& n, const std::string& p) { node(n, p); });
        forEach("meshes", kError, [this](const json& m, const std::string& p) { mesh(m, p); });
        forEach("accessors", kError, [this](const json& a, const std::string& p) { accessor(a, p); });
        forEach("bufferViews", kError, [this](const json& b, const std::string& p) { bufferView(b, p); });
        forEach("buffers", kError, [this](const json& b, const std::string& p) { buffer(b, p); });
        forEach("materials", kError, [this](const json& m, const std::string& p) { material(m, p); });
        forEach("textures", kError, [this](const json& t, const std::string& p) { texture(t, p); });
        forEach("samplers", kWarn, [this](const json& s, const std::string& p) { sampler(s, p); });
        forEach("images", kError, [this](const json& i, const std::string& p) { image(i, p); });
        forEach("animations", kError, [this](const json& a, const std::string& p) { animation(a, p); });
        // Read by nobody: checked as warnings (the baker goes on without them).
        forEach("cameras", kWarn, [this](const json& c, const std::string& p) { camera(c, p); });
        forEach("skins", kWarn, [this](const json& s, const std::string& p) { skin(s, p); });
        common(root_, "");
        return std::move(issues_);
    }

private:
    // ---- Reporting and typed access --------------------------------------------------

    void report(Severity severity, const std::string& path, const std::string& message)
    {
        issues_.push_back({severity, path, message});
    }

    static std::string at(const std::string& path, const std::string& key)
    {
        return path.empty() ? key : path + "." + key;
    }
    static std::string at(const std::string& path, size_t i) { return path + "[" + std::to_string(i) + "]"; }

    static const json* member(const json& object, const char* key)
    {
        const auto it = object.find(key);
        return it == object.end() ? nullptr : &*it;
    }

    // The member `key` of `object` (at `path`), or nullptr when it is absent (reported
    // if required) or not of the expected kind (reported).
    template <class Is>
    const json* typed(const json& object, const char* key, const std::string& path, Severity severity,
                      bool required, Is is, const char* expected)
    {
        const json* v = member(object, key);
        if (v == nullptr) {
            if (required)
                report(severity, at(path, key), "required property missing");
            return nullptr;
        }
        if (!is(*v)) {
            report(severity, at(path, key), std::string("expected ") + expected + ", got " + describe(*v));
            return nullptr;
        }
        return v;
    }

    const json* object(const json& o, const char* key, const std::string& path, Severity s, bool required = false)
    {
        return typed(o, key, path, s, required, [](const json& v) { return v.is_object(); }, "an object");
    }
    const json* array(const json& o, const char* key, const std::string& path, Severity s, bool required = false)
    {
        return typed(o, key, path, s, required, [](const json& v) { return v.is_array(); }, "an array");
    }
    const json* string(const json& o, const char* key, const std::string& path, Severity s, bool required = false)
    {
        return typed(o, key, path, s, required, [](const json& v) { return v.is_string(); }, "a string");
    }
    const json* boolean(const json& o, const char* key, const std::string& path, Severity s)
    {
        return typed(o, key, path, s, false, [](const json& v) { return v.is_boolean(); }, "a boolean");
    }

    static bool isInteger(const json& v)
    {
        if (v.is_number_integer() || v.is_number_unsigned())
            return true;
        // JSON has one number type; 2.0 is an integer (JSON Schema "integer").
        return v.is_number_float() && std::floor(v.get<double>()) == v.get<double>();
    }

    // An integer member in [min, max]; nullopt when absent or reported.
    std::optional<int64_t> integer(const json& o, const char* key, const std::string& path, Severity s,
                                   bool required, double min, double max = 9.0e15)
    {
        const json* v = typed(o, key, path, s, required, isInteger, "an integer");
        if (v == nullptr)
            return std::nullopt;
        const double d = v->get<double>();
        if (d < min || d > max) {
            report(s, at(path, key), "expected an integer " +
                                         (max < 9.0e15 ? "in [" + std::to_string(int64_t(min)) + ", " +
                                                             std::to_string(int64_t(max)) + "]"
                                                       : ">= " + std::to_string(int64_t(min))) +
                                         ", got " + describe(*v));
            return std::nullopt;
        }
        return int64_t(d);
    }

    // A number member; out-of-[min, max] values are warnings (the importer clamps).
    void number(const json& o, const char* key, const std::string& path, double min, double max)
    {
        const json* v = typed(o, key, path, kError, false, [](const json& x) { return x.is_number(); }, "a number");
        if (v != nullptr)
            clampWarning(*v, at(path, key), min, max);
    }

    void clampWarning(const json& v, const std::string& path, double min, double max)
    {
        const double d = v.get<double>();
        if (d < min || d > max)
            report(kWarn, path, describe(v) + " is outside [" + json(min).dump() + ", " +
                                    (max > 1e300 ? std::string("inf") : json(max).dump()) + "]: clamped");
    }

    // An array member of exactly `n` numbers (n == 0: any length).
    const json* numbers(const json& o, const char* key, const std::string& path, size_t n, Severity s)
    {
        const json* v = array(o, key, path, s);
        if (v == nullptr)
            return nullptr;
        if (n != 0 && v->size() != n) {
            report(s, at(path, key), "expected " + std::to_string(n) + " numbers, got " + std::to_string(v->size()));
            return nullptr;
        }
        for (size_t i = 0; i < v->size(); ++i)
            if (!(*v)[i].is_number()) {
                report(s, at(at(path, key), i), "expected a number, got " + describe((*v)[i]));
                return nullptr;
            }
        return v;
    }

    size_t punctualLightCount() const
    {
        const json* lights = extensionObject(root_, "KHR_lights_punctual");
        const json* list = lights != nullptr ? member(*lights, "lights") : nullptr;
        return list != nullptr && list->is_array() ? list->size() : 0;
    }

    size_t rootCount(const char* array) const
    {
        const json* v = member(root_, array);
        return v != nullptr && v->is_array() ? v->size() : 0;
    }

    // `v` (at `path`) must be an index into the top-level array `target`.
    std::optional<size_t> index(const json& v, const std::string& path, const char* target, Severity s)
    {
        return indexInto(v, path, target, rootCount(target), s);
    }

    std::optional<size_t> indexInto(const json& v, const std::string& path, const std::string& target, size_t count,
                                    Severity s)
    {
        if (!isInteger(v)) {
            report(s, path, "expected an index into " + target + ", got " + describe(v));
            return std::nullopt;
        }
        const double d = v.get<double>();
        if (d < 0 || d >= double(count)) {
            report(s, path, describe(v) + " is not an index into " + target + " (" + std::to_string(count) +
                                (count == 1 ? " element)" : " elements)"));
            return std::nullopt;
        }
        return size_t(d);
    }

    std::optional<size_t> indexMember(const json& o, const char* key, const std::string& path, const char* target,
                                      Severity s, bool required = false)
    {
        const json* v = member(o, key);
        if (v == nullptr) {
            if (required)
                report(s, at(path, key), "required property missing");
            return std::nullopt;
        }
        return index(*v, at(path, key), target, s);
    }

    // Integer member that must be one of `allowed`.
    std::optional<int64_t> enumInteger(const json& o, const char* key, const std::string& path,
                                       std::initializer_list<int> allowed, Severity s, bool required = false)
    {
        const json* v = typed(o, key, path, s, required, isInteger, "an integer");
        if (v == nullptr)
            return std::nullopt;
        const double d = v->get<double>();
        for (int a : allowed)
            if (d == a)
                return int64_t(a);
        report(s, at(path, key), "expected one of " + join(allowed) + ", got " + describe(*v) +
                                     (s == kWarn ? ": ignored" : ""));
        return std::nullopt;
    }

    std::optional<std::string> enumString(const json& o, const char* key, const std::string& path,
                                          std::initializer_list<const char*> allowed, Severity s,
                                          bool required, const char* consequence)
    {
        const json* v = string(o, key, path, kError, required);
        if (v == nullptr)
            return std::nullopt;
        const std::string& value = v->get_ref<const std::string&>();
        for (const char* a : allowed)
            if (value == a)
                return value;
        report(s, at(path, key), "expected one of " + join(allowed) + ", got " + describe(*v) + consequence);
        return std::nullopt;
    }

    // Calls fn(element, path) for each object of the top-level array `key`.
    template <class Fn>
    void forEach(const char* key, Severity s, Fn fn)
    {
        const json* list = array(root_, key, "", s);
        if (list == nullptr)
            return;
        // The schema's minItems 1: an empty top-level array should be left out. Nothing in
        // it can be wrong, so the baker goes on.
        if (list->empty())
            report(kWarn, key, "empty array (the schema requires at least one element, or none at all): ignored");
        for (size_t i = 0; i < list->size(); ++i) {
            const std::string path = at(std::string(key), i);
            if (!(*list)[i].is_object())
                report(s, path, "expected an object, got " + describe((*list)[i]));
            else
                fn((*list)[i], path);
        }
    }

    // name, extensions and extras: on every glTF object (section 3.12, 3.8 "Extras").
    void common(const json& o, const std::string& path)
    {
        if (const json* name = member(o, "name"); name != nullptr && !name->is_string())
            report(kWarn, at(path, "name"), "expected a string, got " + describe(*name) + ": name ignored");
        if (const json* ext = object(o, "extensions", path, kWarn))
            for (const auto& [name, value] : ext->items())
                if (!value.is_object())
                    report(kWarn, at(at(path, "extensions"), name),
                           "expected an object, got " + describe(value) + ": extension ignored");
    }

    // ---- Properties ---------------------------------------------------------------

    void asset()
    {
        const json* a = object(root_, "asset", "", kError, true);
        if (a == nullptr)
            return;
        // Section 4.3 "Versioning": a loader refuses assets whose major version (or
        // minVersion) it does not support.
        auto checkVersion = [&](const char* key, bool required) {
            const json* v = string(*a, key, "asset", kError, required);
            if (v == nullptr)
                return;
            const std::string& s = v->get_ref<const std::string&>();
            const size_t dot = s.find('.');
            const auto digits = [](const std::string& t) {
                return !t.empty() && std::all_of(t.begin(), t.end(), [](char c) { return c >= '0' && c <= '9'; });
            };
            if (dot == std::string::npos || !digits(s.substr(0, dot)) || !digits(s.substr(dot + 1)))
                report(kError, at("asset", key), "expected a version \"<major>.<minor>\", got " + describe(*v));
            else if (s.substr(0, dot) != "2" || (std::string(key) == "minVersion" && s.substr(dot + 1) != "0"))
                report(kError, at("asset", key), "glTF " + s + " is not supported (this baker reads glTF 2.0)");
        };
        checkVersion("version", true);
        checkVersion("minVersion", false);
        string(*a, "generator", "asset", kWarn);
        string(*a, "copyright", "asset", kWarn);
        common(*a, "asset");
    }

    void extensionLists()
    {
        std::set<std::string> used;
        for (const char* key : {"extensionsUsed", "extensionsRequired"}) {
            const json* list = array(root_, key, "", kError);
            if (list == nullptr)
                continue;
            std::set<std::string> seen;
            for (size_t i = 0; i < list->size(); ++i) {
                const json& v = (*list)[i];
                if (!v.is_string()) {
                    report(kError, at(std::string(key), i), "expected a string, got " + describe(v));
                    continue;
                }
                const std::string& name = v.get_ref<const std::string&>();
                if (!seen.insert(name).second) // the schema's uniqueItems
                    report(kError, at(std::string(key), i), "\"" + name + "\" listed twice");
                if (std::strcmp(key, "extensionsUsed") == 0)
                    used.insert(name);
                else if (!used.count(name))
                    // Section 3.12: every required extension "MUST also be listed in extensionsUsed".
                    report(kError, at(std::string(key), i), "\"" + name + "\" is not in extensionsUsed");
            }
        }
    }

    void scene(const json& s, const std::string& path)
    {
        if (const json* nodes = array(s, "nodes", path, kError)) {
            if (nodes->empty())
                report(kWarn, at(path, "nodes"), "empty array (the schema requires at least one node, or no nodes property)");
            std::set<size_t> seen;
            for (size_t i = 0; i < nodes->size(); ++i)
                if (auto n = index((*nodes)[i], at(at(path, "nodes"), i), "nodes", kError); n && !seen.insert(*n).second)
                    report(kError, at(at(path, "nodes"), i), "node " + std::to_string(*n) + " listed twice");
        }
        common(s, path);
    }

    void node(const json& n, const std::string& path)
    {
        indexMember(n, "camera", path, "cameras", kWarn);
        indexMember(n, "skin", path, "skins", kWarn);
        indexMember(n, "mesh", path, "meshes", kError);
        if (const json* light = extensionObject(n, "KHR_lights_punctual")) {
            const std::string p = at(at(path, "extensions"), "KHR_lights_punctual");
            if (const json* index = member(*light, "light"))
                indexInto(*index, at(p, "light"), "extensions.KHR_lights_punctual.lights", punctualLightCount(), kError);
            else
                report(kError, at(p, "light"), "required property missing");
            common(*light, p);
        }
        if (const json* children = array(n, "children", path, kError)) {
            if (children->empty())
                report(kWarn, at(path, "children"), "empty array (the schema requires at least one child)");
            std::set<size_t> seen;
            for (size_t i = 0; i < children->size(); ++i)
                if (auto c = index((*children)[i], at(at(path, "children"), i), "nodes", kError);
                    c && !seen.insert(*c).second)
                    report(kError, at(at(path, "children"), i), "node " + std::to_string(*c) + " listed twice");
        }
        const json* matrix = numbers(n, "matrix", path, 16, kError);
        const json* rotation = numbers(n, "rotation", path, 4, kError);
        const json* scale = numbers(n, "scale", path, 3, kError);
        const json* translation = numbers(n, "translation", path, 3, kError);
        numbers(n, "weights", path, 0, kWarn);
        if (rotation != nullptr) {
            double len2 = 0;
            for (const json& c : *rotation)
                len2 += c.get<double>() * c.get<double>();
            // Section 5.25 "node.rotation": a unit quaternion. The importer normalises.
            if (std::abs(std::sqrt(len2) - 1.0) > 1e-3)
                report(kWarn, at(path, "rotation"),
                       "not a unit quaternion (length " + json(std::sqrt(len2)).dump() + "): normalised");
        }
        // Section 3.5.2 "Transformations": "a matrix or any combination of TRS", not both.
        // (A matrix that is not TRS: gltf_semantics.cpp.)
        if (matrix != nullptr && (rotation != nullptr || scale != nullptr || translation != nullptr))
            report(kError, at(path, "matrix"), "given together with translation/rotation/scale (a node has one or the other)");
        common(n, path);
    }

    void mesh(const json& m, const std::string& path)
    {
        if (const json* prims = array(m, "primitives", path, kError, true)) {
            if (prims->empty())
                report(kWarn, at(path, "primitives"), "empty array: the mesh has no geometry");
            for (size_t i = 0; i < prims->size(); ++i) {
                const std::string p = at(at(path, "primitives"), i);
                if (!(*prims)[i].is_object())
                    report(kError, p, "expected an object, got " + describe((*prims)[i]));
                else
                    primitive((*prims)[i], p);
            }
        }
        numbers(m, "weights", path, 0, kWarn);
        common(m, path);
    }

    void primitive(const json& p, const std::string& path)
    {
        if (const json* attributes = object(p, "attributes", path, kError, true))
            for (const auto& [name, value] : attributes->items()) {
                const std::string ap = at(at(path, "attributes"), name);
                index(value, ap, "accessors", kError);
                if (!knownAttributeName(name))
                    report(kWarn, ap, "unknown attribute semantic (application-specific ones start with '_'): ignored");
            }
        indexMember(p, "indices", path, "accessors", kError);
        indexMember(p, "material", path, "materials", kError);
        integer(p, "mode", path, kError, false, 0, 6);
        if (const json* targets = array(p, "targets", path, kWarn))
            for (size_t i = 0; i < targets->size(); ++i) {
                const json& t = (*targets)[i];
                const std::string tp = at(at(path, "targets"), i);
                if (!t.is_object()) {
                    report(kWarn, tp, "expected an object, got " + describe(t) + ": ignored");
                    continue;
                }
                for (const auto& [name, value] : t.items())
                    index(value, at(tp, name), "accessors", kWarn);
            }
        common(p, path);
        if (const json* ext = member(p, "extensions"); ext != nullptr && ext->is_object())
            if (const json* draco = object(*ext, "KHR_draco_mesh_compression", at(path, "extensions"), kError))
                dracoExtension(*draco, at(at(path, "extensions"), "KHR_draco_mesh_compression"), p);
    }

    // KHR_draco_mesh_compression (its README, "glTF Schema Updates"): the view holding the
    // stream, and the stream's id of each attribute, "a subset of the attributes of the
    // primitive". The baker decodes it whether or not the file also has the uncompressed data.
    void dracoExtension(const json& d, const std::string& path, const json& primitive)
    {
        indexMember(d, "bufferView", path, "bufferViews", kError, true);
        const json* attributes = object(d, "attributes", path, kError, true);
        if (attributes == nullptr)
            return;
        const json* own = member(primitive, "attributes");
        for (const auto& [name, id] : attributes->items()) {
            const std::string ap = at(at(path, "attributes"), name);
            if (!isInteger(id) || id.get<double>() < 0 || id.get<double>() > double(INT32_MAX))
                report(kError, ap, "expected a Draco attribute id (an integer >= 0), got " + describe(id));
            else if (own == nullptr || !own->is_object() || !own->contains(name))
                report(kError, ap, "names an attribute the primitive does not have (the extension's attributes are a "
                                   "subset of the primitive's)");
        }
    }

    void accessor(const json& a, const std::string& path)
    {
        const bool hasView = indexMember(a, "bufferView", path, "bufferViews", kError).has_value();
        const std::optional<int64_t> offset = integer(a, "byteOffset", path, kError, false, 0);
        const size_t index = size_t(std::stoul(path.substr(path.find('[') + 1)));
        const Severity readable = usedAccessors_.count(int64_t(index)) ? kError : kWarn;
        const std::optional<int64_t> componentType =
            enumInteger(a, "componentType", path, {5120, 5121, 5122, 5123, 5125, 5126}, readable, true);
        integer(a, "count", path, kError, true, 1);
        const std::optional<std::string> type = enumString(
            a, "type", path, {"SCALAR", "VEC2", "VEC3", "VEC4", "MAT2", "MAT3", "MAT4"}, readable, true,
            readable == kWarn ? ": nothing reads the accessor" : "");
        if (const json* normalized = boolean(a, "normalized", path, kError);
            normalized != nullptr && normalized->get<bool>() && componentType &&
            (*componentType == 5125 || *componentType == 5126))
            // Section 5.1.6 "accessor.normalized": MUST NOT be true for FLOAT or UNSIGNED_INT.
            report(kError, at(path, "normalized"), "must not be true for componentType " +
                                                        std::to_string(*componentType));
        // Section 5.1.2 "accessor.byteOffset": "MUST NOT be defined when bufferView is
        // undefined". (Its alignment: gltf_semantics.cpp, with the buffer view's offset.)
        if (offset && !member(a, "bufferView"))
            report(kError, at(path, "byteOffset"), "given without bufferView");
        const size_t components = type ? size_t(componentCount(*type)) : 0;
        for (const char* bound : {"min", "max"})
            numbers(a, bound, path, components, kWarn);
        if (const json* sparse = object(a, "sparse", path, kError))
            accessorSparse(*sparse, at(path, "sparse"), a);
        (void)hasView;
        common(a, path);
    }

    void accessorSparse(const json& s, const std::string& path, const json& accessor)
    {
        if (auto count = integer(s, "count", path, kError, true, 1)) {
            const json* total = member(accessor, "count");
            if (total != nullptr && total->is_number() && double(*count) > total->get<double>())
                report(kError, at(path, "count"), std::to_string(*count) + " exceeds the accessor count " +
                                                      describe(*total));
        }
        if (const json* indices = object(s, "indices", path, kError, true)) {
            const std::string p = at(path, "indices");
            indexMember(*indices, "bufferView", p, "bufferViews", kError, true);
            integer(*indices, "byteOffset", p, kError, false, 0);
            enumInteger(*indices, "componentType", p, {5121, 5123, 5125}, kError, true);
            common(*indices, p);
        }
        if (const json* values = object(s, "values", path, kError, true)) {
            const std::string p = at(path, "values");
            indexMember(*values, "bufferView", p, "bufferViews", kError, true);
            integer(*values, "byteOffset", p, kError, false, 0);
            common(*values, p);
        }
        common(s, path);
    }

    void bufferView(const json& v, const std::string& path)
    {
        // (The view lying inside its buffer: gltf_semantics.cpp, an error where it is read.)
        indexMember(v, "buffer", path, "buffers", kError, true);
        integer(v, "byteOffset", path, kError, false, 0);
        integer(v, "byteLength", path, kError, true, 1);
        // Section 5.11.4 "bufferView.byteStride": 4 to 252, a multiple of 4.
        if (auto stride = integer(v, "byteStride", path, kError, false, 4, 252); stride && *stride % 4 != 0)
            report(kError, at(path, "byteStride"), std::to_string(*stride) + " is not a multiple of 4");
        // Section 5.11.4: byteStride is for vertex data; an index buffer view has none.
        if (enumInteger(v, "target", path, {34962, 34963}, kWarn) == 34963 && member(v, "byteStride") != nullptr)
            report(kError, at(path, "byteStride"), "defined for a buffer view of index data (target 34963)");
        common(v, path);
        if (const json* ext = member(v, "extensions"); ext != nullptr && ext->is_object()) {
            // KHR_meshopt_compression, "Exclusions": not on a view that has the EXT one.
            if (ext->contains("EXT_meshopt_compression") && ext->contains("KHR_meshopt_compression"))
                report(kError, at(path, "extensions"), "has both EXT_meshopt_compression and KHR_meshopt_compression");
            for (const char* name : {"EXT_meshopt_compression", "KHR_meshopt_compression"})
                if (const json* m = object(*ext, name, at(path, "extensions"), kError))
                    meshoptExtension(*m, at(at(path, "extensions"), name), v,
                                     std::strcmp(name, "KHR_meshopt_compression") == 0);
        }
    }

    // EXT_meshopt_compression / KHR_meshopt_compression, "JSON schema updates": the
    // compressed range and the decoded layout, with the rules "for the extension object to
    // be valid".
    void meshoptExtension(const json& m, const std::string& path, const json& view, bool khr)
    {
        indexMember(m, "buffer", path, "buffers", kError, true);
        integer(m, "byteOffset", path, kError, false, 0);
        integer(m, "byteLength", path, kError, true, 1);
        const std::optional<int64_t> stride = integer(m, "byteStride", path, kError, true, 1, 256);
        const std::optional<int64_t> count = integer(m, "count", path, kError, true, 1);
        const std::optional<std::string> mode =
            enumString(m, "mode", path, {"ATTRIBUTES", "TRIANGLES", "INDICES"}, kError, true, "");
        // KHR_meshopt_compression adds the COLOR filter.
        const std::optional<std::string> filter =
            khr ? enumString(m, "filter", path, {"NONE", "OCTAHEDRAL", "QUATERNION", "EXPONENTIAL", "COLOR"}, kError,
                             false, "")
                : enumString(m, "filter", path, {"NONE", "OCTAHEDRAL", "QUATERNION", "EXPONENTIAL"}, kError, false, "");
        common(m, path);
        if (!stride || !count)
            return;
        auto rule = [&](bool holds, const std::string& what) {
            if (!holds)
                report(kError, path, what);
        };
        const json* viewStride = member(view, "byteStride");
        rule(viewStride == nullptr || !viewStride->is_number() || viewStride->get<double>() == double(*stride),
             "byteStride " + std::to_string(*stride) + " differs from the buffer view's");
        const json* length = member(view, "byteLength");
        rule(length == nullptr || !length->is_number() || length->get<double>() == double(*stride) * double(*count),
             "byteStride " + std::to_string(*stride) + " x count " + std::to_string(*count) +
                 " differs from the buffer view's byteLength");
        const std::string f = filter.value_or("NONE");
        if (mode == "ATTRIBUTES")
            rule(*stride % 4 == 0,
                 "byteStride " + std::to_string(*stride) + " is not a multiple of 4 (mode ATTRIBUTES)");
        if (mode == "TRIANGLES")
            rule(*count % 3 == 0, "count " + std::to_string(*count) + " is not a multiple of 3 (mode TRIANGLES)");
        if (mode == "TRIANGLES" || mode == "INDICES") {
            rule(*stride == 2 || *stride == 4,
                 "byteStride " + std::to_string(*stride) + " is not 2 or 4 (mode " + *mode + ")");
            rule(f == "NONE", "filter " + f + " on index data (mode " + *mode + ")");
        }
        if (f == "OCTAHEDRAL" || f == "COLOR")
            rule(*stride == 4 || *stride == 8,
                 "byteStride " + std::to_string(*stride) + " is not 4 or 8 (filter " + f + ")");
        if (f == "QUATERNION")
            rule(*stride == 8, "byteStride " + std::to_string(*stride) + " is not 8 (filter QUATERNION)");
        if (f == "EXPONENTIAL")
            rule(*stride % 4 == 0,
                 "byteStride " + std::to_string(*stride) + " is not a multiple of 4 (filter EXPONENTIAL)");
    }

    void buffer(const json& b, const std::string& path)
    {
        string(b, "uri", path, kError);
        integer(b, "byteLength", path, kError, true, 1);
        common(b, path);
    }

    // textureInfo / normalTextureInfo / occlusionTextureInfo (sections 5.22, 5.20, 5.21).
    void textureInfo(const json& m, const char* key, const std::string& path)
    {
        const json* info = object(m, key, path, kError);
        if (info == nullptr)
            return;
        const std::string p = at(path, key);
        if (std::strcmp(key, "normalTexture") == 0)
            number(*info, "scale", p, -1e308, 1e308);
        if (std::strcmp(key, "occlusionTexture") == 0)
            number(*info, "strength", p, 0.0, 1.0);
        integer(*info, "texCoord", p, kError, false, 0);
        indexMember(*info, "index", p, "textures", kError, true);
        common(*info, p);
        if (const json* transform = extensionObject(*info, "KHR_texture_transform"))
            textureTransform(*transform, at(at(p, "extensions"), "KHR_texture_transform"));
    }

    // The object `o.extensions.<name>`, or nullptr (a non-object one is common()'s warning).
    static const json* extensionObject(const json& o, const char* name)
    {
        const json* ext = member(o, "extensions");
        const json* value = ext != nullptr && ext->is_object() ? member(*ext, name) : nullptr;
        return value != nullptr && value->is_object() ? value : nullptr;
    }

    // KHR_texture_transform (extension specification, "Properties"): offset and scale are
    // two numbers, rotation a number, texCoord an index of a TEXCOORD set.
    void textureTransform(const json& t, const std::string& path)
    {
        numbers(t, "offset", path, 2, kError);
        typed(t, "rotation", path, kError, false, [](const json& v) { return v.is_number(); }, "a number");
        numbers(t, "scale", path, 2, kError);
        integer(t, "texCoord", path, kError, false, 0);
        common(t, path);
    }

    // KHR_lights_punctual (extension specification, "Defining Light Sources"): the
    // document's `lights`, each a directional, point or spot light.
    void punctualLights()
    {
        const json* lights = extensionObject(root_, "KHR_lights_punctual");
        if (lights == nullptr)
            return;
        const std::string path = "extensions.KHR_lights_punctual";
        const json* list = array(*lights, "lights", path, kError, true);
        if (list == nullptr)
            return;
        if (list->empty())
            report(kWarn, at(path, "lights"), "empty array (the schema requires at least one light)");
        for (size_t i = 0; i < list->size(); ++i) {
            const std::string p = at(at(path, "lights"), i);
            if (!(*list)[i].is_object())
                report(kError, p, "expected an object, got " + describe((*list)[i]));
            else
                light((*list)[i], p);
        }
        common(*lights, path);
    }

    void light(const json& l, const std::string& path)
    {
        const std::optional<std::string> type = enumString(l, "type", path, {"directional", "point", "spot"}, kError,
                                                           true, "");
        factors(l, "color", path, 3);
        number(l, "intensity", path, 0.0, 1e308);
        // "range: MUST be greater than zero"; the importer treats others as unlimited.
        if (const json* range = typed(l, "range", path, kError, false, [](const json& v) { return v.is_number(); },
                                      "a number");
            range != nullptr && !(range->get<double>() > 0.0))
            report(kWarn, at(path, "range"), describe(*range) + " is not greater than 0: ignored (unlimited range)");
        const bool spot = type && *type == "spot";
        if (const json* cone = object(l, "spot", path, kError, spot)) {
            if (type && !spot)
                report(kWarn, at(path, "spot"), "given for a " + *type + " light: ignored");
            else
                spotCone(*cone, at(path, "spot"));
        }
        common(l, path);
    }

    // "0 <= innerConeAngle < outerConeAngle <= PI / 2": angles outside [0, pi/2] are
    // clamped; an inner angle not below the outer one (compared as the f32 the pack
    // stores) leaves no cone to fall off in.
    void spotCone(const json& cone, const std::string& path)
    {
        constexpr double kQuarterTurn = 1.5707963267948966;
        number(cone, "innerConeAngle", path, 0.0, kQuarterTurn);
        number(cone, "outerConeAngle", path, 0.0, kQuarterTurn);
        auto angle = [&](const char* key, double fallback) {
            const json* v = member(cone, key);
            return std::clamp(v != nullptr && v->is_number() ? v->get<double>() : fallback, 0.0, kQuarterTurn);
        };
        const double inner = angle("innerConeAngle", 0.0), outer = angle("outerConeAngle", kQuarterTurn / 2.0);
        if (!(float(inner) < float(outer)))
            report(kError, path, "innerConeAngle " + json(inner).dump() + " is not less than outerConeAngle " +
                                     json(outer).dump());
        common(cone, path);
    }

    void factors(const json& o, const char* key, const std::string& path, size_t n)
    {
        if (const json* v = numbers(o, key, path, n, kError))
            for (size_t i = 0; i < v->size(); ++i)
                clampWarning((*v)[i], at(at(path, key), i), 0.0, 1.0);
    }

    void material(const json& m, const std::string& path)
    {
        if (const json* pbr = object(m, "pbrMetallicRoughness", path, kError)) {
            const std::string p = at(path, "pbrMetallicRoughness");
            factors(*pbr, "baseColorFactor", p, 4);
            textureInfo(*pbr, "baseColorTexture", p);
            number(*pbr, "metallicFactor", p, 0.0, 1.0);
            number(*pbr, "roughnessFactor", p, 0.0, 1.0);
            textureInfo(*pbr, "metallicRoughnessTexture", p);
            common(*pbr, p);
        }
        textureInfo(m, "normalTexture", path);
        textureInfo(m, "occlusionTexture", path);
        textureInfo(m, "emissiveTexture", path);
        factors(m, "emissiveFactor", path, 3);
        enumString(m, "alphaMode", path, {"OPAQUE", "MASK", "BLEND"}, kWarn, false, ": treated as OPAQUE");
        number(m, "alphaCutoff", path, 0.0, 1e308);
        boolean(m, "doubleSided", path, kError);
        common(m, path);
        // KHR_materials_unlit has no properties (an object: common()); emissive strength:
        if (const json* ext = member(m, "extensions"); ext != nullptr && ext->is_object())
            if (const json* strength = member(*ext, "KHR_materials_emissive_strength");
                strength != nullptr && strength->is_object())
                number(*strength, "emissiveStrength", at(at(path, "extensions"), "KHR_materials_emissive_strength"),
                       0.0, 1e308);
    }

    void texture(const json& t, const std::string& path)
    {
        indexMember(t, "sampler", path, "samplers", kWarn);
        indexMember(t, "source", path, "images", kError);
        common(t, path);
        // EXT_texture_webp's image is read (an error), KHR_texture_basisu's never is (a warning).
        if (const json* ext = member(t, "extensions"); ext != nullptr && ext->is_object())
            for (const auto& [name, severity] : {std::pair{kWebp, kError}, std::pair{kBasisu, kWarn}})
                if (const json* e = object(*ext, name, at(path, "extensions"), severity)) {
                    indexMember(*e, "source", at(at(path, "extensions"), name), "images", severity, true);
                    common(*e, at(at(path, "extensions"), name));
                }
    }

    // Samplers are not stored in the pack (the player samples with its own filters).
    void sampler(const json& s, const std::string& path)
    {
        enumInteger(s, "magFilter", path, {9728, 9729}, kWarn);
        enumInteger(s, "minFilter", path, {9728, 9729, 9984, 9985, 9986, 9987}, kWarn);
        enumInteger(s, "wrapS", path, {33071, 33648, 10497}, kWarn);
        enumInteger(s, "wrapT", path, {33071, 33648, 10497}, kWarn);
        common(s, path);
    }

    void image(const json& i, const std::string& path)
    {
        const json* uri = string(i, "uri", path, kError);
        const bool hasView = indexMember(i, "bufferView", path, "bufferViews", kError).has_value();
        // Section 5.18.2 "image.mimeType": image/jpeg or image/png, and the types the
        // image-format extensions the file uses add (gltf_texture_source.h).
        if (const json* mime = string(i, "mimeType", path, kError);
            mime != nullptr && !knownMediaType(root_, mime->get<std::string>()))
            report(kWarn, at(path, "mimeType"), "expected one of " + describeMediaTypes(root_) + ", got " +
                                                    describe(*mime) + ": decoded by content");
        // Section 5.17 "image": uri or bufferView (then with mimeType), exactly one.
        if (uri != nullptr && member(i, "bufferView") != nullptr)
            report(kError, path, "has both uri and bufferView");
        else if (uri == nullptr && member(i, "uri") == nullptr && member(i, "bufferView") == nullptr)
            report(kError, path, "has neither uri nor bufferView");
        if (hasView && member(i, "mimeType") == nullptr)
            report(kWarn, at(path, "mimeType"), "required with bufferView, missing: decoded by content");
        common(i, path);
    }

    // Section 5.12 "camera" (unread by the baker: warnings).
    void camera(const json& c, const std::string& path)
    {
        const std::optional<std::string> type =
            enumString(c, "type", path, {"perspective", "orthographic"}, kWarn, true, ": camera ignored");
        for (const char* kind : {"perspective", "orthographic"}) {
            const json* p = object(c, kind, path, kWarn);
            if (p == nullptr) {
                if (type && *type == kind)
                    report(kWarn, at(path, kind), "required for a camera of type " + *type + ", missing: camera ignored");
                continue;
            }
            const std::string pp = at(path, kind);
            if (!type || *type != kind)
                report(kWarn, pp, std::string("given for a camera of another type: camera ignored"));
            const json* znear = typed(*p, "znear", pp, kWarn, true, [](const json& v) { return v.is_number(); }, "a number");
            const json* zfar = typed(*p, "zfar", pp, kWarn, std::strcmp(kind, "orthographic") == 0,
                                     [](const json& v) { return v.is_number(); }, "a number");
            if (znear && zfar && !(zfar->get<double>() > znear->get<double>()))
                report(kWarn, pp, "zfar is not greater than znear: camera ignored");
            if (std::strcmp(kind, "perspective") == 0) {
                if (const json* yfov = typed(*p, "yfov", pp, kWarn, true, [](const json& v) { return v.is_number(); }, "a number");
                    yfov && !(yfov->get<double>() > 0))
                    report(kWarn, at(pp, "yfov"), "must be greater than 0: camera ignored");
                if (znear && !(znear->get<double>() > 0))
                    report(kWarn, at(pp, "znear"), "must be greater than 0: camera ignored");
            } else {
                for (const char* mag : {"xmag", "ymag"})
                    if (const json* m = typed(*p, mag, pp, kWarn, true, [](const json& v) { return v.is_number(); }, "a number");
                        m && m->get<double>() == 0)
                        report(kWarn, at(pp, mag), "must not be zero: camera ignored");
            }
        }
        common(c, path);
    }

    // Section 5.28 "skin" (skinning is not baked: warnings).
    void skin(const json& s, const std::string& path)
    {
        indexMember(s, "inverseBindMatrices", path, "accessors", kWarn);
        indexMember(s, "skeleton", path, "nodes", kWarn);
        if (const json* joints = array(s, "joints", path, kWarn, true)) {
            if (joints->empty())
                report(kWarn, at(path, "joints"), "empty array (a skin has at least one joint)");
            for (size_t i = 0; i < joints->size(); ++i)
                index((*joints)[i], at(at(path, "joints"), i), "nodes", kWarn);
        }
        common(s, path);
    }

    void animation(const json& a, const std::string& path)
    {
        size_t samplerCount = 0;
        if (const json* samplers = array(a, "samplers", path, kError, true)) {
            samplerCount = samplers->size();
            for (size_t k = 0; k < samplers->size(); ++k) {
                const json& s = (*samplers)[k];
                const std::string p = at(at(path, "samplers"), k);
                if (!s.is_object()) {
                    report(kError, p, "expected an object, got " + describe(s));
                    continue;
                }
                indexMember(s, "input", p, "accessors", kError, true);
                indexMember(s, "output", p, "accessors", kError, true);
                enumString(s, "interpolation", p, {"LINEAR", "STEP", "CUBICSPLINE"}, kError, false, "");
                common(s, p);
            }
        }
        if (const json* channels = array(a, "channels", path, kError, true)) {
            if (channels->empty())
                report(kWarn, at(path, "channels"), "empty array: the animation animates nothing");
            for (size_t k = 0; k < channels->size(); ++k) {
                const json& c = (*channels)[k];
                const std::string p = at(at(path, "channels"), k);
                if (!c.is_object()) {
                    report(kError, p, "expected an object, got " + describe(c));
                    continue;
                }
                if (const json* s = member(c, "sampler"))
                    indexInto(*s, at(p, "sampler"), at(path, "samplers"), samplerCount, kError);
                else
                    report(kError, at(p, "sampler"), "required property missing");
                if (const json* target = object(c, "target", p, kError, true)) {
                    const std::string tp = at(p, "target");
                    indexMember(*target, "node", tp, "nodes", kError);
                    enumString(*target, "path", tp, {"translation", "rotation", "scale", "weights"}, kWarn, true,
                               ": channel ignored");
                    common(*target, tp);
                }
                common(c, p);
            }
        }
        common(a, path);
    }

    const json& root_;
    std::vector<SchemaIssue> issues_;
    const std::set<int64_t> usedAccessors_;
};

} // namespace

std::set<int64_t> accessorsReadByMeshesAndAnimations(const nlohmann::json& document)
{
    std::set<int64_t> used;
    auto add = [&](const json& v) {
        if (v.is_number_integer() || v.is_number_unsigned())
            used.insert(v.get<int64_t>());
    };
    auto member = [](const json& o, const char* key) -> const json* {
        if (!o.is_object())
            return nullptr;
        const auto it = o.find(key);
        return it == o.end() ? nullptr : &*it;
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

std::vector<SchemaIssue> validateGltfSchema(const nlohmann::json& document)
{
    return Validator(document).run();
}


} // namespace lfd::bake::gltf
