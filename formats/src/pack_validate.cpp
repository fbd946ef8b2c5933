// Semantic rules of a Scene, stated once and applied both before writing a pack and
// after decoding one: index and reference ranges, enum values, key times, mip chains and
// finite floats. Sizes here are already bounded by the bytes present (the decoder checks
// counts against section sizes before allocating), so nothing here allocates.
#include "pack_internal.h"

#include <cmath>
#include <string>

namespace lfd::pack {

namespace {

// A reference is either kNone or a valid index into a table of `count` entries.
bool validReference(int32_t ref, size_t count) { return ref == kNone || (ref >= 0 && size_t(ref) < count); }

class SceneChecker {
public:
    SceneChecker(const Scene& scene, const std::string& name, TexelPolicy texels)
        : scene_(scene), name_(name), texels_(texels)
    {
    }

    void run()
    {
        checkVertices();
        checkIndices();
        checkTriangleStats();
        checkPrimitivesAndMeshes();
        checkMaterials();
        checkTextures();
        checkNodes();
        checkAnimations();
        checkBoundsAndSettings();
        validateDeformation(scene_, name_);
        validateLights(scene_, name_);
    }

private:
    [[noreturn]] void fail(const std::string& problem) const { pack::fail(name_, problem); }

    template <typename Vec>
    void checkStream(const Vec& stream, const char* what) const
    {
        const size_t n = scene_.vertices.positions.size();
        if (!stream.empty() && stream.size() != n)
            fail(std::string("vertex stream '") + what + "' has " + std::to_string(stream.size()) +
                 " entries but there are " + std::to_string(n) + " positions");
        for (size_t v = 0; v < stream.size(); ++v)
            if (!finite(stream[v]))
                fail(std::string("vertex ") + std::to_string(v) + ": " + what + " is not finite");
    }

    void checkVertices() const
    {
        checkStream(scene_.vertices.positions, "position");
        checkStream(scene_.vertices.normals, "normal");
        checkStream(scene_.vertices.tangents, "tangent");
        checkStream(scene_.vertices.uvs, "uv");
    }

    void checkIndices() const
    {
        const auto& indices = scene_.indices;
        if (indices.size() % 3 != 0)
            fail("index count " + std::to_string(indices.size()) + " is not a multiple of 3");
        const size_t vertexCount = scene_.vertices.positions.size();
        for (size_t i = 0; i < indices.size(); ++i)
            if (indices[i] >= vertexCount)
                fail("index " + std::to_string(i) + " (triangle " + std::to_string(i / 3) + ") is " +
                     std::to_string(indices[i]) + " but there are " + std::to_string(vertexCount) +
                     " vertices");
    }

    void checkTriangleStats() const
    {
        const auto& stats = scene_.triangleStats;
        if (stats.size() != scene_.triangleCount())
            fail("there are " + std::to_string(stats.size()) + " triangle statistics for " +
                 std::to_string(scene_.triangleCount()) + " triangles");
        constexpr uint32_t kKnownFlags = kTriangleTextured | kTriangleDegenerate;
        for (size_t t = 0; t < stats.size(); ++t) {
            const TriangleStats& s = stats[t];
            if (!finite(s.areaWorld) || !finite(s.areaTexture) || !finite(s.texelCount) || !finite(s.sizeUv) ||
                !finite(s.texPerWorld))
                fail("triangle " + std::to_string(t) + ": statistics are not finite");
            if (s.flags & ~kKnownFlags)
                fail("triangle " + std::to_string(t) + ": unknown flags 0x" + hex(s.flags));
        }
    }

