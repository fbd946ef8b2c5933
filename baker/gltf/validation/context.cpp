// The reporting context and typed JSON access of glTF validation (context.h).
#include "validation/context.h"

#include <cmath>
#include <utility>

namespace lfd::bake::gltf {
namespace {

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

} // namespace

SchemaIssue makeIssue(IssueCode code, std::string path, std::string message, Use use)
{
    const IssueSeverity severity = use == kIgnored ? IssueSeverity::Warning : issueCodeInfo(code).severity;
    return {code, severity, std::move(path), std::move(message)};
}

std::string at(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }

std::string at(const std::string& path, size_t i) { return path + "[" + std::to_string(i) + "]"; }

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

const json* member(const json& o, const char* key)
{
    if (!o.is_object())
        return nullptr;
    const auto it = o.find(key);
    return it == o.end() ? nullptr : &*it;
}

const json& arrayOf(const json& o, const char* key)
{
    static const json empty = json::array();
    const json* v = member(o, key);
    return v != nullptr && v->is_array() ? *v : empty;
}

bool isInteger(const json& v)
{
    if (v.is_number_integer() || v.is_number_unsigned())
        return true;
    return v.is_number_float() && std::floor(v.get<double>()) == v.get<double>();
}

const json* extensionObject(const json& o, const char* name)
{
    const json* ext = member(o, "extensions");
    const json* value = ext != nullptr && ext->is_object() ? member(*ext, name) : nullptr;
    return value != nullptr && value->is_object() ? value : nullptr;
}

ValidationContext::ValidationContext(const json& root, std::vector<SchemaIssue>& issues) : root_(root), issues_(issues)
{
}

void ValidationContext::report(IssueCode code, const std::string& path, const std::string& message, Use use)
{
    issues_.push_back(makeIssue(code, path, message, use));
}

const json* ValidationContext::typed(const json& object, const char* key, const std::string& path, Use use,
                                     bool required, bool (*is)(const json&), const char* expected)
{
    const json* v = member(object, key);
    if (v == nullptr) {
        if (required)
            report(IssueCode::MISSING_REQUIRED_PROPERTY, at(path, key), "required property missing", use);
        return nullptr;
    }
    if (!is(*v)) {
        report(IssueCode::TYPE_MISMATCH, at(path, key), std::string("expected ") + expected + ", got " + describe(*v),
               use);
        return nullptr;
    }
    return v;
}

const json* ValidationContext::object(const json& o, const char* key, const std::string& path, Use use, bool required)
{
    return typed(o, key, path, use, required, [](const json& v) { return v.is_object(); }, "an object");
}

const json* ValidationContext::array(const json& o, const char* key, const std::string& path, Use use, bool required)
{
    return typed(o, key, path, use, required, [](const json& v) { return v.is_array(); }, "an array");
}

const json* ValidationContext::string(const json& o, const char* key, const std::string& path, Use use, bool required)
{
    return typed(o, key, path, use, required, [](const json& v) { return v.is_string(); }, "a string");
}

const json* ValidationContext::boolean(const json& o, const char* key, const std::string& path, Use use)
{
    return typed(o, key, path, use, false, [](const json& v) { return v.is_boolean(); }, "a boolean");
}

const json* ValidationContext::numberMember(const json& o, const char* key, const std::string& path, Use use,
                                            bool required)
{
    return typed(o, key, path, use, required, [](const json& v) { return v.is_number(); }, "a number");
}

std::optional<int64_t> ValidationContext::integer(const json& o, const char* key, const std::string& path, Use use,
                                                  bool required, double min, double max)
{
    const json* v = typed(o, key, path, use, required, isInteger, "an integer");
    if (v == nullptr)
        return std::nullopt;
    const double d = v->get<double>();
    if (d < min || d > max) {
        report(IssueCode::VALUE_OUT_OF_RANGE, at(path, key),
               "expected an integer " +
                   (max < 9.0e15 ? "in [" + std::to_string(int64_t(min)) + ", " + std::to_string(int64_t(max)) + "]"
                                 : ">= " + std::to_string(int64_t(min))) +
                   ", got " + describe(*v),
               use);
        return std::nullopt;
    }
    return int64_t(d);
}

void ValidationContext::number(const json& o, const char* key, const std::string& path, double min, double max)
{
    if (const json* v = numberMember(o, key, path, kRead))
        clamped(*v, at(path, key), min, max);
}

void ValidationContext::clamped(const json& v, const std::string& path, double min, double max)
{
    const double d = v.get<double>();
    if (d < min || d > max)
        report(IssueCode::VALUE_CLAMPED, path,
               describe(v) + " is outside [" + json(min).dump() + ", " +
                   (max > 1e300 ? std::string("inf") : json(max).dump()) + "]: clamped");
}

const json* ValidationContext::numbers(const json& o, const char* key, const std::string& path, size_t n, Use use)
{
    const json* v = array(o, key, path, use);
    if (v == nullptr)
        return nullptr;
    if (n != 0 && v->size() != n) {
        report(IssueCode::ARRAY_LENGTH_MISMATCH, at(path, key),
               "expected " + std::to_string(n) + " numbers, got " + std::to_string(v->size()), use);
        return nullptr;
    }
    for (size_t i = 0; i < v->size(); ++i)
        if (!(*v)[i].is_number()) {
            report(IssueCode::TYPE_MISMATCH, at(at(path, key), i), "expected a number, got " + describe((*v)[i]), use);
            return nullptr;
        }
    return v;
}

void ValidationContext::factors(const json& o, const char* key, const std::string& path, size_t n)
{
    if (const json* v = numbers(o, key, path, n, kRead))
        for (size_t i = 0; i < v->size(); ++i)
            clamped((*v)[i], at(at(path, key), i), 0.0, 1.0);
}

std::optional<size_t> ValidationContext::index(const json& v, const std::string& path, const char* target, Use use)
{
    return indexInto(v, path, target, rootCount(target), use);
}

std::optional<size_t> ValidationContext::indexInto(const json& v, const std::string& path, const std::string& target,
                                                   size_t count, Use use)
{
    if (!isInteger(v)) {
        report(IssueCode::TYPE_MISMATCH, path, "expected an index into " + target + ", got " + describe(v), use);
        return std::nullopt;
    }
    const double d = v.get<double>();
    if (d < 0 || d >= double(count)) {
        report(IssueCode::UNRESOLVED_REFERENCE, path,
               describe(v) + " is not an index into " + target + " (" + std::to_string(count) +
                   (count == 1 ? " element)" : " elements)"),
               use);
        return std::nullopt;
    }
    return size_t(d);
}

std::optional<size_t> ValidationContext::indexMember(const json& o, const char* key, const std::string& path,
                                                     const char* target, Use use, bool required)
{
    const json* v = member(o, key);
    if (v == nullptr) {
        if (required)
            report(IssueCode::MISSING_REQUIRED_PROPERTY, at(path, key), "required property missing", use);
        return std::nullopt;
    }
    return index(*v, at(path, key), target, use);
}

void ValidationContext::uniqueIndices(const json& list, const std::string& path, const char* target)
{
    std::set<size_t> seen;
    for (size_t i = 0; i < list.size(); ++i)
        if (auto n = index(list[i], at(path, i), target, kRead); n && !seen.insert(*n).second)
            report(IssueCode::DUPLICATE_ELEMENT, at(path, i), "node " + std::to_string(*n) + " listed twice");
}

std::optional<int64_t> ValidationContext::enumInteger(const json& o, const char* key, const std::string& path,
                                                      std::initializer_list<int> allowed, Use use, bool required)
{
    const json* v = typed(o, key, path, use, required, isInteger, "an integer");
    if (v == nullptr)
        return std::nullopt;
    const double d = v->get<double>();
    for (int a : allowed)
        if (d == a)
            return int64_t(a);
    report(IssueCode::VALUE_NOT_IN_LIST, at(path, key),
           "expected one of " + join(allowed) + ", got " + describe(*v) + (use == kIgnored ? ": ignored" : ""), use);
    return std::nullopt;
}

std::optional<std::string> ValidationContext::enumString(const json& o, const char* key, const std::string& path,
                                                         std::initializer_list<const char*> allowed, Use use,
                                                         bool required, const char* consequence)
{
    const json* v = string(o, key, path, kRead, required);
    if (v == nullptr)
        return std::nullopt;
    const std::string& value = v->get_ref<const std::string&>();
    for (const char* a : allowed)
        if (value == a)
            return value;
    report(IssueCode::VALUE_NOT_IN_LIST, at(path, key),
           "expected one of " + join(allowed) + ", got " + describe(*v) + consequence, use);
    return std::nullopt;
}

void ValidationContext::common(const json& o, const std::string& path)
{
    if (const json* name = member(o, "name"); name != nullptr && !name->is_string())
        report(IssueCode::TYPE_MISMATCH, at(path, "name"), "expected a string, got " + describe(*name) + ": name ignored",
               kIgnored);
    if (const json* ext = object(o, "extensions", path, kIgnored))
        for (const auto& [name, value] : ext->items())
            if (!value.is_object())
                report(IssueCode::TYPE_MISMATCH, at(at(path, "extensions"), name),
                       "expected an object, got " + describe(value) + ": extension ignored", kIgnored);
}

size_t ValidationContext::rootCount(const char* array) const
{
    const json* v = member(root_, array);
    return v != nullptr && v->is_array() ? v->size() : 0;
}

const std::set<int64_t>& ValidationContext::usedAccessors()
{
    if (!usedAccessors_)
        usedAccessors_ = accessorsReadByMeshesAndAnimations(root_);
    return *usedAccessors_;
}

} // namespace lfd::bake::gltf
