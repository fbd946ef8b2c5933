#version 450 core
// LFDPR visibility splatting (the visibility pipeline; paper section 3.2 without the
// per-splat shading): one invocation per point splats it into every view, writing only
// depth and the point's triangle record; lfdpr_visibility_shade.comp then shades each visible pixel
// once. The record, not the point, is what the shading needs (it evaluates the triangle
// at the pixel's own centre, whichever of its points won), so a pixel's word names it
// directly and the shading reads one texel less per pixel and view.
//
// The splat is the point's sampling cell - a rectangle of the two spacings in the
// triangle plane - projected to a quadrilateral; of the pixels in its bounding box only
// those whose centre lies inside the quad AND inside the point's own triangle (EPR's
// inside-triangle test, with the canonical-edge tie rule so triangles sharing an edge
// neither overlap nor crack) are written. Depth is the triangle plane's along each pixel's
// own ray: 1 / w interpolated with the pixel's screen barycentrics (exact for planes).
//
// Camera-line coherence: the triangle's vertices and the cell's corners are projected
// once per point (lfdpr_camera_line.glsl); per view only their window x moves, by one
// multiply-add each. Facing, coverage and depth are then evaluated per view as usual.
// Views in which the cell holds no pixel centre are culled before the per-view triangle
// setup (docs/player/8k-panels.md "Splat culling"): first by the cell's columns alone, then
// by the columns it shares with the triangle, then, on the GPU work shape and for boxes of
// up to 32 pixels, by testing the box's centres against the cell, whose result the pixel
// loop reuses (llvmpipe runs a lane's skipped setup anyway unless its whole SIMD row
// skips it, and measured the extra loop slower: the CPU shape tests the cell per pixel).
//
// The depth pass also marks, for the point's shading group, the tile chunks and views it
// wrote pixels in (LFDPR_SSBO_CHUNK_MASKS), from which lfdpr_visibility_shade_list.comp lists the
// shading work.
//
// Depth key: lfdPlaneDepthKey (smaller = nearer; 0xFFFFFFFF = empty).
// LFDPR_INT64: atomicMin on (key << 32 | record) (GL_NV_shader_atomic_int64).
// Otherwise 32-bit words: atomicMin on the key, and the invocation that lowered it stores
// its record with a plain store. A nearer point racing a farther one can leave the
// farther one's record behind; lfdpr_visibility_shade.comp checks every pixel's record against its key
// and flags the few that disagree, and only then the index pass runs (LFDPR_INDEX_PASS, a
// program of its own: llvmpipe would run an untaken branch for it in every pixel): where
// the key equals the minimum, atomicMin on the record - for the points that reach a listed
// pixel's tile chunk when the list is short (reachesRepairedChunk). On the GPU work shape a
// point that ties the word's key is queued for the tie pass (LFDPR_TIE_PASS, noteTie), so a
// depth tie goes to the lowest record, the triangle drawn first, as on the 64-bit path.
// The image is the same either way: a pixel's winner is the nearest triangle there.
#ifdef LFDPR_INT64
#extension GL_ARB_gpu_shader_int64 : require
#extension GL_NV_shader_atomic_int64 : require
#endif
#include "scene_bindings.glsl"
#define LFDPR_VISIBILITY_PIPELINE
#include "lfdpr_bindings.glsl"
#include "lfdpr_work_shape.glsl"
#define LFD_PRECISE precise
#include "lfdpr_math.glsl"
#include "lfdpr_scene_access.glsl"
#include "lfdpr_camera_line.glsl"
#include "lfdpr_shade_chunks.glsl"
#include "lfdpr_work_counters.glsl"

layout(local_size_x = LFDPR_GROUP_SIZE) in;

// LFDPR_DIRECT (the direct subpixel splat, lfdpr_direct_fanout.glsl): the same coverage,
// depth and records, written to panel-subpixel words; it marks no tile chunks (its
// shading visits every panel pixel).
#if !defined(LFDPR_DIRECT) && !defined(LFDPR_INDEX_PASS)
#define LFDPR_MARK_CHUNKS
#endif

