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

// The corners of the point's splat: its cell in the triangle plane, enlarged by
// LFDPR_SPLAT_OVERLAP so neighbouring splats leave no cracks.
void splatCorners(vec3 position, LfdprPaperTriangleGpu r, out vec3 c00, out vec3 c10, out vec3 c11, out vec3 c01)
{
    vec3 halfU = r.axisU.xyz * (0.5 * r.axisU.w * LFDPR_SPLAT_OVERLAP);
    vec3 halfV = r.axisV.xyz * (0.5 * r.axisV.w * LFDPR_SPLAT_OVERLAP);
    c00 = position - halfU - halfV;
    c10 = position + halfU - halfV;
    c11 = position + halfU + halfV;
    c01 = position - halfU + halfV;
}

// The pixels of the projected splat's bounding box, clipped to the projected triangle's
// box and the view; false when none is left.
bool pixelBox(vec2 a, vec2 b, vec2 c, vec2 d, vec2 s0, vec2 s1, vec2 s2, ivec2 viewPixels, out ivec2 pixelLo,
              out ivec2 pixelHi)
{
    vec2 lo = max(min(min(a, b), min(c, d)), min(min(s0, s1), s2));
    vec2 hi = min(max(max(a, b), max(c, d)), max(max(s0, s1), s2));
    pixelLo = max(ivec2(ceil(lo - 0.5)), ivec2(0));
    pixelHi = min(ivec2(floor(hi - 0.5)), viewPixels - 1);
    return !any(greaterThan(pixelLo, pixelHi));
}

// Whether the projected triangle s0, s1, s2 is drawn, and which side faces the view
// (`front`), as the rasteriser decides it: not when degenerate, nor a single-sided back face.
bool drawnFacing(vec2 s0, vec2 s1, vec2 s2, bool mirrored, bool doubleSided, out bool front)
{
    float area = lfdCanonicalEdge(s0, s1, s2);
    front = (area > 0.0) != mirrored;
    return area != 0.0 && (front || doubleSided);
}

// The 32-bit path shades in its second pass only (the first finds each pixel's depth).
bool shadesThisPass()
{
#ifndef LFDPR_INT64
    return u_pass == 1u;
#else
    return true;
#endif
}

bool allInFront(mat4 clipFromScene, vec3 p0, vec3 p1, vec3 p2, vec3 c00, vec3 c10, vec3 c11, vec3 c01)
{
    return inFront(clipFromScene, p0) && inFront(clipFromScene, p1) && inFront(clipFromScene, p2) &&
           inFront(clipFromScene, c00) && inFront(clipFromScene, c10) && inFront(clipFromScene, c11) &&
           inFront(clipFromScene, c01);
}

// The weight between the point's LOD_min and LOD_max texture values in this view (eqs.
// interpolationParameter, interplateTexValue), from the projected splat quad a, b, c, d.
float viewMipWeight(vec2 a, vec2 b, vec2 c, vec2 d, float splatUvArea, vec2 viewSize, vec2 mip)
{
    const float cellAreaFraction = 1.0 / (LFDPR_SPLAT_OVERLAP * LFDPR_SPLAT_OVERLAP);
    vec2 ad = d - a, ab = b - a, cb = b - c, cd = d - c;
    float quadPixels = 0.5 * (abs(lfdCross2(ab, ad)) + abs(lfdCross2(cb, cd)));
    float splatNdcArea = quadPixels * cellAreaFraction * 4.0 / (viewSize.x * viewSize.y);
    float sizeVse = lfdSplatTextureArea(splatUvArea, splatNdcArea, viewSize);
    return lfdMipInterpolation(sizeVse, mip.x, mip.y);
}

// The shading normal in one view: the face normal turned to the viewer (as mvr's
// derivative normal), or the point's two normals interpolated, flipped on a double-sided
// back face.
vec3 splatNormal(uint flags, vec3 planeNormal, vec3 normalMin, vec3 normalMax, float weight, vec3 toEye, bool front)
{
    if ((flags & LFDPR_TRIANGLE_FACE_NORMAL) != 0u)
        return dot(planeNormal, toEye) < 0.0 ? -planeNormal : planeNormal;
    vec3 n = normalize(lfdInterpolateTexValue(vec4(normalMin, 0.0), vec4(normalMax, 0.0), weight).xyz);
    return front ? n : -n;
}

