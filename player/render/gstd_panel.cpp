// gstd's panel model (gstd_panel.h): the footprint of a subpixel, its angular weights, and
// the accumulation passes of shaders/gstd_panel_accumulate.comp and gstd_panel_resolve.comp.
#include "gstd_panel.h"

#include "gstd_bindings_gpu.h"
#include "shader_library.h"

#include "lfd/subpixel_phase.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace lfd::player {

namespace {

namespace gb = gstd_bindings;

double squaredRamp(double x)
{
    return x > 0.0 ? x * x : 0.0;
}

} // namespace

GstdPanelFootprint gstdPanelFootprint(const DisplayProfile& profile, uint32_t subViewsInCone)
{
    if (subViewsInCone == 0)
        throw std::invalid_argument("gstd: the panel model needs at least one sub-view");
    const double h = 1.0 / double(subViewsInCone);
    GstdPanelFootprint f;
    f.spreadColumn = std::max(std::abs(profile.mapping.perSubpixel), h / 64.0);
    f.spreadRow = std::max(std::abs(profile.mapping.perRow), h / 64.0);
    if (0.5 * (f.spreadColumn + f.spreadRow + h) >= 0.5)
        throw std::invalid_argument("gstd: display profile '" + profile.name +
                                    "': one subpixel spans half the lens period or more (phase spread " +
                                    std::to_string(f.spreadColumn + f.spreadRow) +
                                    "); the panel model needs lenses wider than one subpixel");
    f.screenWidth = 1.0 / double(std::max(profile.viewWidth, 1u));
    f.screenHeight = 1.0 / double(std::max(profile.viewHeight, 1u));
    return f;
}

double gstdSpreadCdf(double x, const GstdPanelFootprint& footprint)
{
    // The distribution function of the sum of two centred uniforms, widths a and b: the
    // second difference of the squared ramp, scaled by 1 / (2ab).
    const double a = footprint.spreadColumn, b = footprint.spreadRow;
    const double s = x + 0.5 * (a + b);
    if (s <= 0.0)
        return 0.0;
    if (s >= a + b)
        return 1.0; // exactly: the formula's four squares cancel only to rounding
    const double value =
        (squaredRamp(s) - squaredRamp(s - a) - squaredRamp(s - b) + squaredRamp(s - a - b)) / (2.0 * a * b);
    return std::clamp(value, 0.0, 1.0);
}

double gstdAngularWeight(double phase, double t, double h, const GstdPanelFootprint& footprint)
{
    double d = t - phase;
    d -= std::floor(d + 0.5); // circular: [-1/2, 1/2)
    return std::max(gstdSpreadCdf(d + 0.5 * h, footprint) - gstdSpreadCdf(d - 0.5 * h, footprint), 0.0);
}

GstdPanelAccumulator::GstdPanelAccumulator()
    : phases_(gl::buildProgram({{GL_COMPUTE_SHADER, "gstd_panel_phases.comp"}})),
      accumulate_(gl::buildProgram({{GL_COMPUTE_SHADER, "gstd_panel_accumulate.comp"}})),
      resolve_(gl::buildProgram({{GL_COMPUTE_SHADER, "gstd_panel_resolve.comp"}}))
{
}

namespace {

bool sameLenses(const DisplayProfile& a, const DisplayProfile& b)
{
    return a.panelWidth == b.panelWidth && a.panelHeight == b.panelHeight &&
           a.mapping.perSubpixel == b.mapping.perSubpixel && a.mapping.perRow == b.mapping.perRow &&
           a.mapping.offset == b.mapping.offset && a.mapping.invert == b.mapping.invert;
}

gl::Texture panelTexture(const DisplayProfile& profile)
{
    gl::Texture texture = gl::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(texture, 1, GL_RGBA32F, GLsizei(profile.panelWidth), GLsizei(profile.panelHeight));
    return texture;
}

} // namespace

void GstdPanelAccumulator::begin(const DisplayProfile& profile, uint32_t viewCount, uint32_t subViewsPerView)
{
    footprint_ = gstdPanelFootprint(profile, viewCount * subViewsPerView);
    const bool remake = !accum_ || !sameLenses(profile, profile_);
    profile_ = profile;
    viewCount_ = viewCount;
    subViews_ = subViewsPerView;
    if (remake) {
        width_ = profile.panelWidth;
        height_ = profile.panelHeight;
        accum_ = panelTexture(profile);
        phase_ = panelTexture(profile);
        lens_ = panelTexture(profile);
        computePhases();
    }
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearTexImage(accum_, 0, GL_RGBA, GL_FLOAT, zero);
}

