// The reporting context of glTF validation (internal to the baker): the issue list, the
// document's JSON, and the typed member access both phases of every object check use
// (gltf_validation.h). The schema rules follow the glTF 2.0 specification, section 5
// ("Properties Reference") and its JSON schema.
#pragma once

#include "gltf_validation.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace lfd::bake::gltf {

using json = nlohmann::json;

// JSON paths: `path.key` (`key` alone at the top level) and `path[i]`.
std::string at(const std::string& path, const std::string& key);
std::string at(const std::string& path, size_t i);

// How a value looks in a message: its JSON kind, and short scalars verbatim.
std::string describe(const json& v);

// The member `key` of `o`, or nullptr when `o` is no object or has no such member.
const json* member(const json& o, const char* key);

// The array member `key` of `o`, or an empty array when it is absent or no array.
const json& arrayOf(const json& o, const char* key);

// JSON has one number type; 2.0 is an integer (JSON Schema "integer").
bool isInteger(const json& v);

// The object `o.extensions.<name>`, or nullptr (a non-object one is common()'s warning).
const json* extensionObject(const json& o, const char* name);

class ValidationContext {
public:
    ValidationContext(const json& root, std::vector<SchemaIssue>& issues);

    const json& root() const { return root_; }
    void report(IssueCode code, const std::string& path, const std::string& message, Use use = kRead);

    // The member `key` of `object` (at `path`), or nullptr when it is absent (reported if
    // required) or not of the kind `is` accepts (reported as "expected <expected>").
    const json* typed(const json& object, const char* key, const std::string& path, Use use, bool required,
                      bool (*is)(const json&), const char* expected);
    const json* object(const json& o, const char* key, const std::string& path, Use use, bool required = false);
    const json* array(const json& o, const char* key, const std::string& path, Use use, bool required = false);
    const json* string(const json& o, const char* key, const std::string& path, Use use, bool required = false);
    const json* boolean(const json& o, const char* key, const std::string& path, Use use);
    const json* numberMember(const json& o, const char* key, const std::string& path, Use use, bool required = false);

    // An integer member in [min, max]; nullopt when absent or reported.
    std::optional<int64_t> integer(const json& o, const char* key, const std::string& path, Use use, bool required,
                                   double min, double max = 9.0e15);
    // A number member; out-of-[min, max] values are warnings (the importer clamps).
    void number(const json& o, const char* key, const std::string& path, double min, double max);
    void clamped(const json& v, const std::string& path, double min, double max);
    // An array member of exactly `n` numbers (n == 0: any length).
    const json* numbers(const json& o, const char* key, const std::string& path, size_t n, Use use);
    // An array member of `n` numbers in [0, 1] (clamped).
    void factors(const json& o, const char* key, const std::string& path, size_t n);

    // `v` (at `path`) must be an index into the top-level array `target`.
    std::optional<size_t> index(const json& v, const std::string& path, const char* target, Use use);
    std::optional<size_t> indexInto(const json& v, const std::string& path, const std::string& target, size_t count,
                                    Use use);
    std::optional<size_t> indexMember(const json& o, const char* key, const std::string& path, const char* target,
                                      Use use, bool required = false);
    // The elements of array `list` (at `path`) are distinct indices into `target`.
    void uniqueIndices(const json& list, const std::string& path, const char* target);

    // Integer or string member that must be one of `allowed`.
    std::optional<int64_t> enumInteger(const json& o, const char* key, const std::string& path,
                                       std::initializer_list<int> allowed, Use use, bool required = false);
    std::optional<std::string> enumString(const json& o, const char* key, const std::string& path,
                                          std::initializer_list<const char*> allowed, Use use, bool required,
                                          const char* consequence);

    // Calls fn(element, path) for each object of the array `list` at `path`. With an
    // `emptyNote`, the schema's minItems 1: an empty array is a warning with that message
    // (nothing in it can be wrong).
    template <class Fn>
    void forEachObject(const json& list, const std::string& path, Use use, const char* emptyNote, Fn fn)
    {
        if (emptyNote != nullptr && list.empty())
            report(IssueCode::EMPTY_ARRAY, path, emptyNote);
        for (size_t i = 0; i < list.size(); ++i) {
            if (!list[i].is_object())
                report(IssueCode::TYPE_MISMATCH, at(path, i), "expected an object, got " + describe(list[i]), use);
            else
                fn(list[i], at(path, i));
        }
    }
    // The same for the top-level array `key`.
    template <class Fn>
    void forEach(const char* key, Use use, Fn fn)
    {
        if (const json* list = array(root_, key, "", use))
            forEachObject(*list, key, use,
                          "empty array (the schema requires at least one element, or none at all): ignored", fn);
    }

    // name, extensions and extras: on every glTF object (section 3.12, 3.8 "Extras").
    void common(const json& o, const std::string& path);

    size_t rootCount(const char* array) const;
    // The accessors a mesh or an animation reads (accessorsReadByMeshesAndAnimations).
    const std::set<int64_t>& usedAccessors();

private:
    const json& root_;
    std::vector<SchemaIssue>& issues_;
    std::optional<std::set<int64_t>> usedAccessors_;
};

} // namespace lfd::bake::gltf
