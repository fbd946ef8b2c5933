// .lfdpack writer. Plans the whole layout first (every section size is known up front,
// texel sizes from the textures' width/height metadata), then streams the payloads in
// order while hashing them, and finally seeks back to fill in the section table and the
// header. The atomic file write around it lives in pack_file_writer.cpp.
#include "pack_internal.h"

#include <xxhash.h>

#include <algorithm>
#include <cstring>
#include <exception>
#include <functional>
#include <memory>

namespace lfd::pack {

namespace {

static_assert(sizeof(glm::vec2) == 8 && sizeof(glm::vec3) == 12 && sizeof(glm::vec4) == 16,
              "vertex streams are written straight from glm arrays");
static_assert(sizeof(glm::mat2) == 16, "MEXT uv maps are copied from glm::mat2 (column-major)");
static_assert(offsetof(TriangleStats, flags) == 20, "TSTA is written straight from lfd::TriangleStats");

class MemorySink final : public Sink {
public:
    explicit MemorySink(std::vector<uint8_t>& bytes) : bytes_(bytes) {}
    void write(const void* data, size_t size) override
    {
        const auto* p = static_cast<const uint8_t*>(data);
        bytes_.insert(bytes_.end(), p, p + size);
    }
    void writeAt(uint64_t offset, const void* data, size_t size) override
    {
        std::memcpy(bytes_.data() + offset, data, size);
    }

private:
    std::vector<uint8_t>& bytes_;
};

using XxhState = std::unique_ptr<XXH3_state_t, decltype(&XXH3_freeState)>;

// One section's payload on its way out: counts bytes and feeds the XXH3 streaming state.
class SectionStream {
public:
    explicit SectionStream(Sink& sink) : sink_(sink), state_(XXH3_createState(), &XXH3_freeState)
    {
        if (!state_ || XXH3_64bits_reset(state_.get()) != XXH_OK)
            throw std::bad_alloc();
    }
    void write(const void* data, size_t size)
    {
        sink_.write(data, size);
        XXH3_64bits_update(state_.get(), data, size);
        written_ += size;
    }
    uint64_t written() const { return written_; }
    uint64_t digest() const { return XXH3_64bits_digest(state_.get()); }

private:
    Sink& sink_;
    XxhState state_;
    uint64_t written_ = 0;
};

// Names are appended once each; sections refer to them by (offset, length).
class StringTable {
public:
    explicit StringTable(const std::string& name) : name_(name) {}
    StringRef add(const std::string& s)
    {
        if (uint64_t(bytes_.size()) + s.size() > UINT32_MAX)
            fail(name_, "names exceed 4 GiB");
        StringRef ref{uint32_t(bytes_.size()), uint32_t(s.size())};
        bytes_.insert(bytes_.end(), s.begin(), s.end());
        return ref;
    }
    const std::vector<uint8_t>& bytes() const { return bytes_; }

private:
    const std::string& name_;
    std::vector<uint8_t> bytes_;
};

template <typename Record>
std::vector<uint8_t> recordBytes(const std::vector<Record>& records)
{
    std::vector<uint8_t> bytes(records.size() * sizeof(Record));
    if (!records.empty())
        std::memcpy(bytes.data(), records.data(), bytes.size());
    return bytes;
}

// Calls the producer for texture i and checks that the result fills exactly the bytes
// planned from Scene::textures[i]'s metadata.
Texture produceTexture(const Scene& scene, const TextureProducer& produce, uint32_t i, const std::string& name)
{
    const std::string where = "texture " + std::to_string(i) + ": ";
    Texture produced;
    try {
        produced = produce(i);
    } catch (const PackError&) {
        throw;
    } catch (const std::exception& e) {
        fail(name, where + "producer failed: " + e.what());
    } catch (...) {
        fail(name, where + "producer failed with an unknown exception");
    }
    const Texture& meta = scene.textures[i];
    if (produced.width != meta.width || produced.height != meta.height)
        fail(name, where + "produced " + std::to_string(produced.width) + "x" + std::to_string(produced.height) +
                       " but the scene says " + std::to_string(meta.width) + "x" + std::to_string(meta.height));
    if (produced.srgb != meta.srgb)
        fail(name, where + "produced sRGB flag differs from the scene's");
    if (uint32_t(produced.format) >= kTextureFormatCount)
        fail(name, where + "produced an unknown texture format");
    const std::vector<MipLevel> chain = textureMipChain(produced.width, produced.height, produced.format);
    bool same = produced.mips.size() == chain.size();
    for (size_t l = 0; same && l < chain.size(); ++l)
        same = produced.mips[l].width == chain[l].width && produced.mips[l].height == chain[l].height &&
               produced.mips[l].offset == chain[l].offset && produced.mips[l].size == chain[l].size;
    if (!same)
        fail(name, where + "produced mip levels that are not the full chain");
    const uint64_t bytes = textureChainBytes(produced.width, produced.height, produced.format);
    if (produced.texels.size() != bytes)
        fail(name, where + "produced " + std::to_string(produced.texels.size()) + " texel bytes, expected " +
                       std::to_string(bytes));
    return produced;
}

// One texture as TEXL stores it: the format and encoding the producer's texels had, and
// each level's stored size. Filled while TEXL is written, read by the TEXD and MIPS
// emitters that follow it.
struct WrittenTexture {
    TextureFormat format = TextureFormat::Rgba8;
    bool zstd = false;
    std::vector<uint64_t> levelBytes;
};
using WrittenTextures = std::vector<WrittenTexture>;

// Whether zstd is worth it for a texture: it must save at least 5% (noise-like texels and
// most block data do not; inflating them while streaming would cost time for nothing).
// Judged on level 1 (a quarter of level 0, with the same statistics), or level 0 when it
// is the only one, so the decision needs one small frame, not the whole chain.
bool worthZstd(const Texture& t)
{
    const MipLevel& probe = t.mips[t.mips.size() > 1 ? 1 : 0];
    const uint64_t frameBytes = compressLevel(t.texels.data() + probe.offset, size_t(probe.size),
                                              [](const void*, size_t) {}); // counted, not kept
    return frameBytes * 20 <= probe.size * 19;
}

// Writes one texture's levels, as zstd frames (RGBA8 texels and blocks alike: blocks of
// flat regions repeat) when compressing and worthZstd, otherwise raw. Each frame is
// streamed out as it is made, so the writer holds no compressed level.
WrittenTexture writeTexture(const Texture& t, bool compress, SectionStream& out)
{
    WrittenTexture stored{t.format, compress && !t.mips.empty() && worthZstd(t), {}};
    for (const MipLevel& level : t.mips) {
        const uint8_t* texels = t.texels.data() + level.offset;
        if (!stored.zstd) {
            out.write(texels, size_t(level.size));
            stored.levelBytes.push_back(level.size);
            continue;
        }
        stored.levelBytes.push_back(
            compressLevel(texels, size_t(level.size), [&out](const void* bytes, size_t n) { out.write(bytes, n); }));
    }
    return stored;
}

struct PlannedSection {
    SectionEntry entry{}; // size, encoding and checksum filled in while emitting
    // Writes the payload; may set entry.encoding (zstd) and, for TEXL, entry.count.
    std::function<void(SectionStream&, SectionEntry&)> emit;
};

class PackPlanner {
public:
    PackPlanner(const Scene& scene, const TextureProducer& produce, const PackWriteOptions& options,
                const std::string& name)
        : scene_(scene), produce_(produce), options_(options), name_(name), strings_(name)
    {
    }

