#version 450 core
// LFDPR resolve: the winning colour of every view pixel (or the background where no splat
// landed) into the ViewTargets colour array (RGBA8, layer = view, GL row 0 = bottom, the
// orientation mvr renders in), so the EIA builder, quilt and view outputs are shared.
#ifdef LFDPR_INT64
#extension GL_ARB_gpu_shader_int64 : require
#endif
#include "scene_bindings.glsl"
#include "lfdpr_bindings.glsl"

// The C++ side dispatches with gl::dispatchCovering, which reads this local size back.
layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = LFDPR_IMAGE_VIEWS, rgba8) uniform writeonly image2DArray u_views;
#ifdef LFDPR_INT64
layout(std430, binding = LFDPR_SSBO_VIEW_DEPTH) readonly buffer ViewWords {
    uint64_t viewWords[];
};
#else
layout(std430, binding = LFDPR_SSBO_VIEW_DEPTH) readonly buffer ViewDepth {
    uint viewDepth[];
};
layout(std430, binding = LFDPR_SSBO_VIEW_WINNER) readonly buffer ViewColor {
    uint viewColor[];
};
#endif

void main()
{
    uvec3 id = gl_GlobalInvocationID; // x, GL row, view
    uvec2 size = uvec2(u_lfd.viewSize.xy);
    if (id.x >= size.x || id.y >= size.y || id.z >= u_lfd.counts.x)
        return;
    uint pixel = (id.z * size.y + id.y) * size.x + id.x;
#ifdef LFDPR_INT64
    uint64_t word = viewWords[pixel];
    bool covered = uint(word >> 32) != 0xFFFFFFFFu;
    uint color = uint(word & 0xFFFFFFFFul);
#else
    bool covered = viewDepth[pixel] != 0xFFFFFFFFu;
    uint color = viewColor[pixel];
#endif
    imageStore(u_views, ivec3(id), covered ? unpackUnorm4x8(color) : u_frame.background);
}
