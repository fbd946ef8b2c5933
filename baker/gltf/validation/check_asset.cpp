// The asset object and the document's extension lists (glTF 2.0 sections 4.3, 3.12):
// schema phase only (nothing beyond the schema concerns them).
#include "validation/checks.h"

#include <algorithm>
#include <cstring>
#include <set>

namespace lfd::bake::gltf {

void checkAssetSchema(ValidationContext& ctx)
{
    const json* a = ctx.object(ctx.root(), "asset", "", kRead, true);
    if (a == nullptr)
        return;
    // Section 4.3 "Versioning": a loader refuses assets whose major version (or
    // minVersion) it does not support.
    auto checkVersion = [&](const char* key, bool required) {
        const json* v = ctx.string(*a, key, "asset", kRead, required);
        if (v == nullptr)
            return;
        const std::string& s = v->get_ref<const std::string&>();
        const size_t dot = s.find('.');
        const auto digits = [](const std::string& t) {
            return !t.empty() && std::all_of(t.begin(), t.end(), [](char c) { return c >= '0' && c <= '9'; });
        };
        if (dot == std::string::npos || !digits(s.substr(0, dot)) || !digits(s.substr(dot + 1)))
            ctx.report(IssueCode::INVALID_VERSION, at("asset", key),
                       "expected a version \"<major>.<minor>\", got " + describe(*v));
        else if (s.substr(0, dot) != "2" || (std::string(key) == "minVersion" && s.substr(dot + 1) != "0"))
            ctx.report(IssueCode::UNSUPPORTED_VERSION, at("asset", key),
                       "glTF " + s + " is not supported (this baker reads glTF 2.0)");
    };
    checkVersion("version", true);
    checkVersion("minVersion", false);
    ctx.string(*a, "generator", "asset", kIgnored);
    ctx.string(*a, "copyright", "asset", kIgnored);
    ctx.common(*a, "asset");
}

void checkExtensionListsSchema(ValidationContext& ctx)
{
    std::set<std::string> used;
    for (const char* key : {"extensionsUsed", "extensionsRequired"}) {
        const json* list = ctx.array(ctx.root(), key, "", kRead);
        if (list == nullptr)
            continue;
        std::set<std::string> seen;
        for (size_t i = 0; i < list->size(); ++i) {
            const json& v = (*list)[i];
            if (!v.is_string()) {
                ctx.report(IssueCode::TYPE_MISMATCH, at(std::string(key), i), "expected a string, got " + describe(v));
                continue;
            }
            const std::string& name = v.get_ref<const std::string&>();
            if (!seen.insert(name).second) // the schema's uniqueItems
                ctx.report(IssueCode::DUPLICATE_ELEMENT, at(std::string(key), i), "\"" + name + "\" listed twice");
            if (std::strcmp(key, "extensionsUsed") == 0)
                used.insert(name);
            else if (!used.count(name))
                // Section 3.12: every required extension "MUST also be listed in extensionsUsed".
                ctx.report(IssueCode::REQUIRED_EXTENSION_NOT_USED, at(std::string(key), i),
                           "\"" + name + "\" is not in extensionsUsed");
        }
    }
}

} // namespace lfd::bake::gltf
