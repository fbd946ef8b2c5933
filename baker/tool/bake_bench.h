// `lfd-bake --bench`: throughput of the bake stages that use threads (issue 9, "Baker
// throughput"), measured on a scene generated in memory so that the figures can be
// reproduced anywhere without input files.
#pragma once

#include <cstddef>
#include <cstdint>
#include <ostream>
#include <vector>

namespace lfd::bake {

struct BenchOptions {
    size_t triangles = size_t(1) << 20; // input triangles, about (8 grid meshes)
    uint32_t textureSize = 16384;       // one square sRGB texture
    // Each stage runs this many times per thread count and the fastest counts: first
    // touches of fresh memory (costly in a VM) and other work on the machine count less.
    unsigned repeat = 3;
    std::vector<unsigned> threads = {1, 2};
};

// Runs tessellation, triangle statistics and the mip chain once per thread count, each
// run in its own process so its peak memory (ru_maxrss) is its own, and prints one line
// per run (triangles per second, megapixels per second, peak memory), the speed-up of
// every count over the first, and whether every run produced the same bytes.
// Returns 0, or 1 when a run failed or the outputs differ.
int runBench(const BenchOptions& options, std::ostream& out);

// One run, in the process runBench starts (lfd-bake --bench-run THREADS): prints its
// figures as one line for runBench to read. Returns 0, or 1 after printing the error.
int runBenchChild(const BenchOptions& options, unsigned threads, std::ostream& out);

} // namespace lfd::bake
