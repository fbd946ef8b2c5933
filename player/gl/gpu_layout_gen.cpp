// lfd_gpu_layout_gen: writes the C++ side of one shaders/*_bindings.glsl file at build
// time, so a GPU layout is written once, in GLSL:
//
//   lfd_gpu_layout_gen INPUT.glsl OUTPUT.h NAMESPACE PREFIX [DEPFILE]
//
// * every `#define NAME <integer>` becomes `inline constexpr uint32_t kName` (PREFIX
//   stripped from NAME, the rest in camel case: LFDPR_SSBO_POINTS -> kSsboPoints), and a
//   `#define NAME <decimal>` (a leading minus allowed) a double;
// * every `struct` (std430: the structs are elements of storage buffers) and every block
//   with fixed members (`layout(std140|std430, binding = B) uniform|buffer Name {...}`)
//   becomes a C++ struct of glm types with the GLSL offsets (padding members where the
//   GLSL alignment leaves gaps), checked by static_asserts; a block's C++ name is its
//   name with "Block" replaced by (or "Gpu" appended): LfdprFrameBlock -> LfdprFrameGpu;
// * tables of every struct, block and define (player/gl/gpu_layout.h) for the layout test,
//   which checks each member against the offsets, strides and sizes the driver reports.
//
// Layouts C++ cannot mirror member for member (mat2/mat3, doubles, 64-bit integers, vec3
// or std140 scalar arrays, nested structs) are refused with file:line, so the build fails
// instead of a silent mismatch. Preprocessor conditionals are ignored: every declaration in
// the file is generated. An `#include "OTHER.glsl"` of a file in the same folder brings its
// structs in before this file's (as the shader preprocessor does), and they are generated
// here too: a struct two bindings files share is written once in GLSL (e.g.
// triangle_stats_bindings.glsl) and each generated header has its C++ twin. DEPFILE, when
// given, lists the included files for the build's dependency scan. The output is only
// rewritten when it changes.
#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

struct ParseError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

std::string g_file; // input name for error messages

[[noreturn]] void fail(int line, const std::string& message)
{
    throw ParseError(g_file + ":" + std::to_string(line) + ": error: " + message);
}

// ---- Tokens ---------------------------------------------------------------------------

struct Token {
    enum Kind { Identifier, Number, Punct, End } kind;
    std::string text;
    int line;
};

struct Source {
    std::vector<Token> tokens;
    std::map<int, std::string> lineComments; // trailing // comment per line
    std::map<int, bool> commentOnlyLine;      // line holds nothing but a // comment
};

Source tokenize(const std::string& text)
{
    Source s;
    int line = 1;
    size_t i = 0;
    bool lineHasCode = false;
    while (i < text.size()) {
        const char c = text[i];
        if (c == '\n') {
            ++line;
            lineHasCode = false;
            ++i;
        } else if (std::isspace(static_cast<unsigned char>(c))) {
            ++i;
        } else if (text.compare(i, 2, "//") == 0) {
            const size_t end = text.find('\n', i);
            std::string comment = text.substr(i + 2, end == std::string::npos ? std::string::npos : end - i - 2);
            while (!comment.empty() && comment.front() == ' ')
                comment.erase(comment.begin());
            s.lineComments[line] = comment;
            s.commentOnlyLine[line] = !lineHasCode;
            i = end == std::string::npos ? text.size() : end;
        } else if (text.compare(i, 2, "/*") == 0) {
            const size_t end = text.find("*/", i + 2);
            if (end == std::string::npos)
                fail(line, "unterminated /* comment");
            for (size_t k = i; k < end; ++k)
                line += text[k] == '\n';
            i = end + 2;
        } else if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
            const size_t start = i;
            while (i < text.size() && (std::isalnum(static_cast<unsigned char>(text[i])) || text[i] == '_'))
                ++i;
            s.tokens.push_back({Token::Identifier, text.substr(start, i - start), line});
            lineHasCode = true;
        } else if (std::isdigit(static_cast<unsigned char>(c))) {
            const size_t start = i;
            while (i < text.size() && (std::isalnum(static_cast<unsigned char>(text[i])) || text[i] == '.'))
                ++i;
            s.tokens.push_back({Token::Number, text.substr(start, i - start), line});
            lineHasCode = true;
        } else {
            s.tokens.push_back({Token::Punct, std::string(1, c), line});
            lineHasCode = true;
            ++i;
        }
    }
    s.tokens.push_back({Token::End, "", line});
    return s;
}

