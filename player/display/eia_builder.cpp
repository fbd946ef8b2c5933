// EIA construction: the compute pass (shaders/eia_construct.comp) and its CPU reference.
// Both implement the same nearest-view mapping with the same arithmetic (the 64-bit
// fixed-point phase of lfd/subpixel_phase.h, view texel in integer arithmetic, no
// filtering), so their outputs are bit-identical; eia_test checks that. The filtered
// modes mirror the two passes (eia_prefilter.comp, eia_construct.comp) step by step in
// float (within one 8-bit level, see eia_builder.h).
#include "eia_builder.h"

#include "eia_bindings_gpu.h"

#include "frame_stages.h"
#include "gl_context.h"
#include "gpu_timer.h"
#include "shader_library.h"
#include "view_targets.h"

#include "lfd/subpixel_phase.h"

#include <epoxy/gl.h>
#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace lfd::player {

namespace {

// sRGB-encoded byte -> linear value (IEC 61966-2-1), as the GPU's sRGB texture view decodes.
const std::array<float, 256>& linearFromByte() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int i = 0; i < 256; ++i) {
            const double c = i / 255.0;
            t[size_t(i)] = float(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
        }
        return t;
    }();
    return table;
}

// GLSL mix(x, y, a) = x * (1 - a) + y * a.
inline float mixf(float x, float y, float a) { return x * (1.0f - a) + y * a; }

namespace eb = eia_bindings;
static_assert(uint32_t(Reconstruction::None) == eb::kModeNone && uint32_t(Reconstruction::Spatial) == eb::kModeSpatial &&
              uint32_t(Reconstruction::View) == eb::kModeView &&
              uint32_t(Reconstruction::ViewSpatial) == eb::kModeViewSpatial);

} // namespace

Reconstruction parseReconstruction(const std::string& name) {
    const std::vector<std::string> names = reconstructionNames();
    for (size_t i = 0; i < names.size(); ++i)
        if (name == names[i])
            return Reconstruction(uint32_t(i));
    throw std::invalid_argument("unknown reconstruction '" + name +
                                "' (expected: none, spatial, view or view-spatial)");
}

std::vector<std::string> reconstructionNames() { return {"none", "spatial", "view", "view-spatial"}; }

std::string reconstructionName(Reconstruction mode) {
    const std::vector<std::string> names = reconstructionNames();
    const auto i = size_t(mode);
    if (i >= names.size())
        throw std::invalid_argument("unknown reconstruction mode " + std::to_string(i));
    return names[i];
}

namespace {

// IEC 61966-2-1 in double precision: linear -> encoded, and the 8-bit level nearest to it.
double srgbEncoded(double linear) {
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}
double srgbDecoded(double encoded) {
    return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}
int srgbLevel(double linear) { return int(std::lround(std::clamp(srgbEncoded(linear), 0.0, 1.0) * 255.0)); }

} // namespace

const std::array<float, eia_bindings::kEncodeBuckets>& srgbEncodeTable() {
    static const std::array<float, eb::kEncodeBuckets> table = [] {
        constexpr double buckets = eb::kEncodeBuckets;
        std::array<float, eb::kEncodeBuckets> t{};
        for (uint32_t i = 0; i < eb::kEncodeBuckets; ++i) {
            const double low = (i / buckets) * (i / buckets), high = ((i + 1) / buckets) * ((i + 1) / buckets);
            const int level = srgbLevel(low);
            // Where the level rises to level + 1 (its lower rounding edge), as a fraction of
            // the bucket in sqrt(linear); the table's promise is at most one rise per bucket.
            double rise = 1.0;
            if (srgbLevel(std::min(high, 1.0)) > level) {
                if (srgbLevel(std::min(high, 1.0)) > level + 1)
                    throw std::logic_error("sRGB encode table: bucket " + std::to_string(i) + " spans two levels");
                rise = std::sqrt(srgbDecoded((level + 0.5) / 255.0)) * buckets - i;
            }
            t[i] = float(level + 0.5 * std::clamp(rise, 0.0, 1.0));
        }
        return t;
    }();
    return table;
}

float prefilterLinear(uint8_t byte) {
    // eia_prefilter.comp's linearTexel, operation for operation (Horner's scheme in float).
    const float x = float(byte) / 255.0f;
    float high = float(eb::kDecodeC6);
    for (double c : {eb::kDecodeC5, eb::kDecodeC4, eb::kDecodeC3, eb::kDecodeC2, eb::kDecodeC1, eb::kDecodeC0})
        high = high * x + float(c);
    return x <= 0.04045f ? x * (1.0f / 12.92f) : high;
}

