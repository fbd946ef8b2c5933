#version 450 core
// LFDPR visibility pipeline, the frame's clears on a GPU (LFDPR_WORK_GPU; docs/player/lfdpr.md
// "Work shaped for a GPU"): every view pixel's words to all ones (empty: a depth key beyond every
// depth, no record) and its colour to the background, in one dispatch of one invocation per view
// pixel. The same clears through glClearNamedBufferData / glClearTexImage took
// 2.8 ms a frame on an NVIDIA H200 whatever the scene (point generation's stage at 48 views
// of 480x360: 2.79 ms with 25K points, 3.12 ms with 1.74M) - about 100 MB at some 35 GB/s,
// the speed of the few units of a compute chip that do graphics - while shader stores run
// on every multiprocessor. llvmpipe keeps the clear calls (a memset per buffer there).
#ifdef LFDPR_INT64
#extension GL_ARB_gpu_shader_int64 : require
#endif
#include "scene_bindings.glsl"
#define LFDPR_VISIBILITY_PIPELINE
#include "lfdpr_bindings.glsl"

layout(local_size_x = LFDPR_CLEAR_GROUP_X, local_size_y = LFDPR_CLEAR_GROUP_Y) in;

// The words as plain uints (one per pixel, or two on the 64-bit path; all ones is the empty
// value of both halves). A clear writes each once, so the pixel numbering here need not be
// lfdViewWord's: (view, y, x) covers the same viewCount x height x width words.
layout(std430, binding = LFDPR_SSBO_VIEW_DEPTH) writeonly buffer ViewDepth {
    uint viewDepthWords[];
};
#ifndef LFDPR_INT64
layout(std430, binding = LFDPR_SSBO_VIEW_WINNER) writeonly buffer ViewWinner {
    uint viewIndexWords[];
};
#endif
layout(binding = LFDPR_IMAGE_VIEWS, rgba8) uniform writeonly image2DArray u_views;
layout(location = LFDPR_LOC_CLEAR_BACKGROUND) uniform vec4 u_background;

void main()
{
    // x, y: the pixel; z: the view. The dispatch rounds width and height up to the workgroup.
    const uvec3 size = uvec3(imageSize(u_views));
    const uvec3 at = gl_GlobalInvocationID;
    if (at.x >= size.x || at.y >= size.y)
        return;
    const uint pixel = (at.z * size.y + at.y) * size.x + at.x;
#ifdef LFDPR_INT64
    viewDepthWords[2u * pixel] = 0xFFFFFFFFu;
    viewDepthWords[2u * pixel + 1u] = 0xFFFFFFFFu;
#else
    viewDepthWords[pixel] = 0xFFFFFFFFu;
    viewIndexWords[pixel] = 0xFFFFFFFFu;
#endif
    imageStore(u_views, ivec3(at), u_background);
}
