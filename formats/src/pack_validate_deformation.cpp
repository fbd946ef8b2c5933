// The scene rules of deformation (formats/README.md "Deformation"): skin influences, morph
// deltas, skins, deformers and weight channels. Part of validateScene, so the writer
// refuses what the reader would reject.
#include "pack_internal.h"

#include <cmath>

namespace lfd::pack {
namespace {

class DeformationChecker {
public:
    DeformationChecker(const Scene& scene, const std::string& name) : scene_(scene), name_(name) {}

    void run() const
    {
        checkStreams();
        checkSkins();
        checkDeformers();
        checkWeightChannels();
    }

private:
    [[noreturn]] void fail(const std::string& problem) const { pack::fail(name_, problem); }

    template <typename Vec>
    void checkArray(const std::vector<Vec>& values, size_t expected, const char* what) const
    {
        if (!values.empty() && values.size() != expected)
            fail(std::string("'") + what + "' has " + std::to_string(values.size()) + " entries, expected " +
                 std::to_string(expected));
        for (size_t i = 0; i < values.size(); ++i)
            if (!finite(values[i]))
                fail(std::string("'") + what + "' entry " + std::to_string(i) + " is not finite");
    }

    void checkStreams() const
    {
        const DeformationStreams& d = scene_.vertices.deform;
        const size_t n = scene_.vertices.positions.size();
        if (d.joints.empty() != d.weights.empty())
            fail("skin joints and weights must be stored together");
        checkArray(d.joints, n, "VJNT");
        checkArray(d.weights, n, "VWGT");
        for (size_t v = 0; v < d.weights.size(); ++v)
            if (glm::any(glm::lessThan(d.weights[v], glm::vec4(0.0f))))
                fail("vertex " + std::to_string(v) + ": negative skin weight");
        if (d.morphTargets == 0 && !(d.positions.empty() && d.normals.empty() && d.tangents.empty()))
            fail("morph deltas without morph targets");
        const size_t deltas = n * d.morphTargets;
        if (d.positions.size() != deltas)
            fail("'MPOS' has " + std::to_string(d.positions.size()) + " entries, expected " + std::to_string(deltas));
        checkArray(d.positions, deltas, "MPOS");
        checkArray(d.normals, deltas, "MNRM");
        checkArray(d.tangents, deltas, "MTAN");
        if (!d.normals.empty() && scene_.vertices.normals.empty())
            fail("normal morph deltas without normals");
        if (!d.tangents.empty() && scene_.vertices.tangents.empty())
            fail("tangent morph deltas without tangents");
    }

    void checkSkins() const
    {
        for (size_t s = 0; s < scene_.skins.size(); ++s) {
            const Skin& skin = scene_.skins[s];
            const std::string where = "skin " + std::to_string(s) + ": ";
            if (skin.joints.empty() || skin.joints.size() != skin.inverseBindMatrices.size())
                fail(where + std::to_string(skin.joints.size()) + " joints and " +
                     std::to_string(skin.inverseBindMatrices.size()) + " inverse bind matrices");
            for (size_t j = 0; j < skin.joints.size(); ++j) {
                if (skin.joints[j] >= scene_.nodes.size())
                    fail(where + "joint " + std::to_string(j) + " is node " + std::to_string(skin.joints[j]) +
                         ", which does not exist");
                for (int c = 0; c < 4; ++c)
                    if (!finite(skin.inverseBindMatrices[j][c]))
                        fail(where + "inverse bind matrix " + std::to_string(j) + " is not finite");
            }
        }
    }

    void checkDeformer(size_t i, uint64_t& end) const
    {
        const Deformer& d = scene_.deformers[i];
        const DeformationStreams& s = scene_.vertices.deform;
        const std::string where = "deformer " + std::to_string(i) + ": ";
        if (d.node >= scene_.nodes.size() || scene_.nodes[d.node].mesh == kNone)
            fail(where + "node " + std::to_string(d.node) + " does not exist or has no mesh");
        if (d.skin != kNone && (d.skin < 0 || size_t(d.skin) >= scene_.skins.size() || !s.skinned()))
            fail(where + "skin " + std::to_string(d.skin) + " does not exist or the vertices have no joints");
        if (d.firstVertex < end || uint64_t(d.firstVertex) + d.vertexCount > scene_.vertices.positions.size())
            fail(where + "vertices [" + std::to_string(d.firstVertex) + ", +" + std::to_string(d.vertexCount) +
                 ") overlap the previous deformer's or lie outside the vertex streams");
        end = uint64_t(d.firstVertex) + d.vertexCount;
        if (d.weights.size() != s.morphTargets)
            fail(where + std::to_string(d.weights.size()) + " morph weights for " + std::to_string(s.morphTargets) +
                 " targets");
        for (float w : d.weights)
            if (!std::isfinite(w))
                fail(where + "morph weight is not finite");
        if (d.skin == kNone)
            return;
        const size_t joints = scene_.skins[size_t(d.skin)].joints.size();
        for (size_t v = d.firstVertex; v < end; ++v)
            if (glm::any(glm::greaterThanEqual(s.joints[v], glm::uvec4(uint32_t(joints)))))
                fail(where + "vertex " + std::to_string(v) + " names a joint past the skin's " +
                     std::to_string(joints));
    }

    void checkDeformers() const
    {
        uint64_t end = 0;
        for (size_t i = 0; i < scene_.deformers.size(); ++i)
            checkDeformer(i, end);
    }

    void checkWeightChannels() const
    {
        std::vector<bool> deformed(scene_.nodes.size(), false);
        for (const Deformer& d : scene_.deformers)
            deformed[d.node] = true;
        for (size_t a = 0; a < scene_.animations.size(); ++a)
            for (const AnimationChannel& ch : scene_.animations[a].channels) {
                if (ch.path != AnimationPath::Weights)
                    continue;
                if (ch.node >= deformed.size() || !deformed[ch.node] || ch.weightOffset % 4 != 0 ||
                    ch.weightOffset >= scene_.vertices.deform.morphTargets)
                    fail("animation " + std::to_string(a) + ": weights channel on node " + std::to_string(ch.node) +
                         " (offset " + std::to_string(ch.weightOffset) + ") drives no morph target of a deformer");
            }
    }

    const Scene& scene_;
    const std::string& name_;
};

} // namespace

void validateDeformation(const Scene& scene, const std::string& name)
{
    DeformationChecker(scene, name).run();
}

} // namespace lfd::pack
