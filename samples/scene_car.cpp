// The "car" and "room" samples: an untextured object with depth complexity in the
// spirit of the paper's Car scene (seats, dashboard and engine hidden inside a closed
// body), four instances of one wheel mesh with a spin animation, and a grid of such
// cars that instances every mesh (a cheap file with a paper-scale triangle count).
#include "gltf_builder.h"
#include "mesh_builder.h"
#include "sample_scenes.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace lfd::samples {

namespace {

// Car dimensions (metres): 4.2 long along +x (front at +x), 1.8 wide, ~1.6 tall.
constexpr glm::vec3 kBodyRadii{2.1f, 0.42f, 0.9f};
constexpr float kBodyCentreY = 0.72f;
constexpr float kWheelRadius = 0.36f;
constexpr glm::vec3 kWheelPositions[4] = {
    {1.35f, kWheelRadius, 0.9f}, {1.35f, kWheelRadius, -0.9f},
    {-1.35f, kWheelRadius, 0.9f}, {-1.35f, kWheelRadius, -0.9f}};
constexpr float kSpinSeconds = 2.0f;

struct CarMeshes {
    int body, cabin, interior, engine, wheel, headlight, taillight;
};

glm::mat4 translate(glm::vec3 t) { return glm::translate(glm::mat4(1.0f), t); }

// Closed boxy body: a superellipsoid whose upper half drops towards the front (hood).
// The deformation only moves points vertically and is monotone in the latitude, so the
// surface stays closed and free of self-intersections.
glm::vec3 bodyPoint(float theta, float phi)
{
    glm::vec3 p = superellipsoidPoint(kBodyRadii, 0.3f, 0.25f, theta, phi);
    const float upper = std::max(0.0f, p.y / kBodyRadii.y);
    p.y -= 0.18f * glm::smoothstep(0.2f, 1.0f, p.x / kBodyRadii.x) * upper;
    return p;
}

// Greenhouse: narrower towards the roof.
glm::vec3 cabinPoint(float theta, float phi)
{
    glm::vec3 p = superellipsoidPoint({1.15f, 0.42f, 0.78f}, 0.45f, 0.35f, theta, phi);
    const float upper = std::max(0.0f, p.y / 0.42f);
    p.x *= 1.0f - 0.15f * upper;
    p.z *= 1.0f - 0.2f * upper;
    return p;
}

// A seat: cushion plus a backrest leaning back 15 degrees; `at` is the cushion's centre
// on the floor plane of the interior, facing +x.
void addSeat(MeshData& mesh, glm::vec3 at)
{
    addBox(mesh, translate(at), {-0.25f, 0.0f, -0.24f}, {0.25f, 0.12f, 0.24f});
    const glm::mat4 backFromLocal =
        glm::rotate(translate(at + glm::vec3(-0.25f, 0.1f, 0.0f)), glm::radians(15.0f),
                    glm::vec3(0.0f, 0.0f, 1.0f));
    addBox(mesh, backFromLocal, {-0.1f, 0.0f, -0.24f}, {0.0f, 0.55f, 0.24f});
}

// The car's materials, told apart by factors only (no textures anywhere); added before
// any mesh, in this order (their indices in the glTF).
struct CarMaterials {
    int paint, glass, leather, engineMetal, rubber, rimMetal, boltMetal, headlightMat, taillightMat;
};

CarMaterials addCarMaterials(GltfBuilder& gltf)
{
    CarMaterials m{};
    m.paint = gltf.addMaterial({.name = "car_paint",
                                .baseColorFactor = {0.75f, 0.05f, 0.06f, 1.0f},
                                .metallic = 0.5f,
                                .roughness = 0.3f});
    m.glass = gltf.addMaterial({.name = "tinted_glass",
                                .baseColorFactor = {0.05f, 0.08f, 0.12f, 1.0f},
                                .roughness = 0.05f});
    m.leather = gltf.addMaterial(
        {.name = "leather", .baseColorFactor = {0.35f, 0.20f, 0.10f, 1.0f}, .roughness = 0.7f});
    m.engineMetal = gltf.addMaterial({.name = "engine_metal",
                                      .baseColorFactor = {0.30f, 0.30f, 0.32f, 1.0f},
                                      .metallic = 0.9f,
                                      .roughness = 0.5f});
    m.rubber = gltf.addMaterial(
        {.name = "tyre_rubber", .baseColorFactor = {0.03f, 0.03f, 0.03f, 1.0f}, .roughness = 0.9f});
    m.rimMetal = gltf.addMaterial({.name = "rim_metal",
                                   .baseColorFactor = {0.80f, 0.80f, 0.82f, 1.0f},
                                   .metallic = 1.0f,
                                   .roughness = 0.2f});
    m.boltMetal = gltf.addMaterial({.name = "bolt_metal",
                                    .baseColorFactor = {0.2f, 0.2f, 0.2f, 1.0f},
                                    .metallic = 1.0f,
                                    .roughness = 0.4f});
    m.headlightMat = gltf.addMaterial({.name = "headlight",
                                       .baseColorFactor = {1.0f, 1.0f, 0.9f, 1.0f},
                                       .roughness = 0.1f,
                                       .emissive = {1.0f, 0.95f, 0.8f}});
    m.taillightMat = gltf.addMaterial({.name = "taillight",
                                       .baseColorFactor = {0.8f, 0.02f, 0.02f, 1.0f},
                                       .roughness = 0.2f,
                                       .emissive = {0.6f, 0.0f, 0.0f}});
    return m;
}

CarMeshes addCarMeshes(GltfBuilder& gltf)
{
    // Step 1: materials.
    const CarMaterials m = addCarMaterials(gltf);
    CarMeshes meshes{};
    // Step 2: the visible shell: body and cabin, both closed (watertight) meshes.
    MeshData body, cabin;
    addClosedSurface(body, translate({0.0f, kBodyCentreY, 0.0f}), 48, 24, bodyPoint);
    addClosedSurface(cabin, translate({-0.25f, 1.18f, 0.0f}), 32, 16, cabinPoint);
    meshes.body = gltf.addMesh("body", {{&body, m.paint}});
    meshes.cabin = gltf.addMesh("cabin", {{&cabin, m.glass}});

    // Step 3: occluded interior: four seats, dashboard, steering wheel.
    MeshData interior;
    for (float x : {0.15f, -0.75f})
        for (float z : {0.38f, -0.38f})
            addSeat(interior, {x, 0.45f, z});
    addBox(interior, glm::mat4(1.0f), {0.55f, 0.8f, -0.7f}, {0.8f, 1.05f, 0.7f}); // dashboard
    addTorus(interior,
             glm::rotate(translate({0.45f, 1.0f, 0.38f}), glm::radians(-70.0f), glm::vec3(0, 0, 1)) *
                 glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(0, 1, 0)),
             0.17f, 0.02f, 0.02f, 24, 8);
    meshes.interior = gltf.addMesh("interior", {{&interior, m.leather}});

