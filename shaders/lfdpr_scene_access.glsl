// The scene's geometry as compute shaders of the visibility pipeline read it: the index
// buffer and vertex streams bound as storage buffers (the same buffers the raster
// renderers draw from), the draw table and the triangle records. A point holds only its
// record and sampling cell; everything else about it is derived from here.
// Needs scene_bindings.glsl and lfdpr_bindings.glsl first.

// LFDPR_SCENE_TEXELS (lfdpr_visibility_shade.comp): the reads go through buffer textures over the
// same buffers (LFDPR_UNIT_*): Mesa's llvmpipe turns a storage-buffer load at a per-invocation
// address into a loop over the SIMD lanes, once per component and with a bounds check per lane,
// while texelFetch is one vectorised gather of a whole texel. That pays in the shading pass, which
// follows record -> draw -> triangle -> vertices for every pixel (see docs/player/lfdpr.md "View
// generation and shading"); it was measured slower in the splat (one chain per point, amortised
// over its views: gallery view generation 45 -> 71 ms), which keeps the storage buffers, as does
// point generation.
#ifdef LFDPR_SCENE_TEXELS
layout(binding = LFDPR_UNIT_INDICES) uniform usamplerBuffer t_sceneTriangles;
layout(binding = LFDPR_UNIT_POSITIONS) uniform samplerBuffer t_scenePositions;
layout(binding = LFDPR_UNIT_DRAWS) uniform usamplerBuffer t_draws;
layout(binding = LFDPR_UNIT_RECORDS) uniform usamplerBuffer t_records;
layout(binding = LFDPR_UNIT_NODES) uniform samplerBuffer t_nodes;
layout(binding = LFDPR_UNIT_MATERIALS) uniform samplerBuffer t_materials;
// The material flags a program reads (the shading groups' LFD_TEXTURE_MASK): without
// LFD_MATERIAL_UV_TRANSFORM in it, lfdMaterial leaves the texture transforms at identity.
#ifdef LFD_TEXTURE_MASK
#define LFD_SCENE_MATERIAL_MASK LFD_TEXTURE_MASK
#else
#define LFD_SCENE_MATERIAL_MASK 0xFFFFFFFFu
#endif

NodeGpu lfdNode(uint node)
{
    int t = 8 * int(node);
    NodeGpu n;
    n.sceneFromObject = mat4(texelFetch(t_nodes, t), texelFetch(t_nodes, t + 1), texelFetch(t_nodes, t + 2),
                             texelFetch(t_nodes, t + 3));
    n.normalFromObject = mat4(texelFetch(t_nodes, t + 4), texelFetch(t_nodes, t + 5), texelFetch(t_nodes, t + 6),
                              texelFetch(t_nodes, t + 7));
    return n;
}

MaterialGpu lfdMaterial(uint material)
{
    // MaterialGpu is 4 + 2 * LFD_SLOT_COUNT texels; the texture transforms are read only
    // where the material has one (most have none: identity, no fetches).
    int t = (4 + 2 * LFD_SLOT_COUNT) * int(material);
    MaterialGpu m;
    m.baseColorFactor = texelFetch(t_materials, t);
    m.emissiveCutoff = texelFetch(t_materials, t + 1);
    m.params = texelFetch(t_materials, t + 2);
    uvec4 bits = floatBitsToUint(texelFetch(t_materials, t + 3));
    m.flags = bits.x;
    m.alphaMode = bits.y;
    m.pad0 = bits.z;
    m.pad1 = bits.w;
    // note: a program compiled for a texture set without LFD_MATERIAL_UV_TRANSFORM (the
    // shading groups' LFD_TEXTURE_MASK) has no code for the fetches at all: llvmpipe would
    // pay for them under a lane mask even where no material has a transform.
    for (int slot = 0; slot < LFD_SLOT_COUNT; ++slot) {
        m.uvLinear[slot] = vec4(1.0, 0.0, 0.0, 1.0);
        m.uvOffset[slot] = vec4(0.0, 0.0, 1.0, 0.0);
    }
    if ((m.flags & LFD_MATERIAL_UV_TRANSFORM & LFD_SCENE_MATERIAL_MASK) != 0u)
        for (int slot = 0; slot < LFD_SLOT_COUNT; ++slot) {
            m.uvLinear[slot] = texelFetch(t_materials, t + 4 + slot);
            m.uvOffset[slot] = texelFetch(t_materials, t + 4 + LFD_SLOT_COUNT + slot);
        }
    return m;
}

