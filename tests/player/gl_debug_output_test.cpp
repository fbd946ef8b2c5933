// GL errors become clear failures (docs/player/lfd-play.md "GL errors"): glGetError after every
// frame, and with --gl-debug the KHR_debug message naming the call. Each check is made to fire with
// a deliberately invalid call, then shown to stay quiet on a real frame of every renderer.
#include "gl_debug_output.h"
#include "gl_test_support.h"
#include "test_scenes.h"

#include "lfd/pack.h"

#include <epoxy/gl.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sys/wait.h>

namespace lfd::test {
namespace {

namespace fs = std::filesystem;

// An invalid call on purpose: binding a name glGenBuffers never returned is
// GL_INVALID_OPERATION in a core context.
void raiseInvalidOperation() { glBindBuffer(GL_ARRAY_BUFFER, 0x7fff1234u); }

class GlDebugOutputTest : public GlTest {};

TEST_F(GlDebugOutputTest, CheckGlErrorNamesTheErrorAndClearsIt)
{
    gl::checkGlError("a clean start"); // nothing pending
    raiseInvalidOperation();
    try {
        gl::checkGlError("frame 3");
        FAIL() << "the invalid call went unnoticed";
    } catch (const gl::GlError& e) {
        const std::string text = e.what();
        EXPECT_NE(text.find("GL_INVALID_OPERATION"), std::string::npos) << text;
        EXPECT_NE(text.find("frame 3"), std::string::npos) << text;
        EXPECT_NE(text.find("--gl-debug"), std::string::npos) << text;
        EXPECT_EQ(text.find('\n'), std::string::npos) << "one line: " << text;
    }
    EXPECT_NO_THROW(gl::checkGlError("the next frame")) << "the error was drained";
}

TEST_F(GlDebugOutputTest, DebugOutputNamesTheCallThenGoesQuiet)
{
    {
        gl::GlDebugOutput debug("test", false);
        raiseInvalidOperation();
        ASSERT_EQ(debug.errors().size(), 1u) << "synchronous: the message arrives inside the call";
        EXPECT_EQ(debug.errors()[0].type, unsigned(GL_DEBUG_TYPE_ERROR));
        const std::string line = gl::describeDebugMessage(debug.errors()[0]);
        EXPECT_NE(line.find("error"), std::string::npos) << line;
        EXPECT_EQ(line.find('\n'), std::string::npos) << line;
        raiseInvalidOperation();
        try {
            debug.throwOnErrors("frame 7");
            FAIL() << "two errors went unnoticed";
        } catch (const gl::GlError& e) {
            const std::string text = e.what();
            EXPECT_NE(text.find("GL error during frame 7: "), std::string::npos) << text;
            EXPECT_NE(text.find("glBindBuffer"), std::string::npos) << "the driver's text names the call: " << text;
            EXPECT_NE(text.find("(and 1 more)"), std::string::npos) << text;
        }
        EXPECT_TRUE(debug.errors().empty());
        EXPECT_NO_THROW(debug.throwOnErrors("frame 8")) << "errors are reported once";
    }
    // Uninstalled: an error no longer reaches the (destroyed) object, glGetError still sees it.
    raiseInvalidOperation();
    EXPECT_THROW(gl::checkGlError("after"), gl::GlError);
}

TEST_F(GlDebugOutputTest, ErrorWatchUsesWhicheverIsOn)
{
    for (const bool debug : {false, true}) {
        gl::GlErrorWatch watch("test", debug);
        EXPECT_EQ(watch.debug(), debug);
        EXPECT_NO_THROW(watch.check("a clean frame"));
        raiseInvalidOperation();
        EXPECT_THROW(watch.check("a broken frame"), gl::GlError) << "debug " << debug;
        EXPECT_NO_THROW(watch.check("the next frame"));
    }
}

// Our own frames raise nothing: every renderer through lfd-play --gl-debug prints no
// error message and exits 0 (an error would fail the frame, exit 1).
TEST_F(GlDebugOutputTest, EveryRendererRunsCleanUnderGlDebug)
{
    const fs::path dir = testOutputDir("gl_debug_cli");
    const fs::path pack = dir / "scene.lfdpack";
    writePack(pack, cubeAndSphereScene());
    const fs::path play = fs::path(LFD_BINARY_DIR) / "player" / "lfd-play";
    ASSERT_TRUE(fs::exists(play));
    for (const char* renderer : {"mvr", "mvr-layered", "lfdpr", "lfdpr-paper"}) {
        const fs::path err = dir / (std::string(renderer) + ".err");
        const std::string command = "'" + play.string() + "' --headless --gl-debug '" + pack.string() +
                                    "' --renderer " + renderer + " --views 4 --view-size 48x36 --frames 1 --ss 2s" +
                                    " --aa view-spatial > /dev/null 2> '" + err.string() + "'";
        const int raw = std::system(command.c_str());
        std::ifstream in(err);
        const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        EXPECT_TRUE(WIFEXITED(raw) && WEXITSTATUS(raw) == 0) << renderer << ": " << text;
        EXPECT_EQ(text.find("GL debug: error"), std::string::npos) << renderer << ": " << text;
        EXPECT_EQ(text.find("GL error"), std::string::npos) << renderer << ": " << text;
    }
}

} // namespace
} // namespace lfd::test
