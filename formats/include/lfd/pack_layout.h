// .lfdpack version 2 on-disk layout: magic, versions, section tags and the byte layout
// of the header, the section table and every fixed-size payload record. These structs
// are defined once here and mirrored field by field in formats/README.md; the writer,
// the reader and the tests all use them, nothing restates offsets by hand.
//
// All multi-byte values are little-endian. The structs have no implicit padding (every
// reserved word is spelled out and must be zero), so a record is moved to and from the
// file with memcpy on a little-endian host.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace lfd::pack {

static_assert(std::endian::native == std::endian::little,
              "the pack codec memcpys little-endian records; port it before using a big-endian host");

// "LFDPACK" + 0x1A (stops `type`/`cat` on Windows, catches text-mode transfers).
inline constexpr char kMagic[8] = {'L', 'F', 'D', 'P', 'A', 'C', 'K', '\x1A'};
// Version 2 gave meaning to two version-1 reserved fields: the section entry's
// `encoding` (zstd sections) and the texture record's `format` (block-compressed
// textures, zstd-compressed texel levels). A version-1 pack has zeros there and reads as
// before; kOldestFormatVersion is the oldest this reader accepts.
inline constexpr uint32_t kFormatVersion = 2;
inline constexpr uint32_t kOldestFormatVersion = 1;
inline constexpr uint32_t kSectionVersion = 1; // every section of format versions 1 and 2
// Section payloads start at multiples of this (a cache line; satisfies every std430 and
// buffer-offset alignment the player asks for, and page-friendly for mmap).
inline constexpr uint64_t kAlignment = 64;
// Largest texture dimension a pack may hold; keeps width * height * 4 far from overflow.
inline constexpr uint32_t kMaxTextureDimension = 65536;

// A FourCC stored as four bytes in file order ("VPOS" is 'V','P','O','S' on disk).
constexpr uint32_t makeTag(const char (&s)[5])
{
    return uint32_t(uint8_t(s[0])) | uint32_t(uint8_t(s[1])) << 8 | uint32_t(uint8_t(s[2])) << 16 |
           uint32_t(uint8_t(s[3])) << 24;
}
std::string tagName(uint32_t tag); // printable form, non-printable bytes as \xNN

inline constexpr uint32_t kTagBakeSettings = makeTag("BAKE");
inline constexpr uint32_t kTagBounds = makeTag("BNDS");
inline constexpr uint32_t kTagStrings = makeTag("STRS");
inline constexpr uint32_t kTagPositions = makeTag("VPOS");
inline constexpr uint32_t kTagNormals = makeTag("VNRM"); // optional
inline constexpr uint32_t kTagTangents = makeTag("VTAN"); // optional
inline constexpr uint32_t kTagUvs = makeTag("VTUV");      // optional
inline constexpr uint32_t kTagIndices = makeTag("INDX");
inline constexpr uint32_t kTagTriangleStats = makeTag("TSTA");
inline constexpr uint32_t kTagPrimitives = makeTag("PRIM");
inline constexpr uint32_t kTagMeshes = makeTag("MESH");
inline constexpr uint32_t kTagMaterials = makeTag("MATL");
inline constexpr uint32_t kTagTextures = makeTag("TEXD");
inline constexpr uint32_t kTagMipLevels = makeTag("MIPS");
inline constexpr uint32_t kTagTexels = makeTag("TEXL");
inline constexpr uint32_t kTagNodes = makeTag("NODE");
inline constexpr uint32_t kTagAnimations = makeTag("ANIM");
inline constexpr uint32_t kTagChannels = makeTag("ACHN");
inline constexpr uint32_t kTagKeyTimes = makeTag("AKTM");
inline constexpr uint32_t kTagKeyValues = makeTag("AKVL");
// Deformation (skins and morph targets), all optional; see formats/README.md.
inline constexpr uint32_t kTagJoints = makeTag("VJNT");          // u32x4 per vertex
inline constexpr uint32_t kTagWeights = makeTag("VWGT");         // f32x4 per vertex
inline constexpr uint32_t kTagMorphPositions = makeTag("MPOS"); // f32x3 per vertex and target
inline constexpr uint32_t kTagMorphNormals = makeTag("MNRM");
inline constexpr uint32_t kTagMorphTangents = makeTag("MTAN");
inline constexpr uint32_t kTagSkins = makeTag("SKIN");
inline constexpr uint32_t kTagSkinJoints = makeTag("SKJT");
inline constexpr uint32_t kTagDeformers = makeTag("DFRM");
inline constexpr uint32_t kTagDeformerWeights = makeTag("DFWT"); // f32 per deformer and target
// Materials and lights (glTF extensions), optional: written only when used.
inline constexpr uint32_t kTagMaterialExtensions = makeTag("MEXT"); // one per MATL record
inline constexpr uint32_t kTagLights = makeTag("LGHT");             // KHR_lights_punctual instances
// ACHN is written as section version 2 when it holds a Weights channel (path 3, the
// reserved word becomes weightOffset); version-1 readers refuse such packs by name.
inline constexpr uint32_t kChannelsWeightsVersion = 2;

