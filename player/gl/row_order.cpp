#include "row_order.h"

#include <algorithm>
#include <stdexcept>

namespace lfd::gl {

std::vector<uint8_t> flipRows(std::span<const uint8_t> pixels, size_t rowBytes)
{
    if (rowBytes == 0 || pixels.size() % rowBytes != 0)
        throw std::invalid_argument("flipRows: " + std::to_string(pixels.size()) + " bytes are not whole rows of " +
                                    std::to_string(rowBytes));
    const size_t rows = pixels.size() / rowBytes;
    std::vector<uint8_t> out(pixels.size());
    for (size_t y = 0; y < rows; ++y)
        std::copy_n(&pixels[(rows - 1 - y) * rowBytes], rowBytes, &out[y * rowBytes]);
    return out;
}

} // namespace lfd::gl
