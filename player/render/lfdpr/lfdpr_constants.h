// LFDPR binding points, locations and sizes, read once from the embedded
// shaders/lfdpr_bindings.glsl (the definition), so C++ never writes a number twice and the
// shader source is parsed once per renderer, not per frame.
#pragma once

#include <cstdint>

namespace lfd::player {

struct LfdprConstants {
    // Paper pipeline and shared.
    unsigned ssboPoints, ssboCounters, ssboViewDepth, ssboViewColor, uboFrame, imageViews;
    int locPass;
    uint32_t groupSize;
    // Visibility pipeline.
    unsigned ssboRecords, ssboIndices, ssboPositions, ssboNormals, ssboTangents, ssboUvs, ssboDraws;
    unsigned ssboLarge, ssboLargeDispatch, ssboVisCounters, ssboMaterialIds, ssboShadeWork, ssboMaterialGroups;
    unsigned uboCameraLine;
    int locDraw, locTriangles, locShadeMaterial, locLargeBase, locShadeGroup, locShadeGroups;
    uint32_t shadeTile, maxShadeGroups, shadeDispatchWidth;
    uint32_t recordBytes, compactPointBytes, visCounterBytes;
    uint32_t optionLfdSampling, optionTextureSplatting, optionMvMipmapping;

    static const LfdprConstants& get(); // parsed on first use
};

} // namespace lfd::player
