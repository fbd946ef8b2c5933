// GPU layouts: the C++ structs generated from shaders/*_bindings.glsl (player/gl/
// gpu_layout_gen.cpp) against what the driver reports, member by member.
//
// * Every struct and every fixed-member block of both bindings files is compiled into a
//   probe compute shader (generated here from the same tables) that touches every member;
//   program interface queries then give each member's offset, type, array size and
//   strides, and each block's size, binding and number of members, which must equal the
//   C++ offsetof / sizeof. A swapped pair of members, a missing or extra member, a wrong
//   stride or a wrong binding each fail.
// * Every block of every program the renderers build is checked the same way at the
//   block level (binding, element stride or size against the C++ sizes the renderers
//   allocate with); a block the table does not know fails too.
// * A tampered table (two vec4 members swapped) must fail the same check: the check can
//   fail.
// * The generator refuses layouts C++ cannot mirror, and pads where GLSL aligns.
#include "gl_handles.h"
#include "gl_test_support.h"

#include "eia_bindings_gpu.h"
#include "lfdpr_bindings_gpu.h"
#include "lfdpr_constants.h"
#include "pose_bindings_gpu.h"
#include "scene_bindings.h"
#include "shader_library.h"

#include "lfd/scene.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace lfd::test {
namespace {

namespace fs = std::filesystem;
namespace lb = player::lfdpr_bindings;

const gl::GpuLayoutFile* const kLayoutFiles[] = {&player::bindings::kLayoutFile, &lb::kLayoutFile,
                                                  &player::pose_bindings::kLayoutFile};

// ---- GLSL types ---------------------------------------------------------------------------

GLenum glType(const std::string& t)
{
    static const std::pair<const char*, GLenum> types[] = {
        {"float", GL_FLOAT},          {"vec2", GL_FLOAT_VEC2},        {"vec3", GL_FLOAT_VEC3},
        {"vec4", GL_FLOAT_VEC4},      {"int", GL_INT},                {"ivec2", GL_INT_VEC2},
        {"ivec3", GL_INT_VEC3},       {"ivec4", GL_INT_VEC4},         {"uint", GL_UNSIGNED_INT},
        {"uvec2", GL_UNSIGNED_INT_VEC2}, {"uvec3", GL_UNSIGNED_INT_VEC3}, {"uvec4", GL_UNSIGNED_INT_VEC4},
        {"bool", GL_BOOL},            {"mat4", GL_FLOAT_MAT4},
    };
    for (const auto& [name, type] : types)
        if (t == name)
            return type;
    ADD_FAILURE() << "no GL type for GLSL " << t;
    return GL_NONE;
}

// Bytes of one value of a GLSL type as C++ stores it.
uint32_t typeBytes(const std::string& t)
{
    if (t == "mat4")
        return 64;
    const char last = t.back();
    const uint32_t components = (last >= '2' && last <= '4') ? uint32_t(last - '0') : 1u;
    return 4 * components;
}

// A member's value as a vec4, so the probe can sum every member into one output.
std::string asVec4(const std::string& type, const std::string& e)
{
    if (type == "mat4")
        return e + "[0]";
    switch (typeBytes(type)) {
    case 16: return "vec4(" + e + ")";
    case 12: return "vec4(vec3(" + e + "), 0.0)";
    case 8: return "vec4(vec2(" + e + "), 0.0, 0.0)";
    default: return "vec4(float(" + e + "))";
    }
}

// ---- Probe programs -----------------------------------------------------------------------

// Where one struct lives in a probe: a real block of the bindings file, or a probe block
// holding an array of it (structs that only shaders' own blocks use).
struct Target {
    const gl::GpuLayoutFile* file;
    const gl::GpuStruct* layout;
    const gl::GpuBlock* block = nullptr; // null: the probe block LfdProbeBlock
};

bool isArrayTarget(const Target& t) { return !t.block || t.block->arrayMember; }
GLenum blockInterface(const Target& t)
{
    return t.block && t.block->interface == gl::GpuInterface::Uniform ? GL_UNIFORM_BLOCK : GL_SHADER_STORAGE_BLOCK;
}
GLenum memberInterface(const Target& t)
{
    return blockInterface(t) == GL_UNIFORM_BLOCK ? GL_UNIFORM : GL_BUFFER_VARIABLE;
}
std::string blockName(const Target& t) { return t.block ? t.block->name : "LfdProbeBlock"; }

// What GLSL writes before a member (access) and what the driver calls it (resource name
// prefix): "lfdProbe[0]." / "materials[0]." for arrays, "u_lfd." / "LfdprFrameBlock." for
// blocks with an instance name.
std::pair<std::string, std::string> memberPrefix(const Target& t)
{
    if (!t.block)
        return {"lfdProbe[0].", "lfdProbe[0]."};
    const std::string instance = t.block->instance ? t.block->instance : "";
    const std::string access = instance.empty() ? "" : instance + ".";
    const std::string resource = instance.empty() ? "" : std::string(t.block->name) + ".";
    if (t.block->arrayMember)
        return {access + t.block->arrayMember + "[0].", resource + t.block->arrayMember + "[0]."};
    return {access, resource};
}

std::string probeSource(const Target& t)
{
    std::ostringstream s;
    s << "#version 450 core\n#include \"scene_bindings.glsl\"\n";
    if (std::string(t.file->file) != "scene_bindings.glsl")
        s << "#include \"" << t.file->file << "\"\n";
    s << "layout(local_size_x = 1) in;\n";
    if (!t.block)
        s << "layout(std430, binding = 0) readonly buffer LfdProbeBlock { " << t.layout->glslName
          << " lfdProbe[]; };\n";
    s << "layout(std430, binding = 0) writeonly buffer LfdProbeOut { vec4 lfdProbeOut; };\n"
      << "void main()\n{\n    vec4 sum = vec4(0.0);\n";
    const std::string access = memberPrefix(t).first;
    for (const gl::GpuMember& m : t.layout->members)
        s << "    sum += " << asVec4(m.glslType, access + m.name + (m.arraySize ? "[0]" : "")) << ";\n";
    s << "    lfdProbeOut = sum;\n}\n";
    return s.str();
}

gl::Program buildProbe(const std::string& source)
{
    const gl::ShaderLookup lookup = [&](std::string_view name) -> std::optional<std::string> {
        if (name == "layout_probe.comp")
            return source;
        return std::string(gl::shaderSource(name));
    };
    const gl::Shader shader(gl::compileShader(GL_COMPUTE_SHADER, gl::preprocessShader("layout_probe.comp", lookup)));
    gl::Program program(glCreateProgram());
    glAttachShader(program, shader);
    glLinkProgram(program);
    GLint linked = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &linked);
    EXPECT_EQ(linked, GL_TRUE) << source;
    return program;
}

