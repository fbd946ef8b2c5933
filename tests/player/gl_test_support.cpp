#include "gl_test_support.h"

#include <cstdio>
#include <memory>

namespace lfd::test {

namespace {

struct Shared {
    std::unique_ptr<gl::GlContext> context;
    std::string reason;
    bool tried = false;
};

Shared& shared()
{
    static Shared s;
    return s;
}

} // namespace

gl::GlContext* sharedGlContext()
{
    Shared& s = shared();
    if (!s.tried) {
        s.tried = true;
        try {
            s.context = gl::GlContext::createHeadless();
            s.context->require(false);
            std::printf("[ GL       ] %s\n", s.context->describe().c_str());
        } catch (const std::exception& e) {
            s.context.reset();
            s.reason = e.what();
        }
    }
    return s.context.get();
}

const std::string& glUnavailableReason() { return shared().reason; }

std::filesystem::path testOutputDir(const std::string& name)
{
    const std::filesystem::path dir = std::filesystem::path(LFD_BINARY_DIR) / "test_output" / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

} // namespace lfd::test
