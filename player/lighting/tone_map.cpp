// Exposure, PBR Neutral and the sRGB encode; see tone_map.h.
#include "tone_map.h"

#include "colour_spaces.h" // linearToSrgb

#include <algorithm>
#include <cmath>

namespace lfd::lighting {

glm::vec3 pbrNeutralToneMap(glm::vec3 color)
{
    // Khronos PBR Neutral reference implementation, step for step.
    constexpr float startCompression = 0.8f - 0.04f;
    constexpr float desaturation = 0.15f;
    const float x = std::min(color.r, std::min(color.g, color.b));
    const float offset = x < 0.08f ? x - 6.25f * x * x : 0.04f;
    color -= offset;
    const float peak = std::max(color.r, std::max(color.g, color.b));
    if (peak < startCompression)
        return color;
    constexpr float d = 1.0f - startCompression;
    const float newPeak = 1.0f - d * d / (peak + d - startCompression);
    color *= newPeak / peak;
    const float g = 1.0f - 1.0f / (desaturation * (peak - newPeak) + 1.0f);
    return glm::mix(color, glm::vec3(newPeak), g);
}

std::array<uint8_t, 3> displayLevels(glm::vec3 radiance, float exposureEv)
{
    const glm::vec3 mapped = pbrNeutralToneMap(radiance * std::exp2(exposureEv));
    std::array<uint8_t, 3> levels{};
    for (int c = 0; c < 3; ++c)
        levels[size_t(c)] = uint8_t(std::lround(metrics::detail::linearToSrgb(mapped[c]) * 255.0));
    return levels;
}

} // namespace lfd::lighting
