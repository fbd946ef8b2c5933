// Work over the rows (or pixels) of an image spread across the machine's cores, in bands of
// a fixed size. Each band writes only its own part of the output, or its own partial
// result that the caller combines in band order, so the outcome is the same bit for bit
// whatever the number of threads (the bench's error columns are deterministic, and a
// 2-core CI machine computes what a 16-core GPU server does).
#pragma once

#include <cstddef>
#include <functional>

namespace lfd::metrics {

// The number of bands [0, count) is cut into: ceil(count / bandSize).
size_t bandCount(size_t count, size_t bandSize);

// Calls band(index, begin, end) for each band [begin, end) of [0, count) (bands of
// bandSize, the last one shorter), from up to std::thread::hardware_concurrency() threads,
// the caller's among them, and returns when every band has run. The first exception a band
// throws is rethrown here once all threads have stopped.
void forEachBand(size_t count, size_t bandSize, const std::function<void(size_t index, size_t begin, size_t end)>& band);

} // namespace lfd::metrics
