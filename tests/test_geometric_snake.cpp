// Unit and accuracy tests of the geometric snake engine (paper Sections 3-5).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>

#include <Eigen/Dense>

#include <snake_test_util.h>
#include <vcg_ext/energy/energy_source.h>
#include <vcg_ext/io/snake_io.h>
#include <vcg_ext/paths/path_tighten.h>

using namespace vcg::tri;
using gs_test::EnableSnakeAdjacency;
using Snake = GeometricSnake<CMeshO>;
using Surface = SnakeSurface<CMeshO>;

namespace {

std::shared_ptr<Surface> PrepareCube(CMeshO &m, int subdiv = 4, int smoothing = 2, double half = 1.0)
{
    gs_test::MakeRotatedIcoCube(m, subdiv, half);
    EnableSnakeAdjacency(m);
    FeatureEnergy<CMeshO>::Compute(m, FeatureEnergyType::NormalVariation, smoothing);
    return std::make_shared<Surface>(m);
}

std::shared_ptr<Surface> PrepareCylinder(CMeshO &m, int subdiv = 4, int smoothing = 2)
{
    gs_test::MakeRotatedIcoCylinder(m, subdiv);
    EnableSnakeAdjacency(m);
    FeatureEnergy<CMeshO>::Compute(m, FeatureEnergyType::NormalVariation, smoothing);
    return std::make_shared<Surface>(m);
}

// Seeds on the cube face x = half, offset `off` edge lengths from the edge x = y = half.
std::vector<int> CubeEdgeSeeds(const CMeshO &m, double h, double off, double half = 1.0)
{
    std::vector<vcg::Point3d> pts;
    for (double z : {-0.6, -0.2, 0.2, 0.6}) pts.push_back(vcg::Point3d(half, half - off * h, z * half));
    return gs_test::NearestVertices(m, pts);
}

// Seeds around the cylinder, `off` edge lengths below the top rim.
std::vector<int> CylinderRimSeeds(const CMeshO &m, double h, double off, int count)
{
    std::vector<vcg::Point3d> pts;
    for (int i = 0; i < count; ++i) {
        double a = 2 * M_PI * i / count;
        pts.push_back(vcg::Point3d(std::cos(a), std::sin(a), 1.0 - off * h));
    }
    return gs_test::NearestVertices(m, pts);
}

// Distances of the samples from the cube edges, ignoring the ends (open snakes shorten
// there and are not asked to reach the corners).
gs_test::CurveError CubeError(Snake &s, double h, double half = 1.0)
{
    std::vector<vcg::Point3d> p = s.positions();
    return gs_test::MeasureCurve(p, h, [&](const vcg::Point3d &x) { return gs_test::DistToCubeEdges(x, half); });
}

} // namespace

// ---------------------------------------------------------------- spline (Eq. 2-4)
TEST(SnakeSpline, StiffnessIsGradientOfSplineEnergy)
{
    for (bool closed : {false, true}) {
        const int n = 9;
        std::mt19937 rng(3);
        std::uniform_real_distribution<double> U(-1, 1);
        Eigen::MatrixXd X(n, 2);
        for (int i = 0; i < n; ++i) X.row(i) << U(rng), U(rng);
        const double a = 0.7, b = 1.3;
        Eigen::MatrixXd G = SnakeSpline::StiffnessMatrix(n, closed, a, b) * X;
        const double eps = 1e-6;
        for (int i = 0; i < n; ++i)
            for (int c = 0; c < 2; ++c) {
                Eigen::MatrixXd Xp = X, Xm = X;
                Xp(i, c) += eps;
                Xm(i, c) -= eps;
                double fd = (SnakeSpline::Energy(Xp, closed, a, b) - SnakeSpline::Energy(Xm, closed, a, b)) / (2 * eps);
                EXPECT_NEAR(G(i, c), fd, 1e-6) << "closed=" << closed << " i=" << i;
            }
    }
}

TEST(SnakeSpline, FixedSamplesHeldExactlyAndUpdateSolvesEq4)
{
    const int n = 10;
    Eigen::MatrixXd X(n, 2), F(n, 2);
    for (int i = 0; i < n; ++i) { X.row(i) << i, std::sin(i); F.row(i) << 0.1 * i, -0.2; }
    std::vector<bool> fixed(n, false);
    fixed[0] = fixed[4] = true;
    SnakeSpline s;
    s.Setup(n, false, 0.3, 0.8, 2.0, fixed);
    Eigen::MatrixXd Y = s.Update(X, F);
    EXPECT_EQ(Y.row(0), X.row(0));
    EXPECT_EQ(Y.row(4), X.row(4));
    // free rows satisfy (A + gamma I) y = gamma x - f
    Eigen::MatrixXd R = SnakeSpline::StiffnessMatrix(n, false, 0.3, 0.8) * Y + 2.0 * Y - (2.0 * X - F);
    for (int i = 0; i < n; ++i)
        if (!fixed[i]) EXPECT_LT(R.row(i).norm(), 1e-9) << i;
    EXPECT_EQ(s.factorizations, 1);
    s.Setup(n, false, 0.3, 0.8, 2.0, fixed); // unchanged: no new factorization
    EXPECT_EQ(s.factorizations, 1);
}

