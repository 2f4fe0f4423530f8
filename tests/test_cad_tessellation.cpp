// CAD tessellations (issue 10): generated parts whose faces are fans and strips of slivers
// with no interior vertex, seeds given as points a few units off an edge, and the crease
// energy, which is defined at every surface point.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>

#include <common/ml_mesh_type.h>

#include "cad_meshes.h"
#include "snake_test_util.h"
#include "vcg_ext/energy/crease_energy.h"
#include "vcg_ext/energy/crease_energy_field.h"
#include "vcg_ext/energy/feature_energy.h"
#include "vcg_ext/snake/geometric_snake.h"
#include "vcg_ext/embedding/local_region.h"
#include "vcg_ext/surface/mesh_validation.h"
#include "vcg_ext/paths/path_tighten.h"
#include "vcg_ext/paths/seed_points.h"
#include "vcg_ext/session/controller.h"
#include "vcg_ext/surface/triangle_soup.h"

namespace {

using vcg::Point3d;
using vcg::tri::FeatureEnergyType;
using vcg::tri::SurfacePoint;
typedef vcg::tri::CreaseEnergy<CMeshO> Crease;
typedef gs_test::CadBlock B;

SurfacePoint SnapOne(CMeshO &m, const Point3d &p)
{
    return vcg::tri::SeedPointSnap<CMeshO>::Snap(m, {p, p + Point3d(1e-3, 1e-3, 0)}, 1).points[0];
}

TEST(CadMeshes, BlockAndCylinderAreClosedManifoldWithoutInteriorVertices)
{
    CMeshO m;
    gs_test::MakeCadBlock(m, 64);
    auto r = vcg::tri::MeshValidation<CMeshO>::Inspect(m);
    EXPECT_EQ(r.borderEdges, 0);
    EXPECT_EQ(r.nonManifoldEdges, 0);
    EXPECT_EQ(r.nonManifoldVertices, 0);
    EXPECT_EQ(r.degenerateFaces, 0);
    EXPECT_EQ(r.components, 1);
    EXPECT_EQ(m.vn, 12 + 2 * 64 + 8);
    // Volume by the divergence theorem: the faces are oriented outwards.
    double vol = 0;
    for (auto &f : m.face)
        vol += (Point3d::Construct(f.cP(0)) * (Point3d::Construct(f.cP(1)) ^ Point3d::Construct(f.cP(2)))) / 6.0;
    const double bore = 0.5 * 64 * B::BoreR * B::BoreR * std::sin(2 * M_PI / 64) * B::Z;
    const double pocket = (B::PX1 - B::PX0) * (B::PY1 - B::PY0) * (B::Z - B::PocketFloor);
    EXPECT_NEAR(vol, B::X * B::Y * B::Z - bore - pocket, 1e-6 * B::X * B::Y * B::Z);

    CMeshO c;
    gs_test::MakeCadCylinder(c, 48);
    r = vcg::tri::MeshValidation<CMeshO>::Inspect(c);
    EXPECT_EQ(r.borderEdges, 0);
    EXPECT_EQ(r.nonManifoldEdges, 0);
    EXPECT_EQ(c.vn, 96);
    // Written to data/ for the host tests and the README (GS_WRITE_DATA=1).
    if (std::getenv("GS_WRITE_DATA")) {
        EXPECT_TRUE(gs_test::SaveMesh(m, GS_DATA_DIR "/cad_block.ply"));
        EXPECT_TRUE(gs_test::SaveMesh(c, GS_DATA_DIR "/cad_cylinder.ply"));
    }
}

TEST(CreaseEnergy, FindsTheCreasesAndHasAValleyAlongEachInsideSlivers)
{
    CMeshO m;
    gs_test::MakeCadBlock(m, 64);
    Crease ce;
    const double w = 2.0;
    ce.Build(m, Crease::DefaultAngle(), 3 * w);
    // 12 block edges (4 of them split in two at x = SplitX) + 2 x 64 bore rims + 8 pocket rims + 4 pocket floor
    EXPECT_EQ(ce.CreaseCount(), 12 + 4 + 2 * 64 + 4 + 4 + 4);
    // On the top face, 1 unit from the front edge and far from anything else: E = 1 - e^-(1/w)^2,
    // whichever sliver the point falls in.
    for (double x : {5.0, 22.0, 40.0, 57.0}) {
        SCOPED_TRACE(x);
        SurfacePoint p = SnapOne(m, Point3d(x, 1.0, B::Z));
        EXPECT_NEAR(ce.Distance(p), 1.0, 1e-5);
        Point3d g = ce.Gradient(p, w);
        EXPECT_GT(g[1], 0); // downhill is towards y = 0
        EXPECT_NEAR(g[2], 0, 1e-9);
    }
    // Flat inside: the middle of the top face's left half, away from every crease.
    SurfacePoint mid = SnapOne(m, Point3d(3 * w + 0.5 + 0, B::BoreY + B::BoreR + 3 * w + 1.0, B::Z));
    EXPECT_NEAR(ce.Value(mid, w), 1.0, 1e-3);
    // On the crease: zero.
    SurfacePoint on = SnapOne(m, Point3d(20, 0, B::Z));
    EXPECT_NEAR(ce.Value(on, w), 0.0, 1e-9);
    // The pocket's floor: its nearest creases are its own rim (8 away), not the walls' tops.
    SurfacePoint floor = SnapOne(m, Point3d(44, 20, B::PocketFloor));
    EXPECT_NEAR(ce.Distance(floor), 8.0, 1e-6); // to the floor's edges at y = 12 / 28 ... x = 36 / 52
}

TEST(CreaseEnergy, ThresholdDecidesWhatIsACrease)
{
    CMeshO c;
    gs_test::MakeCadCylinder(c, 48); // facets meet at 7.5 degrees, rims at 90
    Crease ce;
    ce.Build(c, 30, 6);
    EXPECT_EQ(ce.CreaseCount(), 2 * 48);
    ce.Build(c, 5, 6);
    EXPECT_EQ(ce.CreaseCount(), 2 * 48 + 48);
    EXPECT_THROW(ce.Build(c, 0, 6), vcg::tri::SnakeError);
    EXPECT_THROW(ce.Build(c, 200, 6), vcg::tri::SnakeError);
}

TEST(CreaseEnergy, FeatureEnergyStoresVertexValues)
{
    CMeshO m;
    gs_test::MakeCadBlock(m, 32);
    auto st = vcg::tri::FeatureEnergy<CMeshO>::Compute(m, FeatureEnergyType::Crease, 2);
    EXPECT_EQ(st.creases, 12 + 4 + 2 * 32 + 12);
    for (auto &v : m.vert) EXPECT_NEAR(v.cQ(), 0.0, 1e-6); // every vertex of a CAD part is on a crease
    CMeshO g;
    gs_test::MakeFlatGrid(g, 10);
    vcg::tri::FeatureEnergy<CMeshO>::Compute(g, FeatureEnergyType::Crease, 2);
    for (auto &v : g.vert) EXPECT_EQ(v.cQ(), 1.0f); // no crease at all: flat everywhere
}

// A ramp between two flats (45-degree creases at x = 4 and x = 6) on a grid whose x spacing
// grades 20x within each part, with alternating diagonals: the distance of every surface
// point within reach is exact (to the nearer crease of its own part), beyond reach + the
// largest face the energy is flat (1), and every crease is found. The dense grid has far
// more faces within reach of a face than the 4096 a walk over the patch once looked at.
struct RampCase { int perUnit, ny; };
class CreaseRampTest : public ::testing::TestWithParam<RampCase> {};

TEST_P(CreaseRampTest, DistanceIsExactWithinReachAndTheEnergyFlatBeyond)
{
    const double x0 = 4, x1 = 6, X = 10, Y = 6;
    std::vector<double> xs{0};
    auto graded = [&](double a, double b, int n, bool growing) { // n spacings in ratio 20
        const double q = std::pow(20.0, 1.0 / (n - 1));
        std::vector<double> h(n);
        double sum = 0;
        for (int i = 0; i < n; ++i) sum += h[i] = std::pow(q, growing ? i : n - 1 - i);
        double x = a;
        for (int i = 0; i + 1 < n; ++i) xs.push_back(x += (b - a) * h[i] / sum);
        xs.push_back(b); // exactly on the crease
    };
    const int n = GetParam().perUnit;
    graded(0, x0, 4 * n, false); // finest at the crease
    graded(x0, x1, 2 * n, true);
    graded(x1, X, 4 * n, true);
    const int ny = GetParam().ny, nx = int(xs.size());
    auto height = [&](double x) { return x <= x0 ? 0.0 : (x >= x1 ? x1 - x0 : x - x0); };
    std::vector<Point3d> pts;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) pts.push_back(Point3d(xs[i], Y * j / (ny - 1), height(xs[i])));
    std::vector<std::array<int, 3>> tris;
    for (int j = 0; j + 1 < ny; ++j)
        for (int i = 0; i + 1 < nx; ++i) {
            const int a = j * nx + i, b = a + 1, c = a + nx + 1, d = a + nx;
            if ((i + j) % 2) tris.push_back({a, b, c}), tris.push_back({a, c, d});
            else tris.push_back({a, b, d}), tris.push_back({b, c, d});
        }
    CMeshO m;
    gs_test::MakeFromArrays(m, pts, tris);
    double maxEdge = 0;
    for (auto &f : m.face)
        for (int k = 0; k < 3; ++k) maxEdge = std::max(maxEdge, double(vcg::Distance(f.cP(k), f.cP((k + 1) % 3))));