    std::vector<PlannedSection> plan()
    {
        // Metadata records are small: encode them now, which also fills the string table.
        std::vector<uint8_t> bake = encodeSettings();
        std::vector<uint8_t> bounds = encodeBounds();
        std::vector<uint8_t> meshes = encodeMeshes();
        std::vector<uint8_t> materials = encodeMaterials();
        std::vector<StringRef> textureNames;
        for (const Texture& t : scene_.textures)
            textureNames.push_back(strings_.add(t.name));
        std::vector<uint8_t> nodes = encodeNodes();
        std::vector<uint8_t> channels;
        std::vector<uint8_t> animations = encodeAnimations(channels);
        std::vector<uint8_t> primitives = encodePrimitives();
        std::vector<uint8_t> skins = encodeSkins();
        // Optional sections add their names last, so a pack without them keeps its strings.
        std::vector<uint8_t> materialExtensions = encodeMaterialExtensions();
        std::vector<uint8_t> lights = encodeLights();

        const VertexStreams& v = scene_.vertices;
        addBytes(kTagBakeSettings, sizeof(BakeSettingsRecord), std::move(bake));
        addBytes(kTagBounds, sizeof(BoundsRecord), std::move(bounds));
        addBytes(kTagStrings, 1, strings_.bytes());
        addArray(kTagPositions, v.positions, true);
        addArray(kTagNormals, v.normals, false);
        addArray(kTagTangents, v.tangents, false);
        addArray(kTagUvs, v.uvs, false);
        addArray(kTagIndices, scene_.indices, true);
        addArray(kTagTriangleStats, scene_.triangleStats, true);
        addBytes(kTagPrimitives, sizeof(PrimitiveRecord), std::move(primitives));
        addBytes(kTagMeshes, sizeof(MeshRecord), std::move(meshes));
        addBytes(kTagMaterials, sizeof(MaterialRecord), std::move(materials));
        if (!materialExtensions.empty())
            addBytes(kTagMaterialExtensions, sizeof(MaterialExtensionRecord), std::move(materialExtensions));
        addBytes(kTagNodes, sizeof(NodeRecord), std::move(nodes));
        if (!lights.empty())
            addBytes(kTagLights, sizeof(LightRecord), std::move(lights));
        addBytes(kTagAnimations, sizeof(AnimationRecord), std::move(animations));
        addBytes(kTagChannels, sizeof(ChannelRecord), std::move(channels));
        if (hasWeightChannels())
            sections_.back().entry.version = kChannelsWeightsVersion;
        addKeys();
        addDeformation(std::move(skins));
        // The large streamed section, then the texture and mip records: their formats and
        // stored sizes are known once the producer has made each texture.
        auto stored = std::make_shared<WrittenTextures>();
        addTexels(stored);
        addTextureRecords(stored, std::move(textureNames));
        return std::move(sections_);
    }

private:
    void add(uint32_t tag, uint32_t stride, uint64_t count, std::function<void(SectionStream&, SectionEntry&)> emit)
    {
        PlannedSection s;
        s.entry.tag = tag;
        s.entry.version = kSectionVersion;
        s.entry.stride = stride;
        s.entry.count = count;
        s.emit = std::move(emit);
        sections_.push_back(std::move(s));
    }

