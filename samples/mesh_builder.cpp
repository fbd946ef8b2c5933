#include "mesh_builder.h"

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <stdexcept>

namespace lfd::samples {

namespace {

// Appends `part` transformed by objectFromLocal: positions by the matrix, normals by its
// inverse transpose, tangent directions by the upper 3x3 (handedness kept: no mirrors).
void appendTransformed(MeshData& mesh, const MeshData& part, const glm::mat4& objectFromLocal)
{
    const glm::mat3 linear(objectFromLocal);
    const glm::mat3 normalFromLocal = glm::transpose(glm::inverse(linear));
    MeshData moved;
    moved.indices = part.indices;
    moved.uvs = part.uvs;
    for (const glm::vec3& p : part.positions)
        moved.positions.push_back(glm::vec3(objectFromLocal * glm::vec4(p, 1.0f)));
    for (const glm::vec3& n : part.normals)
        moved.normals.push_back(glm::normalize(normalFromLocal * n));
    for (const glm::vec4& t : part.tangents)
        moved.tangents.push_back(glm::vec4(glm::normalize(linear * glm::vec3(t)), t.w));
    append(mesh, moved);
}

// Smooth normals: area-weighted sum of the incident face normals (the cross product's
// length is twice the area, so summing unnormalised cross products weights by area).
void computeSmoothNormals(MeshData& mesh, size_t firstVertex, size_t firstIndex)
{
    mesh.normals.resize(mesh.positions.size(), glm::vec3(0.0f));
    for (size_t v = firstVertex; v < mesh.positions.size(); ++v)
        mesh.normals[v] = glm::vec3(0.0f);
    for (size_t i = firstIndex; i + 2 < mesh.indices.size(); i += 3) {
        const uint32_t a = mesh.indices[i], b = mesh.indices[i + 1], c = mesh.indices[i + 2];
        const glm::vec3 faceNormal = glm::cross(mesh.positions[b] - mesh.positions[a],
                                                mesh.positions[c] - mesh.positions[a]);
        mesh.normals[a] += faceNormal;
        mesh.normals[b] += faceNormal;
        mesh.normals[c] += faceNormal;
    }
    for (size_t v = firstVertex; v < mesh.positions.size(); ++v) {
        const float length = glm::length(mesh.normals[v]);
        mesh.normals[v] = length > 0.0f ? mesh.normals[v] / length : glm::vec3(0.0f, 1.0f, 0.0f);
    }
}

float signedPow(float value, float exponent)
{
    return std::copysign(std::pow(std::abs(value), exponent), value);
}

} // namespace

void append(MeshData& mesh, const MeshData& part)
{
    if (!mesh.positions.empty() && (mesh.uvs.empty() != part.uvs.empty() ||
                                    mesh.tangents.empty() != part.tangents.empty()))
        throw std::logic_error("append: parts with different vertex attributes");
    const auto base = static_cast<uint32_t>(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), part.positions.begin(), part.positions.end());
    mesh.normals.insert(mesh.normals.end(), part.normals.begin(), part.normals.end());
    mesh.uvs.insert(mesh.uvs.end(), part.uvs.begin(), part.uvs.end());
    mesh.tangents.insert(mesh.tangents.end(), part.tangents.begin(), part.tangents.end());
    for (uint32_t index : part.indices)
        mesh.indices.push_back(base + index);
}