    const double w = 0.5, reach = 3 * w;
    Crease ce;
    ce.Build(m, Crease::DefaultAngle(), reach);
    ASSERT_EQ(ce.CreaseCount(), 2 * (ny - 1));
    // The exact distance on each part; on the ramp to the nearer of its two creases.
    auto exact = [&](const Point3d &p, double faceX) {
        if (faceX < x0) return x0 - p[0];
        if (faceX > x1) return p[0] - x1;
        const Point3d lo(x0, p[1], 0), hi(x1, p[1], x1 - x0);
        return std::min(vcg::Distance(p, lo), vcg::Distance(p, hi));
    };
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0, 1);
    int within = 0, flat = 0, onRamp = 0;
    for (size_t f = 0; f < m.face.size(); ++f) {
        double a = u(rng), b = u(rng);
        if (a + b > 1) a = 1 - a, b = 1 - b;
        const SurfacePoint p(int(f), vcg::Point3d(1 - a - b, a, b));
        const Point3d x = p.Pd(m);
        const double faceX = (m.face[f].cP(0)[0] + m.face[f].cP(1)[0] + m.face[f].cP(2)[0]) / 3.0;
        const double d = exact(x, faceX), got = ce.Distance(p);
        if (d <= reach) {
            ASSERT_NEAR(got, d, 1e-5) << "face " << f << " at x = " << x[0];
            EXPECT_NEAR(ce.Value(p, w), 1 - std::exp(-(d / w) * (d / w)), 1e-5);
            ++within;
            onRamp += faceX > x0 && faceX < x1;
        } else if (d > reach + 3 * maxEdge) {
            ASSERT_EQ(ce.Value(p, w), 1.0) << "face " << f << " at x = " << x[0];
            ++flat;
        } else {
            ASSERT_TRUE(std::isinf(got) || std::abs(got - d) < 1e-5) << "face " << f; // exact, or none found
        }
    }
    EXPECT_GT(within, int(m.face.size()) / 4);
    EXPECT_GT(flat, int(m.face.size()) / 20);
    EXPECT_GT(onRamp, int(m.face.size()) / 10);
    // Vertex values: 0 on both creases, the exact energy on each side.
    const std::vector<double> e = ce.VertexValues(w);
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const double x = xs[i];
            if (x == x0 || x == x1) EXPECT_EQ(e[j * nx + i], 0.0);
            const double d = x < x0 ? x0 - x : (x > x1 ? x - x1 : std::sqrt(2.0) * std::min(x - x0, x1 - x));
            if (d <= reach) EXPECT_NEAR(e[j * nx + i], 1 - std::exp(-(d / w) * (d / w)), 1e-5) << "x = " << x;
        }
}