uint8_t encodeSrgbLevel(float linear) {
    // eia_construct.comp's encodeSrgb, operation for operation.
    const float x = std::sqrt(std::clamp(linear, 0.0f, 1.0f)) * float(eb::kEncodeBuckets);
    const uint32_t i = std::min(uint32_t(x), eb::kEncodeBuckets - 1);
    const float entry = srgbEncodeTable()[i];
    const float level = std::floor(entry);
    const float rise = x - float(i) >= 2.0f * (entry - level) ? 1.0f : 0.0f;
    return uint8_t(std::min(level + rise, 255.0f));
}

EiaBuilder::EiaBuilder(const DisplayProfile& profile) : profile_(profile) {
    validateDisplayProfile(profile_, profile_.name.empty() ? "display profile" : profile_.name);
    // Strides up to two lenses of 8 pixels, drifting at most half a view per stride (so a
    // workgroup's 8 lanes span at most 4 views; the Looking Glass portrait panels keep 1).
    lensStride_ = samePhasePixelStride(profile_, 16, 0.5);
    program(Reconstruction::None); // the default mode; compile errors surface here
    eia_ = gl::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(eia_, 1, GL_RGBA8, GLsizei(profile_.panelWidth),
                       GLsizei(profile_.panelHeight));
    glTextureParameteri(eia_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(eia_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    encodeTable_ = gl::createBuffer(sizeof(float) * eb::kEncodeBuckets, 0, srgbEncodeTable().data());
    nearest_ = gl::createSampler();
    glSamplerParameteri(nearest_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glSamplerParameteri(nearest_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    bilinear_ = gl::createSampler();
    glSamplerParameteri(bilinear_, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glSamplerParameteri(bilinear_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glSamplerParameteri(bilinear_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(bilinear_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(bilinear_, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
    if (glGetError() != GL_NO_ERROR) {
        throw gl::GlError("EIA: cannot allocate a " + std::to_string(profile_.panelWidth) + "x" +
                          std::to_string(profile_.panelHeight) +
                          " RGBA8 texture for display profile '" + profile_.name + "'");
    }
}

unsigned EiaBuilder::program(Reconstruction mode) {
    reconstructionName(mode); // throws for a value outside the enum
    gl::Program& p = programs_[size_t(mode)];
    if (!p) {
        p.reset(gl::buildProgram({{GL_COMPUTE_SHADER, "eia_construct.comp"}},
                                 {"EIA_MODE " + std::to_string(uint32_t(mode))}));
        if (mode == Reconstruction::View) // the decode table is constant: set once, with the program
            glProgramUniform1fv(p, eb::kLocLinearFromByte, 256, linearFromByte().data());
    }
    return p.get();
}

// The spatial modes' first step: every view in linear light through the 3-tap kernel
// (eia_prefilter.comp), into the mode's prefiltered texture (made or remade for the view size).
unsigned EiaBuilder::prefilter(const ViewTargets& views, Reconstruction mode) {
    const bool layered = mode == Reconstruction::Spatial;
    Prefiltered& target = prefiltered_[layered ? 1 : 0];
    const uint32_t size[3] = {views.width(), views.height(), views.viewCount()};
    if (!std::equal(size, size + 3, target.size)) {
        // Three channel planes side by side: the texture is 3 view widths wide.
        GLint maxWidth = 0, maxDepth = 0;
        glGetIntegerv(layered ? GL_MAX_TEXTURE_SIZE : GL_MAX_3D_TEXTURE_SIZE, &maxWidth);
        glGetIntegerv(layered ? GL_MAX_ARRAY_TEXTURE_LAYERS : GL_MAX_3D_TEXTURE_SIZE, &maxDepth);
        if (3 * uint64_t(size[0]) > uint64_t(maxWidth) || size[1] > uint32_t(maxWidth) || size[2] > uint32_t(maxDepth))
            throw gl::GlError("EIA: " + std::to_string(size[2]) + " views of " + std::to_string(size[0]) + "x" +
                              std::to_string(size[1]) + " exceed the driver's " + (layered ? "array" : "3D") +
                              " texture limits (" + std::to_string(maxWidth) + " texels wide, " +
                              std::to_string(maxDepth) + " deep; the " + reconstructionName(mode) +
                              " reconstruction needs 3 view widths); use --aa none or view");
        target.texture = gl::createTexture(layered ? GL_TEXTURE_2D_ARRAY : GL_TEXTURE_3D);
        glTextureStorage3D(target.texture, 1, GL_R16F, GLsizei(3 * size[0]), GLsizei(size[1]), GLsizei(size[2]));
        std::copy(size, size + 3, target.size);
    }
    if (!target.program) {
        std::vector<std::string> defines;
        if (layered)
            defines.push_back("EIA_PREFILTER_LAYERED 1");
        target.program.reset(gl::buildProgram({{GL_COMPUTE_SHADER, "eia_prefilter.comp"}}, defines));
    }
    glUseProgram(target.program);
    glUniform3ui(eb::kPrefilterLocSize, size[0], size[1], size[2]);
    glUniform1f(eb::kPrefilterLocTap, float(ReconstructionFilter::kSpatialTap));
    glBindTextureUnit(eb::kPrefilterUnitViews, views.colorArray());
    glBindSampler(eb::kPrefilterUnitViews, nearest_);
    glBindImageTexture(eb::kPrefilterImageOut, target.texture, 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R16F); // all slices
    // One invocation per block of texels.
    const uint32_t blockGroup = eb::kPrefilterBlock * eb::kPrefilterLocalSize;
    glDispatchCompute((size[0] + blockGroup - 1) / blockGroup, (size[1] + blockGroup - 1) / blockGroup, size[2]);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    glBindSampler(eb::kPrefilterUnitViews, 0);
    glBindImageTexture(eb::kPrefilterImageOut, 0, 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R16F);
    return target.texture;
}

void EiaBuilder::build(const ViewTargets& views, Reconstruction mode, GpuTimer& timer) {
    if (views.viewCount() != profile_.viewCount)
        throw std::invalid_argument("EIA: " + std::to_string(views.viewCount()) +
                                    " rendered views, display profile '" + profile_.name +
                                    "' needs " + std::to_string(profile_.viewCount));
    const FixedSubpixelMapping m = fixedSubpixelMapping(profile_.mapping);
    const auto fixedUniform = [](GLint location, uint64_t value) {
        glUniform2ui(location, GLuint(value), GLuint(value >> 32)); // low word, high word
    };

    // Step 1: the spatial modes' prefilter; the mode's program and its uniforms
    // (locations from eia_bindings.glsl).
    // The stage "eia" covers both passes.
    const bool spatial = mode == Reconstruction::Spatial || mode == Reconstruction::ViewSpatial;
    timer.begin(stage::kEia);
    const unsigned prefiltered = spatial ? prefilter(views, mode) : 0;
    const unsigned prog = program(mode);
    glUseProgram(prog);
    glUniform2ui(eb::kLocPanelSize, profile_.panelWidth, profile_.panelHeight);
    glUniform2ui(eb::kLocViewSize, views.width(), views.height());
    if (mode != Reconstruction::ViewSpatial) // view-spatial's trilinear read needs no view count
        glUniform1ui(eb::kLocViewCount, profile_.viewCount);
    fixedUniform(eb::kLocPerSubpixel, m.perSubpixel);
    fixedUniform(eb::kLocPerRow, m.perRow);
    fixedUniform(eb::kLocPhaseOffset, m.offset);
    // Invocations in lens order: pixels one stride apart side by side (eia_construct.comp).
    const uint32_t runs = (profile_.panelWidth + lensStride_ - 1) / lensStride_;
    glUniform2ui(eb::kLocLensOrder, lensStride_, runs);
    glUniform1i(eb::kLocInvertPhase, m.invert ? 1 : 0);
    glUniform1i(eb::kLocSubpixelsBgr, profile_.subpixelOrder == SubpixelOrder::BGR ? 1 : 0);

    // Step 2: inputs and output on the shader's units. A nearest-filter sampler object
    // keeps the view array complete whatever its own filter state (texelFetch does not
    // filter, but an incomplete texture would read as zero).
    glBindTextureUnit(eb::kUnitViews, views.colorArray());
    glBindSampler(eb::kUnitViews, nearest_);
    if (mode != Reconstruction::None)
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, eb::kSsboEncodeTable, encodeTable_);
    if (spatial) {
        glBindTextureUnit(eb::kUnitPrefiltered, prefiltered);
        glBindSampler(eb::kUnitPrefiltered, bilinear_);
    }

    glBindImageTexture(eb::kImageEia, eia_, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);

    // Step 3: one invocation per panel pixel (and at most a stride's worth more).
    glDispatchCompute((lensStride_ * runs + eb::kLocalSize - 1) / eb::kLocalSize,
                      (profile_.panelHeight + eb::kLocalSize - 1) / eb::kLocalSize, 1);
    timer.end();
    // Later consumers: texture reads (display, quilt), readback, blits.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                    GL_TEXTURE_UPDATE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);

    glBindSampler(eb::kUnitViews, 0);
    glBindSampler(eb::kUnitPrefiltered, 0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, eb::kSsboEncodeTable, 0);

    glBindImageTexture(eb::kImageEia, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
    glUseProgram(0);
}

uint64_t EiaBuilder::bytes() const { return uint64_t(profile_.panelWidth) * profile_.panelHeight * 4; }

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

namespace {

void requireEiaInputs(const DisplayProfile& profile, const std::vector<std::vector<uint8_t>>& views,
                      uint32_t viewWidth, uint32_t viewHeight) {
    if (profile.panelWidth == 0 || profile.panelHeight == 0 || profile.viewCount == 0)
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
}

// eia_prefilter.comp on the CPU: each view in linear light through the 3-tap kernel, stored
// as half floats (as the RGBA16F texture holds it), image order.
std::vector<std::vector<glm::vec4>> prefilterCpu(const std::vector<std::vector<uint8_t>>& views, uint32_t width,
                                                 uint32_t height) {
    std::array<float, 256> linear{};
    for (int i = 0; i < 256; ++i)
        linear[size_t(i)] = prefilterLinear(uint8_t(i));
    const auto a = float(ReconstructionFilter::kSpatialTap);
    const float w[3] = {a, 1.0f - 2.0f * a, a};
    std::vector<std::vector<glm::vec4>> out;
    for (const std::vector<uint8_t>& view : views) {
        auto texel = [&](int x, int y) {
            const uint8_t* t = &view[(size_t(std::clamp(y, 0, int(height) - 1)) * width +
                                      size_t(std::clamp(x, 0, int(width) - 1))) * 4];
            return glm::vec4(linear[t[0]], linear[t[1]], linear[t[2]], linear[t[3]]);
        };
        std::vector<glm::vec4> filtered(size_t(width) * height);
        for (int y = 0; y < int(height); ++y)
            for (int x = 0; x < int(width); ++x) {
                glm::vec4 sum(0.0f);
                // GL row order is bottom-up: the shader's dy = -1 is the image row below.
                for (int dy = -1; dy <= 1; ++dy) {
                    const int row = y - dy;
                    sum += w[dy + 1] * (w[0] * texel(x - 1, row) + w[1] * texel(x, row) + w[2] * texel(x + 1, row));
                }
                for (int c = 0; c < 4; ++c)
                    sum[c] = glm::unpackHalf1x16(glm::packHalf1x16(sum[c]));
                filtered[size_t(y) * width + size_t(x)] = sum;
            }
        out.push_back(std::move(filtered));
    }
    return out;
}

// GL's bilinear read of a prefiltered view at screen position p (view pixels, image
// order), edges clamped.
float bilinearCpu(const std::vector<glm::vec4>& view, uint32_t width, uint32_t height, glm::vec2 p, uint32_t channel) {
    // GL addresses rows bottom-up: t = 1 - p.y / h, so the row coordinate is h - p.y.
    const float fx = p.x - 0.5f, fy = (float(height) - p.y) - 0.5f;
    const float bx = std::floor(fx), by = std::floor(fy);
    const float ax = fx - bx, ay = fy - by;
    auto at = [&](int x, int glRow) {
        const int row = int(height) - 1 - std::clamp(glRow, 0, int(height) - 1);
        return view[size_t(row) * width + size_t(std::clamp(x, 0, int(width) - 1))][int(channel)];
    };
    const int x0 = int(bx), y0 = int(by);
    return mixf(mixf(at(x0, y0), at(x0 + 1, y0), ax), mixf(at(x0, y0 + 1), at(x0 + 1, y0 + 1), ax), ay);
}

// The filtered modes, step for step as eia_construct.comp's filtered().
void filteredEiaCpu(const DisplayProfile& profile, const std::vector<std::vector<uint8_t>>& views,
                    uint32_t viewWidth, uint32_t viewHeight, Reconstruction mode, std::vector<uint8_t>& eia) {
    const uint32_t W = profile.panelWidth, H = profile.panelHeight, N = profile.viewCount;
    const bool bgr = profile.subpixelOrder == SubpixelOrder::BGR;
    const std::vector<std::vector<glm::vec4>> prefiltered = mode == Reconstruction::View
                                                                ? std::vector<std::vector<glm::vec4>>()
                                                                : prefilterCpu(views, viewWidth, viewHeight);
    const std::array<float, 256>& linear = linearFromByte();
    const FixedSubpixelMapping fixed = fixedSubpixelMapping(profile.mapping);
    constexpr uint64_t kHalf = uint64_t(1) << 63;
    auto clampedView = [&](int v) { return uint32_t(std::clamp(v, 0, int(N) - 1)); };
    for (uint32_t l = 0; l < H; ++l) {
        const uint32_t imageRow = viewRowUnder(l, H, viewHeight);
        const float py = float((2u * l + 1u) * viewHeight) / float(2u * H);
        for (uint32_t x = 0; x < W; ++x) {
            uint8_t* out = &eia[(size_t(l) * W + x) * 4];
            for (uint32_t i = 0; i < 3; ++i) {
                const uint32_t k = 3 * x + i, channel = bgr ? 2 - i : i;
                // c = phase * N = view + fraction. The view centres around c (view modes):
                // floor(c - 1/2) and the next, as eia_construct.comp's filtered().
                const uint64_t phase = fixedSubpixelPhase(fixed, k, l);
                const uint32_t view = fixedPhaseView(phase, N);
                const uint64_t fraction = fixedPhaseViewFraction(phase, N);
                const int below = int(view) - (fraction < kHalf ? 1 : 0);
                const float a = fixedPhaseToFloat(fraction ^ kHalf);
                const uint32_t v0 = clampedView(below), v1 = clampedView(below + 1);
                const glm::vec2 p(float((2u * k + 1u) * viewWidth) / float(6u * W), py);
                float value = 0.0f;
                if (mode == Reconstruction::View) {
                    const size_t texel = (size_t(imageRow) * viewWidth + viewColumnUnder(k, W, viewWidth)) * 4 + channel;
                    value = mixf(linear[views[v0][texel]], linear[views[v1][texel]], a);
                } else if (mode == Reconstruction::Spatial) {
                    value = bilinearCpu(prefiltered[view], viewWidth, viewHeight, p, channel);
                } else {
                    value = mixf(bilinearCpu(prefiltered[v0], viewWidth, viewHeight, p, channel),
                                 bilinearCpu(prefiltered[v1], viewWidth, viewHeight, p, channel), a);
                }
                out[channel] = encodeSrgbLevel(value);
            }
            out[3] = 255;
        }
    }
}

// Subpixel k = 3x + i shows channel i (RGB) or 2 - i (BGR) of view floor(phase * N) at its
// own screen position.
void nearestEiaCpu(const DisplayProfile& profile, const std::vector<std::vector<uint8_t>>& views,
                   uint32_t viewWidth, uint32_t viewHeight, std::vector<uint8_t>& eia) {
    const uint32_t W = profile.panelWidth, H = profile.panelHeight;
    const bool bgr = profile.subpixelOrder == SubpixelOrder::BGR;
    const FixedSubpixelMapping fixed = fixedSubpixelMapping(profile.mapping);
    for (uint32_t l = 0; l < H; ++l) {
        const uint32_t viewRow = viewRowUnder(l, H, viewHeight);
        for (uint32_t x = 0; x < W; ++x) {
            uint8_t* out = &eia[(size_t(l) * W + x) * 4];
            for (uint32_t i = 0; i < 3; ++i) {
                // Subpixel k = 3x + i shows channel i (RGB) or 2 - i (BGR) of view
                // floor(phase * N) at its own screen position.
                const uint32_t k = 3 * x + i;
                const uint32_t channel = bgr ? 2 - i : i;
                const uint32_t view = fixedPhaseView(fixedSubpixelPhase(fixed, k, l), profile.viewCount);
                const uint32_t viewColumn = viewColumnUnder(k, W, viewWidth);
                out[channel] = views[view][(size_t(viewRow) * viewWidth + viewColumn) * 4 + channel];
            }
            out[3] = 255;
        }
    }
}

} // namespace

std::vector<uint8_t> buildEiaCpu(const DisplayProfile& profile,
                                 const std::vector<std::vector<uint8_t>>& views,
                                 uint32_t viewWidth, uint32_t viewHeight, Reconstruction mode) {
    requireEiaInputs(profile, views, viewWidth, viewHeight);
    std::vector<uint8_t> eia(size_t(profile.panelWidth) * profile.panelHeight * 4);
    if (mode != Reconstruction::None)
        filteredEiaCpu(profile, views, viewWidth, viewHeight, mode, eia);
    else
        nearestEiaCpu(profile, views, viewWidth, viewHeight, eia);
    return eia;
}

} // namespace lfd::player
