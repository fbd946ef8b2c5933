// LFDPR point generation in compute (the visibility pipeline; shaders/lfdpr_visibility_points.comp):
// one invocation per triangle, then one workgroup per large triangle. Triangles are cut
// into workgroups of LFDPR_GROUP_SIZE triangles of one draw (LfdprVisibilityWorkgroupGpu), so one
// dispatch samples every draw without an alpha test, and each alpha-tested draw (whose
// textures must be bound) gets one of its own: the dispatch count does not grow with the
// scene's draws. Large triangles are queued per such dispatch class and sampled by one
// indirect dispatch each. The caller binds the scene, the LFDPR buffers (points, records,
// draws, counters) and the frame constants.
#pragma once

#include "gl_handles.h"

#include <cstdint>
#include <vector>

namespace lfd::player {

class GpuScene;

class LfdprVisibilityPointGeneration {
public:
    // Builds the programs (per pass, with and without alpha test); `pixelCentreCulling`
    // compiles in LFDPR_PIXEL_CENTRE_CULLING (LfdprOptions::pixelCentreCulling),
    // `trimMargin` LFDPR_TRIM_MARGIN (LfdprOptions::trimSamplingMargin);
    // cellScale > 1 compiles in LFDPR_CELL_SCALE (LfdprOptions::cellScale) for the programs
    // of materials without an alpha test; `gpuWork` LFDPR_WORK_GPU (lfdpr_work_shape.glsl).
    LfdprVisibilityPointGeneration(bool pixelCentreCulling, bool trimMargin, uint32_t cellScale, bool gpuWork);

    // The workgroup table and the large-triangle queues for `scene`'s draws (again only
    // when the scene changes). drawFirstTriangle: each draw's first drawn-triangle index,
    // where its triangles' records go (the renderer's record numbering).
    void prepare(const GpuScene& scene, const std::vector<uint32_t>& drawFirstTriangle);
    // Clears the large-triangle queues' dispatch words (no barrier: the caller puts one
    // after its own clears).
    void clearQueues() const;
    // Samples every drawn triangle: one dispatch per class, then one indirect dispatch per
    // class over its queued large triangles.
    void run(const GpuScene& scene) const;

    size_t bufferBytes() const; // the workgroup table and the large-triangle queue
    size_t clearedBytes() const; // what clearQueues clears: the queues' dispatch words

private:
    // One dispatch: the workgroups [firstWorkgroup, firstWorkgroup + workgroups) of the
    // table; its large triangles go to queue segment largeBase.. and dispatch word `index`.
    struct DispatchClass {
        int32_t material;     // the alpha-tested draw's material, kNone for the opaque class
        uint32_t firstWorkgroup, workgroups;
        uint32_t largeBase;
    };
    // [alpha test][large pass]: draws of alpha-masked materials use the programs with the
    // alpha test (LFDPR_ALPHA_TEST), all others the ones without.
    gl::Program programs_[2][2];
    uint64_t sceneSerial_ = 0; // GpuScene::serial() of the scene the tables are for
    size_t drawCount_ = 0;
    std::vector<DispatchClass> classes_;
    gl::Buffer workgroups_, large_, largeDispatch_;
    size_t bytes_ = 0;
};

} // namespace lfd::player