// ---------------------------------------------------------------- region and embedding
TEST(Embedding, LocalRegionIsDiskAndEmbeddingInjective)
{
    CMeshO m;
    auto surf = PrepareCube(m, 4, 4);
    double h = surf->MeanEdge();
    Snake s(surf);
    s.InitFromSeeds(CubeEdgeSeeds(m, h, 2.0), false);
    std::vector<int> core;
    for (auto &x : s.Samples()) core.push_back(x.p.face);
    for (auto &g : s.Gaps()) core.insert(core.end(), g.faces.begin(), g.faces.end());
    LocalRegion<CMeshO> r;
    ASSERT_TRUE(r.Build(*surf, core)) << r.error;
    EXPECT_GT(r.RealFaces(), int(core.size()) / 2);
    VirtualBoundaryParam::Result e;
    ASSERT_TRUE(VirtualBoundaryParam::Embed(r.pos, r.tri, r.boundary, h, 2, e)) << e.error;
    EXPECT_EQ(VirtualBoundaryParam::CountFlipped(e.uv, r.tri), 0);
    EXPECT_EQ(VirtualBoundaryParam::CountFlipped(e.uv, e.virtualTri), 0);
    // scale: mean 2D edge length about 1 (units of h)
    double l2 = 0;
    for (auto &t : r.tri) l2 += (e.uv[t[1]] - e.uv[t[0]]).norm();
    EXPECT_NEAR(l2 / r.tri.size(), 1.0, 0.35);
    // barycentric round trip: surface -> plane -> walk -> surface is exact
    for (auto &x : s.Samples()) {
        int t = r.LocalFace(*surf, x.p.face);
        ASSERT_GE(t, 0);
        Eigen::Vector2d p = x.p.bary[0] * e.uv[r.tri[t][0]] + x.p.bary[1] * e.uv[r.tri[t][1]] + x.p.bary[2] * e.uv[r.tri[t][2]];
        RegionWalk::Result w = RegionWalk::Walk(e.uv, r.tri, r.adj, t, p, p, false);
        EXPECT_EQ(w.face, t);
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(w.bary[k], x.p.bary[k], 1e-9);
    }
}

TEST(Embedding, RegionTouchingMeshBorderAndHoles)
{
    // a flat grid with a square hole: a snake crossing it and running along the border
    CMeshO m;
    gs_test::MakeFlatGrid(m, 30, 1.0);
    for (auto &f : m.face) {
        vcg::Point3d c = vcg::Point3d::Construct(vcg::Barycenter(f));
        if (std::abs(c[0] - 0.5) < 0.033 && std::abs(c[1] - 0.5) < 0.033) vcg::tri::Allocator<CMeshO>::DeleteFace(m, f); // a clean 2x2-cell hole
    }
    vcg::tri::Allocator<CMeshO>::CompactEveryVector(m);
    vcg::tri::Clean<CMeshO>::RemoveUnreferencedVertex(m);
    vcg::tri::Allocator<CMeshO>::CompactEveryVector(m);
    EnableSnakeAdjacency(m);
    for (auto &v : m.vert) v.Q() = 1;
    auto surf = std::make_shared<Surface>(m);
    std::vector<int> core;
    for (size_t i = 0; i < m.face.size(); ++i) {
        vcg::Point3d c = vcg::Point3d::Construct(vcg::Barycenter(m.face[i]));
        if (std::abs(c[1] - 0.5) < 0.04 || c[1] < 0.04) core.push_back(int(i));
    }
    LocalRegion<CMeshO> r;
    // two strips joined only through the grid: build them separately
    std::vector<int> strip;
    for (int f : core) {
        vcg::Point3d c = vcg::Point3d::Construct(vcg::Barycenter(m.face[f]));
        if (std::abs(c[1] - 0.5) < 0.04) strip.push_back(f);
    }
    ASSERT_TRUE(r.Build(*surf, strip)) << r.error;
    EXPECT_EQ(r.meshHolesClosed, 1);
    VirtualBoundaryParam::Result e;
    ASSERT_TRUE(VirtualBoundaryParam::Embed(r.pos, r.tri, r.boundary, surf->MeanEdge(), 2, e));
    EXPECT_EQ(VirtualBoundaryParam::CountFlipped(e.uv, r.tri), 0);
    std::vector<int> bottom;
    for (int f : core) {
        vcg::Point3d c = vcg::Point3d::Construct(vcg::Barycenter(m.face[f]));
        if (c[1] < 0.04) bottom.push_back(f);
    }
    ASSERT_TRUE(r.Build(*surf, bottom)) << r.error;
    ASSERT_TRUE(VirtualBoundaryParam::Embed(r.pos, r.tri, r.boundary, surf->MeanEdge(), 2, e));
    EXPECT_EQ(VirtualBoundaryParam::CountFlipped(e.uv, r.tri), 0);
}

// ---------------------------------------------------------------- energy field interface
TEST(EnergyField, VertexFieldGradientMatchesFiniteDifferences)
{
    CMeshO m;
    auto surf = PrepareCube(m, 3, 2);
    const SnakeEnergyField<CMeshO> &f = surf->EnergyField();
    // the default capture pyramid: level 0 and levels reaching 2, 4 and 8 mean edge lengths
    ASSERT_EQ(f.Levels(), 4);
    EXPECT_EQ(f.Reach(0), 0);
    for (int level = 1; level < 4; ++level) EXPECT_NEAR(f.Reach(level), std::ldexp(1.0, level) * surf->MeanEdge(), 1e-12);
    int checked = 0;
    for (int face = 0; face < int(m.face.size()); face += 37)
        for (int level = 0; level < f.Levels(); ++level) {
            SurfacePoint p(face, vcg::Point3d(0.3, 0.3, 0.4));
            vcg::Point3d g = f.Gradient(level, p);
            for (int k = 1; k < 3; ++k) { // along edge v0 -> vk: E(vk) - E(v0) = g . (pk - p0)
                vcg::Point3d e = vcg::Point3d::Construct(m.face[face].P(k) - m.face[face].P(0));
                double d = f.Value(level, SurfacePoint::AtCorner(face, k)) - f.Value(level, SurfacePoint::AtCorner(face, 0));
                EXPECT_NEAR(g * e, d, 1e-5) << face << " " << level;
                ++checked;
            }
        }
    EXPECT_GT(checked, 100);
}

