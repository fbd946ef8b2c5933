#include "scene_lights.h"

#include <cmath>

namespace lfd::player {

glm::dvec3 lightDirectionDisplay() { return glm::normalize(glm::dvec3(-0.35, 0.6, 0.7)); }

PunctualLight defaultLight(const glm::dmat4& displayFromScene)
{
    // The light is fixed in display space; take its direction back to scene space
    // (rotation only: normalise away the uniform mm-per-unit scale).
    const glm::dmat3 sceneFromDisplay = glm::inverse(glm::dmat3(displayFromScene));
    const glm::vec3 towardsLight = glm::vec3(glm::normalize(sceneFromDisplay * lightDirectionDisplay()));
    PunctualLight light;
    light.type = LightType::Directional;
    light.direction = -towardsLight;
    light.radiance = glm::vec3(kLightIntensity);
    return light;
}

std::vector<PunctualLight> sceneLights(const Scene& scene, const std::vector<glm::mat4>& sceneFromNode)
{
    std::vector<PunctualLight> lights;
    lights.reserve(scene.lights.size());
    for (const Light& in : scene.lights) {
        if (in.node >= sceneFromNode.size())
            continue; // the pack reader checked node indices; a scene built by hand may not have
        const glm::mat4& m = sceneFromNode[in.node];
        PunctualLight out;
        out.type = in.type;
        out.position = glm::vec3(m[3]);
        const glm::vec3 forward = -glm::vec3(m[2]); // the node's -Z axis
        const float length = glm::length(forward);
        out.direction = length > 0.0f ? forward / length : glm::vec3(0.0f, 0.0f, -1.0f);
        out.radiance = in.color * in.intensity;
        out.range = in.range;
        out.innerConeAngle = in.innerConeAngle;
        out.outerConeAngle = in.outerConeAngle;
        lights.push_back(out);
    }
    return lights;
}

} // namespace lfd::player
