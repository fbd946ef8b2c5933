// The project's own glTF 2.0 sample scenes (see samples/README.md). Each builder writes
// <dir>/<name>.gltf, <name>.bin and its PNG textures into an existing directory and
// returns what it wrote. Units are metres, +y up.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>

namespace lfd::samples {

struct SceneSummary {
    std::string name;
    size_t storedTriangles = 0; // in the buffer, each mesh once
    size_t drawnTriangles = 0;  // summed over node instances
    int textures = 0;
};

// A gallery interior (8 x 4 x 6 m, open towards +z): tiled floor with base colour,
// normal and metallicRoughness maps, plaster walls, four framed views of one large
// procedural painting (`textureSize`^2; the other textures are at most 1024^2).
SceneSummary writeGalleryScene(const std::filesystem::path& dir, int textureSize);

// A stylised untextured car with occluded interior parts and four instanced wheels
// spinning over a 2 s LINEAR rotation animation.
SceneSummary writeCarScene(const std::filesystem::path& dir);

// `instances` cars on a grid on a large floor, all instancing the car's meshes.
SceneSummary writeRoomScene(const std::filesystem::path& dir, int instances);

// A paper-scale benchmark block: `instances` copies of one textured, normal-mapped
// 4.5K-triangle object (240: about 1.1M drawn triangles), rows behind rows.
SceneSummary writeDenseScene(const std::filesystem::path& dir, int instances);

// A skinned, textured character: a limb of four bones swaying in a wave, with a morph
// target (its middle and head swell) whose weight is animated; 2 s loop.
SceneSummary writeCharacterScene(const std::filesystem::path& dir);

// `instances` characters on a grid (100: about 1M drawn triangles), each with its own
// skeleton at its own phase of the loop, all sharing one mesh.
SceneSummary writeCrowdScene(const std::filesystem::path& dir, int instances);

// Two rows of six spheres, roughness 0 to 1: metal (pale gold) above, a red dielectric
// below - the material grid for judging lighting (docs/lighting.md).
SceneSummary writeSpheresScene(const std::filesystem::path& dir);

// An over-dense, scanned-looking heightfield: 2,093,058 triangles of a 2 x 2 m textured
// patch, far finer than a view pixel when framed whole (issue 40, `lfd-bake --simplify`).
SceneSummary writeTerrainScene(const std::filesystem::path& dir);

// An RGB-D photo for `lfd-bake --rgbd`, not a glTF scene: photo.png, depth.png (white =
// near) and photo_rgbd.png (the two side by side), 512 x 384 each.
SceneSummary writeRgbdSample(const std::filesystem::path& dir);

} // namespace lfd::samples
