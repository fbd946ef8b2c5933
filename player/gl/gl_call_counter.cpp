#include "gl_call_counter.h"

#include <epoxy/gl.h>

#include <stdexcept>
#include <tuple>
#include <type_traits>

namespace lfd::gl {

namespace {

enum class Kind { Dispatch, Draw, Barrier, Sync, QueryResult };

GlCallCounts g_counts;
bool g_installed = false;

void note(Kind kind, const char* name)
{
    switch (kind) {
    case Kind::Dispatch: ++g_counts.dispatches; break;
    case Kind::Draw: ++g_counts.draws; break;
    case Kind::Barrier: ++g_counts.barriers; break;
    case Kind::Sync:
    case Kind::QueryResult:
        ++g_counts.syncs;
        ++g_counts.syncCalls[name];
        break;
    }
}

// One wrapped entry point. `Slot` is libepoxy's function pointer (epoxy_glFoo). note:
// libepoxy starts each pointer at a stub that, on its first call, resolves the real
// function only if the pointer still holds the stub, stores it there and calls through
// the pointer (with the wrapper there: endless recursion). So the wrapper puts the
// pointer it replaced back while it calls it, and takes the slot over again afterwards,
// keeping whatever the stub resolved.
template <auto& Slot, Kind K, class Fn = std::remove_reference_t<decltype(Slot)>>
struct Hook;

template <auto& Slot, Kind K, class R, class... A>
struct Hook<Slot, K, R (*)(A...)> {
    static inline R (*real)(A...) = nullptr;
    static inline const char* name = nullptr;

    static bool counts(A... args)
    {
        if constexpr (K == Kind::QueryResult) {
            // glGetQueryObject*(id, pname, params): only GL_QUERY_RESULT waits.
            const auto tuple = std::make_tuple(args...);
            return GLenum(std::get<1>(tuple)) == GL_QUERY_RESULT;
        } else {
            return true;
        }
    }

    static R wrapper(A... args)
    {
        if (counts(args...))
            note(K, name);
        Slot = real;
        if constexpr (std::is_void_v<R>) {
            real(args...);
            retake();
        } else {
            R result = real(args...);
            retake();
            return result;
        }
    }

    static void retake()
    {
        real = Slot;
        Slot = &wrapper;
    }

    static void install(const char* glName)
    {
        name = glName;
        real = Slot;
        Slot = &wrapper;
    }

    static void uninstall()
    {
        if (Slot == &wrapper)
            Slot = real;
    }
};

#define LFD_GL_HOOKS(X)                                                                                    \
    X(glDispatchCompute, Dispatch)                                                                         \
    X(glDispatchComputeIndirect, Dispatch)                                                                 \
    X(glDrawArrays, Draw)                                                                                  \
    X(glDrawArraysInstanced, Draw)                                                                         \
    X(glDrawArraysInstancedBaseInstance, Draw)                                                             \
    X(glDrawArraysIndirect, Draw)                                                                          \
    X(glDrawElements, Draw)                                                                                \
    X(glDrawElementsInstanced, Draw)                                                                       \
    X(glDrawElementsBaseVertex, Draw)                                                                      \
    X(glDrawElementsInstancedBaseVertex, Draw)                                                             \
    X(glDrawElementsInstancedBaseInstance, Draw)                                                           \
    X(glDrawElementsInstancedBaseVertexBaseInstance, Draw)                                                 \
    X(glDrawRangeElements, Draw)                                                                           \
    X(glDrawRangeElementsBaseVertex, Draw)                                                                 \
    X(glDrawElementsIndirect, Draw)                                                                        \
    X(glMultiDrawArrays, Draw)                                                                             \
    X(glMultiDrawElements, Draw)                                                                           \
    X(glMultiDrawElementsBaseVertex, Draw)                                                                 \
    X(glMultiDrawArraysIndirect, Draw)                                                                     \
    X(glMultiDrawElementsIndirect, Draw)                                                                   \
    X(glMemoryBarrier, Barrier)                                                                            \
    X(glMemoryBarrierByRegion, Barrier)                                                                    \
    X(glTextureBarrier, Barrier)                                                                           \
    X(glFinish, Sync)                                                                                      \
    X(glClientWaitSync, Sync)                                                                              \
    X(glWaitSync, Sync)                                                                                    \
    X(glGetBufferSubData, Sync)                                                                            \
    X(glGetNamedBufferSubData, Sync)                                                                       \
    X(glMapBuffer, Sync)                                                                                   \
    X(glMapBufferRange, Sync)                                                                              \
    X(glMapNamedBuffer, Sync)                                                                              \
    X(glMapNamedBufferRange, Sync)                                                                         \
    X(glReadPixels, Sync)                                                                                  \
    X(glReadnPixels, Sync)                                                                                 \
    X(glGetTexImage, Sync)                                                                                 \
    X(glGetnTexImage, Sync)                                                                                \
    X(glGetTextureImage, Sync)                                                                             \
    X(glGetTextureSubImage, Sync)                                                                          \
    X(glGetCompressedTexImage, Sync)                                                                       \
    X(glGetnCompressedTexImage, Sync)                                                                      \
    X(glGetCompressedTextureImage, Sync)                                                                   \
    X(glGetCompressedTextureSubImage, Sync)                                                                \
    X(glGetQueryObjectiv, QueryResult)                                                                     \
    X(glGetQueryObjectuiv, QueryResult)                                                                    \
    X(glGetQueryObjecti64v, QueryResult)                                                                   \
    X(glGetQueryObjectui64v, QueryResult)

void installAll()
{
#define LFD_INSTALL(fn, kind) Hook<epoxy_##fn, Kind::kind>::install(#fn);
    LFD_GL_HOOKS(LFD_INSTALL)
#undef LFD_INSTALL
}

void uninstallAll()
{
#define LFD_UNINSTALL(fn, kind) Hook<epoxy_##fn, Kind::kind>::uninstall();
    LFD_GL_HOOKS(LFD_UNINSTALL)
#undef LFD_UNINSTALL
}

} // namespace

GlCallCounts GlCallCounts::operator-(const GlCallCounts& earlier) const
{
    GlCallCounts d;
    d.dispatches = dispatches - earlier.dispatches;
    d.draws = draws - earlier.draws;
    d.barriers = barriers - earlier.barriers;
    d.syncs = syncs - earlier.syncs;
    for (const auto& [name, n] : syncCalls) {
        const auto it = earlier.syncCalls.find(name);
        const uint64_t before = it == earlier.syncCalls.end() ? 0 : it->second;
        if (n > before)
            d.syncCalls[name] = n - before;
    }
    return d;
}

GlCallCounter::GlCallCounter()
{
    if (g_installed)
        throw std::logic_error("GlCallCounter: one is already counting");
    g_installed = true;
    g_counts = {};
    installAll();
}

GlCallCounter::~GlCallCounter()
{
    uninstallAll();
    g_installed = false;
}

GlCallCounts GlCallCounter::counts() const { return g_counts; }

void GlCallCounter::reset() { g_counts = {}; }

} // namespace lfd::gl
