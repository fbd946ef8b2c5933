// In-memory scene model: the contract between baker -> formats -> player.
//
// The baker fills a Scene, formats/ writes it to a .lfdpack and reads it back
// (validated), the player uploads it. Nothing outside formats/ parses pack bytes.
//
// Spaces (pbrt-style xFromY naming is used elsewhere):
//   object space  - vertex streams, per-triangle statistics (A_ws is in object units^2;
//                   the player multiplies by the node's world area scale at run time)
//   scene space   - glTF world space (node hierarchy applied), bounds are in scene space
//   display space - millimetres, origin at the screen centre, +x right, +y up,
//                   +z towards the viewer (see display_profile.h / framing.h)
#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace lfd {

inline constexpr int32_t kNone = -1;

// Which optional vertex streams are present. Position is always present; the other
// streams are stored only when the scene uses them ("store only used attributes").
enum VertexStreamBits : uint32_t {
    kStreamPosition = 1u << 0,
    kStreamNormal = 1u << 1,
    kStreamTangent = 1u << 2, // only when some material has a normal map
    kStreamUv = 1u << 3,      // TEXCOORD_0, only when some material has a texture
};

// Skin influences and morph-target deltas (glTF 2.0 sections 3.7.2.2 and 3.7.3): stored
// only when some node is skinned / some mesh is morphed. The player poses them into the
// streams above every frame (formats/README.md "Deformation"); the rest pose stays here.
struct DeformationStreams {
    // JOINTS_0 / WEIGHTS_0: indices into the owning deformer's Skin::joints and weights
    // summing to 1 (the four largest, renormalised). Empty, or one per vertex.
    std::vector<glm::uvec4> joints;
    std::vector<glm::vec4> weights;
    // Morph deltas, vertex-major: target t of vertex v at [v * morphTargets + t]. A
    // vertex of an unmorphed mesh holds zeros. Normal / tangent deltas only when the
    // scene stores that stream and some target has them.
    uint32_t morphTargets = 0;
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec3> tangents;

    bool skinned() const { return !joints.empty(); }
    bool empty() const { return joints.empty() && morphTargets == 0; }
};

struct VertexStreams {
    std::vector<glm::vec3> positions; // always
    std::vector<glm::vec3> normals;   // empty, or positions.size()
    std::vector<glm::vec4> tangents;  // empty, or positions.size(); w = handedness (+-1)
    std::vector<glm::vec2> uvs;       // empty, or positions.size()
    DeformationStreams deform;        // empty for static scenes

    uint32_t mask() const
    {
        return kStreamPosition | (normals.empty() ? 0u : kStreamNormal) |
               (tangents.empty() ? 0u : kStreamTangent) | (uvs.empty() ? 0u : kStreamUv);
    }
    size_t size() const { return positions.size(); }
};

// A contiguous run of triangles sharing one material. Indices are absolute into
// Scene::vertices (one vertex buffer, one index buffer for the whole scene).
// Triangle t of the scene is indices[3t..3t+2]; its statistics are triangleStats[t].
struct Primitive {
    uint32_t firstIndex = 0;  // multiple of 3
    uint32_t indexCount = 0;  // multiple of 3
    int32_t material = kNone; // index into Scene::materials, or kNone (default material)
};

struct Mesh {
    std::string name;
    uint32_t firstPrimitive = 0;
    uint32_t primitiveCount = 0;
};

// Rigid node transform, glTF semantics: local = T * R * S. glTF nodes given as a
// matrix are decomposed by the baker (a matrix with shear is an error).
struct Node {
    std::string name;
    int32_t parent = kNone; // parents always precede children (parent < own index)
    int32_t mesh = kNone;
    glm::vec3 translation{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f}; // glm order: w, x, y, z
    glm::vec3 scale{1.0f};
};

// A skin (glTF 3.7.3): joint nodes and their inverse bind matrices (identity where the
// glTF gives none).
struct Skin {
    std::string name;
    std::vector<uint32_t> joints; // node indices
    std::vector<glm::mat4> inverseBindMatrices; // joints.size() entries
};