GLint resourceProperty(GLuint program, GLenum interface, GLuint index, GLenum property)
{
    GLint value = -1;
    glGetProgramResourceiv(program, interface, index, 1, &property, 1, nullptr, &value);
    return value;
}

// Every difference between `t` (C++) and the driver's view of `program`, one line each.
std::vector<std::string> layoutMismatches(GLuint program, const Target& t)
{
    std::vector<std::string> out;
    const std::string where = std::string(t.file->file) + ": " + t.layout->cppName;
    auto expect = [&](const std::string& what, GLint driver, uint64_t cpp) {
        if (driver < 0 || uint64_t(driver) != cpp)
            out.push_back(where + what + " is " + std::to_string(driver) + " in the driver, " + std::to_string(cpp) +
                          " in C++");
    };

    // The block: size, binding, and exactly as many active members as C++ has.
    const GLuint block = glGetProgramResourceIndex(program, blockInterface(t), blockName(t).c_str());
    if (block == GL_INVALID_INDEX)
        return {where + ": block " + blockName(t) + " is not active in the probe"};
    // A fixed block's size is exact; a block of one unsized array reports the size with one
    // element, which drivers may round up (Mesa: to 16 bytes) - its element size is the
    // top-level stride checked per member below.
    const GLint dataSize = resourceProperty(program, blockInterface(t), block, GL_BUFFER_DATA_SIZE);
    if (isArrayTarget(t) ? dataSize < GLint(t.layout->size) : dataSize != GLint(t.layout->size))
        out.push_back(where + " (block " + blockName(t) + ") size is " + std::to_string(dataSize) +
                      " in the driver, " + std::to_string(t.layout->size) + " in C++");
    expect(" (block " + blockName(t) + ") member count",
           resourceProperty(program, blockInterface(t), block, GL_NUM_ACTIVE_VARIABLES), t.layout->members.size());
    if (t.block)
        expect(" (block " + blockName(t) + ") binding",
               resourceProperty(program, blockInterface(t), block, GL_BUFFER_BINDING), t.block->binding);

    // Every member.
    const std::string prefix = memberPrefix(t).second;
    for (const gl::GpuMember& m : t.layout->members) {
        const std::string name = prefix + m.name + (m.arraySize ? "[0]" : "");
        const std::string what = "." + std::string(m.name);
        const GLuint index = glGetProgramResourceIndex(program, memberInterface(t), name.c_str());
        if (index == GL_INVALID_INDEX) {
            out.push_back(where + what + ": the driver has no active member " + name);
            continue;
        }
        auto property = [&](GLenum p) { return resourceProperty(program, memberInterface(t), index, p); };
        expect(what + " offset", property(GL_OFFSET), m.offset);
        expect(what + " type", property(GL_TYPE), glType(m.glslType));
        expect(what + " array size", property(GL_ARRAY_SIZE), m.arraySize ? m.arraySize : 1);
        expect(what + " array stride", property(GL_ARRAY_STRIDE), m.arraySize ? m.arrayStride : 0);
        expect(what + " matrix stride", property(GL_MATRIX_STRIDE),
               std::string(m.glslType) == "mat4" ? sizeof(glm::vec4) : 0);
        if (memberInterface(t) == GL_BUFFER_VARIABLE)
            expect(what + " top-level array stride", property(GL_TOP_LEVEL_ARRAY_STRIDE),
                   isArrayTarget(t) ? t.layout->size : (m.arraySize ? m.arrayStride : 0));
        // The C++ member holds exactly the GLSL type.
        const uint32_t element = typeBytes(m.glslType);
        if (m.size != (m.arraySize ? m.arraySize * element : element) || (m.arraySize && m.arrayStride != element))
            out.push_back(where + what + ": C++ member of " + std::to_string(m.size) + " bytes for GLSL " +
                          m.glslType);
    }
    return out;
}

