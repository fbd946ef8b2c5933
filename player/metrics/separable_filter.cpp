// Separable filtering with replicated borders; see separable_filter.h. Both passes loop
// over the taps outside and the pixels inside, so the inner loop is a contiguous
// multiply-add the compiler vectorises; rows go to the cores in bands (common/parallel.h:
// each output row is computed exactly as before, whatever thread computes it).
#include "separable_filter.h"

#include "parallel.h"

#include <algorithm>
#include <stdexcept>

namespace lfd::metrics::detail {

namespace {

constexpr size_t kBandRows = 32; // rows per band: a panel-size plane is 68 bands

int checkedRadius(std::span<const float> kernel)
{
    if (kernel.empty() || kernel.size() % 2 == 0)
        throw std::invalid_argument("separable filter: kernel length must be odd");
    return int(kernel.size() / 2);
}

void resizeLike(const Plane& in, Plane& out)
{
    out.width = in.width;
    out.height = in.height;
    out.values.resize(in.values.size());
}

} // namespace

void filterRows(const Plane& in, std::span<const float> kernel, Plane& out)
{
    const int r = checkedRadius(kernel);
    resizeLike(in, out);
    const size_t w = size_t(in.width);
    forEachBand(size_t(in.height), kBandRows, [&](size_t, size_t begin, size_t end) {
        // Each row is copied into a buffer padded by r replicated pixels on either side.
        std::vector<float> padded(w + 2 * size_t(r));
        for (size_t y = begin; y < end; ++y) {
            const float* row = &in.values[y * w];
            std::fill(padded.begin(), padded.begin() + r, row[0]);
            std::copy(row, row + w, padded.begin() + r);
            std::fill(padded.begin() + r + std::ptrdiff_t(w), padded.end(), row[w - 1]);
            float* dst = &out.values[y * w];
            std::fill(dst, dst + w, 0.0f);
            for (size_t k = 0; k < kernel.size(); ++k) {
                const float weight = kernel[k];
                const float* src = padded.data() + k;
                for (size_t x = 0; x < w; ++x)
                    dst[x] += weight * src[x];
            }
        }
    });
}

void filterColumns(const Plane& in, std::span<const float> kernel, Plane& out)
{
    const int r = checkedRadius(kernel);
    resizeLike(in, out);
    const size_t w = size_t(in.width);
    forEachBand(size_t(in.height), kBandRows, [&](size_t, size_t begin, size_t end) {
        for (int y = int(begin); y < int(end); ++y) {
            float* dst = &out.values[size_t(y) * w];
            std::fill(dst, dst + w, 0.0f);
            for (int k = -r; k <= r; ++k) {
                const float weight = kernel[size_t(k + r)];
                const float* src = &in.values[size_t(std::clamp(y + k, 0, in.height - 1)) * w];
                for (size_t x = 0; x < w; ++x)
                    dst[x] += weight * src[x];
            }
        }
    });
}

void filterSeparable(const Plane& in, std::span<const float> horizontal,
                     std::span<const float> vertical, Plane& scratch, Plane& out)
{
    filterRows(in, horizontal, scratch);
    filterColumns(scratch, vertical, out);
}

} // namespace lfd::metrics::detail
