// GL's images run bottom row first (glReadPixels, glGetTextureImage, glTextureSubImage*:
// row 0 = bottom); image files, the CPU metrics and the tests use image order (row 0 =
// top). Reversing the row order converts either way, so this one function is used in both
// directions.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace lfd::gl {

// `pixels` holds whole rows of `rowBytes` each; returns them in the opposite row order.
std::vector<uint8_t> flipRows(std::span<const uint8_t> pixels, size_t rowBytes);

} // namespace lfd::gl
