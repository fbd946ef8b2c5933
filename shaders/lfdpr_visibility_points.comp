#version 450 core
// LFDPR point generation in compute (the visibility pipeline; paper section 3.1). The
// geometry shader of the paper's pipeline is its bottleneck on every driver we measured,
// so here one invocation samples one triangle: the same setup (lfdpr_triangle_setup.glsl:
// culling, LFD-biased densities, texture-based splatting, T_align / S_ortho, coarsening)
// and the same conservative sampling rule as the geometry + fragment shaders, so the
// point set is the same (up to order). A point is 8 bytes: its triangle record and the
// sampling cell (x | y << 16); the record holds the triangle and its final spacings.
//
// Default pass: one invocation per triangle. Workgroups are listed in LfdprVisibilityWorkgroupGpu
// entries (LFDPR_GROUP_SIZE triangles of one draw each), so one dispatch samples every draw
// of a dispatch class: all draws without an alpha test, or one alpha-tested draw (its
// textures bound). A triangle whose sampling box exceeds LFDPR_LARGE_CELLS cells
// (lfdpr_work_shape.glsl) is queued for the large pass instead, so no invocation loops over
// a large box while its neighbours idle.
// LFDPR_LARGE_PASS: one workgroup per queued triangle of the class; one thread sets the
// triangle up, its threads stride over the box, count, reserve one range of the point
// buffer, and write.
//
// LFDPR_PIXEL_CENTRE_CULLING (beyond the paper, on by default): a triangle that holds no
// view pixel centre in any view (lfdMayCoverPixelCentre) emits no points, since none of
// them could win a pixel. Sub-pixel triangles of dense scenes are mostly such triangles.
//
// LFDPR_TRIM_MARGIN (beyond the paper, on by default): the sampling box's first row and
// column are not sampled. They are the one-cell margin lfdPlaceSampling adds for the paper's
// conservative rasteriser, and lie wholly below the triangle's least x or y (which it puts
// at 1), so their cells only touch the triangle: with the closed test of
// lfdPixelOverlapsTriangle every such cell holding a vertex emits a point, and a sub-pixel
// triangle gets three or four points where one cell holds all of it. The splat clips each
// cell to its triangle's box and reaches LFDPR_SPLAT_SLACK pixels past it, which covers
// what those points wrote (centres that the snapped triangle owns just outside the exact
// one). A triangle narrower than the rounding of its placement (greatest x or y below 1)
// keeps that row or column, so that it still emits.
//
// Alpha-masked materials (glTF MASK): a cell whose base-colour alpha at the finest LOD
// any view needs (eq. minLOD) is below the cutoff emits no point, so the visibility pass
// never needs the material's textures. That test is compiled in only for draws of masked
// materials (LFDPR_ALPHA_TEST): a software rasteriser (llvmpipe) runs an untaken branch
// under a lane mask at full price, so every other draw's cells would pay for a texture
// fetch they never make.
#include "scene_bindings.glsl"
#define LFDPR_VISIBILITY_PIPELINE
#include "lfdpr_bindings.glsl"
#include "lfdpr_work_shape.glsl"
#define LFD_PRECISE precise
#include "lfdpr_math.glsl"
#include "lfdpr_triangle_setup.glsl"
#include "lfdpr_scene_access.glsl"
#include "lfdpr_camera_line.glsl"

layout(local_size_x = LFDPR_GROUP_SIZE) in;

// The first sampled column and row of triangle s's box (LFDPR_TRIM_MARGIN above).
uvec2 firstCell(LfdTriangleSetup s)
{
#ifdef LFDPR_TRIM_MARGIN
    return uvec2(greaterThanEqual(max(max(s.q0, s.q1), s.q2), vec2(1.0)));
#else
    return uvec2(0u);
#endif
}

layout(location = LFD_LOC_STREAMS) uniform uint u_streams;
layout(location = LFDPR_LOC_FIRST_WORKGROUP) uniform uint u_firstWorkgroup;
layout(location = LFDPR_LOC_WORKGROUPS) uniform uint u_workgroups;
layout(location = LFDPR_LOC_LARGE_CLASS) uniform uint u_largeClass;
layout(location = LFDPR_LOC_LARGE_BASE) uniform uint u_largeBase;

layout(binding = LFD_UNIT_BASE_COLOR) uniform sampler2D t_baseColor;

layout(std430, binding = LFDPR_SSBO_UVS) readonly buffer SceneUvs {
    vec2 sceneUvs[];
};
layout(std430, binding = LFDPR_SSBO_POINTS) writeonly buffer Points {
    LfdprVisibilityPointGpu points[];
};
layout(std430, binding = LFDPR_SSBO_RECORDS) writeonly buffer Records {
    LfdprVisibilityRecordGpu records[];
};
layout(std430, binding = LFDPR_SSBO_LARGE) buffer Large {
    uvec2 largeTriangles[]; // (workgroup entry, primitive)
};
layout(std430, binding = LFDPR_SSBO_WORKGROUPS) readonly buffer Workgroups {
    LfdprVisibilityWorkgroupGpu workgroups[];
};
layout(std430, binding = LFDPR_SSBO_LARGE_DISPATCH) buffer LargeDispatch {
    uvec4 largeDispatch[];
};
layout(std430, binding = LFDPR_SSBO_VIS_COUNTERS) coherent buffer VisCounters {
    LfdprVisibilityCountersGpu vis;
};