// An extension point after the 32-bit path's index write, empty here: only a test build of
// this program defines it (lfdpr_visibility_shading.cpp, LfdprOptions::testIndexRaces).
#ifndef LFDPR_AFTER_INDEX_WRITE
#define LFDPR_AFTER_INDEX_WRITE(index, pixel, record)
#endif

layout(std430, binding = LFDPR_SSBO_POINTS) readonly buffer Points {
    LfdprVisibilityPointGpu points[];
};
layout(std430, binding = LFDPR_SSBO_RECORDS) readonly buffer Records {
    LfdprVisibilityRecordGpu records[];
};
layout(std430, binding = LFDPR_SSBO_VIS_COUNTERS) readonly buffer VisCounters {
    LfdprVisibilityCountersGpu vis;
};
#ifdef LFDPR_MARK_CHUNKS
layout(std430, binding = LFDPR_SSBO_CHUNK_MASKS) buffer ChunkMasks {
    uint chunkMasks[];
};

// Marks, for the point's shading group, the tile chunks of one view chunk in which it wrote
// pixels: the tiles of columns tileLo..tileHi (the union over the chunk's views) and rows
// tileRows, with the views it wrote in - one atomicOr per tile and mask word, once per
// point and view chunk (lfdpr_visibility_shade_list.comp lists the marks). The union may list a tile
// for a view the point missed; lfdpr_visibility_shade.comp checks each pixel's winner anyway.
void lfdMarkChunk(uint group, uint chunk, int tileLo, int tileHi, uvec2 tileRows, uvec2 views, uvec2 tiles,
                  uint entries)
{
    for (uint ty = tileRows.x; ty <= tileRows.y; ++ty) {
        for (int tx = tileLo; tx <= tileHi; ++tx) {
            uint word = lfdChunkMaskWord(group, lfdShadeChunkIndex(chunk, uvec2(tx, ty), tiles), entries);
#ifdef LFDPR_WORK_GPU
            // Many points mark the same few words: an atomic only where a bit is missing
            // (a stale read costs one redundant atomicOr, never a lost bit).
            uvec2 have = uvec2(chunkMasks[word], chunkMasks[word + 1u]);
            if ((have.x & views.x) != views.x)
                atomicOr(chunkMasks[word], views.x);
            if ((have.y & views.y) != views.y)
                atomicOr(chunkMasks[word + 1u], views.y);
#else
            if (views.x != 0u)
                atomicOr(chunkMasks[word], views.x);
            if (views.y != 0u)
                atomicOr(chunkMasks[word + 1u], views.y);
#endif
        }
    }
}
#endif
#if defined(LFDPR_TIE_PASS)
// The tie pass (32-bit views path): the index pass over the points the splat queued.
layout(std430, binding = LFDPR_SSBO_SHADE_WORK) readonly LFDPR_SHADE_WORK_BUFFER;
#elif defined(LFDPR_INDEX_PASS) && !defined(LFDPR_DIRECT)
// The repair's index pass (32-bit views path) reads the shading's list of raced pixels.
#define LFDPR_REPAIR_FILTER
layout(std430, binding = LFDPR_SSBO_SHADE_WORK) readonly LFDPR_SHADE_WORK_BUFFER;
#elif !defined(LFDPR_INT64) && !defined(LFDPR_DIRECT) && defined(LFDPR_WORK_GPU)
// The 32-bit views path's single pass queues the points that met a depth tie (the GPU work
// shape: on llvmpipe's, the check's read cost the splat 9-16%, see noteTie).
#define LFDPR_FLAG_TIES
layout(std430, binding = LFDPR_SSBO_SHADE_WORK) LFDPR_SHADE_WORK_BUFFER;
#include "lfdpr_repair_list.glsl"
#endif
#ifdef LFDPR_DIRECT
#include "lfdpr_direct_fanout.glsl"
#elif defined(LFDPR_INT64)
layout(std430, binding = LFDPR_SSBO_VIEW_DEPTH) buffer ViewWords {
    uint64_t viewWords[];
};
#else
layout(std430, binding = LFDPR_SSBO_VIEW_DEPTH) buffer ViewDepth {
    uint viewDepth[];
};
layout(std430, binding = LFDPR_SSBO_VIEW_WINNER) buffer ViewIndex {
    uint viewIndex[];
};
#endif

