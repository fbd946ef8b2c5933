// The scene rules of lights (formats/README.md "LGHT", KHR_lights_punctual): known types,
// nodes in range, finite non-negative colour, intensity and range, and a spot light's cone
// 0 <= inner < outer <= pi/2. Part of validateScene, so the writer refuses what the
// reader would reject.
#include "pack_internal.h"

#include <cmath>

namespace lfd::pack {

void validateLights(const Scene& scene, const std::string& name)
{
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const Light& l = scene.lights[i];
        const std::string where = "light " + std::to_string(i) + ": ";
        if (uint32_t(l.type) > uint32_t(LightType::Spot))
            fail(name, where + "invalid type " + std::to_string(uint32_t(l.type)));
        if (l.node >= scene.nodes.size())
            fail(name, where + "node " + std::to_string(l.node) + " does not exist (" +
                           std::to_string(scene.nodes.size()) + " nodes)");
        const float values[] = {l.color.r, l.color.g, l.color.b, l.intensity, l.range, l.innerConeAngle,
                                l.outerConeAngle};
        for (float v : values)
            if (!std::isfinite(v))
                fail(name, where + "values are not finite");
        if (l.color.r < 0.0f || l.color.g < 0.0f || l.color.b < 0.0f)
            fail(name, where + "colour is negative");
        if (l.intensity < 0.0f)
            fail(name, where + "intensity is negative");
        if (l.range < 0.0f)
            fail(name, where + "range is negative");
        if (l.type == LightType::Spot &&
            !(l.innerConeAngle >= 0.0f && l.innerConeAngle < l.outerConeAngle && l.outerConeAngle <= kMaxSpotConeAngle))
            fail(name, where + "spot cone angles " + std::to_string(l.innerConeAngle) + " and " +
                           std::to_string(l.outerConeAngle) + " are not 0 <= inner < outer <= pi/2");
    }
}

} // namespace lfd::pack
