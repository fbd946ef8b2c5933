// Shaders embedded at build time (cmake/embed_shaders.cmake) and compiled from them.
//
// Sources are real files under shaders/. `#include "file.glsl"` lines are resolved from
// the embedded table (each file at most once per program, like #pragma once), and every
// file gets its own GLSL source-string number through `#line`, so driver messages can be
// mapped back: compile errors are thrown as GlError("shaders/<file>:<line>: <message>").
// Variants are made by prepending #defines after the #version line (magnum style).
#pragma once

#include "gl_context.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lfd::gl {

struct EmbeddedShader {
    const char* name;   // path relative to shaders/, e.g. "mvr.vert"
    const char* source; // NUL-terminated text
    size_t size;        // bytes, without the terminator
};

// The generated table (null-terminated, sorted by name) and its length.
const EmbeddedShader* embeddedShaders();
size_t embeddedShaderCount();

// Source text of an embedded file; throws GlError for an unknown name.
std::string_view shaderSource(std::string_view name);
std::vector<std::string> shaderNames();

// The text handed to the driver: includes expanded, defines inserted, #line markers.
struct PreprocessedShader {
    std::string text;
    std::vector<std::string> files; // GLSL source-string number -> file name
};
// `defines` are lines such as "LFD_LAYERED 1" (emitted as "#define LFD_LAYERED 1").
PreprocessedShader preprocessShader(std::string_view name,
                                    const std::vector<std::string>& defines = {});
// Same, with sources from `lookup` (tests inject broken files; fall back to shaderSource).
using ShaderLookup = std::function<std::optional<std::string>(std::string_view name)>;
PreprocessedShader preprocessShader(std::string_view name, const ShaderLookup& lookup,
                                    const std::vector<std::string>& defines = {});

// Maps one driver info-log line to "shaders/<file>:<line>: <message>" (Mesa "0:12(3): ..."
// and NVIDIA "0(12) : ..." formats); returns an empty string if the line is not a message.
std::string mapCompilerMessage(const std::string& logLine, const std::vector<std::string>& files);

struct ShaderStageSource {
    unsigned type;    // GL_VERTEX_SHADER, GL_FRAGMENT_SHADER, GL_COMPUTE_SHADER, ...
    std::string file; // embedded file name
};

// Compiles and links a program; throws GlError (one line, first error, file:line). The
// caller owns the returned name: hold it in a gl::Program (gl_handles.h).
unsigned buildProgram(const std::vector<ShaderStageSource>& stages,
                      const std::vector<std::string>& defines = {});
// Compiles one preprocessed stage; returns the shader name (owned by the caller, as a
// gl::Shader) or throws GlError.
unsigned compileShader(unsigned type, const PreprocessedShader& source);

// Integer value of `#define NAME value` in an embedded file (tests check C++ mirrors).
long shaderDefineValue(std::string_view file, std::string_view name);

// Dispatches the current compute program over at least x * y * z invocations: the group
// counts come from the program's own local size (GL_COMPUTE_WORK_GROUP_SIZE), so the
// size is written only in the shader's layout(local_size_*) line.
void dispatchCovering(unsigned program, uint32_t x, uint32_t y, uint32_t z);

} // namespace lfd::gl
