// Engine robustness on the meshes users bring (issue 9): anisotropic and irregular
// triangulations, mixed edge lengths, ends, closed loops, smoothness near competing features.
// Generated meshes with exact answers; every test was seen failing before its fix.
#include <gtest/gtest.h>

#include <cstdio>

#include <Eigen/Dense>

#include <snake_test_util.h>
#include <vcg_ext/energy/feature_energy.h>

using namespace vcg::tri;
using gs_test::EnableSnakeAdjacency;
using Snake = GeometricSnake<CMeshO>;
using Surface = SnakeSurface<CMeshO>;

namespace {

/// Largest distance from the samples of `now` to the polyline `before` (sliding along the
/// curve does not count).
double CurveDisplacement(const std::vector<vcg::Point3d> &before, const std::vector<vcg::Point3d> &now)
{
    double worst = 0;
    for (const auto &p : now) worst = std::max(worst, gs_test::DistToPolyline(p, before));
    return worst;
}

} // namespace

// ---------------------------------------------------------------- zero-force stability
struct PlateCase
{
    const char *name;
    double cellX, cellY; // cell size (x along the snake)
    double jitter;       // > 0: irregular triangulation
};

class ZeroForceStability : public ::testing::TestWithParam<PlateCase> {};

// With no feature force a straight, evenly sampled open snake has nothing to do: it must stay
// put and converge, whatever the cells' shape (observed: on 10:1 cells it random-walked by
// about 2 cell widths in 100 operations and never converged).
TEST_P(ZeroForceStability, StraightSnakeStaysPutAndConverges)
{
    const PlateCase c = GetParam();
    const int nx = int(std::lround(120 / c.cellX)), ny = int(std::lround(40 / c.cellY));
    const int row = ny / 2;
    CMeshO m;
    gs_test::MakeGridPlate(m, nx, ny, c.cellX, c.cellY, c.jitter, 7, row);
    EnableSnakeAdjacency(m);
    for (auto &v : m.vert) v.Q() = 1;
    auto surf = std::make_shared<Surface>(m);
    const double l = gs_test::MedianEdgeLength(m);
    SnakeParams p;
    p.externalWeight = 0;
    Snake s(surf, p);
    const int first = row * (nx + 1) + nx / 6, last = row * (nx + 1) + nx - nx / 6;
    s.InitFromSeeds({first, (first + last) / 2, last}, false);
    const std::vector<vcg::Point3d> start = s.PolylinePositions();
    double worst = 0;
    int convergedAt = -1;
    for (int op = 0; op < 100; ++op) {
        s.Step();
        worst = std::max(worst, CurveDisplacement(start, s.positions()));

        if (convergedAt < 0 && s.Converged()) convergedAt = op + 1;
    }
    std::printf("%s: %d samples, largest displacement %.4f local edge lengths, converged after %d operations\n",
                c.name, s.SampleCount(), worst / l, convergedAt);
    EXPECT_LT(worst / l, 0.1) << c.name;
    EXPECT_GT(convergedAt, 0) << c.name << ": never converged";
}

INSTANTIATE_TEST_SUITE_P(Plates, ZeroForceStability,
                         ::testing::Values(PlateCase{"grid 1:1", 1, 1, 0}, PlateCase{"grid 5:1", 5, 1, 0},
                                           PlateCase{"grid 10:1", 10, 1, 0}, PlateCase{"grid 1:10", 1, 10, 0},
                                           PlateCase{"irregular", 1, 1, 0.3}),
                         [](const ::testing::TestParamInfo<PlateCase> &i) {
                             std::string n = i.param.name;
                             for (auto &ch : n)
                                 if (!isalnum(static_cast<unsigned char>(ch))) ch = '_';
                             return n;
                         });

// ---------------------------------------------------------------- embedding distortion
class FlatEmbedding : public ::testing::TestWithParam<PlateCase> {};

