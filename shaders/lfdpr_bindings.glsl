// LFDPR buffers: binding points, uniform locations and std430/std140 layouts of both LFDPR
// pipelines (renderer_lfdpr.h): the paper's (LfdprPaper* structs, lfdpr_paper_*
// shaders) and the visibility pipeline (LfdprVisibility* and the other Lfdpr*Gpu structs,
// lfdpr_visibility_* shaders). This file is the only definition: the
// build generates the C++ side from it (lfdpr_bindings_gpu.h: every #define as a constant,
// every struct and fixed-member block as a C++ struct with these offsets; see
// player/gl/gpu_layout_gen.cpp), and tests/player/gpu_layout_test.cpp checks every member
// against the offsets, strides and sizes the driver reports. Sizes are never written here:
// C++ takes sizeof of the generated structs.
//
// Requires scene_bindings.glsl first (LFD_SSBO_* 0..3 and LFD_UBO_FRAME 0 are taken).

#define LFDPR_SSBO_POINTS 4
#define LFDPR_SSBO_TRIANGLES 5    // LfdprPaperTriangleGpu: what view generation needs
#define LFDPR_SSBO_SAMPLING 6     // LfdprPaperSamplingGpu: what the point FS needs
#define LFDPR_SSBO_COUNTERS 7
#define LFDPR_SSBO_VIEW_DEPTH 8   // 32-bit path: depth words; 64-bit path: depth|payload
// 32-bit path: per view pixel, the payload of the depth test's winner - its colour word
// (paper pipeline) or its LfdprVisibilityRecordGpu index (visibility pipeline).
#define LFDPR_SSBO_VIEW_WINNER 9
#define LFDPR_SSBO_VIEW_INVERSE 10 // sceneFromClip per view
#define LFDPR_UBO_FRAME 1
#define LFDPR_IMAGE_VIEWS 0

// Per-draw uniforms beyond LFD_LOC_NODE / MATERIAL / STREAMS (0, 1, 3).
#define LFDPR_LOC_RECORD_BASE 4   // first triangle record of this draw
#define LFDPR_LOC_FIRST_TRIANGLE 5 // scene triangle index of the draw's first triangle
#define LFDPR_LOC_PASS 6          // 32-bit view generation: 0 depth pass, 1 colour pass

// LfdprFrameGpu.options bits (the ablation switches).
#define LFDPR_OPTION_LFD_SAMPLING 1
#define LFDPR_OPTION_TEXTURE_SPLATTING 2
#define LFDPR_OPTION_MV_MIPMAPPING 4

// LfdprPaperTriangleGpu flags.
#define LFDPR_TRIANGLE_DOUBLE_SIDED 1
#define LFDPR_TRIANGLE_MIRRORED 2     // node transform flips the winding (front = CW)
#define LFDPR_TRIANGLE_FACE_NORMAL 4  // no normal stream: shade with the face normal

// Sampling viewport: tiles of LFDPR_TILE_SIZE^2 pixels, at most LFDPR_MAX_TILES per
// triangle (the geometry shader emits 4 vertices per tile).
#define LFDPR_TILE_SIZE 2048
#define LFDPR_MAX_TILES 16

// Splats are enlarged by this factor (per axis) so neighbouring splats of one triangle
// overlap slightly: pixel centres on a cell boundary are never lost to rounding. The
// overlap is resolved by the depth test (same plane) and the colour minimum.
#define LFDPR_SPLAT_OVERLAP 1.02
// ... and, in the visibility pipeline, by this many window pixels: a triangle's vertices are
// snapped to 1/256 pixel for its coverage test (lfdSnapToSubpixels), so it may own a pixel
// centre up to 1/362 pixel outside its exact projection, which a cell much smaller than a
// pixel in some view would not reach by LFDPR_SPLAT_OVERLAP alone. Extra coverage is free
// of effect: a triangle writes the same word wherever its cells overlap.
#define LFDPR_SPLAT_SLACK (1.0 / 64.0)

// Invocations per workgroup of the point-indexed compute passes (local_size_x).
#define LFDPR_GROUP_SIZE 64
// lfdpr_visibility_clear.comp's workgroup: a row of view pixels by a few rows.
#define LFDPR_CLEAR_GROUP_X 64
#define LFDPR_CLEAR_GROUP_Y 4

