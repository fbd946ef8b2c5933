// lfd-bake pipeline: glTF 2.0 in, .lfdpack out. Each stage is a free function, grouped
// by the file that implements it; the driver (main.cpp) calls them in this order:
//
//   importGltf        gltf_import.cpp     glTF -> lfd::Scene (object-space meshes, nodes,
//                                         animations, materials, texture sources)
//   computeBounds     scene_bounds.cpp    scene-space AABB + bounding sphere over animations
//   simplifyScene     simplification.cpp  merge triangles finer than --simplify view pixels
//                                         (simplification.h)
//   tessellateScene   tessellation.cpp    split oversized triangles, crack-free
//   computeTriangleStats triangle_stats.cpp  A_ws, A_ts, n_tex, size_uv, A_ts/A_ws
//   bakeTexture       texture_bake.cpp    decode, reduce, mip chain (sRGB-correct), RGBA8
//   writePack         formats/            atomic write
//
// Errors in input data throw BakeError with a one-line message naming the file.
#pragma once

#include "lfd/display_profile.h"
#include "lfd/framing.h"
#include "lfd/scene.h"
#include "parallel.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace lfd::bake {

class BakeError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Progress / warning sink. Stages report what they do; the driver decides whether to
// print (--quiet keeps warnings and errors only).
struct Log {
    std::function<void(const std::string&)> info = [](const std::string&) {};
    std::function<void(const std::string&)> warn = [](const std::string&) {};
};

// ---- gltf_import.cpp -------------------------------------------------------------
// Where a texture's pixels come from: an image file, or bytes embedded in the glTF
// (bufferView or data URI). Decoding is deferred to bakeTexture so that only one
// texture is decoded at a time.
struct TextureSource {
    std::string name;                 // for messages
    std::filesystem::path file;       // set for external images
    std::vector<uint8_t> encoded;     // set for embedded images (PNG/JPEG bytes)
    std::string mimeType;
    bool srgb = false;                // used as baseColor/emissive
};

struct ImportedScene {
    Scene scene;                        // textures[] carry name + srgb only
    std::vector<TextureSource> textureSources; // parallel to scene.textures
    std::vector<std::string> warnings;  // also sent to Log::warn
    size_t sourceTriangles = 0;
    // Files read besides the textures' (textureSources[].file): the glTF and its buffers.
    std::vector<std::filesystem::path> filesRead;
};

// Reads .gltf (external .bin / images or data URIs) and .glb. Converts strips/fans to
// lists, de-indexes nothing (non-indexed primitives get an index buffer), keeps the node
// hierarchy (matrix nodes decomposed to TRS), animation channels (T/R/S and morph
// weights; LINEAR and STEP; CUBICSPLINE linearised with a warning), skins (JOINTS_0 /
// WEIGHTS_0 and further sets: the four largest influences, renormalised; inverse bind
// matrices) and morph targets (POSITION, NORMAL, TANGENT deltas): each node instance of a
// skinned or morphed mesh becomes a Deformer with a mesh of its own; KHR_texture_transform
// (Material::textureTransforms, texCoord overrides), KHR_materials_unlit and
// KHR_lights_punctual (a Light per node instance). Drops streams nothing uses. Draco- and
// meshopt-compressed geometry is decoded on up to `threads` threads (0: one per hardware
// thread). Errors (throw BakeError): unreadable/malformed file, streams that do not
// decode, required unsupported extensions, out-of-range accessors. Warnings name what is
// not supported: a skinned node whose mesh has no influences, morph attributes other than
// the three, more than four influences, non-triangle primitives, optional extensions.
ImportedScene importGltf(const std::filesystem::path& path, const Log& log, unsigned threads = 0);

// ---- deformers.cpp ----------------------------------------------------------------
// Gives every deformer's node a mesh no other node instances (copies of the mesh's
// primitives and vertices; `file` names the input in the error past 2^32 vertices).
void isolateDeformedMeshes(Scene& scene, const std::string& file);
// Reorders the vertices so each deformer's mesh is one contiguous range (vertices of no
// deformer first) and sets Deformer::firstVertex / vertexCount. Run after import and
// after tessellation (which appends new vertices at the end).
void assignDeformerVertices(Scene& scene);

// ---- scene_bounds.cpp ------------------------------------------------------------
// Bounds over the rest pose and every animation key time (node transforms come from
// lfd::nodeWorldMatrices in formats/, shared with the player).
SceneBounds computeBounds(const Scene& scene);
// Largest linear scale each mesh receives from any node instance at any animation key
// (max column length of the world matrix); 0 for meshes no node uses.
std::vector<float> meshMaxWorldScale(const Scene& scene);