// Every struct and fixed-member block of `file`, with where to probe it.
std::vector<Target> targets(const gl::GpuLayoutFile& file)
{
    std::vector<Target> out;
    for (const gl::GpuStruct& s : file.structs) {
        Target t{&file, &s, nullptr};
        for (const gl::GpuBlock& b : file.blocks)
            if (b.layout == &s || b.arrayStruct == &s)
                t.block = &b;
        out.push_back(t);
    }
    return out;
}

class GpuLayoutTest : public GlTest {};

TEST_F(GpuLayoutTest, EveryStructAndBlockMatchesTheDriverMemberByMember)
{
    size_t checked = 0;
    for (const gl::GpuLayoutFile* file : kLayoutFiles)
        for (const Target& t : targets(*file)) {
            SCOPED_TRACE(std::string(file->file) + ": " + t.layout->cppName);
            const gl::Program program = buildProbe(probeSource(t));
            for (const std::string& mismatch : layoutMismatches(program, t))
                ADD_FAILURE() << mismatch;
            checked += t.layout->members.size();
        }
    std::printf("[ numbers  ] %zu members of %zu + %zu structs and blocks checked\n", checked,
                player::bindings::kLayoutFile.structs.size(), lb::kLayoutFile.structs.size());
    // What the renderers upload or read back must be among them.
    auto has = [](const gl::GpuLayoutFile& file, const char* cppName) {
        for (const gl::GpuStruct& s : file.structs)
            if (std::string(s.cppName) == cppName)
                return true;
        return false;
    };
    for (const char* name : {"MaterialGpu", "NodeGpu", "ViewGpu", "TriangleStatsGpu", "FrameGpu"})
        EXPECT_TRUE(has(player::bindings::kLayoutFile, name)) << name;
    for (const char* name : {"LfdprPaperPointGpu", "LfdprPaperTriangleGpu", "LfdprPaperSamplingGpu", "LfdprPaperCountersGpu",
                             "LfdprFrameGpu", "LfdprVisibilityPointGpu", "LfdprVisibilityRecordGpu", "LfdprVisibilityDrawGpu",
                             "LfdprVisibilityCountersGpu", "LfdprCameraLineGpu"})
        EXPECT_TRUE(has(lb::kLayoutFile, name)) << name;
}

// The check itself can fail: C++ with displayX and displayY swapped (same size, same
// types, so a size-only check passes) and a struct one member short are both caught.
TEST_F(GpuLayoutTest, SwappedOrMissingMembersFailTheCheck)
{
    const Target real = [] {
        for (const Target& t : targets(lb::kLayoutFile))
            if (std::string(t.layout->cppName) == "LfdprFrameGpu")
                return t;
        return Target{};
    }();
    ASSERT_NE(real.layout, nullptr);
    const gl::Program program = buildProbe(probeSource(real));
    EXPECT_TRUE(layoutMismatches(program, real).empty());

    std::vector<gl::GpuMember> swapped(real.layout->members.begin(), real.layout->members.end());
    ASSERT_EQ(std::string(swapped[0].name) + swapped[1].name, "displayXdisplayY");
    std::swap(swapped[0].offset, swapped[1].offset);
    const gl::GpuStruct swappedStruct{real.layout->glslName, "LfdprFrameGpu (swapped)", real.layout->size, swapped};
    Target broken = real;
    broken.layout = &swappedStruct;
    EXPECT_EQ(sizeof(lb::LfdprFrameGpu), swappedStruct.size) << "the same size: a size check cannot see this";
    const std::vector<std::string> errors = layoutMismatches(program, broken);
    ASSERT_EQ(errors.size(), 2u);
    EXPECT_NE(errors[0].find("displayX offset is 0 in the driver, 16 in C++"), std::string::npos) << errors[0];
    EXPECT_NE(errors[1].find("displayY offset is 16 in the driver, 0 in C++"), std::string::npos) << errors[1];

    const std::vector<gl::GpuMember> shorter(real.layout->members.begin(), real.layout->members.end() - 1);
    const gl::GpuStruct shortStruct{real.layout->glslName, "LfdprFrameGpu (short)", real.layout->size, shorter};
    broken.layout = &shortStruct;
    const std::vector<std::string> missing = layoutMismatches(program, broken);
    ASSERT_EQ(missing.size(), 1u);
    EXPECT_NE(missing[0].find("member count"), std::string::npos) << missing[0];
}

