#include "lfdpr_paper_point_generation.h"

#include "gpu_scene.h"
#include "lfdpr_constants.h"
#include "scene_bindings.h"
#include "shader_library.h"

#include "lfd/framing.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <limits>

namespace lfd::player {

std::array<glm::dvec4, 6> unionFrustumPlanesDisplay(const FrameSetup& frame, double slackMm)
{
    // Step 1: every frustum corner in display space; near corners (NDC z = -1) and far
    // corners (z = +1) separately.
    const double inf = std::numeric_limits<double>::infinity();
    double zNear = -inf, zFar = inf;
    glm::dvec2 nearMin(inf), nearMax(-inf), farMin(inf), farMax(-inf); // x, y extremes
    for (const ViewCamera& camera : frame.cameras) {
        const glm::dmat4 displayFromClip = glm::inverse(camera.clipFromDisplay);
        for (int corner = 0; corner < 8; ++corner) {
            const glm::dvec4 ndc((corner & 1) ? 1.0 : -1.0, (corner & 2) ? 1.0 : -1.0,
                                 (corner & 4) ? 1.0 : -1.0, 1.0);
            const glm::dvec4 h = displayFromClip * ndc;
            const glm::dvec3 p = glm::dvec3(h) / h.w;
            if (corner & 4) {
                zFar = std::min(zFar, p.z);
                farMin = glm::min(farMin, glm::dvec2(p));
                farMax = glm::max(farMax, glm::dvec2(p));
            } else {
                zNear = std::max(zNear, p.z);
                nearMin = glm::min(nearMin, glm::dvec2(p));
                nearMax = glm::max(nearMax, glm::dvec2(p));
            }
        }
    }
    // Step 2: near/far planes, then the four chords. A chord for coordinate c (x or y)
    // from value cn at zNear to cf at zFar: c(z) = cn + (z - zNear) * slope.
    const double dz = zNear - zFar;
    auto chord = [&](double cn, double cf, int axis, double side) {
        // side +1: inside is c >= c(z) (left, bottom); -1: inside is c <= c(z).
        const double slope = dz != 0.0 ? (cn - cf) / dz : 0.0;
        glm::dvec4 plane(0.0);
        plane[axis] = side;
        plane.z = -side * slope;
        plane.w = -side * (cn - zNear * slope);
        // Push outwards by the slack (normalise by the normal's length).
        plane.w += slackMm * glm::length(glm::dvec3(plane));
        return plane;
    };
    return {
        glm::dvec4(0.0, 0.0, -1.0, zNear + slackMm), // z <= zNear
        glm::dvec4(0.0, 0.0, 1.0, -zFar + slackMm),  // z >= zFar
        chord(nearMin.x, farMin.x, 0, 1.0),          // left
        chord(nearMax.x, farMax.x, 0, -1.0),         // right
        chord(nearMin.y, farMin.y, 1, 1.0),          // bottom
        chord(nearMax.y, farMax.y, 1, -1.0),         // top
    };
}

LfdprFrameGpu makeLfdprFrame(const FrameSetup& frame, uint32_t pointCapacity, uint32_t options,
                             uint32_t splatViewCount)
{
    const glm::dmat4 sceneFromDisplay = glm::inverse(frame.displayFromScene);
    const glm::dmat3 sceneFromDisplay3(sceneFromDisplay);
    const glm::dvec2 pixelMm = viewPixelSizeMm(frame.profile);
    const glm::dvec3 xScene = sceneFromDisplay3 * glm::dvec3(pixelMm.x, 0.0, 0.0);
    const glm::dvec3 yScene = sceneFromDisplay3 * glm::dvec3(0.0, pixelMm.y, 0.0);
    const glm::dvec3 zScene = sceneFromDisplay3 * glm::dvec3(0.0, 0.0, 1.0);

    LfdprFrameGpu g{};
    g.displayX = glm::vec4(glm::normalize(xScene), glm::length(xScene));
    g.displayY = glm::vec4(glm::normalize(yScene), glm::length(yScene));
    g.displayZ = glm::vec4(glm::normalize(zScene), 0.0f);
    g.screenCenter = glm::vec4(glm::dvec3(sceneFromDisplay * glm::dvec4(0.0, 0.0, 0.0, 1.0)), 1.0f);
    const glm::dvec3 eye0 = frame.cameras.empty() ? glm::dvec3(0.0) : frame.cameras[0].eye;
    g.viewLine = glm::vec4(glm::dvec3(sceneFromDisplay * glm::dvec4(eye0, 1.0)), 1.0f);
    // Planes go from display to scene space with the transpose: dot(P, M p) = dot(M^T P, p).
    const std::array<glm::dvec4, 6> planes = unionFrustumPlanesDisplay(frame);
    for (size_t k = 0; k < planes.size(); ++k)
        g.planes[k] = glm::vec4(glm::transpose(frame.displayFromScene) * planes[k]);
    g.counts = glm::uvec4(frame.profile.viewCount, pointCapacity, options,
                          splatViewCount ? splatViewCount : frame.profile.viewCount);
    g.viewSize = glm::vec4(float(frame.profile.viewWidth), float(frame.profile.viewHeight), 0.0f, 0.0f);
    return g;
}

LfdprPaperPointGeneration::LfdprPaperPointGeneration()
    : program_(gl::buildProgram({{GL_VERTEX_SHADER, "lfdpr_paper_points.vert"},
                                 {GL_GEOMETRY_SHADER, "lfdpr_paper_points.geom"},
                                 {GL_FRAGMENT_SHADER, "lfdpr_paper_points.frag"}})),
      framebuffer_(gl::createFramebuffer())
{
    // The generated frame block must have the driver's size here too (the layout test checks
    // it member by member on the test driver; this guards the driver actually running).
    const GLuint block = glGetUniformBlockIndex(program_, "LfdprFrameBlock");
    GLint size = 0;
    if (block != GL_INVALID_INDEX)
        glGetActiveUniformBlockiv(program_, block, GL_UNIFORM_BLOCK_DATA_SIZE, &size);
    if (size != GLint(sizeof(LfdprFrameGpu)))
        throw gl::GlError("shaders/lfdpr_bindings.glsl: LfdprFrameBlock is " + std::to_string(size) +
                          " bytes, C++ LfdprFrameGpu is " + std::to_string(sizeof(LfdprFrameGpu)));
    // The sampling viewport: a framebuffer with no attachments, LFDPR_TILE_SIZE square.
    const GLint tile = GLint(LfdprConstants::get().tileSize);
    glNamedFramebufferParameteri(framebuffer_, GL_FRAMEBUFFER_DEFAULT_WIDTH, tile);
    glNamedFramebufferParameteri(framebuffer_, GL_FRAMEBUFFER_DEFAULT_HEIGHT, tile);
}

uint64_t LfdprPaperPointGeneration::recordCount(const GpuScene& scene)
{
    uint64_t records = 0;
    for (const DrawItem& draw : scene.draws())
        records += draw.indexCount / 3;
    return records;
}

void LfdprPaperPointGeneration::run(const GpuScene& scene) const
{
    const LfdprConstants& k = LfdprConstants::get();
    const GLint tile = GLint(k.tileSize);

    // Pipeline state: no depth, no culling (the GS decides facing), no raster discard.
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glViewport(0, 0, tile, tile);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_RASTERIZER_DISCARD);
    glUseProgram(program_);
    glBindVertexArray(scene.vertexArray());
    glProgramUniform1ui(program_, bindings::kLocStreams, scene.cpu().vertices.mask());

    uint32_t recordBase = 0;
    for (const DrawItem& draw : scene.draws()) {
        glProgramUniform1ui(program_, bindings::kLocNode, draw.node);
        glProgramUniform1ui(program_, bindings::kLocMaterial, scene.gpuMaterialIndex(draw.material));
        glProgramUniform1ui(program_, k.locRecordBase, recordBase);
        glProgramUniform1ui(program_, k.locFirstTriangle, draw.firstIndex / 3);
        scene.bindMaterialTextures(draw.material);
        glDrawElements(GL_TRIANGLES, GLsizei(draw.indexCount), GL_UNSIGNED_INT,
                       reinterpret_cast<const void*>(size_t(draw.firstIndex) * sizeof(uint32_t)));
        recordBase += draw.indexCount / 3;
    }
    glBindVertexArray(0);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

} // namespace lfd::player