// One point (std430): position, its triangle record, and the texture values
// fetched at LOD_min and LOD_max (paper: tv_min, tv_max), packed 8 bits per channel.
// Normal-mapped surfaces store the two perturbed normals instead of the two normal-map
// texels (the tangent frame is applied at fetch time, so no frame is stored per point).
struct LfdprPaperPointGpu {
    vec3 position;      // scene space (splat centre)
    uint triangle;      // LfdprPaperTriangleGpu index
    uint normalMin;     // octahedral unit normal, 2 x snorm16 (LOD_min)
    uint normalMax;     // (LOD_max)
    uint baseColorMin;  // sRGB-encoded rgb, linear alpha (texture value, factor not applied)
    uint baseColorMax;
    uint ormMin;        // r occlusion, g roughness, b metallic (texture values), a unused
    uint ormMax;
    uint emissiveMin;   // sRGB-encoded rgb (texture value)
    uint emissiveMax;
};

// One triangle as view generation sees it (std430), indexed by draw record base
// + gl_PrimitiveID: scene-space vertices for the inside-triangle test, the sampling axes
// and spacings (the splat size), and the multiview-mipmapping range.
struct LfdprPaperTriangleGpu {
    vec4 p0;    // xyz scene position, w = uintBitsToFloat(material index)
    vec4 p1;    // xyz, w = A_ts / A_ws in scene units (texture area per world area)
    vec4 p2;    // xyz, w = uintBitsToFloat(LFDPR_TRIANGLE_* flags)
    vec4 axisU; // xyz unit "horizontal" axis (T_align row 0), w = spacing along it
    vec4 axisV; // xyz unit "vertical" axis (T_align row 1), w = spacing along it
    vec4 mip;   // x size_vpuv^min, y size_vpuv^max (eqs. minVPUVSize, maxVPUVSize), zw 0
};

// What the point fragment shader needs besides the record (std430).
struct LfdprPaperSamplingGpu {
    vec4 origin;   // xyz scene point of sampling coordinates (0, 0), w unused
    vec4 q01;      // sampling coordinates of p0 (xy) and p1 (zw)
    vec4 q2uv0;    // q2 (xy), uv0 (zw)
    vec4 uv12;     // uv1 (xy), uv2 (zw)
    uvec4 normals; // xyz octahedral vertex normals (scene), w unused
    uvec4 tangents; // xyz octahedral vertex tangents (scene), w bit i: tangent i has w < 0
};

// Counters of the paper's pipeline (C++: LfdprPaperCountersGpu, read back by name).
#ifndef LFDPR_VISIBILITY_PIPELINE // the visibility pipeline has its own counters
layout(std430, binding = LFDPR_SSBO_COUNTERS) coherent buffer LfdprPaperCounters {
    uint pointCount;       // points generated (may exceed the capacity: overflow)
    uint triangleCount;    // triangles that emitted points
    uint oversizedCount;   // triangles larger than one sampling tile (tiled in the GS)
    uint coarsenedCount;   // ... larger than LFDPR_MAX_TILES tiles (sampled coarser)
    uint dispatchX;        // view-generation dispatch arguments (glDispatchComputeIndirect
                           // at offsetof(LfdprPaperCountersGpu, dispatchX))
    uint dispatchY;
    uint dispatchZ;
    uint counterPad;
} counters;
#endif

// Frame constants of point generation (C++: LfdprFrameGpu).
layout(std140, binding = LFDPR_UBO_FRAME) uniform LfdprFrameBlock {
    vec4 displayX;     // xyz unit display x axis in scene space, w = view pixel width (scene units)
    vec4 displayY;     // xyz unit display y axis, w = view pixel height (scene units)
    vec4 displayZ;     // xyz unit display z axis (screen normal, towards the viewer)
    vec4 screenCenter; // xyz screen centre in scene space (zero-parallax plane)
    vec4 viewLine;     // xyz a point of the viewing line (camera 0's eye)
    vec4 planes[6];    // convex hull of the union of all view frusta, inside: dot >= 0
    uvec4 counts;      // x view count, y point capacity, z options (LFDPR_OPTION_*), w views splatted into
    vec4 viewSize;     // x view width, y view height (pixels), zw 0
} u_lfd;

