#include "render_test_util.h"

#include "eia_builder.h"
#include "frame_uniforms.h"
#include "gpu_environment.h"
#include "gpu_scene.h"
#include "gpu_timer.h"
#include "renderer_registry.h"
#include "view_targets.h"

#include "lfd/framing.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <numbers>

namespace lfd::test {

player::FrameLighting toolDefaultLighting()
{
    static const std::shared_ptr<const player::GpuEnvironment> neutral =
        player::uploadEnvironment(lighting::chooseEnvironment("neutral"));
    player::FrameLighting lighting;
    lighting.environment = neutral.get();
    lighting.toneMap = player::ToneMap::PbrNeutral;
    return lighting;
}

player::RendererOptions quickGstdOptions()
{
    player::RendererOptions options;
    options.gstd.factor = 1;
    options.gstd.samples = 4;
    return options;
}

RenderRequest atTurntableAngle(double angle)
{
    return {.time = angle, .turntablePeriod = 2.0 * std::numbers::pi};
}

RenderedFrame renderFrame(player::Renderer& renderer, const Scene& scene, const DisplayProfile& profile,
                          const RenderRequest& request)
{
    const auto start = std::chrono::steady_clock::now();
    RenderedFrame out;
    player::GpuSceneOptions sceneOptions;
    sceneOptions.maxAnisotropy = request.aniso;
    player::GpuScene gpu(scene, sceneOptions);
    gpu.update(request.time);
    gpu.pose(); // skinned and morphed meshes, as FramePipeline's pose stage
    // The framing lfd-play uses: the scene's bounding sphere at the fill it was baked for.
    const double fill = scene.settings.framingFill > 0.0f ? double(scene.settings.framingFill) : 1.0;
    out.setup = player::makeFrameSetup(profile, fitSceneToDisplay(profile, scene.bounds, fill), request.time,
                                       request.turntablePeriod);
    out.setup.textureAnisotropy = gpu.maxAnisotropy();
    out.setup.lighting = request.lighting;
    out.setup.lighting.lights = player::sceneLights(scene, gpu.sceneFromNode());
    player::ViewTargets targets(profile.viewCount, profile.viewWidth, profile.viewHeight);
    player::GpuTimer timer;
    for (int i = 0; i < request.frames; ++i)
        renderer.render(gpu, out.setup, targets, timer);
    // As FramePipeline::completeFrame: a frame that overflowed (known once its counts are
    // back) is rendered again with the grown buffers.
    for (int again = 0; again < 4 && !renderer.settle(); ++again)
        renderer.render(gpu, out.setup, targets, timer);
    if (request.eia) {
        player::EiaBuilder eia(profile);
        // As FramePipeline does: a renderer that integrates the panel itself writes it.
        if (!renderer.writePanelImage(eia.texture(), timer))
            eia.build(targets, player::Reconstruction::None, timer);
        out.eia = {profile.panelWidth, profile.panelHeight, 4, eia.read()};
    }
    timer.finish();
    for (const auto& [stage, times] : timer.stages())
        out.stageMs[stage] = times.mean();
    for (uint32_t i = 0; i < profile.viewCount; ++i)
        out.views.push_back({profile.viewWidth, profile.viewHeight, 4, targets.readView(i)});
    for (const auto& [key, value] : renderer.extraStats())
        out.stats[key] = value;
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR)) << "while rendering with " << renderer.name();
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

RenderedFrame renderFrame(const std::string& rendererName, const Scene& scene, const DisplayProfile& profile,
                          const RenderRequest& request)
{
    const std::unique_ptr<player::Renderer> renderer = player::createRenderer(rendererName, request.rendererOptions);
    return renderFrame(*renderer, scene, profile, request);
}

DisplayProfile smallProfile(uint32_t views, uint32_t width, uint32_t height)
{
    return withViews(prototypeDisplayProfile(), views, width, height);
}

std::string tenthPrototypeProfileJson(const std::string& name)
{
    return R"({
        "format": "lfd-display-profile/1",
        "name": ")" + name + R"(",
        "panel_width": 384, "panel_height": 216,
        "screen_width_mm": 34.54, "screen_height_mm": 19.43,
        "subpixel_order": "RGB",
        "lens_width_mm": 0.72, "lens_tilt_deg": -9.66,
        "view_count": 8, "view_width": 48, "view_height": 36,
        "view_cone_deg": 40.0, "viewing_distance_mm": 300.0
    })";
}

DisplayProfile tenthPrototypeProfile(const std::string& name, uint32_t views, uint32_t width, uint32_t height)
{
    return withViews(parseDisplayProfile(tenthPrototypeProfileJson(name), name + ".json"), views, width, height);
}

double maskedRmse(const metrics::Image& a, const metrics::Image& b, const std::vector<uint8_t>& mask)
{
    double sum = 0.0;
    size_t n = 0;
    for (size_t i = 0; i < mask.size(); ++i)
        if (mask[i])
            for (int c = 0; c < 3; ++c) {
                const double d = double(a.pixels[i * 4 + c]) - b.pixels[i * 4 + c];
                sum += d * d;
                ++n;
            }
    return n ? std::sqrt(sum / double(n)) : 0.0;
}