// ---- Defines ----------------------------------------------------------------------------

struct Define {
    std::string name;
    bool integer;
    uint64_t value;
    std::string text; // the literal as written (floating point defines)
    int line;
};

std::optional<uint64_t> parseInteger(std::string literal)
{
    while (!literal.empty() && (literal.back() == 'u' || literal.back() == 'U'))
        literal.pop_back();
    if (literal.empty())
        return std::nullopt;
    const bool hex = literal.size() > 2 && literal[0] == '0' && (literal[1] == 'x' || literal[1] == 'X');
    const size_t start = hex ? 2 : 0;
    for (size_t k = start; k < literal.size(); ++k)
        if (!(hex ? std::isxdigit(static_cast<unsigned char>(literal[k])) : std::isdigit(static_cast<unsigned char>(literal[k]))))
            return std::nullopt;
    return std::stoull(literal.substr(start), nullptr, hex ? 16 : 10);
}

bool isDecimal(const std::string& literal)
{
    bool digits = false, dot = false;
    // A leading minus sign: a negative constant (polynomial coefficients).
    for (char c : literal.substr(!literal.empty() && literal[0] == '-' ? 1 : 0)) {
        if (std::isdigit(static_cast<unsigned char>(c)))
            digits = true;
        else if (c == '.' && !dot)
            dot = true;
        else
            return false;
    }
    return digits && dot;
}

// Splits the text into directive lines (collected as defines, and the files of #include
// "NAME" as includes) and the rest (directives blanked, so token lines keep their numbers).
std::string takeDirectives(const std::string& text, std::vector<Define>& defines, std::vector<std::string>& includes)
{
    std::istringstream in(text);
    std::string out, line;
    int number = 0;
    while (std::getline(in, line)) {
        ++number;
        size_t first = line.find_first_not_of(" \t");
        if (first == std::string::npos || line[first] != '#') {
            out += line + "\n";
            continue;
        }
        out += "\n";
        std::istringstream d(line.substr(first + 1));
        std::string directive, name, value;
        d >> directive;
        if (directive == "include") {
            const size_t open = line.find('"'), close = line.rfind('"');
            if (open == std::string::npos || close <= open + 1)
                fail(number, "malformed #include (expected #include \"file\")");
            includes.push_back(line.substr(open + 1, close - open - 1));
            continue;
        }
        if (directive != "define")
            continue; // #ifdef, #endif, #extension: not layouts
        d >> name;
        if (name.find('(') != std::string::npos)
            continue; // function-like macro
        std::getline(d, value);
        if (const size_t comment = value.find("//"); comment != std::string::npos)
            value.erase(comment);
        const size_t a = value.find_first_not_of(" \t"), b = value.find_last_not_of(" \t\r");
        value = a == std::string::npos ? "" : value.substr(a, b - a + 1);
        if (const auto integer = parseInteger(value)) {
            if (*integer > 0xFFFFFFFFull)
                fail(number, name + " = " + value + " does not fit 32 bits");
            defines.push_back({name, true, *integer, value, number});
        } else if (isDecimal(value)) {
            defines.push_back({name, false, 0, value, number});
        }
        // Anything else (expressions, flags without a value) is not a constant C++ needs.
    }
    return out;
}

// ---- Types and layouts ------------------------------------------------------------------

struct TypeInfo {
    const char* cpp;
    uint32_t size;
    uint32_t align; // std430 base alignment (std140 rounds arrays and structs up to 16)
};

std::optional<TypeInfo> typeInfo(const std::string& glsl)
{
    static const std::map<std::string, TypeInfo> types = {
        {"float", {"float", 4, 4}},          {"int", {"int32_t", 4, 4}},          {"uint", {"uint32_t", 4, 4}},
        {"bool", {"uint32_t", 4, 4}},        {"vec2", {"glm::vec2", 8, 8}},       {"vec3", {"glm::vec3", 12, 16}},
        {"vec4", {"glm::vec4", 16, 16}},     {"ivec2", {"glm::ivec2", 8, 8}},     {"ivec3", {"glm::ivec3", 12, 16}},
        {"ivec4", {"glm::ivec4", 16, 16}},   {"uvec2", {"glm::uvec2", 8, 8}},     {"uvec3", {"glm::uvec3", 12, 16}},
        {"uvec4", {"glm::uvec4", 16, 16}},   {"mat4", {"glm::mat4", 64, 16}},
    };
    const auto it = types.find(glsl);
    return it == types.end() ? std::nullopt : std::optional<TypeInfo>(it->second);
}

