// LFDPR binding points, uniform locations, options and sizes in one place for the
// renderers. Every value comes from the C++ side generated from shaders/lfdpr_bindings.glsl
// at build time (lfdpr_bindings_gpu.h, namespace lfdpr_bindings), and every size is sizeof
// of a generated struct the layout test checks member by member against the driver; so
// no number is written twice and nothing parses shader text at run time.
#pragma once

#include "lfdpr_bindings_gpu.h"

#include <glm/glm.hpp>

#include <cstdint>

namespace lfd::player {

struct LfdprConstants {
    // Paper pipeline and shared.
    unsigned ssboPoints = lfdpr_bindings::kSsboPoints, ssboTriangles = lfdpr_bindings::kSsboTriangles,
             ssboSampling = lfdpr_bindings::kSsboSampling, ssboCounters = lfdpr_bindings::kSsboCounters,
             ssboViewDepth = lfdpr_bindings::kSsboViewDepth, ssboViewWinner = lfdpr_bindings::kSsboViewWinner,
             ssboViewInverse = lfdpr_bindings::kSsboViewInverse, uboFrame = lfdpr_bindings::kUboFrame,
             imageViews = lfdpr_bindings::kImageViews;
    int locPass = lfdpr_bindings::kLocPass, locRecordBase = lfdpr_bindings::kLocRecordBase,
        locFirstTriangle = lfdpr_bindings::kLocFirstTriangle;
    uint32_t groupSize = lfdpr_bindings::kGroupSize; // local_size_x of the point-indexed passes
    uint32_t clearGroupX = lfdpr_bindings::kClearGroupX, clearGroupY = lfdpr_bindings::kClearGroupY;
    uint32_t tileSize = lfdpr_bindings::kTileSize;   // the paper pipeline's sampling viewport
    uint32_t pointBytes = sizeof(lfdpr_bindings::LfdprPaperPointGpu);
    uint32_t triangleRecordBytes = sizeof(lfdpr_bindings::LfdprPaperTriangleGpu);
    uint32_t triangleSamplingBytes = sizeof(lfdpr_bindings::LfdprPaperSamplingGpu);
    uint32_t counterBytes = sizeof(lfdpr_bindings::LfdprPaperCountersGpu);
    uint32_t viewInverseBytes = sizeof(glm::mat4); // ViewInverse: mat4 sceneFromClip[]
    // Visibility pipeline.
    unsigned ssboRecords = lfdpr_bindings::kSsboRecords, ssboIndices = lfdpr_bindings::kSsboIndices,
             ssboPositions = lfdpr_bindings::kSsboPositions, ssboNormals = lfdpr_bindings::kSsboNormals,
             ssboTangents = lfdpr_bindings::kSsboTangents, ssboUvs = lfdpr_bindings::kSsboUvs,
             ssboDraws = lfdpr_bindings::kSsboDraws;
    unsigned ssboLarge = lfdpr_bindings::kSsboLarge, ssboLargeDispatch = lfdpr_bindings::kSsboLargeDispatch,
             ssboVisCounters = lfdpr_bindings::kSsboVisCounters, ssboShadeWork = lfdpr_bindings::kSsboShadeWork,
             ssboChunkMasks = lfdpr_bindings::kSsboChunkMasks, ssboRepair = lfdpr_bindings::kSsboRepair,
             ssboWorkgroups = lfdpr_bindings::kSsboWorkgroups;
    unsigned uboCameraLine = lfdpr_bindings::kUboCameraLine;
    unsigned unitIndices = lfdpr_bindings::kUnitIndices, unitPositions = lfdpr_bindings::kUnitPositions,
             unitNormals = lfdpr_bindings::kUnitNormals, unitTangents = lfdpr_bindings::kUnitTangents,
             unitUvs = lfdpr_bindings::kUnitUvs,
             unitRecords = lfdpr_bindings::kUnitRecords, unitDraws = lfdpr_bindings::kUnitDraws,
             unitNodes = lfdpr_bindings::kUnitNodes, unitMaterials = lfdpr_bindings::kUnitMaterials,
             unitViewDepth = lfdpr_bindings::kUnitViewDepth, unitViewIndex = lfdpr_bindings::kUnitViewIndex;
    int locFirstWorkgroup = lfdpr_bindings::kLocFirstWorkgroup, locWorkgroups = lfdpr_bindings::kLocWorkgroups,
        locLargeClass = lfdpr_bindings::kLocLargeClass,
        locShadeMaterial = lfdpr_bindings::kLocShadeMaterial, locLargeBase = lfdpr_bindings::kLocLargeBase,
        locShadeGroup = lfdpr_bindings::kLocShadeGroup, locShadeGroups = lfdpr_bindings::kLocShadeGroups,
        locClearBackground = lfdpr_bindings::kLocClearBackground;
    // Shading in tiles per shading group (lfdpr_visibility_shade_list.comp, lfdpr_visibility_shade.comp).
    uint32_t shadeTile = lfdpr_bindings::kShadeTile, maxShadeGroups = lfdpr_bindings::kMaxShadeGroups,
             shadeDispatchWidth = lfdpr_bindings::kShadeDispatchWidth, viewChunk = lfdpr_bindings::kViewChunk,
             shadeEntryWords = lfdpr_bindings::kShadeEntryWords;
    uint32_t shadeCounterBytes = sizeof(lfdpr_bindings::LfdprVisibilityShadeCountersGpu);
    uint32_t recordBytes = sizeof(lfdpr_bindings::LfdprVisibilityRecordGpu);
    uint32_t compactPointBytes = sizeof(lfdpr_bindings::LfdprVisibilityPointGpu);
    uint32_t visCounterBytes = sizeof(lfdpr_bindings::LfdprVisibilityCountersGpu);
    uint32_t repairBytes = sizeof(lfdpr_bindings::LfdprVisibilityRepairGpu);
    uint32_t largeDispatchBytes = sizeof(glm::uvec4); // LargeDispatch: uvec4 per dispatch class
    uint32_t largeEntryBytes = sizeof(glm::uvec2);    // Large: (draw, primitive) per queued triangle
    uint32_t optionLfdSampling = lfdpr_bindings::kOptionLfdSampling,
             optionTextureSplatting = lfdpr_bindings::kOptionTextureSplatting,
             optionMvMipmapping = lfdpr_bindings::kOptionMvMipmapping;

    static const LfdprConstants& get()
    {
        static constexpr LfdprConstants constants{};
        return constants;
    }
};

// Workgroups (or tiles, or chunks) of size b that cover a items: ceil(a / b).
inline uint32_t divideUp(uint32_t a, uint32_t b) { return (a + b - 1) / b; }

} // namespace lfd::player
