// Framing and view cameras: zero parallax on the screen plane, parallax directions, the
// screen rectangle as every view's window, near/far around the fitted scene, and the
// conservative view-pixel length the baker's tessellation bound relies on.
#include "lfd/framing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

namespace {

using namespace lfd;

constexpr double kPi = std::numbers::pi;

glm::dvec4 clipOf(const ViewCamera& camera, const glm::dvec3& pDisplay) {
    return camera.clipFromDisplay * glm::dvec4(pDisplay, 1.0);
}

glm::dvec3 ndcOf(const ViewCamera& camera, const glm::dvec3& pDisplay) {
    const glm::dvec4 clip = clipOf(camera, pDisplay);
    return glm::dvec3(clip) / clip.w;
}

SceneBounds sphereBounds(glm::vec3 center, float radius) {
    SceneBounds b;
    b.center = center;
    b.radius = radius;
    b.min = center - glm::vec3(radius);
    b.max = center + glm::vec3(radius);
    return b;
}

// A small generic panel for the hand-worked cases: 100 x 100 mm, 100 x 100 views (1 mm
// view pixels), viewing distance 200 mm, cone 2 atan(1/4) (outermost eye limit 50 mm).
DisplayProfile squareProfile() {
    DisplayProfile p = prototypeDisplayProfile();
    p.name = "square";
    p.panelWidth = 300;
    p.panelHeight = 300;
    p.screenWidthMm = 100.0;
    p.screenHeightMm = 100.0;
    p.viewCount = 8;
    p.viewWidth = 100;
    p.viewHeight = 100;
    p.viewingDistanceMm = 200.0;
    p.viewConeDeg = 2.0 * std::atan(0.25) * 180.0 / kPi;
    validateDisplayProfile(p, "square");
    return p;
}

// The prototype, plus a Looking Glass Portrait-like panel (square view pixels, tall
// screen) and a close-viewing wide-cone panel, which stress the bounds differently.
std::vector<DisplayProfile> testProfiles() {
    std::vector<DisplayProfile> profiles{prototypeDisplayProfile()};
    DisplayProfile portrait = prototypeDisplayProfile();
    portrait.name = "portrait";
    portrait.panelWidth = 1536;
    portrait.panelHeight = 2048;
    portrait.screenWidthMm = 120.4148;
    portrait.screenHeightMm = 160.5531;
    portrait.viewWidth = 420;
    portrait.viewHeight = 560;
    portrait.viewingDistanceMm = 3.0 * portrait.screenHeightMm;
    profiles.push_back(portrait);
    DisplayProfile close = prototypeDisplayProfile();
    close.name = "close";
    close.viewingDistanceMm = 150.0;
    close.viewConeDeg = 70.0;
    close.viewCount = 12;
    profiles.push_back(close);
    for (const DisplayProfile& p : profiles)
        validateDisplayProfile(p, p.name);
    return profiles;
}

TEST(Framing, FitScalesAndCentresTheSphere) {
    const DisplayProfile p = prototypeDisplayProfile();
    const Framing f = fitSceneToDisplay(p, sphereBounds({1, 2, 3}, 5), 0.8);
    // mmPerUnit = fill * min(345.40, 194.30) / (2 r) = 0.8 * 194.30 / 10 = 15.544
    EXPECT_NEAR(f.mmPerUnit, 15.544, 1e-12);
    EXPECT_DOUBLE_EQ(f.sceneRadius, 5.0);
    EXPECT_DOUBLE_EQ(f.fill, 0.8);
    const glm::dmat4 m0 = displayFromScene(f, 0.0);
    const glm::dvec3 c = glm::dvec3(m0 * glm::dvec4(1, 2, 3, 1));
    EXPECT_NEAR(glm::length(c), 0.0, 1e-12);
    const glm::dvec3 px = glm::dvec3(m0 * glm::dvec4(6, 2, 3, 1)); // c + r x
    EXPECT_NEAR(px.x, 77.72, 1e-12);
    EXPECT_NEAR(px.y, 0.0, 1e-12);
    EXPECT_NEAR(px.z, 0.0, 1e-12);
    // R_y(90 deg) takes +x to -z (right-handed, +y up).
    const glm::dvec3 q = glm::dvec3(displayFromScene(f, kPi / 2) * glm::dvec4(6, 2, 3, 1));
    EXPECT_NEAR(q.x, 0.0, 1e-9);
    EXPECT_NEAR(q.z, -77.72, 1e-9);
    // The vertical axis through c is fixed.
    const glm::dvec3 up = glm::dvec3(displayFromScene(f, 1.234) * glm::dvec4(1, 7, 3, 1));
    EXPECT_NEAR(glm::length(up - glm::dvec3(0, 77.72, 0)), 0.0, 1e-9);
    // A zero radius (one point) frames as radius 1; a bad fill is refused.
    EXPECT_DOUBLE_EQ(fitSceneToDisplay(p, sphereBounds({0, 0, 0}, 0)).sceneRadius, 1.0);
    EXPECT_NEAR(fitSceneToDisplay(p, sphereBounds({0, 0, 0}, 0)).mmPerUnit, 97.15, 1e-12);
    EXPECT_THROW(fitSceneToDisplay(p, sphereBounds({0, 0, 0}, 1), 0.0), std::invalid_argument);
}

TEST(Framing, ViewPixelSize) {
    const glm::dvec2 s = viewPixelSizeMm(prototypeDisplayProfile());
    EXPECT_NEAR(s.x, 345.40 / 480.0, 1e-15); // 0.7195833 mm
    EXPECT_NEAR(s.y, 194.30 / 360.0, 1e-15); // 0.5397222 mm
}

TEST(Framing, EyesSpanTheConeLeftToRight) {
    const DisplayProfile p = prototypeDisplayProfile();
    const Framing f = fitSceneToDisplay(p, sphereBounds({0, 0, 0}, 1));
    // N = 2: x = 600 tan(40 deg * (0.25 - 0.5)) = 600 tan(-10 deg) = 600 * -0.17632698
    //        = -105.796188 mm
    const ViewCamera v0 = makeViewCamera(p, f, 0, 2);
    const ViewCamera v1 = makeViewCamera(p, f, 1, 2);
    EXPECT_NEAR(v0.eye.x, -105.7961884, 1e-6);
    EXPECT_NEAR(v1.eye.x, 105.7961884, 1e-6);
    EXPECT_DOUBLE_EQ(v0.eye.y, 0.0);
    EXPECT_DOUBLE_EQ(v0.eye.z, 600.0);
    // N = 48: strictly increasing, symmetric; the outermost is 600 tan(19.583 deg).
    double previous = -1e9;
    for (uint32_t i = 0; i < 48; ++i) {
        const ViewCamera v = makeViewCamera(p, f, i, 48);
        EXPECT_GT(v.eye.x, previous);
        previous = v.eye.x;
        EXPECT_NEAR(v.eye.x, -makeViewCamera(p, f, 47 - i, 48).eye.x, 1e-9);
    }
    EXPECT_NEAR(previous, 600.0 * std::tan(40.0 * (47.5 / 48.0 - 0.5) * kPi / 180.0), 1e-9);
    EXPECT_THROW(makeViewCamera(p, f, 48, 48), std::invalid_argument);
    EXPECT_THROW(makeViewCamera(p, f, 0, 0), std::invalid_argument);
}

TEST(Framing, ScreenPlaneHasZeroParallaxAndScreenCornersAreNdcCorners) {
    for (const DisplayProfile& p : testProfiles()) {
        const Framing f = fitSceneToDisplay(p, sphereBounds({0, 0, 0}, 1));
        const double W = p.screenWidthMm, H = p.screenHeightMm;
        const glm::dvec3 points[] = {{0, 0, 0}, {10, -20, 0}, {-0.4 * W, 0.3 * H, 0},
                                     {0.5 * W, 0.5 * H, 0}};
        for (uint32_t n : {1u, 7u, p.viewCount}) {
            for (uint32_t i = 0; i < n; ++i) {
                const ViewCamera v = makeViewCamera(p, f, i, n);
                for (const glm::dvec3& q : points) {
                    const glm::dvec3 ndc = ndcOf(v, q);
                    // Every view sees a screen-plane point at its screen position.
                    EXPECT_NEAR(ndc.x, 2.0 * q.x / W, 1e-9) << p.name << " view " << i;
                    EXPECT_NEAR(ndc.y, 2.0 * q.y / H, 1e-9) << p.name << " view " << i;
                }
                for (double sx : {-1.0, 1.0})
                    for (double sy : {-1.0, 1.0}) {
                        const glm::dvec3 ndc = ndcOf(v, {sx * W / 2, sy * H / 2, 0});
                        EXPECT_NEAR(ndc.x, sx, 1e-9);
                        EXPECT_NEAR(ndc.y, sy, 1e-9);
                    }
            }
        }
    }
}

TEST(Framing, ParallaxFollowsTheCameraBehindTheScreenAndOpposesItInFront) {
    // A point behind the screen (z = -z0) seen from the eye (e, 0, D) crosses the screen
    // plane at X_s = e + (x - e) D / (D + z0) = x D/(D + z0) + e z0/(D + z0): it moves WITH
    // the camera (to the right, NDC x increasing, as the view index increases). A point
    // in front (z = +z0 < D) gives X_s = x D/(D - z0) - e z0/(D - z0): it moves against it.
    // The vertical position Y_s = y D / d does not depend on the view.
    const DisplayProfile p = prototypeDisplayProfile();
    const Framing f = fitSceneToDisplay(p, sphereBounds({0, 0, 0}, 1));
    const glm::dvec3 behind{10, 5, -50}, front{10, 5, 50};
    double lastBehind = -1e9, lastFront = 1e9;
    const double yBehind = ndcOf(makeViewCamera(p, f, 0, 48), behind).y;
    const double yFront = ndcOf(makeViewCamera(p, f, 0, 48), front).y;
    for (uint32_t i = 0; i < 48; ++i) {
        const ViewCamera v = makeViewCamera(p, f, i, 48);
        const glm::dvec3 b = ndcOf(v, behind), fr = ndcOf(v, front);
        EXPECT_GT(b.x, lastBehind) << "view " << i;
        EXPECT_LT(fr.x, lastFront) << "view " << i;
        EXPECT_NEAR(b.y, yBehind, 1e-12);
        EXPECT_NEAR(fr.y, yFront, 1e-12);
        lastBehind = b.x;
        lastFront = fr.x;
    }
    // Hand-worked: N = 2, view 1 (e = 105.796188), point (0, 0, -100):
    //   X_s = 105.796188 * 100 / 700 = 15.113741 mm -> NDC 2 * 15.113741 / 345.40 = 0.0875144
    EXPECT_NEAR(ndcOf(makeViewCamera(p, f, 1, 2), {0, 0, -100}).x, 0.0875144250, 1e-9);
    EXPECT_NEAR(ndcOf(makeViewCamera(p, f, 0, 2), {0, 0, -100}).x, -0.0875144250, 1e-9);
}

TEST(Framing, FittedSphereLiesBetweenNearAndFarInEveryView) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    for (const DisplayProfile& p : testProfiles()) {
        for (double fill : {0.5, 1.0}) {
            const Framing f = fitSceneToDisplay(p, sphereBounds({-3, 40, 7}, 12.5f), fill);
            const double rho = f.sceneRadius * f.mmPerUnit;
            for (uint32_t i = 0; i < p.viewCount; ++i) {
                const ViewCamera v = makeViewCamera(p, f, i, p.viewCount);
                // The depth range of the sphere is [D - rho, D + rho] in every view: check
                // its nearest and farthest points and random surface points at random
                // turntable angles, in clip space (-w <= z <= w, w > 0).
                std::vector<glm::dvec3> points{{0, 0, rho}, {0, 0, -rho}};
                for (int n = 0; n < 200; ++n) {
                    const double zs = 2.0 * uniform(rng) - 1.0, phi = 2.0 * kPi * uniform(rng);
                    const double s = std::sqrt(1.0 - zs * zs);
                    const glm::dvec3 onSphere =
                        glm::dvec3(-3, 40, 7) +
                        12.5 * glm::dvec3(s * std::cos(phi), s * std::sin(phi), zs);
                    points.push_back(glm::dvec3(displayFromScene(f, 2.0 * kPi * uniform(rng)) *
                                                glm::dvec4(onSphere, 1.0)));
                }
                for (const glm::dvec3& q : points) {
                    const glm::dvec4 clip = clipOf(v, q);
                    ASSERT_GT(clip.w, 0.0) << p.name;
                    EXPECT_GE(clip.z, -clip.w) << p.name << " view " << i;
                    EXPECT_LE(clip.z, clip.w) << p.name << " view " << i;
                }
            }
        }
    }
}

