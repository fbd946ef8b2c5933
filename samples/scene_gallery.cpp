// The "gallery" sample: a textured interior in the spirit of the paper's Gallery scene.
// Walls and floor are single big quads on purpose, so the baker's tessellation of
// oversized triangles has work to do; the painting is large so mipmapping matters.
#include "gltf_builder.h"
#include "mesh_builder.h"
#include "procedural_textures.h"
#include "sample_scenes.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>

namespace lfd::samples {

namespace {

// Room extents in metres: x in [-4, 4], y in [0, 4], z in [-3, 3]; open towards +z.
constexpr float kHalfWidth = 0.5f * float(kFloorTilesU); // 1 m tiles
constexpr float kHalfDepth = 0.5f * float(kFloorTilesV);
constexpr float kHeight = 4.0f;

struct Picture {
    const char* name;
    glm::vec3 centre;  // on the wall surface
    float yawDegrees;  // turns the local +z (the canvas front) into the wall's normal
    glm::vec2 size;    // canvas width, height in metres
    glm::vec4 uvRect;  // part of the painting shown; its aspect matches `size`
    bool gold;         // gold or dark wooden frame
};

// Four views of one painting; the side pictures show enlarged crops, so the painting's
// texel density on screen varies from picture to picture.
constexpr Picture kPictures[] = {
    {"picture_back", {0.0f, 2.1f, -kHalfDepth}, 0.0f, {3.2f, 2.0f}, {0.0f, 0.1875f, 1.0f, 0.8125f}, true},
    {"picture_left", {-kHalfWidth, 2.0f, 0.2f}, 90.0f, {1.5f, 1.5f}, {0.0f, 0.0f, 0.5f, 0.5f}, false},
    {"picture_right_a", {kHalfWidth, 2.0f, -1.4f}, -90.0f, {1.2f, 1.6f}, {0.5f, 0.4f, 0.8f, 0.8f}, true},
    {"picture_right_b", {kHalfWidth, 2.0f, 1.4f}, -90.0f, {1.2f, 1.6f}, {0.6f, 0.0f, 0.9f, 0.4f}, false},
};

constexpr float kFrameWidth = 0.08f;
constexpr float kFrameDepth = 0.06f;
constexpr float kCanvasOffset = 0.03f; // canvas sits inside the frame, off the wall

// Canvas in the local xy plane facing +z, centred on the origin, and its frame bars.
void buildPicture(const Picture& picture, MeshData& canvas, MeshData& frame)
{
    const float w = 0.5f * picture.size.x, h = 0.5f * picture.size.y, f = kFrameWidth;
    addQuad(canvas, {{-w, h, kCanvasOffset}, {2.0f * w, 0.0f, 0.0f}, {0.0f, -2.0f * h, 0.0f},
                     picture.uvRect},
            Attributes::kNormalsUvs);
    // note: the bars start 2 mm off the wall so their back faces never z-fight with it.
    const float z0 = 0.002f, z1 = kFrameDepth;
    const glm::mat4 identity(1.0f);
    addBox(frame, identity, {-w - f, h, z0}, {w + f, h + f, z1});  // top
    addBox(frame, identity, {-w - f, -h - f, z0}, {w + f, -h, z1}); // bottom
    addBox(frame, identity, {-w - f, -h, z0}, {-w, h, z1});         // left
    addBox(frame, identity, {w, -h, z0}, {w + f, h, z1});           // right
}

// The gallery's textures (written to `dir`) and materials, added to `gltf` before any
// mesh, in this order (their indices in the glTF).
struct GalleryMaterials {
    int floorMat, plasterMat, paintingMat, goldMat, woodMat, marbleMat, chromeMat;
};

GalleryMaterials addGalleryMaterials(GltfBuilder& gltf, const std::filesystem::path& dir, int textureSize)
{
    // Step 1: textures. Only the painting scales with --texture-size; the floor and
    // walls are capped so the stress test stresses one huge image.
    const int detailSize = std::min(textureSize, 1024);
    writePaintingTexture(dir / "picture.png", textureSize);
    writeFloorBaseColor(dir / "floor_basecolor.png", detailSize);
    writeFloorNormal(dir / "floor_normal.png", detailSize);
    writeFloorMetallicRoughness(dir / "floor_metallic_roughness.png", detailSize);
    writePlasterTexture(dir / "plaster_basecolor.png", detailSize);

    const int pictureTexture = gltf.addTexture("picture.png");
    const int floorColour = gltf.addTexture("floor_basecolor.png");
    const int floorNormal = gltf.addTexture("floor_normal.png");
    const int floorMr = gltf.addTexture("floor_metallic_roughness.png");
    const int plaster = gltf.addTexture("plaster_basecolor.png");

    // Step 2: materials. The floor's metallic/roughness come from its texture (the
    // factors multiply it, so they are 1).
    GalleryMaterials m{};
    MaterialSpec floorMaterial{.name = "floor_tiles", .metallic = 1.0f, .roughness = 1.0f};
    floorMaterial.baseColorTexture = floorColour;
    floorMaterial.metallicRoughnessTexture = floorMr;
    floorMaterial.normalTexture = floorNormal;
    m.floorMat = gltf.addMaterial(floorMaterial);
    m.plasterMat = gltf.addMaterial(
        {.name = "plaster", .roughness = 0.9f, .baseColorTexture = plaster});
    m.paintingMat = gltf.addMaterial(
        {.name = "painting", .roughness = 0.6f, .baseColorTexture = pictureTexture});
    m.goldMat = gltf.addMaterial({.name = "frame_gold",
                                  .baseColorFactor = {1.0f, 0.78f, 0.34f, 1.0f},
                                  .metallic = 1.0f,
                                  .roughness = 0.3f});
    m.woodMat = gltf.addMaterial({.name = "frame_dark_wood",
                                  .baseColorFactor = {0.10f, 0.06f, 0.035f, 1.0f},
                                  .roughness = 0.55f});
    m.marbleMat = gltf.addMaterial(
        {.name = "pedestal_marble", .baseColorFactor = {0.9f, 0.9f, 0.88f, 1.0f}, .roughness = 0.4f});
    m.chromeMat = gltf.addMaterial({.name = "chrome",
                                    .baseColorFactor = {0.95f, 0.95f, 0.95f, 1.0f},
                                    .metallic = 1.0f,
                                    .roughness = 0.05f});
    return m;
}

} // namespace

SceneSummary writeGalleryScene(const std::filesystem::path& dir, int textureSize)
{
    // Steps 1 and 2: textures and materials.
    GltfBuilder gltf("gallery.bin");
    const GalleryMaterials m = addGalleryMaterials(gltf, dir, textureSize);

    // Step 3: the room shell, one quad per surface, each facing into the room.
    const float W = kHalfWidth, D = kHalfDepth, H = kHeight;
    MeshData floor;
    addQuad(floor, {{-W, 0.0f, -D}, {2.0f * W, 0.0f, 0.0f}, {0.0f, 0.0f, 2.0f * D}},
            Attributes::kNormalsUvsTangents);
    MeshData walls;
    addQuad(walls, {{-W, H, -D}, {2.0f * W, 0.0f, 0.0f}, {0.0f, -H, 0.0f}}, Attributes::kNormalsUvs);
    addQuad(walls, {{-W, H, D}, {0.0f, 0.0f, -2.0f * D}, {0.0f, -H, 0.0f}}, Attributes::kNormalsUvs);
    addQuad(walls, {{W, H, -D}, {0.0f, 0.0f, 2.0f * D}, {0.0f, -H, 0.0f}}, Attributes::kNormalsUvs);

    std::vector<int> children;
    children.push_back(gltf.addNode(
        {.name = "floor", .mesh = gltf.addMesh("floor", {{&floor, m.floorMat}})}));
    children.push_back(gltf.addNode(
        {.name = "walls", .mesh = gltf.addMesh("walls", {{&walls, m.plasterMat}})}));

    // Step 4: framed pictures, each a node placed on its wall.
    for (const Picture& picture : kPictures) {
        MeshData canvas, frame;
        buildPicture(picture, canvas, frame);
        const int mesh = gltf.addMesh(
            picture.name, {{&canvas, m.paintingMat}, {&frame, picture.gold ? m.goldMat : m.woodMat}});
        children.push_back(gltf.addNode(
            {.name = picture.name,
             .mesh = mesh,
             .translation = picture.centre,
             .rotation = glm::angleAxis(glm::radians(picture.yawDegrees), glm::vec3(0, 1, 0))}));
    }

    // Step 5: a pedestal with a chrome sphere, for some depth in front of the back wall.
    MeshData pedestal, sphere;
    addBox(pedestal, glm::mat4(1.0f), {-0.3f, 0.0f, -0.3f}, {0.3f, 1.0f, 0.3f});
    addClosedSurface(sphere, glm::mat4(1.0f), 48, 24, [](float theta, float phi) {
        return superellipsoidPoint(glm::vec3(0.3f), 1.0f, 1.0f, theta, phi);
    });
    children.push_back(gltf.addNode({.name = "pedestal",
                                     .mesh = gltf.addMesh("pedestal", {{&pedestal, m.marbleMat}}),
                                     .translation = {0.0f, 0.0f, -0.8f}}));
    children.push_back(gltf.addNode({.name = "sphere",
                                     .mesh = gltf.addMesh("sphere", {{&sphere, m.chromeMat}}),
                                     .translation = {0.0f, 1.3f, -0.8f}}));

    const int root = gltf.addNode({.name = "gallery", .children = children});
    gltf.setScene("gallery", {root});
    gltf.write(dir / "gallery.gltf");
    return {"gallery", gltf.storedTriangles(), gltf.drawnTriangles(), 5};
}

} // namespace lfd::samples
