#include "scene_poser.h"

#include "pose_bindings_gpu.h"
#include "shader_library.h"

#include "lfd/scene_pose.h"

#include <epoxy/gl.h>

#include <algorithm>

namespace lfd::player {
namespace {

namespace pb = pose_bindings;

gl::Buffer upload(const void* data, size_t bytes, size_t& total, GLbitfield flags = 0)
{
    total += std::max<size_t>(bytes, 16);
    return gl::createBuffer(bytes, flags, data);
}

template <class T>
gl::Buffer uploadVector(const std::vector<T>& v, size_t& total)
{
    return upload(v.empty() ? nullptr : v.data(), v.size() * sizeof(T), total);
}

// The triangles of the deformers' meshes, as merged (first, count) runs.
std::vector<std::pair<uint32_t, uint32_t>> deformedTriangles(const Scene& scene)
{
    std::vector<std::pair<uint32_t, uint32_t>> runs;
    for (const Deformer& d : scene.deformers) {
        const Mesh& mesh = scene.meshes[size_t(scene.nodes[d.node].mesh)];
        for (uint32_t p = mesh.firstPrimitive; p < mesh.firstPrimitive + mesh.primitiveCount; ++p)
            if (scene.primitives[p].indexCount > 0)
                runs.emplace_back(scene.primitives[p].firstIndex / 3, scene.primitives[p].indexCount / 3);
    }
    std::sort(runs.begin(), runs.end());
    std::vector<std::pair<uint32_t, uint32_t>> merged;
    for (const auto& run : runs) {
        if (!merged.empty() && merged.back().first + merged.back().second >= run.first)
            merged.back().second = std::max(merged.back().first + merged.back().second, run.first + run.second) -
                                   merged.back().first;
        else
            merged.push_back(run);
    }
    return merged;
}

// Runs the bound compute program over `count` items from `first`, at most 65535
// workgroups per dispatch (the smallest GL_MAX_COMPUTE_WORK_GROUP_COUNT GL guarantees).
void dispatchRange(unsigned program, GLint firstLocation, GLint countLocation, uint32_t first, uint32_t count)
{
    const uint32_t chunk = 65535u * pb::kLocalSize;
    for (uint32_t done = 0; done < count; done += chunk) {
        glUniform1ui(firstLocation, first + done);
        glUniform1ui(countLocation, std::min(chunk, count - done));
        gl::dispatchCovering(program, std::min(chunk, count - done), 1, 1);
    }
}

} // namespace

ScenePoser::ScenePoser(const Scene& scene, size_t& gpuBytes)
{
    const VertexStreams& v = scene.vertices;
    const DeformationStreams& d = v.deform;
    restPositions_ = uploadVector(v.positions, gpuBytes);
    restNormals_ = uploadVector(v.normals, gpuBytes);
    restTangents_ = uploadVector(v.tangents, gpuBytes);
    std::vector<pb::PoseInfluenceGpu> influences(d.joints.size());
    for (size_t i = 0; i < influences.size(); ++i)
        influences[i] = {d.joints[i], d.weights[i]};
    influences_ = uploadVector(influences, gpuBytes);
    morphPositions_ = uploadVector(d.positions, gpuBytes);
    morphNormals_ = uploadVector(d.normals, gpuBytes);
    morphTangents_ = uploadVector(d.tangents, gpuBytes);
    std::vector<pb::PoseDeformerGpu> deformers;
    uint32_t joints = 0;
    for (const Deformer& f : scene.deformers) {
        deformers.push_back({f.firstVertex, f.vertexCount, joints, f.skin == kNone ? 0u : 1u});
        joints += f.skin == kNone ? 0u : uint32_t(scene.skins[size_t(f.skin)].joints.size());
    }
    deformers_ = uploadVector(deformers, gpuBytes);
    jointMatrices_ = upload(nullptr, std::max<size_t>(joints, 1) * sizeof(glm::mat4), gpuBytes, GL_DYNAMIC_STORAGE_BIT);
    morphWeights_ = upload(nullptr, std::max<size_t>(deformers.size() * d.morphTargets, 1) * sizeof(float), gpuBytes,
                           GL_DYNAMIC_STORAGE_BIT);
    firstVertex_ = scene.deformers.front().firstVertex;
    vertexCount_ = scene.deformers.back().firstVertex + scene.deformers.back().vertexCount - firstVertex_;
    flags_ = (v.normals.empty() ? 0u : pb::kFlagNormals) | (v.tangents.empty() ? 0u : pb::kFlagTangents) |
             (d.normals.empty() ? 0u : pb::kFlagMorphNormals) | (d.tangents.empty() ? 0u : pb::kFlagMorphTangents);
    triangleRanges_ = deformedTriangles(scene);
    vertices_.reset(gl::buildProgram({{GL_COMPUTE_SHADER, "pose_vertices.comp"}}));
    triangles_.reset(gl::buildProgram({{GL_COMPUTE_SHADER, "pose_triangles.comp"}}));
}

void ScenePoser::pose(const Scene& scene, const std::vector<glm::mat4>& sceneFromNode, float time,
                      const PoseTargets& targets)
{
    const PoseInputs inputs = poseInputs(scene, time, sceneFromNode);
    if (!inputs.jointMatrices.empty())
        glNamedBufferSubData(jointMatrices_, 0, GLsizeiptr(inputs.jointMatrices.size() * sizeof(glm::mat4)),
                             inputs.jointMatrices.data());
    if (!inputs.morphWeights.empty())
        glNamedBufferSubData(morphWeights_, 0, GLsizeiptr(inputs.morphWeights.size() * sizeof(float)),
                             inputs.morphWeights.data());
    const std::pair<GLuint, unsigned> buffers[] = {
        {pb::kSsboRestPositions, restPositions_}, {pb::kSsboRestNormals, restNormals_},
        {pb::kSsboRestTangents, restTangents_},   {pb::kSsboInfluences, influences_},
        {pb::kSsboMorphPositions, morphPositions_}, {pb::kSsboMorphNormals, morphNormals_},
        {pb::kSsboMorphTangents, morphTangents_}, {pb::kSsboDeformers, deformers_},
        {pb::kSsboJointMatrices, jointMatrices_}, {pb::kSsboMorphWeights, morphWeights_},
        {pb::kSsboPositions, targets.positions},  {pb::kSsboNormals, targets.normals ? targets.normals : restNormals_.get()},
        {pb::kSsboTangents, targets.tangents ? targets.tangents : restTangents_.get()},
        {pb::kSsboIndices, targets.indices},      {pb::kSsboTriangleStats, targets.triangleStats}};
    for (const auto& [binding, buffer] : buffers)
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, buffer);

    glUseProgram(vertices_);
    glUniform1ui(pb::kLocDeformerCount, uint32_t(scene.deformers.size()));
    glUniform1ui(pb::kLocMorphTargets, scene.vertices.deform.morphTargets);
    glUniform1ui(pb::kLocFlags, flags_);
    dispatchRange(vertices_, pb::kLocFirstVertex, pb::kLocVertexCount, firstVertex_, vertexCount_);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

    glUseProgram(triangles_);
    for (const auto& [first, count] : triangleRanges_)
        dispatchRange(triangles_, pb::kLocFirstTriangle, pb::kLocTriangleCount, first, count);
    // The renderers read the streams as vertex attributes and SSBOs, the statistics as SSBOs.
    glMemoryBarrier(GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT | GL_ELEMENT_ARRAY_BARRIER_BIT);
    glUseProgram(0);
    for (const auto& [binding, buffer] : buffers)
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, 0);
}

} // namespace lfd::player
