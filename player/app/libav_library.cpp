#include "libav_library.h"

#include "quilt_video.h"

#include <dlfcn.h>

#include <string>

namespace lfd::player {

namespace {

// "libavformat.so.59": the soname of the major version the headers declare.
std::string soname(const char* library, int major) { return "lib" + std::string(library) + ".so." + std::to_string(major); }

int majorVersion(const std::string& library)
{
    if (library == "avformat")
        return LIBAVFORMAT_VERSION_MAJOR;
    if (library == "avcodec")
        return LIBAVCODEC_VERSION_MAJOR;
    if (library == "swscale")
        return LIBSWSCALE_VERSION_MAJOR;
    return LIBAVUTIL_VERSION_MAJOR;
}

void* openLibrary(const char* library)
{
    const std::string name = soname(library, majorVersion(library));
    void* handle = dlopen(name.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle)
        throw VideoError("playing a quilt video needs FFmpeg's " + name +
                         " (not found; on Debian 12: apt install libavformat59 libavcodec59 libswscale6 libavutil57)");
    return handle;
}

LibAv load()
{
    // note: the handles stay open for the process; the functions are used until exit.
    void* const avformat = openLibrary("avformat");
    void* const avcodec = openLibrary("avcodec");
    void* const swscale = openLibrary("swscale");
    void* const avutil = openLibrary("avutil");
    LibAv av;
#define LFD_LIBAV_RESOLVE(library, function)                                                                           \
    av.function = reinterpret_cast<decltype(&::function)>(dlsym(library, #function));                                 \
    if (!av.function)                                                                                                  \
        throw VideoError(soname(#library, majorVersion(#library)) + " has no " #function);
    LFD_LIBAV_FUNCTIONS(LFD_LIBAV_RESOLVE)
#undef LFD_LIBAV_RESOLVE
    return av;
}

} // namespace

const LibAv& libAv()
{
    static const LibAv av = load();
    return av;
}

} // namespace lfd::player