    void addBytes(uint32_t tag, uint32_t stride, std::vector<uint8_t> bytes)
    {
        const uint64_t count = bytes.size() / stride;
        add(tag, stride, count, [bytes = std::move(bytes)](SectionStream& out, SectionEntry&) {
            out.write(bytes.data(), bytes.size());
        });
    }

    // Geometry and key streams: zstd when it makes them smaller (and the option is on).
    void addCompressible(uint32_t tag, uint32_t stride, uint64_t count,
                         std::function<void(std::vector<uint8_t>&)> gather, const void* contiguous)
    {
        add(tag, stride, count,
            [compress = options_.compress, stride, count, gather = std::move(gather),
             contiguous](SectionStream& out, SectionEntry& entry) {
                if (count == 0)
                    return;
                std::vector<uint8_t> gathered;
                const void* data = contiguous;
                if (!data) {
                    gather(gathered);
                    data = gathered.data();
                }
                const size_t bytes = size_t(count * stride);
                const std::vector<uint8_t> frame = compress ? compressSection(data, bytes) : std::vector<uint8_t>{};
                if (frame.empty()) {
                    out.write(data, bytes);
                    return;
                }
                entry.encoding = kEncodingZstd;
                out.write(frame.data(), frame.size());
            });
    }

    template <typename T>
    void addArray(uint32_t tag, const std::vector<T>& values, bool required)
    {
        if (values.empty() && !required)
            return; // optional vertex streams are absent when unused
        addCompressible(tag, sizeof(T), values.size(), {}, values.data());
    }

