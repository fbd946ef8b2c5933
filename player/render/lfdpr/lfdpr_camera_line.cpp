#include "lfdpr_camera_line.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace lfd::player {

namespace {

glm::dvec4 row(const glm::dmat4& m, int r) { return glm::dvec4(m[0][r], m[1][r], m[2][r], m[3][r]); }

double maxAbs(const glm::dvec4& v)
{
    return std::max(std::max(std::abs(v.x), std::abs(v.y)), std::max(std::abs(v.z), std::abs(v.w)));
}

} // namespace

LfdprCameraLine makeLfdprCameraLine(const FrameSetup& frame)
{
    if (frame.cameras.empty())
        throw std::invalid_argument("lfdpr: a frame needs at least one view camera");
    if (frame.cameras.size() > kLfdprMaxViews)
        throw std::invalid_argument("lfdpr: " + std::to_string(frame.cameras.size()) + " views (at most " +
                                    std::to_string(kLfdprMaxViews) + ")");
    // Step 1: clipFromScene per view in double precision; the offsets along the line.
    std::vector<glm::dmat4> clip;
    clip.reserve(frame.cameras.size());
    for (const ViewCamera& camera : frame.cameras)
        clip.push_back(camera.clipFromDisplay * frame.displayFromScene);
    const glm::dvec3 eye0 = frame.cameras.front().eye;
    const glm::dvec3 lineDir = frame.cameras.back().eye - eye0;
    const double lineLength = glm::length(lineDir);
    LfdprCameraLine line{};
    for (const ViewCamera& camera : frame.cameras)
        line.viewOffsets.push_back(lineLength > 0.0 ? float(glm::dot(camera.eye - eye0, lineDir) / lineLength) : 0.0f);

    // Step 2: x row of view 0 and its rate along the line (from the last view).
    const glm::dvec4 row0 = row(clip.front(), 0);
    const double lastOffset = line.viewOffsets.back();
    const glm::dvec4 perOffset = lastOffset != 0.0 ? (row(clip.back(), 0) - row0) / lastOffset : glm::dvec4(0.0);

    // Step 3: check the model on every view.
    for (size_t v = 0; v < clip.size(); ++v) {
        const double tolerance = 1e-5;
        const glm::dvec4 predicted = row0 + perOffset * double(line.viewOffsets[v]);
        bool ok = maxAbs(row(clip[v], 0) - predicted) <= tolerance * maxAbs(row(clip[v], 0));
        for (int r = 1; r < 4; ++r)
            ok = ok && maxAbs(row(clip[v], r) - row(clip.front(), r)) <= tolerance * std::max(maxAbs(row(clip[v], r)), 1e-30);
        if (!ok || (lineLength > 0.0 && glm::length(glm::cross(frame.cameras[v].eye - eye0, lineDir)) > 1e-6 * lineLength))
            throw std::invalid_argument("lfdpr: view camera " + std::to_string(v) +
                                        " is not on the camera line (cameras must be shifted along one line "
                                        "parallel to the screen and share its rectangle)");
    }

    // Step 4: the depth range as w (glm's OpenGL frustum: w = -z_view; near and far from
    // the projection's z row: n = m32 / (m22 - 1), f = m32 / (m22 + 1)).
    const glm::dmat4& p = frame.cameras.front().clipFromView;
    const double nearW = p[3][2] / (p[2][2] - 1.0), farW = p[3][2] / (p[2][2] + 1.0);
    line.gpu.row0 = glm::vec4(row0);
    line.gpu.row0PerOffset = glm::vec4(perOffset);
    line.gpu.row1 = glm::vec4(row(clip.front(), 1));
    line.gpu.row3 = glm::vec4(row(clip.front(), 3));
    line.gpu.wRange = glm::vec4(float(nearW), float(farW), 0.0f, 0.0f);
    for (size_t v = 0; v < line.viewOffsets.size(); ++v)
        line.gpu.viewOffsets[v / 4][int(v % 4)] = line.viewOffsets[v];
    return line;
}

} // namespace lfd::player
