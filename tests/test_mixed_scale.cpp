// Meshes with mixed scale (issue 9): a cube remeshed with edge lengths varying 20x across its
// surface, and a plate of long thin triangles along a crease. Snakes started 2-3 local edge
// lengths off capture the crease: the 95th percentile of their samples' distances to it, each in
// the edge length of the mesh where that sample lies, stays below 0.35.
#include <gtest/gtest.h>

#include <cstdio>

#include <snake_test_util.h>

using namespace vcg::tri;
using gs_test::EnableSnakeAdjacency;
using Snake = GeometricSnake<CMeshO>;
using Surface = SnakeSurface<CMeshO>;

namespace {

std::shared_ptr<Surface> Prepare(CMeshO &m)
{
    return gs_test::SurfaceWithEnergy(m);
}

/// The mesh's edge length near p: the median edge of the faces around the vertex nearest to p.
double LocalEdge(const CMeshO &m, const vcg::Point3d &p)
{
    const int v = gs_test::NearestVertex(m, p);
    std::vector<double> l;
    for (const auto &f : m.face) {
        if (f.IsD()) continue;
        bool has = false;
        for (int k = 0; k < 3; ++k) has |= int(vcg::tri::Index(m, f.cV(k))) == v;
        if (!has) continue;
        for (int k = 0; k < 3; ++k)
            l.push_back(vcg::Distance(vcg::Point3d::Construct(f.cP(k)), vcg::Point3d::Construct(f.cP((k + 1) % 3))));
    }
    std::nth_element(l.begin(), l.begin() + l.size() / 2, l.end());
    return l[l.size() / 2];
}

struct ScaleCase
{
    SnakeMethod method;
    double offset; // in local edge lengths
    const char *name;
};

std::string CaseName(const ::testing::TestParamInfo<ScaleCase> &i) { return i.param.name; }

const auto kCases = ::testing::Values(ScaleCase{SnakeMethod::LocalEmbedding, 2, "embedding_2off"},
                                      ScaleCase{SnakeMethod::LocalEmbedding, 3, "embedding_3off"},
                                      ScaleCase{SnakeMethod::Projection3D, 2, "projection_2off"},
                                      ScaleCase{SnakeMethod::Projection3D, 3, "projection_3off"});

} // namespace

// ---------------------------------------------------------------- a cube graded 20x
class GradedCube : public ::testing::TestWithParam<ScaleCase> {};

// The cube's edge lengths vary 20x (5th to 95th percentile: the 100x conformal grading spreads
// over the surface). The snake runs along the cube edge whose mesh grades the most along it, so
// one snake sees fine and coarse triangles at once (the picks' span grades 2x or more: asserted).
// Until session 6 the end picks sat at +-0.7 along the edge whatever the offset; at the coarse end
// (local edge 0.24-0.41) that put the 2- and 3-off picks 0.38 / 0.77 local edges from the
// perpendicular edge and 1.2 / 2.2 from the target, in the other edge's level-0 well: the snake
// was seeded on another feature, and followed it (final p95 0.50 / 1.05 embedding, 0.58 / 0.76
// projection; docs/evaluation.md). The picks now obey the capture-range test's seed rule.
TEST_P(GradedCube, SnakeCapturesAnEdgeWhoseMeshGrades)
{
    const ScaleCase c = GetParam();
    CMeshO m;
    gs_test::MakeGradedIcoCube(m, 5, 100.0);
    auto surf = Prepare(m);
    // the 12 edges: axis a, the other two coordinates at +-1
    double bestRatio = 0;
    vcg::Point3d A, B, inward; // edge ends and the direction into the face the seeds lie on
    for (int axis = 0; axis < 3; ++axis)
        for (int s1 = -1; s1 <= 1; s1 += 2)
            for (int s2 = -1; s2 <= 1; s2 += 2) {
                vcg::Point3d a, b, n(0, 0, 0);
                a[axis] = -0.7, b[axis] = 0.7;
                a[(axis + 1) % 3] = b[(axis + 1) % 3] = s1;
                a[(axis + 2) % 3] = b[(axis + 2) % 3] = s2;
                n[(axis + 2) % 3] = -s2; // on the face of coordinate (axis+1) = s1, away from the edge
                const double r = LocalEdge(m, a) / LocalEdge(m, b);
                if (std::max(r, 1 / r) > bestRatio) { bestRatio = std::max(r, 1 / r); A = a; B = b; inward = n; }
            }
    std::vector<double> all;
    for (const auto &f : m.face)
        for (int k = 0; k < 3; ++k)
            all.push_back(vcg::Distance(vcg::Point3d::Construct(f.cP(k)), vcg::Point3d::Construct(f.cP((k + 1) % 3))));
    std::sort(all.begin(), all.end());
    std::vector<vcg::Point3d> edge;
    for (int i = 0; i <= 400; ++i) edge.push_back(A + (B - A) * (-0.2 + 1.4 * i / 400)); // beyond the picks
    const std::vector<vcg::Point3d> onMesh = gs_test::ProjectOntoMesh(m, edge);
    // The end picks move in from the corners until they are nearer to the target edge than to
    // the perpendicular edge at that corner, by a quarter of the offset (the seed rule of the
    // capture-range test: never nearer to another crease than to the target). At +-0.7 the coarse
    // end's pick lay 0.3 from the perpendicular edge, less than one of its local edges, and 0.8-1.2
    // from the target: inside the other edge's level-0 well, so the snake was seeded on it.
    const int axis = A[0] != B[0] ? 0 : (A[1] != B[1] ? 1 : 2);
    auto endPick = [&](const vcg::Point3d &end) {
        vcg::Point3d q = end;
        for (int it = 0; it < 40; ++it) {
            const double L = LocalEdge(m, q);
            if (1.0 - std::abs(q[axis]) >= 1.25 * c.offset * L) break;
            q[axis] *= 0.98; // towards the middle of the edge
        }
        return q;
    };
    const vcg::Point3d A1 = endPick(A), B1 = endPick(B);
    std::vector<vcg::Point3d> picks;
    for (double t : {0.0, 0.33, 0.67, 1.0}) {
        vcg::Point3d q = A1 + (B1 - A1) * t;
        picks.push_back(q + inward * (c.offset * LocalEdge(m, q)));
    }
    std::printf("%s: end picks at %.3f and %.3f along the edge (local edges %.3f and %.3f, %.1fx)\n", c.name, A1[axis],
                B1[axis], LocalEdge(m, A1), LocalEdge(m, B1),
                std::max(LocalEdge(m, A1), LocalEdge(m, B1)) / std::min(LocalEdge(m, A1), LocalEdge(m, B1)));
    SnakeParams p;
    p.method = c.method;
    Snake s(surf, p);
    s.InitFromSeeds(gs_test::NearestVertices(m, picks), false);
    auto err = [&](const std::vector<vcg::Point3d> &pts) {
        std::vector<double> d;
        for (const auto &x : pts) d.push_back(gs_test::DistToPolyline(x, onMesh) / LocalEdge(m, x));
        std::sort(d.begin(), d.end());
        return d;
    };
    const std::vector<double> before = err(s.positions());
    s.Run(500);
    const std::vector<double> d = err(s.positions());
    const double p95 = d[size_t(0.95 * (d.size() - 1) + 0.5)];
    std::printf("%s: edge lengths %.4f-%.4f (5th-95th percentile, x%.1f), %.1fx along this edge; %d samples, %d "
                "operations, converged %d; start median %.2f, final p95 %.3f max %.3f local edges\n",
                c.name, all[all.size() / 20], all[all.size() * 19 / 20], all[all.size() * 19 / 20] / all[all.size() / 20],
                bestRatio, s.SampleCount(), s.Stats().operations, int(s.Converged()), before[before.size() / 2], p95,
                d.back());
    EXPECT_GE(all[all.size() * 19 / 20] / all[all.size() / 20], 20.0);
    EXPECT_GT(bestRatio, 2.5);
    EXPECT_GE(std::max(LocalEdge(m, A1), LocalEdge(m, B1)) / std::min(LocalEdge(m, A1), LocalEdge(m, B1)), 2.0);
    EXPECT_GT(before[before.size() / 2], 1.5);
    EXPECT_TRUE(s.Converged()) << c.name;
    EXPECT_LT(p95, 0.35) << c.name;
}

