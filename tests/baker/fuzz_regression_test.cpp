// Inputs the glTF fuzz target found (scripts/fuzz.sh), committed under
// tests/data/fuzz/gltf and run through the same stages (tests/fuzz/gltf_fuzz_pipeline.h).
#include "../fuzz/gltf_fuzz_pipeline.h"

#include <gtest/gtest.h>

#include <chrono>

namespace {

namespace fs = std::filesystem;
const fs::path kFindings = fs::path(LFD_TEST_DATA) / "fuzz" / "gltf";

TEST(GltfFuzzRegression, VertexBeyondTheFloatSquareRangeIsFramedNotTessellatedForever)
{
    // The room sample with one position coordinate mutated to 9.48e21: its squared
    // distance overflowed float, the bounding radius became infinite, the framing fell
    // back to a unit radius and tessellation split a 1e22-unit triangle at a 0.47-unit
    // bound (a fuzzer timeout). Now the radius is computed in double.
    const auto start = std::chrono::steady_clock::now();
    const lfd::Scene scene = lfd::fuzz::bakeToStatistics(kFindings / "room_vertex_beyond_float_square.gltf");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_LT(seconds, 10.0);
    EXPECT_TRUE(std::isfinite(scene.bounds.radius));
    EXPECT_GT(scene.bounds.radius, 4.7e21f);
    EXPECT_LT(scene.bounds.radius, 9.5e21f);
    EXPECT_EQ(scene.triangleStats.size(), scene.triangleCount());
    EXPECT_LT(scene.triangleCount(), 2 * 5394u); // a few oversized triangles split, no more
}

TEST(GltfFuzzRegression, EveryFindingIsCovered)
{
    size_t files = 0;
    for (const auto& entry : fs::directory_iterator(kFindings))
        files += entry.is_regular_file();
    EXPECT_EQ(files, 1u) << "add a test for each new file in " << kFindings;
}

} // namespace