namespace {
// A field evaluated at the point itself (not interpolated from vertices): the distance to the
// cube's nearest edge, in units of 3 edge lengths, clamped to 1.
class CubeEdgeDistanceField : public SnakeEnergyField<CMeshO>
{
public:
    CubeEdgeDistanceField(const CMeshO &m, double h) : mesh(m), scale(3 * h) {}
    int Levels() const override { return 1; }
    double Value(int, const SurfacePoint &p) const override
    {
        return std::min(1.0, gs_test::DistToCubeEdges(p.Pd(mesh)) / scale);
    }
    vcg::Point3d Gradient(int level, const SurfacePoint &p) const override
    {
        // central differences along two unit directions of the face, solved in its plane
        (void)level;
        const CFaceO &f = mesh.face[p.face];
        vcg::Point3d u = vcg::Point3d::Construct(f.cP(1) - f.cP(0)), v = vcg::Point3d::Construct(f.cP(2) - f.cP(0));
        u.Normalize();
        v.Normalize();
        auto at = [&](const vcg::Point3d &x) { return std::min(1.0, gs_test::DistToCubeEdges(x) / scale); };
        const vcg::Point3d x = p.Pd(mesh);
        const double eps = 1e-3 * scale;
        double du = (at(x + u * eps) - at(x - u * eps)) / (2 * eps), dv = (at(x + v * eps) - at(x - v * eps)) / (2 * eps);
        double uv = u * v, det = 1 - uv * uv; // g = a u + b v with g . u = du, g . v = dv
        if (det < 1e-12) return vcg::Point3d(0, 0, 0);
        return u * ((du - uv * dv) / det) + v * ((dv - uv * du) / det);
    }

private:
    const CMeshO &mesh;
    double scale;
};
} // namespace

TEST(EnergyField, SnakeFollowsAFieldEvaluatedAtSurfacePoints)
{
    CMeshO m;
    auto surf = PrepareCube(m);
    const double h = surf->MeanEdge();
    // the vertex energy is made useless (constant): only the plugged-in field can pull the snake
    for (auto &v : m.vert) v.Q() = 1;
    surf->SetEnergyFromQuality();
    surf->SetEnergyField(std::make_shared<CubeEdgeDistanceField>(m, h));
    for (SnakeMethod method : {SnakeMethod::LocalEmbedding, SnakeMethod::Projection3D}) {
        SnakeParams p;
        p.method = method;
        Snake s(surf, p);
        s.InitFromSeeds(CubeEdgeSeeds(m, h, 2.0), false);
        gs_test::CurveError e0 = CubeError(s, h);
        EXPECT_GT(e0.mean, 1.0);
        s.Run(300);
        gs_test::CurveError e = CubeError(s, h);
        EXPECT_LT(e.mean, 0.6) << "method " << int(method) << ", started at " << e0.mean;
    }
}

// ---------------------------------------------------------------- snake invariants
// A closed loop 2.5 mean edges below the cylinder's rim.
std::unique_ptr<Snake> LoopBelowRim(CMeshO &m, double &h)
{
    auto surf = PrepareCylinder(m);
    h = surf->MeanEdge();
    std::unique_ptr<Snake> s(new Snake(surf));
    s->InitFromSeeds(CylinderRimSeeds(m, h, 2.5, 6), true);
    return s;
}

TEST(GeometricSnake, FixedSamplesNeverMoveAndClosedStaysClosed)
{
    CMeshO m;
    double h;
    const auto snake = LoopBelowRim(m, h);
    Snake &s = *snake;
    ASSERT_TRUE(s.Closed());
    int n = s.SampleCount();
    ASSERT_GT(n, 20);
    s.SetFixed(3, true);
    s.SetFixed(n / 2, true);
    SurfacePoint p3 = s.Samples()[3].p, pm = s.Samples()[n / 2].p;
    for (int i = 0; i < 15; ++i) s.Step();
    EXPECT_EQ(s.Samples()[3].p.face, p3.face);
    EXPECT_EQ(s.Samples()[3].p.bary, p3.bary);
    EXPECT_EQ(s.Samples()[n / 2].p.face, pm.face);
    EXPECT_EQ(s.Samples()[n / 2].p.bary, pm.bary);
    EXPECT_TRUE(s.Closed());
    // the closing gap is traced: the last polyline point is near the first sample
    std::vector<vcg::Point3d> pl = s.PolylinePositions();
    EXPECT_LT((pl.back() - pl.front()).Norm(), 3 * h);
    for (auto &x : pl) EXPECT_TRUE(std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]));
}

