// EIA construction: the compute pass (shaders/eia_construct.comp) and its CPU reference.
// Both implement the same nearest-view mapping with the same arithmetic (phase in double
// precision through lfd::subpixelPhase's operations, view texel in integer arithmetic,
// no filtering), so their outputs are bit-identical; eia_test checks that. The filtered
// modes share the sample offsets and the sRGB decoding table and mirror the shader's float
// arithmetic step by step (within one 8-bit level, see eia_builder.h).
#include "eia_builder.h"

#include "eia_bindings_gpu.h"

#include "frame_stages.h"
#include "gl_context.h"
#include "gpu_timer.h"
#include "shader_library.h"
#include "view_targets.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <array>
#include <cmath>
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

// splitmix64 (Steele, Lea & Flood 2014): fully specified, so a seed gives the same samples
// with every compiler and standard library.
struct SplitMix64 {
    uint64_t state;
    uint64_t next() {
        uint64_t z = (state += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    double uniform() { return (double(next() >> 11) + 1.0) * 0x1.0p-53; } // (0, 1]
    // One standard normal value (Box-Muller, the cosine branch).
    double normal() {
        const double u1 = uniform(), u2 = uniform();
        return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * 3.14159265358979323846 * u2);
    }
};

// sRGB-encoded byte -> linear value (IEC 61966-2-1), float: the shader gets this table.
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

// The shader's encodeSrgb: linear -> 8-bit sRGB level.
uint8_t encodeSrgb(float linear) {
    const float c = std::clamp(linear, 0.0f, 1.0f);
    const float e = c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
    return uint8_t(std::lround(std::clamp(e, 0.0f, 1.0f) * 255.0f));
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

std::vector<glm::vec3> reconstructionSamples(Reconstruction mode, uint64_t seed) {
    // Step 1: which dimensions the mode filters, each with sigma = support / 6.
    const bool spatial = mode == Reconstruction::Spatial || mode == Reconstruction::ViewSpatial;
    const bool view = mode == Reconstruction::View || mode == Reconstruction::ViewSpatial;
    const double sigmaXy = ReconstructionFilter::kSpatialDiameter / 6.0;
    const double sigmaV = ReconstructionFilter::kViewSupport / 6.0;
    // Step 2: Gaussian samples, resampled outside 3 sigma (a disc in x, y; an interval in v).
    SplitMix64 rng{seed};
    std::vector<glm::vec3> samples;
    for (uint32_t s = 0; s < ReconstructionFilter::kSamples; ++s) {
        glm::dvec3 o(0.0);
        if (spatial)
            do {
                o.x = rng.normal();
                o.y = rng.normal();
            } while (o.x * o.x + o.y * o.y > 9.0);
        if (view)
            do
                o.z = rng.normal();
            while (std::abs(o.z) > 3.0);
        samples.push_back(glm::vec3(o.x * sigmaXy, o.y * sigmaXy, o.z * sigmaV));
    }
    return samples;
}

EiaBuilder::EiaBuilder(const DisplayProfile& profile, uint64_t seed) : profile_(profile), seed_(seed) {
    validateDisplayProfile(profile_, profile_.name.empty() ? "display profile" : profile_.name);
    program(Reconstruction::None); // the default mode; compile errors surface here
    eia_ = gl::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(eia_, 1, GL_RGBA8, GLsizei(profile_.panelWidth),
                       GLsizei(profile_.panelHeight));
    glTextureParameteri(eia_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(eia_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    nearest_ = gl::createSampler();
    glSamplerParameteri(nearest_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glSamplerParameteri(nearest_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    if (glGetError() != GL_NO_ERROR) {
        throw gl::GlError("EIA: cannot allocate a " + std::to_string(profile_.panelWidth) + "x" +
                          std::to_string(profile_.panelHeight) +
                          " RGBA8 texture for display profile '" + profile_.name + "'");
    }
}

unsigned EiaBuilder::program(Reconstruction mode) {
    reconstructionName(mode); // throws for a value outside the enum
    gl::Program& p = programs_[size_t(mode)];
    if (!p)
        p.reset(gl::buildProgram({{GL_COMPUTE_SHADER, "eia_construct.comp"}},
                                 {"EIA_MODE " + std::to_string(uint32_t(mode))}));
    return p.get();
}

void EiaBuilder::build(const ViewTargets& views, Reconstruction mode, GpuTimer& timer) {
    if (views.viewCount() != profile_.viewCount)
        throw std::invalid_argument("EIA: " + std::to_string(views.viewCount()) +
                                    " rendered views, display profile '" + profile_.name +
                                    "' needs " + std::to_string(profile_.viewCount));
    const SubpixelMapping& m = profile_.mapping;

    // Step 1: the mode's program and its uniforms (locations from eia_bindings.glsl).
    const unsigned prog = program(mode);
    glUseProgram(prog);
    glUniform2ui(eb::kLocPanelSize, profile_.panelWidth, profile_.panelHeight);
    glUniform2ui(eb::kLocViewSize, views.width(), views.height());
    glUniform1ui(eb::kLocViewCount, profile_.viewCount);
    glUniform1d(eb::kLocPerSubpixel, m.perSubpixel);
    glUniform1d(eb::kLocPerRow, m.perRow);
    glUniform1d(eb::kLocPhaseOffset, m.offset);
    glUniform1i(eb::kLocInvertPhase, m.invert ? 1 : 0);
    glUniform1i(eb::kLocSubpixelsBgr, profile_.subpixelOrder == SubpixelOrder::BGR ? 1 : 0);
    if (mode != Reconstruction::None) {
        const std::vector<glm::vec3> samples = reconstructionSamples(mode, seed_);
        glUniform3fv(eb::kLocSamples, GLsizei(samples.size()), &samples[0].x);
        glUniform1fv(eb::kLocLinearFromByte, 256, linearFromByte().data());
    }

    // Step 2: inputs and output on the shader's units. A nearest-filter sampler object
    // keeps the view array complete whatever its own filter state (texelFetch does not
    // filter, but an incomplete texture would read as zero).
    glBindTextureUnit(eb::kUnitViews, views.colorArray());
    glBindSampler(eb::kUnitViews, nearest_);
    glBindImageTexture(eb::kImageEia, eia_, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);

    // Step 3: one invocation per panel pixel.
    timer.begin(stage::kEia);
    glDispatchCompute((profile_.panelWidth + eb::kLocalSize - 1) / eb::kLocalSize,
                      (profile_.panelHeight + eb::kLocalSize - 1) / eb::kLocalSize, 1);
    timer.end();
    // Later consumers: texture reads (display, quilt), readback, blits.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                    GL_TEXTURE_UPDATE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);

    glBindSampler(eb::kUnitViews, 0);
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

// The filtered modes, step for step as eia_construct.comp's filtered().
void filteredEiaCpu(const DisplayProfile& profile, const std::vector<std::vector<uint8_t>>& views,
                    uint32_t viewWidth, uint32_t viewHeight, Reconstruction mode, uint64_t seed,
                    std::vector<uint8_t>& eia) {
    const uint32_t W = profile.panelWidth, H = profile.panelHeight;
    const bool bgr = profile.subpixelOrder == SubpixelOrder::BGR;
    const std::vector<glm::vec3> samples = reconstructionSamples(mode, seed);
    const std::array<float, 256>& linear = linearFromByte();
    const uint32_t N = profile.viewCount;
    auto viewAt = [&](double c) { return uint32_t(std::clamp(std::floor(c), 0.0, double(N - 1))); };
    auto texel = [&](int x, int y, uint32_t view, uint32_t channel) {
        x = std::clamp(x, 0, int(viewWidth) - 1);
        y = std::clamp(y, 0, int(viewHeight) - 1);
        return linear[views[view][(size_t(y) * viewWidth + size_t(x)) * 4 + channel]];
    };
    for (uint32_t l = 0; l < H; ++l) {
        const int imageRow = int(viewRowUnder(l, H, viewHeight));
        const float py = float((2u * l + 1u) * viewHeight) / float(2u * H);
        for (uint32_t x = 0; x < W; ++x) {
            uint8_t* out = &eia[(size_t(l) * W + x) * 4];
            for (uint32_t i = 0; i < 3; ++i) {
                const uint32_t k = 3 * x + i;
                const uint32_t channel = bgr ? 2 - i : i;
                const double c = subpixelPhase(profile, k, l) * double(N);
                const float px = float((2u * k + 1u) * viewWidth) / float(6u * W);
                const int column = int(viewColumnUnder(k, W, viewWidth));
                float sum = 0.0f;
                for (const glm::vec3& o : samples) {
                    const uint32_t view = mode == Reconstruction::Spatial ? viewAt(c) : viewAt(c + double(o.z));
                    if (mode == Reconstruction::View) {
                        sum += texel(column, imageRow, view, channel);
                        continue;
                    }
                    // Bilinear in linear light at (px, py) + (o.x, o.y).
                    const float fx = (px + o.x) - 0.5f, fy = (py + o.y) - 0.5f;
                    const float bx = std::floor(fx), by = std::floor(fy);
                    const float ax = fx - bx, ay = fy - by;
                    const int x0 = int(bx), y0 = int(by);
                    const float top = mixf(texel(x0, y0, view, channel), texel(x0 + 1, y0, view, channel), ax);
                    const float bottom =
                        mixf(texel(x0, y0 + 1, view, channel), texel(x0 + 1, y0 + 1, view, channel), ax);
                    sum += mixf(top, bottom, ay);
                }
                out[channel] = encodeSrgb(sum / float(ReconstructionFilter::kSamples));
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
}

} // namespace

std::vector<uint8_t> buildEiaCpu(const DisplayProfile& profile,
                                 const std::vector<std::vector<uint8_t>>& views,
                                 uint32_t viewWidth, uint32_t viewHeight, Reconstruction mode,
                                 uint64_t seed) {
    requireEiaInputs(profile, views, viewWidth, viewHeight);
    std::vector<uint8_t> eia(size_t(profile.panelWidth) * profile.panelHeight * 4);
    if (mode != Reconstruction::None)
        filteredEiaCpu(profile, views, viewWidth, viewHeight, mode, seed, eia);
    else
        nearestEiaCpu(profile, views, viewWidth, viewHeight, eia);
    return eia;
}

} // namespace lfd::player