// ---- Every block of every program the renderers build -------------------------------------

// A block as the C++ side allocates and binds it: binding point and bytes per array element
// (blocks holding one unsized array) or bytes in all (fixed blocks).
struct BlockUse {
    const char* name;
    uint32_t binding;
    size_t bytes;
    // A block of fixed members (`bytes`) followed by this unsized array (its name, its
    // element size): the array must start at `bytes`, with that stride.
    const char* trailingArray = nullptr;
    size_t trailingBytes = 0;
};

std::vector<BlockUse> sceneBlocks()
{
    namespace b = player::bindings;
    return {{"MaterialBuffer", b::kSsboMaterials, sizeof(b::MaterialGpu)},
            {"NodeBuffer", b::kSsboNodes, sizeof(b::NodeGpu)},
            {"ViewBuffer", b::kSsboViews, sizeof(b::ViewGpu)},
            {"TriangleStatsBuffer", b::kSsboTriangleStats, sizeof(TriangleStats)}, // uploaded as is
            {"FrameBlock", b::kUboFrame, sizeof(b::FrameGpu)}};
}

// Per-view-pixel words of either atomics path (both pipelines): depth|payload, depth, payload.
std::vector<BlockUse> viewWordBlocks(const player::LfdprConstants& k)
{
    return {{"ViewWords", k.ssboViewDepth, sizeof(uint64_t)},
            {"ViewDepth", k.ssboViewDepth, sizeof(uint32_t)},
            {"ViewColor", k.ssboViewWinner, sizeof(uint32_t)},
            {"ViewIndex", k.ssboViewWinner, sizeof(uint32_t)}};
}

std::vector<BlockUse> paperBlocks()
{
    const player::LfdprConstants& k = player::LfdprConstants::get();
    std::vector<BlockUse> blocks = sceneBlocks();
    for (const BlockUse& b : viewWordBlocks(k))
        blocks.push_back(b);
    blocks.insert(blocks.end(), {{"Points", k.ssboPoints, k.pointBytes},
                                 {"TriangleRecords", k.ssboTriangles, k.triangleRecordBytes},
                                 {"TriangleRecordsOut", k.ssboTriangles, k.triangleRecordBytes},
                                 {"TriangleSampling", k.ssboSampling, k.triangleSamplingBytes},
                                 {"TriangleSamplingOut", k.ssboSampling, k.triangleSamplingBytes},
                                 {"LfdprPaperCounters", k.ssboCounters, k.counterBytes},
                                 {"ViewInverse", k.ssboViewInverse, k.viewInverseBytes},
                                 {"LfdprFrameBlock", k.uboFrame, sizeof(lb::LfdprFrameGpu)},
                                 // std140 blocks stay active wherever they are declared.
                                 {"LfdprCameraLineBlock", k.uboCameraLine, sizeof(lb::LfdprCameraLineGpu)}});
    return blocks;
}

