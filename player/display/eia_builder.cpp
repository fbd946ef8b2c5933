// EIA construction: the compute pass (shaders/eia_construct.comp) and its CPU reference.
// Both implement the same nearest-view mapping with the same arithmetic (phase in double
// precision through lfd::subpixelPhase's operations, view texel in integer arithmetic,
// no filtering), so their outputs are bit-identical; eia_test checks that.
#include "eia_builder.h"

#include "frame_stages.h"
#include "gl_context.h"
#include "gpu_timer.h"
#include "shader_library.h"
#include "view_targets.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <stdexcept>

namespace lfd::player {

namespace {

// View texel (image order: row 0 = top) under subpixel column k on panel row l: the view
// pixel containing the subpixel's screen position ((k + 0.5) / 3W, (l + 0.5) / H),
// computed without rounding as floor((2k + 1) w / 6W) and floor((2l + 1) h / 2H).
inline uint32_t viewColumnUnder(uint32_t k, uint32_t panelWidth, uint32_t viewWidth) {
    return uint32_t((uint64_t(2 * k + 1) * viewWidth) / (6ull * panelWidth));
}
inline uint32_t viewRowUnder(uint32_t l, uint32_t panelHeight, uint32_t viewHeight) {
    return uint32_t((uint64_t(2 * l + 1) * viewHeight) / (2ull * panelHeight));
}

GLint uniformLocation(GLuint program, const char* name) {
    const GLint location = glGetUniformLocation(program, name);
    if (location < 0)
        throw gl::GlError(std::string("shaders/eia_construct.comp: uniform '") + name +
                          "' not found (removed or optimised out)");
    return location;
}

} // namespace

Reconstruction parseReconstruction(const std::string& name) {
    if (name == "none")
        return Reconstruction::None;
    throw std::invalid_argument("unknown reconstruction '" + name + "' (expected: none)");
}

EiaBuilder::EiaBuilder(const DisplayProfile& profile) : profile_(profile) {
    validateDisplayProfile(profile_, profile_.name.empty() ? "display profile" : profile_.name);
    program_ = gl::buildProgram({{GL_COMPUTE_SHADER, "eia_construct.comp"}});
    glCreateTextures(GL_TEXTURE_2D, 1, &eia_);
    glTextureStorage2D(eia_, 1, GL_RGBA8, GLsizei(profile_.panelWidth),
                       GLsizei(profile_.panelHeight));
    glTextureParameteri(eia_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(eia_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    if (glGetError() != GL_NO_ERROR) {
        glDeleteTextures(1, &eia_);
        glDeleteProgram(program_);
        throw gl::GlError("EIA: cannot allocate a " + std::to_string(profile_.panelWidth) + "x" +
                          std::to_string(profile_.panelHeight) +
                          " RGBA8 texture for display profile '" + profile_.name + "'");
    }
}

EiaBuilder::~EiaBuilder() {
    glDeleteTextures(1, &eia_);
    glDeleteProgram(program_);
}

void EiaBuilder::build(const ViewTargets& views, Reconstruction mode, GpuTimer& timer) {
    if (views.viewCount() != profile_.viewCount)
        throw std::invalid_argument("EIA: " + std::to_string(views.viewCount()) +
                                    " rendered views, display profile '" + profile_.name +
                                    "' needs " + std::to_string(profile_.viewCount));
    const SubpixelMapping& m = profile_.mapping;

    // Step 1: uniforms (looked up by name, so nothing is mirrored by hand).
    glUseProgram(program_);
    glUniform2ui(uniformLocation(program_, "panelSize"), profile_.panelWidth, profile_.panelHeight);
    glUniform2ui(uniformLocation(program_, "viewSize"), views.width(), views.height());
    glUniform1ui(uniformLocation(program_, "viewCount"), profile_.viewCount);
    glUniform1d(uniformLocation(program_, "perSubpixel"), m.perSubpixel);
    glUniform1d(uniformLocation(program_, "perRow"), m.perRow);
    glUniform1d(uniformLocation(program_, "phaseOffset"), m.offset);
    glUniform1i(uniformLocation(program_, "invertPhase"), m.invert ? 1 : 0);
    glUniform1i(uniformLocation(program_, "subpixelsBgr"),
                profile_.subpixelOrder == SubpixelOrder::BGR ? 1 : 0);
    // note: with a single mode the compiler may drop `mode`; glUniform on location -1 is a
    // defined no-op, so it is the one uniform that may be missing.
    glUniform1ui(glGetUniformLocation(program_, "mode"), uint32_t(mode));

    // Step 2: inputs and output on the units the shader declares. A nearest-filter sampler
    // object keeps the view array complete whatever its own filter state (texelFetch does
    // not filter, but an incomplete texture would read as zero).
    GLint textureUnit = 0, imageUnit = 0;
    glGetUniformiv(program_, uniformLocation(program_, "views"), &textureUnit);
    glGetUniformiv(program_, uniformLocation(program_, "eia"), &imageUnit);
    GLuint sampler = 0;
    glCreateSamplers(1, &sampler);
    glSamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glSamplerParameteri(sampler, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTextureUnit(GLuint(textureUnit), views.colorArray());
    glBindSampler(GLuint(textureUnit), sampler);
    glBindImageTexture(GLuint(imageUnit), eia_, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);

    // Step 3: one invocation per panel pixel.
    GLint localSize[3] = {1, 1, 1};
    glGetProgramiv(program_, GL_COMPUTE_WORK_GROUP_SIZE, localSize);
    timer.begin(stage::kEia);
    glDispatchCompute((profile_.panelWidth + GLuint(localSize[0]) - 1) / GLuint(localSize[0]),
                      (profile_.panelHeight + GLuint(localSize[1]) - 1) / GLuint(localSize[1]), 1);
    timer.end();
    // Later consumers: texture reads (display, quilt), readback, blits.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                    GL_TEXTURE_UPDATE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);

    glBindSampler(GLuint(textureUnit), 0);
    glDeleteSamplers(1, &sampler);
    glBindImageTexture(GLuint(imageUnit), 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
    glUseProgram(0);
}

std::vector<uint8_t> EiaBuilder::read() const {
    const size_t rowBytes = size_t(profile_.panelWidth) * 4;
    std::vector<uint8_t> glOrder(rowBytes * profile_.panelHeight);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureImage(eia_, 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(glOrder.size()),
                      glOrder.data());
    // GL row 0 is the bottom of the panel; return image order.
    std::vector<uint8_t> image(glOrder.size());
    for (uint32_t y = 0; y < profile_.panelHeight; ++y)
        std::copy_n(&glOrder[size_t(profile_.panelHeight - 1 - y) * rowBytes], rowBytes,
                    &image[size_t(y) * rowBytes]);
    return image;
}

std::vector<uint8_t> buildEiaCpu(const DisplayProfile& profile,
                                 const std::vector<std::vector<uint8_t>>& views,
                                 uint32_t viewWidth, uint32_t viewHeight) {
    const uint32_t W = profile.panelWidth, H = profile.panelHeight;
    if (W == 0 || H == 0 || profile.viewCount == 0)
        throw std::invalid_argument("EIA: display profile '" + profile.name +
                                    "' has an empty panel or no views");
    if (views.size() != profile.viewCount)
        throw std::invalid_argument("EIA: " + std::to_string(views.size()) +
                                    " views given, display profile '" + profile.name +
                                    "' needs " + std::to_string(profile.viewCount));
    const size_t viewBytes = size_t(viewWidth) * viewHeight * 4;
    for (size_t v = 0; v < views.size(); ++v)
        if (viewBytes == 0 || views[v].size() != viewBytes)
            throw std::invalid_argument("EIA: view " + std::to_string(v) + " has " +
                                        std::to_string(views[v].size()) + " bytes, expected " +
                                        std::to_string(viewBytes) + " (" +
                                        std::to_string(viewWidth) + "x" +
                                        std::to_string(viewHeight) + " RGBA8)");

    const bool bgr = profile.subpixelOrder == SubpixelOrder::BGR;
    std::vector<uint8_t> eia(size_t(W) * H * 4);
    for (uint32_t l = 0; l < H; ++l) {
        const uint32_t viewRow = viewRowUnder(l, H, viewHeight);
        for (uint32_t x = 0; x < W; ++x) {
            uint8_t* out = &eia[(size_t(l) * W + x) * 4];
            for (uint32_t i = 0; i < 3; ++i) {
                // Subpixel k = 3x + i shows channel i (RGB) or 2 - i (BGR) of view
                // floor(phase * N) at its own screen position.
                const uint32_t k = 3 * x + i;
                const uint32_t channel = bgr ? 2 - i : i;
                const uint32_t view = subpixelView(profile, k, l);
                const uint32_t viewColumn = viewColumnUnder(k, W, viewWidth);
                out[channel] = views[view][(size_t(viewRow) * viewWidth + viewColumn) * 4 + channel];
            }
            out[3] = 255;
        }
    }
    return eia;
}

} // namespace lfd::player
