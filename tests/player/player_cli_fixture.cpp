#include "player_cli_fixture.h"

#include "render_test_util.h"
#include "test_scenes.h"

#include "lfd/pack.h"

#include <fstream>

namespace lfd::test {

void PlayerCliTest::SetUp()
{
    GlTest::SetUp();
    if (IsSkipped())
        return;
    ASSERT_TRUE(std::filesystem::exists(kPlay)) << kPlay << " not built (build target lfd-play)";
    dir_ = testOutputDir(folderPrefix_ + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    pack_ = dir_ / "scene.lfdpack";
    writePack(pack_, cubeAndSphereScene());
    profile_ = dir_ / "profile.json";
    std::ofstream(profile_) << tenthPrototypeProfileJson(profileName_);
}

} // namespace lfd::test