void addQuad(MeshData& mesh, const QuadSpec& quad, Attributes attributes)
{
    // Corners p00 (top left), p10 (top right), p11, p01 (bottom left); the front is
    // cross(down, right), so (p00, p01, p11) and (p00, p11, p10) are counter-clockwise.
    const glm::vec3 normal = glm::normalize(glm::cross(quad.down, quad.right));
    const glm::vec3 corners[4] = {quad.topLeft, quad.topLeft + quad.right,
                                  quad.topLeft + quad.right + quad.down,
                                  quad.topLeft + quad.down};
    const glm::vec4 r = quad.uvRect;
    const glm::vec2 uvs[4] = {{r.x, r.y}, {r.z, r.y}, {r.z, r.w}, {r.x, r.w}};

    MeshData part;
    for (int c = 0; c < 4; ++c) {
        part.positions.push_back(corners[c]);
        part.normals.push_back(normal);
        if (attributes != Attributes::kNormals)
            part.uvs.push_back(uvs[c]);
        // note: glTF's bitangent is cross(normal, tangent) * w and points to image-up
        // (decreasing v); with tangent = +u that is -down, so w = +1 for an upright quad.
        if (attributes == Attributes::kNormalsUvsTangents)
            part.tangents.push_back(glm::vec4(glm::normalize(quad.right), 1.0f));
    }
    part.indices = {0, 3, 2, 0, 2, 1};
    append(mesh, part);
}

void addBox(MeshData& mesh, const glm::mat4& objectFromLocal, glm::vec3 lo, glm::vec3 hi,
            Attributes attributes)
{
    const glm::vec3 e = hi - lo;
    // One quad per face, each read upright from outside (see QuadSpec).
    const QuadSpec faces[6] = {
        {{hi.x, hi.y, hi.z}, {0, 0, -e.z}, {0, -e.y, 0}}, // +x
        {{lo.x, hi.y, lo.z}, {0, 0, e.z}, {0, -e.y, 0}},  // -x
        {{lo.x, hi.y, lo.z}, {e.x, 0, 0}, {0, 0, e.z}},   // +y
        {{lo.x, lo.y, hi.z}, {e.x, 0, 0}, {0, 0, -e.z}},  // -y
        {{lo.x, hi.y, hi.z}, {e.x, 0, 0}, {0, -e.y, 0}},  // +z
        {{hi.x, hi.y, lo.z}, {-e.x, 0, 0}, {0, -e.y, 0}}, // -z
    };
    MeshData box;
    for (const QuadSpec& face : faces)
        addQuad(box, face, attributes);
    appendTransformed(mesh, box, objectFromLocal);
}

glm::vec3 superellipsoidPoint(glm::vec3 radii, float eLatitude, float eLongitude, float theta,
                              float phi)
{
    // Barr's superquadric, oriented like addClosedSurface's reference sphere.
    const float cosPhi = signedPow(std::cos(phi), eLatitude);
    return {radii.x * cosPhi * signedPow(std::cos(theta), eLongitude),
            radii.y * signedPow(std::sin(phi), eLatitude),
            -radii.z * cosPhi * signedPow(std::sin(theta), eLongitude)};
}

void addClosedSurface(MeshData& mesh, const glm::mat4& objectFromLocal, int segments,
                      int rings, const std::function<glm::vec3(float theta, float phi)>& surface)
{
    if (segments < 3 || rings < 2)
        throw std::logic_error("addClosedSurface: too few segments or rings");
    const float pi = glm::pi<float>();
    MeshData part;
    // Vertex layout: south pole, (rings - 1) rings of `segments` vertices, north pole.
    part.positions.push_back(surface(0.0f, -0.5f * pi));
    for (int r = 1; r < rings; ++r) {
        const float phi = -0.5f * pi + pi * float(r) / float(rings);
        for (int s = 0; s < segments; ++s)
            part.positions.push_back(surface(2.0f * pi * float(s) / float(segments), phi));
    }
    part.positions.push_back(surface(0.0f, 0.5f * pi));
    const auto northPole = static_cast<uint32_t>(part.positions.size() - 1);
    auto ringVertex = [&](int r, int s) -> uint32_t {
        if (r == 0)
            return 0;
        if (r == rings)
            return northPole;
        return static_cast<uint32_t>(1 + (r - 1) * segments + (s % segments));
    };

    // With theta growing along +(-z) at theta = 0 and phi growing upwards,
    // cross(dP/dtheta, dP/dphi) points outwards, so (a, b, c) / (a, c, d) below are
    // counter-clockwise from outside. The degenerate triangle at each pole is dropped.
    for (int r = 0; r < rings; ++r) {
        for (int s = 0; s < segments; ++s) {
            const uint32_t a = ringVertex(r, s), b = ringVertex(r, s + 1);
            const uint32_t c = ringVertex(r + 1, s + 1), d = ringVertex(r + 1, s);
            if (r != 0)
                part.indices.insert(part.indices.end(), {a, b, c});
            if (r != rings - 1)
                part.indices.insert(part.indices.end(), {a, c, d});
        }
    }
    MeshData moved;
    appendTransformed(moved, part, objectFromLocal);
    computeSmoothNormals(moved, 0, 0);
    append(mesh, moved);
}

