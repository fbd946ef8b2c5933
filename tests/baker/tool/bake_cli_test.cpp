// End-to-end tests of the lfd-bake command line: bake the project's samples (and the
// third-party scenes when ../shared/scenes exists), verify with --inspect, check the
// tessellation bound on the written pack, and check bad inputs fail cleanly.
#include "texture_compression.h"

#include "lfd/pack.h"

#include "skip_or_fail.h"

#include "tool_run.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

namespace fs = std::filesystem;

namespace {

using lfd::test::kBake;
using lfd::test::kMakeSamples;
using lfd::test::quoted;
using lfd::test::readBytes;
using lfd::test::run;
using lfd::test::RunResult;
using lfd::test::lineCount;

class BakeCli : public ::testing::Test {
protected:
    static void SetUpTestSuite()
    {
        dir_ = fs::temp_directory_path() / ("lfd_bake_cli_" + std::to_string(::getpid()));
        fs::create_directories(dir_);
        const RunResult r = run(kMakeSamples + " " + quoted(dir_ / "samples") + " --scene all --texture-size 256 --quiet");
        ASSERT_EQ(r.exitCode, 0) << r.out;
    }
    static void TearDownTestSuite() { fs::remove_all(dir_); }
    static fs::path dir_;
};
fs::path BakeCli::dir_;

// Longest edge of any drawn triangle in view pixels, using the bake's own pixel size
// and the node scale (rest pose; the samples' animations are rotations only).
double maxEdgeInViewPixels(const lfd::Scene& scene)
{
    double longest = 0.0;
    for (const lfd::Node& node : scene.nodes) {
        if (node.mesh < 0)
            continue;
        // World scale of the node chain (the samples use uniform or unit scales).
        double scale = 1.0;
        for (int32_t n = int32_t(&node - scene.nodes.data()); n >= 0; n = scene.nodes[size_t(n)].parent)
            scale *= double(glm::max(scene.nodes[size_t(n)].scale.x,
                                     glm::max(scene.nodes[size_t(n)].scale.y, scene.nodes[size_t(n)].scale.z)));
        const lfd::Mesh& mesh = scene.meshes[size_t(node.mesh)];
        for (uint32_t p = mesh.firstPrimitive; p < mesh.firstPrimitive + mesh.primitiveCount; ++p) {
            const lfd::Primitive& prim = scene.primitives[p];
            for (uint32_t i = prim.firstIndex; i < prim.firstIndex + prim.indexCount; i += 3)
                for (int e = 0; e < 3; ++e) {
                    const glm::vec3 a = scene.vertices.positions[scene.indices[i + e]];
                    const glm::vec3 b = scene.vertices.positions[scene.indices[i + (e + 1) % 3]];
                    longest = std::max(longest, double(glm::length(a - b)) * scale);
                }
        }
    }
    return longest / double(scene.settings.viewPixelWorld);
}

TEST_F(BakeCli, BakesCarSampleWithinEdgeBoundAndStoresNoUvs)
{
    const fs::path pack = dir_ / "car.lfdpack";
    const RunResult r = run(kBake + " " + quoted(dir_ / "samples/car/car.gltf") + " -o " + quoted(pack));
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_NE(r.out.find("bake report"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("triangles:"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("peak memory"), std::string::npos) << r.out;

    const lfd::Scene scene = lfd::readPack(pack);
    EXPECT_TRUE(scene.vertices.uvs.empty()) << "untextured scene must not store uvs";
    EXPECT_TRUE(scene.vertices.tangents.empty());
    EXPECT_TRUE(scene.textures.empty());
    EXPECT_FALSE(scene.animations.empty()) << "wheel animation must survive the bake";
    EXPECT_GT(scene.settings.viewPixelWorld, 0.0f);
    EXPECT_LE(maxEdgeInViewPixels(scene), 100.0 * 1.0001);
    for (const lfd::TriangleStats& s : scene.triangleStats)
        EXPECT_FALSE(s.flags & lfd::kTriangleTextured);

    const RunResult inspect = run(kBake + " --inspect " + quoted(pack));
    EXPECT_EQ(inspect.exitCode, 0) << inspect.out;
    EXPECT_NE(inspect.out.find("verified"), std::string::npos) << inspect.out;
}

TEST_F(BakeCli, BakesGallerySampleWithTexturesAndTighterBound)
{
    const fs::path pack = dir_ / "gallery.lfdpack";
    const RunResult r = run(kBake + " " + quoted(dir_ / "samples/gallery/gallery.gltf") + " -o " + quoted(pack) +
                            " --max-edge-px 50 --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_EQ(r.out.find("import:"), std::string::npos) << "--quiet must hide progress: " << r.out;

    const lfd::Scene scene = lfd::readPack(pack);
    EXPECT_FALSE(scene.vertices.uvs.empty());
    EXPECT_FALSE(scene.vertices.tangents.empty()) << "gallery has a normal map";
    ASSERT_FALSE(scene.textures.empty());
    for (const lfd::Texture& t : scene.textures) {
        EXPECT_GT(t.width, 0u);
        EXPECT_EQ(t.mips.back().width, 1u);
        EXPECT_EQ(t.mips.back().height, 1u);
    }
    EXPECT_LE(maxEdgeInViewPixels(scene), 50.0 * 1.0001);
    size_t textured = 0;
    for (const lfd::TriangleStats& s : scene.triangleStats) {
        if (s.flags & lfd::kTriangleTextured) {
            ++textured;
            EXPECT_GT(s.texelCount, 0.0f);
            EXPECT_GT(s.sizeUv, 0.0f);
        }
    }
    EXPECT_GT(textured, 0u);
}

TEST_F(BakeCli, MissingInputFailsWithOneLineNamingTheFile)
{
    const fs::path pack = dir_ / "missing.lfdpack";
    const RunResult r = run(kBake + " " + quoted(dir_ / "does_not_exist.gltf") + " -o " + quoted(pack));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_EQ(lineCount(r.out), 1u) << r.out;
    EXPECT_NE(r.out.find("does_not_exist.gltf"), std::string::npos) << r.out;
    EXPECT_FALSE(fs::exists(pack));
}

TEST_F(BakeCli, MalformedGltfFailsAndLeavesExistingOutputIntact)
{
    const fs::path bad = dir_ / "malformed.gltf";
    std::ofstream(bad) << "{ \"asset\": { \"version\": \"2.0\" }, \"meshes\": [ { ";
    const fs::path pack = dir_ / "existing.lfdpack";
    std::ofstream(pack) << "previous contents";
    const RunResult r = run(kBake + " " + quoted(bad) + " -o " + quoted(pack) + " --quiet");
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.out.find("malformed.gltf"), std::string::npos) << r.out;
    std::ifstream in(pack);
    std::string contents((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(contents, "previous contents");
}

TEST_F(BakeCli, MissingTextureFailsWithoutPartialPack)
{
    // Copy the gallery next to a new name and delete one of its images.
    const fs::path copy = dir_ / "gallery_broken";
    fs::copy(dir_ / "samples/gallery", copy, fs::copy_options::recursive);
    fs::path removed;
    for (const auto& entry : fs::directory_iterator(copy))
        if (entry.path().extension() == ".png") {
            removed = entry.path();
            break;
        }
    ASSERT_FALSE(removed.empty());
    fs::remove(removed);
    const fs::path pack = dir_ / "broken.lfdpack";
    const RunResult r = run(kBake + " " + quoted(copy / "gallery.gltf") + " -o " + quoted(pack) + " --quiet");
    EXPECT_NE(r.exitCode, 0) << r.out;
    EXPECT_NE(r.out.find(removed.filename().string()), std::string::npos) << r.out;
    EXPECT_FALSE(fs::exists(pack));
    for (const auto& entry : fs::directory_iterator(dir_))
        EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos) << "temp file left: " << entry.path();
}

TEST_F(BakeCli, InspectRejectsCorruptPack)
{
    const fs::path pack = dir_ / "corrupt.lfdpack";
    ASSERT_EQ(run(kBake + " " + quoted(dir_ / "samples/car/car.gltf") + " -o " + quoted(pack) + " --quiet").exitCode, 0);
    {
        std::fstream f(pack, std::ios::in | std::ios::out | std::ios::binary);
        f.seekp(std::streamoff(fs::file_size(pack) / 2));
        const char garbage = char(0xA5);
        f.write(&garbage, 1);
    }
    const RunResult r = run(kBake + " --inspect " + quoted(pack));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_EQ(lineCount(r.out), 1u) << r.out;
    EXPECT_NE(r.out.find("corrupt.lfdpack"), std::string::npos) << r.out;

    fs::resize_file(pack, 100);
    const RunResult t = run(kBake + " --inspect " + quoted(pack));
    EXPECT_NE(t.exitCode, 0);
    EXPECT_EQ(lineCount(t.out), 1u) << t.out;
}

// The gallery's materials read colour, a normal map and roughness-metallic: the default
// bake block-compresses each by its use and reports format, bytes and PSNR; `none`
// keeps RGBA8 (zstd levels), several times the texel bytes.
TEST_F(BakeCli, TexturesAreBlockCompressedByUseUnlessAskedNotTo)
{
    const fs::path bc = dir_ / "gallery_bc.lfdpack", none = dir_ / "gallery_none.lfdpack";
    const RunResult r = run(kBake + " " + quoted(dir_ / "samples/gallery/gallery.gltf") + " -o " + quoted(bc));
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_TRUE(std::regex_search(r.out, std::regex(R"(\(sRGB\): \d+x\d+[^\n]*, BC1 [0-9.]+ [KM]iB, PSNR [0-9.]+ dB)")))
        << r.out;
    EXPECT_NE(r.out.find(", BC5 "), std::string::npos) << r.out;
    const RunResult n = run(kBake + " " + quoted(dir_ / "samples/gallery/gallery.gltf") + " -o " + quoted(none) +
                            " --texture-compression none --quiet");
    ASSERT_EQ(n.exitCode, 0) << n.out;

    const lfd::Scene blocks = lfd::readPack(bc), rgba8 = lfd::readPack(none);
    ASSERT_EQ(blocks.textures.size(), rgba8.textures.size());
    const std::vector<uint32_t> uses = lfd::bake::textureUses(blocks);
    uint64_t blockBytes = 0, rgbaBytes = 0;
    for (size_t t = 0; t < blocks.textures.size(); ++t) {
        EXPECT_EQ(rgba8.textures[t].format, lfd::TextureFormat::Rgba8);
        EXPECT_EQ(blocks.textures[t].format, lfd::bake::chooseTextureFormat(uses[t], true)) << "texture " << t;
        EXPECT_NE(blocks.textures[t].format, lfd::TextureFormat::Rgba8);
        blockBytes += blocks.textures[t].texels.size();
        rgbaBytes += rgba8.textures[t].texels.size();
    }
    EXPECT_LE(blockBytes * 4, rgbaBytes);
    // (The files: the samples' procedural textures are so regular that zstd shrinks the
    // RGBA8 levels about as small as the blocks; see docs/baker/texture-compression.md.)

    const RunResult inspect = run(kBake + " --inspect " + quoted(bc));
    EXPECT_EQ(inspect.exitCode, 0) << inspect.out;
    EXPECT_NE(inspect.out.find(" BC5, "), std::string::npos) << inspect.out;
    EXPECT_NE(inspect.out.find("zstd"), std::string::npos) << "geometry sections are zstd-compressed: " << inspect.out;

    const RunResult bad = run(kBake + " " + quoted(dir_ / "samples/gallery/gallery.gltf") + " -o " +
                              quoted(dir_ / "x.lfdpack") + " --texture-compression bc7");
    EXPECT_NE(bad.exitCode, 0);
    EXPECT_NE(bad.out.find("--texture-compression"), std::string::npos) << bad.out;
}

TEST_F(BakeCli, BadArgumentsAreRejected)
{
    EXPECT_NE(run(kBake).exitCode, 0);
    EXPECT_NE(run(kBake + " " + quoted(dir_ / "samples/car/car.gltf") + " -o x.lfdpack --max-edge-px 0").exitCode, 0);
    const RunResult r = run(kBake + " " + quoted(dir_ / "samples/car/car.gltf") + " -o " + quoted(dir_ / "p.lfdpack") +
                            " --display " + quoted(dir_ / "no_profile.json"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.out.find("no_profile.json"), std::string::npos) << r.out;
}

TEST_F(BakeCli, BadSimplifyBoundsAreRejectedWithOneLineNamingTheFlag)
{
    const std::string bake = kBake + " " + quoted(dir_ / "samples/car/car.gltf") + " -o " + quoted(dir_ / "s.lfdpack");
    for (const char* bad : {"-1", "nan", "inf", "abc", "0.5px"}) {
        const RunResult r = run(bake + " --simplify " + bad);
        EXPECT_EQ(r.exitCode, 2) << bad << ": " << r.out;
        EXPECT_NE(r.out.find("--simplify"), std::string::npos) << r.out;
        EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
    }
    EXPECT_FALSE(fs::exists(dir_ / "s.lfdpack"));
    // 0 turns the stage off; the report says so.
    const RunResult off = run(bake + " --simplify 0");
    EXPECT_EQ(off.exitCode, 0) << off.out;
    EXPECT_NE(off.out.find("simplification: off"), std::string::npos) << off.out;
    const RunResult on = run(bake + " --simplify 2");
    EXPECT_EQ(on.exitCode, 0) << on.out;
    EXPECT_NE(on.out.find("simplification (bound 2"), std::string::npos) << on.out;
}

const fs::path kGltfCases = fs::path(LFD_TEST_DATA) / "gltf";

TEST_F(BakeCli, SchemaErrorIsRefusedWithOneLineNamingFileAndJsonPath)
{
    const fs::path input = kGltfCases / "schema_error.gltf";
    const fs::path pack = dir_ / "schema_error.lfdpack";
    const RunResult r = run(kBake + " " + quoted(input) + " -o " + quoted(pack));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(r.out, "lfd-bake: error: " + input.string() +
                         ": materials[0].pbrMetallicRoughness: expected an object, got an array\n");
    EXPECT_FALSE(fs::exists(pack));
}

TEST_F(BakeCli, StrictTurnsSchemaWarningsIntoErrors)
{
    const fs::path input = kGltfCases / "schema_warnings.gltf";
    const fs::path pack = dir_ / "schema_warnings.lfdpack";
    const RunResult lenient = run(kBake + " " + quoted(input) + " -o " + quoted(pack) + " --quiet");
    EXPECT_EQ(lenient.exitCode, 0) << lenient.out;
    EXPECT_EQ(lenient.out, "lfd-bake: warning: " + input.string() + ": nodes[0].name: expected a string, got 7: name ignored\n" +
                               "lfd-bake: warning: " + input.string() +
                               ": materials[0].pbrMetallicRoughness.metallicFactor: 1.5 is outside [0.0, 1.0]: clamped\n");
    EXPECT_EQ(lfd::readPack(pack).materials.at(0).metallicFactor, 1.0f);

    fs::remove(pack);
    const RunResult strict = run(kBake + " " + quoted(input) + " -o " + quoted(pack) + " --strict");
    EXPECT_EQ(strict.exitCode, 1);
    EXPECT_EQ(strict.out, "lfd-bake: error: " + input.string() +
                              ": nodes[0].name: expected a string, got 7: name ignored (--strict)\n");
    EXPECT_FALSE(fs::exists(pack));
}

TEST_F(BakeCli, QuietPrintsWarningsAndErrorsOnly)
{
    const fs::path pack = dir_ / "quiet.lfdpack";
    const RunResult clean = run(kBake + " " + quoted(dir_ / "samples/car/car.gltf") + " -o " + quoted(pack) + " --quiet");
    EXPECT_EQ(clean.exitCode, 0) << clean.out;
    EXPECT_EQ(clean.out, ""); // no progress, no bake report
    EXPECT_TRUE(fs::exists(pack));

    const RunResult loud = run(kBake + " " + quoted(dir_ / "samples/car/car.gltf") + " -o " + quoted(pack));
    EXPECT_NE(loud.out.find("bake report"), std::string::npos) << loud.out;
}

TEST_F(BakeCli, BakingTwiceGivesByteIdenticalPacks)
{
    // Every sample scene (textures, animation, hierarchy): same input, same bytes.
    size_t baked = 0;
    for (const auto& entry : fs::directory_iterator(dir_ / "samples")) {
        const std::string name = entry.path().filename().string();
        const fs::path input = entry.path() / (name + ".gltf");
        if (!fs::exists(input))
            continue;
        SCOPED_TRACE(name);
        std::string bytes[2];
        for (int i = 0; i < 2; ++i) {
            const fs::path pack = dir_ / (name + "_det" + std::to_string(i) + ".lfdpack");
            const RunResult r = run(kBake + " " + quoted(input) + " -o " + quoted(pack) + " --quiet");
            ASSERT_EQ(r.exitCode, 0) << r.out;
            bytes[i] = readBytes(pack);
        }
        EXPECT_FALSE(bytes[0].empty());
        EXPECT_TRUE(bytes[0] == bytes[1]) << "two bakes of " << name << " differ";
        ++baked;
    }
    EXPECT_GE(baked, 3u);
}

// The pack keeps lights, unlit materials and texture transforms, and both reports name them.
TEST_F(BakeCli, BakesLightsUnlitMaterialsAndTextureTransforms)
{
    const fs::path input = fs::path(LFD_TEST_DATA) / "gltf" / "materials_and_lights.gltf";
    const fs::path pack = dir_ / "materials_and_lights.lfdpack";
    const RunResult bake = run(kBake + " " + quoted(input) + " -o " + quoted(pack));
    ASSERT_EQ(bake.exitCode, 0) << bake.out;
    const std::string lights = "lights: 4 (1 directional, 1 point, 2 spot; KHR_lights_punctual)";
    const std::string materials =
        "materials: 1 unlit (KHR_materials_unlit), 1 with texture transforms (KHR_texture_transform)";
    EXPECT_NE(bake.out.find("  " + lights + "\n"), std::string::npos) << bake.out;
    EXPECT_NE(bake.out.find("  " + materials + "\n"), std::string::npos) << bake.out;
    EXPECT_NE(bake.out.find("light 0 is on a node outside the imported scene: dropped"), std::string::npos);

    const RunResult inspect = run(kBake + " --inspect " + quoted(pack));
    ASSERT_EQ(inspect.exitCode, 0) << inspect.out;
    EXPECT_NE(inspect.out.find("  " + lights + "\n"), std::string::npos) << inspect.out;
    EXPECT_NE(inspect.out.find("  " + materials + "\n"), std::string::npos) << inspect.out;
    EXPECT_NE(inspect.out.find("MEXT"), std::string::npos) << inspect.out;
    EXPECT_NE(inspect.out.find("LGHT"), std::string::npos) << inspect.out;

    const lfd::Scene scene = lfd::readPack(pack);
    ASSERT_EQ(scene.lights.size(), 4u);
    EXPECT_TRUE(scene.materials[1].unlit);
    EXPECT_NEAR(scene.materials[0].transform(lfd::TextureSlot::BaseColor).areaScale(), 8.0f, 1e-5f);

    // A scene without them: no such lines, no such sections.
    const fs::path car = dir_ / "car_plain.lfdpack";
    ASSERT_EQ(run(kBake + " " + quoted(dir_ / "samples" / "car" / "car.gltf") + " -o " + quoted(car) + " --quiet").exitCode,
              0);
    const RunResult plain = run(kBake + " --inspect " + quoted(car));
    EXPECT_EQ(plain.out.find("lights:"), std::string::npos) << plain.out;
    EXPECT_EQ(plain.out.find("materials:"), std::string::npos) << plain.out;
    EXPECT_EQ(plain.out.find("MEXT"), std::string::npos) << plain.out;
}

TEST_F(BakeCli, BakesThirdPartyScenes)
{
    const fs::path scenes = LFD_SHARED_SCENES;
    if (!fs::exists(scenes))
        LFD_SKIP_OR_FAIL("no third-party scenes at " << scenes);
    for (const char* name : {"CesiumMilkTruck", "DamagedHelmet"}) {
        const fs::path input = scenes / name / (std::string(name) + ".gltf");
        if (!fs::exists(input))
            continue;
        const fs::path pack = dir_ / (std::string(name) + ".lfdpack");
        const RunResult r = run(kBake + " " + quoted(input) + " -o " + quoted(pack) + " --quiet");
        ASSERT_EQ(r.exitCode, 0) << name << ": " << r.out;
        const lfd::Scene scene = lfd::readPack(pack);
        EXPECT_FALSE(scene.textures.empty()) << name;
        EXPECT_EQ(scene.triangleStats.size(), scene.triangleCount()) << name;
        EXPECT_EQ(run(kBake + " --inspect " + quoted(pack)).exitCode, 0) << name;
    }
}

} // namespace

namespace {

// A bake killed with SIGKILL (no handler runs, no temporary is removed) at any moment never
// leaves a corrupt pack: the output is either the previous pack, byte for byte, or the
// complete new one; and the bake can be re-run. Killed at several moments of a finely cut
// gallery bake (import, tessellation, textures, the write), whichever each lands in.
TEST_F(BakeCli, KilledBakeLeavesThePreviousPackAndCanBeRerun)
{
    const fs::path pack = dir_ / "killed.lfdpack";
    ASSERT_EQ(run(kBake + " " + quoted(dir_ / "samples/car/car.gltf") + " -o " + quoted(pack) + " --quiet").exitCode, 0);
    const std::string previous = readBytes(pack);
    const std::string bake = kBake + " " + quoted(dir_ / "samples/gallery/gallery.gltf") + " -o " + quoted(pack) +
                             " --max-edge-px 6 --quiet";
    for (const char* delay : {"0.2", "0.8", "1.5", "3"}) {
        SCOPED_TRACE(std::string("killed after ") + delay + " s");
        const std::string command = "(" + bake + " > /dev/null 2>&1 & pid=$!; sleep " + delay +
                                    "; kill -9 $pid 2>/dev/null; wait $pid) 2>/dev/null";
        EXPECT_NE(std::system(command.c_str()), -1);
        const std::string now = readBytes(pack);
        if (now != previous) {
            // The bake finished before the kill: then the pack is whole.
            EXPECT_NO_THROW(lfd::verifyPack(pack)) << "a killed bake left a corrupt pack";
        }
    }
    // Stale temporaries (`<pack>.tmp.<pid>`) may be left by SIGKILL; none is ever the pack.
    const RunResult again = run(bake);
    ASSERT_EQ(again.exitCode, 0) << again.out;
    EXPECT_NO_THROW(lfd::verifyPack(pack));
    EXPECT_NE(readBytes(pack), previous);
    for (const auto& entry : fs::directory_iterator(dir_))
        if (entry.path().filename().string().starts_with("killed.lfdpack.tmp."))
            fs::remove(entry.path());
}

} // namespace