    void checkPrimitivesAndMeshes() const
    {
        const auto& primitives = scene_.primitives;
        for (size_t p = 0; p < primitives.size(); ++p) {
            const Primitive& prim = primitives[p];
            const std::string where = "primitive " + std::to_string(p) + ": ";
            if (prim.firstIndex % 3 != 0 || prim.indexCount % 3 != 0)
                fail(where + "index range [" + std::to_string(prim.firstIndex) + ", +" +
                     std::to_string(prim.indexCount) + ") is not made of whole triangles");
            if (uint64_t(prim.firstIndex) + prim.indexCount > scene_.indices.size())
                fail(where + "index range [" + std::to_string(prim.firstIndex) + ", +" +
                     std::to_string(prim.indexCount) + ") exceeds the " + std::to_string(scene_.indices.size()) +
                     " indices");
            if (!validReference(prim.material, scene_.materials.size()))
                fail(where + "material " + std::to_string(prim.material) + " does not exist (" +
                     std::to_string(scene_.materials.size()) + " materials)");
        }
        for (size_t m = 0; m < scene_.meshes.size(); ++m) {
            const Mesh& mesh = scene_.meshes[m];
            if (uint64_t(mesh.firstPrimitive) + mesh.primitiveCount > primitives.size())
                fail("mesh " + std::to_string(m) + ": primitive range [" + std::to_string(mesh.firstPrimitive) +
                     ", +" + std::to_string(mesh.primitiveCount) + ") exceeds the " +
                     std::to_string(primitives.size()) + " primitives");
        }
    }

    void checkMaterials() const
    {
        const size_t textureCount = scene_.textures.size();
        for (size_t m = 0; m < scene_.materials.size(); ++m) {
            const Material& mat = scene_.materials[m];
            const std::string where = "material " + std::to_string(m) + ": ";
            if (!finite(mat.baseColorFactor) || !finite(mat.emissiveFactor) || !finite(mat.metallicFactor) ||
                !finite(mat.roughnessFactor) || !finite(mat.normalScale) || !finite(mat.occlusionStrength) ||
                !finite(mat.alphaCutoff))
                fail(where + "factors are not finite");
            if (uint32_t(mat.alphaMode) > uint32_t(AlphaMode::Blend))
                fail(where + "invalid alpha mode " + std::to_string(uint32_t(mat.alphaMode)));
            for (const TextureTransform& t : mat.textureTransforms)
                if (!finite(t.linear[0]) || !finite(t.linear[1]) || !finite(t.offset))
                    fail(where + "texture transform is not finite");
            const struct {
                const char* slot;
                int32_t ref;
            } slots[] = {{"baseColor", mat.baseColorTexture},
                         {"metallicRoughness", mat.metallicRoughnessTexture},
                         {"normal", mat.normalTexture},
                         {"occlusion", mat.occlusionTexture},
                         {"emissive", mat.emissiveTexture}};
            for (const auto& s : slots)
                if (!validReference(s.ref, textureCount))
                    fail(where + s.slot + " texture " + std::to_string(s.ref) + " does not exist (" +
                         std::to_string(textureCount) + " textures)");
        }
    }

    static bool sameLevels(const std::vector<MipLevel>& a, const std::vector<MipLevel>& b)
    {
        if (a.size() != b.size())
            return false;
        for (size_t l = 0; l < a.size(); ++l)
            if (a[l].width != b[l].width || a[l].height != b[l].height || a[l].offset != b[l].offset ||
                a[l].size != b[l].size)
                return false;
        return true;
    }

    void checkTextures() const
    {
        for (size_t t = 0; t < scene_.textures.size(); ++t) {
            const Texture& tex = scene_.textures[t];
            const std::string where = "texture " + std::to_string(t) + ": ";
            if (tex.width == 0 || tex.height == 0 || tex.width > kMaxTextureDimension ||
                tex.height > kMaxTextureDimension)
                fail(where + "size " + std::to_string(tex.width) + "x" + std::to_string(tex.height) +
                     " is outside 1.." + std::to_string(kMaxTextureDimension));
            const bool mipsOptional = texels_ == TexelPolicy::MetadataOnly && tex.mips.empty();
            if (uint32_t(tex.format) >= kTextureFormatCount)
                fail(where + "unknown format " + std::to_string(uint32_t(tex.format)));
            const std::vector<MipLevel> chain = textureMipChain(tex.width, tex.height, tex.format);
            if (!mipsOptional && !sameLevels(tex.mips, chain))
                fail(where + "mip levels are not the full chain of a " + std::to_string(tex.width) + "x" +
                     std::to_string(tex.height) + " " + textureFormatName(tex.format) + " texture (" +
                     std::to_string(tex.mips.size()) + " levels given, " + std::to_string(chain.size()) +
                     " expected)");
            const uint64_t bytes = textureChainBytes(tex.width, tex.height, tex.format);
            if (texels_ == TexelPolicy::Required && tex.texels.size() != bytes)
                fail(where + "has " + std::to_string(tex.texels.size()) + " texel bytes, its mip chain needs " +
                     std::to_string(bytes));
        }
    }