struct FileHeader {
    char magic[8];
    uint32_t formatVersion;
    uint32_t headerSize;       // sizeof(FileHeader)
    uint32_t sectionCount;
    uint32_t sectionEntrySize; // sizeof(SectionEntry)
    uint64_t tableOffset;      // == headerSize: the table follows the header
    uint64_t fileSize;         // total bytes in the file
    uint64_t tableChecksum;    // XXH3_64bits(seed 0) of the whole section table
    uint64_t reserved;         // 0
    uint64_t headerChecksum;   // XXH3_64bits(seed 0) of header bytes [0, 56)
};
static_assert(sizeof(FileHeader) == 64 && offsetof(FileHeader, headerChecksum) == 56);
inline constexpr size_t kHeaderChecksummedBytes = offsetof(FileHeader, headerChecksum);

struct SectionEntry {
    uint32_t tag;
    uint32_t version;
    uint64_t offset;   // from the start of the file, multiple of kAlignment
    uint64_t size;     // payload bytes
    uint64_t count;    // elements in the payload
    uint64_t checksum; // XXH3_64bits(seed 0) of the payload bytes
    uint32_t stride;   // bytes per element (1 for byte blobs)
    uint32_t encoding; // SectionEncoding (format 2; 0 in format 1)
};
static_assert(sizeof(SectionEntry) == 48 && offsetof(SectionEntry, stride) == 40);

// How a payload is stored. Raw: `size == count * stride`. Zstd: the payload is one zstd
// frame whose content is the count * stride bytes a raw section would hold; `size` and
// the checksum cover the stored (compressed) bytes. TEXL is always raw (its levels carry
// their own encoding, see kTextureZstdLevels).
enum SectionEncoding : uint32_t {
    kEncodingRaw = 0,
    kEncodingZstd = 1,
};
// A zstd section may expand to at most this many times its stored size, or to
// kZstdSmallSectionBytes, whichever is larger: decompression allocates the declared size
// up front, so a forged count cannot make a small file claim gigabytes. The writer
// stores a section raw when its data compresses further than that.
inline constexpr uint64_t kZstdMaxRatio = 1024;
inline constexpr uint64_t kZstdSmallSectionBytes = uint64_t(16) << 20;

// A string in STRS: UTF-8 bytes [offset, offset + length), not NUL-terminated.
struct StringRef {
    uint32_t offset;
    uint32_t length;
};
static_assert(sizeof(StringRef) == 8);

// Vertex streams are tightly packed arrays: VPOS/VNRM float3 (stride 12), VTAN float4
// (16), VTUV float2 (8); INDX uint32 (4); TSTA is lfd::TriangleStats (24).

