#include "window_app.h"

#include "camera_controls.h"
#include "gl_context.h"
#include "gl_debug_output.h"
#include "gl_handles.h"
#include "image.h"
#include "monitor_selection.h"
#include "quilt.h"
#include "simulated_viewer.h"
#include "text_overlay_drawer.h"
#include "window_readout.h"

#include <epoxy/gl.h>
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>

namespace lfd::player {

namespace {

enum class Shown { Eia = 0, Quilt = 1, SingleView = 2, Viewer = 3 };
const char* shownName(Shown s)
{
    switch (s) {
    case Shown::Eia: return "EIA";
    case Shown::Quilt: return "quilt";
    case Shown::SingleView: return "single view";
    case Shown::Viewer: return "simulated viewer";
    }
    return "";
}

// Keyboard and mouse state shared with the GLFW callbacks; the frame loop consumes it.
struct Input {
    bool nextRenderer = false, nextReconstruction = false, nextOutput = false;
    bool paused = false;
    bool toggleReadout = false, toggleHelp = false; // I, H / F1 (window_readout.h)
    int viewerStep = 0;
    int frameSteps = 0; // '.' while paused: frames to step forward
    // Camera input gathered since the last frame (camera_controls.h).
    glm::dvec2 orbitPixels{0.0}, panPixels{0.0};
    double zoomSteps = 0.0;
    int focalSteps = 0, depthinessSteps = 0;
    bool toggleTurntable = false, reset = false;
    bool cameraInput = false; // any of the above: starts or extends the preview
    // Drag state: left = orbit (Shift+left = pan), right or middle = pan.
    bool orbiting = false, panning = false;
    double cursorX = 0.0, cursorY = 0.0;
};

Input& inputOf(GLFWwindow* window) { return *static_cast<Input*>(glfwGetWindowUserPointer(window)); }

// Keys that steer the camera; false when `key` is not one of them.
bool cameraKey(Input& input, int key)
{
    switch (key) {
    case GLFW_KEY_RIGHT_BRACKET: ++input.focalSteps; break;
    case GLFW_KEY_LEFT_BRACKET: --input.focalSteps; break;
    case GLFW_KEY_EQUAL:
    case GLFW_KEY_KP_ADD: ++input.depthinessSteps; break;
    case GLFW_KEY_MINUS:
    case GLFW_KEY_KP_SUBTRACT: --input.depthinessSteps; break;
    case GLFW_KEY_T: input.toggleTurntable = !input.toggleTurntable; break;
    case GLFW_KEY_HOME:
    case GLFW_KEY_BACKSPACE: input.reset = true; break;
    default: return false;
    }
    input.cameraInput = true;
    return true;
}

void onKey(GLFWwindow* window, int key, int, int action, int)
{
    if (action != GLFW_PRESS && action != GLFW_REPEAT)
        return;
    Input& input = inputOf(window);
    const bool press = action == GLFW_PRESS;
    if (press && cameraKey(input, key))
        return;
    switch (key) {
    case GLFW_KEY_ESCAPE: glfwSetWindowShouldClose(window, GLFW_TRUE); break;
    case GLFW_KEY_R: input.nextRenderer |= press; break;
    case GLFW_KEY_C: input.nextReconstruction |= press; break;
    case GLFW_KEY_O: input.nextOutput |= press; break;
    case GLFW_KEY_I: input.toggleReadout ^= press; break;
    case GLFW_KEY_H:
    case GLFW_KEY_F1: input.toggleHelp ^= press; break;
    case GLFW_KEY_SPACE: if (press) input.paused = !input.paused; break;
    case GLFW_KEY_PERIOD: input.frameSteps += input.paused ? 1 : 0; break;
    case GLFW_KEY_LEFT: --input.viewerStep; break;
    case GLFW_KEY_RIGHT: ++input.viewerStep; break;
    default: break;
    }
}

// The wheel zooms (either axis; up/right = larger).
void onScroll(GLFWwindow* window, double xoffset, double yoffset)
{
    Input& input = inputOf(window);
    input.zoomSteps += std::abs(xoffset) > std::abs(yoffset) ? xoffset : yoffset;
    input.cameraInput = true;
}

void onMouseButton(GLFWwindow* window, int button, int action, int mods)
{
    // note: the drag starts at the last cursor event's position (onCursor), not at a
    // fresh glfwGetCursorPos: that asks the server for the pointer now, which may already
    // be past motion events still queued, and their movement would be lost.
    Input& input = inputOf(window);
    const bool down = action == GLFW_PRESS;
    if (button == GLFW_MOUSE_BUTTON_LEFT) {
        const bool shift = (mods & GLFW_MOD_SHIFT) != 0;
        input.orbiting = down && !shift;
        input.panning = down && shift;
    } else if (button == GLFW_MOUSE_BUTTON_RIGHT || button == GLFW_MOUSE_BUTTON_MIDDLE) {
        input.panning = down;
    }
}

void onCursor(GLFWwindow* window, double x, double y)
{
    Input& input = inputOf(window);
    const glm::dvec2 delta(x - input.cursorX, y - input.cursorY);
    input.cursorX = x;
    input.cursorY = y;
    if (input.orbiting)
        input.orbitPixels += delta;
    else if (input.panning)
        input.panPixels += delta;
    else
        return;
    input.cameraInput = true;
}

void attachInput(GLFWwindow* window, Input& input)
{
    glfwGetCursorPos(window, &input.cursorX, &input.cursorY);
    glfwSetWindowUserPointer(window, &input);
    glfwSetKeyCallback(window, onKey);
    glfwSetScrollCallback(window, onScroll);
    glfwSetMouseButtonCallback(window, onMouseButton);
    glfwSetCursorPosCallback(window, onCursor);
}

// Applies the camera input gathered since the last frame; true when there was any.
bool applyCameraInput(Input& input, CameraControls& controls, double mmPerPixel, double turntableRad)
{
    if (!input.cameraInput)
        return false;
    controls.orbit(input.orbitPixels.x, input.orbitPixels.y);
    controls.pan(input.panPixels.x, input.panPixels.y, mmPerPixel);
    controls.zoom(input.zoomSteps);
    controls.moveFocalPlane(input.focalSteps);
    controls.changeDepthiness(input.depthinessSteps);
    if (input.toggleTurntable)
        controls.toggleTurntable(turntableRad);
    if (input.reset)
        controls.reset();
    input.orbitPixels = input.panPixels = glm::dvec2(0.0);
    input.zoomSteps = 0.0;
    input.focalSteps = input.depthinessSteps = 0;
    input.toggleTurntable = input.reset = input.cameraInput = false;
    return true;
}

// A 2D RGBA8 texture plus a read framebuffer on it, (re)allocated on size changes.
struct BlitSource {
    gl::Texture texture;
    gl::Framebuffer fbo;
    uint32_t width = 0, height = 0;
    void ensure(uint32_t w, uint32_t h)
    {
        if (texture && w == width && h == height)
            return;
        release();
        width = w;
        height = h;
        texture = gl::createTexture(GL_TEXTURE_2D);
        glTextureStorage2D(texture, 1, GL_RGBA8, GLsizei(w), GLsizei(h));
        fbo = gl::createFramebuffer();
        glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, texture, 0);
        const uint8_t black[4] = {0, 0, 0, 255}; // quilt tiles past the last view stay black
        glClearTexImage(texture, 0, GL_RGBA, GL_UNSIGNED_BYTE, black);
    }
    void release()
    {
        fbo.reset();
        texture.reset();
    }
};

void clearWindow(int windowW, int windowH)
{
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glViewport(0, 0, windowW, windowH);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
}

// Blits the read framebuffer's colour (w x h) into the window, scaled to fit, centred.
void blitToWindow(GLuint readFbo, uint32_t w, uint32_t h, int windowW, int windowH)
{
    clearWindow(windowW, windowH);
    const double scale = std::min(double(windowW) / w, double(windowH) / h);
    const int dw = int(std::lround(w * scale)), dh = int(std::lround(h * scale));
    const int x0 = (windowW - dw) / 2, y0 = (windowH - dh) / 2;
    glNamedFramebufferReadBuffer(readFbo, GL_COLOR_ATTACHMENT0);
    glBlitNamedFramebuffer(readFbo, 0, 0, 0, GLint(w), GLint(h), x0, y0, x0 + dw, y0 + dh,
                           GL_COLOR_BUFFER_BIT, GL_LINEAR);
}

// The EIA pixel for pixel: an unscaled NEAREST blit of the RGBA8 texture into the default
// framebuffer with sRGB conversion and dithering off, so every byte arrives unchanged;
// `placement` is its top-left in window pixels (image coordinates; GL's y runs up).
void blitOneToOne(GLuint readFbo, uint32_t w, uint32_t h, int windowW, int windowH, PanelPlacement placement)
{
    clearWindow(windowW, windowH);
    glDisable(GL_FRAMEBUFFER_SRGB);
    glDisable(GL_DITHER);
    glDisable(GL_SCISSOR_TEST);
    const int x0 = placement.left, y0 = windowH - int(h) - placement.top;
    glNamedFramebufferReadBuffer(readFbo, GL_COLOR_ATTACHMENT0);
    glBlitNamedFramebuffer(readFbo, 0, 0, 0, GLint(w), GLint(h), x0, y0, x0 + GLint(w), y0 + GLint(h),
                           GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

// Reads the back buffer (after drawing, before the swap) and saves it as a PNG.
void saveScreenshot(const std::filesystem::path& path, int w, int h)
{
    std::vector<uint8_t> glOrder(size_t(w) * size_t(h) * 4), image(glOrder.size());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, glOrder.data());
    const size_t row = size_t(w) * 4;
    for (int y = 0; y < h; ++y)
        std::memcpy(&image[size_t(y) * row], &glOrder[size_t(h - 1 - y) * row], row);
    metrics::writeImage(path, image.data(), uint32_t(w), uint32_t(h), 4);
}

// Mean of a timer's samples per stage since the last call, remembered so that a quality
// without new frames keeps showing its last numbers (full and preview side by side).
class StageReadout {
public:
    // "total 812.3 ms, view_generation 790.1 ms, eia 20.2 ms"; empty before any frame.
    std::string update(const GpuTimer& timer)
    {
        for (const auto& [stage, times] : timer.stages()) {
            size_t& from = from_[stage];
            if (from >= times.ms.size())
                continue;
            double sum = 0.0;
            for (size_t i = from; i < times.ms.size(); ++i)
                sum += times.ms[i];
            last_[stage] = sum / double(times.ms.size() - from);
            from = times.ms.size();
        }
        std::string text;
        auto add = [&](const std::string& stage) {
            char part[96];
            std::snprintf(part, sizeof(part), "%s%s %.1f ms", text.empty() ? "" : ", ", stage.c_str(), last_[stage]);
            text += part;
        };
        if (last_.count("total"))
            add("total");
        for (const auto& entry : last_)
            if (entry.first != "total")
                add(entry.first);
        return text;
    }

private:
    std::map<std::string, size_t> from_;
    std::map<std::string, double> last_;
};

// Frame pacing: intervals between buffer swaps since the last readout.
class PacingReadout {
public:
    void swapped(double wall)
    {
        if (last_ >= 0.0)
            intervals_.push_back(wall - last_);
        last_ = wall;
    }
    // "1.2 fps (833.1 +- 12.0 ms)", or empty before two swaps.
    std::string update()
    {
        if (!intervals_.empty()) {
            double sum = 0.0, sq = 0.0;
            for (double d : intervals_)
                sum += d;
            const double mean = sum / double(intervals_.size());
            for (double d : intervals_)
                sq += (d - mean) * (d - mean);
            char text[96];
            std::snprintf(text, sizeof(text), "%.1f fps (%.1f +- %.1f ms)", 1.0 / mean, 1000.0 * mean,
                          1000.0 * std::sqrt(sq / double(intervals_.size())));
            text_ = text;
            intervals_.clear();
        }
        return text_;
    }

private:
    double last_ = -1.0;
    std::vector<double> intervals_;
    std::string text_;
};

std::string controlsText(const ViewControls& c)
{
    char text[192];
    std::snprintf(text, sizeof(text),
                  "yaw %.1f pitch %.1f zoom %.2f pan %.1f,%.1f mm focal %.1f mm depthiness %.1f turntable %s", c.yawDeg,
                  c.pitchDeg, c.zoom, c.panMm.x, c.panMm.y, c.focalDepthMm, c.depthiness, c.turntable ? "on" : "off");
    return text;
}

// Where the window is and what it shows the EIA on.
struct WindowSetup {
    std::unique_ptr<gl::GlContext> context;
    bool fullscreen = false;
    PanelPlacement placement;          // fullscreen: the EIA's top-left on the monitor
    std::vector<MonitorInfo> monitors; // fullscreen: all of them (companion window)
    size_t monitor = 0;
};

WindowSetup createWindow(const PlayOptions& options, const DisplayProfile& profile)
{
    WindowSetup setup;
    if (!options.fullscreen) {
        setup.context = gl::GlContext::createWindow(int(options.windowWidth), int(options.windowHeight), "lfd-play",
                                                    options.glDebug);
        return setup;
    }
    setup.fullscreen = true;
    setup.monitors = listMonitors();
    setup.monitor = selectMonitor(setup.monitors, options.monitor, profile.panelWidth, profile.panelHeight,
                                  options.allowMismatch);
    const MonitorInfo& m = setup.monitors[setup.monitor];
    setup.placement = placePanel(m.width, m.height, profile.panelWidth, profile.panelHeight);
    setup.context = gl::GlContext::createFullscreenWindow(int(setup.monitor), "lfd-play", options.glDebug);
    std::printf("lfd-play: fullscreen on monitor %zu '%s' %ux%u @ %d Hz, EIA %ux%u at %+d%+d%s\n", setup.monitor,
                m.name.c_str(), m.width, m.height, m.refreshHz, profile.panelWidth, profile.panelHeight,
                setup.placement.left, setup.placement.top,
                (m.width == profile.panelWidth && m.height == profile.panelHeight) ? " (pixel for pixel)"
                                                                                   : " (mismatch allowed: unscaled, centred)");
    return setup;
}

// A small window without a GL context on another monitor than the panel's, whose title
// carries the readout (a fullscreen panel shows no title bar); null with one monitor.
GLFWwindow* createCompanion(const WindowSetup& setup, Input& input)
{
    if (!setup.fullscreen || setup.monitors.size() < 2)
        return nullptr;
    const size_t other = setup.monitor == 0 ? 1 : 0;
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    GLFWwindow* companion = glfwCreateWindow(720, 80, "lfd-play stats", nullptr, nullptr);
    if (!companion)
        return nullptr;
    glfwSetWindowPos(companion, setup.monitors[other].x + 40, setup.monitors[other].y + 40);
    attachInput(companion, input);
    return companion;
}

// What the frame loop keeps across frames: the cycles, what is shown, the clock, the counters.
struct LoopState {
    std::vector<std::string> renderers; // R cycles them (empty for quilt input)
    size_t rendererIndex = 0;
    std::vector<std::string> reconstructions; // C cycles them
    size_t reconstructionIndex = 0;
    Shown shown = Shown::Eia;
    double viewerPos = 0.0;
    PreviewMode preview = PreviewMode::Off;
    // Animation clock: wall time minus paused time, or k / fps for a fixed frame count.
    double startWall = 0.0, animationTime = 0.0, lastWall = 0.0, lastTitle = 0.0, lastPrint = -1e300;
    uint32_t frame = 0, fullFrames = 0, previewFrames = 0;
    int frameSteps = 0; // '.' presses not yet applied
    int status = 0;
};

// The GL objects outputs are shown through.
struct ShowTargets {
    BlitSource quilt, viewer;
    gl::Framebuffer layerFbo = gl::createFramebuffer(), eiaFbo = gl::createFramebuffer();
};

// Frame times per quality and frame pacing, each since its last readout.
struct Readouts {
    StageReadout full, preview;
    PacingReadout pacing;
};

// The loop's starting state from the options: renderer and reconstruction cycles, output, viewer, preview.
LoopState initialLoopState(PlayerSession& session, const PlayOptions& options)
{
    const DisplayProfile& display = session.displayProfile();
    LoopState state;
    // R cycles the interactive renderers (windowRendererCycle), each rebuilt by the session
    // with the user's renderer options.
    state.renderers = session.quiltInput() ? std::vector<std::string>{} : windowRendererCycle(options.renderer);
    // The cycle ends with the current one.
    state.rendererIndex = state.renderers.empty() ? 0 : state.renderers.size() - 1;
    state.reconstructions = reconstructionNames();
    state.reconstructionIndex = size_t(session.options().reconstruction);
    state.shown = options.show == "quilt"    ? Shown::Quilt
                  : options.show == "view"   ? Shown::SingleView
                  : options.show == "viewer" ? Shown::Viewer
                                             : Shown::Eia;
    state.viewerPos = options.viewerPosition >= 0.0 ? options.viewerPosition : 0.5 * display.viewCount;
    state.preview = session.quiltInput() ? PreviewMode::Off : options.preview.value_or(PreviewMode::Auto);
    state.animationTime = session.frameTime(options.firstFrame.value_or(0)); // --first-frame: the clock starts there
    return state;
}

// The camera controls, scaled to the scene (none to steer for quilt input).
CameraControls makeCameraControls(PlayerSession& session, const PlayOptions& options)
{
    const double sceneRadiusMm =
        session.quiltInput() ? 0.0 : session.pipeline().framing().sceneRadius * session.pipeline().framing().mmPerUnit;
    return CameraControls(options.controls, sceneRadiusMm, session.displayProfile().viewConeDeg);
}

// Step 1a: the keys that switch renderer, reconstruction, output and viewer position.
void applyKeyInput(Input& input, LoopState& state, PlayerSession& session, const DisplayProfile& display)
{
    if (input.nextRenderer && state.renderers.size() > 1) {
        const size_t next = (state.rendererIndex + 1) % state.renderers.size();
        try {
            session.switchRenderer(state.renderers[next]);
            state.rendererIndex = next;
        } catch (const std::exception& e) {
            std::fprintf(stderr, "lfd-play: cannot switch to %s: %s\n", state.renderers[next].c_str(), e.what());
        }
    }
    if (input.nextReconstruction) {
        state.reconstructionIndex = (state.reconstructionIndex + 1) % state.reconstructions.size();
        session.setReconstruction(parseReconstruction(state.reconstructions[state.reconstructionIndex]));
    }
    if (input.nextOutput)
        state.shown = Shown((int(state.shown) + 1) % 4);
    state.viewerPos = std::clamp(state.viewerPos + input.viewerStep, 0.5, double(display.viewCount) - 0.5);
    state.frameSteps += input.frameSteps;
    input.nextRenderer = input.nextReconstruction = input.nextOutput = false;
    input.viewerStep = input.frameSteps = 0;
}

// Step 1b: camera input into the controls, and the controls into the session.
void steerCamera(Input& input, CameraControls& controls, PlayerSession& session, const WindowSetup& setup,
                 const PlayOptions& options, const LoopState& state, int windowW, int windowH, double wall)
{
    const DisplayProfile& display = session.displayProfile();
    // Pan follows the cursor: window pixels to screen mm at the scale the EIA is shown.
    const double shownScale = setup.fullscreen ? 1.0
                                               : std::min(double(std::max(windowW, 1)) / display.panelWidth,
                                                          double(std::max(windowH, 1)) / display.panelHeight);
    if (applyCameraInput(input, controls, display.screenWidthMm / (display.panelWidth * shownScale),
                         turntableAngle(state.animationTime, options.turntablePeriod)))
        controls.noteInput(wall);
    session.setViewControls(controls.state());
}

// Texture streaming before a frame renders (nothing once every texture is resident).
void streamTextures(PlayerSession& session, const PlayOptions& options)
{
    if (TextureStreamer* streamer = session.streamer(); streamer && !streamer->resident()) {
        // Streaming: the first frame waits for the geometry and the coarsest mips only;
        // after that a bounded amount per frame keeps the window responsive while the
        // textures sharpen. Runs with --frames (screenshots, tests) wait for it all so
        // their output does not depend on upload speed.
        if (options.framesGiven)
            streamer->untilResident();
        else if (!streamer->renderable())
            streamer->untilRenderable();
        else
            streamer->step(kStreamBytesPerFrame);
    }
}

// Step 2: render the frame (views + EIA), at preview quality while the camera moves.
void renderStep(LoopState& state, PlayerSession& session, const PlayOptions& options, const CameraControls& controls,
                bool paused, double wall, gl::GlErrorWatch& glErrors)
{
    if (options.framesGiven)
        state.animationTime = session.frameTime(options.firstFrame.value_or(0) + state.frame);
    else if (!paused)
        state.animationTime += wall - state.lastWall;
    // A step lands on the next frame's start (a quilt video's next frame, a scene's 1 / fps on).
    for (; state.frameSteps > 0; --state.frameSteps)
        state.animationTime = session.frameTime(uint32_t(std::floor(state.animationTime / session.frameTime(1) + 1e-6)) + 1);
    state.lastWall = wall;
    const bool previewNow =
        state.preview == PreviewMode::Always ||
        (state.preview == PreviewMode::Auto && controls.interacting(wall, options.previewHoldSeconds));
    streamTextures(session, options);
    session.renderFrame(state.animationTime, previewNow ? FrameQuality::Preview : FrameQuality::Full);
    glErrors.check("frame " + std::to_string(state.previewFrames + state.fullFrames));
    ++(previewNow ? state.previewFrames : state.fullFrames);
}

// All views tiled into a quilt, scaled to fit in the window.
void showQuilt(const QuiltLayout& layout, const DisplayProfile& views, const ViewTargets& targets, BlitSource& quilt,
               int windowW, int windowH)
{
    // GL rows run bottom-up, so view 0 in the bottom-left tile is tile (0, 0).
    quilt.ensure(layout.width(), layout.height());
    for (uint32_t v = 0; v < views.viewCount; ++v)
        glCopyImageSubData(targets.colorArray(), GL_TEXTURE_2D_ARRAY, 0, 0, 0, GLint(v), quilt.texture, GL_TEXTURE_2D,
                           0, GLint((v % layout.cols) * layout.tileWidth),
                           GLint((v / layout.cols) * layout.tileHeight), 0, GLsizei(targets.width()),
                           GLsizei(targets.height()), 1);
    blitToWindow(quilt.fbo, quilt.width, quilt.height, windowW, windowH);
}

// What one eye at `viewerPos` sees through the lenses, scaled to fit in the window.
void showViewer(PlayerSession& session, double viewerPos, BlitSource& viewer, int windowW, int windowH)
{
    const DisplayProfile& display = session.displayProfile();
    const DisplayProfile& views = session.profile();
    // CPU model of one eye behind the lenticular sheet (image order -> GL order).
    const double t = viewerPos * views.viewCount / display.viewCount;
    const std::vector<uint8_t> seen = simulateViewer(views, session.eia().read(), t);
    viewer.ensure(views.viewWidth, views.viewHeight);
    const size_t row = size_t(views.viewWidth) * 4;
    std::vector<uint8_t> flipped(seen.size());
    for (uint32_t y = 0; y < views.viewHeight; ++y)
        std::memcpy(&flipped[size_t(y) * row], &seen[size_t(views.viewHeight - 1 - y) * row], row);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage2D(viewer.texture, 0, 0, 0, GLsizei(views.viewWidth), GLsizei(views.viewHeight), GL_RGBA,
                        GL_UNSIGNED_BYTE, flipped.data());
    blitToWindow(viewer.fbo, viewer.width, viewer.height, windowW, windowH);
}

// Step 3: show the chosen output: the EIA 1:1 fullscreen, anything scaled to fit in a window.
void showOutput(const LoopState& state, PlayerSession& session, const WindowSetup& setup, ShowTargets& show,
                int windowW, int windowH)
{
    const DisplayProfile& display = session.displayProfile();
    const DisplayProfile& views = session.profile();
    const ViewTargets& targets = session.targets();
    glNamedFramebufferTexture(show.eiaFbo, GL_COLOR_ATTACHMENT0, session.eia().texture(), 0);
    const uint32_t single =
        std::min(uint32_t(state.viewerPos * views.viewCount / display.viewCount), views.viewCount - 1);
    if (windowW <= 0 || windowH <= 0)
        return;
    switch (state.shown) {
    case Shown::Eia:
        if (setup.fullscreen)
            blitOneToOne(show.eiaFbo, display.panelWidth, display.panelHeight, windowW, windowH, setup.placement);
        else
            blitToWindow(show.eiaFbo, display.panelWidth, display.panelHeight, windowW, windowH);
        break;
    case Shown::SingleView:
        glNamedFramebufferTextureLayer(show.layerFbo, GL_COLOR_ATTACHMENT0, targets.colorArray(), 0, GLint(single));
        blitToWindow(show.layerFbo, targets.width(), targets.height(), windowW, windowH);
        break;
    case Shown::Quilt:
        showQuilt(quiltLayoutFor(session.options(), views), views, targets, show.quilt, windowW, windowH);
        break;
    case Shown::Viewer:
        showViewer(session, state.viewerPos, show.viewer, windowW, windowH);
        break;
    }
}

// --screenshot of the last frame; a failure is reported and makes the exit status 1.
void takeScreenshot(const PlayOptions& options, int windowW, int windowH, int& status)
{
    try {
        saveScreenshot(options.screenshot, windowW, windowH);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "lfd-play: %s\n", e.what());
        status = 1;
    }
}

// The window title up to the readout: pack, renderer, reconstruction, output and playback state.
std::string titleText(const LoopState& state, PlayerSession& session, bool paused)
{
    std::string title = "lfd-play - " + session.packName() + " - " + session.rendererName() + " - " +
                        state.reconstructions[state.reconstructionIndex] + " - " + shownName(state.shown);
    if (state.shown == Shown::SingleView || state.shown == Shown::Viewer) {
        char where[48];
        std::snprintf(where, sizeof(where), " (viewer %.1f)", state.viewerPos);
        title += where;
    }
    if (paused)
        title += " - paused";
    if (const TextureStreamer* streamer = session.streamer(); streamer && !streamer->resident()) {
        char loading[48];
        const double total = double(std::max<uint64_t>(streamer->totalBytes(), 1));
        std::snprintf(loading, sizeof(loading), " - loading %.0f%%", 100.0 * double(streamer->uploadedBytes()) / total);
        title += loading;
    }
    title += session.lastQuality() == FrameQuality::Preview ? " - preview" : " - full";
    if (session.quiltInput())
        title += " - " + session.quilts().currentFile().filename().string();
    if (session.quiltInput() && session.quilts().videoFrameCount() > 0)
        title += " frame " + std::to_string(session.quilts().videoFrame()) + " of " +
                 std::to_string(session.quilts().videoFrameCount());
    return title;
}

// "<pacing> | full: <stages> | preview: <stages>" since the last readout; the parts
// not measured yet are left out (empty before the first swap and GPU timing).
std::string readoutText(Readouts& readouts, PlayerSession& session)
{
    std::string readout = readouts.pacing.update();
    auto add = [&](const std::string& label, const std::string& part) {
        if (!part.empty())
            readout += (readout.empty() ? "" : " | ") + label + part;
    };
    add("full: ", readouts.full.update(session.timer()));
    add("preview: ", readouts.preview.update(session.previewTimer()));
    return readout;
}

// Step 4: readout - title (and companion title), and a stdout line every 2 s fullscreen.
void showReadout(LoopState& state, Readouts& readouts, PlayerSession& session, const CameraControls& controls,
                 const WindowSetup& setup, GLFWwindow* companion, bool paused, double wall, bool last)
{
    state.lastTitle = wall;
    std::string title = titleText(state, session, paused);
    const std::string readout = readoutText(readouts, session);
    if (!session.quiltInput())
        title += " | " + controlsText(controls.state());
    if (!readout.empty())
        title += " | " + readout;
    glfwSetWindowTitle(setup.context->window(), title.c_str());
    if (companion)
        glfwSetWindowTitle(companion, readout.c_str());
    // note: nothing is printed before the first measurement (it was an empty "lfd-play: " line).
    if (setup.fullscreen && !readout.empty() && (wall - state.lastPrint >= 2.0 || last)) {
        state.lastPrint = wall;
        std::printf("lfd-play: %s\n", readout.c_str());
        std::fflush(stdout);
    }
}

// The on-screen readout and key help (window_readout.h): toggled by I and H / F1, drawn
// into the window after the output and after --screenshot has read it, before the swap.
struct Overlay {
    ReadoutToggles toggles;
    FrameTimeAverage frameTime;
    std::optional<CameraReadout> lastCamera; // to notice focus and depthiness changes
    std::optional<TextOverlayDrawer> drawer; // built when first shown
};

// What the readout reports about the frame just shown.
ReadoutState readoutState(const LoopState& state, PlayerSession& session, const CameraControls& controls,
                          const Overlay& overlay, bool paused, int windowW, int windowH)
{
    const DisplayProfile& display = session.displayProfile();
    const DisplayProfile& views = session.profile();
    ReadoutState r;
    r.renderer = session.rendererName();
    r.reconstruction = state.reconstructions[state.reconstructionIndex];
    r.shown = shownName(state.shown);
    r.views = views.viewCount;
    r.viewWidth = views.viewWidth;
    r.viewHeight = views.viewHeight;
    switch (state.shown) {
    case Shown::Eia:
        r.outputWidth = display.panelWidth;
        r.outputHeight = display.panelHeight;
        break;
    case Shown::Quilt: {
        const QuiltLayout layout = quiltLayoutFor(session.options(), views);
        r.outputWidth = layout.width();
        r.outputHeight = layout.height();
        break;
    }
    case Shown::SingleView:
        r.outputWidth = session.targets().width();
        r.outputHeight = session.targets().height();
        break;
    case Shown::Viewer:
        r.outputWidth = views.viewWidth;
        r.outputHeight = views.viewHeight;
        break;
    }
    r.windowWidth = uint32_t(std::max(windowW, 0));
    r.windowHeight = uint32_t(std::max(windowH, 0));
    r.preview = session.lastQuality() == FrameQuality::Preview;
    r.paused = paused;
    r.frameMs = overlay.frameTime.meanMs();
    if (!session.quiltInput())
        r.camera = CameraReadout{controls.state().focalDepthMm, controls.state().depthiness};
    return r;
}

// Step 3b: the I and H presses, a focus or depthiness change, and the overlay drawn over
// the output (nothing at all while it is off).
void drawOverlay(Overlay& overlay, Input& input, const LoopState& state, PlayerSession& session,
                 const CameraControls& controls, int windowW, int windowH, double wall)
{
    if (input.toggleReadout)
        overlay.toggles.toggleReadout();
    if (input.toggleHelp)
        overlay.toggles.toggleHelp();
    input.toggleReadout = input.toggleHelp = false;
    const CameraReadout camera{controls.state().focalDepthMm, controls.state().depthiness};
    if (overlay.lastCamera &&
        (overlay.lastCamera->focalDepthMm != camera.focalDepthMm || overlay.lastCamera->depthiness != camera.depthiness))
        overlay.toggles.cameraChanged(wall);
    overlay.lastCamera = camera;
    if (windowW <= 0 || windowH <= 0)
        return;
    const std::vector<OverlayLine> lines =
        overlay.toggles.lines(readoutState(state, session, controls, overlay, input.paused, windowW, windowH), wall);
    if (lines.empty())
        return;
    if (!overlay.drawer)
        overlay.drawer.emplace();
    overlay.drawer->draw(layoutOverlay(lines, windowW, windowH), windowW, windowH);
}

// Finishes the timers and prints the run's frame counts, mean frame times and fps.
void printRunSummary(PlayerSession& session, const LoopState& state)
{
    session.timer().finish();
    session.previewTimer().finish();
    auto meanTotal = [](GpuTimer& timer) {
        const auto it = timer.stages().find("total");
        return it == timer.stages().end() ? 0.0 : it->second.mean();
    };
    std::printf("lfd-play: window: %u full-quality frames (total %.1f ms mean), %u preview frames (total %.1f ms "
                "mean), %.1f fps over the run\n",
                state.fullFrames, meanTotal(session.timer()), state.previewFrames, meanTotal(session.previewTimer()),
                double(state.frame) / std::max(glfwGetTime() - state.startWall, 1e-9));
}

// The frame loop shared by scene and quilt input.
int runLoop(WindowSetup& setup, PlayerSession& session, const PlayOptions& options, gl::GlErrorWatch& glErrors)
{
    GLFWwindow* window = setup.context->window();
    const DisplayProfile& display = session.displayProfile();
    LoopState state = initialLoopState(session, options);
    CameraControls controls = makeCameraControls(session, options);

    Input input;
    attachInput(window, input);
    if (setup.fullscreen) // a cursor over the lenses shows in every view; drags still work
        glfwSetInputMode(window, GLFW_CURSOR, GLFW_CURSOR_HIDDEN);
    GLFWwindow* companion = createCompanion(setup, input);

    ShowTargets show;
    state.startWall = glfwGetTime();
    state.lastWall = state.lastTitle = state.startWall;
    Readouts readouts;
    Overlay overlay{ReadoutToggles(options.readout, setup.fullscreen), {}, {}, {}};
    while (!glfwWindowShouldClose(window) && !(companion && glfwWindowShouldClose(companion))) {
        glfwPollEvents();
        int windowW = 0, windowH = 0;
        glfwGetFramebufferSize(window, &windowW, &windowH);

        // Step 1: apply input.
        applyKeyInput(input, state, session, display);
        const double wall = glfwGetTime();
        steerCamera(input, controls, session, setup, options, state, windowW, windowH, wall);

        renderStep(state, session, options, controls, input.paused, wall, glErrors);
        showOutput(state, session, setup, show, windowW, windowH);
        ++state.frame;
        const bool last = options.framesGiven && state.frame >= options.frames;
        if (last && !options.screenshot.empty())
            takeScreenshot(options, windowW, windowH, state.status);
        drawOverlay(overlay, input, state, session, controls, windowW, windowH, wall);
        glfwSwapBuffers(window);
        const double swapped = glfwGetTime();
        readouts.pacing.swapped(swapped);
        overlay.frameTime.swapped(swapped);

        if (wall - state.lastTitle >= 0.5 || last)
            showReadout(state, readouts, session, controls, setup, companion, input.paused, wall, last);
        if (last)
            break;
    }
    printRunSummary(session, state);
    // Deleted here, with the panel's context current: framebuffers are not shared with the
    // companion window's context.
    show.quilt.release();
    show.viewer.release();
    show.layerFbo.reset();
    show.eiaFbo.reset();
    overlay.drawer.reset();
    if (companion)
        glfwDestroyWindow(companion);
    return state.status;
}

void printStart(const gl::GlContext& context)
{
    std::printf("lfd-play: %s\n", context.describeWithCodePaths().c_str());
    std::fflush(stdout);
}

} // namespace

