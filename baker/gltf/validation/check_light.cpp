// KHR_lights_punctual (extension specification, "Defining Light Sources"): the document's
// `lights`, each a directional, point or spot light. Schema phase only (a node's reference
// to a light: check_node.cpp).
#include "validation/checks.h"

#include <algorithm>

namespace lfd::bake::gltf {
namespace {

// "0 <= innerConeAngle < outerConeAngle <= PI / 2": angles outside [0, pi/2] are
// clamped; an inner angle not below the outer one (compared as the f32 the pack
// stores) leaves no cone to fall off in.
void spotCone(ValidationContext& ctx, const json& cone, const std::string& path)
{
    constexpr double kQuarterTurn = 1.5707963267948966;
    ctx.number(cone, "innerConeAngle", path, 0.0, kQuarterTurn);
    ctx.number(cone, "outerConeAngle", path, 0.0, kQuarterTurn);
    auto angle = [&](const char* key, double fallback) {
        const json* v = member(cone, key);
        return std::clamp(v != nullptr && v->is_number() ? v->get<double>() : fallback, 0.0, kQuarterTurn);
    };
    const double inner = angle("innerConeAngle", 0.0), outer = angle("outerConeAngle", kQuarterTurn / 2.0);
    if (!(float(inner) < float(outer)))
        ctx.report(IssueCode::SPOT_CONE_INVALID, path,
                   "innerConeAngle " + json(inner).dump() + " is not less than outerConeAngle " + json(outer).dump());
    ctx.common(cone, path);
}

void light(ValidationContext& ctx, const json& l, const std::string& path)
{
    const std::optional<std::string> type =
        ctx.enumString(l, "type", path, {"directional", "point", "spot"}, kRead, true, "");
    ctx.factors(l, "color", path, 3);
    ctx.number(l, "intensity", path, 0.0, 1e308);
    // "range: MUST be greater than zero"; the importer treats others as unlimited.
    if (const json* range = ctx.numberMember(l, "range", path, kRead); range != nullptr && !(range->get<double>() > 0.0))
        ctx.report(IssueCode::LIGHT_RANGE_NOT_POSITIVE, at(path, "range"),
                   describe(*range) + " is not greater than 0: ignored (unlimited range)");
    const bool spot = type && *type == "spot";
    if (const json* cone = ctx.object(l, "spot", path, kRead, spot)) {
        if (type && !spot)
            ctx.report(IssueCode::PROPERTY_NOT_APPLICABLE, at(path, "spot"), "given for a " + *type + " light: ignored");
        else
            spotCone(ctx, *cone, at(path, "spot"));
    }
    ctx.common(l, path);
}

} // namespace

void checkPunctualLightsSchema(ValidationContext& ctx)
{
    const json* lights = extensionObject(ctx.root(), "KHR_lights_punctual");
    if (lights == nullptr)
        return;
    const std::string path = "extensions.KHR_lights_punctual";
    const json* list = ctx.array(*lights, "lights", path, kRead, true);
    if (list == nullptr)
        return;
    ctx.forEachObject(*list, at(path, "lights"), kRead, "empty array (the schema requires at least one light)",
                      [&](const json& l, const std::string& p) { light(ctx, l, p); });
    ctx.common(*lights, path);
}

} // namespace lfd::bake::gltf