INSTANTIATE_TEST_SUITE_P(Grids, CreaseRampTest, ::testing::Values(RampCase{10, 60}, RampCase{30, 200}),
                         [](const ::testing::TestParamInfo<RampCase> &i) { return i.param.ny > 100 ? "Dense" : "Coarse"; });

TEST(CreaseEnergy, SnakesReadItAtTheSamplesAndAFlatOneIsWarned)
{
    CMeshO m;
    gs_test::MakeCadBlock(m, 32);
    gs_test::EnableSnakeAdjacency(m);
    vcg::tri::SnakeController<CMeshO> ctl(m);
    ctl.SetEnergySettings(FeatureEnergyType::Crease, 2);
    auto &surf = ctl.EnsureSurface();
    ASSERT_NE(dynamic_cast<const vcg::tri::CreaseEnergyField<CMeshO> *>(&surf.EnergyField()), nullptr);
    // 1 unit off the front edge, inside a sliver whose three vertices all have energy 0
    const SurfacePoint p = SnapOne(m, Point3d(22, 1, B::Z));
    EXPECT_GT(surf.EnergyAt(0, p), 0.1);
    EXPECT_GT(surf.EnergyGradient(0, p)[1], 0);
    EXPECT_TRUE(ctl.EnergyWarnings().empty());
    EXPECT_GT(ctl.LengthScale(), 0);
    CMeshO g; // no crease at all: a warning for the Log, not a silent snake that never moves
    gs_test::MakeFlatGrid(g, 10);
    gs_test::EnableSnakeAdjacency(g);
    vcg::tri::SnakeController<CMeshO> flat(g);
    flat.SetEnergySettings(FeatureEnergyType::Crease, 2);
    ASSERT_EQ(flat.EnergyWarnings().size(), 1u);
    EXPECT_NE(flat.EnergyWarnings()[0].find("crease angle"), std::string::npos);
    // other energy types keep the vertex field and the engine's own length unit
    flat.SetEnergySettings(FeatureEnergyType::NormalVariation, 2);
    EXPECT_EQ(flat.LengthScale(), 0);
    EXPECT_EQ(dynamic_cast<const vcg::tri::CreaseEnergyField<CMeshO> *>(&flat.EnsureSurface().EnergyField()), nullptr);
}

