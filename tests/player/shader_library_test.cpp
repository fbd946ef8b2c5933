// Shader library: embedding, #include resolution, error mapping back to file:line, and the
// C++ mirror of shaders/scene_bindings.glsl (constants and struct layouts).
#include "gl_test_support.h"

#include "scene_bindings.h"
#include "shader_library.h"

#include "lfd/scene.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <cstddef>
#include <fstream>
#include <map>
#include <sstream>

namespace lfd::test {
namespace {

std::string readFile(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// Sources from `files` first, then the embedded table.
gl::ShaderLookup lookupWith(const std::map<std::string, std::string>& files)
{
    return [files](std::string_view name) -> std::optional<std::string> {
        if (auto it = files.find(std::string(name)); it != files.end())
            return it->second;
        for (size_t i = 0; i < gl::embeddedShaderCount(); ++i)
            if (name == gl::embeddedShaders()[i].name)
                return std::string(gl::embeddedShaders()[i].source, gl::embeddedShaders()[i].size);
        return std::nullopt;
    };
}

TEST(ShaderLibrary, EveryShaderFileIsEmbeddedVerbatim)
{
    size_t onDisk = 0;
    for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(LFD_SOURCE_DIR) / "shaders")) {
        const std::string name = entry.path().filename().string();
        ++onDisk;
        EXPECT_EQ(gl::shaderSource(name), readFile(entry.path())) << name;
    }
    EXPECT_EQ(onDisk, gl::embeddedShaderCount());
    EXPECT_THROW(gl::shaderSource("no_such_file.glsl"), gl::GlError);
}

TEST(ShaderLibrary, IncludesResolveOnceWithLineMarkers)
{
    const gl::PreprocessedShader s = gl::preprocessShader("mvr.frag", {"LFD_TEST_DEFINE 7"});
    ASSERT_EQ(s.files.size(), 4u);
    EXPECT_EQ(s.files[0], "mvr.frag");
    EXPECT_EQ(s.files[1], "scene_bindings.glsl");
    EXPECT_EQ(s.files[2], "pbr_shading.glsl");
    EXPECT_EQ(s.files[3], "material_shading.glsl");
    EXPECT_EQ(s.text.find("#include"), std::string::npos);
    EXPECT_NE(s.text.find("struct MaterialGpu"), std::string::npos);
    EXPECT_EQ(s.text.find("struct MaterialGpu"), s.text.rfind("struct MaterialGpu")) << "included twice";
    EXPECT_EQ(s.text.rfind("#version 450 core", 0), 0u) << "#version must stay first";
    EXPECT_NE(s.text.find("#define LFD_TEST_DEFINE 7\n#line 2 0\n"), std::string::npos);
    EXPECT_NE(s.text.find("#line 1 1\n"), std::string::npos);
    // mvr.vert includes mvr_vertex.glsl, which includes scene_bindings.glsl.
    const gl::PreprocessedShader v = gl::preprocessShader("mvr.vert");
    EXPECT_EQ(v.files, (std::vector<std::string>{"mvr.vert", "mvr_vertex.glsl", "scene_bindings.glsl"}));
}

TEST(ShaderLibrary, MissingIncludeNamesFileAndLine)
{
    const auto lookup = lookupWith({{"a.frag", "#version 450 core\n\n#include \"nope.glsl\"\n"}});
    try {
        gl::preprocessShader("a.frag", lookup);
        FAIL() << "missing include accepted";
    } catch (const gl::GlError& e) {
        EXPECT_STREQ(e.what(), "shaders/a.frag:3: included file \"nope.glsl\" not found");
    }
    EXPECT_THROW(gl::preprocessShader("b.frag", lookupWith({{"b.frag", "void main() {}\n"}})), gl::GlError);
}

TEST(ShaderLibrary, CompilerMessagesMapToFiles)
{
    const std::vector<std::string> files = {"main.frag", "inc.glsl"};
    EXPECT_EQ(gl::mapCompilerMessage("1:12(3): error: `x' undeclared", files),
              "shaders/inc.glsl:12: error: `x' undeclared");
    EXPECT_EQ(gl::mapCompilerMessage("0(7) : error C1008: undefined variable \"y\"", files),
              "shaders/main.frag:7: error C1008: undefined variable \"y\"");
    EXPECT_EQ(gl::mapCompilerMessage("some other text", files), "");
}

class ShaderCompileTest : public GlTest {};

std::string compileError(const std::string& main, const std::map<std::string, std::string>& files)
{
    try {
        const GLuint shader = gl::compileShader(GL_FRAGMENT_SHADER, gl::preprocessShader(main, lookupWith(files)));
        glDeleteShader(shader);
    } catch (const gl::GlError& e) {
        return e.what();
    }
    return "";
}

TEST_F(ShaderCompileTest, ErrorInMainFileNamesFileAndLine)
{
    const std::string error = compileError(
        "broken.frag", {{"broken.frag", "#version 450 core\n"
                                        "// an intentionally broken shader\n"
                                        "#include \"scene_bindings.glsl\"\n"
                                        "layout(location = 0) out vec4 o_color;\n"
                                        "void main()\n"
                                        "{\n"
                                        "    o_color = vec4(undefinedThing, 1.0);\n"
                                        "}\n"}});
    EXPECT_EQ(error.rfind("shaders/broken.frag:7: ", 0), 0u) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << "one line: " << error;
}

TEST_F(ShaderCompileTest, ErrorInIncludedFileNamesThatFile)
{
    const std::string error = compileError(
        "main.frag", {{"main.frag", "#version 450 core\n"
                                    "#include \"scene_bindings.glsl\"\n"
                                    "#include \"broken_include.glsl\"\n"
                                    "layout(location = 0) out vec4 o_color;\n"
                                    "void main() { o_color = helper(); }\n"},
                      {"broken_include.glsl", "// helper with a type error on line 4\n"
                                              "vec4 helper()\n"
                                              "{\n"
                                              "    return vec3(1.0);\n"
                                              "}\n"}});
    EXPECT_EQ(error.rfind("shaders/broken_include.glsl:4: ", 0), 0u) << error;
}

TEST_F(ShaderCompileTest, LineNumbersResumeAfterAnInclude)
{
    const std::string error = compileError(
        "main.frag", {{"main.frag", "#version 450 core\n"
                                    "#include \"scene_bindings.glsl\"\n"
                                    "#include \"pbr_shading.glsl\"\n"
                                    "layout(location = 0) out vec4 o_color;\n"
                                    "void main()\n"
                                    "{\n"
                                    "    o_color = vec4(1.0)\n"
                                    "}\n"}});
    EXPECT_EQ(error.rfind("shaders/main.frag:8: ", 0), 0u) << error; // missing ';' seen at '}'
}

TEST_F(ShaderCompileTest, EveryRasterProgramLinks)
{
    for (const char* vert : {"mvr.vert", "mvr_layered.vert"}) {
        if (std::string(vert) == "mvr_layered.vert" && !caps().layerFromVertexShader)
            continue;
        const GLuint program = gl::buildProgram({{GL_VERTEX_SHADER, vert}, {GL_FRAGMENT_SHADER, "mvr.frag"}});
        EXPECT_NE(program, 0u);
        glDeleteProgram(program);
    }
}

// magnum style: the constants are defined once in GLSL; C++ must agree.
TEST(SceneBindings, CppConstantsMatchGlsl)
{
    namespace b = player::bindings;
    const char* file = "scene_bindings.glsl";
    const std::pair<const char*, long> expected[] = {
        {"LFD_ATTRIB_POSITION", b::kAttribPosition},
        {"LFD_ATTRIB_NORMAL", b::kAttribNormal},
        {"LFD_ATTRIB_TANGENT", b::kAttribTangent},
        {"LFD_ATTRIB_UV", b::kAttribUv},
        {"LFD_SSBO_MATERIALS", b::kSsboMaterials},
        {"LFD_SSBO_NODES", b::kSsboNodes},
        {"LFD_SSBO_VIEWS", b::kSsboViews},
        {"LFD_SSBO_TRIANGLE_STATS", b::kSsboTriangleStats},
        {"LFD_UBO_FRAME", b::kUboFrame},
        {"LFD_UNIT_BASE_COLOR", b::kUnitBaseColor},
        {"LFD_UNIT_METALLIC_ROUGHNESS", b::kUnitMetallicRoughness},
        {"LFD_UNIT_NORMAL", b::kUnitNormal},
        {"LFD_UNIT_OCCLUSION", b::kUnitOcclusion},
        {"LFD_UNIT_EMISSIVE", b::kUnitEmissive},
        {"LFD_LOC_NODE", b::kLocNode},
        {"LFD_LOC_MATERIAL", b::kLocMaterial},
        {"LFD_LOC_VIEW", b::kLocView},
        {"LFD_LOC_STREAMS", b::kLocStreams},
        {"LFD_MATERIAL_BASE_COLOR_TEXTURE", b::kMaterialBaseColorTexture},
        {"LFD_MATERIAL_METALLIC_ROUGHNESS_TEXTURE", b::kMaterialMetallicRoughnessTexture},
        {"LFD_MATERIAL_NORMAL_TEXTURE", b::kMaterialNormalTexture},
        {"LFD_MATERIAL_OCCLUSION_TEXTURE", b::kMaterialOcclusionTexture},
        {"LFD_MATERIAL_EMISSIVE_TEXTURE", b::kMaterialEmissiveTexture},
        {"LFD_MATERIAL_DOUBLE_SIDED", b::kMaterialDoubleSided},
        {"LFD_ALPHA_OPAQUE", b::kAlphaOpaque},
        {"LFD_ALPHA_MASK", b::kAlphaMask},
        {"LFD_ALPHA_BLEND", b::kAlphaBlend},
        {"LFD_STREAM_POSITION", kStreamPosition},
        {"LFD_STREAM_NORMAL", kStreamNormal},
        {"LFD_STREAM_TANGENT", kStreamTangent},
        {"LFD_STREAM_UV", kStreamUv},
    };
    for (const auto& [name, value] : expected)
        EXPECT_EQ(gl::shaderDefineValue(file, name), value) << name;
    EXPECT_EQ(b::kAlphaMask, uint32_t(AlphaMode::Mask));
    EXPECT_EQ(b::kAlphaBlend, uint32_t(AlphaMode::Blend));
    EXPECT_THROW(gl::shaderDefineValue(file, "LFD_NOT_DEFINED"), gl::GlError);
}

// Struct layouts as the driver sees them (program interface queries on a compute shader
// that touches every member) must match the C++ structs' offsets and sizes.
TEST_F(ShaderCompileTest, GpuStructLayoutsMatchCpp)
{
    const auto lookup = lookupWith({{"layout_probe.comp", R"(#version 450 core
#include "scene_bindings.glsl"
layout(local_size_x = 1) in;
layout(std430, binding = 7) writeonly buffer Probe { vec4 probe; };
void main()
{
    MaterialGpu m = materials[0];
    NodeGpu n = nodes[0];
    ViewGpu v = views[0];
    TriangleStatsGpu t = triangleStats[0];
    probe = m.baseColorFactor + m.emissiveCutoff + m.params + vec4(m.flags + m.alphaMode + m.pad0 + m.pad1)
          + n.sceneFromObject[0] + n.normalFromObject[0] + v.clipFromScene[0] + v.eyeScene
          + vec4(t.areaWorld + t.areaTexture + t.texelCount + t.sizeUv + t.texPerWorld + float(t.flags))
          + u_frame.lightDirScene + u_frame.lightColor + u_frame.ambientColor + u_frame.background
          + vec4(u_frame.viewCount + u_frame.viewWidth + u_frame.viewHeight + u_frame.framePad);
}
)"}});
    const GLuint shader = gl::compileShader(GL_COMPUTE_SHADER, gl::preprocessShader("layout_probe.comp", lookup));
    const GLuint program = glCreateProgram();
    glAttachShader(program, shader);
    glLinkProgram(program);
    glDeleteShader(shader);
    GLint linked = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &linked);
    ASSERT_EQ(linked, GL_TRUE);

    auto query = [&](GLenum interface, const char* name, GLenum property) {
        const GLuint index = glGetProgramResourceIndex(program, interface, name);
        EXPECT_NE(index, GL_INVALID_INDEX) << name;
        GLint value = -1;
        if (index != GL_INVALID_INDEX)
            glGetProgramResourceiv(program, interface, index, 1, &property, 1, nullptr, &value);
        return value;
    };
    namespace b = player::bindings;
    auto offset = [&](const char* name) { return query(GL_BUFFER_VARIABLE, name, GL_OFFSET); };
    auto stride = [&](const char* name) { return query(GL_BUFFER_VARIABLE, name, GL_TOP_LEVEL_ARRAY_STRIDE); };
    EXPECT_EQ(offset("materials[0].emissiveCutoff"), GLint(offsetof(b::MaterialGpu, emissiveCutoff)));
    EXPECT_EQ(offset("materials[0].params"), GLint(offsetof(b::MaterialGpu, params)));
    EXPECT_EQ(offset("materials[0].flags"), GLint(offsetof(b::MaterialGpu, flags)));
    EXPECT_EQ(offset("materials[0].alphaMode"), GLint(offsetof(b::MaterialGpu, alphaMode)));
    EXPECT_EQ(stride("materials[0].flags"), GLint(sizeof(b::MaterialGpu)));
    EXPECT_EQ(offset("nodes[0].normalFromObject"), GLint(offsetof(b::NodeGpu, normalFromObject)));
    EXPECT_EQ(stride("nodes[0].normalFromObject"), GLint(sizeof(b::NodeGpu)));
    EXPECT_EQ(offset("views[0].eyeScene"), GLint(offsetof(b::ViewGpu, eyeScene)));
    EXPECT_EQ(stride("views[0].eyeScene"), GLint(sizeof(b::ViewGpu)));
    EXPECT_EQ(offset("triangleStats[0].flags"), GLint(offsetof(TriangleStats, flags)));
    EXPECT_EQ(stride("triangleStats[0].flags"), GLint(sizeof(TriangleStats)));
    auto uniformOffset = [&](const char* name) { return query(GL_UNIFORM, name, GL_OFFSET); };
    EXPECT_EQ(uniformOffset("FrameBlock.background"), GLint(offsetof(b::FrameGpu, background)));
    EXPECT_EQ(uniformOffset("FrameBlock.viewCount"), GLint(offsetof(b::FrameGpu, viewCount)));
    EXPECT_EQ(uniformOffset("FrameBlock.framePad"), GLint(offsetof(b::FrameGpu, framePad)));
    EXPECT_EQ(query(GL_UNIFORM_BLOCK, "FrameBlock", GL_BUFFER_DATA_SIZE), GLint(sizeof(b::FrameGpu)));
    EXPECT_EQ(query(GL_UNIFORM_BLOCK, "FrameBlock", GL_BUFFER_BINDING), GLint(b::kUboFrame));
    EXPECT_EQ(query(GL_SHADER_STORAGE_BLOCK, "ViewBuffer", GL_BUFFER_BINDING), GLint(b::kSsboViews));
    glDeleteProgram(program);
}

} // namespace
} // namespace lfd::test