// ---------------------------------------------------------------------------------------
// The visibility pipeline (lfdpr's default; the paper's pipeline above stays selectable):
// compute point generation (lfdpr_visibility_points.comp), visibility splatting of depth and point
// index (lfdpr_visibility_splat.comp), then shading once per visible view pixel
// (lfdpr_visibility_shade.comp). A point is 8 bytes: its triangle record and its sampling cell.
#define LFDPR_SSBO_RECORDS 11      // LfdprVisibilityRecordGpu per emitting triangle
#define LFDPR_SSBO_INDICES 12      // the scene's index buffer (uint)
#define LFDPR_SSBO_POSITIONS 13    // the scene's position stream (float x 3 per vertex)
#define LFDPR_SSBO_NORMALS 14      // normal stream (float x 3), or a dummy
#define LFDPR_SSBO_TANGENTS 15     // tangent stream (vec4), or a dummy
#define LFDPR_SSBO_UVS 16          // uv stream (vec2), or a dummy
#define LFDPR_SSBO_DRAWS 17        // LfdprVisibilityDrawGpu per draw
#define LFDPR_SSBO_LARGE 18        // per dispatch class segment: uvec2 (draw, primitive) sampled by a workgroup
#define LFDPR_SSBO_LARGE_DISPATCH 19 // per dispatch class: uvec4 indirect dispatch (w = triangles queued)
#define LFDPR_SSBO_VIS_COUNTERS 20 // LfdprVisibilityCounters
#define LFDPR_SSBO_SHADE_WORK 21   // LfdprShadeWork: per shading group, its tiles and dispatch
#define LFDPR_SSBO_CHUNK_MASKS 22  // per shading group and tile chunk: the views splatted there
#define LFDPR_SSBO_REPAIR 23       // LfdprVisibilityRepairGpu: the 32-bit path's repair dispatches
#define LFDPR_SSBO_WORKGROUPS 24   // LfdprVisibilityWorkgroupGpu per point-generation workgroup
#define LFDPR_UBO_CAMERA_LINE 2
// The same buffers as buffer textures (texelFetch), for the passes that read them per
// point or per pixel: on Mesa's llvmpipe a storage-buffer load at a per-invocation address
// runs a loop over the SIMD lanes for each component (with a bounds check per lane), while
// a texel fetch is one vectorised gather of a whole texel (see lfdpr_scene_access.glsl).
#define LFDPR_UNIT_INDICES 8       // RGB32UI: texel t = triangle t's three vertex indices
#define LFDPR_UNIT_POSITIONS 9     // RGB32F: texel v = vertex v's position
#define LFDPR_UNIT_NORMALS 10      // RGB32F
#define LFDPR_UNIT_TANGENTS 11     // RGBA32F
#define LFDPR_UNIT_UVS 12          // RG32F
#define LFDPR_UNIT_RECORDS 14      // RGBA32UI: LfdprVisibilityRecordGpu (spacing as float bits)
#define LFDPR_UNIT_DRAWS 15        // RGBA32UI: LfdprVisibilityDrawGpu
#define LFDPR_UNIT_NODES 16        // RGBA32F: NodeGpu, 8 texels each
#define LFDPR_UNIT_MATERIALS 17    // RGBA32F: MaterialGpu, 4 texels each (flags as float bits)
#define LFDPR_UNIT_VIEW_DEPTH 18   // per view pixel: R32UI depth key, or RG32UI 64-bit word
#define LFDPR_UNIT_VIEW_INDEX 19   // per view pixel: R32UI the winner's record (32-bit path)

#define LFDPR_LOC_FIRST_WORKGROUP 7 // lfdpr_visibility_points.comp: the dispatch's first LfdprVisibilityWorkgroupGpu
#define LFDPR_LOC_WORKGROUPS 8     // lfdpr_visibility_points.comp: LfdprVisibilityWorkgroupGpu entries it covers
#define LFDPR_LOC_SHADE_MATERIAL 9 // lfdpr_visibility_shade.comp: the material whose textures are bound
#define LFDPR_LOC_LARGE_BASE 10    // first LFDPR_SSBO_LARGE slot of the dispatch class
#define LFDPR_LOC_SHADE_GROUP 11   // lfdpr_visibility_shade.comp: the shading group dispatched
#define LFDPR_LOC_SHADE_GROUPS 12  // lfdpr_visibility_shade_list.comp, lfdpr_visibility_repair_dispatch.comp: groups in use
#define LFDPR_LOC_LARGE_CLASS 13   // lfdpr_visibility_points.comp: the dispatch class (its LFDPR_SSBO_LARGE_DISPATCH entry)
#define LFDPR_LOC_CLEAR_BACKGROUND 14 // lfdpr_visibility_clear.comp: the views' background colour

