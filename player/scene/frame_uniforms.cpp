#include "frame_uniforms.h"

#include "gpu_environment.h"
#include "scene_bindings.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace lfd::player {

namespace {

// One light's FrameBlock entries (pbr_shading.glsl lfdLightIncidence).
void setLight(bindings::FrameGpu& block, uint32_t i, const PunctualLight& light)
{
    block.lightPosition[i] = glm::vec4(light.position, light.range);
    block.lightDirection[i] = glm::vec4(light.direction, float(uint32_t(light.type)));
    block.lightRadiance[i] = glm::vec4(light.radiance, 0.0f);
    // KHR_lights_punctual's spot smoothing: t = cd * scale + offset, scale = 1 / max(1e-3,
    // cos inner - cos outer), offset = -cos outer * scale.
    const float cosOuter = std::cos(light.outerConeAngle);
    const float scale = 1.0f / std::max(1e-3f, std::cos(light.innerConeAngle) - cosOuter);
    block.lightCone[i] = glm::vec4(scale, -cosOuter * scale, 0.0f, 0.0f);
}

} // namespace

std::vector<PunctualLight> frameLights(const FrameSetup& frame)
{
    const FrameLighting& lighting = frame.lighting;
    std::vector<PunctualLight> lights = lighting.lights;
    if (lights.empty() && !lighting.environment)
        lights.push_back(defaultLight(frame.displayFromScene));
    if (lights.size() > bindings::kMaxLights)
        lights.resize(bindings::kMaxLights);
    return lights;
}

glm::mat3 environmentFromScene(const FrameSetup& frame)
{
    // displayFromScene's 3x3 is a rotation times the uniform mm-per-unit scale; the
    // environment's axes are the display's (+y up, +z towards the viewer, as glTF's
    // default camera sees a scene), turned by the rotation (lighting/environment.h).
    glm::dmat3 displayFromScene(frame.displayFromScene);
    displayFromScene /= glm::length(displayFromScene[0]);
    return lighting::environmentFromScene(float(frame.lighting.environmentRotationDeg)) * glm::mat3(displayFromScene);
}

FrameUniforms::FrameUniforms() : frame_(gl::createBuffer(sizeof(bindings::FrameGpu), GL_DYNAMIC_STORAGE_BIT)) {}

void FrameUniforms::upload(const FrameSetup& frame)
{
    // Views: clipFromScene and eye (scene space) per view, from makeFrameSetup.
    const size_t n = frame.clipFromScene.size();
    std::vector<bindings::ViewGpu> views(n);
    for (size_t i = 0; i < n; ++i)
        views[i] = {frame.clipFromScene[i], glm::vec4(frame.eyeScene[i], 1.0f)};
    if (n > viewCapacity_ || !views_) {
        viewCapacity_ = std::max<size_t>(n, 1);
        views_ = gl::createBuffer(viewCapacity_ * sizeof(bindings::ViewGpu), GL_DYNAMIC_STORAGE_BIT);
    }
    if (n)
        glNamedBufferSubData(views_, 0, GLsizeiptr(n * sizeof(bindings::ViewGpu)), views.data());

    bindings::FrameGpu block{};
    block.ambientColor = glm::vec4(glm::vec3(kAmbientIntensity), 0.0f);
    block.background = glm::vec4(kBackground[0], kBackground[1], kBackground[2], kBackground[3]);
    block.viewCount = frame.profile.viewCount;
    block.viewWidth = frame.profile.viewWidth;
    block.viewHeight = frame.profile.viewHeight;
    block.maxAnisotropy = frame.textureAnisotropy;

    // Lighting: the punctual lights, the environment, exposure and tone mapping.
    const FrameLighting& lighting = frame.lighting;
    const std::vector<PunctualLight> lights = frameLights(frame);
    block.lightCount = uint32_t(lights.size());
    for (uint32_t i = 0; i < block.lightCount; ++i)
        setLight(block, i, lights[i]);
    block.exposure = float(std::exp2(lighting.exposureEv));
    block.lightingFlags = lighting.toneMap == ToneMap::PbrNeutral ? bindings::kLightingToneMap : 0u;
    if (lighting.environment) {
        block.lightingFlags |= bindings::kLightingEnvironment;
        block.environmentMaxLevel = lighting.environment->maxLevel();
        const glm::mat3 envFromScene = environmentFromScene(frame);
        for (int c = 0; c < 3; ++c)
            block.environmentFromScene[c] = glm::vec4(envFromScene[c], 0.0f);
        lighting.environment->bind();
    }
    glNamedBufferSubData(frame_, 0, sizeof(block), &block);

    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, bindings::kSsboViews, views_);
    glBindBufferBase(GL_UNIFORM_BUFFER, bindings::kUboFrame, frame_);
}

} // namespace lfd::player
