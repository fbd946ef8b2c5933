#include "gl_context.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

namespace lfd::gl {

namespace {

bool hasToken(const char* list, const char* token)
{
    if (!list)
        return false;
    const size_t n = std::strlen(token);
    for (const char* p = list; (p = std::strstr(p, token)) != nullptr; p += n)
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0'))
            return true;
    return false;
}

std::string eglErrorName(EGLint error)
{
    switch (error) {
    case EGL_SUCCESS: return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    default: return "EGL error " + std::to_string(error);
    }
}

// A headless GL 4.5 core context without any surface (EGL_KHR_surfaceless_context).
class EglContext final : public GlContext {
public:
    EglContext(EGLDisplay display, EGLContext context) : display_(display), context_(context)
    {
        makeCurrent();
        queryCaps();
    }
    ~EglContext() override
    {
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display_, context_);
        eglTerminate(display_);
    }
    void makeCurrent() override
    {
        if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
            throw GlError("EGL: eglMakeCurrent failed (" + eglErrorName(eglGetError()) + ")");
    }

private:
    EGLDisplay display_;
    EGLContext context_;
};

// Tries to make a GL 4.5 core context on one display; returns EGL_NO_CONTEXT (and leaves
// the reason in `why`) when the display cannot provide one.
EGLContext createOnDisplay(EGLDisplay display, bool debug, std::string& why)
{
    EGLint major = 0, minor = 0;
    if (display == EGL_NO_DISPLAY || !eglInitialize(display, &major, &minor)) {
        why = "eglInitialize failed (" + eglErrorName(eglGetError()) + ")";
        return EGL_NO_CONTEXT;
    }
    const char* extensions = eglQueryString(display, EGL_EXTENSIONS);
    if (!hasToken(extensions, "EGL_KHR_surfaceless_context")) {
        why = "EGL_KHR_surfaceless_context missing";
        eglTerminate(display);
        return EGL_NO_CONTEXT;
    }
    if (!eglBindAPI(EGL_OPENGL_API)) {
        why = "eglBindAPI(EGL_OPENGL_API) failed: desktop OpenGL not supported";
        eglTerminate(display);
        return EGL_NO_CONTEXT;
    }
    const EGLint configAttribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                                    EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint configCount = 0;
    if (!eglChooseConfig(display, configAttribs, &config, 1, &configCount) || configCount < 1) {
        if (!hasToken(extensions, "EGL_KHR_no_config_context")) {
            why = "no EGL config with EGL_OPENGL_BIT";
            eglTerminate(display);
            return EGL_NO_CONTEXT;
        }
        config = EGL_NO_CONFIG_KHR;
    }
    const EGLint contextAttribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                     EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    // EGL 1.5's debug attribute; a driver without it gets the plain context below.
    const EGLint debugAttribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                   EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                   EGL_CONTEXT_OPENGL_DEBUG, EGL_TRUE, EGL_NONE};
    EGLContext context = debug ? eglCreateContext(display, config, EGL_NO_CONTEXT, debugAttribs) : EGL_NO_CONTEXT;
    if (context == EGL_NO_CONTEXT)
        context = eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttribs);
    if (context == EGL_NO_CONTEXT) {
        why = "no OpenGL 4.5 core context (" + eglErrorName(eglGetError()) + ")";
        eglTerminate(display);
    }
    return context;
}

std::string glString(GLenum name)
{
    const GLubyte* s = glGetString(name);
    return s ? reinterpret_cast<const char*>(s) : "";
}

// GLFW reports errors through a callback; keep the last one for our exception text.
std::string g_glfwError;
void onGlfwError(int, const char* description) { g_glfwError = description ? description : ""; }