// One node instance of a skinned and/or morphed mesh. The baker gives each such instance
// its own copy of the mesh, so the posed vertices [firstVertex, +vertexCount) belong to
// this instance alone (they are the mesh's whole vertex range).
struct Deformer {
    uint32_t node = 0;
    int32_t skin = kNone;         // Scene::skins index, or kNone (morph only)
    uint32_t firstVertex = 0;
    uint32_t vertexCount = 0;
    std::vector<float> weights;   // default morph weights, DeformationStreams::morphTargets entries
};

// Weights: a morph-weight channel drives weights [weightOffset, +4) of the node's
// deformer (a glTF "weights" channel of N targets becomes ceil(N / 4) channels).
enum class AnimationPath : uint32_t { Translation = 0, Rotation = 1, Scale = 2, Weights = 3 };
enum class Interpolation : uint32_t { Linear = 0, Step = 1 }; // cubic spline is linearised by the baker

struct AnimationChannel {
    uint32_t node = 0;
    AnimationPath path = AnimationPath::Translation;
    Interpolation interpolation = Interpolation::Linear;
    std::vector<float> times;      // seconds, strictly increasing, size >= 1
    std::vector<glm::vec4> values; // size == times.size(); xyz for T/S, quaternion xyzw for R, 4 weights
    uint32_t weightOffset = 0;     // Weights only: the first morph weight the values drive
};

struct Animation {
    std::string name;
    std::vector<AnimationChannel> channels;
};

enum class AlphaMode : uint32_t { Opaque = 0, Mask = 1, Blend = 2 };

// The material's texture slots, in MaterialRecord / MaterialGpu order.
enum class TextureSlot : uint32_t { BaseColor = 0, MetallicRoughness = 1, Normal = 2, Occlusion = 3, Emissive = 4 };
inline constexpr uint32_t kTextureSlotCount = 5;

// KHR_texture_transform of one textureInfo, as the affine map the shaders apply to
// TEXCOORD_0: uv' = linear * uv + offset, with
//   linear = R * S, S = diag(scale), R = [[cos r, sin r], [-sin r, cos r]] (rows; the
//   extension's "counter-clockwise in uv space", as the Khronos sample viewer and
//   Cesium apply it: u' = u cos r + v sin r, v' = v cos r - u sin r).
// Identity by default; a textureInfo without the extension keeps the identity.
struct TextureTransform {
    glm::mat2 linear{1.0f}; // glm column-major: linear[c][r]
    glm::vec2 offset{0.0f};

    // The extension's offset, rotation (radians) and scale, as the map above.
    static TextureTransform fromOffsetRotationScale(glm::vec2 offset, float rotation, glm::vec2 scale)
    {
        const float c = std::cos(rotation), s = std::sin(rotation);
        TextureTransform t;
        t.linear = glm::mat2(c * scale.x, -s * scale.x, s * scale.y, c * scale.y); // R * S, columns
        t.offset = offset;
        return t;
    }

    glm::vec2 apply(glm::vec2 uv) const { return linear * uv + offset; }
    // |det linear|: how much the map scales texture-space areas (A_ts of this slot).
    float areaScale() const { float d = glm::determinant(linear); return d < 0.0f ? -d : d; }
    bool identity() const { return linear == glm::mat2(1.0f) && offset == glm::vec2(0.0f); }
    bool operator==(const TextureTransform&) const = default;
};

// glTF 2.0 metallic-roughness material. Texture fields index Scene::textures.
struct Material {
    std::string name;
    glm::vec4 baseColorFactor{1.0f};
    glm::vec3 emissiveFactor{0.0f};
    float metallicFactor = 1.0f;
    float roughnessFactor = 1.0f;
    float normalScale = 1.0f;
    float occlusionStrength = 1.0f;
    float alphaCutoff = 0.5f;
    AlphaMode alphaMode = AlphaMode::Opaque;
    bool doubleSided = false;
    int32_t baseColorTexture = kNone;         // sRGB
    int32_t metallicRoughnessTexture = kNone; // linear (G = roughness, B = metallic)
    int32_t normalTexture = kNone;            // linear
    int32_t occlusionTexture = kNone;         // linear (R)
    int32_t emissiveTexture = kNone;          // sRGB
    // KHR_materials_unlit: the colour is the base colour (factor x texture) alone - no
    // lighting, environment, exposure or tone mapping.
    bool unlit = false;
    // KHR_texture_transform per slot (TextureSlot order); identity where absent.
    TextureTransform textureTransforms[kTextureSlotCount];

