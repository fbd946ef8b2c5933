// RGB-D input (docs/baker/rgbd.md): a photo and its depth map - two images, or one
// side-by-side image (colour left, depth right) - turned into a textured relief mesh that
// the rest of the bake treats like an imported glTF scene (bounds, tessellation bound,
// triangle statistics, texture compression).
//
// The relief is orthographic: the image spans aspect x 1 scene units in x and y (y up),
// depth moves vertices along +z (towards the viewer) by up to `relief` image heights. One
// vertex per depth pixel (a coarser grid above kMaxRgbdGridSize points per side, with a
// warning); where the surface is flat the grid is merged into larger right triangles
// within `flatness` image heights (a right-triangulated irregular network: crack-free,
// linear time). Triangles across a depth discontinuity are dropped (default) or kept
// stretched. The photo is the material's emissive texture over a
// black base colour, so it shows as shot whatever the light (plus the metallic-roughness
// model's 4% dielectric reflection).
#pragma once

#include "bake_log.h"
#include "imported_scene.h"

#include <filesystem>

namespace lfd::bake {

// Most grid points per side (2^12 + 1): larger depth maps are sampled coarser.
constexpr uint32_t kMaxRgbdGridSize = 4097;

enum class RgbdEdges { Drop, Stretch };

struct RgbdOptions {
    std::filesystem::path color;
    std::filesystem::path depth; // empty: `color` is side-by-side, colour left, depth right
    double relief = 0.5;         // depth of the relief, in image heights
    double depthLow = 0.0;       // depth-map values mapped to the far plane ...
    double depthHigh = 1.0;      // ... and to the near one (values outside are clamped)
    bool invert = false;         // false: white is near (the usual depth-map convention)
    RgbdEdges edges = RgbdEdges::Drop;
    double edgeThreshold = 0.05; // neighbours further apart (fraction of the depth range) are a discontinuity
    double flatness = 0.001;     // simplification tolerance in image heights; 0: full grid
};

// The relief scene with its one texture source (the photo, or its left half encoded as
// PNG). Throws BakeError with one line naming the file and the problem (unreadable image,
// no depth channel, sizes whose aspects differ, a depth map with no triangle left).
ImportedScene importRgbd(const RgbdOptions& options, const Log& log);

} // namespace lfd::bake
