// The fixture of the tests that run the lfd-play executable on a small pack: a fresh output
// folder per test holding the test scene's pack (cubeAndSphereScene) and a tenth-size
// prototype profile (384x216 panel), so each run is fast on llvmpipe.
#pragma once

#include "gl_test_support.h"
#include "tool_run.h"

#include <filesystem>
#include <string>

namespace lfd::test {

class PlayerCliTest : public GlTest {
protected:
    // Outputs go to testOutputDir(folderPrefix + test name); `profileName` is the profile's name.
    PlayerCliTest(std::string folderPrefix, std::string profileName)
        : folderPrefix_(std::move(folderPrefix)), profileName_(std::move(profileName))
    {
    }
    void SetUp() override;
    std::filesystem::path dir_, pack_, profile_;

private:
    std::string folderPrefix_, profileName_;
};

} // namespace lfd::test
