// The renderer interface every method plugs into (mvr, mvr-layered, lfdpr, gstd): each
// renders the same N views of the same frame into a ViewTargets texture array, so views
// can be compared pixel by pixel and the EIA pass reads them the same way.
#pragma once

#include "frame.h"

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace lfd::player {

class GpuScene;
class GpuTimer;
class ViewTargets;

class Renderer {
public:
    virtual ~Renderer() = default;
    virtual std::string name() const = 0;
    // Renders frame.cameras into targets (layer i = view i, view 0 = leftmost camera).
    // Each stage is bracketed with timer.begin("<stage>") / timer.end(); stage names are
    // the stats keys without "_ms": "view_generation" for raster renderers, lfdpr adds
    // "point_generation".
    virtual void render(const GpuScene& scene, const FrameSetup& frame, ViewTargets& targets,
                        GpuTimer& timer) = 0;
    // Renderer-specific numbers for the stats JSON, e.g. {"points", 2.29e6}; as of the last
    // frame whose counts came back from the GPU (settle() brings them to the last frame).
    virtual std::vector<std::pair<std::string, double>> extraStats() const { return {}; }
    // GPU memory the renderer holds for its frames beyond the scene and the view targets
    // (point, record and per-view-pixel buffers), in bytes.
    virtual uint64_t frameGpuBytes() const { return 0; }
    // True for renderers that rasterise into the view targets' framebuffers and so need
    // their depth array (ViewTargets allocates it on first use); it counts in the frame's
    // GPU memory only for them.
    virtual bool drawsWithDepthTargets() const { return false; }
    // A renderer that sizes its buffers from counts the GPU keeps (lfdpr's points) reads them back
    // frames later, behind a fence, so no frame waits for the GPU (docs/player/lfdpr.md "Frames
    // that never wait"); a frame that overflowed is known only then. settle() waits for the counts
    // of every frame rendered so far, applies them (grown buffers, stats) and says whether the last
    // frame was complete; false: it overflowed and rendering the same frame again draws it whole.
    // Blocking: for frames whose outputs are read, never between steady-state frames.
    virtual bool settle() { return true; }
    // A renderer that computes the panel image itself (gstd's panel model, which integrates
    // every subpixel's own footprint instead of interleaving views) writes it into the EIA
    // texture (RGBA8, panel size) after render(), as stage "eia", and returns true; the
    // pipeline then skips its EIA pass. The default, false: the EIA is built from the views.
    virtual bool writePanelImage(unsigned /*eiaTexture*/, GpuTimer& /*timer*/) { return false; }
};

// Renderers are built by name through the one registry, renderer_registry.h.

} // namespace lfd::player
