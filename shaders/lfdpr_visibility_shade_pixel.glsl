// One visible view pixel shaded as mvr shades a fragment (the visibility pipeline):
// the point's triangle in that view (viewTriangle) and its material evaluated at the pixel
// centre with textureGrad at the exact footprint (shadePixel). Shared by the views path
// (lfdpr_visibility_shade.comp) and the direct subpixel splat (lfdpr_direct_shade.comp), so
// both compute the same colour for the same (record, view, pixel). Needs lfdpr_bindings.glsl,
// lfdpr_work_shape.glsl and lfdpr_math.glsl (LFD_PRECISE precise) first.
#include "pbr_shading.glsl"
vec2 g_duvdx, g_duvdy; // this pixel's uv footprint, for LFD_SAMPLE

#ifdef LFDPR_ANISO_TAPS
// Anisotropic filtering (--aniso) in the shader rather than the sampler's
// (LfdprOptions::AnisoFilter::Taps, the default on software rasterisers; compiled in only
// at --aniso above 1): the footprint's major axis is cut into
// n = min(ceil(major / minor), u_frame.maxAnisotropy) pieces, each fetched with textureGrad
// over its own near-isotropic footprint (the piece along the major axis, the minor axis
// across it), and averaged - what hardware anisotropic filters do, independent of a
// driver's textureGrad in compute (llvmpipe's made lfdpr's grazing textures worse, not
// better). Where n is 1 it is the single trilinear textureGrad.
vec4 lfdSampleFootprint(sampler2D t, vec2 uv, vec2 duvdx, vec2 duvdy)
{
    const vec2 size = vec2(textureSize(t, 0));
    const float lx = length(duvdx * size), ly = length(duvdy * size);
    const vec2 major = lx >= ly ? duvdx : duvdy, minor = lx >= ly ? duvdy : duvdx;
    const float ratio = max(lx, ly) / max(min(lx, ly), 1e-6);
    const int n = int(clamp(ceil(min(ratio, u_frame.maxAnisotropy)), 1.0, 16.0));
    if (n == 1)
        return textureGrad(t, uv, duvdx, duvdy);
    const vec2 piece = major / float(n);
    vec4 sum = vec4(0.0);
    for (int i = 0; i < n; ++i)
        sum += textureGrad(t, uv + piece * (float(i) + 0.5 - 0.5 * float(n)), piece, minor);
    return sum / float(n);
}
#define LFD_SAMPLE(t, uv, uvFromTexcoord) lfdSampleFootprint(t, uv, (uvFromTexcoord) * g_duvdx, (uvFromTexcoord) * g_duvdy)
#else
// One textureGrad at the pixel's exact footprint through the textures' own sampler state:
// trilinear at --aniso 1, and above it the texture unit's anisotropic filter
// (LfdprOptions::AnisoFilter::Hardware, a GPU's default), the one mvr's texture() gets,
// fed the analytic gradients (carried through the slot's KHR_texture_transform).
#define LFD_SAMPLE(t, uv, uvFromTexcoord) textureGrad(t, uv, (uvFromTexcoord) * g_duvdx, (uvFromTexcoord) * g_duvdy)
#endif
#include "material_shading.glsl"
#define LFDPR_SCENE_TEXELS
#include "lfdpr_scene_access.glsl"
#include "lfdpr_camera_line.glsl"

#ifndef LFD_STREAMS
#define LFD_STREAMS 0xFu
#endif

layout(binding = LFDPR_UNIT_NORMALS) uniform samplerBuffer t_sceneNormals;
layout(binding = LFDPR_UNIT_TANGENTS) uniform samplerBuffer t_sceneTangents;
layout(binding = LFDPR_UNIT_UVS) uniform samplerBuffer t_sceneUvs;

vec3 objectNormal(uint vertex)
{
    return texelFetch(t_sceneNormals, int(vertex)).xyz;
}

// A visible point's triangle in one view: its draw, vertices, scene positions and window
// positions (projected as lfdpr_visibility_splat.comp projects them).
struct ViewTriangle {
    LfdprVisibilityDrawGpu draw;
    uvec3 vi;
    vec3 p0, p1, p2;
    vec2 s0, s1, s2;
    vec3 invW;
};

// The triangle seen from camera-line offset e (lfdViewOffset: a view's; the direct splat's
// exact-ray mode also takes offsets between views).
ViewTriangle viewTriangleAt(LfdprVisibilityRecordGpu r, LfdprVisibilityDrawGpu draw, float e)
{
    ViewTriangle t;
    t.draw = draw;
    t.vi = lfdTriangleVertices(t.draw, r.primitive);
    lfdTrianglePositions(t.draw, t.vi, t.p0, t.p1, t.p2);
    vec2 viewSize = u_lfd.viewSize.xy;
    LfdLinePoint v0 = lfdProjectOnLine(t.p0, viewSize), v1 = lfdProjectOnLine(t.p1, viewSize);
    LfdLinePoint v2 = lfdProjectOnLine(t.p2, viewSize);
    t.s0 = lfdWindowInView(v0, e);
    t.s1 = lfdWindowInView(v1, e);
    t.s2 = lfdWindowInView(v2, e);
    t.invW = vec3(v0.invW, v1.invW, v2.invW);
    return t;
}