    int32_t texture(TextureSlot slot) const
    {
        const int32_t t[kTextureSlotCount] = {baseColorTexture, metallicRoughnessTexture, normalTexture,
                                              occlusionTexture, emissiveTexture};
        return t[uint32_t(slot)];
    }
    const TextureTransform& transform(TextureSlot slot) const { return textureTransforms[uint32_t(slot)]; }
    // Whether the material needs the pack's material-extension record (unlit or a
    // non-identity texture transform).
    bool hasExtensions() const
    {
        if (unlit)
            return true;
        for (const TextureTransform& t : textureTransforms)
            if (!t.identity())
                return true;
        return false;
    }
};

// KHR_lights_punctual, one light per node instance: the light sits at the node's origin
// and shines along the node's -Z axis (scene space, node hierarchy and animation
// applied), so lights attached to animated nodes move with them.
enum class LightType : uint32_t { Directional = 0, Point = 1, Spot = 2 };

struct Light {
    std::string name;
    LightType type = LightType::Directional;
    uint32_t node = 0;           // Scene::nodes index
    glm::vec3 color{1.0f};       // linear RGB
    float intensity = 1.0f;      // directional: lux (lm/m^2); point and spot: candela (lm/sr)
    float range = 0.0f;          // point and spot: distance where the light reaches zero; 0 = unlimited
    float innerConeAngle = 0.0f; // spot only, radians, 0 <= inner < outer <= pi/2
    float outerConeAngle = 0.78539816f; // spot only (glTF default pi/4)
};

struct MipLevel {
    uint32_t width = 0;
    uint32_t height = 0;
    uint64_t offset = 0; // byte offset into Texture::texels
    uint64_t size = 0;   // textureLevelBytes(format, width, height)

    bool operator==(const MipLevel&) const = default;
};

// How a texture's texels are laid out, as the GPU takes them (formats/README.md "TEXD").
// The block formats hold 4x4 texel blocks, rows of blocks top to bottom; a level smaller
// than a block still takes one block per dimension.
enum class TextureFormat : uint32_t {
    Rgba8 = 0, // 4 bytes per texel
    Bc1 = 1,   // RGB, alpha 1 (S3TC DXT1, 8 bytes per block)
    Bc3 = 2,   // RGBA (S3TC DXT5, 16 bytes per block)
    Bc4 = 3,   // one channel, replicated to RGB by the sampler, alpha 1 (RGTC1, 8 bytes)
    Bc5 = 4,   // two channels: a normal map's x, y; z = sqrt(1 - x^2 - y^2) (RGTC2, 16 bytes)
};
inline constexpr uint32_t kTextureFormatCount = 5;

const char* textureFormatName(TextureFormat format); // "RGBA8", "BC1", ...
bool isBlockCompressed(TextureFormat format);
// Bytes of one width x height level (whole 4x4 blocks for the block formats).
uint64_t textureLevelBytes(TextureFormat format, uint32_t width, uint32_t height);
// The full chain level 0 .. 1x1 (max(1, w >> l) x max(1, h >> l)), back to back from 0.
std::vector<MipLevel> textureMipChain(uint32_t width, uint32_t height, TextureFormat format);
uint64_t textureChainBytes(uint32_t width, uint32_t height, TextureFormat format);