// ------------------------------------------------------------------ triangle soups

TEST(TriangleSoup, DetectedAndMergedOnlyOnRequest)
{
    CMeshO m;
    gs_test::MakeCadBlock(m, 32);
    const int vn = m.vn, fn = m.fn;
    typedef vcg::tri::TriangleSoup<CMeshO> Soup;
    EXPECT_FALSE(Soup::Inspect(m).soup);
    EXPECT_EQ(Soup::Inspect(m).duplicates, 0);
    // The same part as an STL file stores it: three vertices of its own per face.
    std::vector<Point3d> pts;
    std::vector<std::array<int, 3>> tris;
    for (auto &f : m.face) {
        std::array<int, 3> t;
        for (int k = 0; k < 3; ++k) {
            t[k] = int(pts.size());
            pts.push_back(Point3d::Construct(f.cP(k)));
        }
        tris.push_back(t);
    }
    CMeshO soup;
    gs_test::MakeFromArrays(soup, pts, tris);
    auto r = Soup::Inspect(soup);
    EXPECT_TRUE(r.soup);
    EXPECT_EQ(r.vertices, 3 * fn);
    EXPECT_EQ(r.duplicates, 3 * fn - vn);
    EXPECT_NE(Soup::Message(r).find("Merge Close Vertices"), std::string::npos);
    EXPECT_EQ(Soup::Merge(soup), 3 * fn - vn);
    EXPECT_EQ(soup.vn, vn);
    EXPECT_EQ(soup.fn, fn);
    auto rep = vcg::tri::MeshValidation<CMeshO>::Inspect(soup);
    EXPECT_EQ(rep.borderEdges, 0);
    EXPECT_EQ(rep.components, 1);
    // A few duplicates (a seam) are not a soup.
    CMeshO seam;
    gs_test::MakeFlatGrid(seam, 10);
    seam.vert[0].P() = seam.vert[1].P();
    EXPECT_FALSE(Soup::Inspect(seam).soup);
}

// ------------------------------------------------------------------ regions that are not disks

TEST(LocalRegionTrimming, SliverStarsAroundABoreAreTrimmedNotRefused)
{
    // The faces a segment along the bore's top rim crosses: their vertex stars (the paper's
    // region) are the bore's full-height strips and the top face's slivers fanning to the block's
    // corners, which close around the bore: not a disk. The trimmed region is.
    CMeshO m;
    gs_test::MakeCadBlock(m, 64);
    gs_test::EnableSnakeAdjacency(m);
    vcg::tri::SnakeSurface<CMeshO> surf(m);
    int trimmed = 0, refused = 0, tried = 0;
    for (double a0 = 0; a0 < 2 * M_PI; a0 += M_PI / 6) {
        std::vector<Point3d> arc;
        for (int i = 0; i <= 12; ++i) {
            const double a = a0 + i * (M_PI / 2) / 12; // a quarter of the rim, 0.3 off it on the top face
            arc.push_back(Point3d(B::BoreX + (B::BoreR + 0.3) * std::cos(a), B::BoreY + (B::BoreR + 0.3) * std::sin(a), B::Z));
        }
        auto snap = vcg::tri::SeedPointSnap<CMeshO>::Snap(m, arc, 2);
        std::vector<int> core;
        for (auto &p : snap.points) core.push_back(p.face);
        vcg::tri::LocalRegion<CMeshO> r;
        ++tried;
        if (!r.Build(surf, core)) {
            ++refused;
            continue;
        }
        if (r.trimLevel > 0) ++trimmed;
        for (int f : core) EXPECT_GE(r.LocalFace(surf, f), 0); // the crossed faces are always kept
    }
    std::printf("[cad] bore-rim regions: %d tried, %d trimmed, %d refused\n", tried, trimmed, refused);
    EXPECT_EQ(refused, 0);
    EXPECT_GT(trimmed, 0); // the situation that used to freeze the snake does occur here
}

// ------------------------------------------------------------------ seeds as surface points

