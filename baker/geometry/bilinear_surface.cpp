// The welded mesh of one tessellation group as OpenSubdiv's bilinear surface (see
// bilinear_surface.h).
//
// Why the bilinear scheme: its surface is exactly the input's flat triangles, whatever
// the mesh around a face looks like. Bfr makes every face of the bilinear scheme a
// *linear* surface (Bfr::Surface::IsLinear): its patch points are the face's own corners,
// the midpoints of its edges and its centroid, never its neighbours. So the valence,
// sharpness and non-manifold handling of the smooth schemes is not involved: a face at a
// vertex with 48 or more faces, on an edge shared by three faces, in a double-sided pair
// or with two corners welded together is the same flat triangle (tested:
// tests/baker/geometry/bilinear_surface_test.cpp, also under valgrind;
// docs/baker/lfd-bake.md "What a bake does", step 4).
//
// Why the coordinate conversion: Bfr parameterizes a triangle of the bilinear scheme as
// three quad sub-faces (bilinear_surface.h), while the face patterns are built in
// barycentric weights (face_pattern.cpp: Bfr::Tessellation's triangle parameterization,
// which needs fewer triangles than the sub-faces' own). A sub-face is not a parallelogram
// (corner, two edge midpoints, centroid), so its bilinear map is inverted by solving a
// quadratic, in double precision.

#include "bilinear_surface.h"

#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/far/error.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <mutex>

namespace lfd::bake {
namespace {

namespace Far = OpenSubdiv::Far;
namespace Bfr = OpenSubdiv::Bfr;
namespace Sdc = OpenSubdiv::Sdc;

// Far reports a refused topology through a process-wide callback (by default printed on
// stdout, which lfd-bake keeps for its own output). The callback keeps the message for
// the thread whose TopologyRefinerFactory call raised it, so meshes refined on different
// threads do not mix their messages.
thread_local std::string* farErrorSink = nullptr;

void keepFarError(Far::ErrorType, const char* message)
{
    if (farErrorSink != nullptr && farErrorSink->empty())
        *farErrorSink = message;
}

void dropFarWarning(const char*) {}

void installFarCallbacks()
{
    static std::once_flag once;
    std::call_once(once, [] {
        Far::SetErrorCallback(keepFarError);
        Far::SetWarningCallback(dropFarWarning);
    });
}

// The smaller root of x^2 - p x + q (p >= 2 and q >= 0 here), without the cancellation of
// (p - sqrt(p^2 - 4q)) / 2 for small q.
double smallerRoot(double p, double q)
{
    return 2.0 * q / (p + std::sqrt(std::max(0.0, p * p - 4.0 * q)));
}

} // namespace

SubFaceCoord subFaceCoord(const glm::dvec3& weights)
{
    // The point lies in the sub-face of its heaviest corner: sub-faces i and i + 1 meet on
    // the segment from the midpoint of edge i to the centroid, where the weights of
    // corners i and i + 1 are equal.
    int i = 0;
    if (weights[1] > weights[i])
        i = 1;
    if (weights[2] > weights[i])
        i = 2;
    // With b, c the weights of corners i + 1 and i - 1, barycentricWeights gives
    // b = s/2 - st/6 and c = t/2 - st/6, so s - t = 2 (b - c) = 2d and
    // s^2 - (3 + 2d) s + 6b = 0, t^2 - (3 - 2d) t + 6c = 0, each taking its smaller root
    // (in [0, 1] for b, c <= the weight of corner i). Each from its own equation, so that
    // swapping b and c swaps s and t exactly.
    const double b = weights[(i + 1) % 3], c = weights[(i + 2) % 3];
    const double d = b - c;
    const double s = smallerRoot(3.0 + 2.0 * d, 6.0 * b);
    const double t = smallerRoot(3.0 - 2.0 * d, 6.0 * c);
    return {i, glm::dvec2(std::clamp(s, 0.0, 1.0), std::clamp(t, 0.0, 1.0))};
}

glm::dvec3 barycentricWeights(const SubFaceCoord& coord)
{
    // Bilinear in (s, t) between corner i (weights e_i), the midpoint of edge i
    // ((e_i + e_{i+1}) / 2), the centroid (1/3 each) and the midpoint of edge i - 1.
    const double s = coord.st.x, t = coord.st.y;
    const double corner = (1.0 - s) * (1.0 - t), nextMid = s * (1.0 - t), centre = s * t, prevMid = (1.0 - s) * t;
    glm::dvec3 w(0.0);
    const int i = coord.subFace;
    w[i] = corner + 0.5 * (nextMid + prevMid) + centre / 3.0;
    w[(i + 1) % 3] = 0.5 * nextMid + centre / 3.0;
    w[(i + 2) % 3] = 0.5 * prevMid + centre / 3.0;
    return w;
}

BilinearSurface::BilinearSurface(std::span<const uint32_t> faceCorners, std::span<const glm::vec3> positions)
{
    const size_t faces = faceCorners.size() / 3;
    if (faces == 0 || positions.empty() || faces > size_t(INT_MAX) / 3 || positions.size() > size_t(INT_MAX)) {
        refusal_ = "mesh too large or empty for OpenSubdiv's int indices";
        return;
    }
    points_.reserve(3 * positions.size());
    for (const glm::vec3& p : positions)
        points_.insert(points_.end(), {double(p.x), double(p.y), double(p.z)});

    const std::vector<int> verticesPerFace(faces, 3);
    const std::vector<int> corners(faceCorners.begin(), faceCorners.end());
    Far::TopologyDescriptor descriptor;
    descriptor.numVertices = int(positions.size());
    descriptor.numFaces = int(faces);
    descriptor.numVertsPerFace = verticesPerFace.data();
    descriptor.vertIndicesPerFace = corners.data();

    installFarCallbacks();
    farErrorSink = &refusal_;
    refiner_.reset(Far::TopologyRefinerFactory<Far::TopologyDescriptor>::Create(
        descriptor, Far::TopologyRefinerFactory<Far::TopologyDescriptor>::Options(Sdc::SCHEME_BILINEAR)));
    farErrorSink = nullptr;
    if (!refiner_) {
        if (refusal_.empty())
            refusal_ = "Far::TopologyRefinerFactory refused the topology";
        return;
    }
    refusal_.clear();
    // No cache: linear surfaces never use it, and without one the factory holds no
    // state that faces initialised on different threads could share.
    Bfr::RefinerSurfaceFactory<>::Options options;
    options.EnableCaching(false);
    factory_ = std::make_unique<Bfr::RefinerSurfaceFactory<>>(*refiner_, options);
}

BilinearSurface::~BilinearSurface() = default;

bool BilinearSurface::initFace(uint32_t f, Face& face) const
{
    if (!factory_ || f >= uint32_t(refiner_->GetNumFacesTotal()))
        return false;
    if (!factory_->InitVertexSurface(int(f), &face.surface_))
        return false;
    face.patchPoints_.resize(3 * size_t(face.surface_.GetNumPatchPoints()));
    face.surface_.PreparePatchPoints(points_.data(), 3, face.patchPoints_.data(), 3);
    return true;
}

glm::dvec3 BilinearSurface::Face::at(const glm::dvec3& weights) const
{
    const SubFaceCoord coord = subFaceCoord(weights);
    const double st[2] = {coord.st.x, coord.st.y};
    double uv[2];
    surface_.GetParameterization().ConvertNormalizedSubFaceToCoord(coord.subFace, st, uv);
    double p[3];
    surface_.Evaluate(uv, patchPoints_.data(), 3, p);
    return {p[0], p[1], p[2]};
}

} // namespace lfd::bake
