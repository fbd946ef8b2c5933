// KHR_texture_transform, KHR_materials_unlit and KHR_lights_punctual in every renderer:
// a transformed slot renders as the same scene whose uvs were transformed by hand (per slot,
// with the gradients of lfdpr's textureGrad and the paper pipeline's LOD following the
// transform), an unlit material shows its base colour whatever the lighting, and punctual
// lights follow the extension's falloff and their nodes' animation.
// Every test prints its numbers ("[ numbers  ] ...") so they can be quoted.
#include "gl_test_support.h"
#include "render_test_util.h"
#include "test_scenes.h"

#include "image_metrics.h"

#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace lfd::test {
namespace {

using metrics::Image;

// The largest RMSE between corresponding views of two frames.
double worstViewRmse(const RenderedFrame& a, const RenderedFrame& b)
{
    double worst = 0.0;
    for (size_t v = 0; v < a.views.size(); ++v)
        worst = std::max(worst, metrics::rmse(a.views[v], b.views[v]));
    return worst;
}

TextureTransform makeTransform(glm::vec2 offset, float rotation, glm::vec2 scale)
{
    // KHR_texture_transform: u' = u cos r + v sin r, v' = v cos r - u sin r, after scaling.
    TextureTransform t;
    const float c = std::cos(rotation), s = std::sin(rotation);
    t.linear = glm::mat2(glm::vec2(c, -s), glm::vec2(s, c)) * glm::mat2(glm::vec2(scale.x, 0.0f), glm::vec2(0.0f, scale.y));
    t.offset = offset;
    return t;
}

// A tilted textured square: base colour and emissive checkers of different periods, so a
// slot that takes the wrong transform shows.
Scene texturedSquare()
{
    Scene scene;
    scene.textures.push_back(checkerTexture(64, 8, {230, 40, 30, 255}, {20, 60, 220, 255}, true));
    scene.textures.push_back(checkerTexture(32, 2, {80, 80, 80, 255}, {0, 0, 0, 255}, true));
    Material m;
    m.baseColorTexture = 0;
    m.emissiveTexture = 1;
    m.emissiveFactor = glm::vec3(1.0f);
    m.metallicFactor = 0.0f;
    m.roughnessFactor = 0.6f;
    scene.materials.push_back(m);
    addNode(scene, addMesh(scene, addGrid(scene, 0.5f, 8, 1.0f), 0), glm::vec3(0.0f),
            glm::angleAxis(0.5f, glm::normalize(glm::vec3(1.0f, 0.4f, 0.0f))), glm::vec3(1.0f));
    return scene;
}

const char* const kRenderers[] = {"mvr", "mvr-layered", "lfdpr", "lfdpr-paper"};

class MaterialExtensionsTest : public GlTest {};

// Each slot's transform against the same square with uvs transformed by hand: base colour
// by T (transformed uvs, identity slot), emissive by its own E (slot transform E T^-1 on
// the hand-transformed uvs, so it sees E(uv) in both).
TEST_F(MaterialExtensionsTest, TextureTransformMatchesUvsTransformedByHand)
{
    const TextureTransform t = makeTransform({0.3f, -0.2f}, 0.4f, {2.0f, 1.5f});
    const TextureTransform e = makeTransform({0.1f, 0.05f}, -0.7f, {0.5f, 3.0f});
    Scene transformed = texturedSquare();
    transformed.materials[0].textureTransforms[uint32_t(TextureSlot::BaseColor)] = t;
    transformed.materials[0].textureTransforms[uint32_t(TextureSlot::Emissive)] = e;
    finishScene(transformed);
    Scene byHand = texturedSquare();
    for (glm::vec2& uv : byHand.vertices.uvs)
        uv = t.apply(uv);
    TextureTransform eAfterT; // E T^-1
    const glm::mat2 tInverse = glm::inverse(t.linear);
    eAfterT.linear = e.linear * tInverse;
    eAfterT.offset = e.offset - e.linear * (tInverse * t.offset);
    byHand.materials[0].textureTransforms[uint32_t(TextureSlot::Emissive)] = eAfterT;
    finishScene(byHand);
    Scene untransformed = texturedSquare();
    finishScene(untransformed);

    const DisplayProfile profile = smallProfile(4, 96, 72);
    for (const char* renderer : kRenderers) {
        const RenderedFrame a = renderFrame(renderer, transformed, profile);
        const double worst = worstViewRmse(a, renderFrame(renderer, byHand, profile));
        const double plainDiff = worstViewRmse(a, renderFrame(renderer, untransformed, profile));
        std::printf("[ numbers  ] %s: transformed vs by hand RMSE %.3f (vs untransformed %.1f)\n", renderer, worst,
                    plainDiff);
        EXPECT_LT(worst, 1.0) << renderer << ": the slot transforms are not the hand-transformed uvs";
        EXPECT_GT(plainDiff, 10.0) << renderer << ": the transform changed nothing";
    }
}

// A normal map under a rotating, non-uniformly scaling transform: the tangent frame turns
// with the texture's axes, as for the same square whose uvs and tangents (the baker's
// generateTangents for those uvs) were transformed by hand; a tilted normal lit from the
// upper left shows which way the frame points.
TEST_F(MaterialExtensionsTest, TextureTransformTurnsTheNormalMapsFrame)
{
    auto tiltedSquare = [] {
        Scene scene;
        Texture normal = checkerTexture(4, 2, {204, 128, 230, 255}, {204, 128, 230, 255}, false); // (0.6, 0, 0.8)
        scene.textures.push_back(normal);
        Material m;
        m.baseColorFactor = glm::vec4(0.8f);
        m.metallicFactor = 0.0f;
        m.roughnessFactor = 0.5f;
        m.normalTexture = 0;
        scene.materials.push_back(m);
        addNode(scene, addMesh(scene, addGrid(scene, 0.5f, 4, 1.0f), 0), glm::vec3(0.0f), glm::quat(1, 0, 0, 0),
                glm::vec3(1.0f));
        return scene;
    };
    const TextureTransform t = makeTransform({0.2f, 0.1f}, 1.1f, {2.0f, 0.5f});
    Scene transformed = tiltedSquare();
    transformed.materials[0].textureTransforms[uint32_t(TextureSlot::Normal)] = t;
    finishScene(transformed);
    Scene byHand = tiltedSquare();
    // The square's P(u, v) = (2u - 1, 1 - 2v, 0) / 2 * 2h: dP/du = (1, 0, 0), dP/dv = (0, -1, 0)
    // (h = 0.5); for uv' = L uv + o, [dP/du' dP/dv'] = [dP/du dP/dv] L^-1.
    const glm::mat2 inv = glm::inverse(t.linear);
    const glm::vec3 du = glm::vec3(1, 0, 0) * inv[0][0] + glm::vec3(0, -1, 0) * inv[0][1];
    const glm::vec3 dv = glm::vec3(1, 0, 0) * inv[1][0] + glm::vec3(0, -1, 0) * inv[1][1];
    const glm::vec3 tangent = glm::normalize(glm::vec3(du.x, du.y, 0.0f));
    const float w = glm::dot(glm::cross(glm::vec3(0, 0, 1), tangent), -dv) < 0.0f ? -1.0f : 1.0f;
    for (size_t i = 0; i < byHand.vertices.uvs.size(); ++i) {
        byHand.vertices.uvs[i] = t.apply(byHand.vertices.uvs[i]);
        byHand.vertices.tangents[i] = glm::vec4(tangent, w);
    }
    finishScene(byHand);
    Scene unturned = tiltedSquare();
    finishScene(unturned);

    const DisplayProfile profile = smallProfile(3, 64, 48);
    for (const char* renderer : kRenderers) {
        const RenderedFrame a = renderFrame(renderer, transformed, profile);
        const double worst = worstViewRmse(a, renderFrame(renderer, byHand, profile));
        const double plainDiff = worstViewRmse(a, renderFrame(renderer, unturned, profile));
        std::printf("[ numbers  ] %s: turned normal map vs by hand RMSE %.3f (vs unturned frame %.1f)\n", renderer,
                    worst, plainDiff);
        EXPECT_LT(worst, 1.0) << renderer << ": the normal map's frame does not follow the transform";
        EXPECT_GT(plainDiff, 5.0) << renderer << ": the frame did not turn";
    }
}

// Pixels of `image` whose (2 margin + 1)^2 neighbourhood is all covered (not the
// background, player::kBackground: 13), so edge pixels that a reconstruction filter blends
// with the background are left out.
std::vector<size_t> interiorPixels(const Image& image, int margin)
{
    const int w = int(image.width), h = int(image.height);
    auto covered = [&](int x, int y) {
        const size_t i = (size_t(y) * size_t(w) + size_t(x)) * 4;
        return std::abs(int(image.pixels[i]) - 13) > 2 || std::abs(int(image.pixels[i + 1]) - 13) > 2;
    };
    std::vector<size_t> interior;
    for (int y = margin; y < h - margin; ++y)
        for (int x = margin; x < w - margin; ++x) {
            bool all = true;
            for (int dy = -margin; dy <= margin && all; ++dy)
                for (int dx = -margin; dx <= margin && all; ++dx)
                    all = covered(x + dx, y + dy);
            if (all)
                interior.push_back(size_t(y) * size_t(w) + size_t(x));
        }
    return interior;
}

// KHR_materials_unlit: the base colour, exactly, in every renderer and under any exposure,
// tone mapping and lights.
TEST_F(MaterialExtensionsTest, UnlitShowsTheBaseColourWhateverTheLighting)
{
    Scene scene;
    Material m;
    m.baseColorFactor = glm::vec4(0.5f, 0.2f, 0.05f, 1.0f);
    m.unlit = true;
    scene.materials.push_back(m);
    addNode(scene, addMesh(scene, addGrid(scene, 0.5f, 4, 1.0f), 0), glm::vec3(0.0f),
            glm::angleAxis(0.6f, glm::vec3(0.0f, 1.0f, 0.0f)), glm::vec3(1.0f));
    scene.nodes.push_back({.name = "light"});
    scene.lights.push_back({.type = LightType::Point, .node = 1, .intensity = 50.0f});
    scene.nodes.back().translation = glm::vec3(0.0f, 0.0f, 1.0f);
    finishScene(scene);

    const int expected[3] = {srgbByte(0.5f), srgbByte(0.2f), srgbByte(0.05f)};
    // gstd at 1x and 4 samples: an unlit colour needs no convergence.
    RenderRequest plain, bright;
    plain.rendererOptions = bright.rendererOptions = quickGstdOptions();
    bright.lighting.exposureEv = 3.0;
    bright.lighting.toneMap = player::ToneMap::PbrNeutral;
    const DisplayProfile profile = smallProfile(3, 64, 48);
    for (const char* renderer : {"mvr", "mvr-layered", "lfdpr", "lfdpr-paper", "gstd"}) {
        for (const RenderRequest& request : {plain, bright}) {
            const RenderedFrame f = renderFrame(renderer, scene, profile, request);
            for (const Image& view : f.views) {
                // gstd blends the square's edge pixels with the background (its 2.25-pixel
                // Gaussian over sub-views whose parallax moves the tilted edge): 4 pixels in
                // from the edge it is all square.
                const std::vector<size_t> interior = interiorPixels(view, 4);
                ASSERT_GT(interior.size(), 100u) << renderer;
                size_t wrong = 0;
                for (size_t i : interior)
                    for (int c = 0; c < 3; ++c)
                        wrong += std::abs(int(view.pixels[i * 4 + c]) - expected[c]) > 1;
                EXPECT_EQ(wrong, 0u) << renderer << ": unlit pixels off their base colour (exposure "
                                     << request.lighting.exposureEv << ")";
            }
        }
    }
}

// Mean linear red over a (2 half + 1)^2 window around the centre of `view`.
double centreLinear(const Image& view, int half)
{
    double sum = 0.0;
    int n = 0;
    const int cx = int(view.width) / 2, cy = int(view.height) / 2;
    for (int y = cy - half; y <= cy + half; ++y)
        for (int x = cx - half; x <= cx + half; ++x) {
            const float e = view.pixels[(size_t(y) * view.width + size_t(x)) * 4] / 255.0f;
            sum += e <= 0.04045f ? e / 12.92f : std::pow((e + 0.055f) / 1.055f, 2.4f);
            ++n;
        }
    return sum / n;
}

// A white rough square facing the viewer with one light on its own node at (0, 0, z).
Scene litSquare(LightType type, float z)
{
    Scene scene;
    Material m;
    m.baseColorFactor = glm::vec4(1.0f);
    m.metallicFactor = 0.0f;
    m.roughnessFactor = 1.0f;
    scene.materials.push_back(m);
    addNode(scene, addMesh(scene, addGrid(scene, 0.5f, 8, 1.0f), 0), glm::vec3(0.0f), glm::quat(1, 0, 0, 0),
            glm::vec3(1.0f));
    scene.nodes.push_back({.name = "light"});
    scene.nodes.back().translation = glm::vec3(0.0f, 0.0f, z);
    Light light;
    light.type = type;
    light.node = 1;
    light.intensity = 0.0f;
    light.outerConeAngle = 0.3f;
    light.innerConeAngle = 0.2f;
    scene.lights.push_back(light);
    finishScene(scene);
    return scene;
}

// A point light's direct light falls with the square of its distance (KHR_lights_punctual,
// range unlimited): at twice the height a quarter, measured in linear light at the centre.
TEST_F(MaterialExtensionsTest, PointLightFallsOffWithTheSquareOfTheDistance)
{
    const DisplayProfile profile = smallProfile(3, 64, 48);
    auto direct = [&](const char* renderer, float z, float intensity) {
        Scene lit = litSquare(LightType::Point, z);
        lit.lights[0].intensity = intensity;
        Scene dark = litSquare(LightType::Point, z); // the ambient term alone
        const double a = centreLinear(renderFrame(renderer, lit, profile).views[1], 2);
        const double b = centreLinear(renderFrame(renderer, dark, profile).views[1], 2);
        return a - b;
    };
    for (const char* renderer : {"mvr", "lfdpr"}) {
        const double near = direct(renderer, 0.5f, 0.45f), far = direct(renderer, 1.0f, 0.45f);
        std::printf("[ numbers  ] %s: point light direct %.4f at 0.5, %.4f at 1.0: ratio %.2f\n", renderer, near,
                    far, near / far);
        EXPECT_NEAR(near / far, 4.0, 0.3) << renderer;
    }
}

// A spot light lights inside its outer cone only; the node's -Z axis is its direction.
TEST_F(MaterialExtensionsTest, SpotLightLightsInsideItsConeAlongTheNodesMinusZ)
{
    const DisplayProfile profile = smallProfile(1, 96, 72);
    Scene lit = litSquare(LightType::Spot, 1.0f);
    lit.lights[0].intensity = 1.0f;
    const Scene dark = litSquare(LightType::Spot, 1.0f);
    for (const char* renderer : {"mvr", "lfdpr"}) {
        const Image a = renderFrame(renderer, lit, profile).views[0];
        const Image b = renderFrame(renderer, dark, profile).views[0];
        // The cone (outer half angle 0.3 rad at 1 unit: radius 0.31) is round on the square.
        double insideGain = centreLinear(a, 2) - centreLinear(b, 2);
        size_t litOutside = 0, litInside = 0;
        for (uint32_t y = 0; y < a.height; ++y)
            for (uint32_t x = 0; x < a.width; ++x) {
                const size_t i = (size_t(y) * a.width + x) * 4;
                const bool brighter = int(a.pixels[i]) > int(b.pixels[i]) + 2;
                const float dx = (float(x) + 0.5f) / float(a.width) - 0.5f, dy = (float(y) + 0.5f) / float(a.height) - 0.5f;
                const bool farOut = std::hypot(dx * 16.0f / 9.0f, dy) > 0.45f; // well outside the cone's disc (16:9 screen)
                litOutside += brighter && farOut;
                litInside += brighter;
            }
        std::printf("[ numbers  ] %s: spot gain at the centre %.3f, lit pixels %zu, far outside the cone %zu\n",
                    renderer, insideGain, litInside, litOutside);
        EXPECT_GT(insideGain, 0.1) << renderer;
        EXPECT_GT(litInside, 100u) << renderer;
        EXPECT_EQ(litOutside, 0u) << renderer;
    }
}

// A light on an animated node moves with it: the lit spot of a point light sliding along
// +x moves right in the view.
TEST_F(MaterialExtensionsTest, LightOnAnAnimatedNodeMovesWithIt)
{
    Scene scene = litSquare(LightType::Point, 0.3f);
    scene.lights[0].intensity = 0.2f;
    AnimationChannel slide;
    slide.node = 1;
    slide.path = AnimationPath::Translation;
    slide.times = {0.0f, 1.0f};
    slide.values = {glm::vec4(-0.3f, 0.0f, 0.3f, 0.0f), glm::vec4(0.3f, 0.0f, 0.3f, 0.0f)};
    scene.animations.push_back({"slide", {slide}});
    finishScene(scene);
    const DisplayProfile profile = smallProfile(1, 96, 72);
    auto brightestColumn = [&](double time) {
        RenderRequest request;
        request.time = time;
        const Image view = renderFrame("mvr", scene, profile, request).views[0];
        double best = -1.0, column = 0.0;
        for (uint32_t x = 0; x < view.width; ++x) {
            double sum = 0.0;
            for (uint32_t y = 0; y < view.height; ++y)
                sum += view.pixels[(size_t(y) * view.width + x) * 4];
            if (sum > best) {
                best = sum;
                column = x;
            }
        }
        return column;
    };
    const double start = brightestColumn(0.0), end = brightestColumn(1.0);
    std::printf("[ numbers  ] brightest column at t = 0: %.0f, at t = 1: %.0f (of 96)\n", start, end);
    EXPECT_LT(start, 40.0);
    EXPECT_GT(end, 56.0);
}

} // namespace
} // namespace lfd::test