TEST(SeedPathFromPoints, StartsAndEndsExactlyAtTheSeedsThroughSharedFaces)
{
    CMeshO m;
    gs_test::MakeCadBlock(m, 64);
    gs_test::EnableSnakeAdjacency(m);
    const std::vector<Point3d> q{{6, 3, B::Z}, {30, 2.5, B::Z}, {54, 3, B::Z}};
    auto snap = vcg::tri::SeedPointSnap<CMeshO>::Snap(m, q, 2);
    for (bool closed : {false, true}) {
        SCOPED_TRACE(closed);
        auto r = vcg::tri::SeedPath<CMeshO>::ComputeFromPoints(m, snap.points, closed);
        ASSERT_EQ(r.seedPositions.size(), 3u);
        for (int i = 0; i < 3; ++i) EXPECT_LT((r.points[r.seedPositions[i]].Pd(m) - q[i]).Norm(), 1e-5);
        EXPECT_EQ(r.seedPositions[0], 0);
        if (!closed) EXPECT_EQ(r.seedPositions[2], int(r.points.size()) - 1);
        double straight = (q[1] - q[0]).Norm() + (q[2] - q[1]).Norm() + (closed ? (q[0] - q[2]).Norm() : 0.0);
        EXPECT_GE(r.length, straight - 1e-6);
        // the snake built on it starts and ends exactly at the seed points
        auto surf = std::make_shared<vcg::tri::SnakeSurface<CMeshO>>(m);
        vcg::tri::GeometricSnake<CMeshO> s(surf);
        s.InitFromSeedPoints(snap.points, closed);
        ASSERT_EQ(s.SeedPoints().size(), 3u);
        EXPECT_LT((s.Samples().front().p.Pd(m) - q[0]).Norm(), 1e-5);
        if (!closed) EXPECT_LT((s.Samples().back().p.Pd(m) - q[2]).Norm(), 1e-5);
        // every sample lies on the initial path (consecutive path points share a face)
        std::vector<Point3d> pl;
        for (auto &p : r.points) pl.push_back(p.Pd(m));
        for (auto &smp : s.Samples()) EXPECT_LT(gs_test::DistToPolyline(smp.p.Pd(m), pl, closed), 1e-5);
    }
    // two seeds in one face are joined straight
    auto one = vcg::tri::SeedPointSnap<CMeshO>::Snap(m, {{20, 1, B::Z}, {20.5, 1.2, B::Z}}, 2);
    if (one.points[0].face == one.points[1].face) {
        auto r = vcg::tri::SeedPath<CMeshO>::ComputeFromPoints(m, one.points, false);
        EXPECT_EQ(r.points.size(), 2u);
        EXPECT_TRUE(r.vertices.empty());
    }
}

// ------------------------------------------------------------------ the curve between samples

TEST(PathTighten, CrossingsSlideAlongTheirEdgesToTheShortestPathInTheStrip)
{
    // A strip of 2n triangles over [0,n] x [0,1]; the path from (0.1, 0.3) to (n - 0.1, 0.7)
    // crosses every inner edge. Started at the edges' upper ends (as a distorted embedding or
    // a face path's edge midpoints can place them: on the CAD block, halfway down the bore's
    // wall), it becomes the straight segment. (ClosedSnakeCapturesTheBoreRim needs it.)
    const int n = 8;
    std::vector<Point3d> pts;
    std::vector<std::array<int, 3>> tris;
    for (int i = 0; i <= n; ++i) {
        pts.push_back(Point3d(i, 0, 0));
        pts.push_back(Point3d(i, 1, 0));
    }
    for (int i = 0; i < n; ++i) {
        tris.push_back({2 * i, 2 * i + 2, 2 * i + 3});
        tris.push_back({2 * i, 2 * i + 3, 2 * i + 1});
    }
    CMeshO m;
    gs_test::MakeFromArrays(m, pts, tris);
    auto in = [&](int f, const Point3d &x) {
        SurfacePoint p;
        vcg::Triangle3<double> t(Point3d::Construct(m.face[f].cP(0)), Point3d::Construct(m.face[f].cP(1)),
                                 Point3d::Construct(m.face[f].cP(2)));
        vcg::InterpolationParameters(t, x, p.bary);
        p.face = f;
        return p;
    };
    // faces in the order the path meets them: in cell i the upper-left triangle, then the lower-right
    std::vector<int> order;
    for (int i = 0; i < n; ++i) {
        order.push_back(2 * i + 1);
        order.push_back(2 * i);
    }
    const Point3d a(0.1, 0.3, 0), b(n - 0.1, 0.7, 0);
    std::vector<SurfacePoint> cross;
    for (size_t k = 0; k + 1 < order.size(); ++k) { // the edge between consecutive faces, at its upper end
        const auto &ff = m.face[order[k]];
        Point3d far(0, -1, 0);
        for (int c = 0; c < 3; ++c)
            for (int l = 0; l < 3; ++l)
                if (ff.cV(c) == m.face[order[k + 1]].cV(l) && Point3d::Construct(ff.cP(c))[1] > far[1])
                    far = Point3d::Construct(ff.cP(c));
        cross.push_back(in(order[k], far));
    }
    const double len = vcg::tri::PathTighten<CMeshO>::Tighten(m, in(order.front(), a), cross, in(order.back(), b));
    EXPECT_NEAR(len, (b - a).Norm(), 1e-6);
    for (auto &c : cross) EXPECT_LT(gs_test::DistToPolyline(c.Pd(m), {a, b}), 1e-6);
}

