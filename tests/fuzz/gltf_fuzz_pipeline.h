// What the glTF fuzz target runs on each input, shared with the regression test of its
// findings (tests/baker/import/fuzz_regression_test.cpp): the CPU bake stages up to a
// tessellated, statistics-complete scene, as lfd-bake runs them (baker/pipeline/bake.cpp) -
// import (Draco and meshopt decoding included), bounds, framing on the prototype display,
// tessellation at the default 100-view-pixel edge bound, triangle statistics; embedded
// WebP images are decoded too. Throws lfd::bake::BakeError on bad input.
#pragma once

#include "bake_log.h"
#include "imported_scene.h"
#include "gltf_import.h"
#include "scene_bounds.h"
#include "tessellation.h"
#include "triangle_stats.h"
#include "texture_bake.h"
#include "lfd/display_profile.h"
#include "lfd/framing.h"

#include <cstdint>
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
    // Images are not decoded (texture_bake has its own tests) except embedded WebP ones of
    // up to 1024x1024 (EXT_texture_webp: libwebp on bytes from the file, texture_webp.h);
    // every texture is then taken as 256x256 so that the texel statistics run.
    for (const TextureSource& source : imported.textureSources)
        if (source.mimeType == "image/webp" && !source.encoded.empty()) {
            const glm::uvec2 size = probeTextureSize(source);
            if (uint64_t(size.x) * size.y <= (uint64_t(1) << 20))
                bakeTexture(source, TextureBakeOptions{64, 1, nullptr});
        }
    for (lfd::Texture& texture : scene.textures)
        texture.width = texture.height = 256;
    computeTriangleStats(scene);
    return std::move(imported.scene);
}

} // namespace lfd::fuzz
