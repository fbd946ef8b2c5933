// lfdpr: the choice between its two pipelines, and the options both share.
#include "renderer_lfdpr.h"

#include "gl_context.h"

#include <epoxy/gl.h>

#include <initializer_list>
#include <stdexcept>
#include <string>
#include <utility>

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

// The value of flag `flag` named `text` among `choices`; std::invalid_argument naming the
// flag, the text and every choice otherwise.
template <class Choice>
Choice parseChoice(const char* flag, const std::string& text,
                   std::initializer_list<std::pair<const char*, Choice>> choices)
{
    std::string names;
    for (const auto& [name, value] : choices) {
        if (text == name)
            return value;
        names += (names.empty() ? "" : ", ") + std::string(name);
    }
    throw std::invalid_argument(std::string(flag) + ": \"" + text + "\" is not one of " + names);
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
    using F = LfdprOptions::AnisoFilter;
    return parseChoice<F>("--lfdpr-aniso", text, {{"auto", F::Auto}, {"hardware", F::Hardware}, {"taps", F::Taps}});
}

LfdprOptions::WorkShape parseLfdprWorkShape(const std::string& text)
{
    using W = LfdprOptions::WorkShape;
    return parseChoice<W>("--lfdpr-work", text, {{"auto", W::Auto}, {"gpu", W::Gpu}, {"cpu", W::Cpu}});
}

LfdprOptions::Atomics parseLfdprAtomics(const std::string& text)
{
    using A = LfdprOptions::Atomics;
    return parseChoice<A>("--atomics", text, {{"auto", A::Auto}, {"64", A::Int64}, {"32", A::TwoPass32}});
}

LfdprOptions::Pipeline parseLfdprPipeline(const std::string& text)
{
    using P = LfdprOptions::Pipeline;
    return parseChoice<P>("--lfdpr-pipeline", text, {{"visibility", P::Visibility}, {"paper", P::Paper}});
}

} // namespace lfd::player