// The triangle being sampled: setup plus what the alpha test needs.
struct Sampled {
    uint draw;
    LfdTriangleSetup s;
    float cutoff;
    float alphaLod;
    vec4 baseFactor;
    vec2 uv0, uv1, uv2;
};

bool setUp(uint drawIndex, uint primitive, out Sampled t)
{
    t.draw = drawIndex;
    LfdprVisibilityDrawGpu draw = draws[drawIndex];
    uvec3 vertices = lfdTriangleVertices(draw, primitive);
    vec3 p0, p1, p2;
    lfdTrianglePositions(draw, vertices, p0, p1, p2);
#ifdef LFDPR_PIXEL_CENTRE_CULLING
    if (!lfdMayCoverPixelCentre(p0, p1, p2))
        return false;
#endif
    if (!lfdSetupTriangle(p0, p1, p2, lfdOutsideHullBits(p0), lfdOutsideHullBits(p1), lfdOutsideHullBits(p2),
                          draw.material, draw.node, u_streams, draw.firstTriangle + primitive, t.s))
        return false;
#ifdef LFDPR_ALPHA_TEST
    MaterialGpu m = materials[draw.material];
    t.cutoff = m.emissiveCutoff.w;
    t.baseFactor = m.baseColorFactor;
    bool textured = (u_streams & LFD_STREAM_UV) != 0u && (m.flags & LFD_MATERIAL_BASE_COLOR_TEXTURE) != 0u;
    t.uv0 = textured ? sceneUvs[vertices.x] : vec2(0.0);
    t.uv1 = textured ? sceneUvs[vertices.y] : vec2(0.0);
    t.uv2 = textured ? sceneUvs[vertices.z] : vec2(0.0);
    t.alphaLod = -1.0; // < 0: untextured, the factor alone decides
    if (textured) {
        ivec2 size = textureSize(t_baseColor, 0);
        t.alphaLod = lfdLod(t.s.vpuvMin, float(size.x) * float(size.y));
    }
#endif
    return true;
}

// The conservative sampling rule of lfdpr_paper_points.frag (step 1) plus the alpha test.
bool emits(Sampled t, vec2 q)
{
    if (!lfdPixelOverlapsTriangle(q, t.s.q0, t.s.q1, t.s.q2))
        return false;
#ifndef LFDPR_ALPHA_TEST
    return true;
#else
    float alpha = t.baseFactor.a;
    if (t.alphaLod >= 0.0) {
        vec3 w = lfdClampedBarycentric(t.s.q0, t.s.q1, t.s.q2, q);
        vec2 uv = w.x * t.uv0 + w.y * t.uv1 + w.z * t.uv2;
        alpha *= textureLod(t_baseColor, uv, t.alphaLod).a;
    }
    return alpha >= t.cutoff;
#endif
}

// Writes the record of triangle `primitive` of workgroup entry w at its own slot, the
// triangle's drawn index (w.firstRecord on): the view words break depth ties by the lower
// record, so numbering records in draw order, rather than in the order in which invocations
// happen to run, makes the winner of a tie the same in every run - the triangle drawn first,
// as mvr's depth test keeps it.
uint writeRecord(LfdprVisibilityWorkgroupGpu w, uint primitive, Sampled t)
{
    atomicAdd(vis.recordCount, 1u);
    uint record = w.firstRecord + (primitive - w.firstPrimitive);
    // The spacings carry the frame's choices in their signs (lfdSignedSpacing), so the splat
    // rebuilds this very frame (lfdRecordFrame).
    records[record] = LfdprVisibilityRecordGpu(t.draw, primitive, lfdSignedSpacing(t.s.spacing, t.s.frame.choices));
    return record;
}

// Reserves `count` points; returns the first. The splat's indirect dispatch
// (vis.splatGroups*, lfdSplatGroups of the stored points) is kept covering every point
// reserved so far, as monotone maxima of (x, y), so no pass after point generation has to
// size it; only a reservation that crosses a workgroup boundary of points updates it
// (a few in a hundred), since every reservation of a frame contends for these words.
// splatGroupsZ is 1 from the renderer's clear.
uint reservePoints(uint count)
{
    uint first = atomicAdd(vis.pointCount, count);
    uint capacity = u_lfd.counts.y;
    uint before = (min(first, capacity) + uint(LFDPR_GROUP_SIZE) - 1u) / uint(LFDPR_GROUP_SIZE);
    uint after = (min(first + count, capacity) + uint(LFDPR_GROUP_SIZE) - 1u) / uint(LFDPR_GROUP_SIZE);
    if (after > before) {
        // The splat's view count (counts.w), not the sampling's (counts.x): under --ss 2v
        // points sampled for N views are splatted into 2N, in twice the slices.
        uvec3 groups = lfdSplatGroups(min(first + count, capacity), u_lfd.counts.w);
        atomicMax(vis.splatGroupsX, groups.x);
        atomicMax(vis.splatGroupsY, groups.y);
    }
    return first;
}