struct PrimitiveRecord { // PRIM, 16 bytes
    uint32_t firstIndex;
    uint32_t indexCount;
    int32_t material;
    uint32_t reserved;
};
static_assert(sizeof(PrimitiveRecord) == 16);

struct MeshRecord { // MESH, 16 bytes
    StringRef name;
    uint32_t firstPrimitive;
    uint32_t primitiveCount;
};
static_assert(sizeof(MeshRecord) == 16);

struct MaterialRecord { // MATL, 96 bytes, std430-compatible (vec4s at 16-byte offsets)
    float baseColorFactor[4];
    float emissiveFactor[3];
    float metallicFactor;
    float roughnessFactor;
    float normalScale;
    float occlusionStrength;
    float alphaCutoff;
    uint32_t alphaMode;   // lfd::AlphaMode
    uint32_t doubleSided; // 0 or 1
    int32_t baseColorTexture;
    int32_t metallicRoughnessTexture;
    int32_t normalTexture;
    int32_t occlusionTexture;
    int32_t emissiveTexture;
    uint32_t reserved0;
    StringRef name;
    uint32_t reserved1[2];
};
static_assert(sizeof(MaterialRecord) == 96 && offsetof(MaterialRecord, alphaMode) == 48 &&
              offsetof(MaterialRecord, name) == 80);

// MEXT: material i's KHR_materials_unlit flag and KHR_texture_transform maps, present
// when some material has either (lfd::Material::hasExtensions), then one record per MATL
// record. Each slot's map is uv' = linear * uv + offset applied to TEXCOORD_0.
inline constexpr uint32_t kMaterialUnlit = 1u << 0;

struct UvTransformRecord { // 32 bytes, std430 { mat2 linear; vec2 offset; vec2 reserved; }
    float linear[4]; // column-major: column 0 (x, y), column 1 (x, y)
    float offset[2];
    uint32_t reserved[2];
};
static_assert(sizeof(UvTransformRecord) == 32);

struct MaterialExtensionRecord { // MEXT, 176 bytes, std430-compatible
    uint32_t flags; // kMaterialUnlit
    uint32_t reserved[3];
    UvTransformRecord uvTransforms[5]; // lfd::TextureSlot order (MATL's texture fields)
};
static_assert(sizeof(MaterialExtensionRecord) == 176 && offsetof(MaterialExtensionRecord, uvTransforms) == 16);

// LGHT: one KHR_lights_punctual light per node instance.
struct LightRecord { // LGHT, 48 bytes
    uint32_t type; // lfd::LightType
    uint32_t node; // NODE index
    float color[3];
    float intensity;
    float range;          // 0 = unlimited
    float innerConeAngle; // spot: 0 <= inner < outer <= pi/2
    float outerConeAngle;
    uint32_t reserved;
    StringRef name;
};
static_assert(sizeof(LightRecord) == 48 && offsetof(LightRecord, name) == 40);
// A spot light's largest cone angle, pi/2 rounded to the nearest f32 (0x3FC90FDB).
inline constexpr float kMaxSpotConeAngle = 1.57079637f;

inline constexpr uint32_t kTextureSrgb = 1u << 0;
// Format 2: every mip level is a zstd frame of its texels (RGBA8 texels or blocks); MIPS
// offset/size are the stored bytes.
inline constexpr uint32_t kTextureZstdLevels = 1u << 1;

struct TextureRecord { // TEXD, 64 bytes
    StringRef name;
    uint32_t width;
    uint32_t height;
    uint32_t sourceWidth;
    uint32_t sourceHeight;
    uint32_t flags;     // kTextureSrgb | kTextureZstdLevels
    uint32_t mipCount;  // full chain: floor(log2(max(width, height))) + 1
    uint32_t firstMip;  // index into MIPS
    uint32_t format;    // lfd::TextureFormat (format 2; 0 = RGBA8 in format 1)
    uint64_t texelOffset; // into TEXL
    uint64_t texelSize;   // sum of the levels' stored sizes
    uint64_t reserved1;
};
static_assert(sizeof(TextureRecord) == 64 && offsetof(TextureRecord, texelOffset) == 40);

