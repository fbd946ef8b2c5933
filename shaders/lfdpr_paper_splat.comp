#version 450 core
// LFDPR view generation (paper sections 3.2, 3.3): one invocation per point splats it into
// every view. The splat is the point's sampling cell - a world-space rectangle of the two
// spacings in the triangle plane, aligned with the sampling axes (a square when the
// densities are equal) - projected to a quadrilateral; of the pixels in its bounding box
// only those whose centre lies inside the quad AND inside the point's own triangle (edge
// functions on the projected vertices, with a tie rule, so triangles sharing an edge
// neither overlap nor leave cracks: EPR's inside-triangle test) are filled. Depth comes
// from the triangle plane at each pixel (not the splat centre), so intersecting surfaces
// resolve per pixel. Shading is per view: PBR metallic-roughness (pbr_shading.glsl, as mvr)
// with each texture value interpolated between the point's tv_min and tv_max by the
// splat's texture footprint in this view (eqs. interpolationParameter, interplateTexValue).
//
// Depth resolve: LFDPR_INT64 defined: atomicMin on (depth << 32 | rgba8) words
// (GL_NV_shader_atomic_int64). Otherwise two passes over 32-bit words selected by u_pass:
// 0 = atomicMin on depth, 1 = atomicMin on colour where the depth equals the minimum.
// Both give the same result: the smallest depth, ties broken by the smallest colour word.
#ifdef LFDPR_INT64
#extension GL_ARB_gpu_shader_int64 : require
#extension GL_NV_shader_atomic_int64 : require
#endif
#include "scene_bindings.glsl"
#include "lfdpr_bindings.glsl"
#define LFD_PRECISE precise
#include "lfdpr_math.glsl"
#include "pbr_shading.glsl"
#include "srgb.glsl"

layout(local_size_x = LFDPR_GROUP_SIZE) in;

layout(std430, binding = LFDPR_SSBO_POINTS) readonly buffer Points {
    LfdprPaperPointGpu points[];
};
layout(std430, binding = LFDPR_SSBO_TRIANGLES) readonly buffer TriangleRecords {
    LfdprPaperTriangleGpu records[];
};
layout(std430, binding = LFDPR_SSBO_VIEW_INVERSE) readonly buffer ViewInverse {
    mat4 sceneFromClip[];
};
#ifdef LFDPR_INT64
layout(std430, binding = LFDPR_SSBO_VIEW_DEPTH) buffer ViewWords {
    uint64_t viewWords[];
};
#else
layout(std430, binding = LFDPR_SSBO_VIEW_DEPTH) buffer ViewDepth {
    uint viewDepth[];
};
layout(std430, binding = LFDPR_SSBO_VIEW_WINNER) buffer ViewColor {
    uint viewColor[];
};
layout(location = LFDPR_LOC_PASS) uniform uint u_pass;
#endif

vec4 unpackSrgb(uint word)
{
    vec4 v = unpackUnorm4x8(word);
    return vec4(srgbToLinear(v.rgb), v.a);
}

// View-space window coordinates (pixels, GL row 0 = bottom) of a scene point.
vec2 toWindow(mat4 clipFromScene, vec3 p, vec2 viewSize)
{
    vec4 c = clipFromScene * vec4(p, 1.0);
    return (vec2(c.x, c.y) / c.w * 0.5 + 0.5) * viewSize;
}

bool inFront(mat4 clipFromScene, vec3 p)
{
    return (clipFromScene * vec4(p, 1.0)).w > 0.0;
}