uint32_t roundUp(uint32_t value, uint32_t multiple) { return (value + multiple - 1) / multiple * multiple; }

struct Member {
    std::string type, name;
    bool array = false;
    bool unsized = false;
    uint32_t count = 0;
    std::string comment;
    int line = 0;
    // Layout.
    uint32_t offset = 0, size = 0, stride = 0;
};

struct Aggregate {
    std::string glslName, cppName;
    bool block = false;
    bool uniform = false;
    std::string packing = "std430";
    uint32_t binding = 0;
    std::string instance;
    std::vector<Member> members;
    std::vector<std::string> doc;
    int line = 0;
    std::string file; // the GLSL file it is declared in, for error messages
    uint32_t size = 0, align = 4;
};

// std140 / std430 offsets of every member (GL 4.5 spec, section 7.6.2.2).
void layOut(Aggregate& a)
{
    const bool std140 = a.packing == "std140";
    uint32_t offset = 0, structAlign = 4;
    for (Member& m : a.members) {
        const std::optional<TypeInfo> t = typeInfo(m.type);
        if (!t)
            fail(m.line, "member '" + m.name + "' has type '" + m.type +
                             "', which the C++ mirror cannot lay out member for member (supported: float, int, uint, "
                             "bool, [iu]vec2..4, mat4)");
        uint32_t align = t->align, size = t->size;
        if (m.array) {
            if (std140)
                align = roundUp(align, 16);
            m.stride = roundUp(t->size, align);
            if (m.stride != t->size)
                fail(m.line, "array '" + m.name + "' has a " + std::to_string(m.stride) + "-byte " + a.packing +
                                 " stride but a " + std::to_string(t->size) +
                                 "-byte C++ element; use a vec4 (or a struct) element");
            size = m.unsized ? 0 : m.stride * m.count;
        }
        offset = roundUp(offset, align);
        m.offset = offset;
        m.size = size;
        offset += size;
        structAlign = std::max(structAlign, align);
    }
    if (std140)
        structAlign = roundUp(structAlign, 16);
    a.align = structAlign;
    a.size = roundUp(offset, structAlign);
}

// ---- Parser -------------------------------------------------------------------------------

class Parser {
public:
    Parser(Source source, const std::vector<Define>& defines) : s_(std::move(source)), defines_(defines) {}

    std::vector<Aggregate> parse()
    {
        std::vector<Aggregate> out;
        while (peek().kind != Token::End) {
            const Token& t = peek();
            if (t.kind == Token::Identifier && t.text == "struct") {
                out.push_back(parseStruct());
            } else if (t.kind == Token::Identifier && t.text == "layout") {
                if (std::optional<Aggregate> block = parseLayout())
                    out.push_back(std::move(*block));
            } else {
                skipDeclaration();
            }
        }
        return out;
    }

private:
    const Token& peek(size_t ahead = 0) const { return s_.tokens[std::min(pos_ + ahead, s_.tokens.size() - 1)]; }
    const Token& next()
    {
        const Token& t = peek();
        if (t.kind != Token::End)
            ++pos_;
        return t;
    }
    const Token& expect(const std::string& text)
    {
        const Token& t = next();
        if (t.text != text)
            fail(t.line, "expected '" + text + "', found '" + t.text + "'");
        return t;
    }
    std::string identifier()
    {
        const Token& t = next();
        if (t.kind != Token::Identifier)
            fail(t.line, "expected a name, found '" + t.text + "'");
        return t.text;
    }

    // The // comment lines directly above `line`.
    std::vector<std::string> docAbove(int line) const
    {
        std::vector<std::string> doc;
        for (int l = line - 1; s_.commentOnlyLine.count(l) && s_.commentOnlyLine.at(l); --l)
            doc.insert(doc.begin(), s_.lineComments.at(l));
        return doc;
    }

