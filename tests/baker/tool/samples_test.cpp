// lfd-make-samples: runs the built tool and checks the glTF it writes (structure,
// textures, instancing, animation, winding, watertightness, occluded interior) and its
// command-line errors.
#include "bake_log.h"
#include "imported_scene.h"
#include "gltf_import.h"
#include "tessellation.h"
#include "tool_run.h"
#include "lfd/scene_animation.h"
#include "lfd/scene_pose.h"

#include <gtest/gtest.h>

#include <tiny_gltf.h>

#include <OpenImageIO/imageio.h>

#include <glm/glm.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

using lfd::test::kMakeSamples;

using lfd::test::lineCount;
using lfd::test::RunResult;

// lfd-make-samples with `arguments`: its exit status and its stdout + stderr together.
RunResult runTool(const std::string& arguments) { return lfd::test::run("'" + kMakeSamples + "' " + arguments); }

tinygltf::Model loadGltf(const fs::path& path)
{
    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    std::string error, warning;
    const bool ok = loader.LoadASCIIFromFile(&model, &error, &warning, path.string());
    EXPECT_TRUE(ok) << path << ": " << error;
    EXPECT_TRUE(error.empty()) << error;
    return model;
}

// Reads a float accessor (tightly packed or strided) as `components` floats per element.
std::vector<float> readFloats(const tinygltf::Model& model, int accessorIndex, int components)
{
    const tinygltf::Accessor& accessor = model.accessors.at(size_t(accessorIndex));
    EXPECT_EQ(accessor.componentType, TINYGLTF_COMPONENT_TYPE_FLOAT);
    const tinygltf::BufferView& view = model.bufferViews.at(size_t(accessor.bufferView));
    const auto& bytes = model.buffers.at(size_t(view.buffer)).data;
    const size_t stride = view.byteStride ? view.byteStride : size_t(components) * sizeof(float);
    std::vector<float> values(accessor.count * size_t(components));
    for (size_t i = 0; i < accessor.count; ++i) {
        const size_t at = view.byteOffset + accessor.byteOffset + i * stride;
        EXPECT_LE(at + size_t(components) * sizeof(float), bytes.size());
        std::memcpy(&values[i * size_t(components)], &bytes[at], size_t(components) * sizeof(float));
    }
    return values;
}

