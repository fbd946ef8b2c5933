// Binding points, attribute locations and GPU struct layouts shared by every renderer.
// This file is the single definition: the build generates the C++ side from it
// (scene_bindings_gpu.h, included by player/scene/scene_bindings.h; see
// player/gl/gpu_layout_gen.cpp), and tests/player/gpu_layout_test.cpp checks every member
// against the offsets, strides and sizes the driver reports.

// Vertex attribute locations; each stream has its own vertex buffer, bound at the
// vertex-buffer binding index equal to its location.
#define LFD_ATTRIB_POSITION 0
#define LFD_ATTRIB_NORMAL 1
#define LFD_ATTRIB_TANGENT 2
#define LFD_ATTRIB_UV 3

// Shader storage buffer binding points.
#define LFD_SSBO_MATERIALS 0
#define LFD_SSBO_NODES 1
#define LFD_SSBO_VIEWS 2
#define LFD_SSBO_TRIANGLE_STATS 3

// Uniform buffer binding points.
#define LFD_UBO_FRAME 0

// Texture units of the material textures.
#define LFD_UNIT_BASE_COLOR 0
#define LFD_UNIT_METALLIC_ROUGHNESS 1
#define LFD_UNIT_NORMAL 2
#define LFD_UNIT_OCCLUSION 3
#define LFD_UNIT_EMISSIVE 4

// Texture units of the scene's lighting (frame_uniforms.h binds them every frame): the
// environment's GGX-prefiltered specular cube (one GGX alpha per mip level), its diffuse
// irradiance cube (E / pi) and the split-sum BRDF table (A, B, C; pbr_shading.glsl,
// player/lighting/).
#define LFD_UNIT_ENVIRONMENT 6
#define LFD_UNIT_BRDF_TABLE 7
#define LFD_UNIT_IRRADIANCE 13
#define LFD_UNIT_LOBE_TAPS 20
// The BRDF and lobe tap tables' texels per axis (n.v and roughness at texel centres
// i / (size - 1)).
#define LFD_BRDF_TABLE_SIZE 32

// Explicit uniform locations of the per-draw uniforms.
#define LFD_LOC_NODE 0
#define LFD_LOC_MATERIAL 1
#define LFD_LOC_VIEW 2
#define LFD_LOC_STREAMS 3
// vec4[2 * LFD_SLOT_COUNT] (mvr.frag): the draw's texture transforms, slot s at 2s (the
// linear part, as MaterialGpu.uvLinear) and 2s + 1 (as MaterialGpu.uvOffset).
#define LFD_LOC_UV_TRANSFORMS 4

// MaterialGpu.flags: which textures the material has, double-sidedness, and whether the
// normal texture holds x and y only (BC5; the shader rebuilds z = sqrt(1 - x^2 - y^2)).
#define LFD_MATERIAL_BASE_COLOR_TEXTURE 1
#define LFD_MATERIAL_METALLIC_ROUGHNESS_TEXTURE 2
#define LFD_MATERIAL_NORMAL_TEXTURE 4
#define LFD_MATERIAL_OCCLUSION_TEXTURE 8
#define LFD_MATERIAL_EMISSIVE_TEXTURE 16
#define LFD_MATERIAL_DOUBLE_SIDED 32
#define LFD_MATERIAL_NORMAL_TWO_CHANNEL 64
// KHR_materials_unlit: the base colour alone, no lighting, exposure or tone mapping.
#define LFD_MATERIAL_UNLIT 128
// Some slot has a KHR_texture_transform (MaterialGpu.uvLinear / uvOffset are not all the
// identity); without it the transforms are not read (lfdpr reads materials texel by texel).
#define LFD_MATERIAL_UV_TRANSFORM 256

// MaterialGpu.uvLinear / uvOffset slots (= lfd::TextureSlot).
#define LFD_SLOT_BASE_COLOR 0
#define LFD_SLOT_METALLIC_ROUGHNESS 1
#define LFD_SLOT_NORMAL 2
#define LFD_SLOT_OCCLUSION 3
#define LFD_SLOT_EMISSIVE 4
#define LFD_SLOT_COUNT 5

// MaterialGpu.alphaMode (= lfd::AlphaMode).
#define LFD_ALPHA_OPAQUE 0
#define LFD_ALPHA_MASK 1
#define LFD_ALPHA_BLEND 2