// A flat strip region must be embedded as it is (up to a similarity): then a straight curve
// stays straight in the plane and the spline has nothing to straighten. (The convex
// combination with a virtual boundary deviated by 0.8-2.7 edge lengths here.)
TEST_P(FlatEmbedding, FlatRegionEmbedsWithoutDistortion)
{
    const PlateCase c = GetParam();
    const int nx = int(std::lround(120 / c.cellX)), ny = int(std::lround(40 / c.cellY));
    CMeshO m;
    gs_test::MakeGridPlate(m, nx, ny, c.cellX, c.cellY, c.jitter, 7, ny / 2);
    EnableSnakeAdjacency(m);
    for (auto &v : m.vert) v.Q() = 1;
    auto surf = std::make_shared<Surface>(m);
    const double l = gs_test::MedianEdgeLength(m);
    std::vector<int> core;
    for (size_t i = 0; i < m.face.size(); ++i) {
        vcg::Point3d b = vcg::Point3d::Construct(vcg::Barycenter(m.face[i]));
        if (std::abs(b[1] - 20) < 0.5 * c.cellY && b[0] > 20 && b[0] < 100) core.push_back(int(i));
    }
    LocalRegion<CMeshO> r;
    ASSERT_TRUE(r.Build(*surf, core)) << r.error;
    // the engine's first choice (SnakeSegmentMotion): the least-squares conformal embedding
    VirtualBoundaryParam::Result e;
    std::string err;
    ASSERT_TRUE(ConformalParam::Embed(r.pos, r.tri, r.boundary, l, e.uv, err)) << err;
    EXPECT_EQ(VirtualBoundaryParam::CountFlipped(e.uv, r.tri), 0);
    // least-squares similarity uv ~ s R xy + t, residual on the core's vertices
    const int nv = int(r.verts.size());
    Eigen::MatrixXd M(2 * nv, 4);
    Eigen::VectorXd rhs(2 * nv);
    for (int i = 0; i < nv; ++i) {
        double x = r.pos[i][0], y = r.pos[i][1];
        M.row(2 * i) << x, -y, 1, 0;
        M.row(2 * i + 1) << y, x, 0, 1;
        rhs[2 * i] = e.uv[i].x();
        rhs[2 * i + 1] = e.uv[i].y();
    }
    Eigen::Vector4d q = M.colPivHouseholderQr().solve(rhs);
    const double scale = std::hypot(q[0], q[1]);
    double worst = 0;
    for (int f : core)
        for (int k = 0; k < 3; ++k) {
            int v = -1;
            for (int i = 0; i < nv; ++i)
                if (r.verts[i] == int(vcg::tri::Index(m, m.face[f].V(k)))) v = i;
            ASSERT_GE(v, 0);
            Eigen::Vector2d fit(M.row(2 * v).dot(q), M.row(2 * v + 1).dot(q));
            worst = std::max(worst, (fit - e.uv[v]).norm() / scale / l);
        }
    std::printf("%s: %d region faces, largest deviation from a similarity on the core %.2e local edge lengths\n",
                c.name, r.RealFaces(), worst);
    EXPECT_LT(worst, 1e-3) << c.name;
}

INSTANTIATE_TEST_SUITE_P(Plates, FlatEmbedding,
                         ::testing::Values(PlateCase{"grid 1:1", 1, 1, 0}, PlateCase{"grid 10:1", 10, 1, 0},
                                           PlateCase{"grid 1:10", 1, 10, 0}, PlateCase{"irregular", 1, 1, 0.3}),
                         [](const ::testing::TestParamInfo<PlateCase> &i) {
                             std::string n = i.param.name;
                             for (auto &ch : n)
                                 if (!isalnum(static_cast<unsigned char>(ch))) ch = '_';
                             return n;
                         });

// ---------------------------------------------------------------- closed snakes: no silent collapse
namespace {
std::shared_ptr<Surface> PrepareWithEnergy(CMeshO &m)
{
    return gs_test::SurfaceWithEnergy(m);
}
std::vector<int> CircleSeeds(const CMeshO &m, vcg::Point3d c, double r, int count, double z)
{
    std::vector<vcg::Point3d> pts;
    for (int i = 0; i < count; ++i) {
        double a = 2 * M_PI * i / count;
        pts.push_back(vcg::Point3d(c[0] + r * std::cos(a), c[1] + r * std::sin(a), z));
    }
    return gs_test::NearestVertices(m, pts);
}
} // namespace

