// Per-frame GPU constants shared by every renderer: the views SSBO (clipFromScene and eye
// per view, binding LFD_SSBO_VIEWS) and the FrameBlock UBO (light, ambient, background,
// view count and size, binding LFD_UBO_FRAME). Layouts: shaders/scene_bindings.glsl.
#pragma once

#include "frame.h"
#include "gl_handles.h"

#include <glm/glm.hpp>

namespace lfd::player {

// Background of every view (sRGB-encoded, as stored): dark grey.
inline constexpr float kBackground[4] = {0.05f, 0.05f, 0.05f, 1.0f};

// The fixed directional light, in display space (towards the light: upper left, in front
// of the screen), so the light stays put while the turntable rotates the scene under it.
glm::dvec3 lightDirectionDisplay();
inline constexpr float kLightIntensity = 3.0f; // irradiance scale, white
inline constexpr float kAmbientIntensity = 0.25f;

class FrameUniforms {
public:
    FrameUniforms();

    // Uploads the frame's views and constants and binds both buffers.
    void upload(const FrameSetup& frame);

private:
    gl::Buffer views_, frame_;
    size_t viewCapacity_ = 0;
};

} // namespace lfd::player
