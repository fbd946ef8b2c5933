// The frame's punctual lights in scene space: the scene's KHR_lights_punctual instances at
// their nodes' animated transforms, or the player's default directional light. The
// shaders' light model is pbr_shading.glsl's lfdLightIncidence; docs/lighting.md.
#pragma once

#include "lfd/scene.h"

#include <glm/glm.hpp>

#include <vector>

namespace lfd::player {

struct PunctualLight {
    LightType type = LightType::Directional;
    glm::vec3 position{0.0f};           // scene space (point and spot)
    glm::vec3 direction{0.0f, 0.0f, -1.0f}; // unit, the way the light shines (directional and spot)
    glm::vec3 radiance{1.0f};           // colour * intensity
    float range = 0.0f;                 // 0: unlimited
    float innerConeAngle = 0.0f;        // spot, radians
    float outerConeAngle = 0.78539816f;
};

// The fixed directional light, in display space (towards the light: upper left, in front
// of the screen), so the light stays put while the turntable rotates the scene under it.
glm::dvec3 lightDirectionDisplay();
inline constexpr float kLightIntensity = 3.0f; // irradiance scale, white
inline constexpr float kAmbientIntensity = 0.25f;

// The default light for a frame whose scene is placed by `displayFromScene`.
PunctualLight defaultLight(const glm::dmat4& displayFromScene);

// Every light of `scene` at its node's transform (`sceneFromNode`, GpuScene::sceneFromNode
// of the frame): the node's origin and its -Z axis (KHR_lights_punctual), so lights on
// animated nodes move with them.
std::vector<PunctualLight> sceneLights(const Scene& scene, const std::vector<glm::mat4>& sceneFromNode);

} // namespace lfd::player