LfdprVisibilityDrawGpu lfdDraw(uint draw)
{
    uvec4 d = texelFetch(t_draws, int(draw));
    return LfdprVisibilityDrawGpu(d.x, d.y, d.z, d.w);
}

LfdprVisibilityRecordGpu lfdRecord(uint record)
{
    uvec4 r = texelFetch(t_records, int(record));
    return LfdprVisibilityRecordGpu(r.x, r.y, uintBitsToFloat(r.zw));
}

// Vertex indices of triangle `primitive` of draw `draw`.
uvec3 lfdTriangleVertices(LfdprVisibilityDrawGpu draw, uint primitive)
{
    return texelFetch(t_sceneTriangles, int(draw.firstTriangle + primitive)).xyz;
}

vec3 lfdObjectPosition(uint vertex)
{
    return texelFetch(t_scenePositions, int(vertex)).xyz;
}
#else
NodeGpu lfdNode(uint node)
{
    return nodes[node];
}

MaterialGpu lfdMaterial(uint material)
{
    return materials[material];
}

layout(std430, binding = LFDPR_SSBO_INDICES) readonly buffer SceneIndices {
    uint sceneIndices[];
};
layout(std430, binding = LFDPR_SSBO_POSITIONS) readonly buffer ScenePositions {
    float scenePositions[];
};
layout(std430, binding = LFDPR_SSBO_DRAWS) readonly buffer Draws {
    LfdprVisibilityDrawGpu draws[];
};

LfdprVisibilityDrawGpu lfdDraw(uint draw)
{
    return draws[draw];
}

// Vertex indices of triangle `primitive` of draw `draw`.
uvec3 lfdTriangleVertices(LfdprVisibilityDrawGpu draw, uint primitive)
{
    uint first = 3u * (draw.firstTriangle + primitive);
    return uvec3(sceneIndices[first], sceneIndices[first + 1u], sceneIndices[first + 2u]);
}

vec3 lfdObjectPosition(uint vertex)
{
    return vec3(scenePositions[3u * vertex], scenePositions[3u * vertex + 1u], scenePositions[3u * vertex + 2u]);
}
#endif

// Scene-space positions of a triangle (the node transform applied as the raster vertex
// shaders apply it).
void lfdTrianglePositions(LfdprVisibilityDrawGpu draw, uvec3 vertices, out vec3 p0, out vec3 p1, out vec3 p2)
{
    mat4 sceneFromObject = lfdNode(draw.node).sceneFromObject;
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
    vec2 triangleHi; // the triangle's greatest sampling coordinates (its least are (1, 1))
};

LfdSamplingFrame lfdRecordFrame(vec3 p0, vec3 p1, vec3 p2, vec2 signedSpacing)
{
    LfdSamplingFrame f;
    // The face normal as lfdSetupTriangle computes it (cross / length, not normalize), and
    // the frame's choices as point generation made them (the spacings' signs,
    // lfdSignedSpacing), so the frame comes out as it did there: a v of the other sign would
    // put the point's cells in mirrored places.
    vec2 spacing = abs(signedSpacing);
    vec3 faceCross = cross(p1 - p0, p2 - p0);
    vec3 faceNormal = faceCross / length(faceCross);
    f.frame = lfdAlignFrameWith(faceNormal, u_lfd.displayX.xyz, u_lfd.displayZ.xyz, lfdSpacingChoices(signedSpacing));
    f.spacing = spacing;
    vec2 q0 = lfdSamplingFromScene(p0, p0, f.frame, spacing);
    vec2 q1 = lfdSamplingFromScene(p1, p0, f.frame, spacing);
    vec2 q2 = lfdSamplingFromScene(p2, p0, f.frame, spacing);
    vec2 lo = min(min(q0, q1), q2);
    f.origin = lfdSceneFromSampling(lo - vec2(1.0), p0, f.frame, spacing);
    f.triangleHi = (max(max(q0, q1), q2) - lo) + vec2(1.0); // as lfdPlaceSampling places it
    return f;
}

// A compact point: (record, sampling cell x | y << 16).
vec2 lfdPointCell(LfdprVisibilityPointGpu point)
{
    return vec2(float(point.cell & 0xFFFFu), float(point.cell >> 16)) + vec2(0.5);
}
