// mvr-layered: the single-pass multiview raster baseline the paper did not build
// (Unterguggenberger et al. 2020): one instanced draw per DrawItem with N instances, the
// vertex shader writing gl_Layer = gl_InstanceID into the view texture array. Same
// shading as mvr (shared fragment shader), so both give the same views.
#include "gl_context.h"
#include "raster_draw.h"
#include "view_targets.h"

#include <epoxy/gl.h>

#include <cstring>

namespace lfd::player {

namespace {

bool hasLayerFromVertexShader()
{
    GLint count = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &count);
    for (GLint i = 0; i < count; ++i) {
        const char* e = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, GLuint(i)));
        if (e && (!std::strcmp(e, "GL_ARB_shader_viewport_layer_array") ||
                  !std::strcmp(e, "GL_AMD_vertex_shader_layer") || !std::strcmp(e, "GL_NV_viewport_array2")))
            return true;
    }
    return false;
}

// Checked before the shader is compiled, so a driver without the extension gets a clear
// message instead of a GLSL error about gl_Layer.
const char* checkedVertexShader()
{
    if (!hasLayerFromVertexShader())
        throw gl::GlError("renderer mvr-layered needs GL_ARB_shader_viewport_layer_array "
                          "(gl_Layer from the vertex shader), which this OpenGL driver lacks");
    return "mvr_layered.vert";
}

class MvrLayeredRenderer final : public RasterRenderer {
public:
    MvrLayeredRenderer() : RasterRenderer(checkedVertexShader()) {}
    std::string name() const override { return "mvr-layered"; }

private:
    void drawViews(const GpuScene& scene, ViewTargets& targets) override
    {
        // All layers attached; each instance picks its layer in the vertex shader.
        glBindFramebuffer(GL_FRAMEBUFFER, targets.layeredFramebuffer());
        draw_.drawScene(scene, targets.viewCount());
    }
};

} // namespace

std::unique_ptr<Renderer> createMvrLayeredRenderer() { return std::make_unique<MvrLayeredRenderer>(); }

} // namespace lfd::player
