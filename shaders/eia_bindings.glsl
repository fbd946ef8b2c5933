// The EIA programs' interface: eia_construct.comp (reconstruction modes, units, uniform
// locations, workgroup size) and eia_prefilter.comp (the spatial modes' first step). The
// only definition: the build generates eia_bindings_gpu.h from it for eia_builder.cpp, and
// tests/player/program_interface_test.cpp checks every value against what the driver
// reports for the compiled programs.
#define EIA_MODE_NONE 0
#define EIA_MODE_SPATIAL 1
#define EIA_MODE_VIEW 2
#define EIA_MODE_VIEW_SPATIAL 3
#define EIA_LOCAL_SIZE 8              // x and y: one invocation per panel pixel (x in lens order, EIA_LOC_LENS_ORDER)
#define EIA_UNIT_VIEWS 0              // sampler2DArray: the N views, as stored (sRGB-encoded RGBA8)
#define EIA_UNIT_PREFILTERED 1        // the prefiltered linear views, R16F channel planes: sampler3D (view-spatial, trilinear) or sampler2DArray (spatial)
#define EIA_IMAGE_EIA 0               // rgba8 image2D: the panel-size output
#define EIA_LOC_PANEL_SIZE 0          // uvec2
#define EIA_LOC_VIEW_SIZE 1           // uvec2
#define EIA_LOC_VIEW_COUNT 2          // uint
#define EIA_LOC_PER_SUBPIXEL 3        // uvec2 (FixedSubpixelMapping: 2^-64 lens periods, low word, high word)
#define EIA_LOC_PER_ROW 4             // uvec2
#define EIA_LOC_PHASE_OFFSET 5        // uvec2
#define EIA_LOC_INVERT_PHASE 6        // bool
#define EIA_LOC_SUBPIXELS_BGR 7       // bool
#define EIA_LOC_LINEAR_FROM_BYTE 8    // float[256] (mode view): sRGB byte -> linear, locations 8..263
#define EIA_LOC_LENS_ORDER 264        // uvec2: invocation order, (pixel stride s, runs ceil(W / s)) (lfd::samePhasePixelStride)
#define EIA_ENCODE_BUCKETS 512        // buckets of the sRGB encode table, uniform in sqrt(linear)
#define EIA_SSBO_ENCODE_TABLE 0       // float[EIA_ENCODE_BUCKETS] (filtered modes): linear -> sRGB level
#define EIA_PREFILTER_LOCAL_SIZE 8    // x and y (each invocation EIA_PREFILTER_BLOCK^2 texels); z = 1 (one view per z)
#define EIA_PREFILTER_BLOCK 4         // texels per invocation in x and y
#define EIA_PREFILTER_UNIT_VIEWS 0    // sampler2DArray: the N views, as stored (sRGB-encoded RGBA8)
#define EIA_PREFILTER_IMAGE_OUT 0     // r16f image3D (or image2DArray, EIA_PREFILTER_LAYERED): the prefiltered views, channel planes side by side
#define EIA_PREFILTER_LOC_SIZE 0      // uvec3: view width, height, count
#define EIA_PREFILTER_LOC_TAP 1       // float: the 3-tap kernel's outer weight a ([a, 1 - 2a, a])
// The prefilter's sRGB decode above the linear segment (bytes 11..255): linear =
// ((x + 0.055) / 1.055)^2.4 ~ c6 x^6 + ... + c0, x = byte / 255, a least-squares fit in relative
// error (at most 3.0e-4 there, under the 4.9e-4 of the half float the prefilter stores).
#define EIA_DECODE_C6 -0.10479982942342758
#define EIA_DECODE_C5 0.3657521605491638
#define EIA_DECODE_C4 -0.5790112614631653
#define EIA_DECODE_C3 0.7868330478668213
#define EIA_DECODE_C2 0.4955563247203827
#define EIA_DECODE_C1 0.03466804325580597
#define EIA_DECODE_C0 0.0008686881046742201