class GlfwContext final : public GlContext {
public:
    // monitorIndex < 0: a desktop window of width x height; else fullscreen on that
    // monitor at its current mode (width and height ignored).
    GlfwContext(int width, int height, const std::string& title, int monitorIndex, bool debug)
    {
        glfwSetErrorCallback(onGlfwError);
        if (!glfwInit())
            throw GlError("GLFW: cannot initialise (" + g_glfwError + "); is DISPLAY set?");
        glfwDefaultWindowHints();
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
        glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
        glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
        glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, debug ? GLFW_TRUE : GLFW_FALSE);
        GLFWmonitor* monitor = monitorIndex >= 0 ? fullscreenHints(monitorIndex, width, height) : nullptr;
        window_ = glfwCreateWindow(width, height, title.c_str(), monitor, nullptr);
        if (!window_) {
            const std::string why = g_glfwError;
            glfwTerminate();
            throw GlError("GLFW: cannot create a window with an OpenGL 4.5 core context (" + why +
                          ")");
        }
        makeCurrent();
        // Desktop window: measure the renderers, not the display refresh. Fullscreen on a
        // panel: vsync, so every refresh shows one whole EIA (no tearing across lenses).
        glfwSwapInterval(monitor ? 1 : 0);
        queryCaps();
        if (monitor)
            checkFramebufferIsMode(width, height);
    }
    ~GlfwContext() override
    {
        glfwDestroyWindow(window_);
        glfwTerminate();
    }
    void makeCurrent() override { glfwMakeContextCurrent(window_); }
    GLFWwindow* window() override { return window_; }

private:
    // Hints for a window that takes the monitor's current mode unchanged; sets width and
    // height to that mode.
    static GLFWmonitor* fullscreenHints(int monitorIndex, int& width, int& height)
    {
        int count = 0;
        GLFWmonitor** monitors = glfwGetMonitors(&count);
        if (monitorIndex >= count) {
            glfwTerminate();
            throw GlError("GLFW: no monitor " + std::to_string(monitorIndex) + " (" + std::to_string(count) +
                          " connected)");
        }
        GLFWmonitor* monitor = monitors[monitorIndex];
        const GLFWvidmode* mode = glfwGetVideoMode(monitor);
        glfwWindowHint(GLFW_RED_BITS, mode->redBits);
        glfwWindowHint(GLFW_GREEN_BITS, mode->greenBits);
        glfwWindowHint(GLFW_BLUE_BITS, mode->blueBits);
        glfwWindowHint(GLFW_REFRESH_RATE, mode->refreshRate);
        glfwWindowHint(GLFW_DECORATED, GLFW_FALSE);
        glfwWindowHint(GLFW_AUTO_ICONIFY, GLFW_FALSE); // clicking the desktop monitor keeps the panel lit
        glfwWindowHint(GLFW_SRGB_CAPABLE, GLFW_FALSE); // EIA bytes are already sRGB-encoded
        glfwWindowHint(GLFW_SAMPLES, 0);
        width = mode->width;
        height = mode->height;
        return monitor;
    }

    void checkFramebufferIsMode(int width, int height)
    {
        int fbWidth = 0, fbHeight = 0;
        glfwGetFramebufferSize(window_, &fbWidth, &fbHeight);
        if (fbWidth != width || fbHeight != height) {
            glfwDestroyWindow(window_);
            glfwTerminate();
            throw GlError("GLFW: the fullscreen framebuffer is " + std::to_string(fbWidth) + "x" +
                          std::to_string(fbHeight) + ", not the monitor's " + std::to_string(width) + "x" +
                          std::to_string(height) + " (desktop scaling?); the EIA needs it pixel for pixel");
        }
    }

    GLFWwindow* window_ = nullptr;
};

} // namespace

std::unique_ptr<GlContext> GlContext::createHeadless(bool debug)
{
    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    const bool platformBase = hasToken(clientExtensions, "EGL_EXT_platform_base");

    // Candidate displays, best first. Hardware EGL devices come first (NVIDIA exposes its
    // GPUs only through EGL_EXT_platform_device; on a machine that also has Mesa, the
    // surfaceless platform would otherwise pick llvmpipe). Then Mesa's surfaceless
    // platform (llvmpipe on CI), then the software device, then the default display.
    std::vector<std::pair<std::string, EGLDisplay>> candidates;
    std::vector<std::pair<std::string, EGLDisplay>> softwareDevices;
    if (platformBase && hasToken(clientExtensions, "EGL_EXT_device_enumeration") &&
        hasToken(clientExtensions, "EGL_EXT_platform_device")) {
        EGLint count = 0;
        eglQueryDevicesEXT(0, nullptr, &count);
        std::vector<EGLDeviceEXT> devices(size_t(std::max(count, 0)));
        if (count > 0 && eglQueryDevicesEXT(count, devices.data(), &count)) {
            for (EGLint i = 0; i < count; ++i) {
                const char* deviceExtensions = hasToken(clientExtensions, "EGL_EXT_device_query")
                                                   ? eglQueryDeviceStringEXT(devices[i], EGL_EXTENSIONS)
                                                   : nullptr;
                EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
                auto& list = hasToken(deviceExtensions, "EGL_MESA_device_software") ? softwareDevices
                                                                                    : candidates;
                list.emplace_back("EGL device " + std::to_string(i), d);
            }
        }
    }
    if (platformBase && hasToken(clientExtensions, "EGL_MESA_platform_surfaceless"))
        candidates.emplace_back("EGL surfaceless platform",
                                eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA,
                                                         EGL_DEFAULT_DISPLAY, nullptr));
    candidates.insert(candidates.end(), softwareDevices.begin(), softwareDevices.end());
    candidates.emplace_back("EGL default display", eglGetDisplay(EGL_DEFAULT_DISPLAY));

    std::string reasons;
    for (const auto& [label, display] : candidates) {
        std::string why;
        EGLContext context = createOnDisplay(display, debug, why);
        if (context != EGL_NO_CONTEXT)
            return std::make_unique<EglContext>(display, context);
        reasons += (reasons.empty() ? "" : "; ") + label + ": " + why;
    }
    throw GlError("cannot create a headless OpenGL 4.5 core context through EGL (" + reasons + ")");
}