std::vector<BlockUse> visibilityBlocks()
{
    const player::LfdprConstants& k = player::LfdprConstants::get();
    std::vector<BlockUse> blocks = sceneBlocks();
    for (const BlockUse& b : viewWordBlocks(k))
        blocks.push_back(b);
    // The scene's own buffers bound as storage (player/scene/gpu_scene.cpp's streams).
    blocks.insert(blocks.end(), {{"SceneIndices", k.ssboIndices, sizeof(uint32_t)},
                                 {"ScenePositions", k.ssboPositions, sizeof(float)},
                                 {"SceneNormals", k.ssboNormals, sizeof(float)},
                                 {"SceneTangents", k.ssboTangents, sizeof(glm::vec4)},
                                 {"SceneUvs", k.ssboUvs, sizeof(glm::vec2)},
                                 {"Points", k.ssboPoints, k.compactPointBytes},
                                 {"Records", k.ssboRecords, k.recordBytes},
                                 {"Draws", k.ssboDraws, sizeof(lb::LfdprVisibilityDrawGpu)},
                                 {"Large", k.ssboLarge, k.largeEntryBytes},
                                 {"Workgroups", k.ssboWorkgroups, sizeof(lb::LfdprVisibilityWorkgroupGpu)},
                                 {"Repair", k.ssboRepair, k.repairBytes},
                                 {"LargeDispatch", k.ssboLargeDispatch, k.largeDispatchBytes},
                                 {"VisCounters", k.ssboVisCounters, k.visCounterBytes},
                                 {"ChunkMasks", k.ssboChunkMasks, sizeof(uint32_t)},
                                 // Counters and the per-group dispatches, then the tile lists.
                                 {"ShadeWork", k.ssboShadeWork,
                                  k.shadeCounterBytes + k.maxShadeGroups * sizeof(glm::uvec4), "groupTiles[0]",
                                  sizeof(uint32_t)},
                                 {"LfdprFrameBlock", k.uboFrame, sizeof(lb::LfdprFrameGpu)},
                                 {"LfdprCameraLineBlock", k.uboCameraLine, sizeof(lb::LfdprCameraLineGpu)}});
    return blocks;
}

struct ProgramCase {
    std::string label;
    std::vector<gl::ShaderStageSource> stages;
    std::vector<std::string> defines;
    std::vector<BlockUse> blocks;
};

// Every program the renderers and the EIA build, as they build it (the 64-bit-atomics
// variants only where the driver has the extensions).
std::vector<ProgramCase> programCases(const gl::GlCapabilities& caps)
{
    std::vector<ProgramCase> out;
    out.push_back({"mvr", {{GL_VERTEX_SHADER, "mvr.vert"}, {GL_FRAGMENT_SHADER, "mvr.frag"}}, {}, sceneBlocks()});
    if (caps.layerFromVertexShader)
        out.push_back({"mvr-layered", {{GL_VERTEX_SHADER, "mvr_layered.vert"}, {GL_FRAGMENT_SHADER, "mvr.frag"}}, {},
                       sceneBlocks()});
    out.push_back({"gstd reconstruction", {{GL_COMPUTE_SHADER, "gstd_reconstruct.comp"}}, {}, {}});
    out.push_back({"gstd panel phases", {{GL_COMPUTE_SHADER, "gstd_panel_phases.comp"}}, {}, {}});
    out.push_back({"gstd panel accumulation", {{GL_COMPUTE_SHADER, "gstd_panel_accumulate.comp"}}, {}, {}});
    out.push_back({"gstd panel resolve", {{GL_COMPUTE_SHADER, "gstd_panel_resolve.comp"}}, {}, {}});
    out.push_back({"eia", {{GL_COMPUTE_SHADER, "eia_construct.comp"}}, {}, {}});
    // The filtered modes read the sRGB encode table (EiaBuilder uploads srgbEncodeTable).
    for (uint32_t mode : {player::eia_bindings::kModeSpatial, player::eia_bindings::kModeView,
                          player::eia_bindings::kModeViewSpatial})
        out.push_back({"eia mode " + std::to_string(mode), {{GL_COMPUTE_SHADER, "eia_construct.comp"}},
                       {"EIA_MODE " + std::to_string(mode)},
                       {{"EncodeTable", player::eia_bindings::kSsboEncodeTable,
                         sizeof(float) * player::eia_bindings::kEncodeBuckets}}});
    out.push_back({"lfdpr paper points",
                   {{GL_VERTEX_SHADER, "lfdpr_paper_points.vert"},
                    {GL_GEOMETRY_SHADER, "lfdpr_paper_points.geom"},
                    {GL_FRAGMENT_SHADER, "lfdpr_paper_points.frag"}},
                   {},
                   paperBlocks()});
    out.push_back({"lfdpr paper dispatch", {{GL_COMPUTE_SHADER, "lfdpr_paper_dispatch.comp"}}, {}, paperBlocks()});
    out.push_back({"lfdpr compute points", {{GL_COMPUTE_SHADER, "lfdpr_visibility_points.comp"}}, {}, visibilityBlocks()});
    out.push_back({"lfdpr compute points (large)", {{GL_COMPUTE_SHADER, "lfdpr_visibility_points.comp"}}, {"LFDPR_LARGE_PASS 1"},
                   visibilityBlocks()});
    std::vector<std::vector<std::string>> atomics = {{}};
    if (caps.int64Atomics && caps.gpuShaderInt64)
        atomics.push_back({"LFDPR_INT64 1"});
    for (const std::vector<std::string>& defines : atomics) {
        const std::string path = defines.empty() ? " (32-bit)" : " (64-bit)";
        out.push_back({"lfdpr paper splat" + path, {{GL_COMPUTE_SHADER, "lfdpr_paper_splat.comp"}}, defines, paperBlocks()});
        out.push_back({"lfdpr paper resolve" + path, {{GL_COMPUTE_SHADER, "lfdpr_paper_resolve.comp"}}, defines,
                       paperBlocks()});
        out.push_back({"lfdpr visibility" + path, {{GL_COMPUTE_SHADER, "lfdpr_visibility_splat.comp"}}, defines,
                       visibilityBlocks()});
        out.push_back({"lfdpr shade" + path, {{GL_COMPUTE_SHADER, "lfdpr_visibility_shade.comp"}}, defines, visibilityBlocks()});
        std::vector<std::string> untextured = defines;
        untextured.push_back("LFD_TEXTURE_MASK 0x0u");
        out.push_back({"lfdpr shade untextured" + path, {{GL_COMPUTE_SHADER, "lfdpr_visibility_shade.comp"}}, untextured,
                       visibilityBlocks()});
    }
    out.push_back({"lfdpr index pass", {{GL_COMPUTE_SHADER, "lfdpr_visibility_splat.comp"}}, {"LFDPR_INDEX_PASS 1"},
                   visibilityBlocks()});
    out.push_back({"lfdpr tie pass", {{GL_COMPUTE_SHADER, "lfdpr_visibility_splat.comp"}},
                   {"LFDPR_WORK_GPU 1", "LFDPR_INDEX_PASS 1", "LFDPR_TIE_PASS 1"}, visibilityBlocks()});
    out.push_back({"lfdpr shade list", {{GL_COMPUTE_SHADER, "lfdpr_visibility_shade_list.comp"}}, {}, visibilityBlocks()});
    out.push_back({"lfdpr shade list (repair)", {{GL_COMPUTE_SHADER, "lfdpr_visibility_shade_list.comp"}}, {"LFDPR_REPAIR_LIST 1"},
                   visibilityBlocks()});
    out.push_back({"lfdpr compute points (alpha test)", {{GL_COMPUTE_SHADER, "lfdpr_visibility_points.comp"}},
                   {"LFDPR_ALPHA_TEST 1"}, visibilityBlocks()});
    out.push_back({"lfdpr repair dispatch", {{GL_COMPUTE_SHADER, "lfdpr_visibility_repair_dispatch.comp"}}, {},
                   visibilityBlocks()});
    // The GPU work shape (lfdpr_work_shape.glsl) declares the same blocks.
    const std::string gpu = "LFDPR_WORK_GPU 1";
    out.push_back({"lfdpr compute points (GPU work)", {{GL_COMPUTE_SHADER, "lfdpr_visibility_points.comp"}}, {gpu},
                   visibilityBlocks()});
    out.push_back({"lfdpr visibility (GPU work)", {{GL_COMPUTE_SHADER, "lfdpr_visibility_splat.comp"}}, {gpu},
                   visibilityBlocks()});
    out.push_back({"lfdpr shade (GPU work)", {{GL_COMPUTE_SHADER, "lfdpr_visibility_shade.comp"}}, {gpu}, visibilityBlocks()});
    out.push_back({"lfdpr shade list (GPU work)", {{GL_COMPUTE_SHADER, "lfdpr_visibility_shade_list.comp"}}, {gpu},
                   visibilityBlocks()});
    return out;
}

