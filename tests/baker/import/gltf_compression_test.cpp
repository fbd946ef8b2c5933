// Compressed glTF as pipelines ship it (docs/baker/gltf-extensions.md): the gallery sample run
// through gltf-transform (tests/data/gltf_compressed/make_fixtures.sh) - Draco, meshopt,
// WebP, quantize - imports like the uncompressed gallery.glb; corrupt or truncated streams
// (the fixtures patched here) are refused with one line naming the primitive or buffer
// view; the hand-made cases of tests/data/gltf cover the WebP fallback, KTX2 and quantised
// normals.
#include "bake_log.h"
#include "imported_scene.h"
#include "gltf_findings.h"
#include "gltf_import.h"
#include "import_test_cases.h"
#include "texture_bake.h"
#include "gltf_test_files.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <lfd/scene_animation.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace fs = std::filesystem;
using lfd::bake::BakeError;
using lfd::bake::ImportedScene;
using lfd::test::hasWarning;
using lfd::test::kGltfCases;
using lfd::test::IssueCode;
using nlohmann::json;

namespace {

const fs::path kFixtures = fs::path(LFD_TEST_DATA) / "gltf_compressed";

ImportedScene importCompressed(const fs::path& path, unsigned threads = 0)
{
    return lfd::bake::importGltf(path, lfd::bake::Log{}, threads);
}

// lfd-bake --strict: any warning refuses the file.
ImportedScene importStrict(const fs::path& path)
{
    lfd::bake::Log strict;
    strict.warn = [](const std::string& w) { throw BakeError("warning under --strict: " + w); };
    return lfd::bake::importGltf(path, strict);
}

// Every triangle corner in scene space (node transforms applied at time 0), in scene order.
std::vector<glm::vec3> worldCorners(const lfd::Scene& s)
{
    const std::vector<glm::mat4> world = lfd::nodeWorldMatrices(s, 0.0f);
    std::vector<glm::vec3> out;
    for (size_t n = 0; n < s.nodes.size(); ++n) {
        if (s.nodes[n].mesh == lfd::kNone)
            continue;
        const lfd::Mesh& mesh = s.meshes[size_t(s.nodes[n].mesh)];
        for (uint32_t p = mesh.firstPrimitive; p < mesh.firstPrimitive + mesh.primitiveCount; ++p)
            for (uint32_t i = 0; i < s.primitives[p].indexCount; ++i)
                out.push_back(glm::vec3(world[n] * glm::vec4(s.vertices.positions[s.indices[s.primitives[p].firstIndex + i]], 1.0f)));
    }
    return out;
}

// The largest distance from a point of `a` to the nearest point of `b` (the decoders may
// reorder vertices and triangles, so points are matched by position). Exact: `b` sorted by
// x, each search walks out from p.x until the x gap alone exceeds the nearest distance.
float farthestFromNearest(const std::vector<glm::vec3>& a, std::vector<glm::vec3> b)
{
    const auto byX = [](const glm::vec3& u, const glm::vec3& v) { return u.x < v.x; };
    std::sort(b.begin(), b.end(), byX);
    float worst = 0.0f;
    for (const glm::vec3& p : a) {
        float nearest = std::numeric_limits<float>::max();
        const auto start = std::lower_bound(b.begin(), b.end(), p, byX);
        for (auto q = start; q != b.end() && q->x - p.x < nearest; ++q)
            nearest = std::min(nearest, glm::length(p - *q));
        for (auto q = start; q != b.begin() && p.x - std::prev(q)->x < nearest; --q)
            nearest = std::min(nearest, glm::length(p - *std::prev(q)));
        worst = std::max(worst, nearest);
    }
    return worst;
}

// The compressed scene is the reference's geometry: as many triangles drawn by the same
// nodes, every corner within `tolerance` of one of the other's (both ways), the same
// materials and textures.
void expectSameScene(const ImportedScene& reference, const ImportedScene& test, float tolerance)
{
    EXPECT_EQ(test.sourceTriangles, reference.sourceTriangles);
    EXPECT_EQ(test.scene.nodes.size(), reference.scene.nodes.size());
    EXPECT_EQ(test.scene.materials.size(), reference.scene.materials.size());
    ASSERT_EQ(test.scene.textures.size(), reference.scene.textures.size());
    const std::vector<glm::vec3> a = worldCorners(reference.scene), b = worldCorners(test.scene);
    ASSERT_EQ(a.size(), b.size());
    EXPECT_LE(farthestFromNearest(a, b), tolerance);
    EXPECT_LE(farthestFromNearest(b, a), tolerance);
    // Normals stay unit vectors after the decoders' quantisation (renormalised on import).
    for (const glm::vec3& n : test.scene.vertices.normals)
        ASSERT_NEAR(glm::length(n), 1.0f, 1e-5f);
}

// gltf-transform's default position grid: 14 bits over each mesh's bounds (draco,
// meshopt and quantize all default to --quantize-position 14; Draco's grid is uniform over
// the largest extent). The gallery's largest mesh spans 8 units on an axis, so a corner
// moves by at most half a step, 8 / 16383 / 2 = 2.44e-4, per axis: 4.23e-4 in space
// (measured: 2.7e-4 Draco, 3.4e-4 meshopt and quantize).
constexpr float kGridTolerance = 4.3e-4f;

class GltfCompression : public lfd::test::GltfCaseFiles {
protected:
    GltfCompression() : GltfCaseFiles("lfd_gltf_compression_test") {}

