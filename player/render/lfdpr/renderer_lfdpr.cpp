// lfdpr: the choice between its two pipelines, and the options both share.
#include "renderer_lfdpr.h"

#include "gl_context.h"

#include <epoxy/gl.h>

#include <stdexcept>

namespace lfd::player {

std::unique_ptr<LfdprRenderer> createLfdprRenderer(const LfdprOptions& options)
{
    if (options.pipeline == LfdprOptions::Pipeline::Paper)
        return createLfdprPaperRenderer(options);
    return createLfdprVisibilityRenderer(options);
}

bool lfdprUseInt64(LfdprOptions::Atomics atomics)
{
    const bool available = epoxy_has_gl_extension("GL_NV_shader_atomic_int64") &&
                           epoxy_has_gl_extension("GL_ARB_gpu_shader_int64");
    switch (atomics) {
    case LfdprOptions::Atomics::Int64:
        if (!available)
            throw gl::GlError("lfdpr: --atomics 64 needs GL_NV_shader_atomic_int64 and "
                              "GL_ARB_gpu_shader_int64, which this driver lacks");
        return true;
    case LfdprOptions::Atomics::TwoPass32:
        return false;
    case LfdprOptions::Atomics::Auto:
    default:
        return available;
    }
}

LfdprOptions::Atomics parseLfdprAtomics(const std::string& text)
{
    if (text == "auto")
        return LfdprOptions::Atomics::Auto;
    if (text == "64")
        return LfdprOptions::Atomics::Int64;
    if (text == "32")
        return LfdprOptions::Atomics::TwoPass32;
    throw std::invalid_argument("--atomics: \"" + text + "\" is not one of auto, 64, 32");
}

LfdprOptions::Pipeline parseLfdprPipeline(const std::string& text)
{
    if (text == "visibility")
        return LfdprOptions::Pipeline::Visibility;
    if (text == "paper")
        return LfdprOptions::Pipeline::Paper;
    throw std::invalid_argument("--lfdpr-pipeline: \"" + text + "\" is not one of visibility, paper");
}

} // namespace lfd::player
