// What the glTF import tests share: the folder of hand-written glTF cases and a search of an
// imported scene's warnings.
#pragma once

#include "imported_scene.h"

#include <algorithm>
#include <filesystem>
#include <string>

namespace lfd::test {

// tests/data/gltf: small glTF files written by hand, one feature or defect each.
inline const std::filesystem::path kGltfCases = std::filesystem::path(LFD_TEST_DATA) / "gltf";

// Whether one of the import's warnings contains `part`.
inline bool hasWarning(const lfd::bake::ImportedScene& s, const std::string& part)
{
    return std::any_of(s.warnings.begin(), s.warnings.end(),
                       [&](const std::string& w) { return w.find(part) != std::string::npos; });
}

} // namespace lfd::test
