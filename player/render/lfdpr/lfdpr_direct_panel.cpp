#include "lfdpr_direct_panel.h"

#include "frame_uniforms.h"
#include "gpu_scene.h"
#include "lfdpr_constants.h"
#include "lfdpr_direct_fanout.h"
#include "scene_bindings.h"
#include "shader_library.h"

#include "lfd/subpixel_phase.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cstdio>
#include <utility>

namespace lfd::player {

namespace {

namespace lb = lfdpr_bindings;

// Whether two profiles give the same inverse map (the panel, its mapping and the views).
bool sameMap(const DisplayProfile& a, const DisplayProfile& b)
{
    return a.panelWidth == b.panelWidth && a.panelHeight == b.panelHeight && a.viewCount == b.viewCount &&
           a.viewWidth == b.viewWidth && a.viewHeight == b.viewHeight && a.subpixelOrder == b.subpixelOrder &&
           a.mapping.perSubpixel == b.mapping.perSubpixel && a.mapping.perRow == b.mapping.perRow &&
           a.mapping.offset == b.mapping.offset && a.mapping.invert == b.mapping.invert;
}

} // namespace

LfdprDirectPanel::LfdprDirectPanel(std::vector<std::string> defines, bool int64, bool hardwareAniso, bool exactRay)
    : defines_(std::move(defines)), int64_(int64), hardwareAniso_(hardwareAniso), exactRay_(exactRay),
      trilinear_(gl::createSampler())
{
    glSamplerParameteri(trilinear_, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glSamplerParameteri(trilinear_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glSamplerParameteri(trilinear_, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glSamplerParameteri(trilinear_, GL_TEXTURE_WRAP_T, GL_REPEAT);
    packProgram_ = gl::Program(gl::buildProgram({{GL_COMPUTE_SHADER, "lfdpr_direct_pack.comp"}}, {}));
    // The untextured group's program is always needed; built now so a shader error
    // surfaces at construction.
    shadeProgram(0u, kStreamPosition | kStreamNormal | kStreamTangent | kStreamUv, false);
}

unsigned LfdprDirectPanel::shadeProgram(uint32_t textureMask, uint32_t streams, bool taps)
{
    const uint64_t key = uint64_t(textureMask) << 33 | uint64_t(streams) << 1 | (taps ? 1u : 0u);
    if (const auto it = shadePrograms_.find(key); it != shadePrograms_.end())
        return it->second.get();
    std::vector<std::string> defines = lfdprShadeDefines(defines_, textureMask, streams, taps);
    if (exactRay_)
        defines.emplace_back("LFDPR_DIRECT_EXACT 1");
    gl::Program program(gl::buildProgram({{GL_COMPUTE_SHADER, "lfdpr_direct_shade.comp"}}, defines));
    const unsigned name = program.get();
    shadePrograms_[key] = std::move(program);
    return name;
}

void LfdprDirectPanel::resize(const DisplayProfile& profile)
{
    if (sized_ && sameMap(profile, profile_))
        return;
    profile_ = profile;
    sized_ = true;
    const LfdprDirectFanout map = buildLfdprDirectFanout(profile);
    subpixels_ = map.subpixels.size();
    mapBytes_ = (map.offsets.size() + map.subpixels.size()) * sizeof(uint32_t);
    offsets_ = gl::createBuffer(map.offsets.size() * sizeof(uint32_t), 0, map.offsets.data());
    subpixelList_ = gl::createBuffer(std::max<size_t>(subpixels_, 1) * sizeof(uint32_t), 0, map.subpixels.data());
    const size_t words = std::max<size_t>(subpixels_, 1);
    words_ = gl::createBuffer(words * (int64_ ? sizeof(uint64_t) : sizeof(uint32_t)));
    index_ = int64_ ? gl::Buffer() : gl::createBuffer(words * sizeof(uint32_t));
    // The shading reads the winners: the 64-bit words, or the 32-bit path's records.
    wordTexels_ = gl::createTexture(GL_TEXTURE_BUFFER);
    glTextureBuffer(wordTexels_, int64_ ? GL_RG32UI : GL_R32UI, int64_ ? words_ : index_);
    planes_ = gl::createTexture(GL_TEXTURE_2D_ARRAY);
    glTextureStorage3D(planes_, 1, GL_R8, GLsizei(profile.panelWidth), GLsizei(profile.panelHeight), 3);
}

void LfdprDirectPanel::beginFrame(const GpuScene& scene, const std::vector<int32_t>& texturedMaterials)
{
    // The shading groups, in lfdprMaterialGroups' order (the draws carry each one's slot).
    groups_ = lfdprShadeGroups(scene, texturedMaterials);
    // All ones = empty (a depth key beyond every depth), as the views path's words; each
    // plane to its channel of the background, by the same clear as the views' colours.
    const GLuint ones = 0xFFFFFFFFu;
    glClearNamedBufferData(words_, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &ones);
    if (index_)
        glClearNamedBufferData(index_, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &ones);
    for (GLint c = 0; c < 3; ++c)
        glClearTexSubImage(planes_, 0, 0, 0, c, GLsizei(profile_.panelWidth), GLsizei(profile_.panelHeight), 1, GL_RED,
                           GL_FLOAT, &kBackground[c]);
}

void LfdprDirectPanel::bindForSplat() const
{
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, lb::kSsboDirectOffsets, offsets_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, lb::kSsboDirectSubpixels, subpixelList_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, lb::kSsboPanelWords, words_);
    if (index_)
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, lb::kSsboPanelIndex, index_);
}

void LfdprDirectPanel::setPhaseUniforms(unsigned program) const
{
    const FixedSubpixelMapping m = fixedSubpixelMapping(profile_.mapping);
    const auto fixedUniform = [program](GLint location, uint64_t value) {
        glProgramUniform2ui(program, location, GLuint(value), GLuint(value >> 32)); // low word, high word
    };
    glProgramUniform2ui(program, lb::kLocPanelSize, profile_.panelWidth, profile_.panelHeight);
    fixedUniform(lb::kLocPerSubpixel, m.perSubpixel);
    fixedUniform(lb::kLocPerRow, m.perRow);
    fixedUniform(lb::kLocPhaseOffset, m.offset);
    glProgramUniform1i(program, lb::kLocInvertPhase, m.invert ? 1 : 0);
    glProgramUniform1i(program, lb::kLocSubpixelsBgr, profile_.subpixelOrder == SubpixelOrder::BGR ? 1 : 0);
    if (exactRay_) // only that program has it (an inactive location is a GL error)
        glProgramUniform1f(program, lb::kLocLensSubpixels, float(1.0 / profile_.mapping.perSubpixel));
}

void LfdprDirectPanel::shade(const GpuScene& scene)
{
    const LfdprConstants& k = LfdprConstants::get();
    glBindTextureUnit(lb::kUnitPanelWords, wordTexels_);
    glBindImageTexture(lb::kImageSubpixels, planes_, 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R8);
    // As LfdprVisibilityShading::listAndShade: the shader's taps only where there is
    // anisotropy to filter and the texture unit does not.
    const bool taps = !hardwareAniso_ && scene.maxAnisotropy() > 1.0f;
    constexpr GLsizei kMaterialUnits = 5;
    GLuint samplers[kMaterialUnits];
    std::fill(std::begin(samplers), std::end(samplers), taps ? GLuint(trilinear_) : 0u);
    const uint32_t shared = k.maxShadeGroups - 1;
    dispatches_ = 0;
    for (size_t g = 0; g < groups_.size(); ++g) {
        const Group& group = groups_[g];
        const GLuint program = shadeProgram(group.textureMask, scene.cpu().vertices.mask(), taps);
        setPhaseUniforms(program);
        glProgramUniform1ui(program, k.locShadeGroup, g == 0 ? 0u : 1u + uint32_t((g - 1) % shared));
        glProgramUniform1ui(program, k.locShadeMaterial, group.gpuMaterial);
        glUseProgram(program);
        scene.bindMaterialTextures(group.material);
        glBindSamplers(bindings::kUnitBaseColor, kMaterialUnits, samplers);
        glDispatchCompute(divideUp(profile_.panelWidth, lb::kDirectLocalSize),
                          divideUp(profile_.panelHeight, lb::kDirectLocalSize), 1);
        ++dispatches_;
    }
    glBindSamplers(bindings::kUnitBaseColor, kMaterialUnits, nullptr);
    glUseProgram(0);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

void LfdprDirectPanel::writePanel(unsigned eiaTexture) const
{
    glUseProgram(packProgram_);
    glProgramUniform2ui(packProgram_, lb::kLocPanelSize, profile_.panelWidth, profile_.panelHeight);
    glBindTextureUnit(lb::kUnitSubpixels, planes_);
    glBindImageTexture(lb::kImagePanel, eiaTexture, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
    glDispatchCompute(divideUp(profile_.panelWidth, lb::kDirectLocalSize),
                      divideUp(profile_.panelHeight, lb::kDirectLocalSize), 1);
    glBindImageTexture(lb::kImagePanel, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
    glBindTextureUnit(lb::kUnitSubpixels, 0);
    glUseProgram(0);
    // The panel is read back, blitted or presented next.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                    GL_FRAMEBUFFER_BARRIER_BIT);
}

} // namespace lfd::player