    // Step 4: occluded engine under the hood: block, head, six cylinders' caps, flywheel.
    MeshData engine;
    addBox(engine, glm::mat4(1.0f), {0.95f, 0.42f, -0.35f}, {1.75f, 0.80f, 0.35f});
    addBox(engine, glm::mat4(1.0f), {1.0f, 0.80f, -0.28f}, {1.7f, 0.88f, 0.28f});
    for (int c = 0; c < 6; ++c) {
        const glm::mat4 upright = glm::rotate(translate({1.07f + 0.112f * float(c), 0.88f, 0.0f}),
                                              glm::radians(-90.0f), glm::vec3(1, 0, 0));
        addCylinder(engine, upright, 0.04f, 0.0f, 0.03f, 12);
    }
    addCylinder(engine,
                glm::rotate(translate({0.95f, 0.6f, 0.0f}), glm::radians(-90.0f), glm::vec3(0, 1, 0)),
                0.17f, 0.0f, 0.06f, 24);
    meshes.engine = gltf.addMesh("engine", {{&engine, m.engineMetal}});

    // Step 5: one wheel mesh (axle along local z, symmetric so no node needs a mirror):
    // tyre, rim and five bolts on each face, which make the spin visible.
    MeshData tyre, rim, bolts;
    addTorus(tyre, glm::mat4(1.0f), 0.26f, 0.10f, 0.12f, 32, 10);
    addCylinder(rim, glm::mat4(1.0f), 0.19f, -0.1f, 0.1f, 32);
    for (int b = 0; b < 5; ++b) {
        const float angle = 2.0f * glm::pi<float>() * float(b) / 5.0f;
        const glm::vec3 at(0.1f * std::cos(angle), 0.1f * std::sin(angle), 0.0f);
        addCylinder(bolts, translate(at), 0.018f, 0.1f, 0.12f, 8);
        addCylinder(bolts, translate(at), 0.018f, -0.12f, -0.1f, 8);
    }
    meshes.wheel = gltf.addMesh("wheel", {{&tyre, m.rubber}, {&rim, m.rimMetal}, {&bolts, m.boltMetal}});

    // Step 6: lights, each mesh used by two nodes.
    MeshData headlight, taillight;
    addClosedSurface(headlight, glm::mat4(1.0f), 16, 8, [](float theta, float phi) {
        return superellipsoidPoint({0.06f, 0.07f, 0.15f}, 1.0f, 1.0f, theta, phi);
    });
    addBox(taillight, glm::mat4(1.0f), {-0.02f, -0.04f, -0.15f}, {0.02f, 0.04f, 0.15f});
    meshes.headlight = gltf.addMesh("headlight", {{&headlight, m.headlightMat}});
    meshes.taillight = gltf.addMesh("taillight", {{&taillight, m.taillightMat}});
    return meshes;
}

