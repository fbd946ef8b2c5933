#include "gpu_scene.h"

#include "gl_context.h"
#include "gpu_texture_format.h"
#include "scene_bindings.h"

#include "lfd/scene_animation.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>

namespace lfd::player {

namespace {

// The baker's per-triangle statistics are uploaded as they are stored, so lfd::TriangleStats
// (formats/) must be the generated TriangleStatsGpu byte for byte.
static_assert(sizeof(TriangleStats) == sizeof(bindings::TriangleStatsGpu));
static_assert(offsetof(TriangleStats, areaWorld) == offsetof(bindings::TriangleStatsGpu, areaWorld));
static_assert(offsetof(TriangleStats, areaTexture) == offsetof(bindings::TriangleStatsGpu, areaTexture));
static_assert(offsetof(TriangleStats, texelCount) == offsetof(bindings::TriangleStatsGpu, texelCount));
static_assert(offsetof(TriangleStats, sizeUv) == offsetof(bindings::TriangleStatsGpu, sizeUv));
static_assert(offsetof(TriangleStats, texPerWorld) == offsetof(bindings::TriangleStatsGpu, texPerWorld));
static_assert(offsetof(TriangleStats, flags) == offsetof(bindings::TriangleStatsGpu, flags));

// A buffer counted in the scene's GPU bytes (gl::createBuffer keeps at least 16 bytes, so
// every SSBO binding stays valid for empty scenes).
gl::Buffer makeBuffer(const void* data, size_t bytes, GLbitfield flags, size_t& total)
{
    total += std::max<size_t>(bytes, 16);
    return gl::createBuffer(bytes, flags, data);
}

bindings::MaterialGpu toGpu(const Material& m, const std::vector<Texture>& textures)
{
    bindings::MaterialGpu g{};
    g.baseColorFactor = m.baseColorFactor;
    g.emissiveCutoff = glm::vec4(m.emissiveFactor, m.alphaCutoff);
    g.params = glm::vec4(m.metallicFactor, m.roughnessFactor, m.normalScale, m.occlusionStrength);
    const bool twoChannelNormals = m.normalTexture >= 0 && size_t(m.normalTexture) < textures.size() &&
                                   textures[size_t(m.normalTexture)].format == TextureFormat::Bc5;
    g.flags = materialTextureFlags(m) | (m.doubleSided ? bindings::kMaterialDoubleSided : 0u) |
              (twoChannelNormals ? bindings::kMaterialNormalTwoChannel : 0u) |
              (m.unlit ? bindings::kMaterialUnlit : 0u);
    g.alphaMode = uint32_t(m.alphaMode);
    // KHR_texture_transform per slot: the linear part's columns, the offset and |det|.
    for (uint32_t slot = 0; slot < kTextureSlotCount; ++slot) {
        const TextureTransform& t = m.textureTransforms[slot];
        g.uvLinear[slot] = glm::vec4(t.linear[0], t.linear[1]);
        g.uvOffset[slot] = glm::vec4(t.offset, t.areaScale(), 0.0f);
    }
    return g;
}

// The anisotropy the driver gives for `wanted` (GL 4.6 or EXT/ARB_texture_filter_anisotropic;
// 1 without them, with a warning when more was asked for).
float supportedAnisotropy(float wanted)
{
    if (wanted <= 1.0f)
        return 1.0f;
    if (epoxy_gl_version() < 46 && !epoxy_has_gl_extension("GL_EXT_texture_filter_anisotropic") &&
        !epoxy_has_gl_extension("GL_ARB_texture_filter_anisotropic")) {
        std::fprintf(stderr, "lfd: warning: --aniso %g: the driver has no anisotropic filtering "
                             "(GL_EXT_texture_filter_anisotropic); textures are trilinear\n", double(wanted));
        return 1.0f;
    }
    GLfloat limit = 1.0f;
    glGetFloatv(GL_MAX_TEXTURE_MAX_ANISOTROPY, &limit);
    return std::min(wanted, limit);
}

// One pack texture as a GL texture holding pack levels [layout.firstPackLevel, ..): the
// format's storage and swizzle (gpu_texture_format.h), trilinear filtering and glTF's
// default REPEAT wrap. Without `streamed` every level is uploaded now; streamed, nothing
// is resident yet and the base level is the coarsest: the streamer lowers it as finer
// levels arrive, so sampling never reads a level that has not been uploaded.
gl::Texture createGlTexture(const Texture& tex, const GpuTextureLayout& layout, bool streamed, float anisotropy,
                            size_t& gpuBytes)
{
    gl::Texture name = gl::createTexture(GL_TEXTURE_2D);
    const GLsizei levels = GLsizei(layout.levels);
    const uint32_t first = layout.firstPackLevel;
    const GlTextureFormat format = glTextureFormat(tex.format, tex.srgb);
    glTextureStorage2D(name, levels, format.internalFormat, GLsizei(tex.mips[first].width),
                       GLsizei(tex.mips[first].height));
    glTextureParameteriv(name, GL_TEXTURE_SWIZZLE_RGBA, format.swizzle);
    for (GLsizei level = 0; level < levels; ++level) {
        const MipLevel& mip = tex.mips[size_t(level) + first];
        const uint32_t units = (mip.height + rowsPerUnit(tex.format) - 1) / rowsPerUnit(tex.format);
        if (!streamed)
            uploadLevelRows(name, level, tex.format, format, mip.width, mip.height, 0, units,
                            tex.texels.data() + mip.offset);
        gpuBytes += mip.size;
    }
    glTextureParameteri(name, GL_TEXTURE_BASE_LEVEL, streamed ? levels - 1 : 0);
    glTextureParameteri(name, GL_TEXTURE_MAX_LEVEL, levels - 1);
    glTextureParameteri(name, GL_TEXTURE_MIN_FILTER, levels > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
    glTextureParameteri(name, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(name, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(name, GL_TEXTURE_WRAP_T, GL_REPEAT);
    if (anisotropy > 1.0f)
        glTextureParameterf(name, GL_TEXTURE_MAX_ANISOTROPY, anisotropy);
    return name;
}

// One draw per (node, primitive) of every node that has a mesh, empty primitives skipped.
std::vector<DrawItem> drawItems(const Scene& scene)
{
    std::vector<DrawItem> draws;
    for (uint32_t n = 0; n < scene.nodes.size(); ++n) {
        const Node& node = scene.nodes[n];
        if (node.mesh == kNone)
            continue;
        const Mesh& mesh = scene.meshes[size_t(node.mesh)];
        for (uint32_t p = mesh.firstPrimitive; p < mesh.firstPrimitive + mesh.primitiveCount; ++p) {
            const Primitive& prim = scene.primitives[p];
            if (prim.indexCount != 0)
                draws.push_back({n, p, prim.firstIndex, prim.indexCount, prim.material});
        }
    }
    return draws;
}

} // namespace

uint32_t materialTextureFlags(const Material& m)
{
    bool transformed = false; // a textured slot with a KHR_texture_transform
    for (uint32_t slot = 0; slot < kTextureSlotCount; ++slot)
        transformed |= m.texture(TextureSlot(slot)) != kNone && !m.textureTransforms[slot].identity();
    return (m.baseColorTexture != kNone ? bindings::kMaterialBaseColorTexture : 0u) |
           (m.metallicRoughnessTexture != kNone ? bindings::kMaterialMetallicRoughnessTexture : 0u) |
           (m.normalTexture != kNone ? bindings::kMaterialNormalTexture : 0u) |
           (m.occlusionTexture != kNone ? bindings::kMaterialOcclusionTexture : 0u) |
           (m.emissiveTexture != kNone ? bindings::kMaterialEmissiveTexture : 0u) |
           (transformed ? bindings::kMaterialUvTransform : 0u);
}

namespace {
std::atomic<uint64_t> g_sceneSerial{0};
} // namespace

GpuScene::GpuScene(Scene scene, const GpuSceneOptions& options)
    : scene_(std::move(scene)), serial_(++g_sceneSerial)
{
    // Step 0: what fits (GL_MAX_TEXTURE_SIZE, the budget); planned before any allocation.
    GpuMemoryPlan ownPlan;
    const GpuMemoryPlan* plan = options.plan;
    if (!plan) {
        ownPlan = planGpuMemory(scene_, "scene", std::nullopt, queryGpuLimits().maxTextureSize);
        for (const std::string& warning : ownPlan.warnings)
            std::fprintf(stderr, "warning: %s\n", warning.c_str());
        plan = &ownPlan;
    }
    const GLbitfield streamedFlags = options.streamed ? GL_DYNAMIC_STORAGE_BIT : 0;

    // Step 1: one vertex buffer per present stream, bound at binding index = location.
    vao_ = gl::createVertexArray();
    auto addStream = [&](unsigned location, const void* data, size_t count, GLint components,
                         size_t stride) {
        if (count == 0)
            return;
        streamVbos_[location] =
            makeBuffer(options.streamed ? nullptr : data, count * stride, streamedFlags, gpuBytes_);
        glVertexArrayVertexBuffer(vao_, location, streamVbos_[location], 0, GLsizei(stride));
        glVertexArrayAttribFormat(vao_, location, components, GL_FLOAT, GL_FALSE, 0);
        glVertexArrayAttribBinding(vao_, location, location);
        glEnableVertexArrayAttrib(vao_, location);
    };
    const VertexStreams& v = scene_.vertices;
    addStream(bindings::kAttribPosition, v.positions.data(), v.positions.size(), 3, sizeof(glm::vec3));
    addStream(bindings::kAttribNormal, v.normals.data(), v.normals.size(), 3, sizeof(glm::vec3));
    addStream(bindings::kAttribTangent, v.tangents.data(), v.tangents.size(), 4, sizeof(glm::vec4));
    addStream(bindings::kAttribUv, v.uvs.data(), v.uvs.size(), 2, sizeof(glm::vec2));
    ibo_ = makeBuffer(options.streamed ? nullptr : scene_.indices.data(), scene_.indices.size() * sizeof(uint32_t),
                      streamedFlags, gpuBytes_);
    glVertexArrayElementBuffer(vao_, ibo_);

    // Step 2: textures with the pack's full mip chain; colour textures decode sRGB in the
    // sampler, data textures stay linear. Trilinear filtering, glTF's default REPEAT wrap.
    textures_.reserve(scene_.textures.size());
    anisotropy_ = supportedAnisotropy(options.maxAnisotropy);
    for (size_t t = 0; t < scene_.textures.size(); ++t) {
        Texture& tex = scene_.textures[t];
        if (tex.mips.empty() || (!options.streamed && tex.texels.empty()))
            throw gl::GlError("pack texture " + std::to_string(t) + " (" + tex.name +
                              ") has no texels to upload");
        // Top levels the plan leaves out: GL level l holds pack level first + l.
        const uint32_t first = t < plan->droppedLevels.size() ? plan->droppedLevels[t] : 0u;
        const GpuTextureLayout layout{first, uint32_t(tex.mips.size()) - first};
        textures_.push_back(createGlTexture(tex, layout, options.streamed, anisotropy_, gpuBytes_));
        layouts_.push_back(layout);
        // The texels live on the GPU now; keep the metadata only.
        std::vector<uint8_t>().swap(tex.texels);
    }

    // Step 3: materials, plus the default material (glTF defaults) at index
    // materials.size() for primitives with material -1.
    std::vector<bindings::MaterialGpu> materials;
    materials.reserve(scene_.materials.size() + 1);
    for (const Material& m : scene_.materials)
        materials.push_back(toGpu(m, scene_.textures));
    materials.push_back(toGpu(Material{}, scene_.textures));
    for (const bindings::MaterialGpu& g : materials) {
        std::array<glm::vec4, 2 * kTextureSlotCount>& t = uvTransforms_.emplace_back();
        for (uint32_t slot = 0; slot < kTextureSlotCount; ++slot) {
            t[2 * slot] = g.uvLinear[slot];
            t[2 * slot + 1] = g.uvOffset[slot];
        }
    }
    materialSsbo_ = makeBuffer(materials.data(), materials.size() * sizeof(materials[0]), 0, gpuBytes_);
    statsSsbo_ = makeBuffer(options.streamed ? nullptr : scene_.triangleStats.data(),
                            scene_.triangleStats.size() * sizeof(TriangleStats), streamedFlags, gpuBytes_);

    // Step 4: one draw per (node, primitive) of every node that has a mesh.
    draws_ = drawItems(scene_);

    // Step 5: per-node transforms (rewritten every frame by update()).
    nodeSsbo_ = makeBuffer(nullptr, std::max<size_t>(scene_.nodes.size(), 1) * sizeof(bindings::NodeGpu),
                           GL_DYNAMIC_STORAGE_BIT, gpuBytes_);
    // Step 6: the pose pass, for skinned and morphed meshes only.
    if (!scene_.deformers.empty())
        poser_ = std::make_unique<ScenePoser>(scene_, gpuBytes_);
    update(0.0);
}

void GpuScene::pose()
{
    if (!poser_)
        return;
    const PoseTargets targets{streamVbos_[bindings::kAttribPosition], streamVbos_[bindings::kAttribNormal],
                              streamVbos_[bindings::kAttribTangent], ibo_, statsSsbo_};
    poser_->pose(scene_, sceneFromNode_, float(time_), targets);
}

void GpuScene::update(double time)
{
    time_ = time;
    sceneFromNode_ = nodeWorldMatrices(scene_, float(time));
    if (sceneFromNode_.empty())
        return;
    std::vector<bindings::NodeGpu> nodes(sceneFromNode_.size());
    for (size_t i = 0; i < nodes.size(); ++i) {
        nodes[i].sceneFromObject = sceneFromNode_[i];
        // Normals transform by the inverse transpose; a node scaled to zero (collapsed by
        // an animation) has no inverse and draws nothing visible, keep its normals as is.
        const glm::mat3 m(sceneFromNode_[i]);
        const bool invertible = std::abs(glm::determinant(m)) > 1e-20f;
        nodes[i].normalFromObject = glm::mat4(invertible ? glm::transpose(glm::inverse(m)) : m);
    }
    glNamedBufferSubData(nodeSsbo_, 0, GLsizeiptr(nodes.size() * sizeof(nodes[0])), nodes.data());
}

unsigned GpuScene::texture(int32_t index) const
{
    if (index < 0 || size_t(index) >= textures_.size())
        return 0;
    return textures_[size_t(index)].get();
}

void GpuScene::bindMaterialTextures(int32_t material) const
{
    const Material* m = material == kNone ? nullptr : &scene_.materials[size_t(material)];
    const GLuint units[5] = {m ? texture(m->baseColorTexture) : 0, m ? texture(m->metallicRoughnessTexture) : 0,
                             m ? texture(m->normalTexture) : 0, m ? texture(m->occlusionTexture) : 0,
                             m ? texture(m->emissiveTexture) : 0};
    glBindTextures(bindings::kUnitBaseColor, 5, units);
}

uint32_t GpuScene::gpuMaterialIndex(int32_t material) const
{
    return material == kNone ? uint32_t(scene_.materials.size()) : uint32_t(material);
}

} // namespace lfd::player