// The direct subpixel splat (LfdprOptions::Direct, renderer lfdpr-direct; docs/player/direct-splat.md):
// the splat writes panel-subpixel words instead of view words (lfdpr_direct_fanout.glsl), the
// shading shades each covered subpixel (lfdpr_direct_shade.comp) into one channel plane per
// colour, and the pack pass writes the RGBA8 panel (lfdpr_direct_pack.comp).
// Per view word (lfdViewWord) + 1: its first entry in LFDPR_SSBO_DIRECT_SUBPIXELS.
#define LFDPR_SSBO_DIRECT_OFFSETS 25
// uint per subpixel: subpixel indices l * 3W + k, grouped by the view word they show.
#define LFDPR_SSBO_DIRECT_SUBPIXELS 26
// Per subpixel (l * 3W + k), as a view word: uint64 key << 32 | record, or (32-bit path) the key.
#define LFDPR_SSBO_PANEL_WORDS 27
// 32-bit path: uint per subpixel, the winner's record (the lowest at the nearest key, record pass).
#define LFDPR_SSBO_PANEL_INDEX 28
// The winners read by the shading: RG32UI 64-bit words (x record, y key), or R32UI records.
#define LFDPR_UNIT_PANEL_WORDS 21
#define LFDPR_UNIT_SUBPIXELS 22        // sampler2DArray (R8): the shaded subpixels, layer = channel, GL rows
#define LFDPR_IMAGE_SUBPIXELS 1        // r8 image2DArray: the same, written by the shading
#define LFDPR_IMAGE_PANEL 2            // rgba8 image2D: the panel image (the EIA texture)
#define LFDPR_LOC_PANEL_SIZE 15        // uvec2: panel width, height in pixels
#define LFDPR_LOC_PER_SUBPIXEL 16      // uvec2: lfd::FixedSubpixelMapping::perSubpixel (low word, high word)
#define LFDPR_LOC_PER_ROW 17           // uvec2
#define LFDPR_LOC_PHASE_OFFSET 18      // uvec2
#define LFDPR_LOC_INVERT_PHASE 19      // bool
#define LFDPR_LOC_SUBPIXELS_BGR 20     // bool
#define LFDPR_LOC_LENS_SUBPIXELS 21    // float (exact-ray mode): subpixel columns per lens, 1 / perSubpixel
#define LFDPR_DIRECT_LOCAL_SIZE 8      // x and y of the shading and pack passes: one invocation per panel pixel

// Shading (lfdpr_visibility_shade_list.comp, lfdpr_visibility_shade.comp): view pixels are shaded in tiles of
// LFDPR_SHADE_TILE x LFDPR_SHADE_TILE pixels, a tile position over a chunk of views at a
// time. Materials fall into shading groups - group 0 every untextured material, then one
// group per textured material (whose textures are bound for its dispatch) - and each
// group's dispatch visits only the tile chunks, and in them the views, where a point of
// the group was splatted (lfdpr_visibility_splat.comp marks them). Textured materials beyond
// LFDPR_MAX_SHADE_GROUPS - 1 share groups (each then visits its group's tiles and shades
// only its own pixels).
#define LFDPR_SHADE_TILE 8
#define LFDPR_MAX_SHADE_GROUPS 256

// Word of view pixel (x, y) of `view` in the visibility pipeline's per-pixel buffers:
// views interleaved per pixel, so the 48 splats of one point (same row, nearby columns:
// camera-line coherence) touch a few cache lines instead of 48 separate images.
uint lfdViewWord(uint view, uint x, uint y, uint width, uint viewCount)
{
    return (y * width + x) * viewCount + view;
}

