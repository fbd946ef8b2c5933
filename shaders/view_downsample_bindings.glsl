// view_downsample.comp's interface (the --ss resolve): modes, units, uniform locations and
// workgroup size. The only definition: the build generates view_downsample_bindings_gpu.h
// from it for frame_pipeline.cpp, and tests/player/gpu_layout_test.cpp checks every value
// against what the driver reports for the compiled program.
#define VIEW_DOWNSAMPLE_SPATIAL 1        // 2x2 source pixels per pixel
#define VIEW_DOWNSAMPLE_ANGULAR 2        // source views 2v and 2v + 1 per view v
#define VIEW_DOWNSAMPLE_LOCAL_SIZE 8     // x and y; z = 1 (one view per z)
#define VIEW_DOWNSAMPLE_UNIT_SOURCE 0    // sampler2DArray: the supersampled views
#define VIEW_DOWNSAMPLE_IMAGE_TARGET 0   // rgba8 image2DArray: the display's views
#define VIEW_DOWNSAMPLE_LOC_TARGET_SIZE 0 // uvec3: width, height, views
#define VIEW_DOWNSAMPLE_LOC_MODE 1       // uint: VIEW_DOWNSAMPLE_SPATIAL or _ANGULAR