// The cell's corners projected once onto the camera line (camera-line coherence): the
// cell (sampling coordinates `cell`, its centre) enlarged by LFDPR_SPLAT_OVERLAP so
// neighbouring splats leave no cracks, and clipped to the triangle's bounding box, since
// only centres inside the triangle are written. The clip keeps a cell much larger than
// its triangle (a coarse texture's, around a sub-pixel triangle at its corner) from
// reaching behind a camera, where its projection would fail, and the window-space slack
// (LFDPR_SPLAT_SLACK) keeps the centres the snapped triangle owns just past the box. A
// cell that only touches the box becomes a quad of zero width along it.
void projectCell(vec2 cell, LfdSamplingFrame f, vec2 viewSize, out LfdLinePoint ca, out LfdLinePoint cb,
                 out LfdLinePoint cc, out LfdLinePoint cd)
{
    vec2 lo = max(cell - vec2(0.5 * LFDPR_SPLAT_OVERLAP), vec2(1.0));
    vec2 hi = max(min(cell + vec2(0.5 * LFDPR_SPLAT_OVERLAP), f.triangleHi), lo);
    ca = lfdProjectOnLine(lfdSceneFromSampling(lo, f.origin, f.frame, f.spacing), viewSize);
    cb = lfdProjectOnLine(lfdSceneFromSampling(vec2(hi.x, lo.y), f.origin, f.frame, f.spacing), viewSize);
    cc = lfdProjectOnLine(lfdSceneFromSampling(hi, f.origin, f.frame, f.spacing), viewSize);
    cd = lfdProjectOnLine(lfdSceneFromSampling(vec2(lo.x, hi.y), f.origin, f.frame, f.spacing), viewSize);
}

// The point's triangle (v*) and cell (c*) projected once onto the camera line; false when
// any of them lies behind a camera plane.
bool projectSplat(LfdprVisibilityPointGpu point, LfdprVisibilityRecordGpu r, LfdprVisibilityDrawGpu draw, vec2 viewSize,
                  out LfdLinePoint v0, out LfdLinePoint v1, out LfdLinePoint v2, out LfdLinePoint ca,
                  out LfdLinePoint cb, out LfdLinePoint cc, out LfdLinePoint cd)
{
    vec3 p0, p1, p2;
    lfdTrianglePositions(draw, lfdTriangleVertices(draw, r.primitive), p0, p1, p2);
    LfdSamplingFrame f = lfdRecordFrame(p0, p1, p2, r.spacing);
    v0 = lfdProjectOnLine(p0, viewSize);
    v1 = lfdProjectOnLine(p1, viewSize);
    v2 = lfdProjectOnLine(p2, viewSize);
    projectCell(lfdPointCell(point), f, viewSize, ca, cb, cc, cd);
    return v0.invW > 0.0 && v1.invW > 0.0 && v2.invW > 0.0 && ca.invW > 0.0 && cb.invW > 0.0 && cc.invW > 0.0 &&
           cd.invW > 0.0;
}

// Adds view v of the chunk (and its tile columns colLo..colHi) to the chunk's marks.
void gatherMarks(uint v, int colLo, int colHi, inout int markLo, inout int markHi, inout uvec2 markViews)
{
    markLo = min(markLo, colLo / LFDPR_SHADE_TILE);
    markHi = max(markHi, colHi / LFDPR_SHADE_TILE);
    markViews[v >> 5] |= 1u << (v & 31u);
}

// The pixel rows (or columns) both the cell (its four corners' coordinates, widened by
// LFDPR_SPLAT_SLACK) and the triangle (its three vertices') cover, clipped to
// 0..size - 1; empty when x > y.
ivec2 pixelSpan(vec4 cell, vec3 triangle, int size)
{
    float lo = max(min(min(cell.x, cell.y), min(cell.z, cell.w)) - LFDPR_SPLAT_SLACK,
                   min(min(triangle.x, triangle.y), triangle.z));
    float hi = min(max(max(cell.x, cell.y), max(cell.z, cell.w)) + LFDPR_SPLAT_SLACK,
                   max(max(triangle.x, triangle.y), triangle.z));
    return ivec2(max(int(ceil(lo - 0.5)), 0), min(int(floor(hi - 0.5)), size - 1));
}