void GstdPanelAccumulator::computePhases()
{
    const FixedSubpixelMapping m = fixedSubpixelMapping(profile_.mapping);
    const auto fixedUniform = [](GLint location, uint64_t value) {
        glUniform2ui(location, GLuint(value), GLuint(value >> 32)); // low word, high word
    };
    glUseProgram(phases_);
    glUniform2ui(gb::kPanelLocPanelSize, width_, height_);
    fixedUniform(gb::kPanelLocPerSubpixel, m.perSubpixel);
    fixedUniform(gb::kPanelLocPerRow, m.perRow);
    fixedUniform(gb::kPanelLocPhaseOffset, m.offset);
    glUniform1i(gb::kPanelLocInvertPhase, m.invert ? 1 : 0);
    glUniform1f(gb::kPanelLocLensSubpixels, float(1.0 / profile_.mapping.perSubpixel));
    glBindImageTexture(gb::kPanelImagePhase, phase_, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindImageTexture(gb::kPanelImageLens, lens_, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glDispatchCompute((width_ + gb::kPanelLocalSize - 1) / gb::kPanelLocalSize,
                      (height_ + gb::kPanelLocalSize - 1) / gb::kPanelLocalSize, 1);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    glBindImageTexture(gb::kPanelImagePhase, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindImageTexture(gb::kPanelImageLens, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glUseProgram(0);
}

void GstdPanelAccumulator::add(unsigned subViews, uint32_t width, uint32_t height, uint32_t firstView, uint32_t views)
{
    const double h = 1.0 / (double(viewCount_) * double(subViews_));
    // Taps at the sub-views' texel spacing across the footprint (at least one per axis):
    // with bilinear fetches this integrates the box exactly up to the texels' own tent.
    const uint32_t tapsX = std::clamp(uint32_t(std::ceil(footprint_.screenWidth * width - 1e-9)), 1u, 32u);
    const uint32_t tapsY = std::clamp(uint32_t(std::ceil(footprint_.screenHeight * height - 1e-9)), 1u, 32u);
    glUseProgram(accumulate_);
    glUniform2ui(gb::kPanelLocPanelSize, width_, height_);
    glUniform1i(gb::kPanelLocSubpixelsBgr, profile_.subpixelOrder == SubpixelOrder::BGR ? 1 : 0);
    glUniform1f(gb::kPanelLocFirstPhase, float((double(firstView) * subViews_ + 0.5) * h));
    glUniform1f(gb::kPanelLocSubViewWidth, float(h));
    glUniform1ui(gb::kPanelLocLayerCount, views * subViews_);
    glUniform2f(gb::kPanelLocSpread, float(footprint_.spreadColumn), float(footprint_.spreadRow));
    glUniform2f(gb::kPanelLocFootprint, float(footprint_.screenWidth), float(footprint_.screenHeight));
    glUniform2ui(gb::kPanelLocTaps, tapsX, tapsY);
    glBindTextureUnit(gb::kPanelUnitSubViews, subViews);
    glBindImageTexture(gb::kPanelImageAccum, accum_, 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
    glBindImageTexture(gb::kPanelImagePhase, phase_, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindImageTexture(gb::kPanelImageLens, lens_, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    glDispatchCompute((width_ + gb::kPanelLocalSize - 1) / gb::kPanelLocalSize,
                      (height_ + gb::kPanelLocalSize - 1) / gb::kPanelLocalSize, 1);
    // The next interval's pass reads the accumulator; the sub-views are drawn again.
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
    glBindTextureUnit(gb::kPanelUnitSubViews, 0);
    glBindImageTexture(gb::kPanelImageAccum, 0, 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
    glBindImageTexture(gb::kPanelImagePhase, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindImageTexture(gb::kPanelImageLens, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    glUseProgram(0);
}

void GstdPanelAccumulator::resolve(unsigned eiaTexture)
{
    glUseProgram(resolve_);
    glUniform2ui(gb::kPanelLocPanelSize, width_, height_);
    glBindImageTexture(gb::kPanelImageAccum, accum_, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindImageTexture(gb::kPanelImageEia, eiaTexture, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
    glDispatchCompute((width_ + gb::kPanelLocalSize - 1) / gb::kPanelLocalSize,
                      (height_ + gb::kPanelLocalSize - 1) / gb::kPanelLocalSize, 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
    glBindImageTexture(gb::kPanelImageAccum, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindImageTexture(gb::kPanelImageEia, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
    glUseProgram(0);
}

} // namespace lfd::player