std::string resourceName(GLuint program, GLenum interface, GLuint index)
{
    char name[256] = {};
    glGetProgramResourceName(program, interface, index, sizeof(name), nullptr, name);
    return name;
}

TEST_F(GpuLayoutTest, EveryBlockOfEveryProgramHasTheCppBindingAndSize)
{
    size_t checked = 0;
    for (const ProgramCase& c : programCases(caps())) {
        SCOPED_TRACE(c.label);
        const gl::Program program(gl::buildProgram(c.stages, c.defines));
        for (const GLenum interface : {GLenum(GL_SHADER_STORAGE_BLOCK), GLenum(GL_UNIFORM_BLOCK)}) {
            GLint count = 0;
            glGetProgramInterfaceiv(program, interface, GL_ACTIVE_RESOURCES, &count);
            for (GLuint i = 0; i < GLuint(count); ++i) {
                const std::string name = resourceName(program, interface, i);
                const BlockUse* use = nullptr;
                for (const BlockUse& u : c.blocks)
                    use = name == u.name ? &u : use;
                if (!use) {
                    ADD_FAILURE() << "block " << name << " is not in this test's table: add it with the C++ "
                                  << "binding and size it is allocated with";
                    continue;
                }
                ++checked;
                EXPECT_EQ(resourceProperty(program, interface, i, GL_BUFFER_BINDING), GLint(use->binding)) << name;
                // One unsized array: its element stride; otherwise the block's size.
                GLint variables = 0, first = -1;
                variables = resourceProperty(program, interface, i, GL_NUM_ACTIVE_VARIABLES);
                const GLenum activeVariables = GL_ACTIVE_VARIABLES;
                if (variables > 0) {
                    // Room for every index: Mesa writes all GL_ACTIVE_VARIABLES whatever bufSize
                    // says (one int here overwrote the stack beside it).
                    std::vector<GLint> indices(static_cast<size_t>(variables));
                    glGetProgramResourceiv(program, interface, i, 1, &activeVariables, GLsizei(indices.size()), nullptr,
                                           indices.data());
                    first = indices[0];
                }
                // An unsized array of a basic type is the variable itself (array size 0, its
                // stride the array stride); one of structs is the top-level member.
                auto variable = [&](GLenum p) {
                    return resourceProperty(program, GL_BUFFER_VARIABLE, GLuint(first), p);
                };
                if (use->trailingArray) {
                    const GLuint array = glGetProgramResourceIndex(program, GL_BUFFER_VARIABLE, use->trailingArray);
                    if (array == GL_INVALID_INDEX)
                        continue; // the program does not touch the array: the fixed part is checked elsewhere
                    EXPECT_EQ(resourceProperty(program, GL_BUFFER_VARIABLE, array, GL_OFFSET), GLint(use->bytes))
                        << name << ": fixed part";
                    EXPECT_EQ(resourceProperty(program, GL_BUFFER_VARIABLE, array, GL_ARRAY_STRIDE),
                              GLint(use->trailingBytes))
                        << name << ": element stride";
                    continue;
                }
                const bool basicArray = interface == GL_SHADER_STORAGE_BLOCK && first >= 0 && variable(GL_ARRAY_SIZE) == 0;
                const bool structArray =
                    interface == GL_SHADER_STORAGE_BLOCK && first >= 0 && variable(GL_TOP_LEVEL_ARRAY_SIZE) == 0;
                if (basicArray)
                    EXPECT_EQ(variable(GL_ARRAY_STRIDE), GLint(use->bytes)) << name << ": element stride";
                else if (structArray)
                    EXPECT_EQ(variable(GL_TOP_LEVEL_ARRAY_STRIDE), GLint(use->bytes)) << name << ": element stride";
                else
                    EXPECT_EQ(resourceProperty(program, interface, i, GL_BUFFER_DATA_SIZE), GLint(use->bytes))
                        << name << ": size";
            }
        }
    }
    std::printf("[ numbers  ] %zu active blocks checked\n", checked);
    EXPECT_GT(checked, 40u);
}