std::vector<uint32_t> readIndices(const tinygltf::Model& model, int accessorIndex)
{
    const tinygltf::Accessor& accessor = model.accessors.at(size_t(accessorIndex));
    const tinygltf::BufferView& view = model.bufferViews.at(size_t(accessor.bufferView));
    const auto& bytes = model.buffers.at(size_t(view.buffer)).data;
    std::vector<uint32_t> indices(accessor.count);
    for (size_t i = 0; i < accessor.count; ++i) {
        const size_t base = view.byteOffset + accessor.byteOffset;
        if (accessor.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
            uint16_t v;
            std::memcpy(&v, &bytes.at(base + 2 * i), 2);
            indices[i] = v;
        } else {
            EXPECT_EQ(accessor.componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
            std::memcpy(&indices[i], &bytes.at(base + 4 * i), 4);
        }
    }
    return indices;
}

struct Triangles {
    std::vector<glm::vec3> positions, normals;
    std::vector<uint32_t> indices;
};

Triangles readPrimitive(const tinygltf::Model& model, const tinygltf::Primitive& primitive)
{
    Triangles t;
    const std::vector<float> p = readFloats(model, primitive.attributes.at("POSITION"), 3);
    const std::vector<float> n = readFloats(model, primitive.attributes.at("NORMAL"), 3);
    for (size_t i = 0; i + 2 < p.size(); i += 3) {
        t.positions.emplace_back(p[i], p[i + 1], p[i + 2]);
        t.normals.emplace_back(n[i], n[i + 1], n[i + 2]);
    }
    t.indices = readIndices(model, primitive.indices);
    return t;
}

size_t meshTriangles(const tinygltf::Model& model, int mesh)
{
    size_t total = 0;
    for (const tinygltf::Primitive& primitive : model.meshes.at(size_t(mesh)).primitives)
        total += model.accessors.at(size_t(primitive.indices)).count / 3;
    return total;
}

// Triangles drawn by the default scene (mesh triangles summed over node instances).
size_t drawnTriangles(const tinygltf::Model& model)
{
    size_t total = 0;
    std::vector<int> stack = model.scenes.at(size_t(std::max(0, model.defaultScene))).nodes;
    while (!stack.empty()) {
        const tinygltf::Node& node = model.nodes.at(size_t(stack.back()));
        stack.pop_back();
        if (node.mesh >= 0)
            total += meshTriangles(model, node.mesh);
        stack.insert(stack.end(), node.children.begin(), node.children.end());
    }
    return total;
}

int meshByName(const tinygltf::Model& model, const std::string& name)
{
    for (size_t m = 0; m < model.meshes.size(); ++m)
        if (model.meshes[m].name == name)
            return int(m);
    ADD_FAILURE() << "no mesh named " << name;
    return -1;
}

// Moller-Trumbore: does the ray origin + t * dir (t > 0) cross triangle (a, b, c)?
bool rayHitsTriangle(glm::vec3 origin, glm::vec3 dir, glm::vec3 a, glm::vec3 b, glm::vec3 c)
{
    const glm::vec3 e1 = b - a, e2 = c - a, p = glm::cross(dir, e2);
    const float det = glm::dot(e1, p);
    if (std::abs(det) < 1e-12f)
        return false;
    const glm::vec3 s = origin - a;
    const float u = glm::dot(s, p) / det;
    if (u < 0.0f || u > 1.0f)
        return false;
    const glm::vec3 q = glm::cross(s, e1);
    const float v = glm::dot(dir, q) / det;
    if (v < 0.0f || u + v > 1.0f)
        return false;
    return glm::dot(e2, q) / det > 0.0f;
}

// Parity test against a closed mesh; the odd direction avoids grazing edges.
bool insideClosedMesh(const Triangles& mesh, glm::vec3 point)
{
    const glm::vec3 dir = glm::normalize(glm::vec3(0.123f, 1.0f, 0.0517f));
    int crossings = 0;
    for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3)
        crossings += rayHitsTriangle(point, dir, mesh.positions[mesh.indices[i]],
                                     mesh.positions[mesh.indices[i + 1]],
                                     mesh.positions[mesh.indices[i + 2]]);
    return crossings % 2 == 1;
}

