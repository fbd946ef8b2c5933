// LFDPR point generation in compute (the visibility pipeline; shaders/lfdpr_points.comp):
// one invocation per triangle of each draw, then one workgroup per large triangle of each
// draw. The caller binds the scene, the LFDPR buffers (points, records, the large-triangle
// list and its per-draw dispatch words, counters) and the frame constants.
#pragma once

#include "gl_handles.h"

#include <cstdint>
#include <vector>

namespace lfd::player {

class GpuScene;

class LfdprComputePointGeneration {
public:
    // Builds the programs (per pass, with and without alpha test); `pixelCentreCulling`
    // compiles in LFDPR_PIXEL_CENTRE_CULLING (LfdprOptions::pixelCentreCulling);
    // cellScale > 1 compiles in LFDPR_CELL_SCALE (LfdprOptions::cellScale) for the programs
    // of materials without an alpha test.
    LfdprComputePointGeneration(bool pixelCentreCulling, uint32_t cellScale);

    // largeBase[d]: first slot of draw d in the large-triangle list (its triangles before
    // it); largeDispatch: the per-draw indirect dispatch words (uvec4 each, cleared to
    // (0, 1, 1, 0) by the caller).
    void run(const GpuScene& scene, const std::vector<uint32_t>& largeBase, unsigned largeDispatch) const;

private:
    // [alpha test][large pass]: draws of alpha-masked materials use the programs with the
    // alpha test (LFDPR_ALPHA_TEST), all others the ones without.
    gl::Program programs_[2][2];
};

} // namespace lfd::player
