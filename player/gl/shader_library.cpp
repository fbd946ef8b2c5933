#include "shader_library.h"

#include "gl_handles.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cstring>
#include <regex>
#include <set>
#include <sstream>

namespace lfd::gl {

std::string_view shaderSource(std::string_view name)
{
    const EmbeddedShader* table = embeddedShaders();
    for (size_t i = 0; i < embeddedShaderCount(); ++i)
        if (name == table[i].name)
            return {table[i].source, table[i].size};
    throw GlError("shaders/" + std::string(name) + ": no such embedded shader");
}

std::vector<std::string> shaderNames()
{
    std::vector<std::string> names;
    const EmbeddedShader* table = embeddedShaders();
    for (size_t i = 0; i < embeddedShaderCount(); ++i)
        names.emplace_back(table[i].name);
    return names;
}

namespace {

std::string_view trimLeft(std::string_view s)
{
    size_t i = 0;
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t'))
        ++i;
    return s.substr(i);
}

bool startsWithDirective(std::string_view line, std::string_view directive)
{
    line = trimLeft(line);
    if (line.empty() || line[0] != '#')
        return false;
    line = trimLeft(line.substr(1));
    return line.substr(0, directive.size()) == directive &&
           (line.size() == directive.size() || line[directive.size()] == ' ' ||
            line[directive.size()] == '\t' || line[directive.size()] == '"');
}

// Expands #include recursively. Every file gets its own source-string number (its index
// in `files`) and a #line marker wherever the text switches files, so the driver reports
// (file number, line in that file) and mapCompilerMessage can name the file.
class Preprocessor {
public:
    Preprocessor(const ShaderLookup& lookup, const std::vector<std::string>& defines)
        : lookup_(lookup), defines_(defines)
    {
    }

    PreprocessedShader run(std::string_view name)
    {
        expand(std::string(name), true);
        return {std::move(out_), std::move(files_)};
    }

private:
    std::string load(const std::string& name, const std::string& from, int line)
    {
        if (std::optional<std::string> text = lookup_(name))
            return *text;
        if (from.empty())
            throw GlError("shaders/" + name + ": no such shader file");
        throw GlError("shaders/" + from + ":" + std::to_string(line) + ": included file \"" +
                      name + "\" not found");
    }

    void expand(const std::string& name, bool isMain, const std::string& from = {},
                int fromLine = 0)
    {
        const std::string text = load(name, from, fromLine);
        const size_t id = files_.size();
        files_.push_back(name);
        included_.insert(name);
        if (!isMain)
            out_ += "#line 1 " + std::to_string(id) + "\n";

        bool versionSeen = false;
        std::istringstream lines(text);
        std::string line;
        int lineNo = 0;
        while (std::getline(lines, line)) {
            ++lineNo;
            if (startsWithDirective(line, "version")) {
                if (!isMain)
                    throw GlError("shaders/" + name + ":" + std::to_string(lineNo) +
                                  ": #version in an included file");
                versionSeen = true;
                out_ += line + "\n";
                for (const std::string& define : defines_)
                    out_ += "#define " + define + "\n";
                out_ += "#line " + std::to_string(lineNo + 1) + " " + std::to_string(id) + "\n";
                continue;
            }
            if (startsWithDirective(line, "include")) {
                const size_t open = line.find('"');
                const size_t close = open == std::string::npos ? open : line.find('"', open + 1);
                if (close == std::string::npos || close == open + 1)
                    throw GlError("shaders/" + name + ":" + std::to_string(lineNo) +
                                  ": malformed #include (expected #include \"file\")");
                const std::string target = line.substr(open + 1, close - open - 1);
                if (!included_.count(target)) {
                    expand(target, false, name, lineNo);
                    out_ += "#line " + std::to_string(lineNo + 1) + " " + std::to_string(id) + "\n";
                } else {
                    out_ += "\n"; // already included once: keep the line numbering
                }
                continue;
            }
            out_ += line + "\n";
        }
        if (isMain && !versionSeen)
            throw GlError("shaders/" + name + ":1: missing #version directive");
    }

