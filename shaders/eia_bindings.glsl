// eia_construct.comp's interface: reconstruction modes, sample count, units, uniform
// locations and workgroup size. The only definition: the build generates
// eia_bindings_gpu.h from it for eia_builder.cpp, and tests/player/gpu_layout_test.cpp
// checks every value against what the driver reports for the compiled program.
#define EIA_MODE_NONE 0
#define EIA_MODE_SPATIAL 1
#define EIA_MODE_VIEW 2
#define EIA_MODE_VIEW_SPATIAL 3
#define EIA_SAMPLES 8
#define EIA_LOCAL_SIZE 8              // x and y: one invocation per panel pixel
#define EIA_UNIT_VIEWS 0              // sampler2DArray: the N views
#define EIA_IMAGE_EIA 0               // rgba8 image2D: the panel-size output
#define EIA_LOC_PANEL_SIZE 0          // uvec2
#define EIA_LOC_VIEW_SIZE 1           // uvec2
#define EIA_LOC_VIEW_COUNT 2          // uint
#define EIA_LOC_PER_SUBPIXEL 3        // double (SubpixelMapping)
#define EIA_LOC_PER_ROW 4             // double
#define EIA_LOC_PHASE_OFFSET 5        // double
#define EIA_LOC_INVERT_PHASE 6        // bool
#define EIA_LOC_SUBPIXELS_BGR 7       // bool
#define EIA_LOC_SAMPLES 8             // vec3[EIA_SAMPLES]: 8 .. 15
#define EIA_LOC_LINEAR_FROM_BYTE 16   // float[256]: 16 .. 271