    std::vector<uint8_t> encodeSettings()
    {
        const BakeSettings& s = scene_.settings;
        BakeSettingsRecord r{};
        r.bakerVersion = strings_.add(s.bakerVersion);
        r.sourceFile = strings_.add(s.sourceFile);
        r.displayProfile = strings_.add(s.displayProfile);
        r.viewWidth = s.viewWidth;
        r.viewHeight = s.viewHeight;
        r.viewCount = s.viewCount;
        r.maxTextureSize = s.maxTextureSize;
        r.maxEdgePx = s.maxEdgePx;
        r.framingFill = s.framingFill;
        r.viewPixelWorld = s.viewPixelWorld;
        return recordBytes(std::vector<BakeSettingsRecord>{r});
    }

    std::vector<uint8_t> encodeBounds() const
    {
        const SceneBounds& b = scene_.bounds;
        BoundsRecord r{};
        std::memcpy(r.min, &b.min, sizeof r.min);
        std::memcpy(r.max, &b.max, sizeof r.max);
        std::memcpy(r.center, &b.center, sizeof r.center);
        r.radius = b.radius;
        return recordBytes(std::vector<BoundsRecord>{r});
    }

    std::vector<uint8_t> encodePrimitives() const
    {
        std::vector<PrimitiveRecord> records;
        records.reserve(scene_.primitives.size());
        for (const Primitive& p : scene_.primitives)
            records.push_back(PrimitiveRecord{p.firstIndex, p.indexCount, p.material, 0});
        return recordBytes(records);
    }

    std::vector<uint8_t> encodeMeshes()
    {
        std::vector<MeshRecord> records;
        for (const Mesh& m : scene_.meshes)
            records.push_back(MeshRecord{strings_.add(m.name), m.firstPrimitive, m.primitiveCount});
        return recordBytes(records);
    }

    std::vector<uint8_t> encodeMaterials()
    {
        std::vector<MaterialRecord> records;
        for (const Material& m : scene_.materials) {
            MaterialRecord r{};
            std::memcpy(r.baseColorFactor, &m.baseColorFactor, sizeof r.baseColorFactor);
            std::memcpy(r.emissiveFactor, &m.emissiveFactor, sizeof r.emissiveFactor);
            r.metallicFactor = m.metallicFactor;
            r.roughnessFactor = m.roughnessFactor;
            r.normalScale = m.normalScale;
            r.occlusionStrength = m.occlusionStrength;
            r.alphaCutoff = m.alphaCutoff;
            r.alphaMode = uint32_t(m.alphaMode);
            r.doubleSided = m.doubleSided ? 1 : 0;
            r.baseColorTexture = m.baseColorTexture;
            r.metallicRoughnessTexture = m.metallicRoughnessTexture;
            r.normalTexture = m.normalTexture;
            r.occlusionTexture = m.occlusionTexture;
            r.emissiveTexture = m.emissiveTexture;
            r.name = strings_.add(m.name);
            records.push_back(r);
        }
        return recordBytes(records);
    }

    // MEXT: one record per material when some material is unlit or has a texture
    // transform; nothing otherwise (the section is absent).
    std::vector<uint8_t> encodeMaterialExtensions() const
    {
        const auto& materials = scene_.materials;
        if (std::none_of(materials.begin(), materials.end(), [](const Material& m) { return m.hasExtensions(); }))
            return {};
        std::vector<MaterialExtensionRecord> records;
        for (const Material& m : materials) {
            MaterialExtensionRecord r{};
            r.flags = m.unlit ? kMaterialUnlit : 0;
            for (uint32_t slot = 0; slot < kTextureSlotCount; ++slot) {
                const TextureTransform& t = m.textureTransforms[slot];
                std::memcpy(r.uvTransforms[slot].linear, &t.linear[0][0], sizeof r.uvTransforms[slot].linear);
                std::memcpy(r.uvTransforms[slot].offset, &t.offset, sizeof r.uvTransforms[slot].offset);
            }
            records.push_back(r);
        }
        return recordBytes(records);
    }

