// The display profiles the repository ships (samples/profiles/), for the tests that load them.
#pragma once

#include <filesystem>

namespace lfd::test {

inline const std::filesystem::path kSampleProfiles = std::filesystem::path(LFD_SOURCE_DIR) / "samples" / "profiles";

} // namespace lfd::test