TEST(Framing, MinViewPixelWorldHandWorked) {
    // One mm of edge at depth d below the cameras, offset s from a camera's axis, covers at
    // most D sqrt(d^2 + s^2) / (d^2 p) pixels (framing.cpp); over the fitted ball the
    // largest rate is on its boundary, d = D - rho cos(t), s = e_max + rho sin(t).
    // A framing of 50 mm per unit set by hand: the ball of radius 50 mm (on this square
    // screen fitSceneToDisplay fits 44.72 mm, the outer views' frustum being the limit).
    DisplayProfile p = squareProfile();
    const Framing f{glm::dvec3(0.0), 1.0, 50.0, 1.0};

    // Horizontal (1 mm view pixels, D = 200, rho = 50, e_max = 200 tan(cone/2) = 50):
    //   g(t) = sqrt((200 - 50 cos t)^2 + (50 + 50 sin t)^2) / (200 - 50 cos t)^2
    //   g(0) = sqrt(150^2 + 50^2) / 150^2 = 158.114 / 22500 = 0.0070273 (nearest point)
    //   but the maximum is off the axis, at t = 17.363 deg: d = 152.290, s = 64.920,
    //   g = sqrt(23192.2 + 4214.6) / 23192.2 = 165.550 / 23192.2 = 0.0071388
    //   (a plain footprint would give 150/200 = 0.75 mm; with obliquity it is
    //   1 / (200 * 0.0071388) = 0.700396 mm = 0.0140079 scene units).
    // Vertical pixels are the same size with no eye offset, so the horizontal axis rules.
    const double horizontal = minViewPixelWorld(p, f);
    EXPECT_LE(horizontal, 0.0140079174); // conservative
    EXPECT_GE(horizontal, 0.0140079174 * 0.998); // and tight

    // Make the vertical pixels 0.25 mm (400 rows): now the vertical axis rules, with
    //   g_y(t) = sqrt((200 - 50 cos t)^2 + (50 sin t)^2) / (200 - 50 cos t)^2,
    // largest at t = 0 (g_y(30 deg) = 158.68 / 24555 = 0.006462 < 1/150), so the plain
    // footprint holds: 0.25 * 150 / 200 = 0.1875 mm = 0.00375 scene units.
    p.viewHeight = 400;
    EXPECT_NEAR(minViewPixelWorld(p, f), 0.00375, 0.00375 * 1e-5);
    // Twice the radius halves mmPerUnit: the same 0.1875 mm is twice as many scene units.
    const Framing f2{glm::dvec3(0.0), 2.0, 25.0, 1.0};
    EXPECT_NEAR(minViewPixelWorld(p, f2), 0.0075, 0.0075 * 1e-5);
}