std::unique_ptr<GlContext> GlContext::createWindow(int width, int height, const std::string& title, bool debug)
{
    return std::make_unique<GlfwContext>(width, height, title, -1, debug);
}

std::unique_ptr<GlContext> GlContext::createFullscreenWindow(int monitorIndex, const std::string& title,
                                                             bool debug)
{
    return std::make_unique<GlfwContext>(0, 0, title, monitorIndex, debug);
}

void GlContext::queryCaps()
{
    caps_.vendor = glString(GL_VENDOR);
    caps_.renderer = glString(GL_RENDERER);
    caps_.version = glString(GL_VERSION);
    glGetIntegerv(GL_MAJOR_VERSION, &caps_.major);
    glGetIntegerv(GL_MINOR_VERSION, &caps_.minor);

    GLint count = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &count);
    auto has = [&](const char* name) {
        for (GLint i = 0; i < count; ++i) {
            const GLubyte* e = glGetStringi(GL_EXTENSIONS, GLuint(i));
            if (e && std::strcmp(reinterpret_cast<const char*>(e), name) == 0)
                return true;
        }
        return false;
    };
    caps_.int64Atomics = has("GL_NV_shader_atomic_int64");
    caps_.gpuShaderInt64 = has("GL_ARB_gpu_shader_int64");
    caps_.layerFromVertexShader = has("GL_ARB_shader_viewport_layer_array") ||
                                  has("GL_AMD_vertex_shader_layer") || has("GL_NV_viewport_array2");
    caps_.timerQuery = (caps_.major > 3 || (caps_.major == 3 && caps_.minor >= 3)) ||
                       has("GL_ARB_timer_query");
    glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &caps_.maxArrayTextureLayers);
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &caps_.maxTextureSize);
    glGetIntegerv(GL_MAX_GEOMETRY_OUTPUT_VERTICES, &caps_.maxGeometryOutputVertices);
    glGetIntegerv(GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS, &caps_.maxComputeWorkGroupInvocations);
}

std::string GlContext::describe() const
{
    return "OpenGL " + caps_.version + " / " + caps_.renderer + " / " + caps_.vendor;
}

std::string GlContext::describeWithCodePaths() const
{
    auto yesNo = [](bool b) { return b ? "yes" : "no"; };
    return describe() + " (NV_shader_atomic_int64: " + yesNo(caps_.int64Atomics) +
           ", ARB_gpu_shader_int64: " + yesNo(caps_.gpuShaderInt64) +
           ", ARB_shader_viewport_layer_array: " + yesNo(caps_.layerFromVertexShader) + ")";
}

void GlContext::require(bool layeredRendering) const
{
    if (caps_.major < 4 || (caps_.major == 4 && caps_.minor < 5))
        throw GlError("OpenGL 4.5 core is required, but " + caps_.renderer + " provides " +
                      caps_.version);
    if (layeredRendering && !caps_.layerFromVertexShader)
        throw GlError(caps_.renderer +
                      " lacks GL_ARB_shader_viewport_layer_array (gl_Layer from the vertex "
                      "shader), which the layered renderer needs");
}

} // namespace lfd::gl