    std::vector<uint8_t> encodeLights()
    {
        std::vector<LightRecord> records;
        for (const Light& l : scene_.lights) {
            LightRecord r{};
            r.type = uint32_t(l.type);
            r.node = l.node;
            std::memcpy(r.color, &l.color, sizeof r.color);
            r.intensity = l.intensity;
            r.range = l.range;
            r.innerConeAngle = l.innerConeAngle;
            r.outerConeAngle = l.outerConeAngle;
            r.name = strings_.add(l.name);
            records.push_back(r);
        }
        return recordBytes(records);
    }

    std::vector<uint8_t> encodeNodes()
    {
        std::vector<NodeRecord> records;
        for (const Node& n : scene_.nodes) {
            NodeRecord r{};
            std::memcpy(r.translation, &n.translation, sizeof r.translation);
            r.parent = n.parent;
            r.rotation[0] = n.rotation.x;
            r.rotation[1] = n.rotation.y;
            r.rotation[2] = n.rotation.z;
            r.rotation[3] = n.rotation.w;
            std::memcpy(r.scale, &n.scale, sizeof r.scale);
            r.mesh = n.mesh;
            r.name = strings_.add(n.name);
            records.push_back(r);
        }
        return recordBytes(records);
    }

    std::vector<uint8_t> encodeAnimations(std::vector<uint8_t>& channelBytes)
    {
        std::vector<AnimationRecord> animations;
        std::vector<ChannelRecord> channels;
        keyCount_ = 0;
        for (const Animation& a : scene_.animations) {
            animations.push_back(AnimationRecord{strings_.add(a.name), uint32_t(channels.size()),
                                                 uint32_t(a.channels.size())});
            for (const AnimationChannel& c : a.channels) {
                ChannelRecord r{};
                r.node = c.node;
                r.path = uint32_t(c.path);
                r.interpolation = uint32_t(c.interpolation);
                r.reserved = c.path == AnimationPath::Weights ? c.weightOffset : 0;
                r.firstKey = keyCount_;
                r.keyCount = c.times.size();
                keyCount_ += c.times.size();
                channels.push_back(r);
            }
        }
        if (channels.size() > UINT32_MAX)
            fail(name_, "too many animation channels");
        channelBytes = recordBytes(channels);
        return recordBytes(animations);
    }

    bool hasWeightChannels() const
    {
        for (const Animation& a : scene_.animations)
            for (const AnimationChannel& c : a.channels)
                if (c.path == AnimationPath::Weights)
                    return true;
        return false;
    }

    std::vector<uint8_t> encodeSkins()
    {
        std::vector<SkinRecord> records;
        uint32_t joints = 0;
        for (const Skin& skin : scene_.skins) {
            records.push_back(SkinRecord{strings_.add(skin.name), joints, uint32_t(skin.joints.size())});
            joints += uint32_t(skin.joints.size());
        }
        return recordBytes(records);
    }

