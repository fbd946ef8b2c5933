// Sections -> Scene. Runs after validateStructure, so every known section lies inside
// the buffer and its count matches its size: allocations sized from counts are bounded
// by the bytes present. Cross-section runs (strings, channels, keys, mips, texels) are
// checked here before they drive a copy; the remaining rules are validateScene's.
#include "pack_internal.h"

#include "lfd/pack_mapped.h"

#include <cstring>

namespace lfd::pack {

namespace {

class Decoder {
public:
    Decoder(const uint8_t* data, const SectionTable& table, const std::string& name, TexelMode texels,
            std::vector<StoredTexture>* stored)
        : data_(data), table_(table), name_(name), texelMode_(texels), stored_(stored)
    {
        const SectionEntry& strings = section(kTagStrings);
        strings_ = at(strings);
        stringBytes_ = strings.count;
    }

    Scene run()
    {
        Scene scene;
        decodeSettings(scene.settings);
        decodeBounds(scene.bounds);
        decodeVertices(scene.vertices);
        scene.indices = array<uint32_t>(kTagIndices);
        scene.triangleStats = array<TriangleStats>(kTagTriangleStats);
        decodePrimitives(scene.primitives);
        decodeMeshes(scene.meshes);
        decodeMaterials(scene.materials);
        decodeMaterialExtensions(scene.materials);
        decodeTextures(scene.textures);
        decodeNodes(scene.nodes);
        decodeLights(scene.lights);
        decodeAnimations(scene.animations);
        decodeDeformation(scene);
        return scene;
    }

private:
    [[noreturn]] void fail(const std::string& problem) const { pack::fail(name_, problem); }

    const SectionEntry& section(uint32_t tag) const { return *table_.find(tag); } // required: present
    // A section's content (inflated when stored with zstd): count * stride bytes.
    const uint8_t* at(const SectionEntry& e) const { return table_.payload(data_, e); }

    template <typename T>
    std::vector<T> array(uint32_t tag) const
    {
        const SectionEntry* e = table_.find(tag);
        std::vector<T> out;
        if (!e)
            return out;
        out.resize(size_t(e->count));
        if (e->count != 0)
            std::memcpy(out.data(), at(*e), size_t(e->count) * sizeof(T));
        return out;
    }

    template <typename Record>
    Record record(const SectionEntry& e, uint64_t i) const
    {
        Record r;
        std::memcpy(&r, at(e) + i * sizeof(Record), sizeof r);
        return r;
    }

    // Strings may not be shared: their lengths add up to at most the STRS size, so no
    // pack can make the reader allocate more name bytes than it holds.
    std::string string(StringRef ref, const std::string& what)
    {
        if (uint64_t(ref.offset) + ref.length > stringBytes_)
            fail(what + ": name [" + std::to_string(ref.offset) + ", +" + std::to_string(ref.length) +
                 ") is outside the " + std::to_string(stringBytes_) + "-byte string section");
        stringTotal_ += ref.length;
        if (stringTotal_ > stringBytes_)
            fail(what + ": names add up to more bytes than the string section holds");
        return std::string(reinterpret_cast<const char*>(strings_ + ref.offset), ref.length);
    }

    void reserved(uint64_t value, const std::string& what) const
    {
        if (value != 0)
            fail(what + ": non-zero reserved field");
    }

    void decodeSettings(BakeSettings& s)
    {
        const auto r = record<BakeSettingsRecord>(section(kTagBakeSettings), 0);
        s.bakerVersion = string(r.bakerVersion, "bake settings");
        s.sourceFile = string(r.sourceFile, "bake settings");
        s.displayProfile = string(r.displayProfile, "bake settings");
        s.viewWidth = r.viewWidth;
        s.viewHeight = r.viewHeight;
        s.viewCount = r.viewCount;
        s.maxTextureSize = r.maxTextureSize;
        s.maxEdgePx = r.maxEdgePx;
        s.framingFill = r.framingFill;
        s.viewPixelWorld = r.viewPixelWorld;
        reserved(uint64_t(r.reserved[0]) | r.reserved[1] | r.reserved[2], "bake settings");
    }