// The pixel centres the cell's corner coordinates (x or y of a, b, c, d, widened by
// LFDPR_SPLAT_SLACK) span, clipped to 0..size - 1 (pixelSpan with the cell alone: its span
// holds pixelSpan's); empty when x > y.
ivec2 cellSpan(vec4 cell, int size)
{
    float lo = min(min(cell.x, cell.y), min(cell.z, cell.w)) - LFDPR_SPLAT_SLACK;
    float hi = max(max(cell.x, cell.y), max(cell.z, cell.w)) + LFDPR_SPLAT_SLACK;
    return ivec2(max(int(ceil(lo - 0.5)), 0), min(int(floor(hi - 0.5)), size - 1));
}

// Whether the cell's corner coordinates span a pixel centre inside 0..size - 1.
bool cellSpansCentre(vec4 cell, int size)
{
    ivec2 span = cellSpan(cell, size);
    return span.x <= span.y;
}

// The point projected once (camera-line coherence): what every view of it shares.
// Window x of the cell's corners a, b, c, d (vec4) and of the triangle's vertices (vec3) in
// view e is x0 + e * xPer; y is the same in every view (the triangle's on the sub-pixel grid).
struct LfdSplatPoint {
    vec4 cellX0, cellXPer, cellY;
    vec3 triX0, triXPer, triY;
    vec3 invW;
    ivec2 rows; // pixel rows of the cell and the triangle (the same in every view)
};

// Steps 1-3 of main: the point's triangle and cell projected once; false when any of them
// lies behind a camera plane (the near plane clips such triangles) or no pixel row holds
// both.
bool setupSplatPoint(LfdprVisibilityPointGpu point, LfdprVisibilityRecordGpu r, LfdprVisibilityDrawGpu draw,
                     vec2 viewSize, out LfdSplatPoint sp)
{
    LfdLinePoint v0, v1, v2, ca, cb, cc, cd;
    if (!projectSplat(point, r, draw, viewSize, v0, v1, v2, ca, cb, cc, cd))
        return false;
    sp.cellX0 = vec4(ca.x0, cb.x0, cc.x0, cd.x0);
    sp.cellXPer = vec4(ca.xPerOffset, cb.xPerOffset, cc.xPerOffset, cd.xPerOffset);
    sp.cellY = vec4(ca.y, cb.y, cc.y, cd.y);
    sp.triX0 = vec3(v0.x0, v1.x0, v2.x0);
    sp.triXPer = vec3(v0.xPerOffset, v1.xPerOffset, v2.xPerOffset);
    // The triangle's bounds are those of its vertices on the sub-pixel grid, where
    // lfdViewTriangle puts them for the coverage test.
    sp.triY = vec3(lfdSnapToSubpixels(v0.y), lfdSnapToSubpixels(v1.y), lfdSnapToSubpixels(v2.y));
    sp.invW = vec3(v0.invW, v1.invW, v2.invW);
    sp.rows = pixelSpan(sp.cellY, sp.triY, int(viewSize.y));
    return sp.rows.x <= sp.rows.y;
}

#ifdef LFDPR_WORK_GPU
#define LFDPR_CENTRE_TEST 1 // the centre test before setup (above)
#endif

// Whether cellCentres decides `box` (columns x..z, rows y..w): on the GPU work shape, boxes
// of up to 32 pixels; otherwise splatIntoView tests every centre against the cell itself.
bool centresDecided(ivec4 box)
{
#ifdef LFDPR_CENTRE_TEST
    return (box.z - box.x + 1) * (box.w - box.y + 1) <= 32;
#else
    return false;
#endif
}

// Pixel centres of `box` inside the cell's window quad (a, b, c, d), as bits
// (y - box.y) * columns + (x - box.x) (a box centresDecided decides).
uint cellCentres(ivec4 box, vec2 a, vec2 b, vec2 c, vec2 d, vec4 slack)
{
    int columns = box.z - box.x + 1;
    uint bits = 0u;
    for (int y = box.y; y <= box.w; ++y)
        for (int x = box.x; x <= box.z; ++x)
            if (lfdInsideQuadWithSlack(a, b, c, d, slack, vec2(x, y) + 0.5))
                bits |= 1u << uint((y - box.y) * columns + (x - box.x));
    return bits;
}