    // Integer constant expression over literals, defines, + - * / and parentheses.
    uint64_t expression() { return sum(); }
    uint64_t sum()
    {
        uint64_t v = product();
        while (peek().text == "+" || peek().text == "-")
            v = next().text == "+" ? v + product() : v - product();
        return v;
    }
    uint64_t product()
    {
        uint64_t v = primary();
        while (peek().text == "*" || peek().text == "/") {
            const bool multiply = next().text == "*";
            const int line = peek().line;
            const uint64_t r = primary();
            if (!multiply && r == 0)
                fail(line, "division by zero");
            v = multiply ? v * r : v / r;
        }
        return v;
    }
    uint64_t primary()
    {
        const Token& t = next();
        if (t.text == "(") {
            const uint64_t v = sum();
            expect(")");
            return v;
        }
        if (t.kind == Token::Number)
            if (const auto v = parseInteger(t.text))
                return *v;
        if (t.kind == Token::Identifier)
            for (const Define& d : defines_)
                if (d.name == t.text && d.integer)
                    return d.value;
        fail(t.line, "'" + t.text + "' is not an integer constant");
    }

    void skipDeclaration()
    {
        // Up to the ';' ending it, or through the body of a function.
        int parens = 0;
        while (peek().kind != Token::End) {
            const Token& t = next();
            if (t.text == "(")
                ++parens;
            else if (t.text == ")")
                --parens;
            else if (t.text == ";" && parens == 0)
                return;
            else if (t.text == "{" && parens == 0) {
                for (int depth = 1; depth > 0 && peek().kind != Token::End;) {
                    const Token& b = next();
                    depth += b.text == "{" ? 1 : b.text == "}" ? -1 : 0;
                }
                if (peek().text == ";")
                    next();
                return;
            }
        }
    }

    std::vector<Member> members()
    {
        std::vector<Member> out;
        expect("{");
        while (peek().text != "}") {
            if (peek().kind == Token::End)
                fail(peek().line, "unterminated member list");
            static const char* qualifiers[] = {"readonly", "writeonly", "coherent", "volatile", "restrict",
                                               "highp", "mediump", "lowp", "precise", "flat"};
            bool qualifier = false;
            for (const char* q : qualifiers)
                qualifier = qualifier || peek().text == q;
            if (qualifier) {
                next();
                continue;
            }
            const std::string type = identifier();
            for (;;) {
                Member m;
                m.type = type;
                m.line = peek().line;
                m.name = identifier();
                if (peek().text == "[") {
                    next();
                    m.array = true;
                    if (peek().text == "]") {
                        m.unsized = true;
                    } else {
                        const uint64_t count = expression();
                        if (count == 0 || count > 0xFFFFFFFFull)
                            fail(m.line, "array '" + m.name + "' has size " + std::to_string(count));
                        m.count = uint32_t(count);
                    }
                    expect("]");
                    if (peek().text == "[")
                        fail(m.line, "arrays of arrays are not supported ('" + m.name + "')");
                }
                out.push_back(m);
                if (peek().text != ",")
                    break;
                next();
            }
            expect(";");
            // The member's trailing comment, continued on comment-only lines below it.
            Member& last = out.back();
            if (s_.lineComments.count(last.line) && !s_.commentOnlyLine[last.line]) {
                last.comment = s_.lineComments.at(last.line);
                for (int l = last.line + 1; l < peek().line && s_.commentOnlyLine.count(l) && s_.commentOnlyLine[l]; ++l)
                    last.comment += " " + s_.lineComments.at(l);
            }
        }
        expect("}");
        return out;
    }

    Aggregate parseStruct()
    {
        Aggregate a;
        a.line = peek().line;
        a.doc = docAbove(a.line);
        expect("struct");
        a.glslName = identifier();
        a.cppName = a.glslName;
        a.members = members();
        expect(";");
        for (const Member& m : a.members)
            if (m.unsized)
                fail(m.line, "struct " + a.glslName + ": unsized array '" + m.name + "' outside a buffer block");
        return a;
    }

