// gstd_reconstruct.comp's interface: units, image units, uniform locations and workgroup
// size. The only definition: the build generates gstd_bindings_gpu.h from it
// (player/gl/gpu_layout_gen.cpp) for renderer_gstd.cpp, and tests/player/gpu_layout_test.cpp
// checks every value against what the driver reports for the compiled program.
#define GSTD_LOCAL_SIZE 8          // x and y: one invocation per view pixel
#define GSTD_MAX_SAMPLES 64        // Gaussian sample offsets per sub-view
#define GSTD_UNIT_HIGH_RES 5       // sampler2D: the sub-view (after the five material units)
#define GSTD_IMAGE_ACCUM 0         // rgba32f: view-size linear accumulator
#define GSTD_IMAGE_VIEW 1          // rgba8: the ViewTargets layer written
#define GSTD_LOC_SIZE 0            // uvec2: view size in pixels
#define GSTD_LOC_SAMPLE_COUNT 1    // uint
#define GSTD_LOC_SUB_VIEW 2        // uint: 0 .. sub-view count - 1
#define GSTD_LOC_SUB_VIEW_COUNT 3  // uint
#define GSTD_LOC_OFFSETS 4         // vec2[GSTD_MAX_SAMPLES]: view pixels