#ifdef LFDPR_FLAG_TIES
// Depth ties on the 32-bit views path: a point whose key equals the word's while the index
// holds another triangle's record (coincident surfaces: a decal on its wall, a duplicated
// mesh; or two surfaces crossing at one pixel's key). The single pass keeps whichever
// point lowered the word first, which changes from run to run; mvr's depth test (GL_LESS)
// keeps the triangle drawn first, the lowest record. So such a point is queued, and the tie
// pass (LFDPR_TIE_PASS, after this pass, before the shading) splats the queued points again
// as the index pass does: where the key is the word's, atomicMin on the record. Every
// store of this pass has landed by then, and the first point to reach a word left its record
// there (it lowered the word), so each tied pixel ends with the lowest record. An index
// equal to this record is this triangle's own pixel met again (neighbouring cells overlap
// by LFDPR_SPLAT_OVERLAP), no tie; a stale read (the lowering point's store not yet
// visible) only queues a point that needed nothing. (Where a farther point's late store
// also replaced the first point's record, the pass leaves the queued point's record, at
// the right depth: only the order among the tied is off.) Per sample only the index is read;
// the queueing runs once per point (queueTies), so a GPU pays a load where a key ties and
// an atomic per tied point. The GPU work shape only: llvmpipe runs a branch's body for a
// SIMD row whenever it is compiled in, so its CPU work shape paid the read at every sample,
// 9-16% of the dense sample's splat (docs/player/lfdpr.md, Depth ties); there the first
// point to reach a tied word keeps it.
bool tied; // the point met a tie in its slice

void noteTie(uint pixel, uint record)
{
    if (viewIndex[pixel] != record)
        tied = true;
}

// Queues point `index` (its `slice` of views) for the tie pass when it met a tie. A full
// queue lists the point's tile chunks for the repair instead (whose index pass takes the
// lowest record as well, and whose shading shades them again).
void queueTies(uint index, uint slice, uint firstView, int markLo, int markHi, uvec2 tileRows, uvec2 tiles)
{
    if (!tied)
        return;
    uint entry = atomicAdd(shadeCounters.tieDispatch.w, 1u);
    if (entry < shadeCounters.tieCapacity) {
        groupTiles[shadeCounters.tieBase + 2u * entry] = index;
        groupTiles[shadeCounters.tieBase + 2u * entry + 1u] = slice;
        atomicMax(shadeCounters.tieDispatch.x, entry / uint(LFDPR_GROUP_SIZE) + 1u);
        return;
    }
    for (uint ty = tileRows.x; ty <= tileRows.y; ++ty) {
        for (int tx = markLo; tx <= markHi; ++tx)
            lfdListRepair(lfdShadeChunkIndex(firstView / uint(LFDPR_VIEW_CHUNK), uvec2(tx, ty), tiles));
    }
}
#endif

// The word write of one covered sample (step 6), with the work counters' atomics.
void writeSample(uint pixel, uint key, uint record, uint index)
{
#if defined(LFDPR_DIRECT)
    lfdDirectFanOut(pixel, key, record); // to the panel subpixels that show view word `pixel`
#elif defined(LFDPR_INT64)
    // A plain read first: a word already nearer (or as near with a lower record) makes the
    // atomic a no-op, so it is skipped - most of them where depth complexity is high. A
    // stale read is never nearer than the word (words only decrease), so nothing is
    // skipped that would have won.
    uint64_t word = (uint64_t(key) << 32) | uint64_t(record);
    if (word < viewWords[pixel]) {
        LFDPR_COUNT(atomics, 1u);
#ifdef LFDPR_COUNT_WORK
        LFDPR_COUNT(lowered, atomicMin(viewWords[pixel], word) > word ? 1u : 0u);
#else
        atomicMin(viewWords[pixel], word);
#endif
    }
#elif defined(LFDPR_INDEX_PASS)
    if (viewDepth[pixel] == key)
        atomicMin(viewIndex[pixel], record);
#else
    uint depth = viewDepth[pixel];
    if (key < depth) {
        LFDPR_COUNT(atomics, 1u);
        depth = atomicMin(viewDepth[pixel], key);
        if (key < depth) {
            LFDPR_COUNT(lowered, 1u);
            viewIndex[pixel] = record;
        }
    }
#ifdef LFDPR_FLAG_TIES
    if (key == depth) // after the store above: a lane of the same SIMD row sees its record
        noteTie(pixel, record);
#endif
    LFDPR_AFTER_INDEX_WRITE(index, pixel, record);
#endif
}

