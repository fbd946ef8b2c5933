#version 450 core
// LFDPR shading (the visibility pipeline): each view pixel that a point won in
// lfdpr_visibility.comp is shaded once, as mvr shades a fragment - the same material
// function (material_shading.glsl), the point's triangle interpolated perspective-correctly
// at the pixel centre, and every texture fetched with textureGrad at the pixel's exact
// footprint in this view (analytic uv gradients: the pixel's neighbours on the triangle
// plane, as the rasteriser's derivatives), so grazing surfaces filter like mvr's. This
// replaces the paper's per-splat shading with tv_min / tv_max (multiview mipmapping),
// which the paper's pipeline keeps.
//
// Textures are bound per material, so shading runs in passes over LFDPR_SSBO_MATERIAL_IDS:
//   u_pass 0 visits every pixel: the background where no point landed; on the 32-bit path
//            a check that the stored point index belongs to the stored depth key (else
//            the pixel is flagged LFDPR_PIXEL_REPAIR and counted); the pixel's material;
//            untextured materials and u_shadeMaterial are shaded at once.
//   u_pass 1 shades the pending pixels of u_shadeMaterial (one pass per further textured
//            material; a pixel costs one read there).
//   u_pass 2 after a repair (lfdpr_visibility.comp u_pass 1): as u_pass 0 for the flagged
//            pixels only.
// Shaded pixels are marked LFDPR_PIXEL_SHADED.
#ifdef LFDPR_INT64
#extension GL_ARB_gpu_shader_int64 : require
#endif
#include "scene_bindings.glsl"
#define LFDPR_VISIBILITY_PIPELINE
#include "lfdpr_bindings.glsl"
#define LFD_PRECISE precise
#include "lfdpr_math.glsl"
#include "pbr_shading.glsl"
vec2 g_duvdx, g_duvdy; // this pixel's uv footprint, for LFD_SAMPLE
#define LFD_SAMPLE(t, uv) textureGrad(t, uv, g_duvdx, g_duvdy)
#include "material_shading.glsl"
#include "lfdpr_scene_access.glsl"
#include "lfdpr_camera_line.glsl"

layout(local_size_x = 8, local_size_y = 1, local_size_z = 8) in;

layout(binding = LFDPR_IMAGE_VIEWS, rgba8) uniform writeonly image2DArray u_views;
layout(location = LFDPR_LOC_PASS) uniform uint u_pass;
layout(location = LFDPR_LOC_SHADE_MATERIAL) uniform uint u_shadeMaterial;
layout(location = LFD_LOC_STREAMS) uniform uint u_streams;

layout(std430, binding = LFDPR_SSBO_POINTS) readonly buffer Points {
    uvec2 points[];
};
layout(std430, binding = LFDPR_SSBO_RECORDS) readonly buffer Records {
    LfdprRecordGpu records[];
};
layout(std430, binding = LFDPR_SSBO_NORMALS) readonly buffer SceneNormals {
    float sceneNormals[];
};
layout(std430, binding = LFDPR_SSBO_TANGENTS) readonly buffer SceneTangents {
    vec4 sceneTangents[];
};
layout(std430, binding = LFDPR_SSBO_UVS) readonly buffer SceneUvs {
    vec2 sceneUvs[];
};
layout(std430, binding = LFDPR_SSBO_MATERIAL_IDS) buffer MaterialIds {
    uint materialIds[];
};
#ifdef LFDPR_INT64
layout(std430, binding = LFDPR_SSBO_VIEW_DEPTH) readonly buffer ViewWords {
    uint64_t viewWords[];
};
#else
layout(std430, binding = LFDPR_SSBO_VIEW_DEPTH) readonly buffer ViewDepth {
    uint viewDepth[];
};
layout(std430, binding = LFDPR_SSBO_VIEW_COLOR) buffer ViewIndex {
    uint viewIndex[];
};
layout(std430, binding = LFDPR_SSBO_VIS_COUNTERS) buffer VisCounters {
    LfdprVisCountersGpu vis;
};
#endif

const uint kTextureFlags = LFD_MATERIAL_BASE_COLOR_TEXTURE | LFD_MATERIAL_METALLIC_ROUGHNESS_TEXTURE |
                           LFD_MATERIAL_NORMAL_TEXTURE | LFD_MATERIAL_OCCLUSION_TEXTURE |
                           LFD_MATERIAL_EMISSIVE_TEXTURE;