    // Skin influences, morph deltas, skins and deformers: absent in static scenes.
    void addDeformation(std::vector<uint8_t> skins)
    {
        const DeformationStreams& d = scene_.vertices.deform;
        addArray(kTagJoints, d.joints, false);
        addArray(kTagWeights, d.weights, false);
        addArray(kTagMorphPositions, d.positions, false);
        addArray(kTagMorphNormals, d.normals, false);
        addArray(kTagMorphTangents, d.tangents, false);
        if (scene_.deformers.empty())
            return;
        std::vector<SkinJointRecord> joints;
        for (const Skin& skin : scene_.skins)
            for (size_t j = 0; j < skin.joints.size(); ++j) {
                SkinJointRecord r{};
                r.node = skin.joints[j];
                std::memcpy(r.inverseBindMatrix, &skin.inverseBindMatrices[j][0][0], sizeof r.inverseBindMatrix);
                joints.push_back(r);
            }
        std::vector<DeformerRecord> deformers;
        std::vector<float> weights;
        for (const Deformer& f : scene_.deformers) {
            deformers.push_back(DeformerRecord{f.node, f.skin, f.firstVertex, f.vertexCount, uint32_t(weights.size()),
                                               uint32_t(f.weights.size()), {0, 0}});
            weights.insert(weights.end(), f.weights.begin(), f.weights.end());
        }
        addBytes(kTagSkins, sizeof(SkinRecord), std::move(skins));
        addBytes(kTagSkinJoints, sizeof(SkinJointRecord), recordBytes(joints));
        addBytes(kTagDeformers, sizeof(DeformerRecord), recordBytes(deformers));
        addBytes(kTagDeformerWeights, sizeof(float), recordBytes(weights));
    }

    void addKeys()
    {
        const auto& animations = scene_.animations;
        addCompressible(kTagKeyTimes, sizeof(float), keyCount_, [&animations](std::vector<uint8_t>& out) {
            for (const Animation& a : animations)
                for (const AnimationChannel& c : a.channels)
                    append(out, c.times.data(), c.times.size() * sizeof(float));
        }, nullptr);
        addCompressible(kTagKeyValues, sizeof(glm::vec4), keyCount_, [&animations](std::vector<uint8_t>& out) {
            for (const Animation& a : animations)
                for (const AnimationChannel& c : a.channels)
                    append(out, c.values.data(), c.values.size() * sizeof(glm::vec4));
        }, nullptr);
    }

    static void append(std::vector<uint8_t>& out, const void* data, size_t size)
    {
        const auto* p = static_cast<const uint8_t*>(data);
        out.insert(out.end(), p, p + size);
    }

    void addTexels(std::shared_ptr<WrittenTextures> stored)
    {
        // The emitters outlive the planner: capture what they need, never `this`.
        add(kTagTexels, 1, 0,
            [&scene = scene_, &produce = produce_, &name = name_, compress = options_.compress,
             stored](SectionStream& out, SectionEntry& entry) {
                for (uint32_t i = 0; i < scene.textures.size(); ++i) {
                    if (!produce) {
                        stored->push_back(writeTexture(scene.textures[i], compress, out));
                        continue;
                    }
                    // Only one produced texture is alive at a time: it dies at the end of
                    // this iteration, right after its texels are written.
                    const Texture produced = produceTexture(scene, produce, i, name);
                    stored->push_back(writeTexture(produced, compress, out));
                }
                entry.count = out.written();
            });
    }

    void addTextureRecords(std::shared_ptr<WrittenTextures> stored, std::vector<StringRef> names)
    {
        const auto& textures = scene_.textures;
        add(kTagTextures, sizeof(TextureRecord), textures.size(),
            [&textures, stored, names = std::move(names)](SectionStream& out, SectionEntry&) {
                uint64_t texelOffset = 0;
                uint32_t firstMip = 0;
                for (size_t i = 0; i < textures.size(); ++i) {
                    const Texture& t = textures[i];
                    const WrittenTexture& s = (*stored)[i];
                    TextureRecord r{};
                    r.name = names[i];
                    r.width = t.width;
                    r.height = t.height;
                    r.sourceWidth = t.sourceWidth;
                    r.sourceHeight = t.sourceHeight;
                    r.flags = (t.srgb ? kTextureSrgb : 0) | (s.zstd ? kTextureZstdLevels : 0);
                    r.mipCount = uint32_t(s.levelBytes.size());
                    r.firstMip = firstMip;
                    r.format = uint32_t(s.format);
                    r.texelOffset = texelOffset;
                    for (uint64_t bytes : s.levelBytes)
                        r.texelSize += bytes;
                    texelOffset += r.texelSize;
                    firstMip += r.mipCount;
                    out.write(&r, sizeof r);
                }
            });
        uint64_t mipCount = 0;
        for (const Texture& t : textures)
            mipCount += fullMipCount(t.width, t.height);
        add(kTagMipLevels, sizeof(MipRecord), mipCount, [&textures, stored](SectionStream& out, SectionEntry&) {
            for (size_t i = 0; i < textures.size(); ++i) {
                const WrittenTexture& s = (*stored)[i];
                const std::vector<MipLevel> chain = textureMipChain(textures[i].width, textures[i].height, s.format);
                uint64_t offset = 0;
                for (size_t l = 0; l < chain.size(); ++l) {
                    const MipRecord r{chain[l].width, chain[l].height, offset, s.levelBytes[l]};
                    out.write(&r, sizeof r);
                    offset += s.levelBytes[l];
                }
            }
        });
    }