class SamplesTest : public ::testing::Test {
protected:
    static void SetUpTestSuite()
    {
        dir_ = fs::temp_directory_path() / ("lfd_samples_test_" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        generated_ = runTool("'" + (dir_ / "out").string() + "' --texture-size 256 --quiet");
    }
    static void TearDownTestSuite() { fs::remove_all(dir_); }

    void SetUp() override
    {
        ASSERT_EQ(generated_.exitCode, 0) << "lfd-make-samples failed (is it built?): "
                                          << generated_.out;
    }

    static fs::path scenePath(const std::string& scene)
    {
        return dir_ / "out" / scene / (scene + ".gltf");
    }

    static inline fs::path dir_;
    static inline RunResult generated_;
};


TEST_F(SamplesTest, WritesEveryScene_ExternalFilesOnly_NoStagingLeftovers)
{
    EXPECT_TRUE(generated_.out.empty()) << "--quiet printed: " << generated_.out;
    for (const std::string scene : {"gallery", "car", "room"}) {
        EXPECT_TRUE(fs::is_regular_file(scenePath(scene))) << scene;
        EXPECT_TRUE(fs::is_regular_file(dir_ / "out" / scene / (scene + ".bin"))) << scene;
        std::ifstream in(scenePath(scene));
        const std::string json((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        EXPECT_EQ(json.find("data:"), std::string::npos) << scene << " embeds a data URI";
    }
    for (const char* png : {"picture.png", "floor_basecolor.png", "floor_normal.png",
                            "floor_metallic_roughness.png", "plaster_basecolor.png"})
        EXPECT_TRUE(fs::is_regular_file(dir_ / "out" / "gallery" / png)) << png;
    for (const fs::directory_entry& entry : fs::directory_iterator(dir_ / "out"))
        EXPECT_NE(entry.path().filename().string().front(), '.') << "left behind " << entry.path();
}

TEST_F(SamplesTest, Gallery_MaterialsUseColourNormalAndMetallicRoughnessTextures)
{
    const tinygltf::Model model = loadGltf(scenePath("gallery"));
    EXPECT_EQ(model.textures.size(), 5u);
    EXPECT_EQ(model.images.size(), 5u);
    bool fullyTextured = false;
    for (const tinygltf::Material& m : model.materials)
        fullyTextured |= m.pbrMetallicRoughness.baseColorTexture.index >= 0 &&
                         m.pbrMetallicRoughness.metallicRoughnessTexture.index >= 0 &&
                         m.normalTexture.index >= 0;
    EXPECT_TRUE(fullyTextured);

    // Textured primitives carry uvs in [0, 1]; normal-mapped ones carry unit tangents.
    for (const tinygltf::Mesh& mesh : model.meshes) {
        for (const tinygltf::Primitive& primitive : mesh.primitives) {
            const tinygltf::Material& m = model.materials.at(size_t(primitive.material));
            if (m.pbrMetallicRoughness.baseColorTexture.index >= 0) {
                ASSERT_TRUE(primitive.attributes.count("TEXCOORD_0")) << mesh.name;
                for (float uv : readFloats(model, primitive.attributes.at("TEXCOORD_0"), 2)) {
                    EXPECT_GE(uv, 0.0f) << mesh.name;
                    EXPECT_LE(uv, 1.0f) << mesh.name;
                }
            }
            if (m.normalTexture.index >= 0) {
                ASSERT_TRUE(primitive.attributes.count("TANGENT")) << mesh.name;
                const std::vector<float> t = readFloats(model, primitive.attributes.at("TANGENT"), 4);
                for (size_t i = 0; i + 3 < t.size(); i += 4) {
                    EXPECT_NEAR(glm::length(glm::vec3(t[i], t[i + 1], t[i + 2])), 1.0f, 1e-5f);
                    EXPECT_EQ(std::abs(t[i + 3]), 1.0f);
                }
            }
        }
    }
}

TEST_F(SamplesTest, Gallery_TexturesHaveTheRequestedSize)
{
    const tinygltf::Model model = loadGltf(scenePath("gallery"));
    for (const tinygltf::Image& image : model.images) {
        // --texture-size 256: the painting is 256^2; the others are min(256, 1024).
        auto input = OIIO::ImageInput::open((dir_ / "out" / "gallery" / image.uri).string());
        ASSERT_TRUE(input) << image.uri << ": " << OIIO::geterror();
        EXPECT_EQ(input->spec().width, 256) << image.uri;
        EXPECT_EQ(input->spec().height, 256) << image.uri;
        EXPECT_EQ(input->spec().nchannels, 3) << image.uri;
        EXPECT_EQ(input->spec().format, OIIO::TypeDesc::UINT8) << image.uri;
    }
    const auto picture = std::find_if(model.images.begin(), model.images.end(),
                                      [](const tinygltf::Image& i) { return i.uri == "picture.png"; });
    ASSERT_NE(picture, model.images.end());
    // High-frequency content: horizontally neighbouring pixels differ strongly in more
    // than 5% of the places (fine checkers, stripes, text, zone plate).
    const size_t channels = size_t(picture->component);
    size_t bigSteps = 0;
    for (size_t i = channels; i < picture->image.size(); i += channels)
        bigSteps += std::abs(int(picture->image[i]) - int(picture->image[i - channels])) > 24;
    EXPECT_GT(bigSteps, picture->image.size() / channels / 20);
}

TEST_F(SamplesTest, Car_IsUntexturedWithFourInstancedSpinningWheels)
{
    const tinygltf::Model model = loadGltf(scenePath("car"));
    EXPECT_TRUE(model.textures.empty());
    EXPECT_TRUE(model.images.empty());
    for (const tinygltf::Mesh& mesh : model.meshes)
        for (const tinygltf::Primitive& primitive : mesh.primitives)
            EXPECT_EQ(primitive.attributes.count("TEXCOORD_0"), 0u) << mesh.name;
    // Materials told apart by their factors alone.
    std::set<std::vector<double>> looks;
    for (const tinygltf::Material& m : model.materials) {
        std::vector<double> look = m.pbrMetallicRoughness.baseColorFactor;
        look.push_back(m.pbrMetallicRoughness.metallicFactor);
        look.push_back(m.pbrMetallicRoughness.roughnessFactor);
        looks.insert(look);
    }
    EXPECT_GE(looks.size(), 5u);

    const int wheel = meshByName(model, "wheel");
    std::set<int> wheelNodes;
    for (size_t n = 0; n < model.nodes.size(); ++n)
        if (model.nodes[n].mesh == wheel)
            wheelNodes.insert(int(n));
    EXPECT_GE(wheelNodes.size(), 4u);

    ASSERT_EQ(model.animations.size(), 1u);
    const tinygltf::Animation& animation = model.animations[0];
    std::set<int> animated;
    for (const tinygltf::AnimationChannel& channel : animation.channels) {
        EXPECT_EQ(channel.target_path, "rotation");
        const tinygltf::AnimationSampler& sampler = animation.samplers.at(size_t(channel.sampler));
        EXPECT_EQ(sampler.interpolation, "LINEAR");
        const std::vector<float> times = readFloats(model, sampler.input, 1);
        ASSERT_GE(times.size(), 3u);
        EXPECT_FLOAT_EQ(times.front(), 0.0f);
        EXPECT_FLOAT_EQ(times.back(), 2.0f);
        EXPECT_TRUE(std::is_sorted(times.begin(), times.end()));
        // Unit quaternions, consecutive keys in the same hemisphere (no slerp flip).
        const std::vector<float> q = readFloats(model, sampler.output, 4);
        ASSERT_EQ(q.size(), 4 * times.size());
        for (size_t k = 0; k < times.size(); ++k) {
            const glm::vec4 key(q[4 * k], q[4 * k + 1], q[4 * k + 2], q[4 * k + 3]);
            EXPECT_NEAR(glm::length(key), 1.0f, 1e-5f);
            if (k > 0) {
                const glm::vec4 previous(q[4 * k - 4], q[4 * k - 3], q[4 * k - 2], q[4 * k - 1]);
                EXPECT_GT(glm::dot(key, previous), 0.0f);
            }
        }
        animated.insert(channel.target_node);
    }
    EXPECT_EQ(animated, wheelNodes);
}

TEST_F(SamplesTest, TriangleCountsAreInTheExpectedRange)
{
    const size_t gallery = drawnTriangles(loadGltf(scenePath("gallery")));
    EXPECT_GE(gallery, 1000u);
    EXPECT_LE(gallery, 10000u);
    const tinygltf::Model car = loadGltf(scenePath("car"));
    const size_t carDrawn = drawnTriangles(car);
    EXPECT_GE(carDrawn, 3000u);
    EXPECT_LE(carDrawn, 20000u);
    // The room instances the car 16 times (default) plus a two-triangle floor, and stores
    // each mesh only once.
    const tinygltf::Model room = loadGltf(scenePath("room"));
    EXPECT_EQ(drawnTriangles(room), 16 * carDrawn + 2);
    EXPECT_EQ(room.meshes.size(), car.meshes.size() + 1);
}

TEST_F(SamplesTest, EveryTriangleIsCounterClockwiseAroundItsNormals)
{
    for (const std::string scene : {"gallery", "car"}) {
        const tinygltf::Model model = loadGltf(scenePath(scene));
        for (const tinygltf::Mesh& mesh : model.meshes) {
            for (const tinygltf::Primitive& primitive : mesh.primitives) {
                EXPECT_EQ(primitive.mode, TINYGLTF_MODE_TRIANGLES);
                const Triangles t = readPrimitive(model, primitive);
                ASSERT_EQ(t.indices.size() % 3, 0u);
                size_t wrong = 0;
                for (size_t i = 0; i < t.indices.size(); i += 3) {
                    const uint32_t a = t.indices[i], b = t.indices[i + 1], c = t.indices[i + 2];
                    ASSERT_LT(std::max({a, b, c}), t.positions.size()) << mesh.name;
                    const glm::vec3 face = glm::cross(t.positions[b] - t.positions[a],
                                                      t.positions[c] - t.positions[a]);
                    wrong += glm::dot(face, t.normals[a] + t.normals[b] + t.normals[c]) <= 0.0f;
                }
                EXPECT_EQ(wrong, 0u) << scene << "/" << mesh.name;
            }
        }
    }
}

TEST_F(SamplesTest, Car_BodyAndCabinAreWatertightAndConsistentlyOriented)
{
    const tinygltf::Model model = loadGltf(scenePath("car"));
    for (const std::string name : {"body", "cabin"}) {
        const Triangles t = readPrimitive(model, model.meshes.at(size_t(meshByName(model, name))).primitives.at(0));
        // Every directed edge exactly once and its reverse exactly once.
        std::map<std::pair<uint32_t, uint32_t>, int> directed;
        for (size_t i = 0; i < t.indices.size(); i += 3)
            for (int e = 0; e < 3; ++e)
                ++directed[{t.indices[i + size_t(e)], t.indices[i + size_t((e + 1) % 3)]}];
        size_t bad = 0;
        for (const auto& [edge, count] : directed) {
            const auto reverse = directed.find({edge.second, edge.first});
            bad += count != 1 || reverse == directed.end() || reverse->second != 1;
        }
        EXPECT_EQ(bad, 0u) << name;
    }
}

TEST_F(SamplesTest, Car_InteriorAndEngineAreHiddenInsideTheShell)
{
    const tinygltf::Model model = loadGltf(scenePath("car"));
    const Triangles body = readPrimitive(model, model.meshes.at(size_t(meshByName(model, "body"))).primitives.at(0));
    const Triangles cabin = readPrimitive(model, model.meshes.at(size_t(meshByName(model, "cabin"))).primitives.at(0));
    // The parity test itself: the body's centre is inside, a point above the roof is not.
    ASSERT_TRUE(insideClosedMesh(body, {0.0f, 0.72f, 0.0f}));
    ASSERT_FALSE(insideClosedMesh(body, {0.0f, 3.0f, 0.0f}));
    ASSERT_FALSE(insideClosedMesh(cabin, {0.0f, 0.72f, 3.0f}));
    // Body, cabin, interior and engine nodes all sit at the car root's origin.
    for (const std::string name : {"interior", "engine"}) {
        const Triangles part =
            readPrimitive(model, model.meshes.at(size_t(meshByName(model, name))).primitives.at(0));
        size_t outside = 0;
        for (const glm::vec3& p : part.positions)
            outside += !insideClosedMesh(body, p) && !insideClosedMesh(cabin, p);
        EXPECT_EQ(outside, 0u) << name << " pokes out of the body";
    }
}

TEST_F(SamplesTest, Room_InstancesOptionSetsTheNumberOfCars)
{
    const fs::path out = dir_ / "room5";
    const RunResult r = runTool("'" + out.string() + "' --scene room --instances 5");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_EQ(lineCount(r.out), 1u) << r.out; // one progress line per scene
    EXPECT_FALSE(fs::exists(out / "gallery"));
    const tinygltf::Model room = loadGltf(out / "room" / "room.gltf");
    const tinygltf::Model car = loadGltf(scenePath("car"));
    EXPECT_EQ(drawnTriangles(room), 5 * drawnTriangles(car) + 2);
    EXPECT_EQ(room.animations.at(0).channels.size(), 20u);
}

TEST_F(SamplesTest, RewritingAnExistingSceneReplacesIt)
{
    const fs::path out = dir_ / "rewrite";
    ASSERT_EQ(runTool("'" + out.string() + "' --scene car --quiet").exitCode, 0);
    std::ofstream(out / "car" / "stale.txt") << "old";
    ASSERT_EQ(runTool("'" + out.string() + "' --scene car --quiet").exitCode, 0);
    EXPECT_FALSE(fs::exists(out / "car" / "stale.txt")); // the whole directory was replaced
    EXPECT_TRUE(fs::is_regular_file(out / "car" / "car.gltf"));
    for (const fs::directory_entry& entry : fs::directory_iterator(out))
        EXPECT_EQ(entry.path().filename(), "car");
}

TEST_F(SamplesTest, BadArgumentsFailWithOneLineMessage)
{
    const std::string out = "'" + (dir_ / "bad").string() + "'";
    const std::vector<std::string> usageErrors = {
        "",                                   // no OUTDIR
        out + " --scene castle",              // unknown scene
        out + " --texture-size 8",            // too small
        out + " --texture-size 1k",           // not a number
        out + " --instances",                 // missing value
        out + " --frobnicate",                // unknown option
    };
    for (const std::string& arguments : usageErrors) {
        const RunResult r = runTool(arguments);
        EXPECT_EQ(r.exitCode, 2) << arguments;
        EXPECT_EQ(lineCount(r.out), 1u) << arguments << " -> " << r.out;
        EXPECT_NE(r.out.find("error"), std::string::npos) << r.out;
    }
    EXPECT_FALSE(fs::exists(dir_ / "bad"));

    // OUTDIR below a regular file cannot be created.
    std::ofstream(dir_ / "plain_file") << "x";
    const RunResult r = runTool("'" + (dir_ / "plain_file" / "sub").string() + "' --scene car");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(lineCount(r.out), 1u) << r.out;
    EXPECT_NE(r.out.find("plain_file"), std::string::npos) << r.out;
}

// The skinned samples (glTF 3.7.3, 3.7.2.2): the character's limb of four bones and its
// morph target import as one deformer; the crowd gives every character its own skin,
// deformer and mesh copy, and the characters are at different phases of the sway.
TEST_F(SamplesTest, CharacterAndCrowdAreSkinnedMorphedAndOutOfPhase)
{
    const fs::path out = dir_ / "skinned";
    ASSERT_EQ(runTool("'" + out.string() + "' --scene character").exitCode, 0);
    ASSERT_EQ(runTool("'" + out.string() + "' --scene crowd --instances 4").exitCode, 0);
    const lfd::bake::ImportedScene character = lfd::bake::importGltf(out / "character" / "character.gltf", {});
    EXPECT_TRUE(character.warnings.empty()) << character.warnings.front();
    const lfd::Scene& c = character.scene;
    ASSERT_EQ(c.deformers.size(), 1u);
    EXPECT_EQ(c.skins.at(0).joints.size(), 5u);
    EXPECT_EQ(c.vertices.deform.morphTargets, 1u);
    EXPECT_EQ(c.textures.size(), 1u);
    const lfd::bake::ImportedScene crowd = lfd::bake::importGltf(out / "crowd" / "crowd.gltf", {});
    const lfd::Scene& s = crowd.scene;
    ASSERT_EQ(s.deformers.size(), 4u);
    EXPECT_EQ(s.skins.size(), 4u);
    EXPECT_EQ(s.triangleCount(), 4 * c.triangleCount()); // one mesh copy per skinned instance
    // Same time, same vertex: each character's limb tip sits elsewhere relative to its root.
    const float t = 0.5f;
    const std::vector<glm::mat4> world = lfd::nodeWorldMatrices(s, t);
    const lfd::PoseInputs inputs = lfd::poseInputs(s, t, world);
    std::vector<glm::vec3> tips;
    for (size_t d = 0; d < 4; ++d) {
        const lfd::Deformer& deformer = s.deformers[d];
        const glm::vec3 tip = lfd::posedPositions(s, inputs, d).back();
        const glm::mat4 rootFromScene = glm::inverse(world[size_t(s.nodes[deformer.node].parent)]);
        tips.push_back(glm::vec3(rootFromScene * world[deformer.node] * glm::vec4(tip, 1.0f)));
    }
    for (size_t i = 1; i < tips.size(); ++i)
        EXPECT_GT(glm::length(tips[i] - tips[0]), 0.01f) << i;
}

// The character tessellated to a bound well under its edges (0.03 m against 0.09): every
// posed edge stays within it at poses sampled every 1/20 s over the loop, between the
// keys the baker samples too (blending bends pieces near the joints; the baker splits
// those again).
TEST_F(SamplesTest, CharacterKeepsTheEdgeBoundInSampledPoses)
{
    const fs::path out = dir_ / "bound";
    ASSERT_EQ(runTool("'" + out.string() + "' --scene character").exitCode, 0);
    lfd::Scene s = lfd::bake::importGltf(out / "character" / "character.gltf", {}).scene;
    const double bound = 0.03;
    const lfd::bake::TessellationStats stats = lfd::bake::tessellateScene(s, bound, lfd::bake::Log{});
    EXPECT_GT(stats.trianglesSplit, 0u);
    const lfd::Deformer& d = s.deformers.at(0);
    float worst = 0.0f;
    for (float t = 0.0f; t <= 2.0f; t += 0.05f) {
        const std::vector<glm::mat4> world = lfd::nodeWorldMatrices(s, t);
        const std::vector<glm::vec3> posed = lfd::posedPositions(s, lfd::poseInputs(s, t, world), 0);
        const glm::mat3 linear(world[d.node]);
        for (size_t i = 0; i < s.indices.size(); ++i) {
            const uint32_t a = s.indices[i], b = s.indices[i % 3 == 2 ? i - 2 : i + 1];
            worst = std::max(worst, glm::length(linear * (posed[a - d.firstVertex] - posed[b - d.firstVertex])));
        }
    }
    EXPECT_LE(worst, bound * 1.001) << "longest posed edge over the sampled poses";
}

} // namespace
