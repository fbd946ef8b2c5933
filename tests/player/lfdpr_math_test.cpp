// LFDPR formulas (shaders/lfdpr_math.glsl compiled as C++ through player/render/lfdpr/lfdpr_math.h, so
// these test the code the shaders run): pixel-edge reverse projection, T_align / S_ortho,
// the sampling-spacing property, eq. lfd_texelSplatDensity, size_vpuv, LOD, the tv
// interpolation with its division guard, coverage rules, and the union-frustum planes.
// CPU only.
#include "lfdpr_math.h"
#include "lfdpr_paper_point_generation.h"

#include "lfd/display_profile.h"
#include "lfd/framing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace lfd::test {
namespace {

using namespace player::lfdpr_math;

// Display-like geometry in millimetres: screen plane z = 0, cameras on the line y = 0,
// z = D (the prototype's 0.72 x 0.54 mm view pixels).
constexpr float kD = 600.0f;
const vec3 kX(1, 0, 0), kY(0, 1, 0), kZ(0, 0, 1);
const vec3 kScreen(0, 0, 0);
constexpr float kPixelW = 0.72f, kPixelH = 0.54f;

// Ray from eye through screen point s, intersected with the plane (p, n).
vec3 rayPlane(vec3 eye, vec3 s, vec3 p, vec3 n)
{
    const vec3 d = s - eye;
    return eye + d * (glm::dot(n, p - eye) / glm::dot(n, d));
}

// The screen point on the ray from eye through p.
vec3 toScreen(vec3 eye, vec3 p) { return eye + (p - eye) * (eye.z / (eye.z - p.z)); }

TEST(LfdprMath, ReverseProjectionOfFrontalPlanesScalesWithDistance)
{
    // A plane on the screen: a pixel edge is itself (t = 1). Twice as far from the eye
    // (z = -D): twice as long (t = 2). In front, halfway to the eye: half (t = 0.5).
    const vec3 eye(30, 0, kD);
    const vec3 edge(kPixelW, 0, 0);
    EXPECT_NEAR(glm::length(lfdReverseProjectEdge(vec3(10, 5, 0), kZ, eye, kScreen, kZ, edge)), 0.72f, 1e-6f);
    EXPECT_NEAR(glm::length(lfdReverseProjectEdge(vec3(10, 5, -kD), kZ, eye, kScreen, kZ, edge)), 1.44f, 1e-5f);
    EXPECT_NEAR(glm::length(lfdReverseProjectEdge(vec3(10, 5, kD / 2), kZ, eye, kScreen, kZ, edge)), 0.36f, 1e-6f);
}

TEST(LfdprMath, ReverseProjectionMatchesRayCasting)
{
    // Tilted planes, eyes along the line: the returned edge equals the difference of the
    // two ray hits through the pixel edge's ends (first order: within 0.3%).
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    for (int i = 0; i < 200; ++i) {
        const vec3 eye(200.0f * u(rng), 0.0f, kD);
        const vec3 p(80.0f * u(rng), 60.0f * u(rng), 80.0f * u(rng));
        vec3 n = glm::normalize(vec3(u(rng), u(rng), 1.5f + u(rng)));
        const vec3 s = toScreen(eye, p);
        for (const vec3& edge : {vec3(kPixelW, 0, 0), vec3(0, kPixelH, 0)}) {
            const vec3 expected = rayPlane(eye, s + edge, p, n) - rayPlane(eye, s, p, n);
            const vec3 got = lfdReverseProjectEdge(p, n, eye, kScreen, kZ, edge);
            // First order: relative error ~ (pixel / distance) / cos(incidence).
            const float cosIncidence = std::abs(glm::dot(n, glm::normalize(p - eye)));
            EXPECT_LT(glm::length(got - expected), 2e-3f / cosIncidence * glm::length(expected)) << i;
            EXPECT_NEAR(glm::dot(got, n), 0.0f, 1e-4f) << "in the plane";
        }
    }
}

TEST(LfdprMath, ReverseProjectionAtGrazingIsUnbounded)
{
    const vec3 eye(0, 0, kD);
    const vec3 p(0, 0, 0);
    const vec3 n = glm::normalize(p - eye); // plane contains nothing but... n . (p - eye) != 0
    EXPECT_LT(glm::length(lfdReverseProjectEdge(p, n, eye, kScreen, kZ, vec3(kPixelW, 0, 0))), 1.0f);
    const vec3 edgeOn(1, 0, 0); // the ray lies in the plane x = 0
    EXPECT_GE(glm::length(lfdReverseProjectEdge(p, edgeOn, eye, kScreen, kZ, vec3(kPixelW, 0, 0))), 1e29f);
}

TEST(LfdprMath, AlignFrameIsOrthonormalInPlaneAndHorizontal)
{
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    for (int i = 0; i < 500; ++i) {
        const vec3 n = glm::normalize(vec3(u(rng), u(rng), u(rng)));
        const LfdFrame f = lfdAlignFrame(n, kX, kY, kZ);
        EXPECT_NEAR(glm::length(f.u), 1.0f, 1e-5f);
        EXPECT_NEAR(glm::length(f.v), 1.0f, 1e-5f);
        EXPECT_NEAR(glm::dot(f.u, f.v), 0.0f, 1e-5f);
        EXPECT_NEAR(glm::dot(f.u, n), 0.0f, 1e-5f) << "u in the plane";
        EXPECT_NEAR(glm::dot(f.v, n), 0.0f, 1e-5f) << "v in the plane";
        EXPECT_NEAR(std::abs(glm::dot(f.n, n)), 1.0f, 1e-5f);
        EXPECT_GE(glm::dot(f.v, kY), -1e-6f) << "v points up";
        // u is parallel to display x projected onto the plane (when that is defined).
        const vec3 h = kX - n * glm::dot(n, kX);
        if (glm::length(h) > 1e-2f) {
            EXPECT_GT(glm::dot(f.u, glm::normalize(h)), 1.0f - 1e-5f);
        }
        // Rebuilt from its recorded choices, the frame is the same, bit for bit; the choices
        // survive the record's spacing signs.
        const LfdFrame rebuilt = lfdAlignFrameWith(n, kX, kZ, f.choices);
        EXPECT_EQ(rebuilt.u, f.u);
        EXPECT_EQ(rebuilt.v, f.v);
        EXPECT_EQ(f.choices, lfdAlignFrameChoices(n, kX, kY, kZ));
        EXPECT_EQ(f.choices, lfdSpacingChoices(lfdSignedSpacing(vec2(0.5f, 2.0f), f.choices)));
        EXPECT_EQ(glm::abs(lfdSignedSpacing(vec2(0.5f, 2.0f), f.choices)), vec2(0.5f, 2.0f));
    }
    // Hand-worked: a wall facing the viewer (n = z): u = x, v = y. A floor (n = y): u = x,
    // v = -z or +z signed up... v . y = 0 there, so v = n x u = y x x = -z.
    LfdFrame wall = lfdAlignFrame(kZ, kX, kY, kZ);
    EXPECT_NEAR(wall.u.x, 1.0f, 1e-6f);
    EXPECT_NEAR(wall.v.y, 1.0f, 1e-6f);
    LfdFrame floor = lfdAlignFrame(kY, kX, kY, kZ);
    EXPECT_NEAR(floor.u.x, 1.0f, 1e-6f);
    EXPECT_NEAR(floor.v.z, -1.0f, 1e-6f);
    // A side wall (n = x): display x projects to nothing; the depth axis stands in.
    LfdFrame side = lfdAlignFrame(kX, kX, kY, kZ);
    EXPECT_NEAR(std::abs(side.u.z), 1.0f, 1e-6f);
    EXPECT_NEAR(side.v.y, 1.0f, 1e-6f);
    // Nearly a side wall: still finite and orthonormal.
    LfdFrame nearly = lfdAlignFrame(glm::normalize(vec3(1.0f, 0.0f, 1e-4f)), kX, kY, kZ);
    EXPECT_NEAR(glm::length(nearly.u), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(nearly.u, nearly.v), 0.0f, 1e-5f);
}

TEST(LfdprMath, AlignFrameChoicesRebuildTheSameFrame)
{
    // (Random normals: AlignFrameIsOrthonormalInPlaneAndHorizontal rebuilds each frame from
    // its choices.) Hand-worked: a floor (n = y) keeps v = y x x = -z (no choice), its
    // underside (n = -y) gets v = -y x x = +z (no choice either); a side wall (n = x) takes u
    // from the depth axis.
    EXPECT_EQ(lfdAlignFrame(kY, kX, kY, kZ).choices, 0);
    EXPECT_EQ(lfdAlignFrame(-kY, kX, kY, kZ).choices, 0);
    EXPECT_EQ(lfdAlignFrame(kX, kX, kY, kZ).choices & 1, 1);
    // Where the sign test sits on its edge (a floor tilted by 1e-7 rad, within rounding), two
    // normals that differ by rounding may choose apart; rebuilt with one of them's choices,
    // the other's frame keeps the same v.
    const vec3 up = glm::normalize(vec3(0.0f, 1.0f, 1e-7f)), down = glm::normalize(vec3(0.0f, 1.0f, -1e-7f));
    const int chosen = lfdAlignFrameChoices(up, kX, kY, kZ);
    EXPECT_NE(chosen, lfdAlignFrameChoices(down, kX, kY, kZ)) << "the two normals decide apart";
    EXPECT_GT(glm::dot(lfdAlignFrameWith(up, kX, kZ, chosen).v, lfdAlignFrameWith(down, kX, kZ, chosen).v),
              0.99f);
}

TEST(LfdprMath, ClosestPointToTheViewingLine)
{
    // The viewing line is y = 0, z = D (direction x).
    const vec3 line(0, 0, kD);
    // A triangle pierced by the line: distance 0.
    {
        const vec3 a(-10, -10, kD), b(10, -10, kD), c(0, 10, kD);
        const vec3 w = lfdClosestBarycentricToLine(a, b, c, line, kY, kZ);
        const vec3 p = w.x * a + w.y * b + w.z * c;
        EXPECT_NEAR(p.y, 0.0f, 1e-4f);
        EXPECT_NEAR(p.z, kD, 1e-3f);
    }
    // A triangle facing the viewer at z = 0, below the line: its top vertex is closest.
    {
        const vec3 a(-10, -40, 0), b(10, -40, 0), c(3, -20, 0);
        const vec3 w = lfdClosestBarycentricToLine(a, b, c, line, kY, kZ);
        EXPECT_NEAR(w.z, 1.0f, 1e-6f);
    }
    // A triangle whose plane contains the line direction (projects to a segment in yz):
    // the closest point is on the segment's near end, no NaN.
    {
        const vec3 a(-10, 5, 0), b(10, 5, 0), c(0, 5, -30);
        const vec3 w = lfdClosestBarycentricToLine(a, b, c, line, kY, kZ);
        const vec3 p = w.x * a + w.y * b + w.z * c;
        EXPECT_FALSE(std::isnan(p.x));
        EXPECT_NEAR(p.z, 0.0f, 1e-4f);
        EXPECT_NEAR(w.x + w.y + w.z, 1.0f, 1e-6f);
    }
}

TEST(LfdprMath, SamplingSpacingIsBiasedOrIsotropic)
{
    const vec2 biased = lfdSamplingSpacing(0.72f, 0.54f, true);
    EXPECT_FLOAT_EQ(biased.x, 0.72f);
    EXPECT_FLOAT_EQ(biased.y, 0.54f);
    const vec2 iso = lfdSamplingSpacing(0.72f, 0.54f, false);
    EXPECT_FLOAT_EQ(iso.x, 0.54f);
    EXPECT_FLOAT_EQ(iso.y, 0.54f);
}

TEST(LfdprMath, TexelSplatDensity)
{
    // Eq. lfd_texelSplatDensity: texels 4x the pixel area -> half the density per axis.
    EXPECT_FLOAT_EQ(lfdTexelSplatDensityScale(1.0f, 4.0f), 0.5f);
    EXPECT_FLOAT_EQ(lfdTexelSplatDensityScale(0.25f, 100.0f), 0.05f);
    // Texels finer than pixels (or no texture: size_uv = 0): unchanged.
    EXPECT_FLOAT_EQ(lfdTexelSplatDensityScale(1.0f, 0.5f), 1.0f);
    EXPECT_FLOAT_EQ(lfdTexelSplatDensityScale(1.0f, 1.0f), 1.0f);
    EXPECT_FLOAT_EQ(lfdTexelSplatDensityScale(1.0f, 0.0f), 1.0f);
    EXPECT_FLOAT_EQ(lfdTexelSplatDensityScale(0.0f, 1.0f), 1.0f);
}

TEST(LfdprMath, VpuvSizeAndLod)
{
    // A 256 x 256 texture over a 1 x 1 (world) quad: A_ts / A_ws = 1. A pixel of
    // 1/256 x 1/256 world units covers one texel: LOD 0; 2 x 2 texels: LOD 1.
    const float texels = 256.0f * 256.0f;
    const float oneTexel = lfdVpuvSize(1.0f / texels, 1.0f);
    EXPECT_FLOAT_EQ(oneTexel, 1.0f / texels);
    EXPECT_NEAR(lfdLod(oneTexel, texels), 0.0f, 1e-6f);
    EXPECT_NEAR(lfdLod(lfdVpuvSize(4.0f / texels, 1.0f), texels), 1.0f, 1e-6f);
    EXPECT_NEAR(lfdLod(lfdVpuvSize(64.0f / texels, 1.0f), texels), 3.0f, 1e-6f);
    // Magnification: negative (the sampler clamps to the base level).
    EXPECT_NEAR(lfdLod(0.25f / texels, texels), -1.0f, 1e-6f);
    // Texture area per world area scales it: half the uv range per world unit (A_ts / A_ws
    // = 0.25) -> a quarter of the texels per pixel -> one level finer.
    EXPECT_NEAR(lfdLod(lfdVpuvSize(4.0f / texels, 0.25f), texels), 0.0f, 1e-6f);
    // Untextured (0): finite, LOD 0.
    EXPECT_EQ(lfdLod(0.0f, texels), 0.0f);
    EXPECT_EQ(lfdLod(1.0f, 0.0f), 0.0f);
}

TEST(LfdprMath, TexValueInterpolation)
{
    const float lo = 1e-4f, hi = 5e-4f;
    // A splat covering a quarter of a pixel: its texture area grows 4x (eq.
    // interpolationParameter); one covering 4 pixels is never decreased.
    const vec2 view(480, 360);
    const float pixelNdc = 4.0f / (480.0f * 360.0f);
    EXPECT_NEAR(lfdSplatTextureArea(5e-5f, 0.25f * pixelNdc, view), 2e-4f, 1e-9f);
    EXPECT_NEAR(lfdSplatTextureArea(5e-5f, 4.0f * pixelNdc, view), 5e-5f, 1e-10f);
    // Weight: clamp to [lo, hi], map to [0, 1].
    EXPECT_NEAR(lfdMipInterpolation(2e-4f, lo, hi), 0.25f, 1e-5f);
    EXPECT_EQ(lfdMipInterpolation(5e-5f, lo, hi), 0.0f);
    EXPECT_EQ(lfdMipInterpolation(1.0f, lo, hi), 1.0f);
    // Guard: equal bounds give weight 0 (tv = tv_min), no NaN.
    EXPECT_EQ(lfdMipInterpolation(2e-4f, lo, lo), 0.0f);
    EXPECT_EQ(lfdMipInterpolation(0.0f, 0.0f, 0.0f), 0.0f);
    // Eq. interplateTexValue.
    const vec4 tv = lfdInterpolateTexValue(vec4(0.2f, 0.4f, 0.6f, 1.0f), vec4(0.6f, 0.4f, 0.2f, 1.0f), 0.25f);
    EXPECT_NEAR(tv.x, 0.3f, 1e-6f);
    EXPECT_NEAR(tv.y, 0.4f, 1e-6f);
    EXPECT_NEAR(tv.z, 0.5f, 1e-6f);
    EXPECT_NEAR(tv.w, 1.0f, 1e-6f);
}

// The GS's spacing choice over views (same loop as lfdpr_paper_points.geom, step 3).
vec2 finestEdges(vec3 p, vec3 n, const std::vector<vec3>& eyes)
{
    float h = 1e30f, v = 1e30f;
    for (const vec3& eye : eyes) {
        h = std::min(h, glm::length(lfdReverseProjectEdge(p, n, eye, kScreen, kZ, kX * kPixelW)));
        v = std::min(v, glm::length(lfdReverseProjectEdge(p, n, eye, kScreen, kZ, kY * kPixelH)));
    }
    return vec2(h, v);
}

TEST(LfdprMath, PointSpacingMatchesReverseProjectedPixels)
{
    // The property T_align and S_ortho must have: neighbouring sampling pixels, mapped
    // back to the triangle, are one reverse-projected view pixel apart in each axis - and
    // in the view that samples the triangle most finely they land one view pixel apart.
    std::vector<vec3> eyes;
    for (int i = 0; i < 8; ++i)
        eyes.push_back(vec3(kD * std::tan(0.35f * ((i + 0.5f) / 8.0f - 0.5f)), 0.0f, kD));
    struct Case {
        vec3 a, b, c;
    };
    const Case cases[] = {
        {{-40, -30, -50}, {40, -30, -50}, {0, 30, -50}},     // frontal, behind the screen
        {{-40, -30, 20}, {40, -20, -30}, {10, 40, 0}},       // tilted
        {{-40, -50, 60}, {40, -50, 60}, {0, -50, -60}},      // floor
    };
    for (const Case& t : cases) {
        const vec3 n = glm::normalize(glm::cross(t.b - t.a, t.c - t.a));
        const vec3 w = lfdClosestBarycentricToLine(t.a, t.b, t.c, vec3(0, 0, kD), kY, kZ);
        const vec3 p = w.x * t.a + w.y * t.b + w.z * t.c;
        const vec2 edges = finestEdges(p, n, eyes);
        const vec2 spacing = lfdSamplingSpacing(edges.x, edges.y, true);
        const LfdFrame f = lfdAlignFrame(n, kX, kY, kZ);
        const vec2 q = lfdSamplingFromScene(p, t.a, f, spacing);
        const vec3 p00 = lfdSceneFromSampling(q, t.a, f, spacing);
        const vec3 p10 = lfdSceneFromSampling(q + vec2(1, 0), t.a, f, spacing);
        const vec3 p01 = lfdSceneFromSampling(q + vec2(0, 1), t.a, f, spacing);
        EXPECT_LT(glm::length(p00 - p), 1e-3f) << "round trip";
        EXPECT_NEAR(glm::length(p10 - p00), edges.x, 1e-3f * edges.x) << "horizontal spacing";
        EXPECT_NEAR(glm::length(p01 - p00), edges.y, 1e-3f * edges.y) << "vertical spacing";
        EXPECT_NEAR(glm::dot(p10 - p00, n), 0.0f, 1e-4f);
        EXPECT_NEAR(glm::dot(p01 - p00, n), 0.0f, 1e-4f);
        // Frontal case: in every view a horizontal step is at most one pixel wide, and in
        // the finest one exactly one (0.5% for the first-order footprint).
        if (std::abs(n.z) > 0.999f) {
            float widest = 0.0f;
            for (const vec3& eye : eyes) {
                const float px = glm::length(toScreen(eye, p10) - toScreen(eye, p00)) / kPixelW;
                const float py = glm::length(toScreen(eye, p01) - toScreen(eye, p00)) / kPixelH;
                EXPECT_LE(px, 1.005f);
                EXPECT_LE(py, 1.005f);
                widest = std::max(widest, px);
            }
            EXPECT_NEAR(widest, 1.0f, 5e-3f);
        }
    }
}

TEST(LfdprMath, InsideTriangleTieRuleCoversSharedEdgesOnce)
{
    // Two triangles sharing the diagonal of a square, sampled on a grid that puts samples
    // exactly on the diagonal and on the outer edges: every sample strictly inside the
    // square belongs to exactly one triangle, for both windings of the second triangle.
    const vec2 a(0, 0), b(8, 0), c(8, 8), d(0, 8);
    for (bool flipSecond : {false, true}) {
        int doubles = 0, holes = 0;
        for (int y = 1; y < 16; ++y)
            for (int x = 1; x < 16; ++x) {
                const vec2 p(0.5f * float(x), 0.5f * float(y));
                const bool first = lfdInsideTriangle(a, b, c, p);
                const bool second = flipSecond ? lfdInsideTriangle(a, d, c, p) : lfdInsideTriangle(a, c, d, p);
                doubles += first && second;
                holes += !first && !second;
            }
        EXPECT_EQ(doubles, 0) << flipSecond;
        EXPECT_EQ(holes, 0) << flipSecond;
    }
    // Zero-area triangles own nothing.
    EXPECT_FALSE(lfdInsideTriangle(vec2(0, 0), vec2(1, 1), vec2(2, 2), vec2(1, 1)));
}

TEST(LfdprMath, ConservativePixelOverlap)
{
    // A triangle far smaller than a pixel overlaps the pixel containing it, not others.
    const vec2 a(3.40f, 5.40f), b(3.45f, 5.40f), c(3.42f, 5.46f);
    EXPECT_TRUE(lfdPixelOverlapsTriangle(vec2(3.5f, 5.5f), a, b, c));
    EXPECT_FALSE(lfdPixelOverlapsTriangle(vec2(2.5f, 5.5f), a, b, c));
    EXPECT_FALSE(lfdPixelOverlapsTriangle(vec2(3.5f, 6.5f), a, b, c));
    // A thin diagonal sliver that contains no pixel centre still overlaps the pixels it
    // passes through, and not those beside it.
    const vec2 s0(0.2f, 0.1f), s1(9.8f, 9.9f), s2(9.85f, 9.9f);
    for (int i = 0; i < 10; ++i)
        EXPECT_TRUE(lfdPixelOverlapsTriangle(vec2(i + 0.5f, i + 0.5f), s0, s1, s2)) << i;
    EXPECT_FALSE(lfdPixelOverlapsTriangle(vec2(7.5f, 2.5f), s0, s1, s2));
    // Degenerate (a segment): the pixels along it.
    EXPECT_TRUE(lfdPixelOverlapsTriangle(vec2(4.5f, 0.5f), vec2(0.2f, 0.5f), vec2(9.0f, 0.5f), vec2(5.0f, 0.5f)));
    EXPECT_FALSE(lfdPixelOverlapsTriangle(vec2(4.5f, 1.5f), vec2(0.2f, 0.5f), vec2(9.0f, 0.5f), vec2(5.0f, 0.5f)));
}

TEST(LfdprMath, QuadSlackWidensEveryEdgeByAtLeastItsPixels)
{
    // Square (1, 1)-(3, 3), counter-clockwise: each edge is 2 long on one axis, so its L1
    // length is 2 and its edge function grows by 2 per pixel of distance; a slack of 0.25 px
    // is 0.5 in edge-function units.
    const vec2 a(1, 1), b(3, 1), c(3, 3), d(1, 3);
    const vec4 slack = lfdQuadEdgeSlack(a, b, c, d, 0.25f);
    EXPECT_EQ(slack, vec4(0.5f));
    EXPECT_TRUE(lfdInsideQuadWithSlack(a, b, c, d, slack, vec2(2.0f, 2.0f)));
    EXPECT_TRUE(lfdInsideQuadWithSlack(a, b, c, d, slack, vec2(0.8f, 2.0f)));  // 0.2 px outside
    EXPECT_FALSE(lfdInsideQuadWithSlack(a, b, c, d, slack, vec2(0.7f, 2.0f))); // 0.3 px outside
    EXPECT_FALSE(lfdInsideQuad(a, b, c, d, vec2(0.8f, 2.0f)));
    // Either winding.
    EXPECT_TRUE(lfdInsideQuadWithSlack(d, c, b, a, slack, vec2(3.2f, 2.0f)));
    // A diagonal edge's L1 length exceeds its length (by up to sqrt(2)): a point 0.25 px
    // outside it in Euclidean distance passes, one 0.36 px outside does not.
    const vec2 p(0, 0), q(2, 2), r(0, 4), s(-2, 2);
    const vec4 diagonal = lfdQuadEdgeSlack(p, q, r, s, 0.25f);
    EXPECT_EQ(diagonal, vec4(1.0f));
    const vec2 outward = glm::normalize(vec2(1, -1)); // outside edge p-q
    EXPECT_TRUE(lfdInsideQuadWithSlack(p, q, r, s, diagonal, vec2(1, 1) + 0.25f * outward));
    EXPECT_TRUE(lfdInsideQuadWithSlack(p, q, r, s, diagonal, vec2(1, 1) + 0.35f * outward));
    EXPECT_FALSE(lfdInsideQuadWithSlack(p, q, r, s, diagonal, vec2(1, 1) + 0.36f * outward));
    // A quad of zero width (a cell clipped to the edge of its triangle's box) holds the
    // points within the slack of its segment.
    const vec2 e(5, 1), f(5, 3);
    const vec4 thin = lfdQuadEdgeSlack(e, e, f, f, 0.25f);
    EXPECT_TRUE(lfdInsideQuadWithSlack(e, e, f, f, thin, vec2(5.2f, 2.0f)));
    EXPECT_FALSE(lfdInsideQuadWithSlack(e, e, f, f, thin, vec2(5.3f, 2.0f)));
}

TEST(LfdprMath, ClampedBarycentricsStayOnTheTriangle)
{
    const vec2 a(0, 0), b(4, 0), c(0, 4);
    const vec3 inside = lfdClampedBarycentric(a, b, c, vec2(1, 1));
    EXPECT_NEAR(inside.x, 0.5f, 1e-6f);
    EXPECT_NEAR(inside.y, 0.25f, 1e-6f);
    const vec3 outside = lfdClampedBarycentric(a, b, c, vec2(-1, 2));
    EXPECT_GE(std::min(std::min(outside.x, outside.y), outside.z), 0.0f);
    EXPECT_NEAR(outside.x + outside.y + outside.z, 1.0f, 1e-6f);
    const vec2 q = outside.x * a + outside.y * b + outside.z * c;
    EXPECT_NEAR(q.x, 0.0f, 1e-6f);
    EXPECT_NEAR(q.y, 2.0f, 1e-6f);
}

// The shading's texture footprint: exact derivatives of a perspective-correct attribute.
TEST(LfdprMath, PerspectiveDerivativeIsTheExactFootprint)
{
    // Affine (equal 1 / w), by hand: screen barycentrics (1, 1, 2) / 4 give a = (1, 4);
    // moving along the axis shifts weight from vertex 1 to vertex 0, so
    // d a.x = (1 (0 - 1) - 1 (4 - 1)) / 4 = -1 and d a.y = (1 (0 - 4) - 1 (0 - 4)) / 4 = 0.
    const vec2 d = lfdPerspectiveDerivative(vec3(1, 1, 2), vec3(1, -1, 0), vec3(1, 1, 1), vec2(0, 0),
                                            vec2(4, 0), vec2(0, 8));
    EXPECT_NEAR(d.x, -1.0f, 1e-6f);
    EXPECT_NEAR(d.y, 0.0f, 1e-6f);

    // A floor receding up the window: near edge s0 s1 (1 / w = 1, v = 0), far apex s2
    // (1 / w = 0.25, v = 1). Up the centre line x = 5 the screen weight of s2 is t = y / 10
    // and v = 0.25 t / (1 - 0.75 t), so dv/dy = 0.025 / (1 - 0.75 t)^2 = 0.064 at y = 5.
    const vec2 s0(0, 0), s1(10, 0), s2(5, 10);
    const vec3 invW(1.0f, 1.0f, 0.25f);
    const vec2 uv0(0, 0), uv1(1, 0), uv2(0.5f, 1);
    const auto edgesAt = [&](vec2 p) { return vec3(lfdEdge(s1, s2, p), lfdEdge(s2, s0, p), lfdEdge(s0, s1, p)); };
    const auto uvAt = [&](vec2 p) {
        const vec3 w = edgesAt(p) * invW;
        return (w.x * uv0 + w.y * uv1 + w.z * uv2) / (w.x + w.y + w.z);
    };
    // Edge (a, b)'s value changes by -(b.y - a.y) per pixel in x and (b.x - a.x) in y.
    const vec3 dx(-(s2.y - s1.y), -(s0.y - s2.y), -(s1.y - s0.y));
    const vec3 dy(s2.x - s1.x, s0.x - s2.x, s1.x - s0.x);
    const vec2 p(5, 5);
    const vec2 duvdy = lfdPerspectiveDerivative(edgesAt(p), dy, invW, uv0, uv1, uv2);
    EXPECT_NEAR(duvdy.y, 0.064f, 1e-6f);
    EXPECT_NEAR(duvdy.x, 0.0f, 1e-6f); // u stays 0.5 on the centre line
    // Off the centre line, against central differences of the interpolation itself.
    const vec2 q(4.2f, 3.1f);
    const float h = 1.0f / 64.0f;
    const vec2 duvdxQ = lfdPerspectiveDerivative(edgesAt(q), dx, invW, uv0, uv1, uv2);
    const vec2 duvdyQ = lfdPerspectiveDerivative(edgesAt(q), dy, invW, uv0, uv1, uv2);
    const vec2 cx = (uvAt(q + vec2(h, 0)) - uvAt(q - vec2(h, 0))) / (2.0f * h);
    const vec2 cy = (uvAt(q + vec2(0, h)) - uvAt(q - vec2(0, h))) / (2.0f * h);
    EXPECT_NEAR(duvdxQ.x, cx.x, 1e-4f);
    EXPECT_NEAR(duvdxQ.y, cx.y, 1e-4f);
    EXPECT_NEAR(duvdyQ.x, cy.x, 1e-4f);
    EXPECT_NEAR(duvdyQ.y, cy.y, 1e-4f);
    // What it replaced: the one-pixel forward difference is the secant towards the far side,
    // 0.0727 instead of 0.064 here - a footprint 14% too wide, so a blurrier texture.
    const float forward = uvAt(p + vec2(0, 1)).y - uvAt(p).y;
    EXPECT_NEAR(forward, 0.15f / 0.55f - 0.2f, 1e-5f);
    EXPECT_GT(forward, duvdy.y * 1.1f);
}

TEST(LfdprMath, OctahedralRoundTrip)
{
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    for (int i = 0; i < 1000; ++i) {
        const vec3 n = glm::normalize(vec3(u(rng), u(rng), u(rng)));
        const vec2 e = lfdOctEncode(n);
        EXPECT_LE(std::abs(e.x), 1.0f);
        EXPECT_LE(std::abs(e.y), 1.0f);
        // snorm16 quantisation as packSnorm2x16 does it.
        const vec2 qe = glm::round(e * 32767.0f) / 32767.0f;
        EXPECT_LT(glm::length(lfdOctDecode(qe) - n), 1e-4f);
    }
}

TEST(LfdprMath, CoarseningFitsTheTileBudget)
{
    const float tile = 2048.0f, maxTiles = 16.0f;
    EXPECT_EQ(lfdCoarsening(vec2(100, 100), tile, maxTiles), 1.0f);
    EXPECT_EQ(lfdCoarsening(vec2(3000, 8000), tile, maxTiles), 1.0f); // 2 x 4 tiles
    EXPECT_EQ(lfdTileCount(vec2(3000, 8000), tile), 8.0f);
    for (const vec2& extent : {vec2(9000, 9000), vec2(40000, 100), vec2(1e6f, 1e6f)}) {
        const float f = lfdCoarsening(extent, tile, maxTiles);
        EXPECT_GT(f, 1.0f);
        EXPECT_LE(lfdTileCount(extent / f + vec2(2.0f), tile), maxTiles);
        // Not much coarser than needed (one 1.25 step).
        EXPECT_GT(lfdTileCount(extent / (f / 1.25f) + vec2(2.0f), tile), maxTiles);
    }
}

TEST(LfdprFrame, UnionFrustumPlanesContainEveryFrustum)
{
    const DisplayProfile profile = withViews(prototypeDisplayProfile(), 48, 480, 360);
    SceneBounds bounds;
    bounds.min = glm::vec3(-1.0f);
    bounds.max = glm::vec3(1.0f);
    bounds.radius = std::sqrt(3.0f);
    const Framing framing = fitSceneToDisplay(profile, bounds);
    const player::FrameSetup frame = player::makeFrameSetup(profile, framing, 0.0, 0.0);
    const auto planes = player::unionFrustumPlanesDisplay(frame);
    // Every corner of every frustum, and points inside each frustum, are inside all planes.
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (const ViewCamera& camera : frame.cameras) {
        const glm::dmat4 displayFromClip = glm::inverse(camera.clipFromDisplay);
        for (int i = 0; i < 64; ++i) {
            const glm::dvec4 ndc = i < 8 ? glm::dvec4((i & 1) ? 1 : -1, (i & 2) ? 1 : -1, (i & 4) ? 1 : -1, 1)
                                         : glm::dvec4(u(rng), u(rng), u(rng), 1.0);
            const glm::dvec4 h = displayFromClip * ndc;
            const glm::dvec4 p(glm::dvec3(h) / h.w, 1.0);
            for (const glm::dvec4& plane : planes)
                EXPECT_GE(glm::dot(plane, p), 0.0);
        }
    }
    // Points outside the union: well beside and below the screen at depth 0 (the chords
    // are looser than the screen edges there), far behind, far in front.
    const glm::dvec2 pixel = viewPixelSizeMm(profile);
    const double halfW = 0.5 * pixel.x * profile.viewWidth, halfH = 0.5 * pixel.y * profile.viewHeight;
    for (const glm::dvec4& p : {glm::dvec4(halfW * 2.0, 0, 0, 1), glm::dvec4(0, -halfH * 2.0, 0, 1),
                                glm::dvec4(0, 0, -1e6, 1), glm::dvec4(0, 0, 1e6, 1)}) {
        bool outsideSome = false;
        for (const glm::dvec4& plane : planes)
            outsideSome = outsideSome || glm::dot(plane, p) < 0.0;
        EXPECT_TRUE(outsideSome) << p.x << " " << p.y << " " << p.z;
    }
}

} // namespace
} // namespace lfd::test