    void decodeBounds(SceneBounds& b) const
    {
        const auto r = record<BoundsRecord>(section(kTagBounds), 0);
        std::memcpy(&b.min, r.min, sizeof r.min);
        std::memcpy(&b.max, r.max, sizeof r.max);
        std::memcpy(&b.center, r.center, sizeof r.center);
        b.radius = r.radius;
        reserved(uint64_t(r.reserved0) | r.reserved1, "scene bounds");
    }

    void decodeVertices(VertexStreams& v) const
    {
        v.positions = array<glm::vec3>(kTagPositions);
        v.normals = array<glm::vec3>(kTagNormals);
        v.tangents = array<glm::vec4>(kTagTangents);
        v.uvs = array<glm::vec2>(kTagUvs);
    }

    void decodePrimitives(std::vector<Primitive>& primitives) const
    {
        const SectionEntry& e = section(kTagPrimitives);
        primitives.resize(size_t(e.count));
        for (uint64_t i = 0; i < e.count; ++i) {
            const auto r = record<PrimitiveRecord>(e, i);
            reserved(r.reserved, "primitive " + std::to_string(i));
            primitives[i] = Primitive{r.firstIndex, r.indexCount, r.material};
        }
    }

    void decodeMeshes(std::vector<Mesh>& meshes)
    {
        const SectionEntry& e = section(kTagMeshes);
        meshes.resize(size_t(e.count));
        for (uint64_t i = 0; i < e.count; ++i) {
            const auto r = record<MeshRecord>(e, i);
            Mesh& m = meshes[i];
            m.name = string(r.name, "mesh " + std::to_string(i));
            m.firstPrimitive = r.firstPrimitive;
            m.primitiveCount = r.primitiveCount;
        }
    }

    void decodeMaterials(std::vector<Material>& materials)
    {
        const SectionEntry& e = section(kTagMaterials);
        materials.resize(size_t(e.count));
        for (uint64_t i = 0; i < e.count; ++i) {
            const auto r = record<MaterialRecord>(e, i);
            const std::string where = "material " + std::to_string(i);
            Material& m = materials[i];
            m.name = string(r.name, where);
            std::memcpy(&m.baseColorFactor, r.baseColorFactor, sizeof r.baseColorFactor);
            std::memcpy(&m.emissiveFactor, r.emissiveFactor, sizeof r.emissiveFactor);
            m.metallicFactor = r.metallicFactor;
            m.roughnessFactor = r.roughnessFactor;
            m.normalScale = r.normalScale;
            m.occlusionStrength = r.occlusionStrength;
            m.alphaCutoff = r.alphaCutoff;
            m.alphaMode = AlphaMode(r.alphaMode); // range checked by validateScene
            if (r.doubleSided > 1)
                fail(where + ": doubleSided is " + std::to_string(r.doubleSided) + ", must be 0 or 1");
            m.doubleSided = r.doubleSided == 1;
            m.baseColorTexture = r.baseColorTexture;
            m.metallicRoughnessTexture = r.metallicRoughnessTexture;
            m.normalTexture = r.normalTexture;
            m.occlusionTexture = r.occlusionTexture;
            m.emissiveTexture = r.emissiveTexture;
            reserved(uint64_t(r.reserved0) | r.reserved1[0] | r.reserved1[1], where);
        }
    }

    // MEXT (optional): one record per MATL record, in the same order.
    void decodeMaterialExtensions(std::vector<Material>& materials) const
    {
        const SectionEntry* e = table_.find(kTagMaterialExtensions);
        if (!e)
            return;
        if (e->count != materials.size())
            fail("'MEXT' holds " + std::to_string(e->count) + " records for " + std::to_string(materials.size()) +
                 " materials");
        for (uint64_t i = 0; i < e->count; ++i) {
            const auto r = record<MaterialExtensionRecord>(*e, i);
            const std::string where = "material " + std::to_string(i) + " extensions";
            if (r.flags & ~kMaterialUnlit)
                fail(where + ": unknown flags " + std::to_string(r.flags));
            reserved(uint64_t(r.reserved[0]) | r.reserved[1] | r.reserved[2], where);
            Material& m = materials[size_t(i)];
            m.unlit = (r.flags & kMaterialUnlit) != 0;
            for (uint32_t slot = 0; slot < kTextureSlotCount; ++slot) {
                const UvTransformRecord& uv = r.uvTransforms[slot];
                reserved(uint64_t(uv.reserved[0]) | uv.reserved[1], where);
                std::memcpy(&m.textureTransforms[slot].linear[0][0], uv.linear, sizeof uv.linear);
                std::memcpy(&m.textureTransforms[slot].offset, uv.offset, sizeof uv.offset);
            }
        }
    }