double ssimOverMaskBox(const metrics::Image& a, const metrics::Image& reference, const std::vector<uint8_t>& mask)
{
    int x0 = int(a.width), y0 = int(a.height), x1 = -1, y1 = -1;
    for (size_t i = 0; i < mask.size(); ++i)
        if (mask[i]) {
            const int x = int(i % a.width), y = int(i / a.width);
            x0 = std::min(x0, x);
            y0 = std::min(y0, y);
            x1 = std::max(x1, x);
            y1 = std::max(y1, y);
        }
    if (x1 < 0)
        return 1.0;
    x0 = std::max(0, x0 - 5);
    y0 = std::max(0, y0 - 5);
    x1 = std::min(int(a.width) - 1, x1 + 5);
    y1 = std::min(int(a.height) - 1, y1 + 5);
    auto crop = [&](const metrics::Image& image) {
        metrics::Image c{uint32_t(x1 - x0 + 1), uint32_t(y1 - y0 + 1), 4, {}};
        for (int y = y0; y <= y1; ++y) {
            const uint8_t* row = &image.pixels[(size_t(y) * image.width + size_t(x0)) * 4];
            c.pixels.insert(c.pixels.end(), row, row + size_t(c.width) * 4);
        }
        return c;
    };
    return metrics::ssim(crop(a), crop(reference));
}

uint8_t srgbByte(float linear)
{
    const float c = std::clamp(linear, 0.0f, 1.0f);
    const float e = c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
    return uint8_t(std::lround(e * 255.0f));
}

std::vector<uint8_t> coverageMask(const metrics::Image& image)
{
    const uint8_t bg = uint8_t(std::lround(player::kBackground[0] * 255.0f));
    std::vector<uint8_t> mask(size_t(image.width) * image.height);
    for (size_t i = 0; i < mask.size(); ++i) {
        const uint8_t* p = &image.pixels[i * 4];
        mask[i] = p[0] != bg || p[1] != bg || p[2] != bg;
    }
    return mask;
}

CoverageStats compareCoverage(const metrics::Image& reference, const metrics::Image& test)
{
    const std::vector<uint8_t> m = coverageMask(reference), l = coverageMask(test);
    const int W = int(reference.width), H = int(reference.height);
    auto at = [&](int x, int y) { return x < 0 || y < 0 || x >= W || y >= H ? uint8_t(0) : m[size_t(y) * W + x]; };
    CoverageStats s;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const uint8_t self = at(x, y);
            bool nearBoundary = false;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    nearBoundary = nearBoundary || at(x + dx, y + dy) != self;
            const bool testCovers = l[size_t(y) * W + x] != 0;
            if (self) {
                ++s.covered;
                if (!nearBoundary) {
                    ++s.interior;
                    s.holes += !testCovers;
                }
            } else if (!nearBoundary && testCovers) {
                ++s.extra;
            }
        }
    return s;
}

std::string blankReason(const metrics::Image& image)
{
    const size_t pixels = size_t(image.width) * image.height;
    if (pixels == 0)
        return "empty image";
    std::map<uint32_t, size_t> colours;
    for (size_t i = 0; i < pixels; ++i) {
        const uint8_t* p = &image.pixels[i * image.channels];
        const uint32_t rgb = image.channels >= 3 ? uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 : p[0];
        ++colours[rgb];
    }
    const auto top = std::max_element(colours.begin(), colours.end(),
                                      [](const auto& a, const auto& b) { return a.second < b.second; });
    if (double(top->second) <= 0.99 * double(pixels))
        return "";
    char text[96];
    std::snprintf(text, sizeof(text), "blank: %.2f%% of the pixels are (%u, %u, %u)",
                  100.0 * double(top->second) / double(pixels), top->first & 255u, (top->first >> 8) & 255u,
                  (top->first >> 16) & 255u);
    return text;
}

std::string imageMismatch(const metrics::Image& written, const metrics::Image& reference, int tolerance)
{
    if (written.width != reference.width || written.height != reference.height ||
        written.channels != reference.channels)
        return "size " + std::to_string(written.width) + "x" + std::to_string(written.height) + "x" +
               std::to_string(written.channels) + ", expected " + std::to_string(reference.width) + "x" +
               std::to_string(reference.height) + "x" + std::to_string(reference.channels);
    const int diff = metrics::maxAbsDiff(written, reference);
    if (diff > tolerance)
        return "differs from the reference by up to " + std::to_string(diff) + " (tolerance " +
               std::to_string(tolerance) + "), RMSE " + std::to_string(metrics::rmse(written, reference));
    return blankReason(written);
}

metrics::Image boxDownsample(const metrics::Image& image, uint32_t factor)
{
    metrics::Image out{image.width / factor, image.height / factor, 4, {}};
    out.pixels.resize(size_t(out.width) * out.height * 4);
    for (uint32_t y = 0; y < out.height; ++y)
        for (uint32_t x = 0; x < out.width; ++x)
            for (uint32_t c = 0; c < 4; ++c) {
                uint32_t sum = 0;
                for (uint32_t dy = 0; dy < factor; ++dy)
                    for (uint32_t dx = 0; dx < factor; ++dx)
                        sum += image.pixels[((size_t(y * factor + dy) * image.width) + x * factor + dx) * 4 + c];
                out.pixels[(size_t(y) * out.width + x) * 4 + c] = uint8_t((sum + factor * factor / 2) / (factor * factor));
            }
    return out;
}

} // namespace lfd::test
