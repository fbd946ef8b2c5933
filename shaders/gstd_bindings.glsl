// gstd_reconstruct.comp's interface: units, image units, uniform locations and workgroup
// size. The only definition: the build generates gstd_bindings_gpu.h from it
// (player/gl/gpu_layout_gen.cpp) for renderer_gstd.cpp, and tests/player/gpu_layout_test.cpp
// checks every value against what the driver reports for the compiled program.
#define GSTD_LOCAL_SIZE 8          // x and y: one invocation per view pixel
#define GSTD_MAX_SAMPLES 64        // Gaussian sample offsets per sub-view
#define GSTD_UNIT_HIGH_RES 5       // sampler2DArray: the view's sub-views, one per layer (after the five material units)
#define GSTD_IMAGE_ACCUM 0         // rgba32f: view-size linear accumulator
#define GSTD_IMAGE_VIEW 1          // rgba8: the ViewTargets layer written
#define GSTD_LOC_SIZE 0            // uvec2: view size in pixels
#define GSTD_LOC_SAMPLE_COUNT 1    // uint
#define GSTD_LOC_SUB_VIEW 2        // uint: 0 .. sub-view count - 1
#define GSTD_LOC_SUB_VIEW_COUNT 3  // uint
#define GSTD_LOC_OFFSETS 4         // vec2[GSTD_MAX_SAMPLES]: view pixels
#define GSTD_LOC_LAYER 68          // uint: the sub-view's layer (after the offsets' 64 locations)
#define GSTD_MAX_SUB_VIEWS 16      // sub-views per view interval
#define GSTD_MAX_BATCH_LAYERS 256  // sub-views drawn before the panel model integrates them
// gstd's panel model (gstd_panel_phases.comp, gstd_panel_accumulate.comp,
// gstd_panel_resolve.comp): one invocation per panel pixel (its three subpixels).
#define GSTD_PANEL_LOCAL_SIZE 8          // x and y
#define GSTD_PANEL_UNIT_SUB_VIEWS 5      // sampler2DArray: a batch of consecutive sub-views (sRGB storage: linear fetches)
#define GSTD_PANEL_IMAGE_ACCUM 0         // rgba32f image2D: panel size, GL rows, linear channel sums
#define GSTD_PANEL_IMAGE_EIA 1           // rgba8 image2D: the EIA the resolve writes
#define GSTD_PANEL_IMAGE_PHASE 2         // rgba32f image2D: the three subpixels' phases (after inversion)
#define GSTD_PANEL_IMAGE_LENS 3          // rgba32f image2D: the three subpixels' lens centres, texture u
#define GSTD_PANEL_LOC_PANEL_SIZE 0      // uvec2: W, H
#define GSTD_PANEL_LOC_PER_SUBPIXEL 1    // uvec2 (FixedSubpixelMapping: 2^-64 lens periods, low word, high word)
#define GSTD_PANEL_LOC_PER_ROW 2         // uvec2
#define GSTD_PANEL_LOC_PHASE_OFFSET 3    // uvec2
#define GSTD_PANEL_LOC_INVERT_PHASE 4    // bool
#define GSTD_PANEL_LOC_SUBPIXELS_BGR 5   // bool
#define GSTD_PANEL_LOC_FIRST_PHASE 6     // float: phase t of the batch's first sub-view (layer 0)
#define GSTD_PANEL_LOC_SUB_VIEW_WIDTH 7  // float: one sub-view's interval h = 1 / (sub-views in the cone)
#define GSTD_PANEL_LOC_LAYER_COUNT 8     // uint: sub-views in the batch (the array's layers)
#define GSTD_PANEL_LOC_SPREAD 9          // vec2: phase spread over a subpixel's width, its height
#define GSTD_PANEL_LOC_FOOTPRINT 10      // vec2: spatial footprint (one view pixel), texture units
#define GSTD_PANEL_LOC_TAPS 11           // uvec2: bilinear taps across the footprint, x and y
#define GSTD_PANEL_LOC_LENS_SUBPIXELS 12 // float: 1 / perSubpixel, subpixel columns per lens (signed)
