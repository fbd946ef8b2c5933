#include "window_app.h"

#include "gl_context.h"
#include "image_output.h"
#include "quilt.h"
#include "simulated_viewer.h"

#include <epoxy/gl.h>
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

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

// Keyboard and mouse state shared with the GLFW callbacks.
struct Input {
    bool nextRenderer = false, nextReconstruction = false, nextOutput = false;
    bool paused = false;
    int viewerStep = 0;
};

void onKey(GLFWwindow* window, int key, int, int action, int)
{
    if (action != GLFW_PRESS && action != GLFW_REPEAT)
        return;
    auto* input = static_cast<Input*>(glfwGetWindowUserPointer(window));
    switch (key) {
    case GLFW_KEY_ESCAPE: glfwSetWindowShouldClose(window, GLFW_TRUE); break;
    case GLFW_KEY_R: input->nextRenderer |= action == GLFW_PRESS; break;
    case GLFW_KEY_C: input->nextReconstruction |= action == GLFW_PRESS; break;
    case GLFW_KEY_O: input->nextOutput |= action == GLFW_PRESS; break;
    case GLFW_KEY_SPACE: if (action == GLFW_PRESS) input->paused = !input->paused; break;
    case GLFW_KEY_LEFT: --input->viewerStep; break;
    case GLFW_KEY_RIGHT: ++input->viewerStep; break;
    default: break;
    }
}

// Mouse: the wheel (either axis) moves the simulated viewer like Left/Right; a left click
// cycles the displayed output like O.
void onScroll(GLFWwindow* window, double xoffset, double yoffset)
{
    auto* input = static_cast<Input*>(glfwGetWindowUserPointer(window));
    const double step = std::abs(xoffset) > std::abs(yoffset) ? xoffset : yoffset;
    input->viewerStep += step > 0.0 ? 1 : (step < 0.0 ? -1 : 0);
}

void onMouseButton(GLFWwindow* window, int button, int action, int)
{
    auto* input = static_cast<Input*>(glfwGetWindowUserPointer(window));
    if (button == GLFW_MOUSE_BUTTON_LEFT && action == GLFW_PRESS)
        input->nextOutput = true;
}

// A 2D RGBA8 texture plus a read framebuffer on it, (re)allocated on size changes.
struct BlitSource {
    GLuint texture = 0, fbo = 0;
    uint32_t width = 0, height = 0;
    void ensure(uint32_t w, uint32_t h)
    {
        if (texture && w == width && h == height)
            return;
        release();
        width = w;
        height = h;
        glCreateTextures(GL_TEXTURE_2D, 1, &texture);
        glTextureStorage2D(texture, 1, GL_RGBA8, GLsizei(w), GLsizei(h));
        glCreateFramebuffers(1, &fbo);
        glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, texture, 0);
        const uint8_t black[4] = {0, 0, 0, 255}; // quilt tiles past the last view stay black
        glClearTexImage(texture, 0, GL_RGBA, GL_UNSIGNED_BYTE, black);
    }
    void release()
    {
        if (fbo)
            glDeleteFramebuffers(1, &fbo);
        if (texture)
            glDeleteTextures(1, &texture);
        fbo = texture = 0;
    }
};

// Blits the read framebuffer's colour (w x h) into the window, scaled to fit, centred.
void blitToWindow(GLuint readFbo, uint32_t w, uint32_t h, int windowW, int windowH)
{
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glViewport(0, 0, windowW, windowH);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    const double scale = std::min(double(windowW) / w, double(windowH) / h);
    const int dw = int(std::lround(w * scale)), dh = int(std::lround(h * scale));
    const int x0 = (windowW - dw) / 2, y0 = (windowH - dh) / 2;
    glNamedFramebufferReadBuffer(readFbo, GL_COLOR_ATTACHMENT0);
    glBlitNamedFramebuffer(readFbo, 0, 0, 0, GLint(w), GLint(h), x0, y0, x0 + dw, y0 + dh,
                           GL_COLOR_BUFFER_BIT, GL_LINEAR);
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
    writeImage(path, image.data(), uint32_t(w), uint32_t(h), 4);
}

} // namespace