TEST(GeometricSnake, TracedPolylineStaysOnSurface)
{
    CMeshO m;
    auto surf = PrepareCube(m);
    double h = surf->MeanEdge();
    Snake s(surf);
    s.InitFromSeeds(CubeEdgeSeeds(m, h, 2.0), false);
    for (int i = 0; i < 10; ++i) s.Step();
    std::vector<SurfacePoint> pl = s.Polyline();
    ASSERT_GT(pl.size(), s.Samples().size());
    // consecutive points share a face: the straight segment between them lies in that face
    for (size_t i = 0; i + 1 < pl.size(); ++i) {
        std::set<CVertexO *> a, b;
        for (int k = 0; k < 3; ++k) { a.insert(m.face[pl[i].face].V(k)); b.insert(m.face[pl[i + 1].face].V(k)); }
        // the points lie on a common face if every non-zero barycentric vertex of one is in the other's face
        auto onFace = [&](const SurfacePoint &p, const std::set<CVertexO *> &verts) {
            for (int k = 0; k < 3; ++k)
                if (p.bary[k] > 1e-9 && !verts.count(m.face[p.face].V(k))) return false;
            return true;
        };
        EXPECT_TRUE(onFace(pl[i], b) || onFace(pl[i + 1], a)) << "polyline point " << i;
    }
}

// The motion leaves a gap's crossings on the straight segment of its embedding; the polyline
// a caller reads is the shortest path through the same faces (issue 12: tightened where it is
// read, between the samples the gap was traced between). On a cylinder the conformal map is not
// an isometry, so the straight trace is measurably off that path.
TEST(GeometricSnake, PolylineIsTheShortestPathThroughItsFaces)
{
    CMeshO m;
    double h;
    const auto snake = LoopBelowRim(m, h);
    Snake &s = *snake;
    for (int i = 0; i < 10; ++i) s.Step();
    // how far tightening the traced gaps again moves their crossings (and how many are traced)
    auto retighten = [&](int &traced) {
        double moved = 0;
        traced = 0;
        for (const auto &g : s.Gaps()) {
            if (!g.traced) continue;
            ++traced;
            std::vector<SurfacePoint> c = g.crossings;
            PathTighten<CMeshO>::Tighten(m, g.tracedFrom, c, g.tracedTo);
            for (size_t k = 0; k < c.size(); ++k) moved = std::max(moved, (c[k].Pd(m) - g.crossings[k].Pd(m)).Norm());
        }
        return moved;
    };
    int traced = 0;
    // before the polyline is read: the straight traces are off the shortest path
    EXPECT_GT(retighten(traced), 1e-4 * h);
    ASSERT_GT(s.Polyline().size(), s.Samples().size());
    // read: every traced gap is already shortest
    EXPECT_LT(retighten(traced), 1e-5 * h);
    EXPECT_GT(traced, 0);
}

TEST(GeometricSnake, ScaleAndTranslationInvariant)
{
    std::vector<vcg::Point3d> results[2];
    for (int k = 0; k < 2; ++k) {
        CMeshO m;
        double half = k == 0 ? 1.0 : 250.0;
        auto surf = PrepareCube(m, 4, 2, half);
        double h = surf->MeanEdge();
        Snake s(surf);
        s.InitFromSeeds(CubeEdgeSeeds(m, h, 2.0, half), false);
        for (int i = 0; i < 8; ++i) s.Step();
        for (auto p : s.positions()) results[k].push_back(p / half);
    }
    ASSERT_EQ(results[0].size(), results[1].size());
    for (size_t i = 0; i < results[0].size(); ++i) EXPECT_LT((results[0][i] - results[1][i]).Norm(), 1e-3);
}

TEST(GeometricSnake, EditingUndoRedoAndJsonRoundTrip)
{
    CMeshO m;
    auto surf = PrepareCube(m);
    double h = surf->MeanEdge();
    Snake s(surf);
    s.InitFromSeeds(CubeEdgeSeeds(m, h, 2.0), false);
    int n = s.SampleCount();
    auto before = s.Samples();
    s.MoveSample(2, SurfacePoint::AtCorner(s.Samples()[5].p.face, 0), true);
    EXPECT_TRUE(s.Samples()[2].fixed);
    int ins = s.InsertSample(0);
    EXPECT_EQ(ins, 1);
    EXPECT_EQ(s.SampleCount(), n + 1);
    s.DeleteSample(ins);
    EXPECT_EQ(s.SampleCount(), n);
    s.Step(); // the moved sample stretched its gaps: samples may go in before it (FollowSample)
    EXPECT_TRUE(s.Samples()[s.FollowSample(2)].fixed);
    EXPECT_TRUE(s.Undo()); // step
    EXPECT_TRUE(s.Undo()); // delete
    EXPECT_TRUE(s.Undo()); // insert
    EXPECT_TRUE(s.Undo()); // move
    ASSERT_EQ(s.SampleCount(), n);
    for (int i = 0; i < n; ++i) {
        EXPECT_EQ(s.Samples()[i].p.face, before[i].p.face);
        EXPECT_EQ(s.Samples()[i].fixed, before[i].fixed);
    }
    EXPECT_TRUE(s.Redo());
    EXPECT_TRUE(s.Samples()[2].fixed);
    // JSON round trip keeps samples and pins
    nlohmann::json j = SnakeIO<CMeshO>::ToJson(s);
    Snake t(surf);
    SnakeIO<CMeshO>::FromJson(t, j);
    ASSERT_EQ(t.SampleCount(), s.SampleCount());
    for (int i = 0; i < n; ++i) {
        EXPECT_EQ(t.Samples()[i].p.face, s.Samples()[i].p.face);
        EXPECT_EQ(t.Samples()[i].fixed, s.Samples()[i].fixed);
    }
    for (auto key : {"closed", "initial", "samples", "polyline", "stats"}) EXPECT_TRUE(j.contains(key)) << key;
}

