#ifndef GS_TESTS_SNAKE_TEST_UTIL_H
#define GS_TESTS_SNAKE_TEST_UTIL_H

// Shared helpers for the snake tests: CMeshO with the adjacency the engine needs, seeds
// placed near known features, and distances of a curve to the exact feature.

#include <common/ml_mesh_type.h>
#include <generated_meshes.h>
#include <vcg_ext/feature_energy.h>
#include <vcg_ext/geometric_snake.h>

namespace gs_test {

inline void EnableSnakeAdjacency(CMeshO &m)
{
    if (!m.vert.IsVFAdjacencyEnabled()) m.vert.EnableVFAdjacency();
    if (!m.face.IsVFAdjacencyEnabled()) m.face.EnableVFAdjacency();
    if (!m.face.IsFFAdjacencyEnabled()) m.face.EnableFFAdjacency();
    if (!m.vert.IsCurvatureEnabled()) m.vert.EnableCurvature();
    if (!m.vert.IsCurvatureDirEnabled()) m.vert.EnableCurvatureDir();
    if (!m.vert.IsMarkEnabled()) m.vert.EnableMark();
    if (!m.face.IsMarkEnabled()) m.face.EnableMark();
    vcg::tri::UpdateTopology<CMeshO>::FaceFace(m);
    vcg::tri::UpdateTopology<CMeshO>::VertexFace(m);
}

/// Index of the mesh vertex nearest to p.
inline int NearestVertex(const CMeshO &m, const vcg::Point3d &p)
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

inline std::vector<int> NearestVertices(const CMeshO &m, const std::vector<vcg::Point3d> &pts)
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

} // namespace gs_test

#endif
