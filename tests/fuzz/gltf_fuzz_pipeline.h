// What the glTF fuzz target runs on each input, shared with the regression test of its
// findings (tests/baker/fuzz_regression_test.cpp): the CPU bake stages up to a
// tessellated, statistics-complete scene, as lfd-bake runs them (baker/main.cpp) -
// import, bounds, framing on the prototype display, tessellation at the default
// 100-view-pixel edge bound, triangle statistics. Throws lfd::bake::BakeError on bad input.
#pragma once

#include "bake.h"

#include <filesystem>

namespace lfd::fuzz {

inline lfd::Scene bakeToStatistics(const std::filesystem::path& file)
{
    using namespace lfd::bake;
    const Log quiet;
    ImportedScene imported = importGltf(file, quiet);
    lfd::Scene& scene = imported.scene;
    scene.bounds = computeBounds(scene);
    const lfd::DisplayProfile profile = lfd::prototypeDisplayProfile();
    const lfd::Framing framing = lfd::fitSceneToDisplay(profile, scene.bounds, 1.0);
    const double viewPixelWorld = lfd::minViewPixelWorld(profile, framing);
    tessellateScene(scene, 100.0 * viewPixelWorld, quiet);
    // Images are not decoded (texture_bake has its own tests): every texture is taken as
    // 256x256 so that the texel statistics run.
    for (lfd::Texture& texture : scene.textures)
        texture.width = texture.height = 256;
    computeTriangleStats(scene);
    return std::move(imported.scene);
}

} // namespace lfd::fuzz
