#include "frame_uniforms.h"

#include "scene_bindings.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <vector>

namespace lfd::player {

glm::dvec3 lightDirectionDisplay() { return glm::normalize(glm::dvec3(-0.35, 0.6, 0.7)); }

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

    // The light is fixed in display space; take its direction back to scene space
    // (rotation only: normalise away the uniform mm-per-unit scale).
    const glm::dmat3 sceneFromDisplay = glm::inverse(glm::dmat3(frame.displayFromScene));
    const glm::vec3 lightScene = glm::vec3(glm::normalize(sceneFromDisplay * lightDirectionDisplay()));
    bindings::FrameGpu block{};
    block.lightDirScene = glm::vec4(lightScene, 0.0f);
    block.lightColor = glm::vec4(glm::vec3(kLightIntensity), 0.0f);
    block.ambientColor = glm::vec4(glm::vec3(kAmbientIntensity), 0.0f);
    block.background = glm::vec4(kBackground[0], kBackground[1], kBackground[2], kBackground[3]);
    block.viewCount = frame.profile.viewCount;
    block.viewWidth = frame.profile.viewWidth;
    block.viewHeight = frame.profile.viewHeight;
    block.maxAnisotropy = frame.textureAnisotropy;
    glNamedBufferSubData(frame_, 0, sizeof(block), &block);

    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, bindings::kSsboViews, views_);
    glBindBufferBase(GL_UNIFORM_BUFFER, bindings::kUboFrame, frame_);
}

} // namespace lfd::player