// ------------------------------------------------------------------ capture on CAD parts

struct CadCapture
{
    double p95 = 0, coverage = 0, tol = 0;
    int operations = 0;
    bool converged = false;
};

/// Runs a snake from seed points with the given energy and measures it against the exact
/// feature: p95 of the curve's distance to it, and the fraction of the seeded span that the
/// curve covers within tolerance (`param` maps a point to its position along the feature,
/// in [0, spanLength); `spanFrom`..`spanTo` is the seeded span, closed = the whole feature).
template <class Dist, class Param>
CadCapture Capture(CMeshO &m, FeatureEnergyType type, const std::vector<Point3d> &seeds, bool closed, double tol,
                   Dist dist, Param param, double spanFrom, double spanTo)
{
    gs_test::EnableSnakeAdjacency(m);
    vcg::tri::SnakeController<CMeshO> ctl(m);
    ctl.SetEnergySettings(type, 2);
    auto snap = vcg::tri::SeedPointSnap<CMeshO>::Snap(m, seeds, closed ? 3 : 2, closed);
    ctl.CreateSnakeFromSeedPoints(snap.points, closed);
    auto &s = ctl.Get(0);
    if (std::getenv("GS_CAD_VERBOSE"))
        for (auto &p : s.InitialPolyline()) {
            Point3d x = p.Pd(m);
            std::printf("  init %.3f %.3f %.3f\n", x[0], x[1], x[2]);
        }
    s.Run(600);
    CadCapture c;
    c.tol = tol;
    c.operations = s.Stats().operations;
    if (std::getenv("GS_CAD_VERBOSE")) {
        std::printf("  samples %d, region failures %d, embeddings %d\n", s.SampleCount(), s.Stats().regionFailures,
                    s.Stats().embeddings);
        for (auto &w : s.Stats().warnings) std::printf("  warning: %s\n", w.c_str());
        for (auto &p : s.PolylinePositions()) std::printf("  %.3f %.3f %.3f\n", p[0], p[1], p[2]);
    }
    c.converged = s.Converged();
    std::vector<Point3d> pl = s.PolylinePositions();
    std::vector<double> d;
    for (auto &p : pl) d.push_back(dist(p));
    std::vector<double> sd = d;
    std::sort(sd.begin(), sd.end());
    c.p95 = sd[std::min(sd.size() - 1, size_t(0.95 * (sd.size() - 1) + 0.5))];
    // coverage: bins of the span hit by a polyline piece whose both ends are within tol
    const int bins = 400;
    std::vector<char> hit(bins, 0);
    const double len = spanTo - spanFrom;
    const size_t n = pl.size();
    for (size_t i = 0; i + (closed ? 0 : 1) < n; ++i) {
        const size_t j = (i + 1) % n;
        if (d[i] > tol || d[j] > tol) continue;
        double a = param(pl[i]) - spanFrom, b = param(pl[j]) - spanFrom;
        if (closed && std::abs(b - a) > len / 2) (a < b ? a : b) += len; // wraps around
        if (a > b) std::swap(a, b);
        for (int k = 0; k < bins; ++k) {
            double x = (k + 0.5) * len / bins;
            if ((x >= a && x <= b) || (closed && x + len >= a && x + len <= b)) hit[k] = 1;
        }
    }
    c.coverage = std::count(hit.begin(), hit.end(), 1) / double(bins);
    return c;
}

const char *Name(FeatureEnergyType t) { return vcg::tri::FeatureEnergyName(t); }

void Report(const char *what, FeatureEnergyType t, const CadCapture &c)
{
    std::printf("[cad] %-40s %-17s p95 %.4f (tol %.3f)  coverage %5.1f%%  ops %d%s\n", what, Name(t), c.p95, c.tol,
                100 * c.coverage, c.operations, c.converged ? "" : " (not converged)");
}

/// Issue 10's acceptance: p95 within tolerance, >= 95 % of the seeded span covered; asserted
/// for the crease energy, reported for the others.
void ReportAndCheck(const char *what, FeatureEnergyType t, const CadCapture &c)
{
    Report(what, t, c);
    if (t != FeatureEnergyType::Crease) return;
    EXPECT_LE(c.p95, c.tol);
    EXPECT_GE(c.coverage, 0.95);
}

/// Every case runs with the crease energy (asserted) and with normal variation (reported,
/// for docs/evaluation.md: on these parts it has no valley along the creases).
class CadCaptureTest : public ::testing::TestWithParam<FeatureEnergyType> {};