    // Textures own consecutive runs of MIPS and TEXL, in order, covering both sections.
    void decodeTextures(std::vector<Texture>& textures)
    {
        const SectionEntry& e = section(kTagTextures);
        const SectionEntry& mips = section(kTagMipLevels);
        const SectionEntry& texels = section(kTagTexels);
        textures.resize(size_t(e.count));
        if (stored_)
            stored_->assign(size_t(e.count), StoredTexture{});
        uint64_t nextMip = 0;
        uint64_t nextTexel = 0;
        for (uint64_t i = 0; i < e.count; ++i) {
            const auto r = record<TextureRecord>(e, i);
            const std::string where = "texture " + std::to_string(i);
            Texture& t = textures[i];
            decodeTextureRecord(r, where, t);

            // Mip chain: the full chain, stored as the next run of MIPS records.
            const bool zstd = (r.flags & kTextureZstdLevels) != 0;
            const std::vector<MipLevel> chain = textureMipChain(r.width, r.height, t.format);
            if (r.mipCount != chain.size())
                fail(where + ": " + std::to_string(r.mipCount) + " mip levels, a " + std::to_string(r.width) + "x" +
                     std::to_string(r.height) + " texture has " + std::to_string(chain.size()));
            if (r.firstMip != nextMip || mips.count - nextMip < chain.size())
                fail(where + ": mip levels [" + std::to_string(r.firstMip) + ", +" + std::to_string(r.mipCount) +
                     ") do not follow the previous texture's within the " + std::to_string(mips.count) +
                     " mip records");
            std::vector<std::pair<uint64_t, uint64_t>> levels; // stored (offset, size) relative to the texture
            uint64_t storedOffset = 0;
            for (uint32_t l = 0; l < chain.size(); ++l) {
                const auto m = record<MipRecord>(mips, nextMip + l);
                checkStoredLevel(m, chain[l], storedOffset, zstd, where + ": mip level " + std::to_string(l));
                levels.emplace_back(m.offset, m.size);
                storedOffset += m.size;
            }
            nextMip += chain.size();
            t.mips = chain;

            // Texels: the next run of TEXL, exactly the stored chain's size.
            if (r.texelOffset != nextTexel || r.texelSize != storedOffset || texels.size - nextTexel < storedOffset)
                fail(where + ": texels [" + std::to_string(r.texelOffset) + ", +" + std::to_string(r.texelSize) +
                     ") are not the next " + std::to_string(storedOffset) + " bytes of the " +
                     std::to_string(texels.size) + "-byte texel section");
            const uint8_t* base = data_ + texels.offset + nextTexel;
            readTexels(t, base, levels, zstd, where);
            if (stored_) {
                StoredTexture& s = (*stored_)[size_t(i)];
                s.zstd = zstd;
                for (const auto& [offset, size] : levels)
                    s.levels.emplace_back(nextTexel + offset, size);
            }
            nextTexel += storedOffset;
        }
        if (nextMip != mips.count)
            fail("textures use " + std::to_string(nextMip) + " of " + std::to_string(mips.count) + " mip records");
        if (nextTexel != texels.size)
            fail("textures use " + std::to_string(nextTexel) + " of " + std::to_string(texels.size) + " texel bytes");
    }

