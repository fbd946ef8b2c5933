// Shared fixture for tests that need OpenGL: one headless GL 4.5 core context per test
// binary (EGL surfaceless; Mesa llvmpipe on CI), created on first use and made current
// again before every test. Without EGL or GL 4.5 the tests are skipped with the reason
// (and fail under CI=true: skip_or_fail.h).
#pragma once

#include "gl_context.h"
#include "skip_or_fail.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace lfd::test {

// The binary's context, or null when none can be made (see glUnavailableReason()).
gl::GlContext* sharedGlContext();
const std::string& glUnavailableReason();

class GlTest : public ::testing::Test {
protected:
    void SetUp() override
    {
        gl::GlContext* context = sharedGlContext();
        if (!context)
            LFD_SKIP_OR_FAIL("no headless OpenGL 4.5 context: " << glUnavailableReason());
        context->makeCurrent();
    }
    const gl::GlCapabilities& caps() const { return sharedGlContext()->caps(); }
};

// A fresh empty directory for one test's outputs (under the build tree), removed first.
std::filesystem::path testOutputDir(const std::string& name);

} // namespace lfd::test
