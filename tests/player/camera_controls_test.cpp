// Camera controls (CPU only): the ViewControls composition in makeFrameSetup against
// hand-worked projections of the display geometry (framing.h), and the CameraControls
// state machine the window's mouse and keys drive.
#include "camera_controls.h"
#include "frame.h"

#include "lfd/display_profile.h"
#include "lfd/framing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace lfd::player {
namespace {

constexpr double kPi = std::numbers::pi;

// The prototype (W = 345.40 mm, H = 194.30 mm, D = 600 mm, cone 40 deg, 48 views of
// 480x360) and a scene of radius 2 about c = (1, 2, 3): mmPerUnit = 194.30 / 4 = 48.575.
struct Prototype {
    DisplayProfile profile = prototypeDisplayProfile();
    Framing framing;
    glm::dvec3 c{1.0, 2.0, 3.0};
    Prototype()
    {
        SceneBounds bounds;
        bounds.center = glm::vec3(c);
        bounds.radius = 2.0f;
        framing = fitSceneToDisplay(profile, bounds);
    }
};

// Hand-worked projection (framing.h), independent of makeViewCamera: a display point P
// seen from the eye E_i = (e_i, 0, D), e_i = D tan(cone ((i + 0.5) / N - 0.5)), lands on
// the screen at X = e + (x - e) D / (D - z), Y = y D / (D - z); view pixel x from the left
// = (X / W + 0.5) w.
double eyeX(const DisplayProfile& p, uint32_t i, double coneScale = 1.0)
{
    const double t = (i + 0.5) / p.viewCount - 0.5;
    return p.viewingDistanceMm * std::tan(glm::radians(p.viewConeDeg * coneScale) * t);
}
double handPixelX(const DisplayProfile& p, const glm::dvec3& P, double e)
{
    const double D = p.viewingDistanceMm;
    const double X = e + (P.x - e) * D / (D - P.z);
    return (X / p.screenWidthMm + 0.5) * p.viewWidth;
}

// The pipeline's projection of a scene point in view i, in view pixels (x from the left):
// double (cameras) or the float matrices the shaders get.
glm::dvec3 clipOf(const FrameSetup& f, uint32_t i, const glm::dvec3& scenePoint, bool asFloat)
{
    const glm::dvec4 clip = asFloat ? glm::dvec4(f.clipFromScene[i] * glm::vec4(glm::vec3(scenePoint), 1.0f))
                                    : f.cameras[i].clipFromDisplay * f.displayFromScene * glm::dvec4(scenePoint, 1.0);
    return glm::dvec3(clip) / clip.w;
}
double pixelX(const FrameSetup& f, uint32_t i, const glm::dvec3& scenePoint, bool asFloat = false)
{
    return (clipOf(f, i, scenePoint, asFloat).x * 0.5 + 0.5) * f.profile.viewWidth;
}

TEST(ViewControls, DefaultsReproduceTheFrameWithoutControls)
{
    const Prototype s;
    const FrameSetup a = makeFrameSetup(s.profile, s.framing, 2.5, 10.0);
    const FrameSetup b = makeFrameSetup(s.profile, s.framing, 2.5, 10.0, ViewControls{});
    EXPECT_EQ(a.displayFromScene, displayFromScene(s.framing, kPi / 2.0)); // 2.5 s of a 10 s turn
    EXPECT_EQ(a.displayFromScene, b.displayFromScene);
    for (uint32_t i = 0; i < s.profile.viewCount; ++i)
        EXPECT_EQ(a.clipFromScene[i], b.clipFromScene[i]) << i;
}

// The check: after moving the focal plane, a point at the new focal depth
// projects to the same screen position in every view (within 0.01 px), and the old
// zero-parallax depth now shows the parallax of a point focalDepth behind the screen.
TEST(ViewControls, FocalPlaneMovesTheZeroParallaxDepth)
{
    const Prototype s;
    ViewControls controls;
    controls.turntable = false;
    controls.focalDepthMm = 30.0;
    const FrameSetup f = makeFrameSetup(s.profile, s.framing, 0.0, 10.0, controls);
    const double mm = s.framing.mmPerUnit; // 48.575

    // A point 30 mm in front of the scene centre (before the shift), off-axis.
    const glm::dvec3 onFocalPlane = s.c + glm::dvec3(0.5, -0.3, 30.0 / mm);
    const double expected = (0.5 * mm / s.profile.screenWidthMm + 0.5) * s.profile.viewWidth; // 273.75 px
    for (uint32_t i = 0; i < s.profile.viewCount; ++i) {
        EXPECT_NEAR(pixelX(f, i, onFocalPlane), expected, 1e-6) << "view " << i;
        EXPECT_NEAR(pixelX(f, i, onFocalPlane, true), expected, 0.01) << "view " << i << " (float)";
    }

    // The scene centre now sits at display z = -30: X = e * 30 / 630, e.g. view 0
    // (e = 600 tan(-19.583 deg) = -213.45 mm): X = -10.164 mm, 225.875 px (centre 240).
    for (const uint32_t i : {0u, 23u, 47u}) {
        const double hand = handPixelX(s.profile, glm::dvec3(0.0, 0.0, -30.0), eyeX(s.profile, i));
        EXPECT_NEAR(pixelX(f, i, s.c), hand, 1e-6) << "view " << i;
    }
    EXPECT_NEAR(pixelX(f, 0, s.c), 225.875, 0.001);
}

TEST(ViewControls, ZoomScalesAboutTheSceneCentre)
{
    const Prototype s;
    ViewControls controls;
    controls.turntable = false;
    controls.zoom = 2.0;
    const FrameSetup f = makeFrameSetup(s.profile, s.framing, 0.0, 10.0, controls);
    // c + (1, 0, 0) lands at x = 2 * 48.575 = 97.15 mm on the screen plane: 375.009 px in every view.
    const double expected = (97.15 / 345.40 + 0.5) * 480.0;
    for (uint32_t i = 0; i < s.profile.viewCount; ++i)
        EXPECT_NEAR(pixelX(f, i, s.c + glm::dvec3(1.0, 0.0, 0.0)), expected, 1e-6);
    EXPECT_NEAR(expected, 375.009, 0.001);
    EXPECT_DOUBLE_EQ(f.framing.mmPerUnit, 2.0 * s.framing.mmPerUnit);
}

TEST(ViewControls, PanShiftsAlongTheScreenPlane)
{
    const Prototype s;
    ViewControls controls;
    controls.turntable = false;
    controls.panMm = {10.0, -5.0};
    const FrameSetup f = makeFrameSetup(s.profile, s.framing, 0.0, 10.0, controls);
    for (uint32_t i = 0; i < s.profile.viewCount; ++i) {
        const glm::dvec3 ndc = clipOf(f, i, s.c, false);
        EXPECT_NEAR(ndc.x * 0.5 * 345.40, 10.0, 1e-9); // screen mm
        EXPECT_NEAR(ndc.y * 0.5 * 194.30, -5.0, 1e-9);
    }
}

TEST(ViewControls, OrbitTurnsYawThenPitchAboutTheSceneCentre)
{
    const Prototype s;
    const double mm = s.framing.mmPerUnit;
    auto display = [&](double yaw, double pitch, const glm::dvec3& offset) {
        ViewControls controls;
        controls.turntable = false;
        controls.yawDeg = yaw;
        controls.pitchDeg = pitch;
        const FrameSetup f = makeFrameSetup(s.profile, s.framing, 0.0, 10.0, controls);
        return glm::dvec3(f.displayFromScene * glm::dvec4(s.c + offset, 1.0));
    };
    auto near = [](const glm::dvec3& a, const glm::dvec3& b) { return glm::length(a - b) < 1e-9; };
    // R_y(90) takes +x to -z (the right side turns away); R_x(30) takes +z to (0, -sin 30, cos 30).
    EXPECT_TRUE(near(display(90.0, 0.0, {1, 0, 0}), {0.0, 0.0, -mm}));
    EXPECT_TRUE(near(display(0.0, 30.0, {0, 0, 1}), {0.0, -0.5 * mm, std::sqrt(3.0) / 2.0 * mm}));
    // Yaw first, then pitch: +x -> -z -> (0, sin 30, -cos 30).
    EXPECT_TRUE(near(display(90.0, 30.0, {1, 0, 0}), {0.0, 0.5 * mm, -std::sqrt(3.0) / 2.0 * mm}));
    // The front (+z) moves right for positive yaw.
    EXPECT_GT(display(10.0, 0.0, {0, 0, 1}).x, 0.0);
}

TEST(ViewControls, DepthinessScalesTheViewCone)
{
    const Prototype s;
    ViewControls controls;
    controls.turntable = false;
    controls.depthiness = 0.5;
    const FrameSetup half = makeFrameSetup(s.profile, s.framing, 0.0, 10.0, controls);
    EXPECT_DOUBLE_EQ(half.profile.viewConeDeg, 20.0);
    for (const uint32_t i : {0u, 10u, 47u})
        EXPECT_NEAR(half.cameras[i].eye.x, eyeX(s.profile, i, 0.5), 1e-9); // view 0: -103.55 mm
    EXPECT_NEAR(half.cameras[0].eye.x, -103.548, 0.001);

    // Depthiness 0: every camera central, every view the same image.
    controls.depthiness = 0.0;
    const FrameSetup flat = makeFrameSetup(s.profile, s.framing, 0.0, 10.0, controls);
    for (uint32_t i = 1; i < s.profile.viewCount; ++i)
        EXPECT_EQ(flat.clipFromScene[i], flat.clipFromScene[0]) << i;
}

TEST(ViewControls, TurntableOffHoldsTheAngle)
{
    const Prototype s;
    ViewControls controls;
    EXPECT_DOUBLE_EQ(makeFrameSetup(s.profile, s.framing, 2.5, 10.0, controls).turntableAngle, kPi / 2.0);
    controls.turntable = false;
    EXPECT_DOUBLE_EQ(makeFrameSetup(s.profile, s.framing, 2.5, 10.0, controls).turntableAngle, 0.0);
    EXPECT_DOUBLE_EQ(turntableAngle(7.5, 10.0), 1.5 * kPi);
    EXPECT_DOUBLE_EQ(turntableAngle(7.5, 0.0), 0.0);
}

// Zoomed and moved toward the viewer, the scene still lies between every view's near and
// far planes (the framing handed to the cameras grows by the focal shift).
TEST(ViewControls, NearAndFarEncloseTheMovedScene)
{
    const Prototype s;
    ViewControls controls;
    controls.turntable = false;
    controls.zoom = 1.5;
    for (const double focal : {-80.0, 80.0}) {
        controls.focalDepthMm = focal;
        const FrameSetup f = makeFrameSetup(s.profile, s.framing, 0.0, 10.0, controls);
        for (const glm::dvec3 offset : {glm::dvec3(0, 0, 2), glm::dvec3(0, 0, -2), glm::dvec3(2, 0, 0)})
            for (uint32_t i = 0; i < s.profile.viewCount; ++i) {
                const double z = clipOf(f, i, s.c + offset, false).z;
                EXPECT_GT(z, -1.0) << "focal " << focal << " view " << i;
                EXPECT_LT(z, 1.0) << "focal " << focal << " view " << i;
            }
    }
}

TEST(CameraControls, MouseAndKeysStepAsDocumented)
{
    // Scene radius 97.15 mm on the display: the focal plane moves 9.715 mm per key.
    CameraControls c(ViewControls{}, 97.15, 40.0);
    c.orbit(100.0, -50.0); // 0.3 deg per pixel
    EXPECT_DOUBLE_EQ(c.state().yawDeg, 30.0);
    EXPECT_DOUBLE_EQ(c.state().pitchDeg, -15.0);
    c.orbit(0.0, 1000.0);
    EXPECT_DOUBLE_EQ(c.state().pitchDeg, 89.0); // clamped
    c.orbit(500.0, 0.0); // 30 + 150 = 180
    EXPECT_DOUBLE_EQ(c.state().yawDeg, 180.0);
    c.orbit(100.0, 0.0); // 210 wraps to -150
    EXPECT_DOUBLE_EQ(c.state().yawDeg, -150.0);

    c.zoom(3.0);
    EXPECT_NEAR(c.state().zoom, 1.331, 1e-12);
    c.zoom(100.0);
    EXPECT_DOUBLE_EQ(c.state().zoom, 10.0);
    c.zoom(-1000.0);
    EXPECT_DOUBLE_EQ(c.state().zoom, 0.1);

    c.pan(10.0, 20.0, 0.09); // window y runs down: dragging down moves the scene down
    EXPECT_NEAR(c.state().panMm.x, 0.9, 1e-12);
    EXPECT_NEAR(c.state().panMm.y, -1.8, 1e-12);

    c.moveFocalPlane(2);
    EXPECT_NEAR(c.state().focalDepthMm, 19.43, 1e-12);
    c.moveFocalPlane(-3);
    EXPECT_NEAR(c.state().focalDepthMm, -9.715, 1e-12);

    c.changeDepthiness(1);
    EXPECT_DOUBLE_EQ(c.state().depthiness, 1.1);
    c.changeDepthiness(-20);
    EXPECT_DOUBLE_EQ(c.state().depthiness, 0.0);
    c.changeDepthiness(100);
    EXPECT_DOUBLE_EQ(c.state().depthiness, 4.0); // min(4, 170 / 40 = 4.25)
    EXPECT_NEAR(maxDepthiness(60.0), 170.0 / 60.0, 1e-12);

    c.reset();
    EXPECT_EQ(c.state().yawDeg, 0.0);
    EXPECT_EQ(c.state().zoom, 1.0);
    EXPECT_EQ(c.state().focalDepthMm, 0.0);
    EXPECT_EQ(c.state().depthiness, 1.0);
    EXPECT_EQ(c.state().panMm, glm::dvec2(0.0));
}

TEST(CameraControls, TurntableToggleKeepsTheSceneWhereItIs)
{
    ViewControls start;
    start.yawDeg = 10.0;
    CameraControls c(start, 100.0, 40.0);
    // On, at a turntable angle of 90 deg: the scene is turned by 100 deg in all.
    c.toggleTurntable(kPi / 2.0);
    EXPECT_FALSE(c.state().turntable);
    EXPECT_DOUBLE_EQ(c.state().yawDeg, 100.0); // off: 100 + 0
    // Back on when the turntable has reached 180 deg: -80 + 180 = 100, no jump.
    c.toggleTurntable(kPi);
    EXPECT_TRUE(c.state().turntable);
    EXPECT_DOUBLE_EQ(c.state().yawDeg, -80.0);
    c.reset();
    EXPECT_DOUBLE_EQ(c.state().yawDeg, 10.0); // the start-up state, not zero
}

TEST(CameraControls, InteractionClockForThePreview)
{
    CameraControls c(ViewControls{}, 100.0, 40.0);
    EXPECT_FALSE(c.interacting(0.0, 0.3));
    c.noteInput(1.0);
    EXPECT_TRUE(c.interacting(1.2, 0.3));
    EXPECT_FALSE(c.interacting(1.31, 0.3));
}

TEST(CameraControls, FlagParsingAndValidation)
{
    EXPECT_EQ(parseNumberPair("30,-15"), glm::dvec2(30.0, -15.0));
    EXPECT_EQ(parseNumberPair("0.5,2e1"), glm::dvec2(0.5, 20.0));
    for (const char* bad : {"30", "a,b", "1,2,3", "nan,1", ",", "1,"})
        EXPECT_FALSE(parseNumberPair(bad)) << bad;

    auto message = [](const ViewControls& v, double cone) {
        try {
            validateViewControls(v, cone);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    ViewControls v;
    EXPECT_EQ(message(v, 40.0), "");
    v.zoom = 0.0;
    EXPECT_NE(message(v, 40.0).find("--zoom"), std::string::npos);
    v = ViewControls{};
    v.depthiness = 5.0;
    EXPECT_NE(message(v, 40.0).find("--depthiness"), std::string::npos);
    v = ViewControls{};
    v.pitchDeg = 90.0;
    EXPECT_NE(message(v, 40.0).find("--orbit"), std::string::npos);
    v = ViewControls{};
    v.focalDepthMm = std::nan("");
    EXPECT_NE(message(v, 40.0).find("--focal-depth"), std::string::npos);
}

} // namespace
} // namespace lfd::player