    void decodeTextureRecord(const TextureRecord& r, const std::string& where, Texture& t)
    {
        t.name = string(r.name, where);
        if (r.width == 0 || r.height == 0 || r.width > kMaxTextureDimension || r.height > kMaxTextureDimension)
            fail(where + ": size " + std::to_string(r.width) + "x" + std::to_string(r.height) + " is outside 1.." +
                 std::to_string(kMaxTextureDimension));
        t.width = r.width;
        t.height = r.height;
        t.sourceWidth = r.sourceWidth;
        t.sourceHeight = r.sourceHeight;
        const bool version1 = table_.info.formatVersion == 1;
        const uint32_t knownFlags = version1 ? kTextureSrgb : kTextureSrgb | kTextureZstdLevels;
        if (r.flags & ~knownFlags)
            fail(where + ": unknown flags " + std::to_string(r.flags));
        t.srgb = (r.flags & kTextureSrgb) != 0;
        if (version1)
            reserved(r.format, where);
        if (r.format >= kTextureFormatCount)
            fail(where + ": unknown format " + std::to_string(r.format));
        t.format = TextureFormat(r.format);
        reserved(r.reserved1, where);
    }

    // Raw levels are exactly the decoded layout; zstd levels are back to back, non-empty,
    // and may not claim to expand beyond kZstdMaxRatio (checked again when inflated).
    void checkStoredLevel(const MipRecord& m, const MipLevel& want, uint64_t storedOffset, bool zstd,
                          const std::string& where) const
    {
        const bool sizeOk = zstd ? m.size > 0 && want.size <= maxInflatedBytes(m.size) : m.size == want.size;
        if (m.width == want.width && m.height == want.height && m.offset == storedOffset && sizeOk)
            return;
        fail(where + " is " + std::to_string(m.width) + "x" + std::to_string(m.height) + " at +" +
             std::to_string(m.offset) + " size " + std::to_string(m.size) + ", expected " +
             std::to_string(want.width) + "x" + std::to_string(want.height) + " at +" + std::to_string(storedOffset) +
             (zstd ? " (zstd, for " : " size ") + std::to_string(want.size) + (zstd ? " bytes)" : ""));
    }

    void readTexels(Texture& t, const uint8_t* base, const std::vector<std::pair<uint64_t, uint64_t>>& levels,
                    bool zstd, const std::string& where) const
    {
        if (texelMode_ == TexelMode::Skip || (!zstd && texelMode_ == TexelMode::Verify))
            return; // raw texels are covered by the TEXL checksum
        const uint64_t total = t.mips.back().offset + t.mips.back().size;
        if (texelMode_ == TexelMode::Copy)
            t.texels.resize(size_t(total));
        for (size_t l = 0; l < levels.size(); ++l) {
            const auto [offset, size] = levels[l];
            if (!zstd) {
                std::memcpy(t.texels.data() + t.mips[l].offset, base + offset, size_t(size));
                continue;
            }
            LevelInflater level({base + offset, size_t(size)}, t.mips[l].size, name_,
                                where + " mip level " + std::to_string(l));
            if (texelMode_ == TexelMode::Copy)
                level.read(t.texels.data() + t.mips[l].offset, size_t(t.mips[l].size));
            else
                level.skipAll();
        }
    }

    void decodeNodes(std::vector<Node>& nodes)
    {
        const SectionEntry& e = section(kTagNodes);
        nodes.resize(size_t(e.count));
        for (uint64_t i = 0; i < e.count; ++i) {
            const auto r = record<NodeRecord>(e, i);
            Node& n = nodes[i];
            n.name = string(r.name, "node " + std::to_string(i));
            n.parent = r.parent;
            n.mesh = r.mesh;
            std::memcpy(&n.translation, r.translation, sizeof r.translation);
            n.rotation = glm::quat(r.rotation[3], r.rotation[0], r.rotation[1], r.rotation[2]);
            std::memcpy(&n.scale, r.scale, sizeof r.scale);
            reserved(uint64_t(r.reserved[0]) | r.reserved[1], "node " + std::to_string(i));
        }
    }

