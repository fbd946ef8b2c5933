// OpenGL 4.5 core contexts: headless through EGL (surfaceless platform: Mesa llvmpipe on
// CI, NVIDIA on GPU machines) or windowed through GLFW. Function pointers come from
// libepoxy. Creation prints nothing; callers print describe().
#pragma once

#include <memory>
#include <stdexcept>
#include <string>

struct GLFWwindow;

namespace lfd::gl {

class GlError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct GlCapabilities {
    std::string vendor, renderer, version;
    int major = 0, minor = 0;
    bool int64Atomics = false;      // GL_NV_shader_atomic_int64 (64-bit atomicMin on SSBOs)
    bool gpuShaderInt64 = false;    // GL_ARB_gpu_shader_int64
    bool layerFromVertexShader = false; // GL_ARB_shader_viewport_layer_array (or AMD/NV variants)
    bool timerQuery = false;        // core since 3.3, checked anyway
    int maxArrayTextureLayers = 0;
    int maxTextureSize = 0;
    int maxGeometryOutputVertices = 0;
    int maxComputeWorkGroupInvocations = 0;
};

class GlContext {
public:
    // Throws GlError with a clear message when no context, or no GL 4.5 core, can be made.
    // `debug`: ask for a debug context (`--gl-debug`; KHR_debug messages in full), falling
    // back to a plain one where the driver has none.
    static std::unique_ptr<GlContext> createHeadless(bool debug = false);
    // Visible window with a GL 4.5 core context (GLFW; works under Xvfb).
    static std::unique_ptr<GlContext> createWindow(int width, int height, const std::string& title,
                                                   bool debug = false);
    // Fullscreen on monitor `monitorIndex` (glfwGetMonitors order) at its current video
    // mode - same size, bit depths and refresh rate, so nothing switches modes -
    // undecorated, no sRGB framebuffer, no iconify on focus loss, vsync on. Throws GlError
    // when the framebuffer is not the mode's size (a scaled desktop would resample it).
    static std::unique_ptr<GlContext> createFullscreenWindow(int monitorIndex, const std::string& title,
                                                             bool debug = false);
    virtual ~GlContext() = default;

    virtual void makeCurrent() = 0;
    virtual GLFWwindow* window() { return nullptr; } // null when headless
    const GlCapabilities& caps() const { return caps_; }
    // One line: "OpenGL 4.5 (Core Profile) Mesa 22.3.6 / llvmpipe (LLVM 15.0.6, 256 bits) / Mesa"
    std::string describe() const;
    // describe() plus the extensions that choose code paths, for the start-up line:
    // "... (NV_shader_atomic_int64: no, ARB_gpu_shader_int64: yes, ARB_shader_viewport_layer_array: yes)"
    std::string describeWithCodePaths() const;
    // Throws GlError naming what is missing (extensions the renderers need).
    void require(bool layeredRendering) const;

protected:
    void queryCaps(); // after the context is current
    GlCapabilities caps_;
};

} // namespace lfd::gl
