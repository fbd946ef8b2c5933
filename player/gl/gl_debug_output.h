// GL errors made visible (`--gl-debug`, docs/player/lfd-play.md "GL errors"). Two levels:
//  * always: checkGlError() drains glGetError after a frame, so a GL error becomes a clear
//    message and a non-zero exit instead of a silently wrong image;
//  * with --gl-debug: GlDebugOutput installs a KHR_debug callback (core since GL 4.3) on a
//    debug context, synchronous so a message is delivered inside the call that caused it:
//    every message above notification severity is printed as one line, and errors are
//    kept so the frame that raised them fails naming the call (the driver's text).
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace lfd::gl {

struct GlDebugMessage {
    unsigned source = 0, type = 0, id = 0, severity = 0;
    std::string text;
};

// One line: "GL debug: error (high, api) #1282: glBindBuffer(non-gen name)".
std::string describeDebugMessage(const GlDebugMessage& message);

class GlDebugOutput {
public:
    // Needs a current context. `print`: write every message above notification severity
    // to stderr as it arrives (prefixed with `tool`: "lfd-play: GL debug: ...").
    GlDebugOutput(std::string tool, bool print);
    ~GlDebugOutput(); // removes the callback and disables debug output
    GlDebugOutput(const GlDebugOutput&) = delete;
    GlDebugOutput& operator=(const GlDebugOutput&) = delete;

    // Error messages (GL_DEBUG_TYPE_ERROR) received since the last throwOnErrors().
    const std::vector<GlDebugMessage>& errors() const { return errors_; }
    size_t messageCount() const { return messages_; }
    // Throws GlError "GL error during WHAT: <first error> (and N more)" when errors arrived
    // since the last call, then forgets them; also drains glGetError.
    void throwOnErrors(const std::string& what);

    void receive(GlDebugMessage message); // the callback's entry point

private:
    std::string tool_;
    bool print_ = false;
    size_t messages_ = 0;
    std::vector<GlDebugMessage> errors_;
};

// Drains glGetError; throws GlError "GL error GL_INVALID_OPERATION during WHAT (run with
// --gl-debug to name the call)" if any was set.
void checkGlError(const std::string& what);

// What a tool checks after each frame: with --gl-debug the debug output's errors (named
// calls), else glGetError. Needs a current context.
class GlErrorWatch {
public:
    GlErrorWatch(const std::string& tool, bool debug);
    bool debug() const { return output_ != nullptr; }
    void check(const std::string& what); // throws GlError

private:
    std::unique_ptr<GlDebugOutput> output_;
};

// "GL_INVALID_ENUM", ... for glGetError codes.
std::string glErrorName(unsigned error);

} // namespace lfd::gl