// One point of the visibility pipeline (std430): its triangle record and its sampling cell.
struct LfdprVisibilityPointGpu {
    uint record; // LfdprVisibilityRecordGpu index
    uint cell;   // sampling cell: x | y << 16
};

// One emitting triangle (std430): which triangle (the vertices, attributes,
// node and material come from the scene) and its final sampling spacings.
struct LfdprVisibilityRecordGpu {
    uint draw;       // LfdprVisibilityDrawGpu index
    uint primitive;  // triangle within the draw
    vec2 spacing;    // along T_align's U and V (texture splatting, coarsening applied),
                     // signed with the frame's choices (lfdSignedSpacing)
};

// One workgroup of compute point generation (std430): LFDPR_GROUP_SIZE consecutive
// triangles of one draw, so every draw is sampled by one dispatch per dispatch class (all
// draws without an alpha test in one; each alpha-tested draw, whose textures must be
// bound, in its own) and no invocation searches for its draw.
struct LfdprVisibilityWorkgroupGpu {
    uint draw;           // LfdprVisibilityDrawGpu index
    uint firstPrimitive; // its first triangle within the draw
    uint primitives;     // triangles it samples (1..LFDPR_GROUP_SIZE)
    uint firstRecord;    // the record slot of its first triangle: the drawn-triangle index
                         // (draws in order), so records are numbered in draw order
};

// One draw (std430).
struct LfdprVisibilityDrawGpu {
    uint node;
    uint material;      // GPU material index
    uint firstTriangle; // scene triangle index of the draw's first triangle
    uint group;         // its material's shading group (lfdprMaterialGroups)
};

// Counters of the visibility pipeline (std430). The splat's indirect dispatch is made from
// them on the GPU (lfdpr_paper_dispatch.comp); the renderer reads them back frames later behind a
// fence (gl::GpuReadback, by name), for the stats and to grow the point buffer after an
// overflow - never waiting for them.
struct LfdprVisibilityCountersGpu {
    uint pointCount;     // points generated (may exceed the capacity: overflow)
    uint recordCount;    // emitting triangles (records sit at their drawn-triangle slots)
    uint oversizedCount; // larger than one sampling tile
    uint coarsenedCount; // larger than LFDPR_MAX_TILES tiles (sampled coarser)
    uint largeCount;     // sampled by a workgroup
    uint splatGroupsX;   // the splat's indirect dispatch (glDispatchComputeIndirect at
    uint splatGroupsY;   // offsetof(LfdprVisibilityCountersGpu, splatGroupsX)): workgroups of
    uint splatGroupsZ;   // LFDPR_GROUP_SIZE points, x at most 65535
    // Work counters (docs/player/8k-panels.md), written only by programs compiled with
    // LFDPR_COUNT_WORK (LfdprOptions::countWork; lfdpr_work_counters.glsl), else 0:
    uint workCulled;     // (point, view) pairs skipped before the per-view triangle setup
    uint workSamples;    // pixel centres inside the cell, the triangle and the depth range
    uint workAtomics;    // of those, the atomicMin issued (the plain read found the word farther)
    uint workLowered;    // of those, the atomics that lowered the word
    uint workShadings;   // view pixels shaded (repair passes included)
    uint workCulledCentres; // of workCulled, those whose cell and triangle columns overlap but
                            // whose cell holds no pixel centre there (the centre test)
    // A whole number of 16-byte units: Mesa reports the block's GL_BUFFER_DATA_SIZE rounded up
    // to 16 (64 for 56 bytes), and the layout test holds the allocation to what GL reports.
    uint reserved0;
    uint reserved1;
};

// The 32-bit path's repair, made on the GPU from the shading's first pass
// (lfdpr_visibility_repair_dispatch.comp, std430): three indirect dispatches, each of zero workgroups
// when it has nothing to do, so the frame never waits to learn whether to repair.
struct LfdprVisibilityRepairGpu {
    uvec4 indexPass;  // xyz: lfdpr_visibility_splat.comp LFDPR_INDEX_PASS over every point (0 without
                      // repairs); w: view pixels to repair (the first pass's repairCount)
    uvec4 listRepair; // xyz: lfdpr_visibility_shade_list.comp LFDPR_REPAIR_LIST over the repair list,
                      // when the list holds every repair; w 0
    uvec4 listAll;    // xyz: lfdpr_visibility_shade_list.comp over every marked chunk again, when more
                      // pixels raced than the list holds; w 0
};