TEST(GeometricSnake, FaceRepeatingAVertexIsRefusedBeforeAdjacency)
{
    // vcglib's adjacency asserts on such faces (aborting MeshLab): the surface must refuse first
    CMeshO m;
    gs_test::MakeFromArrays(m, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}, {{0, 1, 2}, {1, 3, 2}, {1, 1, 3}});
    EXPECT_THROW(MeshValidation<CMeshO>::RequireAdjacencySafe(m), SnakeError);
    m.vert.EnableVFAdjacency();
    m.face.EnableVFAdjacency();
    m.face.EnableFFAdjacency();
    try {
        Surface s(m);
        FAIL() << "accepted a face that repeats a vertex";
    } catch (const SnakeError &e) {
        EXPECT_NE(std::string(e.what()).find("same vertex twice"), std::string::npos) << e.what();
    }
}

// The surface takes the caller's adjacency as it is only if it is right: FF is checked (on a
// second thread above MeshValidation::ConcurrentFaces() faces) and rebuilt when stale, VF is
// always rebuilt. Both stale here, on a small mesh (one thread, then two: where ThreadSanitizer
// sees races) and on a large one.
TEST(GeometricSnake, StaleAdjacencyIsRebuiltAlsoWhenCheckedOnASecondThread)
{
    for (int c = 0; c < 3; ++c) {
        const int n = c < 2 ? 20 : 250;
        gs_test::ConcurrentFacesScope threads(c == 1 ? 0 : MeshValidation<CMeshO>::ConcurrentFaces());
        CMeshO m;
        gs_test::MakeFlatGrid(m, n);
        EnableSnakeAdjacency(m);
        ASSERT_EQ(c > 0, m.fn > MeshValidation<CMeshO>::ConcurrentFaces());
        ASSERT_TRUE(Surface::FaceFaceCurrent(m));
        const int f = m.fn / 2 + n; // an interior face
        CMeshO::FaceType *g = m.face[f].FFp(0);
        m.face[f].FFp(0) = &m.face[f]; // a border where there is none
        m.vert[m.vn / 2].VFp() = nullptr; // a vertex that lost its faces
        m.vert[m.vn / 2].VFi() = -1;
        ASSERT_FALSE(Surface::FaceFaceCurrent(m));
        Surface s(m);
        EXPECT_TRUE(Surface::FaceFaceCurrent(m)) << n;
        EXPECT_EQ(m.face[f].FFp(0), g) << n;
        int faces = 0;
        for (vcg::face::VFIterator<CMeshO::FaceType> vfi(&m.vert[m.vn / 2]); !vfi.End(); ++vfi) ++faces;
        EXPECT_EQ(faces, 6) << n; // an interior vertex of the grid's diagonal
    }
}

// The snake filter builds MeshLab's adjacency while the energy is computed, on the second core
// of a large mesh: the energy is the one computed after the adjacency, bit for bit, and the
// adjacency is complete. A failing adjacency build is the caller's error, after the energy has
// ended. On a small mesh with one thread and with two (where ThreadSanitizer sees races), and
// on a large one.
TEST(SnakeEnergySource, EnergyComputedBesideTheAdjacencyOnASecondThread)
{
    for (int c = 0; c < 3; ++c)
        for (FeatureEnergyType type : {FeatureEnergyType::NormalVariation, FeatureEnergyType::Crease}) {
            const int n = c < 2 ? 32 : 256;
            gs_test::ConcurrentFacesScope threads(c == 1 ? 0 : MeshValidation<CMeshO>::ConcurrentFaces());
            CMeshO ref, m;
            gs_test::MakeFlatGrid(ref, n);
            for (auto &v : ref.vert) // 16 ridges and valleys of 53 degrees, on vertex columns
                v.P()[2] = std::fabs(v.P()[0] * 8 - std::floor(v.P()[0] * 8) - 0.5f) / 16;
            vcg::tri::Append<CMeshO, CMeshO>::MeshCopy(m, ref);
            ASSERT_EQ(c > 0, m.fn > MeshValidation<CMeshO>::ConcurrentFaces());
            EnableSnakeAdjacency(ref);
            FeatureEnergy<CMeshO>::Compute(ref, type, 2);

            SnakeEnergySource<CMeshO> src(m);
            src.SetSettings(type, 2);
            ASSERT_FALSE(m.face.IsFFAdjacencyEnabled());
            int calls = 0;
            src.ComputeBeside([&] {
                ++calls;
                EnableSnakeAdjacency(m);
            });
            EXPECT_EQ(calls, 1);
            EXPECT_TRUE(src.Computed());
            ASSERT_TRUE(Surface::FaceFaceCurrent(m)) << n;
            float lo = 1, hi = 0;
            for (size_t i = 0; i < m.vert.size(); ++i) {
                ASSERT_EQ(m.vert[i].cQ(), ref.vert[i].cQ()) << n << " vertex " << i;
                lo = std::min(lo, m.vert[i].cQ()), hi = std::max(hi, m.vert[i].cQ());
            }
            EXPECT_LT(lo, 0.5f * hi) << n; // the ridges are in it
            src.ComputeBeside([&] { ++calls; }); // computed: only the adjacency runs
            EXPECT_EQ(calls, 2);

            CMeshO bad;
            vcg::tri::Append<CMeshO, CMeshO>::MeshCopy(bad, ref);
            SnakeEnergySource<CMeshO> failing(bad);
            failing.SetSettings(type, 2);
            EXPECT_THROW(failing.ComputeBeside([] { throw SnakeError("no adjacency"); }), SnakeError);
        }
}

