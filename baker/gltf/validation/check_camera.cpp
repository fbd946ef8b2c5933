// Cameras (glTF 2.0 sections 3.10, 5.12-5.14): schema phase only. The baker does not read
// cameras (the display defines the views), so every finding is a warning.
#include "validation/checks.h"

#include <cstring>

namespace lfd::bake::gltf {
namespace {

void projection(ValidationContext& ctx, const json& p, const std::string& pp, const char* kind)
{
    const bool orthographic = std::strcmp(kind, "orthographic") == 0;
    const json* znear = ctx.numberMember(p, "znear", pp, kIgnored, true);
    const json* zfar = ctx.numberMember(p, "zfar", pp, kIgnored, orthographic);
    if (znear && zfar && !(zfar->get<double>() > znear->get<double>()))
        ctx.report(IssueCode::CAMERA_ZFAR_NOT_GREATER, pp, "zfar is not greater than znear: camera ignored");
    if (!orthographic) {
        if (const json* yfov = ctx.numberMember(p, "yfov", pp, kIgnored, true); yfov && !(yfov->get<double>() > 0))
            ctx.report(IssueCode::VALUE_OUT_OF_RANGE, at(pp, "yfov"), "must be greater than 0: camera ignored",
                       kIgnored);
        if (znear && !(znear->get<double>() > 0))
            ctx.report(IssueCode::VALUE_OUT_OF_RANGE, at(pp, "znear"), "must be greater than 0: camera ignored",
                       kIgnored);
    } else {
        for (const char* mag : {"xmag", "ymag"})
            if (const json* m = ctx.numberMember(p, mag, pp, kIgnored, true); m && m->get<double>() == 0)
                ctx.report(IssueCode::VALUE_OUT_OF_RANGE, at(pp, mag), "must not be zero: camera ignored", kIgnored);
    }
}

} // namespace

void checkCameraSchema(ValidationContext& ctx, const json& c, const std::string& path)
{
    const std::optional<std::string> type =
        ctx.enumString(c, "type", path, {"perspective", "orthographic"}, kIgnored, true, ": camera ignored");
    for (const char* kind : {"perspective", "orthographic"}) {
        const json* p = ctx.object(c, kind, path, kIgnored);
        if (p == nullptr) {
            if (type && *type == kind)
                ctx.report(IssueCode::MISSING_REQUIRED_PROPERTY, at(path, kind),
                           "required for a camera of type " + *type + ", missing: camera ignored", kIgnored);
            continue;
        }
        if (!type || *type != kind)
            ctx.report(IssueCode::PROPERTY_NOT_APPLICABLE, at(path, kind),
                       "given for a camera of another type: camera ignored");
        projection(ctx, *p, at(path, kind), kind);
    }
    ctx.common(c, path);
}

} // namespace lfd::bake::gltf