// Splats the cell (window quad a, b, c, d) into one view: every pixel centre in `box`
// (columns x..z, rows y..w) inside the quad (bits of `centres` where `decided`, cellCentres)
// that the view's triangle t owns, depth-tested at t's plane within keyRange (near, far).
// `record` is what the view words hold; `index` the point's (the test hook's races key on
// it). Returns whether any pixel was written.
bool splatIntoView(uint view, uint viewCount, int viewWidth, ivec4 box, bool decided, uint centres, vec2 a,
                   vec2 b, vec2 c, vec2 d, vec4 slack, LfdViewTriangle t, uvec2 keyRange, uint record, uint index)
{
    bool wrote = false;
    // One loop over the box's pixels, not one per row and column: llvmpipe runs a loop as
    // long as its busiest lane, so nested loops cost a SIMD row its tallest box times its
    // widest, one loop only its largest box (boxes vary from lane to lane as cells and
    // triangles do).
    int columns = box.z - box.x + 1;
    int count = columns * (box.w - box.y + 1);
    int x = box.x, y = box.y;
    for (int i = 0; i < count; ++i) {
        vec2 p = vec2(x, y) + 0.5;
        bool inCell = decided ? (centres & (1u << uint(i))) != 0u : lfdInsideQuadWithSlack(a, b, c, d, slack, p);
        if (inCell) {
            vec3 edges = lfdEdgeValues(t, p);
            uint key = lfdPlaneDepthKey(t, edges);
            // Keys outside keyRange are clipped by the near or far plane.
            if (lfdOwnsSample(t, edges) && key >= keyRange.x && key <= keyRange.y) {
                wrote = true;
                LFDPR_COUNT(samples, 1u);
                writeSample(lfdViewWord(view, uint(x), uint(y), uint(viewWidth), viewCount), key, record, index);
            }
        }
        // The next pixel of the box, row by row (bit i of `centres`).
        bool rowEnd = x == box.z;
        x = rowEnd ? box.x : x + 1;
        y = rowEnd ? y + 1 : y;
    }
    return wrote;
}

#ifdef LFDPR_REPAIR_FILTER
// Whether the point may write a pixel of a tile chunk the repair lists (the index pass's
// step 3): the tiles of its rows and of the columns its cell spans over the slice's views
// (x is linear in the camera offset, so the slice's extreme offsets bound it), in this
// view chunk. Why: the index pass exists for the few raced pixels the shading found
// (lfdpr_visibility_shade.comp), mostly one or two per frame, and walking every point's
// views for them cost as much as the splat; only the listed chunks are shaded again, so
// the words elsewhere need no index. When the list overflowed (the shading then shades
// every chunk again) or is long, every point runs.
bool reachesRepairedChunk(LfdSplatPoint sp, uint sliceFirst, uint endView, uint firstView, ivec2 viewPixels)
{
    uint repairs = shadeCounters.repairCount;
    if (repairs > shadeCounters.repairCapacity || repairs > uint(LFDPR_REPAIR_FILTER_MAX))
        return true;
    float eLo = lfdViewOffset(sliceFirst), eHi = eLo;
    for (uint view = sliceFirst + 1u; view < endView; ++view) {
        eLo = min(eLo, lfdViewOffset(view));
        eHi = max(eHi, lfdViewOffset(view));
    }
    ivec2 spanLo = cellSpan(sp.cellX0 + eLo * sp.cellXPer, viewPixels.x);
    ivec2 spanHi = cellSpan(sp.cellX0 + eHi * sp.cellXPer, viewPixels.x);
    ivec2 columns = ivec2(min(spanLo.x, spanHi.x), max(spanLo.y, spanHi.y)); // their union
    if (columns.x > columns.y)
        return false; // no column in any view: nothing to write
    uvec2 tiles = lfdShadeTiles(uvec2(viewPixels));
    uvec2 tileLo = uvec2(columns.x, sp.rows.x) / uint(LFDPR_SHADE_TILE);
    uvec2 tileHi = uvec2(columns.y, sp.rows.y) / uint(LFDPR_SHADE_TILE);
    for (uint i = 0u; i < repairs; ++i) {
        LfdShadeChunk c = lfdShadeChunk(groupTiles[shadeCounters.repairBase + i], tiles, u_lfd.counts.x);
        if (c.firstView == firstView && all(greaterThanEqual(c.tile, tileLo)) && all(lessThanEqual(c.tile, tileHi)))
            return true;
    }
    return false;
}
#endif