    const ShaderLookup& lookup_;
    const std::vector<std::string>& defines_;
    std::vector<std::string> files_;
    std::set<std::string> included_;
    std::string out_;
};

const char* stageName(unsigned type)
{
    switch (type) {
    case GL_VERTEX_SHADER: return "vertex";
    case GL_GEOMETRY_SHADER: return "geometry";
    case GL_FRAGMENT_SHADER: return "fragment";
    case GL_COMPUTE_SHADER: return "compute";
    default: return "unknown";
    }
}

std::string infoLog(unsigned object, bool program)
{
    GLint length = 0;
    if (program)
        glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
    else
        glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    std::string log(size_t(std::max(length, 1)), '\0');
    if (program)
        glGetProgramInfoLog(object, length, nullptr, log.data());
    else
        glGetShaderInfoLog(object, length, nullptr, log.data());
    log.resize(std::strlen(log.c_str()));
    return log;
}

} // namespace

PreprocessedShader preprocessShader(std::string_view name, const ShaderLookup& lookup,
                                    const std::vector<std::string>& defines)
{
    return Preprocessor(lookup, defines).run(name);
}

PreprocessedShader preprocessShader(std::string_view name, const std::vector<std::string>& defines)
{
    const ShaderLookup embedded = [](std::string_view file) -> std::optional<std::string> {
        const EmbeddedShader* table = embeddedShaders();
        for (size_t i = 0; i < embeddedShaderCount(); ++i)
            if (file == table[i].name)
                return std::string(table[i].source, table[i].size);
        return std::nullopt;
    };
    return preprocessShader(name, embedded, defines);
}

std::string mapCompilerMessage(const std::string& logLine, const std::vector<std::string>& files)
{
    // Mesa: "0:12(3): error: ..."; NVIDIA: "0(12) : error C1008: ...".
    static const std::regex mesa(R"(^\s*(\d+):(\d+)\(\d+\):\s*(.*)$)");
    static const std::regex nvidia(R"(^\s*(\d+)\((\d+)\)\s*:\s*(.*)$)");
    std::smatch m;
    if (!std::regex_match(logLine, m, mesa) && !std::regex_match(logLine, m, nvidia))
        return {};
    const size_t fileId = std::stoul(m[1].str());
    const std::string file = fileId < files.size() ? files[fileId] : "<source " + m[1].str() + ">";
    return "shaders/" + file + ":" + m[2].str() + ": " + m[3].str();
}

unsigned compileShader(unsigned type, const PreprocessedShader& source)
{
    Shader shader(glCreateShader(type));
    const char* text = source.text.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok == GL_TRUE)
        return shader.release();

    // Report the first error (warnings only if there is no error line), one line.
    const std::string log = infoLog(shader, false);
    std::istringstream lines(log);
    std::string line, first, firstError;
    int errors = 0;
    while (std::getline(lines, line)) {
        const std::string mapped = mapCompilerMessage(line, source.files);
        if (mapped.empty())
            continue;
        if (first.empty())
            first = mapped;
        if (mapped.find("error") != std::string::npos) {
            if (firstError.empty())
                firstError = mapped;
            ++errors;
        }
    }
    std::string message = !firstError.empty() ? firstError : first;
    if (message.empty()) {
        const std::string main = source.files.empty() ? "<unknown>" : source.files.front();
        std::string flat = log;
        std::replace(flat.begin(), flat.end(), '\n', ' ');
        message = "shaders/" + main + ": " + stageName(type) + " shader failed to compile: " + flat;
    }
    if (errors > 1)
        message += " (and " + std::to_string(errors - 1) + " more errors)";
    throw GlError(message);
}

unsigned buildProgram(const std::vector<ShaderStageSource>& stages,
                      const std::vector<std::string>& defines)
{
    std::vector<Shader> shaders;
    std::string names;
    for (const ShaderStageSource& stage : stages) {
        shaders.emplace_back(compileShader(stage.type, preprocessShader(stage.file, defines)));
        names += (names.empty() ? "" : " + ") + ("shaders/" + stage.file);
    }
    Program program(glCreateProgram());
    for (const Shader& s : shaders)
        glAttachShader(program, s);
    glLinkProgram(program);
    for (const Shader& s : shaders)
        glDetachShader(program, s);
    GLint ok = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) {
        std::string log = infoLog(program, true);
        const size_t end = log.find('\n');
        log = log.substr(0, end);
        throw GlError(names + ": link failed: " + log);
    }
    return program.release();
}

long shaderDefineValue(std::string_view file, std::string_view name)
{
    std::istringstream lines{std::string(shaderSource(file))};
    std::string line;
    while (std::getline(lines, line)) {
        if (!startsWithDirective(line, "define"))
            continue;
        std::istringstream words(line);
        std::string hash, key, value;
        words >> hash >> key >> value;
        if (hash == "#define" && key == name && !value.empty())
            return std::stol(value, nullptr, 0);
    }
    throw GlError("shaders/" + std::string(file) + ": no #define " + std::string(name));
}

void dispatchCovering(unsigned program, uint32_t x, uint32_t y, uint32_t z)
{
    GLint local[3] = {1, 1, 1};
    glGetProgramiv(program, GL_COMPUTE_WORK_GROUP_SIZE, local);
    auto groups = [](uint32_t n, GLint size) { return (n + uint32_t(size) - 1) / uint32_t(size); };
    glDispatchCompute(groups(x, local[0]), groups(y, local[1]), groups(z, local[2]));
}

} // namespace lfd::gl