TEST(GeometricSnake, BadInputIsAClearError)
{
    CMeshO m;
    auto surf = PrepareCube(m);
    Snake s(surf);
    EXPECT_THROW(s.Step(), SnakeError); // no samples yet
    EXPECT_THROW(s.InitFromSeeds({1}, false), SnakeError);
    EXPECT_THROW(s.InitFromSeeds({1, int(m.vert.size()) + 5}, false), SnakeError);
    s.InitFromSeeds({1, 40, 90}, false);
    EXPECT_THROW(s.MoveSample(999, SurfacePoint(0, vcg::Point3d(1, 0, 0))), SnakeError);
    EXPECT_THROW(s.MoveSample(0, SurfacePoint(-3, vcg::Point3d(1, 0, 0))), SnakeError);
    EXPECT_THROW(s.MoveSample(0, SurfacePoint(0, vcg::Point3d(NAN, 0, 0))), SnakeError);
    SnakeParams p;
    p.gamma = 0;
    EXPECT_THROW(s.SetParams(p), SnakeError);
    p = SnakeParams();
    p.alpha = NAN;
    EXPECT_THROW(s.SetParams(p), SnakeError);
    p = SnakeParams();
    p.spacing = 1e-9;
    EXPECT_THROW(s.SetParams(p), SnakeError);
    EXPECT_THROW(s.Run(-1), SnakeError);
}

// ---------------------------------------------------------------- accuracy with exact answers
struct AccuracyCase
{
    SnakeMethod method;
    double offset;
};

class CubeEdgeAccuracy : public ::testing::TestWithParam<AccuracyCase> {};

TEST_P(CubeEdgeAccuracy, OpenSnakeConvergesOntoTheEdge)
{
    CMeshO m;
    auto surf = PrepareCube(m);
    double h = surf->MeanEdge();
    SnakeParams p;
    p.method = GetParam().method;
    Snake s(surf, p);
    s.InitFromSeeds(CubeEdgeSeeds(m, h, GetParam().offset), false);
    // the edge as it exists on the mesh (its straddling triangles cut it like a chamfer)
    std::vector<vcg::Point3d> onMesh = gs_test::ProjectOntoMesh(m, gs_test::CubeEdgeLine(1.0, 0.95));
    auto dist = [&](const vcg::Point3d &x) { return gs_test::DistToPolyline(x, onMesh); };
    EXPECT_GT(gs_test::MeasureCurve(s.positions(), h, dist).mean, 1.5);
    s.Run(300);
    EXPECT_TRUE(s.Converged());
    gs_test::CurveError e = gs_test::MeasureCurve(s.positions(), h, dist);
    EXPECT_LT(e.p95, 0.25) << "mean " << e.mean << " max " << e.max;
    EXPECT_LT(e.max, 0.5) << "mean " << e.mean << " p95 " << e.p95;
    // and no farther from the exact edge than the mesh itself allows (about 0.45 h here)
    EXPECT_LT(CubeError(s, h).max, 0.6);
}

INSTANTIATE_TEST_SUITE_P(Methods, CubeEdgeAccuracy,
                         ::testing::Values(AccuracyCase{SnakeMethod::LocalEmbedding, 2.0},
                                           AccuracyCase{SnakeMethod::LocalEmbedding, 3.0},
                                           AccuracyCase{SnakeMethod::Projection3D, 2.0},
                                           AccuracyCase{SnakeMethod::Projection3D, 3.0}));

class CylinderRimAccuracy : public ::testing::TestWithParam<AccuracyCase> {};

TEST_P(CylinderRimAccuracy, ClosedSnakeConvergesOntoTheRim)
{
    CMeshO m;
    auto surf = PrepareCylinder(m);
    double h = surf->MeanEdge();
    SnakeParams p;
    p.method = GetParam().method;
    Snake s(surf, p);
    s.InitFromSeeds(CylinderRimSeeds(m, h, GetParam().offset, 8), true);
    std::vector<vcg::Point3d> onMesh = gs_test::ProjectOntoMesh(m, gs_test::CylinderRimLine(1.0, 1.0));
    auto dist = [&](const vcg::Point3d &x) { return gs_test::DistToPolyline(x, onMesh, true); };
    EXPECT_GT(gs_test::MeasureCurve(s.positions(), h, dist).mean, 1.5);
    s.Run(300);
    gs_test::CurveError e = gs_test::MeasureCurve(s.positions(), h, dist);
    EXPECT_TRUE(s.Converged());
    EXPECT_LT(e.p95, 0.25) << "mean " << e.mean << " max " << e.max;
    EXPECT_LT(e.max, 0.5) << "mean " << e.mean << " p95 " << e.p95;
    // the traced curve, not just the samples, lies on the rim
    EXPECT_LT(gs_test::MeasureCurve(s.PolylinePositions(), h, dist).p95, 0.3);
    EXPECT_LT(gs_test::MeasureCurve(s.positions(), h, [](const vcg::Point3d &x) { return gs_test::DistToCylinderRims(x); }).max, 0.65);
}

