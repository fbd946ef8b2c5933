// Per-frame GPU constants shared by every renderer: the views SSBO (clipFromScene and eye
// per view, binding LFD_SSBO_VIEWS) and the FrameBlock UBO (lights, environment, exposure
// and tone mapping, background, view count and size, binding LFD_UBO_FRAME), with the
// environment's textures bound. Layouts: shaders/scene_bindings.glsl.
#pragma once

#include "frame.h"
#include "gl_handles.h"

#include <glm/glm.hpp>

namespace lfd::player {

// Background of every view (sRGB-encoded, as stored): dark grey.
inline constexpr float kBackground[4] = {0.05f, 0.05f, 0.05f, 1.0f};

// The lights a frame shades with (FrameLighting::lights, or the default light when it has
// none and there is no environment), at most LFD_MAX_LIGHTS: the first ones.
std::vector<PunctualLight> frameLights(const FrameSetup& frame);

// environmentFromScene of the FrameBlock: the scene's orientation in the display (the
// environment stays with the display, like the default light) turned by the rotation.
glm::mat3 environmentFromScene(const FrameSetup& frame);

class FrameUniforms {
public:
    FrameUniforms();

    // Uploads the frame's views and constants, binds both buffers and the environment's
    // textures (when it has one).
    void upload(const FrameSetup& frame);

private:
    gl::Buffer views_, frame_;
    size_t viewCapacity_ = 0;
};

} // namespace lfd::player
