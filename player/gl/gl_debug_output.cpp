#include "gl_debug_output.h"

#include "gl_context.h"

#include <epoxy/gl.h>

#include <cstdio>
#include <utility>

namespace lfd::gl {

namespace {

const char* severityName(GLenum severity)
{
    switch (severity) {
    case GL_DEBUG_SEVERITY_HIGH: return "high";
    case GL_DEBUG_SEVERITY_MEDIUM: return "medium";
    case GL_DEBUG_SEVERITY_LOW: return "low";
    default: return "notification";
    }
}

const char* typeName(GLenum type)
{
    switch (type) {
    case GL_DEBUG_TYPE_ERROR: return "error";
    case GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR: return "deprecated";
    case GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR: return "undefined behaviour";
    case GL_DEBUG_TYPE_PORTABILITY: return "portability";
    case GL_DEBUG_TYPE_PERFORMANCE: return "performance";
    case GL_DEBUG_TYPE_MARKER: return "marker";
    default: return "other";
    }
}

const char* sourceName(GLenum source)
{
    switch (source) {
    case GL_DEBUG_SOURCE_API: return "api";
    case GL_DEBUG_SOURCE_WINDOW_SYSTEM: return "window system";
    case GL_DEBUG_SOURCE_SHADER_COMPILER: return "shader compiler";
    case GL_DEBUG_SOURCE_THIRD_PARTY: return "third party";
    case GL_DEBUG_SOURCE_APPLICATION: return "application";
    default: return "other";
    }
}

void GLAPIENTRY onDebugMessage(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                               const GLchar* text, const void* user)
{
    GlDebugMessage message{source, type, id, severity,
                           text ? (length >= 0 ? std::string(text, size_t(length)) : std::string(text)) : ""};
    // Drivers end messages with a newline; the report is one line.
    while (!message.text.empty() && (message.text.back() == '\n' || message.text.back() == '\r'))
        message.text.pop_back();
    static_cast<GlDebugOutput*>(const_cast<void*>(user))->receive(std::move(message));
}

} // namespace

std::string glErrorName(unsigned error)
{
    switch (error) {
    case GL_NO_ERROR: return "GL_NO_ERROR";
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    case GL_STACK_UNDERFLOW: return "GL_STACK_UNDERFLOW";
    case GL_STACK_OVERFLOW: return "GL_STACK_OVERFLOW";
    default: return "GL error 0x" + [&] {
        char hex[16];
        std::snprintf(hex, sizeof hex, "%04x", error);
        return std::string(hex);
    }();
    }
}

std::string describeDebugMessage(const GlDebugMessage& m)
{
    return std::string("GL debug: ") + typeName(m.type) + " (" + severityName(m.severity) + ", " +
           sourceName(m.source) + ") #" + std::to_string(m.id) + ": " + m.text;
}

GlDebugOutput::GlDebugOutput(std::string tool, bool print) : tool_(std::move(tool)), print_(print)
{
    glEnable(GL_DEBUG_OUTPUT);
    // Synchronous: the message arrives inside the GL call that raised it (a debugger's
    // breakpoint on receive() stops in the caller's stack).
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(onDebugMessage, this);
    glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
}

GlDebugOutput::~GlDebugOutput()
{
    glDebugMessageCallback(nullptr, nullptr);
    glDisable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDisable(GL_DEBUG_OUTPUT);
}

void GlDebugOutput::receive(GlDebugMessage message)
{
    ++messages_;
    if (print_ && message.severity != GL_DEBUG_SEVERITY_NOTIFICATION) {
        std::fprintf(stderr, "%s: %s\n", tool_.c_str(), describeDebugMessage(message).c_str());
        std::fflush(stderr);
    }
    if (message.type == GL_DEBUG_TYPE_ERROR)
        errors_.push_back(std::move(message));
}

void GlDebugOutput::throwOnErrors(const std::string& what)
{
    std::vector<GlDebugMessage> errors = std::move(errors_);
    errors_.clear();
    GLenum code = GL_NO_ERROR;
    for (GLenum e = glGetError(); e != GL_NO_ERROR; e = glGetError())
        if (code == GL_NO_ERROR)
            code = e;
    if (errors.empty() && code == GL_NO_ERROR)
        return;
    std::string text = "GL error during " + what + ": ";
    text += errors.empty() ? glErrorName(code) : errors.front().text;
    if (errors.size() > 1)
        text += " (and " + std::to_string(errors.size() - 1) + " more)";
    throw GlError(text);
}

void checkGlError(const std::string& what)
{
    const GLenum first = glGetError();
    if (first == GL_NO_ERROR)
        return;
    while (glGetError() != GL_NO_ERROR) {
    }
    throw GlError("GL error " + glErrorName(first) + " during " + what + " (run with --gl-debug to name the call)");
}

GlErrorWatch::GlErrorWatch(const std::string& tool, bool debug)
{
    if (debug)
        output_ = std::make_unique<GlDebugOutput>(tool, true);
    checkGlError("context creation");
}

void GlErrorWatch::check(const std::string& what)
{
    if (output_)
        output_->throwOnErrors(what);
    else
        checkGlError(what);
}

} // namespace lfd::gl
