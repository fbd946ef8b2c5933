// The pose pass's interface (pose_vertices.comp, pose_triangles.comp; player/scene/
// scene_poser.cpp): binding points, uniform locations, flags, workgroup size and GPU
// structs. The only definition: the build generates pose_bindings_gpu.h from it, and
// tests/player/gpu_layout_test.cpp checks it against what the driver reports.
#define POSE_LOCAL_SIZE 64

// Shader storage buffers of pose_vertices.comp: the rest pose (as baked), skin
// influences, morph deltas (vertex-major, POSE_LOC_MORPH_TARGETS per vertex), the
// deformers, this frame's joint matrices and morph weights, and the vertex streams every
// renderer reads (LFD_ATTRIB_*), written in place.
#define POSE_SSBO_REST_POSITIONS 0  // float[3n]
#define POSE_SSBO_REST_NORMALS 1    // float[3n]
#define POSE_SSBO_REST_TANGENTS 2   // vec4[n]
#define POSE_SSBO_INFLUENCES 3      // PoseInfluenceGpu[n]
#define POSE_SSBO_MORPH_POSITIONS 4 // float[3nk]
#define POSE_SSBO_MORPH_NORMALS 5   // float[3nk]
#define POSE_SSBO_MORPH_TANGENTS 6  // float[3nk]
#define POSE_SSBO_DEFORMERS 7       // PoseDeformerGpu[], by firstVertex
#define POSE_SSBO_JOINT_MATRICES 8  // mat4[]: nodeFromScene * sceneFromJoint * inverseBind
#define POSE_SSBO_MORPH_WEIGHTS 9   // float[deformers * k]
#define POSE_SSBO_POSITIONS 10      // float[3n], the position stream
#define POSE_SSBO_NORMALS 11        // float[3n], the normal stream
#define POSE_SSBO_TANGENTS 12       // vec4[n], the tangent stream
// pose_triangles.comp: the index buffer and the per-triangle statistics.
#define POSE_SSBO_INDICES 13        // uint[]
#define POSE_SSBO_TRIANGLE_STATS 14 // TriangleStatsGpu[] (= lfd::TriangleStats)

#define POSE_LOC_FIRST_VERTEX 0     // uint: first vertex of the dispatch
#define POSE_LOC_VERTEX_COUNT 1     // uint: vertices of the dispatch
#define POSE_LOC_DEFORMER_COUNT 2   // uint
#define POSE_LOC_MORPH_TARGETS 3    // uint: morph target slots per vertex
#define POSE_LOC_FLAGS 4            // uint: POSE_FLAG_*
#define POSE_LOC_FIRST_TRIANGLE 5   // uint: pose_triangles.comp
#define POSE_LOC_TRIANGLE_COUNT 6   // uint

// POSE_LOC_FLAGS: which optional streams the scene has.
#define POSE_FLAG_NORMALS 1
#define POSE_FLAG_TANGENTS 2
#define POSE_FLAG_MORPH_NORMALS 4
#define POSE_FLAG_MORPH_TANGENTS 8

// lfd::TriangleStats.flags bit of a zero-area triangle (baker/triangle_stats.cpp).
#define POSE_TRIANGLE_DEGENERATE 2

// One vertex's four joint influences (indices into its deformer's joints).
struct PoseInfluenceGpu {
    uvec4 joints;
    vec4 weights;
};

// One deformer (lfd::Deformer): its vertex range, where its joint matrices start.
struct PoseDeformerGpu {
    uint firstVertex;
    uint vertexCount;
    uint firstJoint;
    uint skinned; // 0: morph targets only
};

// lfd::TriangleStats: TriangleStatsGpu, the struct the scene's readers use.
#include "triangle_stats_bindings.glsl"
