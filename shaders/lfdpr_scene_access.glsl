// The scene's geometry as compute shaders of the visibility pipeline read it: the index
// buffer and vertex streams bound as storage buffers (the same buffers the raster
// renderers draw from), the draw table and the triangle records. A point holds only its
// record and sampling cell; everything else about it is derived from here.
// Needs scene_bindings.glsl and lfdpr_bindings.glsl first.

layout(std430, binding = LFDPR_SSBO_INDICES) readonly buffer SceneIndices {
    uint sceneIndices[];
};
layout(std430, binding = LFDPR_SSBO_POSITIONS) readonly buffer ScenePositions {
    float scenePositions[];
};
layout(std430, binding = LFDPR_SSBO_DRAWS) readonly buffer Draws {
    LfdprDrawGpu draws[];
};

// Vertex indices of triangle `primitive` of draw `draw`.
uvec3 lfdTriangleVertices(LfdprDrawGpu draw, uint primitive)
{
    uint first = 3u * (draw.firstTriangle + primitive);
    return uvec3(sceneIndices[first], sceneIndices[first + 1u], sceneIndices[first + 2u]);
}

vec3 lfdObjectPosition(uint vertex)
{
    return vec3(scenePositions[3u * vertex], scenePositions[3u * vertex + 1u], scenePositions[3u * vertex + 2u]);
}

// Scene-space positions of a triangle (the node transform applied as the raster vertex
// shaders apply it).
void lfdTrianglePositions(LfdprDrawGpu draw, uvec3 vertices, out vec3 p0, out vec3 p1, out vec3 p2)
{
    mat4 sceneFromObject = nodes[draw.node].sceneFromObject;
    p0 = (sceneFromObject * vec4(lfdObjectPosition(vertices.x), 1.0)).xyz;
    p1 = (sceneFromObject * vec4(lfdObjectPosition(vertices.y), 1.0)).xyz;
    p2 = (sceneFromObject * vec4(lfdObjectPosition(vertices.z), 1.0)).xyz;
}

// The sampling frame of a recorded triangle, rebuilt exactly as point generation built
// it (lfdpr_triangle_setup.glsl, steps 6-7, with the final spacings): sampling
// coordinates of the vertices and the scene point of sampling coordinates (0, 0).
struct LfdSamplingFrame {
    LfdFrame frame;
    vec2 spacing;
    vec3 origin;
};

LfdSamplingFrame lfdRecordFrame(vec3 p0, vec3 p1, vec3 p2, vec2 spacing)
{
    LfdSamplingFrame f;
    vec3 faceNormal = normalize(cross(p1 - p0, p2 - p0));
    f.frame = lfdAlignFrame(faceNormal, u_lfd.displayX.xyz, u_lfd.displayY.xyz, u_lfd.displayZ.xyz);
    f.spacing = spacing;
    vec2 q0 = lfdSamplingFromScene(p0, p0, f.frame, spacing);
    vec2 q1 = lfdSamplingFromScene(p1, p0, f.frame, spacing);
    vec2 q2 = lfdSamplingFromScene(p2, p0, f.frame, spacing);
    vec2 lo = min(min(q0, q1), q2);
    f.origin = lfdSceneFromSampling(lo - vec2(1.0), p0, f.frame, spacing);
    return f;
}

// A compact point: (record, sampling cell x | y << 16).
vec2 lfdPointCell(uvec2 point)
{
    return vec2(float(point.y & 0xFFFFu), float(point.y >> 16)) + vec2(0.5);
}
