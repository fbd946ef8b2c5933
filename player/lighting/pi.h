// π in the single precision the lighting code's per-sample math runs in (the GLSL shaders'
// precision), declared once for the library: one definition, not one per file.
#pragma once

#include <numbers>

namespace lfd::lighting {

inline constexpr float kPi = std::numbers::pi_v<float>;

} // namespace lfd::lighting