    static const ImportedScene& reference()
    {
        static const ImportedScene r = importCompressed(kFixtures / "gallery.glb");
        return r;
    }

    // The fixture `name` after `change` edited its JSON and BIN chunk, as a new file.
    template <class Change>
    fs::path patched(const char* name, Change change)
    {
        lfd::test::GlbParts parts = lfd::test::readGlb(kFixtures / name);
        change(parts.doc, parts.bin);
        return writeBytes(lfd::test::glbOf(parts), ".glb");
    }

    // Refused with one line "<file>: <path>: ...", whose finding is `code` (gltf_issue_codes.h).
    static void expectRefused(const fs::path& file, IssueCode code, const std::string& path)
    {
        lfd::test::expectRefusedWith(file, code, path);
        expectRefused(file, path, "");
    }

    // Refused with one line "<file>: <path>: ...<part>..." (the importer's own refusals).
    static void expectRefused(const fs::path& file, const std::string& path, const std::string& part)
    {
        try {
            importCompressed(file);
            ADD_FAILURE() << "accepted, expected " << path << ": ..." << part;
        } catch (const BakeError& e) {
            const std::string what = e.what();
            EXPECT_EQ(what.rfind(file.string() + ": " + path + ": ", 0), 0u) << what;
            EXPECT_NE(what.find(part), std::string::npos) << what;
            EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        }
    }
};

// ---- Geometry: Draco, meshopt, quantize --------------------------------------------

TEST_F(GltfCompression, DracoImportsLikeTheUncompressedScene)
{
    const ImportedScene draco = importStrict(kFixtures / "gallery-draco.glb");
    expectSameScene(reference(), draco, kGridTolerance);
    // Draco keeps the vertices (a welded seam would change the count).
    EXPECT_EQ(draco.scene.vertices.size(), reference().scene.vertices.size());
}

TEST_F(GltfCompression, MeshoptImportsLikeTheUncompressedScene)
{
    // EXT_meshopt_compression over KHR_mesh_quantization: 8-bit octahedral normals,
    // quaternion-free here; the fallback buffer has no uri.
    const ImportedScene meshopt = importStrict(kFixtures / "gallery-meshopt.glb");
    expectSameScene(reference(), meshopt, kGridTolerance);
}

TEST_F(GltfCompression, QuantizedSceneBakesUnderStrict)
{
    // gltf-transform quantize writes 10-bit normals into SHORT: their lengths are off 1 by
    // up to ~1e-3, which used to warn for every NORMAL and TANGENT accessor.
    const ImportedScene quantized = importStrict(kFixtures / "gallery-quantize.glb");
    expectSameScene(reference(), quantized, kGridTolerance);
}

TEST_F(GltfCompression, KhrMeshoptCompressionReadsAsTheExtPrefix)
{
    // KHR_meshopt_compression has EXT_meshopt_compression's JSON; its version-0 streams
    // decode alike.
    const fs::path khr = patched("gallery-meshopt.glb", [](json& doc, std::vector<uint8_t>&) {
        for (const char* list : {"extensionsUsed", "extensionsRequired"})
            for (json& name : doc[list])
                if (name == "EXT_meshopt_compression")
                    name = "KHR_meshopt_compression";
        for (json& view : doc["bufferViews"])
            if (view.contains("extensions")) {
                view["extensions"]["KHR_meshopt_compression"] = view["extensions"]["EXT_meshopt_compression"];
                view["extensions"].erase("EXT_meshopt_compression");
            }
        doc["buffers"][1].erase("extensions");
    });
    expectSameScene(reference(), importCompressed(khr), kGridTolerance);
}

TEST_F(GltfCompression, MeshoptIntegersWrittenAsFloatsAreIntegers)
{
    // JSON has one number type: "count": 4.0 is the integer 4 (the schema check's rule too).
    const fs::path floats = patched("gallery-meshopt.glb", [](json& doc, std::vector<uint8_t>&) {
        for (json& view : doc["bufferViews"])
            if (view.contains("extensions"))
                for (const char* key : {"byteStride", "count", "byteLength", "byteOffset"}) {
                    json& ext = view["extensions"]["EXT_meshopt_compression"];
                    ext[key] = ext.value(key, 0.0) * 1.0;
                }
    });
    expectSameScene(reference(), importCompressed(floats), kGridTolerance);
}

TEST_F(GltfCompression, DecodedSceneDoesNotDependOnTheThreadCount)
{
    for (const char* name : {"gallery-draco.glb", "gallery-meshopt.glb"}) {
        SCOPED_TRACE(name);
        const ImportedScene one = importCompressed(kFixtures / name, 1), three = importCompressed(kFixtures / name, 3);
        EXPECT_EQ(one.scene.indices, three.scene.indices);
        EXPECT_EQ(one.scene.vertices.positions, three.scene.vertices.positions);
        EXPECT_EQ(one.scene.vertices.normals, three.scene.vertices.normals);
        EXPECT_EQ(one.scene.vertices.uvs, three.scene.vertices.uvs);
    }
}

TEST_F(GltfCompression, KhronosDracoSampleOfAssimpTestModelsImports)
{
    // Khronos' 2CylinderEngine, Draco-compressed (Debian assimp-testmodels): 34 primitives
    // of one GLTF with an external .bin.
    const fs::path engine = "/usr/share/assimp/models/glTF2/draco/2CylinderEngine.gltf";
    if (!fs::exists(engine))
        GTEST_SKIP() << engine << " absent (Debian assimp-testmodels): Draco sample skipped";
    const ImportedScene r = importCompressed(engine);
    EXPECT_EQ(r.scene.primitives.size(), 34u);
    EXPECT_EQ(r.sourceTriangles, 65311u);
}

// ---- Corrupt and mismatching streams ------------------------------------------------

// The byte range of buffer view `v` in the BIN chunk.
std::pair<size_t, size_t> viewRange(const json& doc, size_t v)
{
    const json& view = doc["bufferViews"][v];
    return {view.value("byteOffset", size_t(0)), view["byteLength"].get<size_t>()};
}

TEST_F(GltfCompression, CorruptDracoStreamNamesThePrimitiveAndView)
{
    // meshes[0].primitives[0]'s stream is bufferViews[5]: its "DRACO" header overwritten.
    const fs::path corrupt = patched("gallery-draco.glb", [](json& doc, std::vector<uint8_t>& bin) {
        const auto [offset, length] = viewRange(doc, 5);
        std::fill(bin.begin() + std::ptrdiff_t(offset), bin.begin() + std::ptrdiff_t(offset + std::min<size_t>(length, 16)), 0xFF);
    });
    expectRefused(corrupt, IssueCode::DRACO_DECODE_FAILED, "meshes[0].primitives[0].extensions.KHR_draco_mesh_compression");
    // Truncated: the view keeps only half its bytes.
    const fs::path truncated = patched("gallery-draco.glb", [](json& doc, std::vector<uint8_t>&) {
        doc["bufferViews"][6]["byteLength"] = doc["bufferViews"][6]["byteLength"].get<size_t>() / 2;
    });
    expectRefused(truncated, IssueCode::DRACO_DECODE_FAILED, "meshes[1].primitives[0].extensions.KHR_draco_mesh_compression");
}

TEST_F(GltfCompression, DracoDataMustMatchItsAccessors)
{
    // meshes[0].primitives[0]: indices accessors[0] (6), POSITION accessors[2] (4 vertices),
    // NORMAL accessors[1] (VEC3 FLOAT), Draco attribute ids 0..3.
    const char* path = "meshes[0].primitives[0].extensions.KHR_draco_mesh_compression";
    expectRefused(patched("gallery-draco.glb", [](json& doc, std::vector<uint8_t>&) { doc["accessors"][2]["count"] = 5; }), IssueCode::DRACO_DECODE_FAILED,
                  path);
    expectRefused(patched("gallery-draco.glb", [](json& doc, std::vector<uint8_t>&) { doc["accessors"][0]["count"] = 9; }), IssueCode::DRACO_DECODE_FAILED,
                  path);
    expectRefused(patched("gallery-draco.glb",
                          [](json& doc, std::vector<uint8_t>&) {
                              doc["accessors"][1]["componentType"] = 5122;
                              doc["accessors"][1]["normalized"] = true;
                              doc["extensionsUsed"].push_back("KHR_mesh_quantization");
                          }), IssueCode::DRACO_DECODE_FAILED,
                  path);
    expectRefused(patched("gallery-draco.glb",
                          [](json& doc, std::vector<uint8_t>&) {
                              doc["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["attributes"]["NORMAL"] = 9;
                          }), IssueCode::DRACO_DECODE_FAILED,
                  path);
}

TEST_F(GltfCompression, DracoSchemaIsChecked)
{
    const std::string ext = "meshes[0].primitives[0].extensions.KHR_draco_mesh_compression";
    expectRefused(patched("gallery-draco.glb",
                          [](json& doc, std::vector<uint8_t>&) {
                              doc["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["bufferView"] = 99;
                          }), IssueCode::UNRESOLVED_REFERENCE,
                  ext + ".bufferView");
    expectRefused(patched("gallery-draco.glb",
                          [](json& doc, std::vector<uint8_t>&) {
                              doc["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["attributes"]["COLOR_0"] = 4;
                          }), IssueCode::DRACO_ATTRIBUTE_UNKNOWN,
                  ext + ".attributes.COLOR_0");
    expectRefused(patched("gallery-draco.glb", [](json& doc, std::vector<uint8_t>&) { doc["meshes"][0]["primitives"][0]["mode"] = 5; }), IssueCode::DRACO_MODE_UNSUPPORTED,
                  "meshes[0].primitives[0].mode");
}

TEST_F(GltfCompression, CorruptMeshoptStreamNamesTheView)
{
    // bufferViews[5]: the TRIANGLES index stream (header byte 0xe1); bufferViews[6]: an
    // OCTAHEDRAL attribute stream (0xa0).
    const fs::path header = patched("gallery-meshopt.glb", [](json& doc, std::vector<uint8_t>& bin) {
        bin[doc["bufferViews"][5]["extensions"]["EXT_meshopt_compression"]["byteOffset"].get<size_t>()] = 0x00;
    });
    expectRefused(header, IssueCode::MESHOPT_DECODE_FAILED, "bufferViews[5].extensions.EXT_meshopt_compression");
    const fs::path truncated = patched("gallery-meshopt.glb", [](json& doc, std::vector<uint8_t>&) {
        json& ext = doc["bufferViews"][6]["extensions"]["EXT_meshopt_compression"];
        ext["byteLength"] = ext["byteLength"].get<size_t>() - 8;
    });
    expectRefused(truncated, IssueCode::MESHOPT_DECODE_FAILED, "bufferViews[6].extensions.EXT_meshopt_compression");
    const fs::path version1 = patched("gallery-meshopt.glb", [](json& doc, std::vector<uint8_t>& bin) {
        bin[doc["bufferViews"][6]["extensions"]["EXT_meshopt_compression"]["byteOffset"].get<size_t>()] = 0xa1;
    });
    expectRefused(version1, IssueCode::MESHOPT_DECODE_FAILED, "bufferViews[6].extensions.EXT_meshopt_compression");
    const fs::path outside = patched("gallery-meshopt.glb", [](json& doc, std::vector<uint8_t>&) {
        doc["bufferViews"][6]["extensions"]["EXT_meshopt_compression"]["byteOffset"] = 1 << 20;
    });
    expectRefused(outside, IssueCode::COMPRESSED_DATA_OUT_OF_BOUNDS, "bufferViews[6].extensions.EXT_meshopt_compression");
}

TEST_F(GltfCompression, MeshoptSchemaIsChecked)
{
    const std::string ext = "bufferViews[6].extensions.EXT_meshopt_compression";
    auto with = [&](const char* key, json value) {
        return patched("gallery-meshopt.glb", [&](json& doc, std::vector<uint8_t>&) {
            doc["bufferViews"][6]["extensions"]["EXT_meshopt_compression"][key] = value;
        });
    };
    expectRefused(with("mode", "STRIPS"), IssueCode::VALUE_NOT_IN_LIST, ext + ".mode");
    expectRefused(with("filter", "COLOR"), IssueCode::VALUE_NOT_IN_LIST, ext + ".filter");
    expectRefused(with("count", 5), IssueCode::MESHOPT_INVALID, ext);
    expectRefused(with("byteStride", 8), IssueCode::MESHOPT_INVALID, ext);
    expectRefused(with("filter", "QUATERNION"), IssueCode::MESHOPT_INVALID, ext);
    expectRefused(with("buffer", 7), IssueCode::UNRESOLVED_REFERENCE, ext + ".buffer");
    // The fallback buffer must hold the decoded view (EXT_meshopt_compression, "Fallback buffers").
    expectRefused(patched("gallery-meshopt.glb", [](json& doc, std::vector<uint8_t>&) { doc["buffers"][1]["byteLength"] = 100; }), IssueCode::MESHOPT_DECODED_TOO_LONG,
                  "bufferViews[5]");
}

// ---- Textures: WebP, KTX2 -----------------------------------------------------------

// Mean and largest absolute difference of two textures' mip level `level` (RGBA8, same size).
std::pair<double, int> levelDifference(const lfd::Texture& a, const lfd::Texture& b, size_t level)
{
    const lfd::MipLevel& m = a.mips.at(level);
    double sum = 0.0;
    int worst = 0;
    for (size_t i = m.offset; i < m.offset + m.size; ++i) {
        const int d = std::abs(int(a.texels[i]) - int(b.texels[i]));
        sum += d;
        worst = std::max(worst, d);
    }
    return {sum / double(m.size), worst};
}

TEST_F(GltfCompression, WebpTexturesBakeLikeThePngOnes)
{
    // gltf-transform webp: every image re-encoded lossy (quality 80), EXT_texture_webp
    // required, no core source.
    const ImportedScene webp = importStrict(kFixtures / "gallery-webp.glb");
    ASSERT_EQ(webp.textureSources.size(), reference().textureSources.size());
    for (size_t t = 0; t < webp.textureSources.size(); ++t) {
        SCOPED_TRACE(reference().textureSources[t].name);
        EXPECT_EQ(webp.textureSources[t].mimeType, "image/webp");
        const lfd::Texture a = lfd::bake::bakeTexture(reference().textureSources[t], {});
        const lfd::Texture b = lfd::bake::bakeTexture(webp.textureSources[t], {});
        ASSERT_EQ(b.width, a.width);
        ASSERT_EQ(b.height, a.height);
        ASSERT_EQ(b.texels.size(), a.texels.size());
        // Lossy (sharp's WebP at quality 80, 4:2:0 chroma) on 32-pixel images: level 0
        // within 12 levels on average (measured 9.5 on the painting, whose colour edges the
        // chroma subsampling blurs; 0.3 to 3.2 on the others), level 2 (8x8, the texels a
        // view four times farther samples) within 6 on average and 40 at most (measured
        // 4.4 and 29 on the painting). A swapped channel, a wrong row stride or
        // premultiplied colours are off by far more.
        EXPECT_LT(levelDifference(a, b, 0).first, 12.0);
        const auto [mean2, worst2] = levelDifference(a, b, 2);
        EXPECT_LT(mean2, 6.0);
        EXPECT_LT(worst2, 40);
    }
}

TEST_F(GltfCompression, WebpIsPreferredToItsPngFallbackWithStraightAlpha)
{
    const ImportedScene r = importStrict(kGltfCases / "webp_fallback.gltf");
    ASSERT_EQ(r.textureSources.size(), 1u);
    EXPECT_EQ(r.textureSources[0].mimeType, "image/webp");
    const lfd::Texture t = lfd::bake::bakeTexture(r.textureSources[0], {});
    ASSERT_EQ(t.width, 4u);
    ASSERT_EQ(t.height, 4u);
    for (size_t i = 0; i < 16 * 4; i += 4)
        ASSERT_EQ(std::vector<int>(t.texels.begin() + std::ptrdiff_t(i), t.texels.begin() + std::ptrdiff_t(i + 4)),
                  (std::vector<int>{40, 200, 90, 128}))
            << "texel " << i / 4;
}

TEST_F(GltfCompression, CorruptWebpIsOneLineNamingTheImage)
{
    lfd::bake::TextureSource source;
    source.name = "images[3]";
    source.encoded = {'R', 'I', 'F', 'F', 30, 0, 0, 0, 'W', 'E', 'B', 'P', 'V', 'P', '8', 'L', 17, 0, 0, 0, 0x2f, 3};
    source.mimeType = "image/webp";
    try {
        lfd::bake::bakeTexture(source, {});
        ADD_FAILURE() << "decoded";
    } catch (const BakeError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("images[3]: cannot decode: ", 0), 0u) << e.what();
    }
}

TEST_F(GltfCompression, KtxTextureFallsBackToItsPngOrIsRefusedWhenRequired)
{
    const ImportedScene r = importCompressed(kGltfCases / "basisu_fallback.gltf");
    ASSERT_EQ(r.textureSources.size(), 1u);
    EXPECT_EQ(r.textureSources[0].mimeType, "image/png");
    EXPECT_TRUE(hasWarning(r, "ignores optional extension KHR_texture_basisu"));
    const lfd::Texture t = lfd::bake::bakeTexture(r.textureSources[0], {});
    EXPECT_EQ(std::vector<int>(t.texels.begin(), t.texels.begin() + 4), (std::vector<int>{255, 0, 0, 255}));
    expectRefused(kGltfCases / "basisu_required.gltf", "extensionsRequired[0]",
                  "requires unsupported extension KHR_texture_basisu (KTX2 / Basis Universal textures: Debian 12 packages "
                  "no KTX2 decoder)");
}

// ---- KHR_mesh_quantization normals --------------------------------------------------

TEST_F(GltfCompression, QuantizedNormalsWithinTheirGridDoNotWarnButWrongOnesDo)
{
    EXPECT_NO_THROW(importStrict(kGltfCases / "quantized_normals.gltf"));
    const ImportedScene bad = importCompressed(kGltfCases / "quantized_bad_normal.gltf");
    EXPECT_FALSE(bad.warnings.empty());
    lfd::test::expectWarningWith(kGltfCases / "quantized_bad_normal.gltf", IssueCode::ACCESSOR_NON_UNIT, "accessors[0]");
}

} // namespace