// Steps 4-6 of main for one view: the culls before any per-view setup (the cell's columns,
// those it shares with the triangle, its pixel centres), then the triangle's setup, facing
// and the splat. Returns the columns written (x > y: none).
ivec2 splatView(uint view, uint viewCount, LfdSplatPoint sp, ivec2 viewPixels, bool doubleSided, bool mirrored,
                uvec2 keyRange, uint record, uint index)
{
    // Step 4: this view's window x of the cell's corners; no pixel centre column, no setup.
    float e = lfdViewOffset(view);
    vec4 cellX = sp.cellX0 + e * sp.cellXPer;
#ifdef LFDPR_CENTRE_TEST // (llvmpipe: one test below rather than two masked branches)
    if (!cellSpansCentre(cellX, viewPixels.x)) {
        LFDPR_COUNT(culled, 1u);
        return ivec2(0, -1);
    }
#endif
    vec3 triX = sp.triX0 + e * sp.triXPer;
    triX = vec3(lfdSnapToSubpixels(triX.x), lfdSnapToSubpixels(triX.y), lfdSnapToSubpixels(triX.z));
    ivec2 columns = pixelSpan(cellX, triX, viewPixels.x);
    ivec4 box = ivec4(columns.x, sp.rows.x, columns.y, sp.rows.y);
    vec2 a = vec2(cellX.x, sp.cellY.x), b = vec2(cellX.y, sp.cellY.y);
    vec2 c = vec2(cellX.z, sp.cellY.z), d = vec2(cellX.w, sp.cellY.w);
    if (columns.x > columns.y) {
        LFDPR_COUNT(culled, 1u);
        return ivec2(0, -1);
    }
    bool decided = centresDecided(box);
    vec4 slack = lfdQuadEdgeSlack(a, b, c, d, LFDPR_SPLAT_SLACK);
    uint centres = decided ? cellCentres(box, a, b, c, d, slack) : 0u;
    if (decided && centres == 0u) {
        LFDPR_COUNT(culled, 1u);
        LFDPR_COUNT(culledCentres, 1u);
        return ivec2(0, -1);
    }

    // Step 5: the triangle in this view; facing as the rasteriser decides it.
    LfdViewTriangle t = lfdViewTriangleSnapped(vec2(triX.x, sp.triY.x), vec2(triX.y, sp.triY.y),
                                               vec2(triX.z, sp.triY.z), sp.invW);
    if (t.orientation == 0.0 || (!doubleSided && (t.orientation > 0.0) == mirrored))
        return ivec2(0, -1); // degenerate, or a single-sided back face

    // Step 6: covered pixels, their plane depth, the atomic depth test.
    bool wrote =
        splatIntoView(view, viewCount, viewPixels.x, box, decided, centres, a, b, c, d, slack, t, keyRange, record,
                      index);
    return wrote ? columns : ivec2(0, -1);
}

