#include "lfdpr_camera_line.h"

#include <algorithm>
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

namespace {

// The coherent rows of one frame's cameras (steps 1-3 of makeLfdprCameraLine).
struct LineRows {
    glm::dvec4 row0, perOffset, row1, row3;
    std::vector<float> offsets; // per view, from view 0 along the line
    glm::dvec3 eye0{0.0}, direction{0.0}; // view 0's eye; the line's unit direction (or 0)
};

LineRows lineRows(const FrameSetup& frame)
{
    if (frame.cameras.empty())
        throw std::invalid_argument("lfdpr: a frame needs at least one view camera");
    if (frame.cameras.size() > kLfdprMaxViews)
        throw std::invalid_argument("lfdpr: " + std::to_string(frame.cameras.size()) +
                                    " views, more than the " + std::to_string(kLfdprMaxViews) +
                                    " its camera-line block holds (set --views " +
                                    std::to_string(kLfdprMaxViews) + " or fewer)");
    // Step 1: clipFromScene per view in double precision; the offsets along the line.
    std::vector<glm::dmat4> clip;
    clip.reserve(frame.cameras.size());
    for (const ViewCamera& camera : frame.cameras)
        clip.push_back(camera.clipFromDisplay * frame.displayFromScene);
    const glm::dvec3 eye0 = frame.cameras.front().eye;
    const glm::dvec3 lineDir = frame.cameras.back().eye - eye0;
    const double lineLength = glm::length(lineDir);
    LineRows rows;
    rows.eye0 = eye0;
    rows.direction = lineLength > 0.0 ? lineDir / lineLength : glm::dvec3(0.0);
    for (const ViewCamera& camera : frame.cameras)
        rows.offsets.push_back(lineLength > 0.0 ? float(glm::dot(camera.eye - eye0, lineDir) / lineLength) : 0.0f);

    // Step 2: x row of view 0 and its rate along the line (from the last view).
    rows.row0 = row(clip.front(), 0);
    const double lastOffset = rows.offsets.back();
    rows.perOffset = lastOffset != 0.0 ? (row(clip.back(), 0) - rows.row0) / lastOffset : glm::dvec4(0.0);
    rows.row1 = row(clip.front(), 1);
    rows.row3 = row(clip.front(), 3);

    // Step 3: check the model on every view.
    for (size_t v = 0; v < clip.size(); ++v) {
        const double tolerance = 1e-5;
        const glm::dvec4 predicted = rows.row0 + rows.perOffset * double(rows.offsets[v]);
        bool ok = maxAbs(row(clip[v], 0) - predicted) <= tolerance * maxAbs(row(clip[v], 0));
        for (int r = 1; r < 4; ++r)
            ok = ok && maxAbs(row(clip[v], r) - row(clip.front(), r)) <= tolerance * std::max(maxAbs(row(clip[v], r)), 1e-30);
        if (!ok || (lineLength > 0.0 && glm::length(glm::cross(frame.cameras[v].eye - eye0, lineDir)) > 1e-6 * lineLength))
            throw std::invalid_argument("lfdpr: view camera " + std::to_string(v) +
                                        " is not on the camera line (cameras must be shifted along one line "
                                        "parallel to the screen and share its rectangle)");
    }
    return rows;
}

} // namespace

LfdprCameraLine makeLfdprCameraLine(const FrameSetup& frame)
{
    // Steps 1-3: the splatted views' rows; the sampling frame's for pixel-centre culling.
    const LineRows views = lineRows(frame);
    const LineRows sampling = lineRows(frame.samplingFrame());
    LfdprCameraLine line{};
    line.viewOffsets = views.offsets;

    // Step 4: the depth range as w (glm's OpenGL frustum: w = -z_view; near and far from
    // the projection's z row: n = m32 / (m22 - 1), f = m32 / (m22 + 1)).
    const glm::dmat4& p = frame.cameras.front().clipFromView;
    const double nearW = p[3][2] / (p[2][2] - 1.0), farW = p[3][2] / (p[2][2] + 1.0);
    line.gpu.row0 = glm::vec4(views.row0);
    line.gpu.row0PerOffset = glm::vec4(views.perOffset);
    line.gpu.row1 = glm::vec4(views.row1);
    line.gpu.row3 = glm::vec4(views.row3);
    line.gpu.wRange = glm::vec4(float(nearW), float(farW), 0.0f, 0.0f);
    for (size_t v = 0; v < line.viewOffsets.size(); ++v)
        line.gpu.viewOffsets[v / 4][int(v % 4)] = line.viewOffsets[v];

    // Step 5: the sampling frame's whole cone, which holds every view angular
    // supersampling can place (frame_pipeline.cpp: makeViewCameraAt inside each view's
    // interval): its two end cameras on the line, widened to be safe by half the widest
    // gap between neighbouring views beyond the first and last view.
    const FrameSetup& s = frame.samplingFrame();
    auto offsetOf = [&](const glm::dvec3& eye) { return glm::dot(eye - sampling.eye0, sampling.direction); };
    const auto [first, last] = std::minmax_element(sampling.offsets.begin(), sampling.offsets.end());
    double halfGap = 0.0;
    for (size_t v = 1; v < sampling.offsets.size(); ++v)
        halfGap = std::max(halfGap, 0.5 * std::abs(double(sampling.offsets[v]) - double(sampling.offsets[v - 1])));
    double lo = double(*first) - halfGap, hi = double(*last) + halfGap;
    for (const double end : {0.0, 1.0}) {
        const double e = offsetOf(makeViewCameraAt(s.profile, s.framing, end).eye);
        if (std::isfinite(e)) {
            lo = std::min(lo, e);
            hi = std::max(hi, e);
        }
    }
    line.gpu.cullRow0 = glm::vec4(sampling.row0);
    line.gpu.cullRow0PerOffset = glm::vec4(sampling.perOffset);
    line.gpu.cullRow1 = glm::vec4(sampling.row1);
    line.gpu.cullRow3 = glm::vec4(sampling.row3);
    line.gpu.cullOffsets = glm::vec4(float(lo), float(hi), 0.0f, 0.0f);
    return line;
}

} // namespace lfd::player