TEST_P(CylinderRimAccuracy, OpenSnakeConvergesOntoTheRim)
{
    CMeshO m;
    auto surf = PrepareCylinder(m);
    double h = surf->MeanEdge();
    SnakeParams p;
    p.method = GetParam().method;
    Snake s(surf, p);
    // picks below the rim over 135 degrees of arc
    std::vector<vcg::Point3d> pts;
    for (int i = 0; i < 4; ++i) {
        double a = 0.75 * M_PI * i / 3;
        pts.push_back(vcg::Point3d(std::cos(a), std::sin(a), 1.0 - GetParam().offset * h));
    }
    s.InitFromSeeds(gs_test::NearestVertices(m, pts), false);
    std::vector<vcg::Point3d> onMesh = gs_test::ProjectOntoMesh(m, gs_test::CylinderRimLine(1.0, 1.0));
    auto dist = [&](const vcg::Point3d &x) { return gs_test::DistToPolyline(x, onMesh, true); };
    EXPECT_GT(gs_test::MeasureCurve(s.positions(), h, dist).mean, 1.5);
    s.Run(300);
    EXPECT_TRUE(s.Converged());
    // measured: mean 0.08-0.10 h, 95th percentile 0.23-0.30 h (the ends of an open arc settle last)
    gs_test::CurveError e = gs_test::MeasureCurve(s.positions(), h, dist);
    EXPECT_LT(e.mean, 0.15) << "p95 " << e.p95 << " max " << e.max;
    EXPECT_LT(e.p95, 0.35) << "mean " << e.mean << " max " << e.max;
}

class CubeLoopAccuracy : public ::testing::TestWithParam<AccuracyCase> {};

TEST_P(CubeLoopAccuracy, ClosedSnakeConvergesOntoTheFaceBorder)
{
    // the 4 edges around the face z = 1: a closed feature with 4 right-angle corners, which the
    // rigidity of the snake rounds; away from the corners the curve lies on the edges
    CMeshO m;
    auto surf = PrepareCube(m);
    double h = surf->MeanEdge();
    SnakeParams p;
    p.method = GetParam().method;
    Snake s(surf, p);
    const double a = 1.0 - GetParam().offset * h;
    std::vector<vcg::Point3d> pts;
    for (auto q : std::vector<std::array<double, 2>>{{-a, -a}, {0, -a}, {a, -a}, {a, 0}, {a, a}, {0, a}, {-a, a}, {-a, 0}})
        pts.push_back(vcg::Point3d(q[0], q[1], 1.0));
    s.InitFromSeeds(gs_test::NearestVertices(m, pts), true);
    std::vector<vcg::Point3d> border;
    for (int side = 0; side < 4; ++side)
        for (int i = 0; i < 100; ++i) {
            double t = -1 + 2.0 * i / 100;
            vcg::Point3d q = side == 0 ? vcg::Point3d(t, -1, 1) : side == 1 ? vcg::Point3d(1, t, 1)
                           : side == 2 ? vcg::Point3d(-t, 1, 1) : vcg::Point3d(-1, -t, 1);
            border.push_back(q);
        }
    std::vector<vcg::Point3d> onMesh = gs_test::ProjectOntoMesh(m, border);
    s.Run(300);
    EXPECT_TRUE(s.Converged());
    std::vector<vcg::Point3d> away; // samples more than 3 edge lengths from a corner
    for (auto &x : s.positions())
        if (std::min(1 - std::abs(x[0]), 1 - std::abs(x[1])) > 3 * h || std::max(1 - std::abs(x[0]), 1 - std::abs(x[1])) > 3 * h)
            if (!(1 - std::abs(x[0]) < 3 * h && 1 - std::abs(x[1]) < 3 * h)) away.push_back(x);
    ASSERT_GT(away.size(), s.positions().size() / 2);
    // measured: mean 0.07-0.11 h, 95th percentile 0.27-0.29 h away from the corners
    gs_test::CurveError e = gs_test::MeasureCurve(away, h, [&](const vcg::Point3d &x) { return gs_test::DistToPolyline(x, onMesh, true); });
    EXPECT_LT(e.mean, 0.15) << "p95 " << e.p95 << " max " << e.max;
    EXPECT_LT(e.p95, 0.35) << "mean " << e.mean << " max " << e.max;
    // and the whole loop, corners included, stays near them: the rigidity rounds the 90-degree
    // corners. Measured below 1.0 h before issue 9, 1.15-1.16 h (embedding) and 0.71-1.06 h
    // (projection) since. Why, for the embedding method: a cube corner is a cone vertex (angle
    // defect 90 degrees); the least-squares conformal embedding must open it to 360 degrees, so
    // near it straight lines of the surface are curved in the plane and the spline, straightening
    // them there, rounds the corner more. With the virtual-boundary embedding forced, the same
    // loops end 0.46-0.51 h from the corners; falling back to it near cone vertices was tried
    // (below 20 degrees of defect: conformal) and pushed CubeEdgeAccuracy past its 0.25 h bound,
    // so the conformal embedding stays, the samples away from corners are unchanged.
    EXPECT_LT(gs_test::MeasureCurve(s.positions(), h, [&](const vcg::Point3d &x) { return gs_test::DistToPolyline(x, onMesh, true); }).max, 1.25);
}