void addTorus(MeshData& mesh, const glm::mat4& objectFromLocal, float major, float minor,
              float minorZ, int segments, int sides)
{
    const float twoPi = 2.0f * glm::pi<float>();
    MeshData part;
    for (int i = 0; i < sides; ++i) {
        const float psi = twoPi * float(i) / float(sides);
        for (int j = 0; j < segments; ++j) {
            const float theta = twoPi * float(j) / float(segments);
            const float ring = major + minor * std::cos(psi);
            part.positions.push_back(
                {ring * std::cos(theta), ring * std::sin(theta), minorZ * std::sin(psi)});
        }
    }
    // Both directions wrap; cross(dP/dtheta, dP/dpsi) points away from the tube's axis.
    auto at = [&](int i, int j) {
        return static_cast<uint32_t>((i % sides) * segments + (j % segments));
    };
    for (int i = 0; i < sides; ++i) {
        for (int j = 0; j < segments; ++j) {
            const uint32_t a = at(i, j), b = at(i, j + 1), c = at(i + 1, j + 1), d = at(i + 1, j);
            part.indices.insert(part.indices.end(), {a, b, c, a, c, d});
        }
    }
    MeshData moved;
    appendTransformed(moved, part, objectFromLocal);
    computeSmoothNormals(moved, 0, 0);
    append(mesh, moved);
}

void addCylinder(MeshData& mesh, const glm::mat4& objectFromLocal, float radius, float z0,
                 float z1, int segments)
{
    const float twoPi = 2.0f * glm::pi<float>();
    MeshData part;
    auto rim = [&](int j, float z) {
        const float theta = twoPi * float(j % segments) / float(segments);
        return glm::vec3(radius * std::cos(theta), radius * std::sin(theta), z);
    };
    // Side: two rings with radial normals; cross(dP/dtheta, dP/dz) points outwards.
    for (int j = 0; j < segments; ++j) {
        for (float z : {z0, z1}) {
            const glm::vec3 p = rim(j, z);
            part.positions.push_back(p);
            part.normals.push_back(glm::normalize(glm::vec3(p.x, p.y, 0.0f)));
        }
    }
    for (int j = 0; j < segments; ++j) {
        const uint32_t a = 2 * j, d = 2 * j + 1;
        const uint32_t b = 2 * ((j + 1) % segments), c = b + 1;
        part.indices.insert(part.indices.end(), {a, b, c, a, c, d});
    }
    // Caps: a fan around a centre vertex, counter-clockwise seen from outside.
    for (float z : {z0, z1}) {
        const bool top = z == z1;
        const glm::vec3 normal(0.0f, 0.0f, top ? 1.0f : -1.0f);
        const auto centre = static_cast<uint32_t>(part.positions.size());
        part.positions.push_back({0.0f, 0.0f, z});
        part.normals.push_back(normal);
        for (int j = 0; j < segments; ++j) {
            part.positions.push_back(rim(j, z));
            part.normals.push_back(normal);
        }
        for (int j = 0; j < segments; ++j) {
            const uint32_t p = centre + 1 + j, q = centre + 1 + (j + 1) % segments;
            if (top)
                part.indices.insert(part.indices.end(), {centre, p, q});
            else
                part.indices.insert(part.indices.end(), {centre, q, p});
        }
    }
    appendTransformed(mesh, part, objectFromLocal);
}

} // namespace lfd::samples