// ---- tessellation.cpp ------------------------------------------------------------
struct TessellationStats {
    size_t trianglesIn = 0;
    size_t trianglesOut = 0;
    size_t trianglesSplit = 0;        // input triangles that were oversized
    double maxEdgeWorldBefore = 0.0;  // longest edge in scene units (after instance scale)
    double maxEdgeWorldAfter = 0.0;
    // Mean edge length after, scene units: over every output triangle's edges, and over
    // the edges of the pieces of split triangles only (how close to the bound cuts land).
    double meanEdgeWorldAfter = 0.0;
    double meanPieceEdgeWorld = 0.0;
    // New points lie on OpenSubdiv's bilinear surface of each welded mesh that has
    // triangles to split (bilinear_surface.h): meshes it took and meshes it refused, and
    // split triangles whose interior points were placed by barycentric weights of their
    // corners instead (a refused mesh, or a face Bfr gave no surface).
    size_t surfaceMeshes = 0;
    size_t surfaceMeshesRefused = 0;
    size_t surfaceFallbacks = 0;
};

// Cuts every triangle with a scene-space edge longer than maxEdgeWorld (edges are scaled
// per mesh by meshMaxWorldScale). Each edge is cut into ceil(length / bound) equal pieces
// by a rule that depends only on the (position-welded) edge itself, so neighbouring
// triangles - including across UV/normal seams - cut shared edges identically: no
// T-junctions. Oversized faces are filled by OpenSubdiv's Bfr::Tessellation for their
// edge rates, checked to keep every output edge within the bound (face_pattern.h); new
// points lie on OpenSubdiv's bilinear Bfr::Surface of the welded mesh.
// Attributes are interpolated from each face's own corners; normals/tangents
// re-normalised. Triangles within the bound are left untouched. Updates primitives'
// index ranges. Meshes are tessellated on up to `threads` threads at once (0: one per
// hardware thread); the result is the same for any thread count (parallel.h).
TessellationStats tessellateScene(Scene& scene, double maxEdgeWorld, const Log& log, unsigned threads = 0);

// ---- triangle_stats.cpp ----------------------------------------------------------
// Paper eqs. texelCount / lfd_UVSize for every triangle. Needs the final (stored) size of
// each texture (scene.textures[i].width/height set). Ranges of triangles are computed on
// up to `threads` threads (0: one per hardware thread); the result does not depend on it.
void computeTriangleStats(Scene& scene, unsigned threads = 0);
// One texture of a triangle's material: its stored size and the area scale of the slot's
// texture transform (TextureTransform::areaScale), so A_ts in the texture's own uv space
// is TEXCOORD_0's area times areaScale.
struct TextureDensity {
    glm::uvec2 size{0};
    double areaScale = 1.0;
    bool operator==(const TextureDensity&) const = default;
};
TriangleStats triangleStats(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2,
                            const glm::vec2& uv0, const glm::vec2& uv1, const glm::vec2& uv2,
                            const std::vector<TextureDensity>& textures);

// ---- texture_bake.cpp ------------------------------------------------------------

struct TextureBakeOptions {
    uint32_t maxSize = 16384;      // larger dimensions are reduced by powers of two
    unsigned threads = 0;          // for the mip chain's row bands (0: one per hardware thread)
    ThreadBudget* pool = nullptr;  // if set, the bands take their threads from it instead
};

// Reads only the image header: source size (for n_tex and reporting) before decoding.
glm::uvec2 probeTextureSize(const TextureSource& source);
// Size the texture will be stored at (power-of-two reductions until <= maxSize).
glm::uvec2 storedTextureSize(glm::uvec2 sourceSize, const TextureBakeOptions& options);

// Decodes, converts to RGBA8, reduces to the stored size, builds the full mip chain
// (box filter in linear light for sRGB textures, plain for data textures). Peak memory
// stays under about two full-size RGBA8 copies of the source. Throws BakeError.
Texture bakeTexture(const TextureSource& source, const TextureBakeOptions& options);

// ---- texture_budget.cpp ----------------------------------------------------------
// "Model no more than the scene needs": the largest size texture `textureIndex` needs so
// that its texels are no finer than `detail` times the finest view pixel that can land on
// any triangle using it (viewPixelWorld: conservative scene units per view pixel, see
// framing.h; meshScale: meshMaxWorldScale). Texture area is measured in the texture's own
// uv space (the sampling slot's texture transform applied: a tiled texture needs fewer
// texels). Returns sourceSize reduced by a power of two (never enlarged); triangles
// without texture area are ignored.
glm::uvec2 resolvableTextureSize(const Scene& scene, uint32_t textureIndex, glm::uvec2 sourceSize,
                                 double viewPixelWorld, const std::vector<float>& meshScale,
                                 double detail);

} // namespace lfd::bake