// Shading work (std430, LFDPR_SSBO_SHADE_WORK): counters, then per group an indirect
// dispatch (x, y, z) with the group's entry count in w (at byte 16 + 16 * group), then per
// group its list of tile chunk entries (LFDPR_SHADE_ENTRY_WORDS words each, from
// groupTiles[group * lfdShadeEntryCount * 3]), then the repair list (32-bit path): the
// tile chunk index of each repaired pixel, at groupTiles[repairBase + i], then the tie
// queue (32-bit views path): the points that met a depth tie, two words each (point
// index, view slice) from groupTiles[tieBase] (lfdpr_visibility_splat.comp queueTies).
struct LfdprVisibilityShadeCountersGpu {
    uint repairCount;    // 32-bit path: view pixels whose record lost a race
    uint repairBase;     // groupTiles index of the repair list: the tile chunk of each such pixel
    uint repairCapacity; // entries the repair list holds
    uint tieBase;        // groupTiles index of the tie queue
    uvec4 tieDispatch;   // xyz: the tie pass's indirect dispatch (LFDPR_TIE_PASS), w: points queued
    uint tieCapacity;    // points the tie queue holds
    uint pad0, pad1, pad2;
};
#define LFDPR_SHADE_WORK_BUFFER \
    buffer ShadeWork { \
        LfdprVisibilityShadeCountersGpu shadeCounters; \
        uvec4 groupDispatch[LFDPR_MAX_SHADE_GROUPS]; \
        uint groupTiles[]; \
    }
// The repair's index pass (32-bit views path) matches each point against the listed raced
// pixels when there are at most this many (lfdpr_visibility_splat.comp reachesRepairedChunk).
#define LFDPR_REPAIR_FILTER_MAX 64
#define LFDPR_SHADE_DISPATCH_WIDTH 32768 // workgroups per dispatch row (x stays under GL's 65535)
// Marking and shading walk the views of one tile position in chunks of LFDPR_VIEW_CHUNK
// views (a 64-bit view mask per group and chunk: LFDPR_VIEW_MASK_WORDS, at
// LFDPR_SSBO_CHUNK_MASKS[(group * lfdShadeEntryCount + chunk index) * 2]). A group's list
// holds, per tile chunk where the group was splatted, three words: the chunk's index
// (lfdShadeChunk) and the two words of its view mask.
#define LFDPR_VIEW_CHUNK 64
#define LFDPR_VIEW_MASK_WORDS 2
#define LFDPR_SHADE_ENTRY_WORDS 3


// Views the camera-line block holds offsets for (4 per vec4).
#define LFDPR_MAX_VIEWS 256

// Camera-line coherence (C++: LfdprCameraLineGpu). Every view camera
// lies on one line parallel to the screen and shares the screen rectangle, so clip y, z
// and w rows are the same in every view and clip x is affine in the camera's offset e
// along the line: x_clip(view) = dot(row0, p) + e(view) * dot(row0PerOffset, p).
layout(std140, binding = LFDPR_UBO_CAMERA_LINE) uniform LfdprCameraLineBlock {
    vec4 row0;          // clip x row of view 0 (scene space)
    vec4 row0PerOffset; // its derivative with respect to the camera offset
    vec4 row1;          // clip y row (every view)
    vec4 row3;          // clip w row (every view)
    vec4 wRange;        // x near w, y far w (the depth range every view clips to), zw 0
    // Pixel-centre culling (lfdMayCoverPixelCentre): the same rows for the frame the points
    // are sampled for (the display's views, also under angular supersampling, so the point
    // cloud does not depend on the views it is splatted into), and in cullOffsets.xy the
    // offsets of the two ends of its whole view cone (view 0's interval start, the last
    // view's interval end), which every splatted view lies between.
    vec4 cullRow0;
    vec4 cullRow0PerOffset;
    vec4 cullRow1;
    vec4 cullRow3;
    vec4 cullOffsets;   // xy: cone ends, zw 0
    vec4 viewOffsets[LFDPR_MAX_VIEWS / 4]; // camera offset of view i from view 0 along the
                                           // line: component i % 4 of element i / 4
} u_line;