void main()
{
    uint index = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * uint(LFDPR_GROUP_SIZE) +
                 gl_LocalInvocationIndex;
    if (index >= min(counters.pointCount, u_lfd.counts.y))
        return;

    // Step 1: the point, its triangle and its material.
    LfdprPaperPointGpu point = points[index];
    LfdprPaperTriangleGpu r = records[point.triangle];
    vec3 p0 = r.p0.xyz, p1 = r.p1.xyz, p2 = r.p2.xyz;
    uint flags = floatBitsToUint(r.p2.w);
    MaterialGpu m = materials[floatBitsToUint(r.p0.w)];
    bool doubleSided = (flags & LFDPR_TRIANGLE_DOUBLE_SIDED) != 0u;
    bool mirrored = (flags & LFDPR_TRIANGLE_MIRRORED) != 0u;
    vec3 axisU = r.axisU.xyz, axisV = r.axisV.xyz;
    vec3 planeNormal = cross(axisU, axisV);
    vec4 planeScene = vec4(planeNormal, -dot(planeNormal, p0));
    vec3 halfU = axisU * (0.5 * r.axisU.w * LFDPR_SPLAT_OVERLAP);
    vec3 halfV = axisV * (0.5 * r.axisV.w * LFDPR_SPLAT_OVERLAP);
    vec3 c00 = point.position - halfU - halfV, c10 = point.position + halfU - halfV;
    vec3 c11 = point.position + halfU + halfV, c01 = point.position - halfU + halfV;
    // The splat's texture area (the unenlarged cell) for eq. interpolationParameter.
    float splatUvArea = r.axisU.w * r.axisV.w * r.p1.w;
    const float cellAreaFraction = 1.0 / (LFDPR_SPLAT_OVERLAP * LFDPR_SPLAT_OVERLAP);

    vec4 baseMin = unpackSrgb(point.baseColorMin), baseMax = unpackSrgb(point.baseColorMax);
    vec4 ormMin = unpackUnorm4x8(point.ormMin), ormMax = unpackUnorm4x8(point.ormMax);
    vec4 emissiveMin = unpackSrgb(point.emissiveMin), emissiveMax = unpackSrgb(point.emissiveMax);
    vec3 normalMin = lfdOctDecode(unpackSnorm2x16(point.normalMin));
    vec3 normalMax = lfdOctDecode(unpackSnorm2x16(point.normalMax));

    vec2 viewSize = u_lfd.viewSize.xy;
    ivec2 viewPixels = ivec2(viewSize);
    uint viewCount = u_lfd.counts.x;
    for (uint view = 0u; view < viewCount; ++view) {
        mat4 clipFromScene = views[view].clipFromScene;
        if (!inFront(clipFromScene, p0) || !inFront(clipFromScene, p1) || !inFront(clipFromScene, p2) ||
            !inFront(clipFromScene, c00) || !inFront(clipFromScene, c10) ||
            !inFront(clipFromScene, c11) || !inFront(clipFromScene, c01))
            continue;

        // Step 2: the projected triangle; facing as the rasteriser decides it.
        vec2 s0 = toWindow(clipFromScene, p0, viewSize);
        vec2 s1 = toWindow(clipFromScene, p1, viewSize);
        vec2 s2 = toWindow(clipFromScene, p2, viewSize);
        float area = lfdCanonicalEdge(s0, s1, s2);
        if (area == 0.0)
            continue;
        bool front = (area > 0.0) != mirrored;
        if (!front && !doubleSided)
            continue;

        // Step 3: the projected splat and the pixels of its bounding box (clipped to the
        // triangle's box and the view).
        vec2 a = toWindow(clipFromScene, c00, viewSize), b = toWindow(clipFromScene, c10, viewSize);
        vec2 c = toWindow(clipFromScene, c11, viewSize), d = toWindow(clipFromScene, c01, viewSize);
        vec2 lo = max(min(min(a, b), min(c, d)), min(min(s0, s1), s2));
        vec2 hi = min(max(max(a, b), max(c, d)), max(max(s0, s1), s2));
        ivec2 pixelLo = max(ivec2(ceil(lo - 0.5)), ivec2(0));
        ivec2 pixelHi = min(ivec2(floor(hi - 0.5)), viewPixels - 1);
        if (any(greaterThan(pixelLo, pixelHi)))
            continue;

        // Step 4: per-view texture values (eqs. interpolationParameter, interplateTexValue).
        vec2 ad = d - a, ab = b - a, cb = b - c, cd = d - c;
        float quadPixels = 0.5 * (abs(lfdCross2(ab, ad)) + abs(lfdCross2(cb, cd)));
        float splatNdcArea = quadPixels * cellAreaFraction * 4.0 / (viewSize.x * viewSize.y);
        float sizeVse = lfdSplatTextureArea(splatUvArea, splatNdcArea, viewSize);
        float weight = lfdMipInterpolation(sizeVse, r.mip.x, r.mip.y);
        vec4 base = m.baseColorFactor * lfdInterpolateTexValue(baseMin, baseMax, weight);
        if (m.alphaMode == LFD_ALPHA_MASK && base.a < m.emissiveCutoff.w)
            continue;

        // Step 5: depth plane in clip space (z_ndc = -(A x + B y + D) / C), so each pixel
        // gets the depth of the triangle plane along its own ray.
        vec4 planeClip = planeScene * sceneFromClip[view]; // = transpose(sceneFromClip) * plane
        if (planeClip.z == 0.0)
            continue;

        uint color = 0u;
#ifndef LFDPR_INT64
        bool shade = u_pass == 1u;
#else
        bool shade = true;
#endif
        if (shade) {
            // Step 6: shade for this view's eye (the same shading function as mvr).
            vec3 n = (flags & LFDPR_TRIANGLE_FACE_NORMAL) != 0u
                         ? planeNormal
                         : normalize(lfdInterpolateTexValue(vec4(normalMin, 0.0), vec4(normalMax, 0.0), weight).xyz);
            vec3 eye = views[view].eyeScene.xyz;
            if ((flags & LFDPR_TRIANGLE_FACE_NORMAL) != 0u) {
                if (dot(n, eye - point.position) < 0.0)
                    n = -n; // the face normal always faces the viewer (as mvr's derivative normal)
            } else if (!front) {
                n = -n; // double-sided back face
            }
            vec4 orm = lfdInterpolateTexValue(ormMin, ormMax, weight);
            SurfacePbr s;
            s.baseColor = base.rgb;
            s.metallic = clamp(m.params.x * orm.b, 0.0, 1.0);
            s.roughness = clamp(m.params.y * orm.g, 0.0, 1.0);
            s.occlusion = 1.0 + m.params.w * (orm.r - 1.0);
            s.emissive = m.emissiveCutoff.rgb * lfdInterpolateTexValue(emissiveMin, emissiveMax, weight).rgb;
            s.normal = n;
            color = packUnorm4x8(vec4(linearToSrgb(shadePbr(s, point.position, eye)), 1.0));
        }

        // Step 7: fill the covered pixels, depth-tested.
        uint viewBase = view * uint(viewPixels.x * viewPixels.y);
        for (int y = pixelLo.y; y <= pixelHi.y; ++y) {
            for (int x = pixelLo.x; x <= pixelHi.x; ++x) {
                vec2 centre = vec2(x, y) + 0.5;
                if (!lfdInsideQuad(a, b, c, d, centre) || !lfdInsideTriangle(s0, s1, s2, centre))
                    continue;
                vec2 ndc = centre / viewSize * 2.0 - 1.0;
                precise float zNdc = -(planeClip.x * ndc.x + planeClip.y * ndc.y + planeClip.w) / planeClip.z;
                if (zNdc < -1.0 || zNdc > 1.0)
                    continue; // clipped by the near or far plane
                precise float depth = zNdc * 0.5 + 0.5;
                uint depthBits = floatBitsToUint(depth);
                uint pixel = viewBase + uint(y * viewPixels.x + x);
#ifdef LFDPR_INT64
                atomicMin(viewWords[pixel], (uint64_t(depthBits) << 32) | uint64_t(color));
#else
                if (u_pass == 0u)
                    atomicMin(viewDepth[pixel], depthBits);
                else if (viewDepth[pixel] == depthBits)
                    atomicMin(viewColor[pixel], color);
#endif
            }
        }
    }
}
