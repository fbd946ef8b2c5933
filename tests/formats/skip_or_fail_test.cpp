// The CI rule of tests/common/skip_or_fail.h: a missing prerequisite fails the test when
// CI=true (the local behaviour, a skip, is what every guarded test shows off CI).
#include "skip_or_fail.h"

#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>
#include <string>

namespace {

// Sets CI for one scope and restores the previous value.
class ScopedCi {
public:
    explicit ScopedCi(const char* value)
    {
        if (const char* old = std::getenv("CI"))
            old_ = old;
        if (value)
            ::setenv("CI", value, 1);
        else
            ::unsetenv("CI");
    }
    ~ScopedCi()
    {
        if (old_)
            ::setenv("CI", old_->c_str(), 1);
        else
            ::unsetenv("CI");
    }

private:
    std::optional<std::string> old_;
};

void needsSomethingAbsent() { LFD_SKIP_OR_FAIL("fixture X absent"); }

TEST(SkipOrFail, OnlyCiTrueForbidsSkips)
{
    {
        const ScopedCi ci("true");
        EXPECT_TRUE(lfd::test::ciForbidsSkips());
    }
    for (const char* value : {static_cast<const char*>(nullptr), "", "false", "1", "TRUE"}) {
        const ScopedCi ci(value);
        EXPECT_FALSE(lfd::test::ciForbidsSkips()) << (value ? value : "(unset)");
    }
}

TEST(SkipOrFail, MissingPrerequisiteFailsUnderCi)
{
    const ScopedCi ci("true");
    EXPECT_FATAL_FAILURE(needsSomethingAbsent(), "CI=true forbids skipping: fixture X absent");
}

} // namespace