// Pixel spans of the segment a-b (display space) in one view.
glm::dvec2 pixelSpan(const DisplayProfile& p, const ViewCamera& v, const glm::dvec3& a,
                     const glm::dvec3& b) {
    const glm::dvec3 na = ndcOf(v, a), nb = ndcOf(v, b);
    return {std::fabs(nb.x - na.x) * 0.5 * p.viewWidth,
            std::fabs(nb.y - na.y) * 0.5 * p.viewHeight};
}

TEST(Framing, EdgeOfMaxEdgePxPixelLengthsNeverSpansMoreThanMaxEdgePx) {
    constexpr double kMaxEdgePx = 100.0;
    std::mt19937 rng(12345);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    for (const DisplayProfile& p : testProfiles()) {
        const glm::vec3 c{2.0f, -1.0f, 0.5f};
        const float r = 3.0f;
        const Framing f = fitSceneToDisplay(p, sphereBounds(c, r));
        const double L = kMaxEdgePx * minViewPixelWorld(p, f); // scene units
        std::vector<ViewCamera> views;
        for (uint32_t i = 0; i < p.viewCount; ++i)
            views.push_back(makeViewCamera(p, f, i, p.viewCount));

        // Random edges fully inside the sphere, at random turntable angles.
        double largest = 0.0;
        int tested = 0;
        while (tested < 3000) {
            const glm::dvec3 m{uniform(rng), uniform(rng), uniform(rng)};
            glm::dvec3 dir{uniform(rng), uniform(rng), uniform(rng)};
            if (glm::length(m) > 1.0 || glm::length(dir) < 1e-3 || glm::length(dir) > 1.0)
                continue;
            dir = glm::normalize(dir);
            const glm::dvec3 a = glm::dvec3(c) + double(r) * m - 0.5 * L * dir;
            const glm::dvec3 b = a + L * dir;
            if (glm::length(a - glm::dvec3(c)) > r || glm::length(b - glm::dvec3(c)) > r)
                continue;
            ++tested;
            const glm::dmat4 displayFromSceneM = displayFromScene(f, kPi * uniform(rng));
            const glm::dvec3 da = glm::dvec3(displayFromSceneM * glm::dvec4(a, 1.0));
            const glm::dvec3 db = glm::dvec3(displayFromSceneM * glm::dvec4(b, 1.0));
            for (const ViewCamera& v : views) {
                const glm::dvec2 span = pixelSpan(p, v, da, db);
                ASSERT_LE(span.x, kMaxEdgePx * (1.0 + 1e-9)) << p.name;
                ASSERT_LE(span.y, kMaxEdgePx * (1.0 + 1e-9)) << p.name;
                largest = std::max({largest, span.x, span.y});
            }
        }

        // Adversarial edges: on the sphere's boundary in the plane of the camera line, at
        // every angle t from the nearest point, aimed along the worst direction for the
        // outermost views (u ~ (1, 0, (x - e) / d) horizontally, u ~ (0, 1, y / d)
        // vertically, see framing.cpp), pulled inwards so the whole edge stays inside.
        // Long edges must stay within their pixel count; one-pixel edges show the bound
        // is tight (long edges near close cameras cannot reach it: the rate falls along
        // them).
        const double rho = f.sceneRadius * f.mmPerUnit;
        const double D = p.viewingDistanceMm;
        const double pixelMm = minViewPixelWorld(p, f) * f.mmPerUnit;
        for (double n : {kMaxEdgePx, 10.0, 1.0}) {
            const double Lmm = n * pixelMm;
            double largestRatio = 0.0;
            // The outermost cameras of a very fine view set sit at the cone's edge, which
            // the bound covers (angular supersampling renders views anywhere in the cone).
            for (const ViewCamera& v :
                 {views.front(), views.back(), makeViewCamera(p, f, 0, 1u << 16),
                  makeViewCamera(p, f, (1u << 16) - 1, 1u << 16)}) {
                const double side = v.eye.x > 0.0 ? -1.0 : 1.0; // far side of the axis
                const double radius = rho - 0.5 * Lmm;
                for (double t = 0.0; t < kPi; t += kPi / 720.0) {
                    const glm::dvec3 cx{side * radius * std::sin(t), 0.0, radius * std::cos(t)};
                    const glm::dvec3 cy{0.0, radius * std::sin(t), radius * std::cos(t)};
                    const glm::dvec3 ux = glm::normalize(
                        glm::dvec3(1.0, 0.0, (cx.x - v.eye.x) / (D - cx.z)));
                    const glm::dvec3 uy =
                        glm::normalize(glm::dvec3(0.0, 1.0, cy.y / (D - cy.z)));
                    for (int axis = 0; axis < 2; ++axis) {
                        const glm::dvec3 centre = axis == 0 ? cx : cy;
                        const glm::dvec3 dir = axis == 0 ? ux : uy;
                        const glm::dvec3 a = centre - 0.5 * Lmm * dir;
                        const glm::dvec3 b = centre + 0.5 * Lmm * dir;
                        if (D - std::max(a.z, b.z) < 1.0)
                            continue; // nearer than the near plane floor
                        const double span = pixelSpan(p, v, a, b)[axis];
                        EXPECT_LE(span, n * (1.0 + 1e-9)) << p.name << " t=" << t;
                        largestRatio = std::max(largestRatio, span / n);
                    }
                }
            }
            std::printf("%s: %g-pixel edges reach %.4f of the bound (adversarial)\n",
                        p.name.c_str(), n, largestRatio);
            if (n == 1.0) {
                EXPECT_GT(largestRatio, 0.95) << p.name;
            }
        }
        std::printf("%s: %d random %g-pixel edges reach %.2f px\n", p.name.c_str(), tested,
                    kMaxEdgePx, largest);
        EXPECT_GT(largest, 0.6 * kMaxEdgePx) << p.name; // not vacuous
    }
}