INSTANTIATE_TEST_SUITE_P(Mixed, GradedCube, kCases, CaseName);

// ---------------------------------------------------------------- long thin triangles
class ThinPlate : public ::testing::TestWithParam<ScaleCase> {};

// A plate of 10:1 cells, long along a 45-degree crease that runs 2 degrees off the mesh lines,
// so it cuts through the thin triangles. Across the crease the mesh's edge length is the cell's
// short side: the offsets and the accuracy are measured in it.
TEST_P(ThinPlate, SnakeCapturesACreaseAlongThinTriangles)
{
    const ScaleCase c = GetParam();
    const double w = 1.0, L = 10.0; // cell width across the crease, length along it
    const double tilt = std::tan(vcg::math::ToRad(2.0));
    auto creaseY = [&](double x) { return 20.3 * w + tilt * (x - 100); };
    CMeshO m;
    gs_test::MakeHeightPlate(m, 20, 40, L, w, 0.0, 1, [&](double x, double y) { return std::max(0.0, y - creaseY(x)); });
    auto surf = Prepare(m);
    auto at = [&](double x, double off) { // off > 0: the flat side
        vcg::Point3d q(x, creaseY(x) - off * w, 0);
        return q;
    };
    std::vector<vcg::Point3d> line;
    for (int i = 0; i <= 400; ++i) line.push_back(at(20 + 160.0 * i / 400, 0));
    const std::vector<vcg::Point3d> onMesh = gs_test::ProjectOntoMesh(m, line);
    std::vector<vcg::Point3d> picks;
    for (double x : {40.0, 80.0, 120.0, 160.0}) picks.push_back(at(x, c.offset));
    SnakeParams p;
    p.method = c.method;
    Snake s(surf, p);
    s.InitFromSeeds(gs_test::NearestVertices(m, picks), false);
    auto dist = [&](const vcg::Point3d &x) { return gs_test::DistToPolyline(x, onMesh); };
    const gs_test::CurveError before = gs_test::MeasureCurve(s.positions(), w, dist);
    s.Run(500);
    const gs_test::CurveError e = gs_test::MeasureCurve(s.positions(), w, dist);
    std::printf("%s: length scale %.2f; %d samples, %d operations, converged %d; start mean %.2f, final mean %.3f "
                "p95 %.3f max %.3f short edges\n", c.name, s.LengthScale(), s.SampleCount(), s.Stats().operations,
                int(s.Converged()), before.mean, e.mean, e.p95, e.max);
    EXPECT_GT(before.mean, 1.5);
    EXPECT_TRUE(s.Converged()) << c.name;
    EXPECT_LT(e.p95, 0.35) << c.name << " mean " << e.mean << " max " << e.max;
}

INSTANTIATE_TEST_SUITE_P(Mixed, ThinPlate, kCases, CaseName);