    // layout(...) [qualifiers] uniform|buffer Name { members } [instance];  Anything else
    // starting with layout (layout(local_size_x = ...) in;) is skipped.
    std::optional<Aggregate> parseLayout()
    {
        Aggregate a;
        a.line = peek().line;
        a.doc = docAbove(a.line);
        const size_t start = pos_;
        expect("layout");
        expect("(");
        bool haveBinding = false, havePacking = false;
        while (peek().text != ")") {
            const std::string key = identifier();
            if (peek().text == "=") {
                next();
                const int line = peek().line;
                const uint64_t value = expression();
                if (key == "binding") {
                    if (value > 0xFFFFFFFFull)
                        fail(line, "binding out of range");
                    a.binding = uint32_t(value);
                    haveBinding = true;
                }
            } else if (key == "std140" || key == "std430") {
                a.packing = key;
                havePacking = true;
            }
            if (peek().text == ",")
                next();
            else if (peek().text != ")")
                fail(peek().line, "unexpected '" + peek().text + "' in layout()");
        }
        expect(")");
        while (peek().kind == Token::Identifier && peek().text != "uniform" && peek().text != "buffer" &&
               peek(1).text != "{")
            next(); // readonly, coherent, ...
        if (peek().text != "uniform" && peek().text != "buffer") {
            pos_ = start;
            skipDeclaration();
            return std::nullopt;
        }
        a.uniform = next().text == "uniform";
        if (peek(1).text != "{") { // a plain uniform (sampler, image): not a block
            pos_ = start;
            skipDeclaration();
            return std::nullopt;
        }
        a.block = true;
        a.glslName = identifier();
        if (!havePacking)
            fail(a.line, "block " + a.glslName + " needs an explicit std140 or std430 layout");
        if (!haveBinding)
            fail(a.line, "block " + a.glslName + " needs an explicit binding");
        const std::string suffix = "Block";
        a.cppName = a.glslName.size() > suffix.size() && a.glslName.ends_with(suffix)
                        ? a.glslName.substr(0, a.glslName.size() - suffix.size()) + "Gpu"
                        : a.glslName + "Gpu";
        a.members = members();
        if (peek().kind == Token::Identifier)
            a.instance = identifier();
        expect(";");
        for (size_t k = 0; k < a.members.size(); ++k)
            if (a.members[k].unsized && (k + 1 != a.members.size() || a.uniform))
                fail(a.members[k].line, "unsized array '" + a.members[k].name + "' must be the last member of a buffer");
        return a;
    }

    Source s_;
    const std::vector<Define>& defines_;
    size_t pos_ = 0;
};

// ---- Output ---------------------------------------------------------------------------------

std::string constantName(const std::string& define, const std::string& prefix)
{
    std::string rest = define.rfind(prefix, 0) == 0 ? define.substr(prefix.size()) : define;
    std::string out = "k";
    bool upper = true;
    for (char c : rest) {
        if (c == '_') {
            upper = true;
            continue;
        }
        out += upper ? char(std::toupper(static_cast<unsigned char>(c))) : char(std::tolower(static_cast<unsigned char>(c)));
        upper = false;
    }
    return out;
}

std::string quoted(const std::string& s) { return "\"" + s + "\""; }

// The struct and block tables of the layout test (gpu_layout.h).
void emitTables(std::ostringstream& o, const std::vector<Aggregate>& aggregates,
                std::map<std::string, size_t>& structIndex)
{
    o << "inline constexpr lfd::gl::GpuStruct kStructs[] = {\n";
    size_t index = 0;
    for (const Aggregate& a : aggregates) {
        if (a.block && a.members.size() == 1 && a.members[0].unsized)
            continue;
        o << "    {" << quoted(a.glslName) << ", " << quoted(a.cppName) << ", sizeof(" << a.cppName << "), k"
          << a.cppName << "Members},\n";
        structIndex[a.glslName] = index++;
    }
    o << "};\n";
    // Structs without blocks (the blocks declared by the shaders): an empty span, since
    // C++ has no zero-size arrays.
    if (std::none_of(aggregates.begin(), aggregates.end(), [](const Aggregate& a) { return a.block; })) {
        o << "inline constexpr std::span<const lfd::gl::GpuBlock> kBlocks{};\n";
        return;
    }
    o << "inline constexpr lfd::gl::GpuBlock kBlocks[] = {\n";
    for (const Aggregate& a : aggregates) {
        if (!a.block)
            continue;
        const bool arrayBlock = a.members.size() == 1 && a.members[0].unsized;
        o << "    {" << quoted(a.glslName) << ", lfd::gl::GpuInterface::" << (a.uniform ? "Uniform" : "Storage")
          << ", " << quoted(a.packing) << ", " << a.binding << ", ";
        if (arrayBlock)
            o << "nullptr, " << quoted(a.members[0].name) << ", &kStructs[" << structIndex.at(a.members[0].type) << "]";
        else
            o << "&kStructs[" << structIndex.at(a.glslName) << "], nullptr, nullptr";
        o << ", " << (a.instance.empty() ? "nullptr" : quoted(a.instance)) << "},\n";
    }
    o << "};\n";
}

