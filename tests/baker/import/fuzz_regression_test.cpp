// Inputs the glTF fuzz target found (scripts/fuzz.sh), committed under
// tests/data/fuzz/gltf and run through the same stages (tests/fuzz/gltf_fuzz_pipeline.h).
#include "../../fuzz/gltf_fuzz_pipeline.h"

#include <gtest/gtest.h>

#include <chrono>

namespace {

namespace fs = std::filesystem;
const fs::path kFindings = fs::path(LFD_TEST_DATA) / "fuzz" / "gltf";

// The file is refused by the bounds stage, with one line, within a few seconds.
void expectRefusedScale(const std::string& name)
{
    const auto start = std::chrono::steady_clock::now();
    try {
        lfd::fuzz::bakeToStatistics(kFindings / name);
        ADD_FAILURE() << name << " was accepted";
    } catch (const lfd::bake::BakeError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("exceeds 1e18 units, where squared lengths overflow single precision"), std::string::npos)
            << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 10.0);
}

TEST(GltfFuzzRegression, VertexBeyondTheFloatSquareRangeIsRefusedNotTessellatedForever)
{
    // The room sample with one position coordinate mutated to 9.48e21: its squared
    // distance overflowed float, the bounding radius became infinite, the framing fell
    // back to a unit radius and tessellation split a 1e22-unit triangle at a 0.47-unit
    // bound (a fuzzer timeout).
    expectRefusedScale("room_vertex_beyond_float_square.gltf");
}

TEST(GltfFuzzRegression, HugeSceneIsRefusedBeforeTessellationRunsOutOfMemory)
{
    // A .glb box whose vertices reach 7e22: the radius was finite, but tessellation's
    // float edge lengths overflowed to infinity, so every edge stayed "oversized" until
    // the process ran out of memory (a fuzzer out-of-memory after 90k runs).
    expectRefusedScale("vertex_1e22_tessellation_oom.glb");
}

TEST(GltfFuzzRegression, EveryFindingIsCovered)
{
    size_t files = 0;
    for (const auto& entry : fs::directory_iterator(kFindings))
        files += entry.is_regular_file();
    EXPECT_EQ(files, 2u) << "add a test for each new file in " << kFindings;
}

} // namespace
