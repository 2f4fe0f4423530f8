#ifndef GS_TESTS_SNAKE_TEST_UTIL_H
#define GS_TESTS_SNAKE_TEST_UTIL_H

// Shared helpers for the snake tests: a mesh (CMeshO, or one with its components, such as a
// double-precision one) with the adjacency the engine needs, seeds
// placed near known features, and distances of a curve to the exact feature.

#include <memory>

#include <common/ml_mesh_type.h>
#include <generated_meshes.h>
#include <vcg_ext/energy/feature_energy.h>
#include <vcg_ext/snake/geometric_snake.h>
#include <vcg/complex/algorithms/closest.h>
#include <vcg/space/index/grid_static_ptr.h>

namespace gs_test {

/// For its scope, meshes of more than `faces` faces run the engine's second-thread passes (see
/// MeshValidation::SetConcurrentFaces): small meshes then take the threaded path too, where
/// ThreadSanitizer sees both sides of a race.
struct ConcurrentFacesScope
{
    typedef vcg::tri::MeshValidation<CMeshO> MV;
    explicit ConcurrentFacesScope(int faces) : before(MV::ConcurrentFaces()) { MV::SetConcurrentFaces(faces); }
    ~ConcurrentFacesScope() { MV::SetConcurrentFaces(before); }
    ConcurrentFacesScope(const ConcurrentFacesScope &) = delete;
    ConcurrentFacesScope &operator=(const ConcurrentFacesScope &) = delete;
    const int before;
};

template <class M>
void EnableSnakeAdjacency(M &m)
{
    if (!m.vert.IsVFAdjacencyEnabled()) m.vert.EnableVFAdjacency();
    if (!m.face.IsVFAdjacencyEnabled()) m.face.EnableVFAdjacency();
    if (!m.face.IsFFAdjacencyEnabled()) m.face.EnableFFAdjacency();
    if (!m.vert.IsCurvatureEnabled()) m.vert.EnableCurvature();
    if (!m.vert.IsCurvatureDirEnabled()) m.vert.EnableCurvatureDir();
    if (!m.vert.IsMarkEnabled()) m.vert.EnableMark();
    if (!m.face.IsMarkEnabled()) m.face.EnableMark();
    vcg::tri::UpdateTopology<M>::FaceFace(m);
    vcg::tri::UpdateTopology<M>::VertexFace(m);
}

/// The rotated ico-cube (MakeRotatedIcoCube) with the engine's adjacency: the session tests' mesh.
inline void MakeSnakeCube(CMeshO &m, int subdiv = 4)
{
    MakeRotatedIcoCube(m, subdiv);
    EnableSnakeAdjacency(m);
}

/// Index of the mesh vertex nearest to p.
/// The set-up most snake tests share: the engine's adjacency, unit face normals, the feature
/// energy in the vertex quality (2 smoothing steps, as the filters' default) and a surface over it.
inline std::shared_ptr<vcg::tri::SnakeSurface<CMeshO>> SurfaceWithEnergy(
    CMeshO &m, vcg::tri::FeatureEnergyType type = vcg::tri::FeatureEnergyType::NormalVariation, int smoothing = 2)
{
    EnableSnakeAdjacency(m);
    vcg::tri::UpdateNormal<CMeshO>::PerFaceNormalized(m);
    vcg::tri::FeatureEnergy<CMeshO>::Compute(m, type, smoothing);
    return std::make_shared<vcg::tri::SnakeSurface<CMeshO>>(m);
}

template <class M>
int NearestVertex(const M &m, const vcg::Point3d &p)
{
    int best = -1;
    double bd = 1e300;
    for (size_t i = 0; i < m.vert.size(); ++i) {
        if (m.vert[i].IsD()) continue;
        double d = (vcg::Point3d::Construct(m.vert[i].cP()) - p).Norm();
        if (d < bd) { bd = d; best = int(i); }
    }
    return best;
}

template <class M>
std::vector<int> NearestVertices(const M &m, const std::vector<vcg::Point3d> &pts)
{
    std::vector<int> out;
    for (auto &p : pts) {
        int v = NearestVertex(m, p);
        if (out.empty() || out.back() != v) out.push_back(v);
    }
    return out;
}

struct CurveError
{
    double mean = 0, p95 = 0, max = 0;
};

template <class DistFn>
CurveError MeasureCurve(const std::vector<vcg::Point3d> &pts, double h, DistFn dist)
{
    CurveError e;
    std::vector<double> d;
    for (auto &p : pts) d.push_back(dist(p) / h);
    if (d.empty()) return e;
    for (double x : d) e.mean += x;
    e.mean /= d.size();
    std::sort(d.begin(), d.end());
    e.p95 = d[std::min(d.size() - 1, size_t(0.95 * (d.size() - 1) + 0.5))];
    e.max = d.back();
    return e;
}

/// A snake of about `samples` samples one local edge length apart, as in the paper (samples
/// taken along the seed path's edges), for the benchmarks: seeds are the vertices nearest to 8
/// points on a circle of circumference samples * h in the tangent plane at the model's top
/// (closed), or to 5 points on half of that circle (open, from seeds).
inline std::unique_ptr<vcg::tri::GeometricSnake<CMeshO>> MakeSnakeCurve(
    CMeshO &m, std::shared_ptr<vcg::tri::SnakeSurface<CMeshO>> surf, int samples, vcg::tri::SnakeMethod method,
    bool closed)
{
    const double h = surf->MeanEdge();
    vcg::tri::UpdateBounding<CMeshO>::Box(m);
    vcg::Point3d c = vcg::Point3d::Construct(m.bbox.Center());
    c[1] = m.bbox.max[1];
    int cv = NearestVertex(m, c);
    vcg::Point3d o = vcg::Point3d::Construct(m.vert[cv].cP()), n = vcg::Point3d::Construct(m.vert[cv].cN()).Normalize();
    vcg::Point3d t1 = (std::abs(n[0]) < 0.9 ? vcg::Point3d(1, 0, 0) : vcg::Point3d(0, 1, 0)) ^ n;
    t1.Normalize();
    vcg::Point3d t2 = n ^ t1;
    double r = samples * h / (closed ? 2 * M_PI : M_PI);
    std::vector<vcg::Point3d> pts;
    for (int i = 0; i < (closed ? 8 : 5); ++i) {
        double a = closed ? 2 * M_PI * i / 8 : M_PI * i / 4;
        pts.push_back(o + t1 * (r * std::cos(a)) + t2 * (r * std::sin(a)));
    }
    auto path = vcg::tri::SeedPath<CMeshO>::Compute(m, NearestVertices(m, pts), closed);
    // the snake's unit is the median edge of its seed path: space the samples in it
    std::vector<double> edges;
    std::vector<int> pv = path.vertices;
    if (closed) pv.push_back(pv.front());
    for (size_t i = 1; i < pv.size(); ++i)
        edges.push_back(vcg::Distance(vcg::Point3d::Construct(m.vert[pv[i - 1]].cP()), vcg::Point3d::Construct(m.vert[pv[i]].cP())));
    std::nth_element(edges.begin(), edges.begin() + edges.size() / 2, edges.end());
    vcg::tri::SnakeParams p;
    p.method = method;
    p.spacing = path.length / (closed ? samples : samples - 1) / edges[edges.size() / 2];
    std::unique_ptr<vcg::tri::GeometricSnake<CMeshO>> s(new vcg::tri::GeometricSnake<CMeshO>(surf, p));
    s->InitFromPath(path.vertices, closed);
    return s;
}

inline std::unique_ptr<vcg::tri::GeometricSnake<CMeshO>> MakeSnakeLoop(
    CMeshO &m, std::shared_ptr<vcg::tri::SnakeSurface<CMeshO>> surf, int samples, vcg::tri::SnakeMethod method)
{
    return MakeSnakeCurve(m, surf, samples, method, true);
}

/// The exact feature as it exists on the mesh: points of the exact feature curve, each moved
/// to its closest point on the surface (vcglib's closest-point search on a uniform grid).
/// A mesh whose triangles straddle a sharp edge cuts it off like a chamfer, up to about half
/// an edge length deep, so no curve on the surface gets closer than that to the exact edge;
/// accuracy is therefore measured against this projected curve.
inline std::vector<vcg::Point3d> ProjectOntoMesh(CMeshO &m, const std::vector<vcg::Point3d> &feature)
{
    vcg::GridStaticPtr<CFaceO, float> grid;
    grid.Set(m.face.begin(), m.face.end());
    vcg::tri::UpdateNormal<CMeshO>::PerFaceNormalized(m);
    std::vector<vcg::Point3d> out;
    for (const auto &q : feature) {
        float dist = 1e30f;
        Point3m closest;
        vcg::tri::GetClosestFaceBase(m, grid, Point3m::Construct(q), 1e30f, dist, closest);
        out.push_back(vcg::Point3d::Construct(closest));
    }
    return out;
}

/// Distance from p to a polyline.
inline double DistToPolyline(const vcg::Point3d &p, const std::vector<vcg::Point3d> &pl, bool closed = false)
{
    double best = 1e300;
    size_t n = pl.size();
    for (size_t i = 0; i + (closed ? 0 : 1) < n; ++i) {
        const vcg::Point3d &a = pl[i], &b = pl[(i + 1) % n];
        vcg::Point3d d = b - a;
        double L2 = d.SquaredNorm();
        double t = L2 > 0 ? std::max(0.0, std::min(1.0, ((p - a) * d) / L2)) : 0.0;
        best = std::min(best, (p - (a + d * t)).Norm());
    }
    return best;
}

/// Dense samples of an exact feature: the cube edge x = y = half for |z| <= zmax, the top
/// rim of the cylinder.
inline std::vector<vcg::Point3d> CubeEdgeLine(double half, double zmax, int n = 400)
{
    std::vector<vcg::Point3d> out;
    for (int i = 0; i < n; ++i) out.push_back(vcg::Point3d(half, half, -zmax + 2 * zmax * i / (n - 1)));
    return out;
}
inline std::vector<vcg::Point3d> CylinderRimLine(double radius, double z, int n = 600)
{
    std::vector<vcg::Point3d> out;
    for (int i = 0; i < n; ++i) {
        double a = 2 * M_PI * i / n;
        out.push_back(vcg::Point3d(radius * std::cos(a), radius * std::sin(a), z));
    }
    return out;
}

} // namespace gs_test

#endif