void emitDefines(std::ostringstream& o, const std::string& input, const std::string& prefix,
                 const std::vector<Define>& defines)
{
    o << "// ---- #defines of shaders/" << input << "\n\n";
    for (const Define& d : defines)
        o << "inline constexpr " << (d.integer ? "uint32_t " : "double ") << constantName(d.name, prefix) << " = "
          << d.text << "; // " << d.name << "\n";
}

// The C++ struct of one laid-out struct or fixed block: members with explicit padding where
// GLSL aligns, static_asserts of its size and offsets, and its member table.
void emitStruct(std::ostringstream& o, const Aggregate& a)
{
    o << "\n";
    for (const std::string& line : a.doc)
        o << "// " << line << "\n";
    if (a.block)
        o << "// C++ mirror of the " << a.packing << " " << (a.uniform ? "uniform" : "buffer") << " block "
          << a.glslName << ".\n";
    o << "struct " << a.cppName << " {\n";
    uint32_t cppOffset = 0, pad = 0;
    auto padTo = [&](uint32_t offset) {
        if (offset > cppOffset)
            o << "    uint32_t pad_" << pad++ << "_[" << (offset - cppOffset) / 4 << "]; // " << a.packing
              << " alignment\n";
        cppOffset = offset;
    };
    for (const Member& m : a.members) {
        padTo(m.offset);
        o << "    " << typeInfo(m.type)->cpp << " " << m.name;
        if (m.array)
            o << "[" << m.count << "]";
        o << "; // offset " << m.offset;
        if (!m.comment.empty())
            o << ": " << m.comment;
        o << "\n";
        cppOffset = m.offset + m.size;
    }
    padTo(a.size);
    o << "};\n";
    o << "static_assert(sizeof(" << a.cppName << ") == " << a.size << ");\n";
    for (const Member& m : a.members)
        o << "static_assert(offsetof(" << a.cppName << ", " << m.name << ") == " << m.offset << ");\n";
    o << "inline constexpr lfd::gl::GpuMember k" << a.cppName << "Members[] = {\n";
    for (const Member& m : a.members) {
        o << "    {" << quoted(m.name) << ", " << quoted(m.type) << ", offsetof(" << a.cppName << ", " << m.name
          << "), sizeof(" << a.cppName << "::" << m.name << "), " << (m.array ? m.count : 0) << ", ";
        if (m.array)
            o << "sizeof(" << a.cppName << "::" << m.name << "[0])";
        else
            o << "0";
        o << "},\n";
    }
    o << "};\n";
}

// Lays out every struct and fixed block and emits it; an array block's element must be a
// struct declared earlier.
void emitStructs(std::ostringstream& o, std::vector<Aggregate>& aggregates)
{
    o << "\n// ---- Structs (std430) and blocks with fixed members\n";
    std::map<std::string, const Aggregate*> structs;
    for (Aggregate& a : aggregates) {
        g_file = a.file;
        const bool arrayBlock = a.block && a.members.size() == 1 && a.members[0].unsized;
        if (arrayBlock) {
            const Member& m = a.members[0];
            if (!structs.count(m.type))
                fail(m.line, "block " + a.glslName + ": the array element '" + m.type +
                                 "' must be a struct declared earlier in this file");
            continue;
        }
        for (const Member& m : a.members)
            if (m.unsized)
                fail(m.line, "block " + a.glslName + " mixes fixed members and an unsized array");
        layOut(a);
        emitStruct(o, a);
        if (!a.block)
            structs[a.glslName] = &a;
    }
}

