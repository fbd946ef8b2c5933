// mvr: the paper's multiview-raster baseline ("MVR"): one raster pass per view, each
// drawing the whole scene with hardware trilinear mipmapping and view-dependent PBR.
#include "raster_draw.h"
#include "scene_bindings.h"
#include "view_targets.h"

#include <epoxy/gl.h>

namespace lfd::player {

namespace {

class MvrRenderer final : public RasterRenderer {
public:
    MvrRenderer() : RasterRenderer("mvr.vert") {}
    std::string name() const override { return "mvr"; }

private:
    void drawViews(const GpuScene& scene, ViewTargets& targets) override
    {
        // One pass per view: bind view i's layer, select its camera, draw everything.
        for (uint32_t view = 0; view < targets.viewCount(); ++view) {
            glBindFramebuffer(GL_FRAMEBUFFER, targets.layerFramebuffer(view));
            glProgramUniform1i(draw_.program(), bindings::kLocView, GLint(view));
            draw_.drawScene(scene, 1);
        }
    }
};

} // namespace

std::unique_ptr<Renderer> createMvrRenderer() { return std::make_unique<MvrRenderer>(); }

} // namespace lfd::player
