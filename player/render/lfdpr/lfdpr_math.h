// The LFDPR formulas of shaders/lfdpr_math.glsl, compiled as C++ (glm supplies the GLSL
// types and functions), so CPU tests exercise the exact code the shaders run.
#pragma once

#include <glm/glm.hpp>

namespace lfd::player::lfdpr_math {

using namespace glm;

#define LFD_FN inline
#define LFD_PRECISE
#include "lfdpr_math.glsl"
#undef LFD_FN
#undef LFD_PRECISE

} // namespace lfd::player::lfdpr_math
