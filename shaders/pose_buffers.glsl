// The pose pass's buffers and uniforms (pose_vertices.comp, pose_triangles.comp), declared
// once for both; bindings, locations and structs come from pose_bindings.glsl.
#include "pose_bindings.glsl"

layout(std430, binding = POSE_SSBO_REST_POSITIONS) readonly buffer PoseRestPositions {
    float restPositions[];
};
layout(std430, binding = POSE_SSBO_REST_NORMALS) readonly buffer PoseRestNormals {
    float restNormals[];
};
layout(std430, binding = POSE_SSBO_REST_TANGENTS) readonly buffer PoseRestTangents {
    vec4 restTangents[];
};
layout(std430, binding = POSE_SSBO_INFLUENCES) readonly buffer PoseInfluences {
    PoseInfluenceGpu influences[];
};
layout(std430, binding = POSE_SSBO_MORPH_POSITIONS) readonly buffer PoseMorphPositions {
    float morphPositions[];
};
layout(std430, binding = POSE_SSBO_MORPH_NORMALS) readonly buffer PoseMorphNormals {
    float morphNormals[];
};
layout(std430, binding = POSE_SSBO_MORPH_TANGENTS) readonly buffer PoseMorphTangents {
    float morphTangents[];
};
layout(std430, binding = POSE_SSBO_DEFORMERS) readonly buffer PoseDeformers {
    PoseDeformerGpu deformers[];
};
layout(std430, binding = POSE_SSBO_JOINT_MATRICES) readonly buffer PoseJointMatrices {
    mat4 jointMatrices[];
};
layout(std430, binding = POSE_SSBO_MORPH_WEIGHTS) readonly buffer PoseMorphWeights {
    float morphWeights[];
};
layout(std430, binding = POSE_SSBO_POSITIONS) buffer PosePositions {
    float positions[];
};
layout(std430, binding = POSE_SSBO_NORMALS) writeonly buffer PoseNormals {
    float normals[];
};
layout(std430, binding = POSE_SSBO_TANGENTS) writeonly buffer PoseTangents {
    vec4 tangents[];
};
layout(std430, binding = POSE_SSBO_INDICES) readonly buffer PoseIndices {
    uint indices[];
};
layout(std430, binding = POSE_SSBO_TRIANGLE_STATS) buffer PoseTriangleStats {
    TriangleStatsGpu triangleStats[];
};

layout(location = POSE_LOC_FIRST_VERTEX) uniform uint u_firstVertex;
layout(location = POSE_LOC_VERTEX_COUNT) uniform uint u_vertexCount;
layout(location = POSE_LOC_DEFORMER_COUNT) uniform uint u_deformerCount;
layout(location = POSE_LOC_MORPH_TARGETS) uniform uint u_morphTargets;
layout(location = POSE_LOC_FLAGS) uniform uint u_flags;
layout(location = POSE_LOC_FIRST_TRIANGLE) uniform uint u_firstTriangle;
layout(location = POSE_LOC_TRIANGLE_COUNT) uniform uint u_triangleCount;