    void checkNodes() const
    {
        const auto& nodes = scene_.nodes;
        for (size_t n = 0; n < nodes.size(); ++n) {
            const Node& node = nodes[n];
            const std::string where = "node " + std::to_string(n) + ": ";
            if (node.parent != kNone && (node.parent < 0 || size_t(node.parent) >= n))
                fail(where + "parent " + std::to_string(node.parent) + " does not precede the node");
            if (!validReference(node.mesh, scene_.meshes.size()))
                fail(where + "mesh " + std::to_string(node.mesh) + " does not exist (" +
                     std::to_string(scene_.meshes.size()) + " meshes)");
            if (!finite(node.translation) || !finite(node.rotation) || !finite(node.scale))
                fail(where + "transform is not finite");
        }
    }

    void checkAnimations() const
    {
        for (size_t a = 0; a < scene_.animations.size(); ++a) {
            const Animation& anim = scene_.animations[a];
            for (size_t c = 0; c < anim.channels.size(); ++c) {
                const AnimationChannel& ch = anim.channels[c];
                const std::string where = "animation " + std::to_string(a) + " channel " + std::to_string(c) + ": ";
                if (ch.node >= scene_.nodes.size())
                    fail(where + "node " + std::to_string(ch.node) + " does not exist (" +
                         std::to_string(scene_.nodes.size()) + " nodes)");
                if (uint32_t(ch.path) > uint32_t(AnimationPath::Weights))
                    fail(where + "invalid path " + std::to_string(uint32_t(ch.path)));
                if (uint32_t(ch.interpolation) > uint32_t(Interpolation::Step))
                    fail(where + "invalid interpolation " + std::to_string(uint32_t(ch.interpolation)));
                if (ch.times.empty())
                    fail(where + "has no keys");
                if (ch.values.size() != ch.times.size())
                    fail(where + std::to_string(ch.values.size()) + " values for " + std::to_string(ch.times.size()) +
                         " key times");
                for (size_t k = 0; k < ch.times.size(); ++k) {
                    if (!finite(ch.times[k]) || !finite(ch.values[k]))
                        fail(where + "key " + std::to_string(k) + " is not finite");
                    if (k > 0 && !(ch.times[k] > ch.times[k - 1]))
                        fail(where + "key times are not strictly increasing at key " + std::to_string(k));
                }
            }
        }
    }

    void checkBoundsAndSettings() const
    {
        const SceneBounds& b = scene_.bounds;
        if (!finite(b.min) || !finite(b.max) || !finite(b.center) || !finite(b.radius))
            fail("scene bounds are not finite");
        if (b.radius < 0.0f)
            fail("scene bounds radius is negative");
        const BakeSettings& s = scene_.settings;
        if (!finite(s.maxEdgePx) || !finite(s.framingFill) || !finite(s.viewPixelWorld))
            fail("bake settings are not finite");
    }

    static std::string hex(uint32_t v)
    {
        static const char kDigits[] = "0123456789abcdef";
        std::string out;
        for (int shift = 28; shift >= 0; shift -= 4)
            out += kDigits[(v >> shift) & 15];
        return out;
    }

    const Scene& scene_;
    const std::string& name_;
    TexelPolicy texels_;
};

} // namespace

void validateScene(const Scene& scene, const std::string& name, TexelPolicy texels)
{
    SceneChecker(scene, name, texels).run();
}

} // namespace lfd::pack