int runWindowed(const PlayOptions& options, const DisplayProfile& profile, Scene scene,
                const std::string& packName)
{
    std::unique_ptr<gl::GlContext> context =
        gl::GlContext::createWindow(int(options.windowWidth), int(options.windowHeight), "lfd-play");
    std::printf("lfd-play: %s\n", context->describeWithCodePaths().c_str());
    std::fflush(stdout);
    context->require(options.renderer == "mvr-layered");
    GLFWwindow* window = context->window();

    PlayerSession session(options, profile, std::move(scene), packName);
    // R cycles the interactive renderers (windowRendererCycle), each rebuilt by the session
    // with the user's renderer options.
    const std::vector<std::string> renderers = windowRendererCycle(options.renderer);
    size_t rendererIndex = renderers.size() - 1; // the cycle ends with the current renderer
    const std::vector<std::string> reconstructions = reconstructionNames(); // C cycles them
    size_t reconstructionIndex = size_t(parseReconstruction(session.options().reconstruction));
    Shown shown = options.show == "quilt"    ? Shown::Quilt
                  : options.show == "view"   ? Shown::SingleView
                  : options.show == "viewer" ? Shown::Viewer
                                             : Shown::Eia;
    double viewerPos = options.viewerPosition >= 0.0 ? options.viewerPosition : 0.5 * profile.viewCount;

    Input input;
    glfwSetWindowUserPointer(window, &input);
    glfwSetKeyCallback(window, onKey);
    glfwSetScrollCallback(window, onScroll);
    glfwSetMouseButtonCallback(window, onMouseButton);

    BlitSource quilt, viewer;
    GLuint layerFbo = 0, eiaFbo = 0;
    glCreateFramebuffers(1, &layerFbo);
    glCreateFramebuffers(1, &eiaFbo);
    glNamedFramebufferTexture(eiaFbo, GL_COLOR_ATTACHMENT0, session.eia().texture(), 0);
    const QuiltLayout layout = chooseQuiltLayout(profile);

    // Animation clock: wall time minus paused time, or k / fps for a fixed frame count.
    double animationTime = 0.0, lastWall = glfwGetTime(), lastTitle = lastWall;
    std::map<std::string, size_t> titleFrom; // per stage: first sample not yet shown
    uint32_t frame = 0;
    int status = 0;
    while (!glfwWindowShouldClose(window)) {
        glfwPollEvents();

        // Step 1: apply input.
        if (input.nextRenderer && renderers.size() > 1) {
            const size_t next = (rendererIndex + 1) % renderers.size();
            try {
                session.switchRenderer(renderers[next]);
                rendererIndex = next;
            } catch (const std::exception& e) {
                std::fprintf(stderr, "lfd-play: cannot switch to %s: %s\n", renderers[next].c_str(), e.what());
            }
        }
        if (input.nextReconstruction) {
            reconstructionIndex = (reconstructionIndex + 1) % reconstructions.size();
            session.setReconstruction(parseReconstruction(reconstructions[reconstructionIndex]));
        }
        if (input.nextOutput)
            shown = Shown((int(shown) + 1) % 4);
        viewerPos = std::clamp(viewerPos + input.viewerStep, 0.5, double(profile.viewCount) - 0.5);
        input.nextRenderer = input.nextReconstruction = input.nextOutput = false;
        input.viewerStep = 0;

        // Step 2: render the frame (views + EIA).
        const double wall = glfwGetTime();
        if (options.framesGiven)
            animationTime = double(frame) / options.fps;
        else if (!input.paused)
            animationTime += wall - lastWall;
        lastWall = wall;
        session.renderFrame(animationTime);

        // Step 3: show the chosen output, scaled to fit.
        int windowW = 0, windowH = 0;
        glfwGetFramebufferSize(window, &windowW, &windowH);
        const ViewTargets& targets = session.targets();
        const uint32_t single = std::min(uint32_t(viewerPos), profile.viewCount - 1);
        if (windowW > 0 && windowH > 0) {
            switch (shown) {
            case Shown::Eia:
                blitToWindow(eiaFbo, profile.panelWidth, profile.panelHeight, windowW, windowH);
                break;
            case Shown::SingleView:
                glNamedFramebufferTextureLayer(layerFbo, GL_COLOR_ATTACHMENT0, targets.colorArray(), 0, GLint(single));
                blitToWindow(layerFbo, profile.viewWidth, profile.viewHeight, windowW, windowH);
                break;
            case Shown::Quilt:
                // GL rows run bottom-up, so view 0 in the bottom-left tile is tile (0, 0).
                quilt.ensure(layout.width(), layout.height());
                for (uint32_t v = 0; v < profile.viewCount; ++v)
                    glCopyImageSubData(targets.colorArray(), GL_TEXTURE_2D_ARRAY, 0, 0, 0, GLint(v), quilt.texture,
                                       GL_TEXTURE_2D, 0, GLint((v % layout.cols) * layout.tileWidth),
                                       GLint((v / layout.cols) * layout.tileHeight), 0, GLsizei(profile.viewWidth),
                                       GLsizei(profile.viewHeight), 1);
                blitToWindow(quilt.fbo, quilt.width, quilt.height, windowW, windowH);
                break;
            case Shown::Viewer: {
                // CPU model of one eye behind the lenticular sheet (image order -> GL order).
                const std::vector<uint8_t> seen = simulateViewer(profile, session.eia().read(), viewerPos);
                viewer.ensure(profile.viewWidth, profile.viewHeight);
                const size_t row = size_t(profile.viewWidth) * 4;
                std::vector<uint8_t> flipped(seen.size());
                for (uint32_t y = 0; y < profile.viewHeight; ++y)
                    std::memcpy(&flipped[size_t(y) * row], &seen[size_t(profile.viewHeight - 1 - y) * row], row);
                glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
                glTextureSubImage2D(viewer.texture, 0, 0, 0, GLsizei(profile.viewWidth), GLsizei(profile.viewHeight),
                                    GL_RGBA, GL_UNSIGNED_BYTE, flipped.data());
                blitToWindow(viewer.fbo, viewer.width, viewer.height, windowW, windowH);
                break;
            }
            }
        }
        ++frame;
        const bool last = options.framesGiven && frame >= options.frames;
        if (last && !options.screenshot.empty()) {
            try {
                saveScreenshot(options.screenshot, windowW, windowH);
            } catch (const std::exception& e) {
                std::fprintf(stderr, "lfd-play: %s\n", e.what());
                status = 1;
            }
        }
        glfwSwapBuffers(window);

        // Step 4: title readout of the stages' mean milliseconds since the last update.
        if (wall - lastTitle >= 0.5 || last) {
            lastTitle = wall;
            std::string title = "lfd-play - " + packName + " - " + session.rendererName() + " - " +
                                reconstructions[reconstructionIndex] + " - " + shownName(shown);
            if (shown == Shown::SingleView || shown == Shown::Viewer) {
                char where[48];
                std::snprintf(where, sizeof(where), " (viewer %.1f)", viewerPos);
                title += where;
            }
            if (input.paused)
                title += " - paused";
            for (const auto& [stage, times] : session.timer().stages()) {
                size_t& from = titleFrom[stage];
                if (from >= times.ms.size())
                    continue;
                double sum = 0.0;
                for (size_t i = from; i < times.ms.size(); ++i)
                    sum += times.ms[i];
                char part[96];
                std::snprintf(part, sizeof(part), " | %s %.1f ms", stage.c_str(), sum / double(times.ms.size() - from));
                title += part;
                from = times.ms.size();
            }
            glfwSetWindowTitle(window, title.c_str());
        }
        if (last)
            break;
    }
    session.timer().finish();
    quilt.release();
    viewer.release();
    glDeleteFramebuffers(1, &layerFbo);
    glDeleteFramebuffers(1, &eiaFbo);
    return status;
}

} // namespace lfd::player
