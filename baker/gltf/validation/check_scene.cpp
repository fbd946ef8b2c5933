// Scenes (glTF 2.0 section 3.5.1): the JSON of a scene, and that it lists root nodes only.
#include "validation/checks.h"
#include "validation/model_context.h"

#include <map>

namespace lfd::bake::gltf {

void checkSceneSchema(ValidationContext& ctx, const json& s, const std::string& path)
{
    if (const json* nodes = ctx.array(s, "nodes", path, kRead)) {
        if (nodes->empty())
            ctx.report(IssueCode::EMPTY_ARRAY, at(path, "nodes"),
                       "empty array (the schema requires at least one node, or no nodes property)");
        ctx.uniqueIndices(*nodes, at(path, "nodes"), "nodes");
    }
    ctx.common(s, path);
}

void checkSceneSemantics(ModelContext& mc)
{
    // A scene lists root nodes only ("MUST be root nodes", section 3.5.1).
    const tinygltf::Model& m = mc.model;
    std::map<int, size_t> parent;
    for (size_t n = 0; n < m.nodes.size(); ++n)
        for (int c : m.nodes[n].children)
            parent.emplace(c, n);
    for (size_t s = 0; s < m.scenes.size(); ++s)
        for (size_t i = 0; i < m.scenes[s].nodes.size(); ++i)
            if (auto it = parent.find(m.scenes[s].nodes[i]); it != parent.end())
                mc.report(IssueCode::SCENE_NON_ROOT_NODE, at(at(at("scenes", s), "nodes"), i),
                          "node " + std::to_string(m.scenes[s].nodes[i]) + " is not a root node (it is a child of nodes[" +
                              std::to_string(it->second) + "])");
}

} // namespace lfd::bake::gltf
