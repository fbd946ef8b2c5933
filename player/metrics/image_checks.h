// Argument checks shared by the metrics (internal to lfd_image_metrics).
#pragma once

#include "image_metrics.h"

#include <span>

namespace lfd::metrics::detail {

// Throws std::invalid_argument naming `metric` when the images are empty, differ in size,
// or a pixel buffer does not hold width * height * 3 values.
void requireSameSize(const RgbImage& reference, const RgbImage& test, const char* metric);
// Throws std::invalid_argument when the mask is not width * height bytes.
void requireMaskSize(const RgbImage& image, std::span<const uint8_t> mask, const char* metric);

} // namespace lfd::metrics::detail