std::string generate(const std::string& input, const std::string& ns, const std::string& prefix,
                     const std::vector<Define>& defines, std::vector<Aggregate>& aggregates)
{
    std::ostringstream o;
    o << "// Generated by lfd_gpu_layout_gen (player/gl/gpu_layout_gen.cpp) from shaders/" << input
      << " - do not edit;\n// change the GLSL file. See player/gl/gpu_layout.h.\n"
      << "#pragma once\n\n#include \"gpu_layout.h\"\n\n#include <glm/glm.hpp>\n\n#include <cstddef>\n#include <cstdint>\n\n"
      << "namespace " << ns << " {\n\n";
    emitDefines(o, input, prefix, defines);
    emitStructs(o, aggregates);

    // Tables: structs (free structs and fixed blocks), blocks, defines.
    o << "\n// ---- Tables for the layout test\n\n";
    std::map<std::string, size_t> structIndex;
    // A file of #defines only (a program's units and locations): empty tables, as spans,
    // since C++ has no zero-size arrays.
    if (aggregates.empty()) {
        o << "inline constexpr std::span<const lfd::gl::GpuStruct> kStructs{};\n";
        o << "inline constexpr std::span<const lfd::gl::GpuBlock> kBlocks{};\n";
    } else {
        emitTables(o, aggregates, structIndex);
    }
    o << "inline constexpr lfd::gl::GpuDefine kDefines[] = {\n";
    for (const Define& d : defines)
        if (d.integer)
            o << "    {" << quoted(d.name) << ", " << d.value << "u},\n";
    o << "};\n";
    o << "inline constexpr lfd::gl::GpuLayoutFile kLayoutFile = {" << quoted(input)
      << ", kStructs, kBlocks, kDefines};\n";
    o << "\n} // namespace " << ns << "\n";
    return o.str();
}

std::string readFile(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw ParseError(path + ": error: cannot read");
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// The aggregates of `path` after those of the files it includes (each file once, in the
// order the shader preprocessor would expand them); `files` collects every file read.
void parseFile(const std::string& path, std::vector<Define>& defines, std::vector<Aggregate>& aggregates,
               std::vector<std::string>& files)
{
    if (std::find(files.begin(), files.end(), path) != files.end())
        return;
    files.push_back(path);
    g_file = path;
    std::vector<Define> own;
    std::vector<std::string> includes;
    const std::string code = takeDirectives(readFile(path), own, includes);
    const std::string folder = path.substr(0, path.find_last_of("/\\") + 1);
    for (const std::string& include : includes)
        parseFile(folder + include, defines, aggregates, files);
    g_file = path;
    std::vector<Aggregate> parsed = Parser(tokenize(code), own).parse();
    for (Aggregate& a : parsed) {
        a.file = path;
        aggregates.push_back(std::move(a));
    }
    // Only the file's own constants become C++ constants; an included file's stay in its
    // own header.
    if (path == files.front())
        defines = std::move(own);
}

std::string depfileText(const std::string& outputPath, const std::vector<std::string>& files)
{
    std::string text = outputPath + ":";
    for (const std::string& f : files)
        text += " " + f;
    return text + "\n";
}

} // namespace

int main(int argc, char** argv)
{
    if (argc != 5 && argc != 6) {
        std::fprintf(stderr, "usage: lfd_gpu_layout_gen INPUT.glsl OUTPUT.h NAMESPACE PREFIX [DEPFILE]\n");
        return 2;
    }
    const std::string inputPath = argv[1], outputPath = argv[2];
    try {
        std::vector<Define> defines;
        std::vector<Aggregate> aggregates;
        std::vector<std::string> files;
        parseFile(inputPath, defines, aggregates, files);
        const std::string name = inputPath.substr(inputPath.find_last_of("/\\") + 1);
        const std::string content = generate(name, argv[3], argv[4], defines, aggregates);
        if (argc == 6) {
            std::ofstream dep(argv[5], std::ios::binary | std::ios::trunc);
            dep << depfileText(outputPath, files);
        }

        std::ifstream old(outputPath, std::ios::binary);
        std::ostringstream oldText;
        if (old)
            oldText << old.rdbuf();
        if (old && oldText.str() == content)
            return 0;
        old.close();
        std::ofstream out(outputPath, std::ios::binary | std::ios::trunc);
        out << content;
        if (!out) {
            std::fprintf(stderr, "%s: error: cannot write\n", outputPath.c_str());
            return 1;
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
    return 0;
}