ViewTriangle viewTriangle(LfdprVisibilityRecordGpu r, LfdprVisibilityDrawGpu draw, uint view)
{
    return viewTriangleAt(r, draw, lfdViewOffset(view));
}

// Shades triangle t at the window point whose edge values are `edges`, lit and viewed
// from `eye` (scene space).
vec4 shadePixelFrom(ViewTriangle t, vec3 eye, LfdViewTriangle vt, vec3 edges)
{
    // Step 1: the triangle in this view.
    LfdprVisibilityDrawGpu draw = t.draw;
    uvec3 vi = t.vi;
    vec3 p0 = t.p0, p1 = t.p1, p2 = t.p2;
    vec3 invW = t.invW;

    // Step 2: attributes at the pixel centre (perspective-correct barycentrics: the screen
    // ones, its edge values, weighted by 1 / w as the rasteriser interpolates varyings),
    // and the uv footprint there (lfdPerspectiveDerivative: the exact derivatives, not a
    // one-pixel difference). The edge values (lfdEdgeValues, which the 32-bit check uses
    // too) are affine in the window position: the derivatives of canonical edge k are its
    // run rotated (lfdViewTriangleEdge).
    vec3 w = edges * invW;
    vec3 b = w / (w.x + w.y + w.z);
    NodeGpu node = lfdNode(draw.node);
    LfdSurfacePoint p;
    p.position = b.x * p0 + b.y * p1 + b.z * p2;
    p.vertexNormal = (LFD_STREAMS & LFD_STREAM_NORMAL) != 0u;
    if (p.vertexNormal) {
        mat3 normalFromObject = mat3(node.normalFromObject);
        p.normal = normalFromObject * (b.x * objectNormal(vi.x) + b.y * objectNormal(vi.y) + b.z * objectNormal(vi.z));
    } else {
        vec3 face = cross(p1 - p0, p2 - p0);
        p.normal = dot(face, eye - p.position) < 0.0 ? -face : face;
    }
    bool mirrored = determinant(mat3(node.sceneFromObject)) < 0.0;
    p.frontFacing = (vt.orientation > 0.0) != mirrored; // as the splat decided it
    p.tangent = vec4(0.0, 0.0, 0.0, 1.0);
    if ((LFD_STREAMS & LFD_STREAM_TANGENT) != 0u) {
        vec4 t = b.x * texelFetch(t_sceneTangents, int(vi.x)) + b.y * texelFetch(t_sceneTangents, int(vi.y)) +
                 b.z * texelFetch(t_sceneTangents, int(vi.z));
        p.tangent = vec4(mat3(node.sceneFromObject) * t.xyz, t.w);
    }
    p.uv = vec2(0.0);
    g_duvdx = vec2(0.0);
    g_duvdy = vec2(0.0);
    if ((LFD_STREAMS & LFD_STREAM_UV) != 0u) {
        vec2 uv0 = texelFetch(t_sceneUvs, int(vi.x)).xy, uv1 = texelFetch(t_sceneUvs, int(vi.y)).xy;
        vec2 uv2 = texelFetch(t_sceneUvs, int(vi.z)).xy;
        p.uv = b.x * uv0 + b.y * uv1 + b.z * uv2;
        vec3 ddx = -vec3(vt.edgeRun[0].y, vt.edgeRun[1].y, vt.edgeRun[2].y) * vt.edgeSign;
        vec3 ddy = vec3(vt.edgeRun[0].x, vt.edgeRun[1].x, vt.edgeRun[2].x) * vt.edgeSign;
        g_duvdx = lfdPerspectiveDerivative(edges, ddx, invW, uv0, uv1, uv2);
        g_duvdy = lfdPerspectiveDerivative(edges, ddy, invW, uv0, uv1, uv2);
    }

    // Step 3: the material, as mvr shades it (alpha-masked cells were dropped when the
    // points were generated, so a discard here keeps the colour of the cell's centre).
    vec3 color;
    lfdShadeMaterial(lfdMaterial(draw.material), LFD_STREAMS, p, eye, color);
    return vec4(color, 1.0);
}

// Shades view pixel (edges) of `view` (lfdpr_visibility_shade.comp's and the direct splat's
// nearest mode's colour).
vec4 shadePixel(ViewTriangle t, uint view, LfdViewTriangle vt, vec3 edges)
{
    return shadePixelFrom(t, views[view].eyeScene.xyz, vt, edges);
}
