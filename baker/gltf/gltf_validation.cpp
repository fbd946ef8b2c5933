// The two phases of glTF validation (gltf_validation.h): the order in which the object
// checks of validation/ run, which is the order of the issues they report.
#include "gltf_validation.h"

#include "validation/checks.h"
#include "validation/model_context.h"

namespace lfd::bake::gltf {

std::vector<SchemaIssue> validateGltfSchema(const nlohmann::json& document)
{
    std::vector<SchemaIssue> issues;
    ValidationContext ctx(document, issues);
    if (!document.is_object()) {
        ctx.report(IssueCode::TYPE_MISMATCH, "(top level)", "expected a JSON object, got " + describe(document));
        return issues;
    }
    checkAssetSchema(ctx);
    checkExtensionListsSchema(ctx);
    if (const json* v = member(document, "scene"))
        ctx.index(*v, "scene", "scenes", kRead);
    ctx.forEach("scenes", kRead, [&](const json& s, const std::string& p) { checkSceneSchema(ctx, s, p); });
    checkPunctualLightsSchema(ctx); // before the nodes that refer to them
    ctx.forEach("nodes", kRead, [&](const json& n, const std::string& p) { checkNodeSchema(ctx, n, p); });
    ctx.forEach("meshes", kRead, [&](const json& m, const std::string& p) { checkMeshSchema(ctx, m, p); });
    ctx.forEach("accessors", kRead, [&](const json& a, const std::string& p) { checkAccessorSchema(ctx, a, p); });
    ctx.forEach("bufferViews", kRead, [&](const json& b, const std::string& p) { checkBufferViewSchema(ctx, b, p); });
    ctx.forEach("buffers", kRead, [&](const json& b, const std::string& p) { checkBufferSchema(ctx, b, p); });
    ctx.forEach("materials", kRead, [&](const json& m, const std::string& p) { checkMaterialSchema(ctx, m, p); });
    ctx.forEach("textures", kRead, [&](const json& t, const std::string& p) { checkTextureSchema(ctx, t, p); });
    // Samplers are not stored in the pack (the player samples with its own filters).
    ctx.forEach("samplers", kIgnored, [&](const json& s, const std::string& p) { checkSamplerSchema(ctx, s, p); });
    ctx.forEach("images", kRead, [&](const json& i, const std::string& p) { checkImageSchema(ctx, i, p); });
    ctx.forEach("animations", kRead, [&](const json& a, const std::string& p) { checkAnimationSchema(ctx, a, p); });
    // Read by nobody: checked as warnings (the baker goes on without them).
    ctx.forEach("cameras", kIgnored, [&](const json& c, const std::string& p) { checkCameraSchema(ctx, c, p); });
    ctx.forEach("skins", kIgnored, [&](const json& s, const std::string& p) { checkSkinSchema(ctx, s, p); });
    ctx.common(document, "");
    return issues;
}

void validateGltfSemantics(const tinygltf::Model& model, const nlohmann::json& document,
                           const std::set<size_t>& buffersWithoutData, std::vector<SchemaIssue>& issues)
{
    ValidationContext ctx(document, issues);
    ModelContext mc(ctx, model, buffersWithoutData);
    // Storage before its users, and the node forest before the scenes that list roots of
    // it: the first error reported is then the cause, not a consequence (an accessor that
    // overruns its view, not the attribute counts that differ because of it; a cycle, not
    // the scene root that is consequently a child).
    checkImageViewSemantics(mc);
    checkBufferViewSemantics(mc);
    checkAccessorSemantics(mc);
    checkNodeHierarchy(mc);
    checkSceneSemantics(mc);
    checkNodeSemantics(mc);
    checkMeshSemantics(mc);
    checkAnimationSemantics(mc);
    checkSkinSemantics(mc);
}

} // namespace lfd::bake::gltf