// The point that won this pixel, or 0xFFFFFFFF.
uint winner(uint pixel)
{
#ifdef LFDPR_INT64
    uint64_t word = viewWords[pixel];
    return uint(word >> 32) == 0xFFFFFFFFu ? 0xFFFFFFFFu : uint(word & 0xFFFFFFFFul);
#else
    return viewDepth[pixel] == 0xFFFFFFFFu ? 0xFFFFFFFFu : viewIndex[pixel];
#endif
}

vec3 objectNormal(uint vertex)
{
    return vec3(sceneNormals[3u * vertex], sceneNormals[3u * vertex + 1u], sceneNormals[3u * vertex + 2u]);
}

// Perspective-correct barycentrics of window point p (screen barycentrics weighted by
// 1 / w, as the rasteriser interpolates varyings).
vec3 perspectiveBarycentric(vec2 s0, vec2 s1, vec2 s2, vec3 invW, vec2 p)
{
    vec3 b = vec3(lfdEdge(s1, s2, p), lfdEdge(s2, s0, p), lfdEdge(s0, s1, p)) * invW;
    return b / (b.x + b.y + b.z);
}

// A visible point's triangle in one view: its draw, vertices, scene positions and window
// positions (projected as lfdpr_visibility.comp projects them).
struct ViewTriangle {
    LfdprDrawGpu draw;
    uvec3 vi;
    vec3 p0, p1, p2;
    vec2 s0, s1, s2;
    vec3 invW;
};

ViewTriangle viewTriangle(uint index, uint view)
{
    ViewTriangle t;
    LfdprRecordGpu r = records[points[index].x];
    t.draw = draws[r.draw];
    t.vi = lfdTriangleVertices(t.draw, r.primitive);
    lfdTrianglePositions(t.draw, t.vi, t.p0, t.p1, t.p2);
    vec2 viewSize = u_lfd.viewSize.xy;
    LfdLinePoint v0 = lfdProjectOnLine(t.p0, viewSize), v1 = lfdProjectOnLine(t.p1, viewSize);
    LfdLinePoint v2 = lfdProjectOnLine(t.p2, viewSize);
    float e = lfdViewOffset(view);
    t.s0 = lfdWindowInView(v0, e);
    t.s1 = lfdWindowInView(v1, e);
    t.s2 = lfdWindowInView(v2, e);
    t.invW = vec3(v0.invW, v1.invW, v2.invW);
    return t;
}

vec4 shadePixel(ViewTriangle t, uint view, vec2 centre)
{
    // Step 1: the triangle in this view.
    LfdprDrawGpu draw = t.draw;
    uvec3 vi = t.vi;
    vec3 p0 = t.p0, p1 = t.p1, p2 = t.p2;
    vec2 s0 = t.s0, s1 = t.s1, s2 = t.s2;
    vec3 invW = t.invW;

    // Step 2: attributes at the pixel centre, and the uv footprint from its neighbours.
    vec3 b = perspectiveBarycentric(s0, s1, s2, invW, centre);
    vec3 bx = perspectiveBarycentric(s0, s1, s2, invW, centre + vec2(1.0, 0.0));
    vec3 by = perspectiveBarycentric(s0, s1, s2, invW, centre + vec2(0.0, 1.0));
    NodeGpu node = nodes[draw.node];
    LfdSurfacePoint p;
    p.position = b.x * p0 + b.y * p1 + b.z * p2;
    vec3 eye = views[view].eyeScene.xyz;
    p.vertexNormal = (u_streams & LFD_STREAM_NORMAL) != 0u;
    if (p.vertexNormal) {
        mat3 normalFromObject = mat3(node.normalFromObject);
        p.normal = normalFromObject * (b.x * objectNormal(vi.x) + b.y * objectNormal(vi.y) + b.z * objectNormal(vi.z));
    } else {
        vec3 face = cross(p1 - p0, p2 - p0);
        p.normal = dot(face, eye - p.position) < 0.0 ? -face : face;
    }
    bool mirrored = determinant(mat3(node.sceneFromObject)) < 0.0;
    p.frontFacing = (lfdCanonicalEdge(s0, s1, s2) > 0.0) != mirrored;
    p.tangent = vec4(0.0, 0.0, 0.0, 1.0);
    if ((u_streams & LFD_STREAM_TANGENT) != 0u) {
        vec4 t = b.x * sceneTangents[vi.x] + b.y * sceneTangents[vi.y] + b.z * sceneTangents[vi.z];
        p.tangent = vec4(mat3(node.sceneFromObject) * t.xyz, t.w);
    }
    p.uv = vec2(0.0);
    g_duvdx = vec2(0.0);
    g_duvdy = vec2(0.0);
    if ((u_streams & LFD_STREAM_UV) != 0u) {
        vec2 uv0 = sceneUvs[vi.x], uv1 = sceneUvs[vi.y], uv2 = sceneUvs[vi.z];
        p.uv = b.x * uv0 + b.y * uv1 + b.z * uv2;
        g_duvdx = bx.x * uv0 + bx.y * uv1 + bx.z * uv2 - p.uv;
        g_duvdy = by.x * uv0 + by.y * uv1 + by.z * uv2 - p.uv;
    }

    // Step 3: the material, as mvr shades it (alpha-masked cells were dropped when the
    // points were generated, so a discard here keeps the colour of the cell's centre).
    vec3 color;
    lfdShadeMaterial(materials[draw.material], u_streams, p, eye, color);
    return vec4(color, 1.0);
}

