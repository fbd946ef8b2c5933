#include "render_test_util.h"

#include "gpu_scene.h"
#include "gpu_timer.h"
#include "renderer.h"
#include "view_targets.h"

#include "lfd/framing.h"

#include <epoxy/gl.h>

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

} // namespace lfd::test