// One invocation's work (main): the point `index` into the views of its slice.
void splatPoint(uint index, uint slice, uint viewCount)
{
    // Step 1: the point, its triangle and the cell's corners in the triangle plane.
    LfdprVisibilityPointGpu point = points[index];
    uint record = point.record; // what the view words hold
    LfdprVisibilityRecordGpu r = records[record];
    LfdprVisibilityDrawGpu draw = draws[r.draw];
    bool doubleSided = (materials[draw.material].flags & LFD_MATERIAL_DOUBLE_SIDED) != 0u;
    bool mirrored = determinant(mat3(nodes[draw.node].sceneFromObject)) < 0.0;

    // This invocation's views: one slice, inside one view chunk (LFDPR_SPLAT_VIEWS divides
    // LFDPR_VIEW_CHUNK), whose marks it gathers.
    uint sliceFirst = slice * uint(LFDPR_SPLAT_VIEWS);
    uint firstView = sliceFirst - sliceFirst % uint(LFDPR_VIEW_CHUNK); // the chunk's first view
    uint endView = min(sliceFirst + uint(LFDPR_SPLAT_VIEWS), viewCount);

    // Steps 2-3: project once (camera-line coherence); the rows are the same in every view.
    // Geometry outside the shared depth range is clipped in every view alike.
    vec2 viewSize = u_lfd.viewSize.xy;
    LfdSplatPoint sp;
    if (!setupSplatPoint(point, r, draw, viewSize, sp)) {
        LFDPR_COUNT(culled, endView - sliceFirst);
        return;
    }
    ivec2 viewPixels = ivec2(viewSize);
#ifdef LFDPR_REPAIR_FILTER
    if (!reachesRepairedChunk(sp, sliceFirst, endView, firstView, viewPixels))
        return;
#endif
    uvec2 keyRange = uvec2(lfdDepthKey(1.0 / u_line.wRange.x), lfdDepthKey(1.0 / u_line.wRange.y));

    int markLo = viewPixels.x, markHi = -1; // tile columns written in this view chunk
    uvec2 markViews = uvec2(0u);
#ifdef LFDPR_FLAG_TIES
    tied = false;
#endif
    for (uint view = sliceFirst; view < endView; ++view) {
        ivec2 columns = splatView(view, viewCount, sp, viewPixels, doubleSided, mirrored, keyRange, record, index);
#ifdef LFDPR_MARK_CHUNKS
        // Step 7: gather this view's tiles for the chunk's marks.
        if (columns.x <= columns.y)
            gatherMarks(view - firstView, columns.x, columns.y, markLo, markHi, markViews);
#endif
    }
#ifdef LFDPR_MARK_CHUNKS
    uvec2 tiles = lfdShadeTiles(uvec2(viewPixels));
    lfdMarkChunk(draw.group, firstView / uint(LFDPR_VIEW_CHUNK), markLo, markHi,
                 uvec2(sp.rows) / uint(LFDPR_SHADE_TILE), markViews, tiles, lfdShadeEntryCount(tiles, viewCount));
#endif
#ifdef LFDPR_FLAG_TIES
    queueTies(index, slice, firstView, markLo, markHi, uvec2(sp.rows) / uint(LFDPR_SHADE_TILE), tiles);
#endif
}

void main()
{
    // Workgroup w splats LFDPR_GROUP_SIZE consecutive points into one slice of
    // LFDPR_SPLAT_VIEWS views (lfdpr_work_shape.glsl; lfdpr_paper_dispatch.comp sized the grid).
    uint viewCount = u_lfd.counts.x;
    uint slices = lfdSplatSlices(viewCount);
    uint workgroup = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
#ifdef LFDPR_TIE_PASS
    uint entry = workgroup * uint(LFDPR_GROUP_SIZE) + gl_LocalInvocationIndex;
    if (entry < min(shadeCounters.tieDispatch.w, shadeCounters.tieCapacity))
        splatPoint(groupTiles[shadeCounters.tieBase + 2u * entry], groupTiles[shadeCounters.tieBase + 2u * entry + 1u],
                   viewCount);
#else
    uint slice = workgroup % slices;
    uint index = (workgroup / slices) * uint(LFDPR_GROUP_SIZE) + gl_LocalInvocationIndex;
    if (index < min(vis.pointCount, u_lfd.counts.y))
        splatPoint(index, slice, viewCount);
#endif
#if defined(LFDPR_COUNT_WORK) && !defined(LFDPR_INDEX_PASS)
    lfdWorkFlush(); // uniform control flow: every invocation of the workgroup gets here
#endif
}