void main()
{
    // Workgroups are 8 x 8 pixel tiles of one view (image stores stay in one layer, which a
    // software rasteriser needs to be fast), dispatched as (x tile, view, row tile): the
    // tiles of all views of one band of rows follow each other, so the view-interleaved
    // buffers' cache lines are reused by the neighbouring views' tiles.
    uvec3 id = gl_GlobalInvocationID.xzy; // x, GL row, view
    uvec2 size = uvec2(u_lfd.viewSize.xy);
    if (id.x >= size.x || id.y >= size.y || id.z >= u_lfd.counts.x)
        return;
    uint pixel = lfdViewWord(id.z, id.x, id.y, size.x, u_lfd.counts.x);
    uint state = materialIds[pixel];
    vec2 centre = vec2(id.xy) + 0.5;

    // note: a software rasteriser (llvmpipe) runs both sides of a divergent `if` under a
    // lane mask, but leaves a loop as soon as no lane is in it. The costly blocks below are
    // one-trip loops, so a vector of pixels with nothing to do here skips them entirely
    // (a pass that shades one material out of many then costs about one read per pixel).
    bool classify = u_pass == 0u || (u_pass == 2u && state == LFDPR_PIXEL_REPAIR);
    bool shade = u_pass == 1u && state == u_shadeMaterial;
    ViewTriangle t;
    for (uint once = classify ? 0u : 1u; once < 1u; ++once) {
        // Classify: background, a point index to repair, or the winner's material.
        uint index = winner(pixel);
        if (index == 0xFFFFFFFFu) {
            materialIds[pixel] = LFDPR_PIXEL_SHADED;
            imageStore(u_views, ivec3(id), u_frame.background);
            break;
        }
        t = viewTriangle(index, id.z);
#ifndef LFDPR_INT64
        LfdViewTriangle vt = lfdViewTriangle(t.s0, t.s1, t.s2, t.invW);
        if (u_pass == 0u && lfdPlaneDepthKey(vt, lfdEdgeValues(vt, centre)) != viewDepth[pixel]) {
            materialIds[pixel] = LFDPR_PIXEL_REPAIR;
            viewIndex[pixel] = 0xFFFFFFFFu; // lfdpr_visibility.comp u_pass 1 sets it again
            atomicAdd(vis.repairCount, 1u);
            break;
        }
#endif
        uint material = t.draw.material;
        bool textured = (u_streams & LFD_STREAM_UV) != 0u && (materials[material].flags & kTextureFlags) != 0u;
        if (textured && material != u_shadeMaterial) {
            materialIds[pixel] = material; // a later pass, with this material's textures bound
            break;
        }
        shade = true;
    }
    for (uint once = shade ? 0u : 1u; once < 1u; ++once) {
        if (u_pass == 1u)
            t = viewTriangle(winner(pixel), id.z);
        imageStore(u_views, ivec3(id), shadePixel(t, id.z, centre));
        materialIds[pixel] = LFDPR_PIXEL_SHADED;
    }
}
