// Procedural textures for the gallery scene, written as RGB8 PNGs strip by strip so
// that even a 16384^2 picture never needs more than one strip of pixels in memory.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>

namespace lfd::samples {

// Fills `rowCount` rows starting at row `y0` of an RGB8 image into `pixels`
// (rowCount * width * 3 bytes, rows top to bottom).
using RowFiller = std::function<void(int y0, int rowCount, uint8_t* pixels)>;

// Streams an RGB8 PNG to `path`, asking `fill` for strips of rows. Rows are filled
// on all cores; throws std::runtime_error naming the file on failure.
void writePngRgb8(const std::filesystem::path& path, int width, int height, const RowFiller& fill);

// The gallery's floor is kFloorTilesU x kFloorTilesV square tiles of 1 m, mapped once
// onto the whole floor (uvs stay in [0, 1]); the scene sizes the floor to match.
inline constexpr int kFloorTilesU = 8;
inline constexpr int kFloorTilesV = 6;

// A procedural painting with high-frequency detail at every scale (colour bands,
// 4-pixel checkers, 3-pixel stripes, a zone plate reaching Nyquist at its rim, rows of
// 5x7 text, hairlines), so minification without mipmapping visibly aliases. sRGB.
void writePaintingTexture(const std::filesystem::path& path, int size);

// Marble floor tiles with grout: base colour (sRGB), tangent-space normal map (glTF
// convention: +Y is image-up) and metallicRoughness (R occlusion, G roughness,
// B metallic), all `size` x `size`.
void writeFloorBaseColor(const std::filesystem::path& path, int size);
void writeFloorNormal(const std::filesystem::path& path, int size);
void writeFloorMetallicRoughness(const std::filesystem::path& path, int size);

// Plaster wall: warm off-white with mottling and trowel streaks. sRGB.
void writePlasterTexture(const std::filesystem::path& path, int size);

} // namespace lfd::samples