    const Scene& scene_;
    const TextureProducer& produce_;
    const PackWriteOptions& options_;
    const std::string& name_;
    StringTable strings_;
    std::vector<PlannedSection> sections_;
    uint64_t keyCount_ = 0;
};

} // namespace

void emitPack(Sink& sink, const Scene& scene, const TextureProducer& produce, const PackWriteOptions& options,
              const std::string& name)
{
    validateScene(scene, name, produce ? TexelPolicy::MetadataOnly : TexelPolicy::Required);
    std::vector<PlannedSection> sections = PackPlanner(scene, produce, options, name).plan();

    // Header and table are placeholders until the sizes and checksums are known; each
    // payload goes at the next aligned offset, its size is what it wrote.
    static const uint8_t kZeros[kAlignment] = {};
    const uint64_t tableBytes = sections.size() * sizeof(SectionEntry);
    std::vector<uint8_t> placeholder(sizeof(FileHeader) + tableBytes, 0);
    sink.write(placeholder.data(), placeholder.size());
    uint64_t position = placeholder.size();
    for (PlannedSection& s : sections) {
        s.entry.offset = alignUp(position);
        sink.write(kZeros, size_t(s.entry.offset - position));
        SectionStream out(sink);
        s.emit(out, s.entry);
        s.entry.size = out.written();
        if (s.entry.encoding == kEncodingRaw && s.entry.size != s.entry.count * s.entry.stride)
            fail(name, "internal error: section '" + tagName(s.entry.tag) + "' wrote " + std::to_string(out.written()) +
                           " bytes for " + std::to_string(s.entry.count) + " elements of " +
                           std::to_string(s.entry.stride));
        s.entry.checksum = out.digest();
        position = s.entry.offset + s.entry.size;
    }
    const uint64_t fileSize = position;

    std::vector<SectionEntry> table;
    for (const PlannedSection& s : sections)
        table.push_back(s.entry);
    FileHeader header{};
    std::memcpy(header.magic, kMagic, sizeof kMagic);
    header.formatVersion = kFormatVersion;
    header.headerSize = sizeof(FileHeader);
    header.sectionCount = uint32_t(table.size());
    header.sectionEntrySize = sizeof(SectionEntry);
    header.tableOffset = sizeof(FileHeader);
    header.fileSize = fileSize;
    header.tableChecksum = checksum(table.data(), size_t(tableBytes));
    header.headerChecksum = checksum(&header, kHeaderChecksummedBytes);
    sink.writeAt(sizeof(FileHeader), table.data(), size_t(tableBytes));
    sink.writeAt(0, &header, sizeof header);
}

} // namespace lfd::pack

namespace lfd {

std::vector<uint8_t> writePackToMemory(const Scene& scene, const TextureProducer& produce,
                                       const PackWriteOptions& options)
{
    std::vector<uint8_t> bytes;
    pack::MemorySink sink(bytes);
    pack::emitPack(sink, scene, produce, options, "<memory>");
    return bytes;
}

} // namespace lfd