    // LGHT (optional); types, nodes and values are validateScene's.
    void decodeLights(std::vector<Light>& lights)
    {
        const SectionEntry* e = table_.find(kTagLights);
        if (!e)
            return;
        lights.resize(size_t(e->count));
        for (uint64_t i = 0; i < e->count; ++i) {
            const auto r = record<LightRecord>(*e, i);
            const std::string where = "light " + std::to_string(i);
            Light& l = lights[size_t(i)];
            l.name = string(r.name, where);
            l.type = LightType(r.type);
            l.node = r.node;
            std::memcpy(&l.color, r.color, sizeof r.color);
            l.intensity = r.intensity;
            l.range = r.range;
            l.innerConeAngle = r.innerConeAngle;
            l.outerConeAngle = r.outerConeAngle;
            reserved(r.reserved, where);
        }
    }

    // Animations own consecutive runs of channels, channels consecutive runs of keys.
    void decodeAnimations(std::vector<Animation>& animations)
    {
        const SectionEntry& e = section(kTagAnimations);
        const SectionEntry& channels = section(kTagChannels);
        const SectionEntry& times = section(kTagKeyTimes);
        const SectionEntry& values = section(kTagKeyValues);
        if (times.count != values.count)
            fail(std::to_string(times.count) + " key times but " + std::to_string(values.count) + " key values");
        animations.resize(size_t(e.count));
        uint64_t nextChannel = 0;
        uint64_t nextKey = 0;
        for (uint64_t a = 0; a < e.count; ++a) {
            const auto r = record<AnimationRecord>(e, a);
            const std::string where = "animation " + std::to_string(a);
            Animation& anim = animations[a];
            anim.name = string(r.name, where);
            if (r.firstChannel != nextChannel || channels.count - nextChannel < r.channelCount)
                fail(where + ": channels [" + std::to_string(r.firstChannel) + ", +" + std::to_string(r.channelCount) +
                     ") do not follow the previous animation's within the " + std::to_string(channels.count) +
                     " channels");
            anim.channels.resize(r.channelCount);
            for (uint32_t c = 0; c < r.channelCount; ++c) {
                const auto ch = record<ChannelRecord>(channels, nextChannel + c);
                const std::string channelWhere = where + " channel " + std::to_string(c);
                if (channels.version < kChannelsWeightsVersion || ch.path != uint32_t(AnimationPath::Weights))
                    reserved(ch.reserved, channelWhere);
                else
                    anim.channels[c].weightOffset = ch.reserved;
                if (channels.version < kChannelsWeightsVersion && ch.path == uint32_t(AnimationPath::Weights))
                    fail(channelWhere + ": a weights channel in a version-1 'ACHN' section");
                if (ch.firstKey != nextKey || times.count - nextKey < ch.keyCount)
                    fail(channelWhere + ": keys [" + std::to_string(ch.firstKey) + ", +" +
                         std::to_string(ch.keyCount) + ") do not follow the previous channel's within the " +
                         std::to_string(times.count) + " keys");
                AnimationChannel& out = anim.channels[c];
                out.node = ch.node;
                out.path = AnimationPath(ch.path);                  // range checked by validateScene
                out.interpolation = Interpolation(ch.interpolation); // likewise
                out.times.resize(size_t(ch.keyCount));
                out.values.resize(size_t(ch.keyCount));
                if (ch.keyCount != 0) {
                    std::memcpy(out.times.data(), at(times) + nextKey * 4, size_t(ch.keyCount * 4));
                    std::memcpy(out.values.data(), at(values) + nextKey * 16, size_t(ch.keyCount * 16));
                }
                nextKey += ch.keyCount;
            }
            nextChannel += r.channelCount;
        }
        if (nextChannel != channels.count)
            fail("animations use " + std::to_string(nextChannel) + " of " + std::to_string(channels.count) +
                 " channels");
        if (nextKey != times.count)
            fail("animation channels use " + std::to_string(nextKey) + " of " + std::to_string(times.count) + " keys");
    }