// Observed on lion-head: a closed snake around an eye shrank to a single point in 19
// operations and reported "converged". Around a smooth bump nothing holds a closed snake.
TEST(ClosedSnake, CollapseStopsWithAWarningInsteadOfConverging)
{
    CMeshO m;
    gs_test::MakeBumpPlate(m, 60, 60.0, 6.0, 8.0);
    auto surf = PrepareWithEnergy(m);
    Snake s(surf);
    s.InitFromSeeds(CircleSeeds(m, vcg::Point3d(30, 30, 0), 6.0, 6, 0), true);
    const int n = s.SampleCount();
    s.Run(300);
    std::vector<vcg::Point3d> p = s.positions();
    double spread = 0;
    for (auto &x : p) spread = std::max(spread, (x - p[0]).Norm());
    std::printf("bump: %d samples, %d operations, converged %d, stopped %d, spread %.3f, warnings %zu\n", n,
                s.Stats().operations, int(s.Converged()), int(s.Stats().stopped), spread, s.Stats().warnings.size());
    EXPECT_FALSE(s.Converged() && spread < 1.0) << "converged at a point";
    ASSERT_TRUE(s.Stats().stopped);
    EXPECT_FALSE(s.Converged());
    ASSERT_FALSE(s.Stats().warnings.empty());
    EXPECT_NE(s.Stats().warnings.back().find("collaps"), std::string::npos) << s.Stats().warnings.back();
}

// A positive balloon inflates a closed snake seeded inside a rim until the rim holds it: the
// top rim of the capped cylinder (rotated icosphere) seen from the cap, seeds on a circle of
// 0.3 its radius on the flat cap, where there is no feature force at all (observed: with a
// constant pressure of 0.4 the snake settled 2.8 h short of the rim, at 1 it passed it).
class BalloonOntoRim : public ::testing::TestWithParam<SnakeMethod> {};

TEST_P(BalloonOntoRim, PositiveBalloonExpandsOntoTheRim)
{
    CMeshO m;
    gs_test::MakeRotatedIcoCylinder(m, 4);
    auto surf = PrepareWithEnergy(m);
    const double h = surf->MeanEdge();
    std::vector<vcg::Point3d> onMesh = gs_test::ProjectOntoMesh(m, gs_test::CylinderRimLine(1.0, 1.0));
    auto dist = [&](const vcg::Point3d &x) { return gs_test::DistToPolyline(x, onMesh, true); };
    for (double balloon : {0.0, 0.3}) {
        SnakeParams p;
        p.method = GetParam();
        p.balloon = balloon;
        Snake s(surf, p);
        s.InitFromSeeds(CircleSeeds(m, vcg::Point3d(0, 0, 1), 0.3, 6, 1.0), true);
        s.Run(500);
        gs_test::CurveError e = gs_test::MeasureCurve(s.positions(), s.LengthScale(), dist);
        std::printf("balloon %.2f: %d samples, %d operations, converged %d, stopped %d: distance to the rim mean "
                    "%.3f, p95 %.3f, max %.3f local edges\n", balloon, s.SampleCount(), s.Stats().operations,
                    int(s.Converged()), int(s.Stats().stopped), e.mean, e.p95, e.max);
        // without the balloon, printed only: before the energy pyramid (c9) it collapsed from here and
        // stopped, warned; the pyramid's coarse levels now capture the rim from 7 h inside as well
        if (balloon == 0) continue;
        // measured: mean 0.11 (embedding) and 0.12 (projection), p95 0.24 and 0.35 local edges
        EXPECT_TRUE(s.Converged());
        EXPECT_FALSE(s.Stats().stopped);
        EXPECT_LT(e.mean, 0.2) << "p95 " << e.p95 << " max " << e.max;
        EXPECT_LT(e.p95, 0.5) << "mean " << e.mean << " max " << e.max;
    }
}

INSTANTIATE_TEST_SUITE_P(Methods, BalloonOntoRim,
                         ::testing::Values(SnakeMethod::LocalEmbedding, SnakeMethod::Projection3D));
