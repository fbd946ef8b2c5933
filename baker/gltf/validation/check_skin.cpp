// Skins (glTF 2.0 sections 3.7.3, 5.28): the JSON of a skin; its inverse bind matrices,
// joint hierarchy and skeleton. The baker does not pose skins, so every finding is a
// warning.
#include "validation/checks.h"
#include "validation/model_context.h"

#include <map>

namespace lfd::bake::gltf {
namespace {

// The node forest's parent links, walked up at most as many steps as there are nodes.
class Ancestry {
public:
    explicit Ancestry(const std::vector<tinygltf::Node>& nodes) : steps_(nodes.size())
    {
        for (size_t n = 0; n < nodes.size(); ++n)
            for (int c : nodes[n].children)
                parent_.emplace(c, int(n));
    }
    int root(int n) const
    {
        for (size_t steps = 0; steps <= steps_ && parent_.count(n); ++steps)
            n = parent_.at(n);
        return n;
    }
    bool isAncestor(int ancestor, int n) const
    {
        for (size_t steps = 0; steps <= steps_; ++steps) {
            if (n == ancestor)
                return true;
            if (!parent_.count(n))
                return false;
            n = parent_.at(n);
        }
        return false;
    }

private:
    size_t steps_;
    std::map<int, int> parent_;
};

void inverseBindMatrices(ModelContext& mc, const json& skin, const std::string& path, size_t joints)
{
    const json* ibm = member(skin, "inverseBindMatrices");
    if (!ibm || !ibm->is_number_integer() || !mc.validAccessor(int(ibm->get<int64_t>())))
        return;
    const int a = int(ibm->get<int64_t>());
    const tinygltf::Accessor& acc = mc.model.accessors[size_t(a)];
    const std::string p = at(path, "inverseBindMatrices");
    if (acc.type != TINYGLTF_TYPE_MAT4 || acc.componentType != kFloat)
        mc.report(IssueCode::ACCESSOR_WRONG_FORMAT, p, formatOf(a, acc, false) + ", not MAT4/FLOAT", kIgnored);
    if (acc.count < joints)
        mc.report(IssueCode::SKIN_TOO_FEW_MATRICES, p,
                  accessorPath(a) + " has " + std::to_string(acc.count) + " matrices for " + std::to_string(joints) +
                      " joints");
    if (mc.viewStride(a) != 0)
        mc.report(IssueCode::SKIN_IBM_ACCESSOR_WITH_BYTESTRIDE, p, accessorPath(a) + " lies in a buffer view with a byteStride");
}

void skin(ModelContext& mc, const Ancestry& ancestry, const json& skin, const std::string& path)
{
    std::vector<int> joints;
    if (const json* j = member(skin, "joints"); j && j->is_array())
        for (const json& v : *j)
            if (v.is_number_integer() && v.get<int64_t>() >= 0 && size_t(v.get<int64_t>()) < mc.model.nodes.size())
                joints.push_back(int(v.get<int64_t>()));
    inverseBindMatrices(mc, skin, path, joints.size());
    if (joints.empty())
        return;
    const int common = ancestry.root(joints[0]);
    for (size_t i = 1; i < joints.size(); ++i)
        if (ancestry.root(joints[i]) != common) {
            mc.report(IssueCode::SKIN_NO_COMMON_ROOT, at(path, "joints"), "the joints do not share a common root");
            break;
        }
    if (const json* s = member(skin, "skeleton"); s && s->is_number_integer())
        for (int j : joints)
            if (!ancestry.isAncestor(int(s->get<int64_t>()), j)) {
                mc.report(IssueCode::SKIN_SKELETON_INVALID, at(path, "skeleton"),
                          "is not an ancestor of every joint (nodes[" + std::to_string(j) + "])");
                break;
            }
}

} // namespace

void checkSkinSchema(ValidationContext& ctx, const json& s, const std::string& path)
{
    ctx.indexMember(s, "inverseBindMatrices", path, "accessors", kIgnored);
    ctx.indexMember(s, "skeleton", path, "nodes", kIgnored);
    if (const json* joints = ctx.array(s, "joints", path, kIgnored, true)) {
        if (joints->empty())
            ctx.report(IssueCode::EMPTY_ARRAY, at(path, "joints"), "empty array (a skin has at least one joint)");
        for (size_t i = 0; i < joints->size(); ++i)
            ctx.index((*joints)[i], at(at(path, "joints"), i), "nodes", kIgnored);
    }
    ctx.common(s, path);
}

void checkSkinSemantics(ModelContext& mc)
{
    for (size_t n = 0; n < mc.model.nodes.size(); ++n)
        if (mc.model.nodes[n].skin >= 0 && mc.model.nodes[n].mesh < 0)
            mc.report(IssueCode::PROPERTY_NOT_APPLICABLE, at(at("nodes", n), "skin"),
                      "given for a node without a mesh: ignored");
    const Ancestry ancestry(mc.model.nodes);
    const json* skins = member(mc.doc, "skins");
    for (size_t k = 0; skins && skins->is_array() && k < skins->size(); ++k)
        skin(mc, ancestry, (*skins)[k], at("skins", k));
}

} // namespace lfd::bake::gltf