    // Skin influences, morph deltas, skins and deformers (all optional sections).
    void decodeDeformation(Scene& scene)
    {
        DeformationStreams& d = scene.vertices.deform;
        d.joints = array<glm::uvec4>(kTagJoints);
        d.weights = array<glm::vec4>(kTagWeights);
        d.positions = array<glm::vec3>(kTagMorphPositions);
        d.normals = array<glm::vec3>(kTagMorphNormals);
        d.tangents = array<glm::vec3>(kTagMorphTangents);
        const size_t vertices = scene.vertices.positions.size();
        if (!d.positions.empty() && (vertices == 0 || d.positions.size() % vertices != 0))
            fail("'MPOS' holds " + std::to_string(d.positions.size()) + " deltas, not a multiple of the " +
                 std::to_string(vertices) + " vertices");
        d.morphTargets = vertices == 0 ? 0 : uint32_t(d.positions.size() / vertices);
        decodeSkins(scene.skins);
        decodeDeformers(scene.deformers);
    }

    void decodeSkins(std::vector<Skin>& skins)
    {
        const SectionEntry* e = table_.find(kTagSkins);
        const SectionEntry* joints = table_.find(kTagSkinJoints);
        if (!e)
            return;
        const uint64_t jointCount = joints ? joints->count : 0;
        uint64_t next = 0;
        skins.resize(size_t(e->count));
        for (uint64_t i = 0; i < e->count; ++i) {
            const auto r = record<SkinRecord>(*e, i);
            const std::string where = "skin " + std::to_string(i);
            if (r.firstJoint != next || jointCount - next < r.jointCount)
                fail(where + ": joints [" + std::to_string(r.firstJoint) + ", +" + std::to_string(r.jointCount) +
                     ") do not follow the previous skin's within the " + std::to_string(jointCount) + " joints");
            skins[i].name = string(r.name, where);
            for (uint32_t j = 0; j < r.jointCount; ++j) {
                const auto jr = record<SkinJointRecord>(*joints, next + j);
                reserved(uint64_t(jr.reserved[0]) | jr.reserved[1] | jr.reserved[2], where + " joint " + std::to_string(j));
                glm::mat4 m;
                std::memcpy(&m[0][0], jr.inverseBindMatrix, sizeof jr.inverseBindMatrix);
                skins[i].joints.push_back(jr.node);
                skins[i].inverseBindMatrices.push_back(m);
            }
            next += r.jointCount;
        }
        if (next != jointCount)
            fail("skins use " + std::to_string(next) + " of " + std::to_string(jointCount) + " joints");
    }

    void decodeDeformers(std::vector<Deformer>& deformers)
    {
        const SectionEntry* e = table_.find(kTagDeformers);
        if (!e)
            return;
        const std::vector<float> weights = array<float>(kTagDeformerWeights);
        uint64_t next = 0;
        deformers.resize(size_t(e->count));
        for (uint64_t i = 0; i < e->count; ++i) {
            const auto r = record<DeformerRecord>(*e, i);
            const std::string where = "deformer " + std::to_string(i);
            reserved(uint64_t(r.reserved[0]) | r.reserved[1], where);
            if (r.firstWeight != next || weights.size() - next < r.weightCount)
                fail(where + ": weights [" + std::to_string(r.firstWeight) + ", +" + std::to_string(r.weightCount) +
                     ") do not follow the previous deformer's within the " + std::to_string(weights.size()) + " weights");
            deformers[i] = Deformer{r.node, r.skin, r.firstVertex, r.vertexCount,
                                    std::vector<float>(weights.begin() + std::ptrdiff_t(next),
                                                       weights.begin() + std::ptrdiff_t(next + r.weightCount))};
            next += r.weightCount;
        }
        if (next != weights.size())
            fail("deformers use " + std::to_string(next) + " of " + std::to_string(weights.size()) + " weights");
    }

    const uint8_t* data_;
    const SectionTable& table_;
    const std::string& name_;
    TexelMode texelMode_;
    std::vector<StoredTexture>* stored_;
    const uint8_t* strings_ = nullptr;
    uint64_t stringBytes_ = 0;
    uint64_t stringTotal_ = 0;
};

} // namespace

Scene decodeScene(const uint8_t* data, const SectionTable& table, const std::string& name, TexelMode texels,
                  std::vector<StoredTexture>* stored)
{
    Scene scene = Decoder(data, table, name, texels, stored).run();
    validateScene(scene, name, texels == TexelMode::Copy ? TexelPolicy::Required : TexelPolicy::MetadataOnly);
    return scene;
}

} // namespace lfd::pack