// ---- Constants ------------------------------------------------------------------------------

// The generated constants are the #defines the shaders see (the run-time parser agrees), and
// the values formats/ defines on its own side match them.
TEST(GpuLayout, GeneratedConstantsAreTheShaderDefines)
{
    for (const gl::GpuLayoutFile* file : kLayoutFiles) {
        EXPECT_GT(file->defines.size(), 20u) << file->file;
        for (const gl::GpuDefine& d : file->defines)
            EXPECT_EQ(uint64_t(uint32_t(gl::shaderDefineValue(file->file, d.name))), d.value) << d.name;
    }
    namespace b = player::bindings;
    EXPECT_EQ(b::kStreamPosition, uint32_t(kStreamPosition));
    EXPECT_EQ(b::kStreamNormal, uint32_t(kStreamNormal));
    EXPECT_EQ(b::kStreamTangent, uint32_t(kStreamTangent));
    EXPECT_EQ(b::kStreamUv, uint32_t(kStreamUv));
    EXPECT_EQ(b::kAlphaOpaque, uint32_t(AlphaMode::Opaque));
    EXPECT_EQ(b::kAlphaMask, uint32_t(AlphaMode::Mask));
    EXPECT_EQ(b::kAlphaBlend, uint32_t(AlphaMode::Blend));
    EXPECT_EQ(lb::kMaxViews % 4, 0u) << "the camera-line block packs 4 offsets per vec4";
}

// ---- The generator --------------------------------------------------------------------------

struct GenResult {
    int status;
    std::string header, errors;
};

