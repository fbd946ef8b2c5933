// C++ mirror of shaders/scene_bindings.glsl (binding points, attribute locations, GPU
// struct layouts). The GLSL file is the definition; tests/player/shader_library_test.cpp
// reads its #defines from the embedded source and checks every constant and struct size
// here against it, so the two cannot drift apart silently.
#pragma once

#include <glm/glm.hpp>
#include <cstdint>

namespace lfd::player::bindings {

inline constexpr unsigned kAttribPosition = 0;
inline constexpr unsigned kAttribNormal = 1;
inline constexpr unsigned kAttribTangent = 2;
inline constexpr unsigned kAttribUv = 3;

inline constexpr unsigned kSsboMaterials = 0;
inline constexpr unsigned kSsboNodes = 1;
inline constexpr unsigned kSsboViews = 2;
inline constexpr unsigned kSsboTriangleStats = 3;

inline constexpr unsigned kUboFrame = 0;

inline constexpr unsigned kUnitBaseColor = 0;
inline constexpr unsigned kUnitMetallicRoughness = 1;
inline constexpr unsigned kUnitNormal = 2;
inline constexpr unsigned kUnitOcclusion = 3;
inline constexpr unsigned kUnitEmissive = 4;

inline constexpr int kLocNode = 0;
inline constexpr int kLocMaterial = 1;
inline constexpr int kLocView = 2;
inline constexpr int kLocStreams = 3;

inline constexpr uint32_t kMaterialBaseColorTexture = 1;
inline constexpr uint32_t kMaterialMetallicRoughnessTexture = 2;
inline constexpr uint32_t kMaterialNormalTexture = 4;
inline constexpr uint32_t kMaterialOcclusionTexture = 8;
inline constexpr uint32_t kMaterialEmissiveTexture = 16;
inline constexpr uint32_t kMaterialDoubleSided = 32;

inline constexpr uint32_t kAlphaOpaque = 0;
inline constexpr uint32_t kAlphaMask = 1;
inline constexpr uint32_t kAlphaBlend = 2;

// std430 layouts (see the GLSL structs of the same names).
struct MaterialGpu {
    glm::vec4 baseColorFactor;
    glm::vec4 emissiveCutoff; // xyz emissiveFactor, w alphaCutoff
    glm::vec4 params;         // metallic, roughness, normalScale, occlusionStrength
    uint32_t flags;
    uint32_t alphaMode;
    uint32_t pad0;
    uint32_t pad1;
};
static_assert(sizeof(MaterialGpu) == 64);

struct NodeGpu {
    glm::mat4 sceneFromObject;
    glm::mat4 normalFromObject;
};
static_assert(sizeof(NodeGpu) == 128);

struct ViewGpu {
    glm::mat4 clipFromScene;
    glm::vec4 eyeScene;
};
static_assert(sizeof(ViewGpu) == 80);

// std140 FrameBlock.
struct FrameGpu {
    glm::vec4 lightDirScene;
    glm::vec4 lightColor;
    glm::vec4 ambientColor;
    glm::vec4 background;
    uint32_t viewCount;
    uint32_t viewWidth;
    uint32_t viewHeight;
    uint32_t framePad;
};
static_assert(sizeof(FrameGpu) == 80);

} // namespace lfd::player::bindings
