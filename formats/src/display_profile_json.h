// Internal to formats/: helpers shared by the two display profile readers
// (display_profile.cpp: the project's own format; looking_glass_import.cpp: visual.json).
#pragma once

#include "lfd/display_profile.h"
#include "number_text.h"

#include <nlohmann/json.hpp>

#include <string>

namespace lfd::detail {

// Throws DisplayProfileError("<source>: <field>: <problem>"), folded onto one line.
[[noreturn]] void throwProfileError(const std::string& source, const std::string& field,
                                    const std::string& problem);

// Checks that `value` is a JSON integer in [0, 2^32) and returns it.
uint32_t toUint32(const nlohmann::json& value, const std::string& source,
                  const std::string& field);

// Default name of a profile loaded from `source`: the file stem ("prototype").
std::string defaultProfileName(const std::string& source);

// Default viewing distance when a profile gives none: three screen heights.
inline constexpr double kDefaultViewingDistanceScreenHeights = 3.0;
// Default view cone when a profile gives none (the paper gives none for its prototype).
inline constexpr double kDefaultViewConeDeg = 40.0;

// A Looking Glass visual.json calibration is recognised by its "pitch" and "slope" keys.
bool isLookingGlassVisual(const nlohmann::json& root);

// Imports a visual.json calibration (looking_glass_import.cpp). Not yet validated.
DisplayProfile importLookingGlassVisual(const nlohmann::json& root, const std::string& source);

} // namespace lfd::detail