INSTANTIATE_TEST_SUITE_P(Methods, CubeLoopAccuracy,
                         ::testing::Values(AccuracyCase{SnakeMethod::LocalEmbedding, 2.0},
                                           AccuracyCase{SnakeMethod::LocalEmbedding, 3.0},
                                           AccuracyCase{SnakeMethod::Projection3D, 2.0},
                                           AccuracyCase{SnakeMethod::Projection3D, 3.0}));

INSTANTIATE_TEST_SUITE_P(Methods, CylinderRimAccuracy,
                         ::testing::Values(AccuracyCase{SnakeMethod::LocalEmbedding, 2.0},
                                           AccuracyCase{SnakeMethod::LocalEmbedding, 3.0},
                                           AccuracyCase{SnakeMethod::Projection3D, 2.0},
                                           AccuracyCase{SnakeMethod::Projection3D, 3.0}));

// ---------------------------------------------------------------- fandisk: a CAD mesh's sharp edges
namespace {

// The longest chain of sharp mesh edges (dihedral angle above 40 degrees) through vertices
// of sharp-degree 2: a crease of the CAD model, exact because it is made of mesh edges.
std::vector<int> LongestSharpChain(CMeshO &m)
{
    std::map<int, std::vector<int>> g;
    for (auto &f : m.face)
        for (int k = 0; k < 3; ++k) {
            CFaceO *o = f.FFp(k);
            if (o == &f || o < &f) continue;
            if (vcg::AngleN(f.N(), o->N()) < vcg::math::ToRad(40.f)) continue;
            int a = int(vcg::tri::Index(m, f.V(k))), b = int(vcg::tri::Index(m, f.V((k + 1) % 3)));
            g[a].push_back(b);
            g[b].push_back(a);
        }
    std::vector<int> best;
    double bestLen = 0;
    for (auto &kv : g) {
        if (kv.second.size() == 2) continue; // start at chain ends and corners
        for (int next : kv.second) {
            std::vector<int> chain{kv.first, next};
            while (g[chain.back()].size() == 2 && chain.size() < 2000) {
                const auto &nb = g[chain.back()];
                int n = nb[0] == chain[chain.size() - 2] ? nb[1] : nb[0];
                if (n == chain.front()) break;
                chain.push_back(n);
            }
            double len = 0;
            for (size_t i = 1; i < chain.size(); ++i) len += (m.vert[chain[i]].P() - m.vert[chain[i - 1]].P()).Norm();
            if (len > bestLen) { bestLen = len; best = chain; }
        }
    }
    return best;
}

} // namespace

class FandiskAccuracy : public ::testing::TestWithParam<SnakeMethod> {};

TEST_P(FandiskAccuracy, SnakeLandsOnSharpEdges)
{
    CMeshO m;
    ASSERT_TRUE(gs_test::LoadMesh(m, std::string(GS_DATA_DIR) + "/fandisk.ply"));
    auto surf = gs_test::SurfaceWithEnergy(m);
    const double h = surf->MeanEdge();
    std::vector<int> chain = LongestSharpChain(m);
    ASSERT_GE(chain.size(), 10u);
    std::vector<vcg::Point3d> crease;
    for (int v : chain) crease.push_back(vcg::Point3d::Construct(m.vert[v].P()));
    // seeds two edge lengths to the left of the crease, at 20 .. 80 % of its length
    std::vector<vcg::Point3d> pts;
    for (double f : {0.2, 0.4, 0.6, 0.8}) {
        size_t i = size_t(f * (chain.size() - 1));
        int a = chain[i], b = chain[i + 1];
        CFaceO *left = nullptr;
        for (vcg::face::VFIterator<CFaceO> vfi(&m.vert[a]); !vfi.End(); ++vfi)
            if (vfi.F()->V((vfi.I() + 1) % 3) == &m.vert[b]) left = vfi.F();
        ASSERT_NE(left, nullptr);
        vcg::Point3d t = crease[i + 1] - crease[i], n = vcg::Point3d::Construct(left->N());
        vcg::Point3d d = (n ^ t).Normalize();
        pts.push_back((crease[i] + crease[i + 1]) / 2 + d * (2 * h));
    }
    Snake s(surf, [] { SnakeParams p; p.method = GetParam(); return p; }());
    s.InitFromSeeds(gs_test::NearestVertices(m, pts), false);
    auto dist = [&](const vcg::Point3d &x) { return gs_test::DistToPolyline(x, crease); };
    gs_test::CurveError e0 = gs_test::MeasureCurve(s.positions(), h, dist);
    EXPECT_GT(e0.mean, 0.8);
    s.Run(300);
    gs_test::CurveError e = gs_test::MeasureCurve(s.positions(), h, dist);
    EXPECT_LT(e.p95, 0.25) << "mean " << e.mean << " max " << e.max << " (started at " << e0.mean << ")";
    EXPECT_LT(e.mean, 0.1);
    RecordProperty("initial_mean", std::to_string(e0.mean));
    RecordProperty("final_p95", std::to_string(e.p95));
    std::printf("fandisk crease of %zu edges: mean distance %.2f -> %.3f h (p95 %.3f), %d samples, %d operations\n",
                chain.size() - 1, e0.mean, e.mean, e.p95, s.SampleCount(), s.Stats().operations);
}

INSTANTIATE_TEST_SUITE_P(Methods, FandiskAccuracy,
                         ::testing::Values(SnakeMethod::LocalEmbedding, SnakeMethod::Projection3D));