// Vertex stream bits of the u_streams uniform (= lfd::VertexStreamBits).
#define LFD_STREAM_POSITION 1
#define LFD_STREAM_NORMAL 2
#define LFD_STREAM_TANGENT 4
#define LFD_STREAM_UV 8

// glTF metallic-roughness material (std430).
struct MaterialGpu {
    vec4 baseColorFactor;
    vec4 emissiveCutoff; // xyz emissiveFactor, w alphaCutoff
    vec4 params;         // metallicFactor, roughnessFactor, normalScale, occlusionStrength
    uint flags;          // LFD_MATERIAL_*
    uint alphaMode;      // LFD_ALPHA_*
    uint pad0;
    uint pad1;
    // KHR_texture_transform per slot (LFD_SLOT_*): uv' = mat2(uvLinear[s]) * uv + uvOffset[s].xy
    // (mat2 from a vec4 is column-major: columns xy and zw, as lfd::TextureTransform::linear);
    // uvOffset[s].z = |det| of the linear part, the slot's texture-space area scale.
    vec4 uvLinear[LFD_SLOT_COUNT];
    vec4 uvOffset[LFD_SLOT_COUNT];
};

// Per-node transforms for the current frame (std430).
struct NodeGpu {
    mat4 sceneFromObject;
    mat4 normalFromObject; // inverse transpose of the upper 3x3, padded to mat4
};

// One LFD view camera (std430).
struct ViewGpu {
    mat4 clipFromScene;
    vec4 eyeScene; // xyz camera position in scene space, for view-dependent shading
};

// Per-triangle statistics from the baker: TriangleStatsGpu, shared with the pose pass.
#include "triangle_stats_bindings.glsl"

layout(std430, binding = LFD_SSBO_MATERIALS) readonly buffer MaterialBuffer {
    MaterialGpu materials[];
};
layout(std430, binding = LFD_SSBO_NODES) readonly buffer NodeBuffer {
    NodeGpu nodes[];
};
layout(std430, binding = LFD_SSBO_VIEWS) readonly buffer ViewBuffer {
    ViewGpu views[];
};
layout(std430, binding = LFD_SSBO_TRIANGLE_STATS) readonly buffer TriangleStatsBuffer {
    TriangleStatsGpu triangleStats[];
};

// FrameBlock.lightingFlags.
#define LFD_LIGHTING_ENVIRONMENT 1 // image-based lighting (else the constant ambient term)
#define LFD_LIGHTING_TONE_MAP 2    // Khronos PBR Neutral before the sRGB encode (else a clamp)

// Punctual lights per frame (the scene's KHR_lights_punctual instances, or the default
// directional light); FrameBlock.light* arrays.
#define LFD_MAX_LIGHTS 16
#define LFD_LIGHT_DIRECTIONAL 0
#define LFD_LIGHT_POINT 1
#define LFD_LIGHT_SPOT 2

// Frame constants (C++: FrameGpu).
layout(std140, binding = LFD_UBO_FRAME) uniform FrameBlock {
    vec4 ambientColor;  // rgb constant ambient light (without an environment)
    vec4 background;    // rgba clear colour (sRGB-encoded, as stored in the views)
    uint viewCount;
    uint viewWidth;
    uint viewHeight;
    float maxAnisotropy; // --aniso: lfdpr's textureGrad taps along a footprint's major axis
    uint lightingFlags;  // LFD_LIGHTING_*
    uint lightCount;     // punctual lights in the arrays below (<= LFD_MAX_LIGHTS)
    float exposure;      // 2^EV: the scene radiance's scale before tone mapping
    float environmentMaxLevel; // the specular cube's last mip level: the wide level after GGX alpha 1
    // The environment's orientation: environment direction = mat3(columns 0..2) * scene
    // direction (a rotation: the environment is fixed to the display, turned by
    // --environment-rotation about the vertical).
    vec4 environmentFromScene[3];
    vec4 lightPosition[LFD_MAX_LIGHTS];  // xyz scene position; w range (0: unlimited)
    vec4 lightDirection[LFD_MAX_LIGHTS]; // xyz unit direction the light shines along; w type (LFD_LIGHT_*)
    vec4 lightRadiance[LFD_MAX_LIGHTS];  // rgb colour * intensity; w unused
    vec4 lightCone[LFD_MAX_LIGHTS];      // spot: x = 1 / (cos inner - cos outer), y = -cos outer * x
} u_frame;