// The view's pixel centres inside both the splat quad (a, b, c, d) and the projected
// triangle (s0, s1, s2), within pixelLo..pixelHi, depth-tested at the triangle plane's
// depth along each pixel's own ray.
void fillSplat(uint view, ivec2 viewPixels, vec2 viewSize, ivec2 pixelLo, ivec2 pixelHi, vec2 a, vec2 b, vec2 c,
               vec2 d, vec2 s0, vec2 s1, vec2 s2, vec4 planeClip, uint color)
{
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

// One splat's colour word for one view: glTF PBR as mvr shades it (an unlit material: its
// base colour), sRGB-encoded.
uint shadeSplat(MaterialGpu m, vec4 base, vec4 orm, vec3 emissive, vec3 n, vec3 position, vec3 eye)
{
    if ((m.flags & LFD_MATERIAL_UNLIT) != 0u)
        return packUnorm4x8(vec4(linearToSrgb(base.rgb), 1.0));
    SurfacePbr s;
    s.baseColor = base.rgb;
    s.metallic = clamp(m.params.x * orm.b, 0.0, 1.0);
    s.roughness = clamp(m.params.y * orm.g, 0.0, 1.0);
    s.occlusion = 1.0 + m.params.w * (orm.r - 1.0);
    s.emissive = m.emissiveCutoff.rgb * emissive;
    s.normal = n;
    return packUnorm4x8(vec4(lfdDisplayEncode(shadePbr(s, position, eye)), 1.0));
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
    vec3 planeNormal = cross(r.axisU.xyz, r.axisV.xyz);
    vec4 planeScene = vec4(planeNormal, -dot(planeNormal, p0));
    vec3 c00, c10, c11, c01;
    splatCorners(point.position, r, c00, c10, c11, c01);
    // The splat's texture area (the unenlarged cell) for eq. interpolationParameter.
    float splatUvArea = r.axisU.w * r.axisV.w * r.p1.w;

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
        if (!allInFront(clipFromScene, p0, p1, p2, c00, c10, c11, c01))
            continue;

        // Step 2: the projected triangle; facing as the rasteriser decides it.
        vec2 s0 = toWindow(clipFromScene, p0, viewSize);
        vec2 s1 = toWindow(clipFromScene, p1, viewSize);
        vec2 s2 = toWindow(clipFromScene, p2, viewSize);
        bool front;
        if (!drawnFacing(s0, s1, s2, mirrored, doubleSided, front))
            continue;

        // Step 3: the projected splat and the pixels of its bounding box (clipped to the
        // triangle's box and the view).
        vec2 a = toWindow(clipFromScene, c00, viewSize), b = toWindow(clipFromScene, c10, viewSize);
        vec2 c = toWindow(clipFromScene, c11, viewSize), d = toWindow(clipFromScene, c01, viewSize);
        ivec2 pixelLo, pixelHi;
        if (!pixelBox(a, b, c, d, s0, s1, s2, viewPixels, pixelLo, pixelHi))
            continue;

        // Step 4: per-view texture values (eqs. interpolationParameter, interplateTexValue).
        float weight = viewMipWeight(a, b, c, d, splatUvArea, viewSize, r.mip.xy);
        vec4 base = m.baseColorFactor * lfdInterpolateTexValue(baseMin, baseMax, weight);
        if (m.alphaMode == LFD_ALPHA_MASK && base.a < m.emissiveCutoff.w)
            continue;

        // Step 5: depth plane in clip space (z_ndc = -(A x + B y + D) / C), so each pixel
        // gets the depth of the triangle plane along its own ray.
        vec4 planeClip = planeScene * sceneFromClip[view]; // = transpose(sceneFromClip) * plane
        if (planeClip.z == 0.0)
            continue;

        uint color = 0u;
        if (shadesThisPass()) {
            // Step 6: shade for this view's eye (the same shading function as mvr).
            vec3 eye = views[view].eyeScene.xyz;
            vec3 n = splatNormal(flags, planeNormal, normalMin, normalMax, weight, eye - point.position, front);
            vec4 orm = lfdInterpolateTexValue(ormMin, ormMax, weight);
            vec3 emissive = lfdInterpolateTexValue(emissiveMin, emissiveMax, weight).rgb;
            color = shadeSplat(m, base, orm, emissive, n, point.position, eye);
        }

        // Step 7: fill the covered pixels, depth-tested.
        fillSplat(view, viewPixels, viewSize, pixelLo, pixelHi, a, b, c, d, s0, s1, s2, planeClip, color);
    }
}
