// Nodes (glTF 2.0 section 3.5.2, 5.25): the JSON of a node; the hierarchy (a forest), the
// matrix (decomposable into TRS) and the weights (one per morph target) of the model.
#include "validation/checks.h"
#include "validation/model_context.h"

#include <cmath>
#include <map>

namespace lfd::bake::gltf {
namespace {

// The number of punctual lights the document defines (KHR_lights_punctual).
size_t punctualLightCount(const json& root)
{
    const json* lights = extensionObject(root, "KHR_lights_punctual");
    const json* list = lights != nullptr ? member(*lights, "lights") : nullptr;
    return list != nullptr && list->is_array() ? list->size() : 0;
}

void lightReference(ValidationContext& ctx, const json& n, const std::string& path)
{
    const json* light = extensionObject(n, "KHR_lights_punctual");
    if (light == nullptr)
        return;
    const std::string p = at(at(path, "extensions"), "KHR_lights_punctual");
    if (const json* index = member(*light, "light"))
        ctx.indexInto(*index, at(p, "light"), "extensions.KHR_lights_punctual.lights", punctualLightCount(ctx.root()),
                      kRead);
    else
        ctx.report(IssueCode::MISSING_REQUIRED_PROPERTY, at(p, "light"), "required property missing");
    ctx.common(*light, p);
}

// Section 3.5.3: "matrix MUST be decomposable to TRS": an affine matrix (last row
// 0 0 0 1) whose 3x3 part is a rotation times a positive scale - orthogonal columns.
void decomposable(ModelContext& mc, const std::vector<double>& m, const std::string& path)
{
    // Column-major: column c is m[4c..4c+3].
    const bool affine = std::abs(m[3]) < 1e-6 && std::abs(m[7]) < 1e-6 && std::abs(m[11]) < 1e-6 &&
                        std::abs(m[15] - 1.0) < 1e-6;
    double len[3];
    for (int c = 0; c < 3; ++c)
        len[c] = std::sqrt(m[4 * c] * m[4 * c] + m[4 * c + 1] * m[4 * c + 1] + m[4 * c + 2] * m[4 * c + 2]);
    // A zero column is a zero scale (valid: it hides the node); others are orthogonal.
    bool orthogonal = std::isfinite(len[0] + len[1] + len[2]);
    for (int a = 0; orthogonal && a < 3; ++a)
        for (int b = a + 1; b < 3 && len[a] > 0; ++b) {
            const double dot = m[4 * a] * m[4 * b] + m[4 * a + 1] * m[4 * b + 1] + m[4 * a + 2] * m[4 * b + 2];
            if (std::abs(dot) > 1e-4 * len[a] * len[b])
                orthogonal = false;
        }
    if (!affine || !orthogonal)
        mc.report(IssueCode::NODE_MATRIX_NON_TRS, path,
                  affine ? "has shear: not decomposable into translation, rotation and scale"
                         : "has a projective last row (expected 0, 0, 0, 1): not decomposable into "
                           "translation, rotation and scale");
}

} // namespace

void checkNodeSchema(ValidationContext& ctx, const json& n, const std::string& path)
{
    ctx.indexMember(n, "camera", path, "cameras", kIgnored);
    ctx.indexMember(n, "skin", path, "skins", kIgnored);
    ctx.indexMember(n, "mesh", path, "meshes", kRead);
    lightReference(ctx, n, path);
    if (const json* children = ctx.array(n, "children", path, kRead)) {
        if (children->empty())
            ctx.report(IssueCode::EMPTY_ARRAY, at(path, "children"), "empty array (the schema requires at least one child)");
        ctx.uniqueIndices(*children, at(path, "children"), "nodes");
    }
    const json* matrix = ctx.numbers(n, "matrix", path, 16, kRead);
    const json* rotation = ctx.numbers(n, "rotation", path, 4, kRead);
    const json* scale = ctx.numbers(n, "scale", path, 3, kRead);
    const json* translation = ctx.numbers(n, "translation", path, 3, kRead);
    ctx.numbers(n, "weights", path, 0, kIgnored);
    if (rotation != nullptr) {
        double len2 = 0;
        for (const json& c : *rotation)
            len2 += c.get<double>() * c.get<double>();
        // Section 5.25 "node.rotation": a unit quaternion. The importer normalises.
        if (std::abs(std::sqrt(len2) - 1.0) > 1e-3)
            ctx.report(IssueCode::NODE_ROTATION_NON_UNIT, at(path, "rotation"),
                       "not a unit quaternion (length " + json(std::sqrt(len2)).dump() + "): normalised");
    }
    // Section 3.5.2 "Transformations": "a matrix or any combination of TRS", not both.
    // (A matrix that is not TRS: the semantic phase, decomposable().)
    if (matrix != nullptr && (rotation != nullptr || scale != nullptr || translation != nullptr))
        ctx.report(IssueCode::NODE_MATRIX_TRS, at(path, "matrix"),
                   "given together with translation/rotation/scale (a node has one or the other)");
    ctx.common(n, path);
}

// Section 3.5.2: the nodes form a forest - no node is the child of two nodes or its own
// ancestor.
void checkNodeHierarchy(ModelContext& mc)
{
    const std::vector<tinygltf::Node>& nodes = mc.model.nodes;
    std::map<int, size_t> parent;
    for (size_t n = 0; n < nodes.size(); ++n)
        for (size_t i = 0; i < nodes[n].children.size(); ++i) {
            const int c = nodes[n].children[i];
            if (c < 0 || size_t(c) >= nodes.size())
                continue;
            const auto [it, fresh] = parent.emplace(c, n);
            if (!fresh && it->second != n)
                mc.report(IssueCode::NODE_MULTIPLE_PARENTS, at(at(at("nodes", n), "children"), i),
                          "node " + std::to_string(c) + " is already a child of nodes[" + std::to_string(it->second) +
                              "]");
        }
    for (size_t n = 0; n < nodes.size(); ++n) {
        // Walk up at most as many parents as there are nodes: longer means a cycle.
        int current = int(n);
        for (size_t steps = 0; steps <= nodes.size(); ++steps) {
            const auto it = parent.find(current);
            if (it == parent.end())
                break;
            current = int(it->second);
            if (current == int(n)) {
                mc.report(IssueCode::NODE_LOOP, at("nodes", n), "is its own ancestor (the children form a cycle)");
                break;
            }
        }
    }
}

void checkNodeSemantics(ModelContext& mc)
{
    for (size_t n = 0; n < mc.model.nodes.size(); ++n) {
        const tinygltf::Node& node = mc.model.nodes[n];
        const std::string path = at("nodes", n);
        // Section 3.5.2: "a matrix or any combination of TRS, not both".
        // (Matrix and TRS together: the schema phase; tinygltf keeps only the matrix.)
        if (node.matrix.size() == 16)
            decomposable(mc, node.matrix, at(path, "matrix"));
        // Section 3.7.2.2: node weights override the mesh's, one per morph target.
        if (!node.weights.empty() && node.weights.size() != mc.morphTargets(node.mesh))
            mc.report(IssueCode::WEIGHTS_COUNT_MISMATCH, at(path, "weights"),
                      std::to_string(node.weights.size()) + " weights, but meshes[" + std::to_string(node.mesh) +
                          "] has " + std::to_string(mc.morphTargets(node.mesh)) + " morph targets");
    }
}

} // namespace lfd::bake::gltf