TEST(Framing, PlainFootprintBoundIsNotConservativeForObliqueEdges) {
    // Why minViewPixelWorld carries the obliquity factor: on a square-pixel panel the plain
    // footprint pixel * (D - rho) / D lets an edge tilted along the outermost camera's line
    // of sight span more than the intended pixel count.
    const DisplayProfile p = testProfiles()[1]; // portrait, square view pixels
    const Framing f = fitSceneToDisplay(p, sphereBounds({0, 0, 0}, 1));
    const double rho = f.sceneRadius * f.mmPerUnit;
    const double D = p.viewingDistanceMm;
    const double plainMm = viewPixelSizeMm(p).x * (D - rho) / D;
    const ViewCamera v = makeViewCamera(p, f, p.viewCount - 1, p.viewCount);
    const double Lmm = 100.0 * plainMm;
    const glm::dvec3 centre{0.0, 0.0, rho - 0.6 * Lmm};
    const glm::dvec3 dir =
        glm::normalize(glm::dvec3(1.0, 0.0, (centre.x - v.eye.x) / (D - centre.z)));
    const glm::dvec3 a = centre - 0.5 * Lmm * dir, b = centre + 0.5 * Lmm * dir;
    ASSERT_LE(glm::length(a), rho);
    ASSERT_LE(glm::length(b), rho);
    EXPECT_GT(pixelSpan(p, v, a, b).x, 100.0);
    // The shipped bound keeps the same edge, shortened to 100 of its pixels, within 100.
    const double safeMm = 100.0 * minViewPixelWorld(p, f) * f.mmPerUnit;
    EXPECT_LE(pixelSpan(p, v, centre - 0.5 * safeMm * dir, centre + 0.5 * safeMm * dir).x, 100.0);
}

} // namespace

