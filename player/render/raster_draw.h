// What mvr and mvr-layered share: the per-frame uniforms, the GL state of a raster pass,
// and the loop over the scene's draws (per-draw node, material, textures and culling).
// They differ only in how views are selected: a uniform per pass, or gl_InstanceID.
#pragma once

#include "frame_uniforms.h"
#include "gl_handles.h"
#include "renderer.h"

namespace lfd::player {

class RasterDraw {
public:
    explicit RasterDraw(const char* vertexShader); // compiles vertexShader + mvr.frag

    unsigned program() const { return program_.get(); }
    // Uploads the frame's views/constants and sets program, VAO, buffers, depth state.
    void beginFrame(const GpuScene& scene, const FrameSetup& frame);
    // Issues every DrawItem with `instances` instances (1 for mvr, N for mvr-layered).
    void drawScene(const GpuScene& scene, unsigned instances) const;
    // Restores what beginFrame and the draws changed, and binds the default framebuffer.
    void endFrame() const;

    // Work counters of a frame (extraStats), computed on the CPU with no read-back: drawn
    // triangles x views, and the bytes the targets' clear writes (RGBA8 colour + D32F depth).
    void countWork(const GpuScene& scene, const ViewTargets& targets);
    std::vector<std::pair<std::string, double>> workStats() const;

private:
    gl::Program program_;
    FrameUniforms uniforms_;
    uint64_t workTriangleViews_ = 0, workBytesCleared_ = 0;
};

// The raster renderers' frame: one "view_generation" stage that clears the targets
// (colour and the depth array they draw with), counts the work, sets up the pass, lets the
// renderer issue its draws (drawViews) and restores the state.
class RasterRenderer : public Renderer {
public:
    explicit RasterRenderer(const char* vertexShader) : draw_(vertexShader) {}
    bool drawsWithDepthTargets() const final { return true; }
    void render(const GpuScene& scene, const FrameSetup& frame, ViewTargets& targets, GpuTimer& timer) final;
    std::vector<std::pair<std::string, double>> extraStats() const final { return draw_.workStats(); }

protected:
    // Binds framebuffers and issues draw_.drawScene for every view.
    virtual void drawViews(const GpuScene& scene, ViewTargets& targets) = 0;
    RasterDraw draw_;
};

std::unique_ptr<Renderer> createMvrRenderer();
std::unique_ptr<Renderer> createMvrLayeredRenderer();

} // namespace lfd::player