int runWindowed(const PlayOptions& options, const DisplayProfile& profile, Scene scene,
                const std::string& packName)
{
    WindowSetup setup = createWindow(options, profile);
    printStart(*setup.context);
    setup.context->require(options.renderer == "mvr-layered");
    gl::GlErrorWatch glErrors("lfd-play", options.glDebug);
    PlayerSession session(options, profile, std::move(scene), packName);
    glErrors.check("the upload of " + packName);
    return runLoop(setup, session, options, glErrors);
}

int runWindowedStreamed(const PlayOptions& options, const DisplayProfile& profile, std::shared_ptr<MappedPack> pack,
                        const std::string& packName)
{
    WindowSetup setup = createWindow(options, profile);
    printStart(*setup.context);
    setup.context->require(options.renderer == "mvr-layered");
    gl::GlErrorWatch glErrors("lfd-play", options.glDebug);
    PlayerSession session(options, profile, std::move(pack), packName);
    glErrors.check("the start of the upload of " + packName);
    return runLoop(setup, session, options, glErrors);
}

int runWindowedQuilts(const PlayOptions& options, const DisplayProfile& profile,
                      std::vector<std::filesystem::path> quilts)
{
    WindowSetup setup = createWindow(options, profile);
    printStart(*setup.context);
    setup.context->require(false);
    gl::GlErrorWatch glErrors("lfd-play", options.glDebug);
    PlayerSession session(options, profile, std::move(quilts));
    glErrors.check("the upload of the quilts");
    return runLoop(setup, session, options, glErrors);
}

int listMonitorsCommand(const DisplayProfile& profile)
{
    const std::vector<MonitorInfo> monitors = listMonitors();
    std::fputs(describeMonitors(monitors, profile.panelWidth, profile.panelHeight).c_str(), stdout);
    glfwTerminate();
    return monitors.empty() ? 1 : 0;
}

} // namespace lfd::player