GenResult runGenerator(const std::string& glsl)
{
    // One directory per test: testOutputDir empties it, and ctest runs the tests in parallel.
    const fs::path dir =
        testOutputDir(std::string("gpu_layout_gen_") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    const fs::path input = dir / "test_bindings.glsl", output = dir / "test_bindings_gpu.h", log = dir / "log.txt";
    std::ofstream(input) << glsl;
    const std::string command = std::string("\"") + LFD_GPU_LAYOUT_GEN + "\" \"" + input.string() + "\" \"" +
                                output.string() + "\" lfd::test_gen TEST_ > \"" + log.string() + "\" 2>&1";
    GenResult r;
    r.status = std::system(command.c_str());
    std::ifstream h(output), l(log);
    std::stringstream hs, ls;
    hs << h.rdbuf();
    ls << l.rdbuf();
    r.header = hs.str();
    r.errors = ls.str();
    return r;
}

TEST(GpuLayoutGen, PadsWhereGlslAlignsAndNamesConstants)
{
    const GenResult r = runGenerator("#define TEST_SSBO_THINGS 3 // binding\n"
                                     "#define TEST_COUNT (2)\n"
                                     "#define TEST_MASK 0xFFu\n"
                                     "#define TEST_WEIGHT 0.25\n"
                                     "#define TEST_SLOPE -1.5\n"
                                     "#define TEST_NEGATIVE_INT -3\n"
                                     "struct ThingGpu {\n"
                                     "    vec3 position; // xyz\n"
                                     "    vec4 colour;\n"
                                     "    float weights[4];\n"
                                     "};\n"
                                     "uint helper(uint x) { return x * 2u; }\n"
                                     "layout(std140, binding = TEST_SSBO_THINGS) uniform ThingBlock {\n"
                                     "    vec4 rows[TEST_SSBO_THINGS + 1];\n"
                                     "    uint count;\n"
                                     "} u_thing;\n");
    ASSERT_EQ(r.status, 0) << r.errors;
    EXPECT_NE(r.header.find("inline constexpr uint32_t kSsboThings = 3; // TEST_SSBO_THINGS"), std::string::npos);
    EXPECT_NE(r.header.find("inline constexpr uint32_t kMask = 0xFFu;"), std::string::npos);
    EXPECT_EQ(r.header.find("kCount"), std::string::npos) << "an expression is not a constant";
    // Decimals, negative ones too (polynomial coefficients), become doubles.
    EXPECT_NE(r.header.find("inline constexpr double kWeight = 0.25;"), std::string::npos) << r.header;
    EXPECT_NE(r.header.find("inline constexpr double kSlope = -1.5;"), std::string::npos) << r.header;
    EXPECT_EQ(r.header.find("kNegativeInt"), std::string::npos) << "a negative integer is not a uint32_t constant";
    // std430: vec3 at 0 (12 bytes), vec4 aligned to 16: 4 bytes of padding; 48 bytes in all.
    EXPECT_NE(r.header.find("glm::vec3 position; // offset 0: xyz\n    uint32_t pad_0_[1]; // std430 alignment\n"
                            "    glm::vec4 colour; // offset 16"),
              std::string::npos)
        << r.header;
    EXPECT_NE(r.header.find("static_assert(sizeof(ThingGpu) == 48);"), std::string::npos) << r.header;
    // std140 block: vec4 rows[3 + 1] at 0, count at 64, size rounded up to 16.
    EXPECT_NE(r.header.find("glm::vec4 rows[4]; // offset 0"), std::string::npos) << r.header;
    EXPECT_NE(r.header.find("static_assert(sizeof(ThingGpu) == 80);"), std::string::npos) << r.header;
    EXPECT_NE(r.header.find("{\"ThingBlock\", lfd::gl::GpuInterface::Uniform, \"std140\", 3, &kStructs[1], "
                            "nullptr, nullptr, \"u_thing\"}"),
              std::string::npos)
        << r.header;
    EXPECT_EQ(r.header.find("helper"), std::string::npos) << "functions are not layouts";
}

TEST(GpuLayoutGen, RefusesLayoutsCppCannotMirrorWithFileAndLine)
{
    const std::pair<const char*, const char*> cases[] = {
        {"struct A {\n    mat3 m;\n};\n", ":2: error: member 'm' has type 'mat3'"},
        {"struct A {\n    vec3 v[2];\n};\n", ":2: error: array 'v' has a 16-byte std430 stride but a 12-byte C++ element"},
        {"layout(std140, binding = 0) uniform B {\n    float f[4];\n};\n", ":2: error: array 'f' has a 16-byte std140"},
        {"layout(binding = 0) buffer B {\n    uint x;\n};\n", ":1: error: block B needs an explicit std140 or std430"},
        {"struct A {\n    uint x;\n};\nlayout(std430) buffer B {\n    A a[];\n};\n", ":4: error: block B needs an explicit binding"},
        {"struct A {\n    uint x[UNKNOWN];\n};\n", ":2: error: 'UNKNOWN' is not an integer constant"},
    };
    for (const auto& [glsl, message] : cases) {
        const GenResult r = runGenerator(glsl);
        EXPECT_NE(r.status, 0) << glsl;
        EXPECT_NE(r.errors.find(message), std::string::npos) << glsl << "\n" << r.errors;
    }
}

} // namespace
} // namespace lfd::test
