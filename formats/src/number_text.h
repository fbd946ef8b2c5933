// Internal to formats/: how numbers are quoted in error messages, one form for every reader
// and check in the library.
#pragma once

#include <string>

namespace lfd::detail {

// Short decimal form of a number for error messages ("0.72", "-3", "inf").
std::string formatNumber(double value);

} // namespace lfd::detail
