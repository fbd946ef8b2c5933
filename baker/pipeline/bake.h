// lfd-bake pipeline: glTF 2.0 (or an RGB-D image) in, .lfdpack out. bake() is the one entry
// point: lfd-bake (tool/), the tests and any binding call it. Its stages are free
// functions in libraries named for them, in data-flow order, each declared in the header
// of the file that implements it:
//
//   importGltf        import/gltf_import.h       glTF -> lfd::Scene (object-space meshes,
//                                                nodes, animations, materials, texture sources;
//                                                reading and checking the glTF: gltf/)
//   importRgbd        import/rgbd_import.h       a photo and its depth map -> lfd::Scene
//   computeBounds     geometry/scene_bounds.h    scene-space AABB + bounding sphere over animations
//   simplifyScene     geometry/simplification.h  merge triangles finer than --simplify view pixels
//   tessellateScene   geometry/tessellation.h    split oversized triangles, crack-free
//   computeTriangleStats geometry/triangle_stats.h  A_ws, A_ts, n_tex, size_uv, A_ts/A_ws
//   resolvableTextureSize texture/texture_budget.h  the texture size the views can resolve
//   bakeTexture       texture/texture_bake.h     decode, reduce, mip chain (sRGB-correct), RGBA8
//   compressTexture   texture/texture_compression.h  BC1/BC3/BC4/BC5 by what the materials read
//   writePack         formats/                   atomic write
//
// Errors in input data throw BakeError (base/bake_log.h) with a one-line message naming
// the file.
#pragma once

#include "bake_log.h"
#include "bake_report.h"
#include "rgbd_import.h"
#include "texture_compression.h"

#include <cstdint>
#include <filesystem>
#include <optional>

namespace lfd::bake {

// Everything a bake needs; lfd-bake fills it from its flags (docs/baker/lfd-bake.md).
struct BakeOptions {
    std::filesystem::path input;   // glTF 2.0 scene; with `rgbd`, the colour image (names the bake)
    std::filesystem::path output;  // the pack (resolveOutputPath, bake_outputs.h)
    std::filesystem::path display; // display profile or Looking Glass visual.json; empty: the prototype
    std::filesystem::path depfile; // also write the files the bake read here (Make/Ninja); empty: none
    double maxEdgePx = 100.0;      // split triangles whose edges exceed this many view pixels
    double simplifyPx = 0.25;      // merge triangles within this error, view pixels (0: off)
    double fill = 1.0;             // fraction of the display's sphere the scene's bounding sphere fills
    uint32_t maxTextureSize = 16384;
    double textureDetail = 2.0;    // texels this many times finer than the finest view pixel
    bool keepFullTextures = false; // never drop mip levels the views cannot resolve
    TextureCompression textureCompression = TextureCompression::Bc;
    unsigned threads = 0;          // 0: one per hardware thread; the pack is the same bytes for any count
    std::optional<RgbdOptions> rgbd; // set: bake this RGB-D image instead of a glTF scene
};

// The whole bake: the stages above in order, each timed for the report, the pack written
// atomically to options.output (and the depfile, if asked for). Progress and warnings go
// to `log`; errors in the input throw BakeError (one line naming the file), a failed write
// PackError. The report is what lfd-bake prints (printBakeReport).
BakeReport bake(const BakeOptions& options, const Log& log);

} // namespace lfd::bake