// One car's node tree; the wheel nodes are appended to `wheelNodes` for the animation.
int addCarNodes(GltfBuilder& gltf, const CarMeshes& meshes, const std::string& name,
                glm::vec3 translation, float yawDegrees, std::vector<int>& wheelNodes)
{
    std::vector<int> children = {
        gltf.addNode({.name = name + "_body", .mesh = meshes.body}),
        gltf.addNode({.name = name + "_cabin", .mesh = meshes.cabin}),
        gltf.addNode({.name = name + "_interior", .mesh = meshes.interior}),
        gltf.addNode({.name = name + "_engine", .mesh = meshes.engine}),
    };
    for (int w = 0; w < 4; ++w) {
        const int node = gltf.addNode({.name = name + "_wheel_" + std::to_string(w),
                                       .mesh = meshes.wheel,
                                       .translation = kWheelPositions[w]});
        children.push_back(node);
        wheelNodes.push_back(node);
    }
    for (float z : {0.55f, -0.55f}) {
        const std::string side = z > 0.0f ? "_left" : "_right";
        children.push_back(gltf.addNode({.name = name + "_headlight" + side,
                                         .mesh = meshes.headlight,
                                         .translation = {2.09f, 0.82f, z}}));
        children.push_back(gltf.addNode({.name = name + "_taillight" + side,
                                         .mesh = meshes.taillight,
                                         .translation = {-2.1f, 0.9f, z}}));
    }
    return gltf.addNode(
        {.name = name,
         .translation = translation,
         .rotation = glm::angleAxis(glm::radians(yawDegrees), glm::vec3(0, 1, 0)),
         .children = children});
}

// Rolling forward (+x) turns the wheels by a negative angle about +z: one turn in
// kSpinSeconds, keyed every quarter turn so LINEAR (slerp) interpolation between
// neighbouring keys always takes the intended 90-degree path.
void addWheelSpin(GltfBuilder& gltf, const std::vector<int>& wheelNodes)
{
    std::vector<float> times;
    std::vector<glm::quat> rotations;
    for (int k = 0; k <= 4; ++k) {
        times.push_back(kSpinSeconds * float(k) / 4.0f);
        rotations.push_back(glm::angleAxis(-0.5f * glm::pi<float>() * float(k), glm::vec3(0, 0, 1)));
    }
    gltf.addRotationAnimation("wheel_spin", wheelNodes, times, rotations);
}

} // namespace

SceneSummary writeCarScene(const std::filesystem::path& dir)
{
    GltfBuilder gltf("car.bin");
    const CarMeshes meshes = addCarMeshes(gltf);
    std::vector<int> wheelNodes;
    const int car = addCarNodes(gltf, meshes, "car", glm::vec3(0.0f), 0.0f, wheelNodes);
    addWheelSpin(gltf, wheelNodes);
    gltf.setScene("car", {car});
    gltf.write(dir / "car.gltf");
    return {"car", gltf.storedTriangles(), gltf.drawnTriangles(), 0};
}

SceneSummary writeRoomScene(const std::filesystem::path& dir, int instances)
{
    GltfBuilder gltf("room.bin");
    const CarMeshes meshes = addCarMeshes(gltf);

    // Step 1: a near-square grid of cars, 6 m apart along x and 4.5 m along z, centred
    // on the origin; alternate rows face opposite ways, with a little yaw jitter.
    const int columns = std::max(1, int(std::ceil(std::sqrt(double(instances)))));
    const int rows = (instances + columns - 1) / columns;
    const float pitchX = 6.0f, pitchZ = 4.5f;
    std::vector<int> children, wheelNodes;
    for (int i = 0; i < instances; ++i) {
        const int row = i / columns, column = i % columns;
        const glm::vec3 at(pitchX * (float(column) - 0.5f * float(columns - 1)), 0.0f,
                           pitchZ * (float(row) - 0.5f * float(rows - 1)));
        const float yaw = (row % 2 ? 180.0f : 0.0f) + float((i * 23) % 31 - 15);
        children.push_back(
            addCarNodes(gltf, meshes, "car_" + std::to_string(i), at, yaw, wheelNodes));
    }

    // Step 2: one big floor quad (two triangles) under the grid with a 4 m margin.
    const float halfX = 0.5f * pitchX * float(columns) + 4.0f;
    const float halfZ = 0.5f * pitchZ * float(rows) + 4.0f;
    MeshData floor;
    addQuad(floor, {{-halfX, 0.0f, -halfZ}, {2.0f * halfX, 0.0f, 0.0f}, {0.0f, 0.0f, 2.0f * halfZ}},
            Attributes::kNormals);
    const int concrete = gltf.addMaterial(
        {.name = "concrete", .baseColorFactor = {0.5f, 0.5f, 0.48f, 1.0f}, .roughness = 0.8f});
    children.insert(children.begin(),
                    gltf.addNode({.name = "floor", .mesh = gltf.addMesh("floor", {{&floor, concrete}})}));

    addWheelSpin(gltf, wheelNodes);
    const int root = gltf.addNode({.name = "room", .children = children});
    gltf.setScene("room", {root});
    gltf.write(dir / "room.gltf");
    return {"room", gltf.storedTriangles(), gltf.drawnTriangles(), 0};
}

} // namespace lfd::samples
