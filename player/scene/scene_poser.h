// The pose pass: skinned and morphed meshes (lfd::Deformer) posed on the GPU every frame
// into the vertex streams every renderer reads, and the per-triangle statistics that
// follow the triangles' size (shaders/pose_vertices.comp, pose_triangles.comp). Made by
// GpuScene only for scenes that have deformers, so static scenes pay nothing.
#pragma once

#include "gl_handles.h"

#include "lfd/scene.h"

#include <glm/glm.hpp>

#include <utility>
#include <vector>

namespace lfd::player {

// The GpuScene buffers the pass writes (LFD_ATTRIB_* streams; 0 when absent).
struct PoseTargets {
    unsigned positions = 0;
    unsigned normals = 0;
    unsigned tangents = 0;
    unsigned indices = 0;
    unsigned triangleStats = 0;
};

class ScenePoser {
public:
    // Needs a current GL context and a scene with deformers. Uploads the rest pose, the
    // influences and morph deltas (adds their bytes to gpuBytes) and builds the programs.
    ScenePoser(const Scene& scene, size_t& gpuBytes);

    // Poses every deformer at `time` (sceneFromNode: nodeWorldMatrices at that time).
    void pose(const Scene& scene, const std::vector<glm::mat4>& sceneFromNode, float time, const PoseTargets& targets);

private:
    gl::Buffer restPositions_, restNormals_, restTangents_, influences_;
    gl::Buffer morphPositions_, morphNormals_, morphTangents_, deformers_;
    gl::Buffer jointMatrices_, morphWeights_;
    gl::Program vertices_, triangles_;
    uint32_t firstVertex_ = 0, vertexCount_ = 0;
    uint32_t flags_ = 0;
    std::vector<std::pair<uint32_t, uint32_t>> triangleRanges_; // (first, count), merged
};

} // namespace lfd::player
