// lfdpr: the choice between its two pipelines, and the options both share.
#include "renderer_lfdpr.h"

#include "gl_context.h"

#include <epoxy/gl.h>

#include <stdexcept>
#include <string>

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

namespace {

// The software rasterisers Mesa ships (llvmpipe, softpipe) and OpenSWR, which run compute
// invocations as SIMD rows on a few CPU cores; everything else is a GPU.
bool softwareRasteriser()
{
    const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const std::string name = renderer ? renderer : "";
    for (const char* software : {"llvmpipe", "softpipe", "SWR"})
        if (name.find(software) != std::string::npos)
            return true;
    return false;
}

} // namespace

bool lfdprGpuWorkShape(LfdprOptions::WorkShape shape)
{
    switch (shape) {
    case LfdprOptions::WorkShape::Gpu:
        return true;
    case LfdprOptions::WorkShape::Cpu:
        return false;
    case LfdprOptions::WorkShape::Auto:
    default:
        return !softwareRasteriser();
    }
}

bool lfdprHardwareAniso(LfdprOptions::AnisoFilter filter)
{
    switch (filter) {
    case LfdprOptions::AnisoFilter::Hardware:
        return true;
    case LfdprOptions::AnisoFilter::Taps:
        return false;
    case LfdprOptions::AnisoFilter::Auto:
    default:
        return !softwareRasteriser();
    }
}

LfdprOptions::AnisoFilter parseLfdprAnisoFilter(const std::string& text)
{
    if (text == "auto")
        return LfdprOptions::AnisoFilter::Auto;
    if (text == "hardware")
        return LfdprOptions::AnisoFilter::Hardware;
    if (text == "taps")
        return LfdprOptions::AnisoFilter::Taps;
    throw std::invalid_argument("--lfdpr-aniso: \"" + text + "\" is not one of auto, hardware, taps");
}

LfdprOptions::WorkShape parseLfdprWorkShape(const std::string& text)
{
    if (text == "auto")
        return LfdprOptions::WorkShape::Auto;
    if (text == "gpu")
        return LfdprOptions::WorkShape::Gpu;
    if (text == "cpu")
        return LfdprOptions::WorkShape::Cpu;
    throw std::invalid_argument("--lfdpr-work: \"" + text + "\" is not one of auto, gpu, cpu");
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
