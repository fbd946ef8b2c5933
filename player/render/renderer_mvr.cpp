// mvr: the paper's multiview-raster baseline ("MVR"): one raster pass per view, each
// drawing the whole scene with hardware trilinear mipmapping and view-dependent PBR.
#include "frame_stages.h"
#include "gpu_timer.h"
#include "raster_draw.h"
#include "scene_bindings.h"
#include "view_targets.h"

#include <epoxy/gl.h>

namespace lfd::player {

namespace {

class MvrRenderer final : public Renderer {
public:
    MvrRenderer() : draw_("mvr.vert") {}
    std::string name() const override { return "mvr"; }
    bool drawsWithDepthTargets() const override { return true; }

    void render(const GpuScene& scene, const FrameSetup& frame, ViewTargets& targets,
                GpuTimer& timer) override
    {
        timer.begin(stage::kViewGeneration);
        targets.clear(kBackground);
        draw_.countWork(scene, targets);
        draw_.beginFrame(scene, frame);
        // One pass per view: bind view i's layer, select its camera, draw everything.
        for (uint32_t view = 0; view < targets.viewCount(); ++view) {
            glBindFramebuffer(GL_FRAMEBUFFER, targets.layerFramebuffer(view));
            glProgramUniform1i(draw_.program(), bindings::kLocView, GLint(view));
            draw_.drawScene(scene, 1);
        }
        draw_.endFrame();
        timer.end();
    }

    std::vector<std::pair<std::string, double>> extraStats() const override
    {
        return draw_.workStats();
    }

private:
    RasterDraw draw_;
};

} // namespace

std::unique_ptr<Renderer> createMvrRenderer() { return std::make_unique<MvrRenderer>(); }

} // namespace lfd::player
