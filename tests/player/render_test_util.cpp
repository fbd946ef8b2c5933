#include "render_test_util.h"

#include "frame_uniforms.h"
#include "gpu_scene.h"
#include "gpu_timer.h"
#include "renderer_registry.h"
#include "view_targets.h"

#include "lfd/framing.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lfd::test {

RenderedViews renderScene(const Scene& scene, const std::string& rendererName,
                          const DisplayProfile& profile, double time, double turntablePeriod)
{
    RenderedViews out;
    player::GpuScene gpu(scene);
    gpu.update(time);
    const Framing framing = fitSceneToDisplay(profile, scene.bounds);
    out.frame = player::makeFrameSetup(profile, framing, time, turntablePeriod);
    player::ViewTargets targets(profile.viewCount, profile.viewWidth, profile.viewHeight);
    player::GpuTimer timer;
    std::unique_ptr<player::Renderer> renderer = player::createRenderer(rendererName);
    renderer->render(gpu, out.frame, targets, timer);
    timer.finish();
    for (const auto& [stage, times] : timer.stages())
        out.stageMs.emplace_back(stage, times.mean());
    for (uint32_t i = 0; i < profile.viewCount; ++i)
        out.views.push_back({profile.viewWidth, profile.viewHeight, 4, targets.readView(i)});
    const GLenum error = glGetError();
    if (error != GL_NO_ERROR)
        throw std::runtime_error("GL error " + std::to_string(error) + " while rendering with " + rendererName);
    return out;
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

double maskedRmse(const player::Image& a, const player::Image& b, const std::vector<uint8_t>& mask)
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

double ssimOverMaskBox(const player::Image& a, const player::Image& reference, const std::vector<uint8_t>& mask)
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
    auto crop = [&](const player::Image& image) {
        player::Image c{uint32_t(x1 - x0 + 1), uint32_t(y1 - y0 + 1), 4, {}};
        for (int y = y0; y <= y1; ++y) {
            const uint8_t* row = &image.pixels[(size_t(y) * image.width + size_t(x0)) * 4];
            c.pixels.insert(c.pixels.end(), row, row + size_t(c.width) * 4);
        }
        return c;
    };
    return player::ssimLuma(crop(a), crop(reference));
}

std::vector<uint8_t> coverageMask(const player::Image& image)
{
    const uint8_t bg = uint8_t(std::lround(player::kBackground[0] * 255.0f));
    std::vector<uint8_t> mask(size_t(image.width) * image.height);
    for (size_t i = 0; i < mask.size(); ++i) {
        const uint8_t* p = &image.pixels[i * 4];
        mask[i] = p[0] != bg || p[1] != bg || p[2] != bg;
    }
    return mask;
}

CoverageStats compareCoverage(const player::Image& reference, const player::Image& test)
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

player::Image boxDownsample(const player::Image& image, uint32_t factor)
{
    player::Image out{image.width / factor, image.height / factor, 4, {}};
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