TEST_P(CadCaptureTest, OpenSnakeOnTopFaceCapturesTheFrontEdge)
{
    CMeshO m;
    gs_test::MakeCadBlock(m, 64);
    const std::vector<Point3d> seeds{{6, 3, B::Z}, {20, 2, B::Z}, {35, 4, B::Z}, {54, 3, B::Z}};
    auto c = Capture(m, GetParam(), seeds, false, 0.01 * B::X, gs_test::DistToBlockTopFrontEdge,
                     [](const Point3d &p) { return p[0]; }, 6, 54);
    ReportAndCheck("open, top face, 2-4 off the front edge", GetParam(), c);
}

TEST_P(CadCaptureTest, OpenSnakeOnFrontFaceCapturesTheTopEdge)
{
    CMeshO m;
    gs_test::MakeCadBlock(m, 64);
    const std::vector<Point3d> seeds{{8, 0, B::Z - 3}, {30, 0, B::Z - 3.5}, {52, 0, B::Z - 2.5}};
    auto c = Capture(m, GetParam(), seeds, false, 0.01 * B::X, gs_test::DistToBlockTopFrontEdge,
                     [](const Point3d &p) { return p[0]; }, 8, 52);
    ReportAndCheck("open, front face, 2.5-3.5 below the edge", GetParam(), c);
}

TEST_P(CadCaptureTest, ClosedSnakeCapturesTheBoreRim)
{
    CMeshO m;
    const int n = 64;
    gs_test::MakeCadBlock(m, n);
    std::vector<Point3d> seeds;
    for (int i = 0; i < 4; ++i) {
        const double a = 2 * M_PI * i / 4 + 0.3, r = B::BoreR + 2 + i % 2 * 1.5; // 2 - 3.5 off the rim
        seeds.push_back(Point3d(B::BoreX + r * std::cos(a), B::BoreY + r * std::sin(a), B::Z));
    }
    const auto rim = gs_test::CirclePolygon(B::BoreX, B::BoreY, B::BoreR, B::Z, n);
    const double rimLength = 2 * n * B::BoreR * std::sin(M_PI / n);
    const double sliver = 2 * M_PI * B::BoreR / n; // the bore's strips
    auto c = Capture(m, GetParam(), seeds, true, std::max(0.1 * sliver, 0.01 * rimLength),
                     [&](const Point3d &p) { return gs_test::DistToClosedPolygon(p, rim); },
                     [&](const Point3d &p) { return std::atan2(p[1] - B::BoreY, p[0] - B::BoreX) + M_PI; }, 0, 2 * M_PI);
    ReportAndCheck("closed, top face, 2-3.5 off the bore rim", GetParam(), c);
}

TEST_P(CadCaptureTest, ClosedSnakeOnStripsCapturesTheCylinderRim)
{
    CMeshO m;
    const int n = 48;
    const double r = 10, h = 40;
    gs_test::MakeCadCylinder(m, n, r, h);
    std::vector<Point3d> seeds;
    for (int i = 0; i < 5; ++i) {
        const double a = 2 * M_PI * i / 5 + 0.1;
        seeds.push_back(Point3d(r * std::cos(a), r * std::sin(a), h - 2 - (i % 3)));
    }
    const auto rim = gs_test::CirclePolygon(0, 0, r, h, n);
    const double rimLength = 2 * n * r * std::sin(M_PI / n);
    auto c = Capture(m, GetParam(), seeds, true, std::max(0.1 * 2 * M_PI * r / n, 0.01 * rimLength),
                     [&](const Point3d &p) { return gs_test::DistToClosedPolygon(p, rim); },
                     [&](const Point3d &p) { return std::atan2(p[1], p[0]) + M_PI; }, 0, 2 * M_PI);
    ReportAndCheck("closed, side strips, 2-4 below the top rim", GetParam(), c);
}

TEST_P(CadCaptureTest, OpenSnakeOnTopFaceCapturesThePocketRim)
{
    CMeshO m;
    gs_test::MakeCadBlock(m, 64);
    const std::vector<Point3d> seeds{{B::PX0 + 2, B::PY0 - 3, B::Z}, {B::PX0 + 8, B::PY0 - 2, B::Z}, {B::PX1 - 2, B::PY0 - 4, B::Z}};
    const Point3d e0(B::PX0, B::PY0, B::Z), e1(B::PX1, B::PY0, B::Z);
    auto c = Capture(m, GetParam(), seeds, false, 0.01 * (B::PX1 - B::PX0),
                     [&](const Point3d &p) { return gs_test::DistToPolyline(p, {e0, e1}); },
                     [](const Point3d &p) { return p[0]; }, B::PX0 + 2, B::PX1 - 2);
    ReportAndCheck("open, top face, 2-4 off the pocket rim", GetParam(), c);
}

