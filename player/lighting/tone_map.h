// From outgoing radiance to the 8-bit sRGB level a view pixel holds: exposure, the Khronos
// PBR Neutral tone mapper, the sRGB encode of shaders/srgb.glsl, and GL's rounding when a
// fragment's float is stored to RGBA8.
#pragma once

#include <glm/glm.hpp>

#include <array>
#include <cstdint>

namespace lfd::lighting {

// Khronos PBR Neutral (the Khronos 3D Commerce "PBR Neutral" tone mapper specification and
// its reference GLSL): below a peak of 0.76 the colour only loses a small toe offset
// (x - 6.25 x^2 for min channel x < 0.08, else 0.04); above, the peak is compressed towards
// 1 (1 - 0.24^2 / (peak + 0.24 - 0.76)) and desaturated towards white by 0.15.
glm::vec3 pbrNeutralToneMap(glm::vec3 linear);

// radiance * 2^exposureEv, tone mapped, clamped to [0, 1], sRGB-encoded (IEC 61966-2-1)
// and rounded to the nearest of 0..255, per channel.
std::array<uint8_t, 3> displayLevels(glm::vec3 radiance, float exposureEv);

} // namespace lfd::lighting