namespace {

// Largest |NDC x| of a 10 x 1 x 1 box (its bounding sphere fitted by `framing`) over every
// view of the cone and every turntable angle: above 1, the box is cut off at a side.
double widestNdcX(const DisplayProfile& p, const Framing& framing) {
    double widest = 0.0;
    for (int degree = 0; degree < 360; ++degree)
        for (uint32_t v = 0; v < p.viewCount; ++v) {
            const ViewCamera camera = makeViewCamera(p, framing, v, p.viewCount);
            const glm::dmat4 m = displayFromScene(framing, degree * kPi / 180.0);
            for (int corner = 0; corner < 8; ++corner) {
                const glm::dvec3 s((corner & 1) ? 5.0 : -5.0, (corner & 2) ? 0.5 : -0.5, (corner & 4) ? 0.5 : -0.5);
                widest = std::max(widest, std::abs(ndcOf(camera, glm::dvec3(m * glm::dvec4(s, 1.0))).x));
            }
        }
    return widest;
}

} // namespace

// A wide scene on a portrait panel (the Looking Glass Portrait: 120.4 x 160.6 mm, 40 degree
// cone at 3 screen heights) stays inside every view; fitting the sphere to the screen width
// alone, as the framing did before, cut it off at both sides of the outer views.
TEST(Framing, WideSceneOnAPortraitPanelFitsEveryView) {
    DisplayProfile p = prototypeDisplayProfile();
    p.screenWidthMm = 120.4148;
    p.screenHeightMm = 160.5531;
    p.viewingDistanceMm = 3.0 * p.screenHeightMm;
    p.viewConeDeg = 40.0;
    const SceneBounds bounds = sphereBounds({0, 0, 0}, float(std::sqrt(25.0 + 0.25 + 0.25)));
    const Framing f = fitSceneToDisplay(p, bounds);
    // R_fit = D (W/2) / sqrt(D^2 + (W/2 + D tan 20)^2) = 54.09 mm, below W / 2 = 60.21 mm.
    EXPECT_NEAR(f.sceneRadius * f.mmPerUnit, 54.09, 0.005);
    const double widest = widestNdcX(p, f);
    std::printf("[ numbers  ] 10x1x1 box on the Portrait: widest |NDC x| %.4f (fitted to the width alone: %.4f)\n",
                widest, widestNdcX(p, Framing{f.sceneCenter, f.sceneRadius, 0.5 * p.screenWidthMm / f.sceneRadius, 1.0}));
    EXPECT_LE(widest, 1.0);
    EXPECT_GT(widestNdcX(p, Framing{f.sceneCenter, f.sceneRadius, 0.5 * p.screenWidthMm / f.sceneRadius, 1.0}), 1.05);
    // Landscape panels keep their framing: the prototype's sphere is half the screen height.
    const Framing proto = fitSceneToDisplay(prototypeDisplayProfile(), bounds);
    EXPECT_NEAR(proto.sceneRadius * proto.mmPerUnit, 97.15, 1e-9);
}
