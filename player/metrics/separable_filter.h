// Separable filtering of one float plane with replicated borders (the border handling FLIP
// specifies). Kernels have odd length and are applied centred, as a correlation:
// out(x) = sum_k kernel[k] * in(clamp(x + k - r)). Internal to lfd_image_metrics.
#pragma once

#include <span>
#include <vector>

namespace lfd::metrics::detail {

struct Plane {
    int width = 0;
    int height = 0;
    std::vector<float> values; // row 0 = top
};

// Filters along x (each row) or along y (each column) into `out`, which is resized to the
// input's size; passing the same `out` again reuses its memory (panel-size planes are
// 33 MB each, and fresh ones cost more in page faults than the filtering itself).
void filterRows(const Plane& in, std::span<const float> kernel, Plane& out);
void filterColumns(const Plane& in, std::span<const float> kernel, Plane& out);
// out = columns(rows(in, horizontal), vertical), with `scratch` for the intermediate.
void filterSeparable(const Plane& in, std::span<const float> horizontal,
                     std::span<const float> vertical, Plane& scratch, Plane& out);

} // namespace lfd::metrics::detail