void countShape(Sampled t)
{
    if (t.s.coarsened)
        atomicAdd(vis.coarsenedCount, 1u);
    if (lfdTileCount(t.s.extent, float(LFDPR_TILE_SIZE)) > 1.0)
        atomicAdd(vis.oversizedCount, 1u);
}

#ifndef LFDPR_LARGE_PASS

void main()
{
    uint workgroup = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
    if (workgroup >= u_workgroups)
        return;
    LfdprVisibilityWorkgroupGpu w = workgroups[u_firstWorkgroup + workgroup];
    if (gl_LocalInvocationIndex >= w.primitives)
        return;
    uint primitive = w.firstPrimitive + gl_LocalInvocationIndex;
    Sampled t;
    if (!setUp(w.draw, primitive, t))
        return;
    uint ex = uint(t.s.extent.x), ey = uint(t.s.extent.y);
    if (ex * ey > uint(LFDPR_LARGE_CELLS) || ex > 0xFFFFu || ey > 0xFFFFu) {
        // Step 1 (large): queue for a workgroup. The class's indirect dispatch keeps
        // (x, y) covering the queue with x at most 65535 (monotone maxima, so the order in
        // which triangles queue does not matter) and the count in w.
        uint slot = atomicAdd(largeDispatch[u_largeClass].w, 1u);
        atomicMax(largeDispatch[u_largeClass].x, min(slot + 1u, 65535u));
        atomicMax(largeDispatch[u_largeClass].y, slot / 65535u + 1u);
        largeTriangles[u_largeBase + slot] = uvec2(u_firstWorkgroup + workgroup, primitive);
        atomicAdd(vis.largeCount, 1u);
        return;
    }
    countShape(t);

    // Step 2: count the cells, reserve them, write them (the capacity is never exceeded;
    // the count still grows so the renderer sees the overflow).
    uvec2 first = firstCell(t.s);
    uint count = 0u;
    for (uint y = first.y; y < ey; ++y)
        for (uint x = first.x; x < ex; ++x)
            if (emits(t, vec2(x, y) + 0.5))
                ++count;
    if (count == 0u)
        return;
    uint record = writeRecord(w, primitive, t);
    uint index = reservePoints(count);
    uint capacity = u_lfd.counts.y;
    for (uint y = first.y; y < ey; ++y)
        for (uint x = first.x; x < ex; ++x)
            if (emits(t, vec2(x, y) + 0.5)) {
                if (index < capacity)
                    points[index] = LfdprVisibilityPointGpu(record, x | (y << 16));
                ++index;
            }
}

#else

shared Sampled s_triangle;
shared bool s_emitting;
shared uint s_count;
shared uint s_first;
shared uint s_record;

void main()
{
    uint slot = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
    if (slot >= largeDispatch[u_largeClass].w)
        return; // past the queue (the (x, y) grid rounds up); the same for the whole workgroup
    uvec2 queued = largeTriangles[u_largeBase + slot]; // (workgroup entry, primitive)
    LfdprVisibilityWorkgroupGpu w = workgroups[queued.x];

    // Step 1: one thread sets the triangle up (same inputs as the default pass: it emits).
    if (gl_LocalInvocationIndex == 0u) {
        s_count = 0u;
        Sampled t;
        s_emitting = setUp(w.draw, queued.y, t);
        s_triangle = t;
        if (s_emitting)
            countShape(t);
    }
    barrier();
    Sampled t = s_triangle;
    // The sampled part of the box: columns first.x.. and rows first.y.. of the extent.
    uvec2 first = firstCell(t.s);
    uint ex = s_emitting ? uint(t.s.extent.x) - first.x : 0u, ey = s_emitting ? uint(t.s.extent.y) - first.y : 0u;
    uint cells = ex * ey;

    // Step 2: each thread counts its cells (cells i, i + group, i + 2 group, ...).
    uint mine = 0u;
    for (uint c = gl_LocalInvocationIndex; c < cells; c += uint(LFDPR_GROUP_SIZE))
        if (emits(t, vec2(first.x + c % ex, first.y + c / ex) + 0.5))
            ++mine;
    uint offset = atomicAdd(s_count, mine);
    barrier();

    // Step 3: one thread reserves the range and writes the record.
    if (gl_LocalInvocationIndex == 0u && s_count > 0u) {
        s_record = writeRecord(w, queued.y, t);
        s_first = reservePoints(s_count);
    }
    barrier();
    if (s_count == 0u)
        return;

    // Step 4: write.
    uint index = s_first + offset;
    uint capacity = u_lfd.counts.y;
    for (uint c = gl_LocalInvocationIndex; c < cells; c += uint(LFDPR_GROUP_SIZE))
        if (emits(t, vec2(first.x + c % ex, first.y + c / ex) + 0.5)) {
            if (index < capacity)
                points[index] = LfdprVisibilityPointGpu(s_record, (first.x + c % ex) | ((first.y + c / ex) << 16));
            ++index;
        }
}

#endif