/// Position along the pocket's rim (counter-clockwise from its corner PX0, PY0) of the point
/// of the rim nearest to p.
double PocketRimParam(const Point3d &p)
{
    const auto rim = gs_test::PocketRim();
    double best = 1e300, at = 0, acc = 0;
    for (int i = 0; i < 4; ++i) {
        const Point3d a = rim[i], b = rim[(i + 1) % 4];
        const double L = (b - a).Norm();
        const double t = std::min(1.0, std::max(0.0, ((p - a) * (b - a)) / (L * L)));
        const double d = (a + (b - a) * t - p).Norm();
        if (d < best) { best = d; at = acc + t * L; }
        acc += L;
    }
    return at;
}

TEST_P(CadCaptureTest, ClosedSnakeCapturesThePocketRimWithItsCorners)
{
    CMeshO m;
    gs_test::MakeCadBlock(m, 64);
    const std::vector<Point3d> seeds{{B::PX0 - 2, B::PY0 - 3, B::Z}, {B::PX1 + 3, B::PY0 - 4, B::Z},
                                     {B::PX1 + 4, B::PY1 + 2.5, B::Z}, {B::PX0 - 2.5, B::PY1 + 2, B::Z}};
    const auto rim = gs_test::PocketRim();
    const double rimLength = 2 * ((B::PX1 - B::PX0) + (B::PY1 - B::PY0));
    auto c = Capture(m, GetParam(), seeds, true, 0.01 * rimLength,
                     [&](const Point3d &p) { return gs_test::DistToClosedPolygon(p, rim); }, PocketRimParam, 0, rimLength);
    ReportAndCheck("closed, top face, 2-4 off the pocket rim", GetParam(), c);
}

// ------------------------------------------------------------------ the edit tool's flow

TEST(CadEditTool, ClickedSeedsAreSurfacePointsAndTheClosedSnakeCapturesTheBoreRim)
{
    // What the edit tool does on a click (the surface point under the cursor, not its nearest
    // vertex: every vertex of this part is on some crease), then Shift+Enter and Run.
    CMeshO m;
    gs_test::MakeCadBlock(m, 64);
    gs_test::EnableSnakeAdjacency(m);
    vcg::tri::SnakeController<CMeshO> ctl(m);
    ctl.SetEnergySettings(FeatureEnergyType::Crease, 2);
    std::vector<Point3d> clicks;
    for (int i = 0; i < 5; ++i) {
        const double a = 2 * M_PI * i / 5 + 0.2, r = B::BoreR + 2.5 + (i % 2);
        clicks.push_back(Point3d(B::BoreX + r * std::cos(a), B::BoreY + r * std::sin(a), B::Z));
    }
    for (const auto &c : clicks) {
        const SurfacePoint p = SnapOne(m, c);
        ctl.AddSeedFromPick(p.face, p.bary);
    }
    for (size_t i = 0; i < clicks.size(); ++i) EXPECT_LT((ctl.SeedPosition(int(i)) - clicks[i]).Norm(), 1e-4);
    ctl.CloseSeeds(true);
    ctl.Run(600);
    auto &s = ctl.Get(0);
    ASSERT_EQ(s.SeedPoints().size(), clicks.size());
    for (size_t i = 0; i < clicks.size(); ++i) EXPECT_LT((s.SeedPoints()[i].Pd(m) - clicks[i]).Norm(), 1e-4);
    const auto rim = gs_test::CirclePolygon(B::BoreX, B::BoreY, B::BoreR, B::Z, 64);
    std::vector<double> d;
    for (auto &p : s.PolylinePositions()) d.push_back(gs_test::DistToClosedPolygon(p, rim));
    std::sort(d.begin(), d.end());
    const double p95 = d[size_t(0.95 * (d.size() - 1) + 0.5)], tol = 0.01 * 2 * 64 * B::BoreR * std::sin(M_PI / 64);
    std::printf("[cad] edit tool: 5 clicks 2.5-3.5 off the bore rim, crease distance: p95 %.4f (tol %.3f), %d operations\n",
                p95, tol, s.Stats().operations);
    EXPECT_TRUE(s.Converged());
    EXPECT_LE(p95, tol);
    // The session as the tool autosaves it next to the mesh (<mesh>.snakes.json): with
    // GS_CAD_SESSION=<file> it is written there (scripts/screenshot_cad.sh shows it in MeshLab).
    if (const char *out = std::getenv("GS_CAD_SESSION")) ctl.Save(out);
}

INSTANTIATE_TEST_SUITE_P(Energies, CadCaptureTest,
                         ::testing::Values(FeatureEnergyType::Crease, FeatureEnergyType::NormalVariation),
                         [](const ::testing::TestParamInfo<FeatureEnergyType> &i) {
                             return i.param == FeatureEnergyType::Crease ? std::string("Crease") : std::string("NormalVariation");
                         });

} // namespace
