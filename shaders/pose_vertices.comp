#version 450
// The pose pass (glTF 2.0 sections 3.7.2.2 and 3.7.3; lfd::poseVertices in
// formats/src/scene_pose.cpp is its CPU reference and follows the same steps): each
// deformed vertex starts from its rest pose, adds its weighted morph deltas, then is
// skinned by the weighted sum of its four joint matrices (linear blend skinning); normals
// by that matrix's cofactor (the inverse transpose up to a positive factor), tangents by
// the matrix, both renormalised. The results overwrite the vertex streams every renderer
// reads, in the deformer node's object space, so they draw it as any other mesh.
// One invocation per vertex of [u_firstVertex, + u_vertexCount).
#include "pose_buffers.glsl"

layout(local_size_x = POSE_LOCAL_SIZE) in;

vec3 load3(uint i, uint which)
{
    if (which == 0u)
        return vec3(restPositions[3u * i], restPositions[3u * i + 1u], restPositions[3u * i + 2u]);
    if (which == 1u)
        return vec3(restNormals[3u * i], restNormals[3u * i + 1u], restNormals[3u * i + 2u]);
    if (which == 2u)
        return vec3(morphPositions[3u * i], morphPositions[3u * i + 1u], morphPositions[3u * i + 2u]);
    if (which == 3u)
        return vec3(morphNormals[3u * i], morphNormals[3u * i + 1u], morphNormals[3u * i + 2u]);
    return vec3(morphTangents[3u * i], morphTangents[3u * i + 1u], morphTangents[3u * i + 2u]);
}

// The deformer whose range holds vertex v (deformers are sorted by firstVertex), or
// u_deformerCount when none does.
uint deformerOf(uint v)
{
    uint lo = 0u, hi = u_deformerCount;
    while (hi - lo > 1u) {
        const uint mid = (lo + hi) / 2u;
        if (deformers[mid].firstVertex <= v)
            lo = mid;
        else
            hi = mid;
    }
    const PoseDeformerGpu d = deformers[lo];
    return v >= d.firstVertex && v - d.firstVertex < d.vertexCount ? lo : u_deformerCount;
}

mat4 skinMatrix(uint v, PoseDeformerGpu d)
{
    if (d.skinned == 0u)
        return mat4(1.0);
    const PoseInfluenceGpu inf = influences[v];
    mat4 m = mat4(0.0);
    for (int k = 0; k < 4; ++k)
        if (inf.weights[k] != 0.0)
            m += inf.weights[k] * jointMatrices[d.firstJoint + inf.joints[k]];
    return m;
}

vec3 normalizedOr(vec3 v, vec3 fallback)
{
    const float len = length(v);
    return len > 1e-20 ? v / len : fallback;
}

void main()
{
    if (gl_GlobalInvocationID.x >= u_vertexCount)
        return;
    const uint v = u_firstVertex + gl_GlobalInvocationID.x;
    const uint di = deformerOf(v);
    if (di == u_deformerCount)
        return;
    const PoseDeformerGpu d = deformers[di];
    const uint k = u_morphTargets;
    vec3 p = load3(v, 0u);
    vec3 n = (u_flags & POSE_FLAG_NORMALS) != 0u ? load3(v, 1u) : vec3(0.0);
    const vec4 restTangent = (u_flags & POSE_FLAG_TANGENTS) != 0u ? restTangents[v] : vec4(0.0);
    vec3 t = restTangent.xyz;
    for (uint i = 0u; i < k; ++i) {
        const float w = morphWeights[di * k + i];
        if (w == 0.0)
            continue;
        p += w * load3(v * k + i, 2u);
        if ((u_flags & POSE_FLAG_MORPH_NORMALS) != 0u)
            n += w * load3(v * k + i, 3u);
        if ((u_flags & POSE_FLAG_MORPH_TANGENTS) != 0u)
            t += w * load3(v * k + i, 4u);
    }
    const mat4 m = skinMatrix(v, d);
    const vec3 q = (m * vec4(p, 1.0)).xyz;
    positions[3u * v] = q.x;
    positions[3u * v + 1u] = q.y;
    positions[3u * v + 2u] = q.z;
    const mat3 l = mat3(m);
    if ((u_flags & POSE_FLAG_NORMALS) != 0u) {
        mat3 cofactor = mat3(cross(l[1], l[2]), cross(l[2], l[0]), cross(l[0], l[1]));
        if (determinant(l) < 0.0)
            cofactor = -cofactor;
        const vec3 nn = normalizedOr(cofactor * n, load3(v, 1u));
        normals[3u * v] = nn.x;
        normals[3u * v + 1u] = nn.y;
        normals[3u * v + 2u] = nn.z;
    }
    if ((u_flags & POSE_FLAG_TANGENTS) != 0u)
        tangents[v] = vec4(normalizedOr(l * t, restTangent.xyz), restTangent.w);
}