// A texture with its full mip chain (level 0 .. 1x1), levels stored back to back.
struct Texture {
    std::string name;
    uint32_t width = 0;  // level 0 as stored (after any reduction)
    uint32_t height = 0;
    uint32_t sourceWidth = 0; // as decoded from the source image
    uint32_t sourceHeight = 0;
    bool srgb = false; // colour data (baseColor, emissive) is sRGB-encoded
    TextureFormat format = TextureFormat::Rgba8;
    std::vector<MipLevel> mips;
    std::vector<uint8_t> texels;
};

// Per-triangle statistics, paper section 3.1 (eqs. texelCount, lfd_UVSize).
enum TriangleFlags : uint32_t {
    kTriangleTextured = 1u << 0,   // material has at least one texture and uvs exist
    kTriangleDegenerate = 1u << 1, // zero world area (stats are zero)
};

// Texture transforms (Material::textureTransforms): A_ts of texture t is the triangle's
// area in t's own uv space, areaTexture * areaScale() of the slot that samples t, so
// texelCount and sizeUv follow the transforms. areaTexture and texPerWorld stay in
// TEXCOORD_0's space: a consumer multiplies them by a slot's areaScale() itself.
struct TriangleStats {
    float areaWorld = 0.0f;   // A_ws, object units^2
    float areaTexture = 0.0f; // A_ts of TEXCOORD_0, uv units^2 (untransformed)
    float texelCount = 0.0f;  // n_tex = max_t areaTexture * areaScale(slot of t) * X_t * Y_t
    float sizeUv = 0.0f;      // size_uv = A_ws / n_tex  (0 when untextured)
    float texPerWorld = 0.0f; // areaTexture / A_ws (TEXCOORD_0), for size_vpuv (0 when untextured/degenerate)
    uint32_t flags = 0;       // TriangleFlags
};
static_assert(sizeof(TriangleStats) == 24, "TriangleStats is a GPU-visible layout");

struct SceneBounds {
    glm::vec3 min{0.0f}; // scene-space AABB, conservative over all animation keys
    glm::vec3 max{0.0f};
    glm::vec3 center{0.0f}; // bounding sphere (the turntable rotates about center)
    float radius = 0.0f;
};

// What the baker was asked to do; stored so the player can reproduce the framing the
// tessellation bound assumed, and so a pack says how it was made.
struct BakeSettings {
    std::string bakerVersion;
    std::string sourceFile;     // file name only, no directories
    std::string displayProfile; // profile name
    uint32_t viewWidth = 0;
    uint32_t viewHeight = 0;
    uint32_t viewCount = 0;
    float maxEdgePx = 100.0f;      // tessellation bound in view pixels
    float framingFill = 1.0f;      // see framing.h
    float viewPixelWorld = 0.0f;   // scene units per view pixel used for the bound (conservative)
    uint32_t maxTextureSize = 0;   // largest texture dimension kept
};

struct Scene {
    VertexStreams vertices;
    std::vector<uint32_t> indices; // triangle list
    std::vector<TriangleStats> triangleStats; // indices.size() / 3 entries
    std::vector<Primitive> primitives;
    std::vector<Mesh> meshes;
    std::vector<Material> materials;
    std::vector<Texture> textures;
    std::vector<Node> nodes;
    std::vector<Animation> animations;
    std::vector<Skin> skins;
    std::vector<Deformer> deformers; // by firstVertex, ranges disjoint
    std::vector<Light> lights;       // KHR_lights_punctual instances; empty: the player's default light
    SceneBounds bounds;
    BakeSettings settings;

    size_t triangleCount() const { return indices.size() / 3; }
    // Triangles drawn per frame: every node instance of a mesh counts its triangles.
    size_t drawnTriangleCount() const
    {
        size_t drawn = 0;
        for (const Node& node : nodes) {
            if (node.mesh < 0 || size_t(node.mesh) >= meshes.size())
                continue;
            const Mesh& mesh = meshes[size_t(node.mesh)];
            for (uint32_t p = mesh.firstPrimitive; p < mesh.firstPrimitive + mesh.primitiveCount && p < primitives.size(); ++p)
                drawn += primitives[p].indexCount / 3;
        }
        return drawn;
    }
};

} // namespace lfd
