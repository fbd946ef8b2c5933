// Shader library: embedding, #include resolution, error mapping back to file:line, and
// programs linking. (The C++ side of the bindings files is checked in gpu_layout_test.cpp.)
#include "gl_handles.h"
#include "gl_test_support.h"

#include "shader_library.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

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
    // scene_bindings.glsl includes triangle_stats_bindings.glsl and pbr_shading.glsl includes
    // srgb.glsl, so each comes right after its includer; material_shading.glsl includes
    // texture_transform.glsl.
    EXPECT_EQ(s.files, (std::vector<std::string>{"mvr.frag", "scene_bindings.glsl", "triangle_stats_bindings.glsl",
                                                 "pbr_shading.glsl", "srgb.glsl", "material_shading.glsl",
                                                 "texture_transform.glsl"}));
    EXPECT_EQ(s.text.find("#include"), std::string::npos);
    EXPECT_NE(s.text.find("struct MaterialGpu"), std::string::npos);
    EXPECT_EQ(s.text.find("struct MaterialGpu"), s.text.rfind("struct MaterialGpu")) << "included twice";
    EXPECT_EQ(s.text.rfind("#version 450 core", 0), 0u) << "#version must stay first";
    EXPECT_NE(s.text.find("#define LFD_TEST_DEFINE 7\n#line 2 0\n"), std::string::npos);
    EXPECT_NE(s.text.find("#line 1 1\n"), std::string::npos);
    // mvr.vert includes mvr_vertex.glsl, which includes scene_bindings.glsl.
    const gl::PreprocessedShader v = gl::preprocessShader("mvr.vert");
    EXPECT_EQ(v.files, (std::vector<std::string>{"mvr.vert", "mvr_vertex.glsl", "scene_bindings.glsl",
                                                 "triangle_stats_bindings.glsl"}));
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
        const gl::Shader shader(gl::compileShader(GL_FRAGMENT_SHADER, gl::preprocessShader(main, lookupWith(files))));
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
        const gl::Program program(gl::buildProgram({{GL_VERTEX_SHADER, vert}, {GL_FRAGMENT_SHADER, "mvr.frag"}}));
        EXPECT_NE(program.get(), 0u);
    }
}

} // namespace
} // namespace lfd::test
