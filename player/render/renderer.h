// The renderer interface every method plugs into (mvr, mvr-layered, lfdpr, gstd): each
// renders the same N views of the same frame into a ViewTargets texture array, so views
// can be compared pixel by pixel and the EIA pass reads them the same way.
#pragma once

#include "frame.h"

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
    // Renderer-specific numbers for the stats JSON, e.g. {"points", 2.29e6}.
    virtual std::vector<std::pair<std::string, double>> extraStats() const { return {}; }
};

// Renderers are built by name through the one registry, renderer_registry.h.

} // namespace lfd::player
