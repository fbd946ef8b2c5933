// The per-triangle statistics the baker writes (lfd::TriangleStats, formats/) as the GPU
// reads them (std430). One definition for the scene's readers (scene_bindings.glsl) and the
// pose pass that recomputes them for a deformed mesh (pose_bindings.glsl); the shader
// preprocessor includes a file once, so a shader may include both. The build generates
// triangle_stats_bindings_gpu.h from this file (player/gl/gpu_layout_gen.cpp):
// player/scene/gpu_scene.cpp asserts that lfd::TriangleStats matches it byte for byte, and
// tests/player/gpu_layout_test.cpp checks every member against the driver.
struct TriangleStatsGpu {
    float areaWorld;
    float areaTexture;
    float texelCount;
    float sizeUv;
    float texPerWorld;
    uint flags;
};