struct MipRecord { // MIPS, 24 bytes
    uint32_t width;
    uint32_t height;
    uint64_t offset; // relative to the texture's texelOffset
    uint64_t size;   // stored bytes: lfd::textureLevelBytes, or the zstd frame's size
};
static_assert(sizeof(MipRecord) == 24);

struct NodeRecord { // NODE, 64 bytes, std430-compatible
    float translation[3];
    int32_t parent;
    float rotation[4]; // quaternion x, y, z, w (glTF order)
    float scale[3];
    int32_t mesh;
    StringRef name;
    uint32_t reserved[2];
};
static_assert(sizeof(NodeRecord) == 64 && offsetof(NodeRecord, name) == 48);

struct AnimationRecord { // ANIM, 16 bytes
    StringRef name;
    uint32_t firstChannel;
    uint32_t channelCount;
};
static_assert(sizeof(AnimationRecord) == 16);

struct ChannelRecord { // ACHN, 32 bytes
    uint32_t node;
    uint32_t path;          // lfd::AnimationPath
    uint32_t interpolation; // lfd::Interpolation
    uint32_t reserved;      // section version 2: weightOffset (Weights channels), else 0
    uint64_t firstKey; // into AKTM / AKVL
    uint64_t keyCount;
};
static_assert(sizeof(ChannelRecord) == 32);
// AKTM: float32 per key (stride 4). AKVL: float4 per key (stride 16).

struct SkinRecord { // SKIN, 16 bytes
    StringRef name;
    uint32_t firstJoint; // into SKJT, consecutive runs
    uint32_t jointCount;
};
static_assert(sizeof(SkinRecord) == 16);

struct SkinJointRecord { // SKJT, 80 bytes
    uint32_t node;
    uint32_t reserved[3];
    float inverseBindMatrix[16]; // column-major (glTF)
};
static_assert(sizeof(SkinJointRecord) == 80);

struct DeformerRecord { // DFRM, 32 bytes
    uint32_t node;
    int32_t skin; // SKIN index or -1
    uint32_t firstVertex;
    uint32_t vertexCount;
    uint32_t firstWeight; // into DFWT, consecutive runs
    uint32_t weightCount; // == morph targets per vertex
    uint32_t reserved[2];
};
static_assert(sizeof(DeformerRecord) == 32);

struct BoundsRecord { // BNDS, 48 bytes, exactly one element
    float min[3];
    float radius;
    float max[3];
    uint32_t reserved0;
    float center[3];
    uint32_t reserved1;
};
static_assert(sizeof(BoundsRecord) == 48);

struct BakeSettingsRecord { // BAKE, 64 bytes, exactly one element
    StringRef bakerVersion;
    StringRef sourceFile;
    StringRef displayProfile;
    uint32_t viewWidth;
    uint32_t viewHeight;
    uint32_t viewCount;
    uint32_t maxTextureSize;
    float maxEdgePx;
    float framingFill;
    float viewPixelWorld;
    uint32_t reserved[3];
};
static_assert(sizeof(BakeSettingsRecord) == 64);

// Round up to the section alignment (callers keep values far below overflow).
constexpr uint64_t alignUp(uint64_t value) { return (value + kAlignment - 1) / kAlignment * kAlignment; }

// XXH3_64bits with seed 0: the one checksum of the format.
uint64_t checksum(const void* data, size_t size);

// Test and tooling helper: recomputes, in place, the checksum of every section whose
// range lies inside `bytes`, then the table checksum and the header checksum. Lets tests
// build packs that are well-sealed but semantically broken. Sections outside the buffer
// keep their checksums; when the table itself does not fit, only the header is resealed;
// a buffer shorter than the header is left alone.
void resealPack(std::vector<uint8_t>& bytes);

} // namespace lfd::pack
