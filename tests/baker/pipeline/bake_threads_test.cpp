// Issue 9: "Baking the same input twice gives byte-identical packs, also when the baker
// uses threads." The stages that use threads (tessellation, triangle statistics, mip
// chains) give the same bytes for 1, 2, 3 and 8 threads, and `lfd-bake --threads N` writes
// the same pack for every N, on scenes with several meshes and textures.
#include "bake_log.h"
#include "triangle_stats.h"
#include "tessellation.h"

#include "skip_or_fail.h"

#include "tool_run.h"

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace lfd::bake {
namespace {

// ---- In-process: the stages --------------------------------------------------------------

// Appends a jittered n x n grid (own vertices, uvs, normals) as one primitive over
// vertices [base, base + (n + 1)^2); `shareFrom` >= 0 makes the primitive reuse that
// earlier primitive's vertices instead (two meshes on one vertex range).
void addGrid(Scene& scene, uint32_t n, float cell, glm::vec3 origin, uint32_t seed, int32_t material,
             int shareFrom = -1)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> jitter(-0.2f, 0.2f);
    VertexStreams& v = scene.vertices;
    uint32_t base = uint32_t(v.positions.size());
    if (shareFrom >= 0) {
        base = scene.indices[scene.primitives[size_t(shareFrom)].firstIndex];
    } else {
        for (uint32_t j = 0; j <= n; ++j)
            for (uint32_t i = 0; i <= n; ++i) {
                v.positions.push_back(origin + glm::vec3(float(i) * cell, float(j) * cell, jitter(rng) * cell));
                v.normals.push_back(glm::normalize(glm::vec3(jitter(rng), jitter(rng), 1.0f)));
                v.uvs.emplace_back(float(i) / float(n), float(j) / float(n));
            }
    }
    Primitive prim;
    prim.firstIndex = uint32_t(scene.indices.size());
    prim.material = material;
    for (uint32_t j = 0; j < n; ++j)
        for (uint32_t i = 0; i < n; ++i) {
            const uint32_t c = base + j * (n + 1) + i;
            // Alternate the diagonal so that faces differ.
            if ((i + j) % 2 == 0)
                scene.indices.insert(scene.indices.end(), {c, c + 1, c + n + 2, c, c + n + 2, c + n + 1});
            else
                scene.indices.insert(scene.indices.end(), {c, c + 1, c + n + 1, c + 1, c + n + 2, c + n + 1});
        }
    prim.indexCount = uint32_t(scene.indices.size()) - prim.firstIndex;
    scene.primitives.push_back(prim);
}

// Seven meshes: coarse grids cut into many pieces per face, fine grids that are mostly
// left alone, one mesh of two primitives, one sharing another's vertices, and two
// textures of different sizes on two materials.
Scene multiMeshScene()
{
    Scene scene;
    for (uint32_t t = 0; t < 2; ++t) {
        Texture texture;
        texture.name = "t" + std::to_string(t);
        texture.width = texture.height = 256u << t;
        scene.textures.push_back(texture);
        Material material;
        material.baseColorTexture = int32_t(t);
        scene.materials.push_back(material);
    }
    const std::array<std::pair<uint32_t, float>, 6> grids = {
        {{4, 2.5f}, {40, 0.3f}, {6, 1.7f}, {3, 4.0f}, {30, 0.5f}, {8, 1.1f}}};
    for (uint32_t g = 0; g < grids.size(); ++g) {
        addGrid(scene, grids[g].first, grids[g].second, glm::vec3(12.0f * float(g), 0.0f, 0.0f), g + 1,
                int32_t(g % 2));
        if (g == 2) // mesh 2 has a second primitive
            addGrid(scene, 5, 1.3f, glm::vec3(12.0f * float(g), 12.0f, 0.0f), 99, kNone);
        Mesh mesh;
        mesh.name = "grid " + std::to_string(g);
        mesh.firstPrimitive = uint32_t(scene.primitives.size()) - (g == 2 ? 2 : 1);
        mesh.primitiveCount = g == 2 ? 2 : 1;
        scene.meshes.push_back(mesh);
    }
    addGrid(scene, 4, 2.5f, glm::vec3(0.0f), 1, 1, /*shareFrom=*/0);
    Mesh shared;
    shared.name = "shares grid 0's vertices";
    shared.firstPrimitive = uint32_t(scene.primitives.size()) - 1;
    shared.primitiveCount = 1;
    scene.meshes.push_back(shared);
    return scene;
}

std::vector<double> bounds(const Scene& scene, double bound) { return std::vector<double>(scene.meshes.size(), bound); }
std::vector<float> unitScales(const Scene& scene) { return std::vector<float>(scene.meshes.size(), 1.0f); }

template <typename T>
std::string bytesOf(const std::vector<T>& values)
{
    return std::string(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

struct StageOutput {
    std::string positions, normals, uvs, indices, primitives, stats;
    TessellationStats tessellation;
};

StageOutput tessellateAndMeasure(unsigned threads, double bound)
{
    Scene scene = multiMeshScene();
    std::vector<std::string> lines;
    Log log;
    log.info = [&](const std::string& s) { lines.push_back(s); };
    StageOutput out;
    out.tessellation = tessellateMeshes(scene, bounds(scene, bound), unitScales(scene), log, threads);
    computeTriangleStats(scene, threads);
    out.positions = bytesOf(scene.vertices.positions);
    out.normals = bytesOf(scene.vertices.normals);
    out.uvs = bytesOf(scene.vertices.uvs);
    out.indices = bytesOf(scene.indices);
    out.primitives = bytesOf(scene.primitives);
    out.stats = bytesOf(scene.triangleStats);
    return out;
}

TEST(BakeThreads, TessellationAndStatisticsAreTheSameBytesForAnyThreadCount)
{
    for (double bound : {0.35, 1.0}) {
        const StageOutput serial = tessellateAndMeasure(1, bound);
        ASSERT_GT(serial.tessellation.trianglesSplit, 100u) << "bound " << bound;
        ASSERT_GT(serial.tessellation.trianglesOut, serial.tessellation.trianglesIn + 2000) << "bound " << bound;
        for (unsigned threads : {2u, 3u, 8u}) {
            SCOPED_TRACE("bound " + std::to_string(bound) + ", " + std::to_string(threads) + " threads");
            const StageOutput parallel = tessellateAndMeasure(threads, bound);
            EXPECT_TRUE(parallel.positions == serial.positions);
            EXPECT_TRUE(parallel.normals == serial.normals);
            EXPECT_TRUE(parallel.uvs == serial.uvs);
            EXPECT_TRUE(parallel.indices == serial.indices);
            EXPECT_TRUE(parallel.primitives == serial.primitives);
            EXPECT_TRUE(parallel.stats == serial.stats);
            // The report's figures too (sums are taken in mesh order).
            EXPECT_EQ(parallel.tessellation.trianglesOut, serial.tessellation.trianglesOut);
            EXPECT_EQ(parallel.tessellation.trianglesSplit, serial.tessellation.trianglesSplit);
            EXPECT_EQ(parallel.tessellation.maxEdgeWorldAfter, serial.tessellation.maxEdgeWorldAfter);
            EXPECT_EQ(parallel.tessellation.meanEdgeWorldAfter, serial.tessellation.meanEdgeWorldAfter);
            EXPECT_EQ(parallel.tessellation.meanPieceEdgeWorld, serial.tessellation.meanPieceEdgeWorld);
        }
    }
}

TEST(BakeThreads, MeshesSharingVerticesAreCutAlikeWithThreads)
{
    // Grid 0 and the mesh sharing its vertices (tessellated side by side, each with its
    // own weld table) cut the same edges the same way.
    Scene scene = multiMeshScene();
    tessellateMeshes(scene, bounds(scene, 0.35), unitScales(scene), Log{}, 4);
    EXPECT_EQ(countBoundaryEdges(scene, 0), countBoundaryEdges(scene, uint32_t(scene.meshes.size() - 1)));
}

TEST(BakeThreads, StatisticsOverManyRangesMatchTheSerialOnes)
{
    // More triangles than one work range (65536), split unevenly between primitives.
    Scene scene = multiMeshScene();
    addGrid(scene, 300, 0.05f, glm::vec3(0.0f, -20.0f, 0.0f), 7, 1);
    ASSERT_GT(scene.triangleCount(), size_t(2) << 16);
    Scene serial = scene;
    computeTriangleStats(serial, 1);
    for (unsigned threads : {2u, 3u, 5u}) {
        Scene parallel = scene;
        computeTriangleStats(parallel, threads);
        EXPECT_TRUE(bytesOf(parallel.triangleStats) == bytesOf(serial.triangleStats)) << threads << " threads";
    }

    // Two bad indices in different ranges: the first one is reported, as in a serial loop.
    const auto vertices = uint32_t(scene.vertices.size());
    scene.indices[3 * 150000 + 1] = vertices + 7;
    scene.indices[3 * 10 + 2] = vertices + 3;
    for (unsigned threads : {1u, 2u, 5u}) {
        Scene bad = scene;
        std::string message;
        try {
            computeTriangleStats(bad, threads);
        } catch (const BakeError& e) {
            message = e.what();
        }
        EXPECT_EQ(message, "triangle stats: vertex index " + std::to_string(vertices + 3) + " out of range (" +
                               std::to_string(vertices) + " vertices)")
            << threads << " threads";
    }
}

TEST(BakeThreads, TriangleLimitRefusalIsTheSameForAnyThreadCount)
{
    // Scenes that would exceed 2^28 triangles are refused with one message, whichever mesh
    // (and thread) gets there first. Meshes 1 and 3 are refused on their first face (an edge
    // of 2^17 bounds: 2^14 pieces, the most an edge gets, so about 2^28 pieces); the others
    // are cut into a few pieces each, and stop or finish.
    Scene input = multiMeshScene();
    const double bound = std::ldexp(1.0, -17);
    std::vector<double> maxEdge(input.meshes.size(), 0.5);
    for (uint32_t refused : {1u, 3u}) {
        const uint32_t first = input.primitives[input.meshes[refused].firstPrimitive].firstIndex;
        const glm::vec3 a = input.vertices.positions[input.indices[first]];
        for (uint32_t k = 1; k < 3; ++k) // an edge of exactly 1 unit from the first corner
            input.vertices.positions[input.indices[first + k]] = a + glm::vec3(k == 1 ? 1.0f : 0.0f, k == 2 ? 1.0f : 0.0f, 0.0f);
        maxEdge[refused] = bound;
    }
    for (unsigned threads : {1u, 2u, 4u}) {
        Scene scene = input;
        std::string message;
        try {
            tessellateMeshes(scene, maxEdge, unitScales(scene), Log{}, threads);
        } catch (const BakeError& e) {
            message = e.what();
        }
        EXPECT_EQ(message, "tessellation: the scene would exceed 268435456 (2^28) triangles at this edge bound; "
                           "raise the bound")
            << threads << " threads";
        EXPECT_TRUE(bytesOf(scene.vertices.positions) == bytesOf(input.vertices.positions))
            << "the scene must be left as it was";
        EXPECT_TRUE(bytesOf(scene.indices) == bytesOf(input.indices));
    }
}

// ---- lfd-bake --threads -------------------------------------------------------------------

using lfd::test::kBake;
using lfd::test::kMakeSamples;
using lfd::test::quoted;
using lfd::test::readBytes;
using lfd::test::run;
using lfd::test::RunResult;
class BakeThreadsCli : public ::testing::Test {
protected:
    static void SetUpTestSuite()
    {
        dir_ = fs::temp_directory_path() / ("lfd_bake_threads_" + std::to_string(::getpid()));
        fs::create_directories(dir_);
        const RunResult r =
            run(kMakeSamples + " " + quoted(dir_ / "samples") + " --scene all --texture-size 512 --quiet");
        ASSERT_EQ(r.exitCode, 0) << r.out;
    }
    static void TearDownTestSuite() { fs::remove_all(dir_); }

    // Bakes `input` with 1, 2 and 3 threads and expects three identical packs; returns the
    // report of the 2-thread bake.
    static std::string expectIdenticalPacks(const fs::path& input, const std::string& options)
    {
        std::string bytes[3], report;
        for (unsigned threads = 1; threads <= 3; ++threads) {
            const fs::path pack = dir_ / (input.stem().string() + "_t" + std::to_string(threads) + ".lfdpack");
            const RunResult r = run(kBake + " " + quoted(input) + " -o " + quoted(pack) + " " + options +
                                    " --threads " + std::to_string(threads));
            EXPECT_EQ(r.exitCode, 0) << r.out;
            bytes[threads - 1] = readBytes(pack);
            if (threads == 2)
                report = r.out;
        }
        EXPECT_FALSE(bytes[0].empty()) << input;
        EXPECT_TRUE(bytes[0] == bytes[1]) << input << ": --threads 1 and 2 differ";
        EXPECT_TRUE(bytes[0] == bytes[2]) << input << ": --threads 1 and 3 differ";
        return report;
    }

    static fs::path dir_;
};
fs::path BakeThreadsCli::dir_;

TEST_F(BakeThreadsCli, GalleryPackIsByteIdenticalForOneTwoAndThreeThreads)
{
    // Five textures (sRGB and linear, reduced and not), several meshes, many cut faces.
    const std::string report = expectIdenticalPacks(dir_ / "samples/gallery/gallery.gltf", "--max-edge-px 15");
    EXPECT_NE(report.find("(2 threads)"), std::string::npos) << report;
}

TEST_F(BakeThreadsCli, CarAndRoomPacksAreByteIdenticalForOneTwoAndThreeThreads)
{
    // Many meshes and instances, node animation; the car cut finely.
    expectIdenticalPacks(dir_ / "samples/car/car.gltf", "--max-edge-px 12 --quiet");
    expectIdenticalPacks(dir_ / "samples/room/room.gltf", "--max-edge-px 25 --quiet");
}

TEST_F(BakeThreadsCli, ThirdPartyPacksAreByteIdenticalForOneTwoAndThreeThreads)
{
    const fs::path scenes = LFD_SHARED_SCENES;
    if (!fs::exists(scenes))
        LFD_SKIP_OR_FAIL("no third-party scenes at " << scenes);
    // Five 2048² JPEG textures on one mesh (reduced, to keep the test short); one PNG
    // texture on several meshes.
    expectIdenticalPacks(scenes / "DamagedHelmet/DamagedHelmet.gltf", "--max-edge-px 20 --max-texture-size 1024 --quiet");
    expectIdenticalPacks(scenes / "CesiumMilkTruck/CesiumMilkTruck.gltf", "--max-edge-px 15 --quiet");
}

TEST_F(BakeThreadsCli, BadThreadCountsAreRejected)
{
    const std::string bake = kBake + " " + quoted(dir_ / "samples/car/car.gltf") + " -o " + quoted(dir_ / "x.lfdpack");
    for (const char* bad : {"-1", "two", "100000"}) {
        const RunResult r = run(bake + " --threads " + bad);
        EXPECT_NE(r.exitCode, 0) << bad << ": " << r.out;
        EXPECT_NE(r.out.find("--threads"), std::string::npos) << r.out;
    }
    EXPECT_FALSE(fs::exists(dir_ / "x.lfdpack"));
}

} // namespace
} // namespace lfd::bake
