// Feature energy (Lee & Lee 2002, Sec. 6): definitions, normalization, smoothing, gradients.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>

#include <common/ml_mesh_type.h>

#include "generated_meshes.h"
#include "snake_test_util.h"
#include "vcg_ext/energy/feature_energy.h"

namespace {

using vcg::tri::FeatureEnergyType;
using vcg::tri::SnakeError;
typedef vcg::tri::FeatureEnergy<CMeshO> FE;

// A plain (non-Ocf, double) VCG mesh without face normals or adjacency.
class PVertex;
class PFace;
struct PUsed : public vcg::UsedTypes<vcg::Use<PVertex>::AsVertexType, vcg::Use<PFace>::AsFaceType> {};
class PVertex : public vcg::Vertex<PUsed, vcg::vertex::Coord3d, vcg::vertex::Normal3d, vcg::vertex::Qualityd,
                                   vcg::vertex::BitFlags> {};
class PFace : public vcg::Face<PUsed, vcg::face::VertexRef, vcg::face::BitFlags> {};
class PMesh : public vcg::tri::TriMesh<std::vector<PVertex>, std::vector<PFace>> {};

const FeatureEnergyType kTypes[] = {FeatureEnergyType::NormalVariation, FeatureEnergyType::CurvatureNorm,
                                    FeatureEnergyType::QuadricError};

const char *EnergyName(FeatureEnergyType t)
{
    return t == FeatureEnergyType::NormalVariation ? "NormalVariation"
           : t == FeatureEnergyType::CurvatureNorm ? "CurvatureNorm"
                                                   : "QuadricError";
}

template <class M>
void ExpectValid(const M &m, const std::string &what)
{
    for (size_t i = 0; i < m.vert.size(); ++i) {
        if (m.vert[i].IsD()) continue;
        const double q = m.vert[i].cQ();
        ASSERT_TRUE(std::isfinite(q)) << what << " vertex " << i;
        ASSERT_GE(q, 0.0) << what << " vertex " << i;
        ASSERT_LE(q, 1.0) << what << " vertex " << i;
    }
}

vcg::Point3d P(const CVertexO &v) { return vcg::Point3d::Construct(v.cP()); }

struct Bands
{
    double nearMean = 0, farMean = 0, farVar = 0;
    int nNear = 0, nFar = 0;
};

// Energy statistics by distance to the feature (in mean edge lengths).
Bands BandStats(const CMeshO &m, const std::function<double(const vcg::Point3d &)> &dist, double nearL = 1.0,
                double farL = 3.0)
{
    const double L = vcg::tri::MeshValidation<CMeshO>::MeanEdgeLength(m);
    Bands b;
    std::vector<double> far;
    for (const auto &v : m.vert) {
        const double d = dist(P(v)) / L;
        if (d < nearL) b.nearMean += v.cQ(), ++b.nNear;
        if (d > farL) far.push_back(v.cQ());
    }
    b.nFar = int(far.size());
    b.nearMean /= std::max(1, b.nNear);
    for (double q : far) b.farMean += q;
    b.farMean /= std::max<size_t>(1, far.size());
    for (double q : far) b.farVar += (q - b.farMean) * (q - b.farMean);
    b.farVar /= std::max<size_t>(1, far.size());
    return b;
}

TEST(FeatureEnergy, FlatPlaneHasNoFeature)
{
    for (auto t : kTypes)
        for (int steps : {0, 5}) {
            CMeshO m;
            gs_test::MakeFlatGrid(m, 20, 3.0);
            FE::Stats st = FE::Compute(m, t, steps);
            for (const auto &v : m.vert) ASSERT_FLOAT_EQ(v.cQ(), 1.0f) << EnergyName(t) << " steps " << steps;
            EXPECT_EQ(st.degenerateFaces, 0);
            EXPECT_EQ(st.nonManifoldVertices, 0);
            EXPECT_GE(st.seconds, 0.0);
        }
}

TEST(FeatureEnergy, AxisAlignedCubeFeatureIsExactlyOnEdges)
{
    for (auto t : kTypes) {
        CMeshO m;
        vcg::tri::Box(m, vcg::Box3<float>(vcg::Point3f(-1, -1, -1), vcg::Point3f(1, 1, 1)));
        gs_test::Subdivide(m, 3000); // midpoint refinement keeps vertices exactly on the cube edges
        FE::Compute(m, t, 0);
        ExpectValid(m, EnergyName(t));
        double maxEdge = -1, minEdge = 2, minInterior = 2;
        int nEdge = 0;
        for (const auto &v : m.vert) {
            const bool onEdge = gs_test::DistToCubeEdges(P(v)) < 1e-6;
            if (onEdge) {
                maxEdge = std::max(maxEdge, double(v.cQ()));
                minEdge = std::min(minEdge, double(v.cQ()));
                ++nEdge;
            } else {
                minInterior = std::min(minInterior, double(v.cQ()));
            }
        }
        EXPECT_GT(nEdge, 50);
        EXPECT_LT(maxEdge, minInterior) << EnergyName(t); // every edge vertex below every face vertex
        EXPECT_FLOAT_EQ(minEdge, 0.0f) << EnergyName(t);  // the global minimum is on the edges
        EXPECT_FLOAT_EQ(minInterior, 1.0f) << EnergyName(t); // flat faces carry no feature
    }
}

TEST(FeatureEnergy, RotatedIcoCubeBandAlongEdges)
{
    for (auto t : kTypes) {
        CMeshO m;
        gs_test::MakeRotatedIcoCube(m, 4);
        FE::Compute(m, t, 0);
        ExpectValid(m, EnergyName(t));
        Bands b = BandStats(m, [](const vcg::Point3d &p) { return gs_test::DistToCubeEdges(p); });
        EXPECT_GT(b.nNear, 50);
        EXPECT_GT(b.nFar, 500);
        EXPECT_LT(b.nearMean, 0.6) << EnergyName(t);
        EXPECT_GT(b.farMean, 0.95) << EnergyName(t);
        // And the single lowest vertex is close to an edge.
        const double L = vcg::tri::MeshValidation<CMeshO>::MeanEdgeLength(m);
        int best = 0;
        for (size_t i = 0; i < m.vert.size(); ++i)
            if (m.vert[i].cQ() < m.vert[best].cQ()) best = int(i);
        EXPECT_LT(gs_test::DistToCubeEdges(P(m.vert[best])), 1.5 * L) << EnergyName(t);
    }
}

TEST(FeatureEnergy, OctahedronAndCylinderBands)
{
    for (auto t : kTypes) {
        CMeshO o, c;
        gs_test::MakeRotatedIcoOctahedron(o, 4);
        gs_test::MakeRotatedIcoCylinder(c, 4);
        FE::Compute(o, t, 0);
        FE::Compute(c, t, 0);
        ExpectValid(o, EnergyName(t));
        ExpectValid(c, EnergyName(t));
        Bands bo = BandStats(o, [](const vcg::Point3d &p) { return gs_test::DistToOctahedronEdges(p); });
        EXPECT_LT(bo.nearMean + 0.3, bo.farMean) << EnergyName(t);
        // The cylinder's side is curved, so its "far" band is not perfectly flat.
        Bands bc = BandStats(c, [](const vcg::Point3d &p) { return gs_test::DistToCylinderRims(p); });
        EXPECT_LT(bc.nearMean + 0.3, bc.farMean) << EnergyName(t);
    }
}

TEST(FeatureEnergy, ScaleInvariant)
{
    for (auto t : kTypes) {
        CMeshO a, b;
        gs_test::MakeRotatedIcoCube(a, 4);
        gs_test::MakeRotatedIcoCube(b, 4, 1000.0);
        FE::Compute(a, t, 0);
        FE::Compute(b, t, 0);
        double maxDiff = 0;
        for (size_t i = 0; i < a.vert.size(); ++i)
            maxDiff = std::max(maxDiff, std::fabs(double(a.vert[i].cQ()) - double(b.vert[i].cQ())));
        EXPECT_LT(maxDiff, 1e-3) << EnergyName(t);
        // Smoothed too.
        FE::Compute(a, t, 4);
        FE::Compute(b, t, 4);
        maxDiff = 0;
        for (size_t i = 0; i < a.vert.size(); ++i)
            maxDiff = std::max(maxDiff, std::fabs(double(a.vert[i].cQ()) - double(b.vert[i].cQ())));
        EXPECT_LT(maxDiff, 1e-3) << EnergyName(t);
    }
}

// Local minima of the quality (lower than every neighbour by more than float round-off) among
// vertices farther than `farL` edge lengths from the cube edges.
int FarLocalMinima(const CMeshO &m, double farL)
{
    const double L = vcg::tri::MeshValidation<CMeshO>::MeanEdgeLength(m);
    std::vector<char> isMin(m.vert.size(), 1);
    for (const auto &f : m.face)
        for (int k = 0; k < 3; ++k) {
            const int a = int(f.cV(k) - &m.vert[0]), b = int(f.cV((k + 1) % 3) - &m.vert[0]);
            if (!(m.vert[a].cQ() < m.vert[b].cQ() - 1e-4f)) isMin[a] = 0;
            if (!(m.vert[b].cQ() < m.vert[a].cQ() - 1e-4f)) isMin[b] = 0;
        }
    int n = 0;
    for (size_t i = 0; i < m.vert.size(); ++i)
        if (isMin[i] && gs_test::DistToCubeEdges(P(m.vert[i])) > farL * L) ++n;
    return n;
}

TEST(FeatureEnergy, SmoothingSuppressesNoiseKeepsEdges)
{
    for (auto t : kTypes) {
        CMeshO clean;
        gs_test::MakeRotatedIcoCube(clean, 5);
        FE::Compute(clean, t, 0);
        // Far from the edges, beyond the reach of 10 smoothing rounds, the faces are flat.
        const double farL = 8.0;
        EXPECT_EQ(FarLocalMinima(clean, farL), 0) << EnergyName(t); // sanity: without noise, no spurious minima

        CMeshO m;
        gs_test::MakeRotatedIcoCube(m, 5);
        gs_test::AddVertexNoise(m, 0.05, 1234);
        FE::Compute(m, t, 0);
        ExpectValid(m, EnergyName(t));
        auto edgeDist = [](const vcg::Point3d &p) { return gs_test::DistToCubeEdges(p); };
        const Bands raw = BandStats(m, edgeDist, 1.0, farL);
        const int rawMinima = FarLocalMinima(m, farL);
        EXPECT_GT(rawMinima, 20) << EnergyName(t); // noise creates spurious minima away from the edges
        EXPECT_GT(raw.farVar, 0.0) << EnergyName(t);

        // (a) Sec. 6.3 averaging itself lowers the variance in the flat region, edges stay lower.
        FE::Smooth(m, 10);
        const Bands avg = BandStats(m, edgeDist, 1.0, farL);
        EXPECT_LT(avg.farVar, 0.5 * raw.farVar) << EnergyName(t);
        EXPECT_LT(avg.nearMean, avg.farMean - 0.1) << EnergyName(t);

        // (b) The full pipeline (smoothing + renormalization): far fewer spurious minima, edge
        // band still clearly lowest. (Variances are not compared here: the unsmoothed field is
        // clipped at 1 by the percentile normalization, which hides most of its noise.)
        FE::Compute(m, t, 10);
        ExpectValid(m, EnergyName(t));
        const Bands sm = BandStats(m, edgeDist, 1.0, farL);
        EXPECT_LT(FarLocalMinima(m, farL), rawMinima / 4) << EnergyName(t);
        EXPECT_LT(sm.nearMean + 0.3, sm.farMean) << EnergyName(t);
        std::printf("%s: far var raw %.3g averaged %.3g; far minima raw %d smoothed %d; near/far %.3f/%.3f\n", EnergyName(t),
                    raw.farVar, avg.farVar, rawMinima, FarLocalMinima(m, farL), sm.nearMean, sm.farMean);
        EXPECT_LT(sm.nearMean + 0.3, sm.farMean) << EnergyName(t); // edge band still clearly lower
    }
}

TEST(FeatureEnergy, SmoothingSpreadsFeatureForDistantAttraction)
{
    // Sec. 6.3: after smoothing the energy decreases towards the edge from farther away.
    CMeshO a, b;
    gs_test::MakeRotatedIcoCube(a, 5);
    gs_test::MakeRotatedIcoCube(b, 5);
    FE::Compute(a, FeatureEnergyType::NormalVariation, 0);
    FE::Compute(b, FeatureEnergyType::NormalVariation, 10);
    auto edgeDist = [](const vcg::Point3d &p) { return gs_test::DistToCubeEdges(p); };
    // Vertices 2-3 edge lengths away: untouched (1) without smoothing, pulled below 1 with it.
    const Bands ra = BandStats(a, edgeDist, 3.0, 1e9), rb = BandStats(b, edgeDist, 3.0, 1e9);
    const Bands na = BandStats(a, edgeDist, 2.0, 1e9), nb = BandStats(b, edgeDist, 2.0, 1e9);
    const double ringA = (ra.nearMean * ra.nNear - na.nearMean * na.nNear) / (ra.nNear - na.nNear);
    const double ringB = (rb.nearMean * rb.nNear - nb.nearMean * nb.nNear) / (rb.nNear - nb.nNear);
    EXPECT_GT(ringA, 0.99);
    EXPECT_LT(ringB, 0.9);
}

TEST(FeatureEnergy, NormalizeAndSmoothPrimitives)
{
    CMeshO m;
    gs_test::MakeIcosphere(m, 3);
    for (size_t i = 0; i < m.vert.size(); ++i) m.vert[i].Q() = float(i);
    FE::Normalize(m, true);
    EXPECT_FLOAT_EQ(m.vert.front().cQ(), 0.0f);
    EXPECT_FLOAT_EQ(m.vert.back().cQ(), 1.0f);
    EXPECT_NEAR(m.vert[321].cQ(), 0.5, 0.01);
    for (size_t i = 0; i < m.vert.size(); ++i) m.vert[i].Q() = float(i);
    FE::Normalize(m, false); // high raw value = feature
    EXPECT_FLOAT_EQ(m.vert.front().cQ(), 1.0f);
    EXPECT_FLOAT_EQ(m.vert.back().cQ(), 0.0f);
    // Outliers are clamped, not allowed to squash the range (percentiles).
    for (size_t i = 0; i < m.vert.size(); ++i) m.vert[i].Q() = float(i % 2);
    m.vert[7].Q() = -1e6f;
    FE::Normalize(m, true);
    EXPECT_FLOAT_EQ(m.vert[7].cQ(), 0.0f);
    EXPECT_FLOAT_EQ(m.vert[2].cQ(), 0.0f);
    EXPECT_FLOAT_EQ(m.vert[3].cQ(), 1.0f);
    // Constant and NaN fields -> 1 (no feature).
    for (auto &v : m.vert) v.Q() = 0.25f;
    m.vert[3].Q() = std::numeric_limits<float>::quiet_NaN();
    FE::Normalize(m, true);
    for (const auto &v : m.vert) EXPECT_FLOAT_EQ(v.cQ(), 1.0f);
    // Smoothing keeps a constant field, reduces the spread of a random one and keeps the mean near.
    FE::Smooth(m, 3);
    for (const auto &v : m.vert) EXPECT_FLOAT_EQ(v.cQ(), 1.0f);
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> U(0, 1);
    for (auto &v : m.vert) v.Q() = U(rng);
    auto spread = [&]() {
        float lo = 1, hi = 0;
        for (const auto &v : m.vert) lo = std::min(lo, v.cQ()), hi = std::max(hi, v.cQ());
        return hi - lo;
    };
    const float s0 = spread();
    FE::Smooth(m, 5);
    EXPECT_LT(spread(), 0.5f * s0);
}

// Issue 8: long smoothing reports progress through a callback (MeshLab's cb) and can be
// cancelled; a cancelled computation leaves the vertex quality as it was.
TEST(FeatureEnergy, SmoothingReportsProgressAndCancels)
{
    CMeshO m;
    gs_test::MakeRotatedIcoCube(m, 2);
    std::vector<int> seen;
    FE::Compute(m, FeatureEnergyType::NormalVariation, 1000, 30, [&](int pct) {
        seen.push_back(pct);
        return true;
    });
    ASSERT_GE(seen.size(), 100u);
    EXPECT_EQ(seen.front(), 0);
    EXPECT_EQ(seen.back(), 100);
    EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
    std::vector<float> done;
    for (const auto &v : m.vert) done.push_back(v.cQ());

    // the same result without a callback
    CMeshO m2;
    gs_test::MakeRotatedIcoCube(m2, 2);
    FE::Compute(m2, FeatureEnergyType::NormalVariation, 1000);
    for (size_t i = 0; i < m.vert.size(); ++i) ASSERT_EQ(m2.vert[i].cQ(), done[i]);

    // cancelled at 40 %: SnakeCancelled, the quality the mesh had before
    for (auto &v : m2.vert) v.Q() = 0.123f;
    int calls = 0;
    try {
        FE::Compute(m2, FeatureEnergyType::NormalVariation, 1000, 30, [&](int pct) {
            ++calls;
            return pct < 40;
        });
        ADD_FAILURE() << "no exception";
    } catch (const vcg::tri::SnakeCancelled &e) {
        EXPECT_NE(std::string(e.what()).find("cancelled after 400 of 1000"), std::string::npos) << e.what();
    }
    EXPECT_EQ(calls, 41);
    for (const auto &v : m2.vert) ASSERT_EQ(v.cQ(), 0.123f);
    // Smooth alone returns the rounds it did
    EXPECT_EQ(FE::Smooth(m2, 50, [](int pct) { return pct < 10; }), 5);
    EXPECT_EQ(FE::Smooth(m2, 50), 50);
}

TEST(FeatureEnergy, FaceGradientMatchesFiniteDifferences)
{
    CMeshO m;
    gs_test::MakeIcosphere(m, 2);
    gs_test::AddVertexNoise(m, 0.2, 5);
    // 1) A linear field q = a.p + c: the gradient is a projected onto each face plane.
    const vcg::Point3d a(0.3, -1.2, 0.7);
    for (auto &v : m.vert) v.Q() = float(a * P(v) + 2.0);
    std::vector<vcg::Point3f> g = FE::FaceGradients(m);
    ASSERT_EQ(g.size(), m.face.size());
    for (size_t i = 0; i < m.face.size(); ++i) {
        const auto &f = m.face[i];
        vcg::Point3d n = (vcg::Point3d::Construct(f.cP(1)) - vcg::Point3d::Construct(f.cP(0))) ^
                         (vcg::Point3d::Construct(f.cP(2)) - vcg::Point3d::Construct(f.cP(0)));
        n.Normalize();
        const vcg::Point3d expect = a - n * (a * n);
        EXPECT_LT(vcg::Distance(vcg::Point3d::Construct(g[i]), expect), 1e-4) << "face " << i;
    }
    // 2) Random values: directional finite differences of the interpolated field.
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> U(0, 1);
    for (auto &v : m.vert) v.Q() = float(U(rng));
    g = FE::FaceGradients(m);
    for (size_t i = 0; i < m.face.size(); i += 7) {
        const auto &f = m.face[i];
        vcg::Point3d p[3];
        double q[3];
        for (int k = 0; k < 3; ++k) p[k] = vcg::Point3d::Construct(f.cP(k)), q[k] = f.cV(k)->cQ();
        const vcg::Point3d x = (p[0] + p[1] + p[2]) / 3.0;
        auto interp = [&](const vcg::Point3d &y) {
            // barycentric coordinates of y (in the plane) by sub-triangle areas
            const vcg::Point3d n = (p[1] - p[0]) ^ (p[2] - p[0]);
            const double A = n.SquaredNorm();
            const double b0 = (((p[1] - y) ^ (p[2] - y)) * n) / A, b1 = (((p[2] - y) ^ (p[0] - y)) * n) / A;
            return b0 * q[0] + b1 * q[1] + (1 - b0 - b1) * q[2];
        };
        const double h = 1e-4;
        for (const vcg::Point3d &d : {(p[1] - p[0]).Normalize(), (p[2] - p[0]).Normalize()}) {
            const double fd = (interp(x + d * h) - interp(x - d * h)) / (2 * h);
            EXPECT_NEAR(fd, vcg::Point3d::Construct(g[i]) * d, 1e-3 * (1 + std::fabs(fd))) << "face " << i;
        }
    }
    // 3) Degenerate faces: zero, never NaN.
    CMeshO d;
    gs_test::MakeFromArrays(d, {vcg::Point3d(0, 0, 0), vcg::Point3d(1, 0, 0), vcg::Point3d(2, 0, 0)}, {{0, 1, 2}, {0, 0, 1}});
    for (auto &v : d.vert) v.Q() = float(&v - &d.vert[0]);
    for (const auto &gg : FE::FaceGradients(d)) EXPECT_EQ(gg, vcg::Point3f(0, 0, 0));
}

TEST(FeatureEnergy, BadInputThrows)
{
    for (auto t : kTypes) {
        CMeshO empty;
        EXPECT_THROW(FE::Compute(empty, t, 0), SnakeError);
        CMeshO cloud;
        vcg::tri::Allocator<CMeshO>::AddVertices(cloud, 10);
        EXPECT_THROW(FE::Compute(cloud, t, 0), SnakeError);
        CMeshO nan;
        gs_test::MakeIcosphere(nan, 2);
        nan.vert[5].P()[1] = std::numeric_limits<float>::quiet_NaN();
        EXPECT_THROW(FE::Compute(nan, t, 0), SnakeError);
        CMeshO inf;
        gs_test::MakeIcosphere(inf, 2);
        inf.vert[5].P()[1] = std::numeric_limits<float>::infinity();
        EXPECT_THROW(FE::Compute(inf, t, 0), SnakeError);
        CMeshO ok;
        gs_test::MakeIcosphere(ok, 2);
        EXPECT_THROW(FE::Compute(ok, t, -1), SnakeError);
        // All collapsed to one point: no usable edge length.
        CMeshO point;
        gs_test::MakeFromArrays(point, {vcg::Point3d(1, 1, 1), vcg::Point3d(1, 1, 1), vcg::Point3d(1, 1, 1)}, {{0, 1, 2}});
        if (t != FeatureEnergyType::NormalVariation) EXPECT_THROW(FE::Compute(point, t, 0), SnakeError);
    }
}

TEST(FeatureEnergy, NonManifoldDegenerateBorderMultiComponentDoNotBreak)
{
    std::vector<std::pair<std::string, std::function<void(CMeshO &)>>> makers = {
        {"cones", [](CMeshO &m) { gs_test::MakeTouchingCones(m, 12); }},
        {"fin", [](CMeshO &m) { gs_test::MakeNonManifoldFin(m); }},
        {"degenerate",
         [](CMeshO &m) {
             gs_test::MakeFromArrays(m,
                                     {vcg::Point3d(0, 0, 0), vcg::Point3d(1, 0, 0), vcg::Point3d(2, 0, 0),
                                      vcg::Point3d(1, 1, 0), vcg::Point3d(1, -1, 0.5)},
                                     {{0, 1, 3}, {1, 2, 3}, {0, 2, 1}, {0, 4, 1}, {1, 1, 4}, {4, 2, 1}});
         }},
        {"grid+sphere",
         [](CMeshO &m) {
             gs_test::MakeFlatGrid(m, 8);
             CMeshO s;
             gs_test::MakeRotatedIcoCube(s, 2, 0.3);
             gs_test::AppendMesh(m, s);
         }},
        {"deleted face+isolated vertex",
         [](CMeshO &m) {
             gs_test::MakeRotatedIcoCube(m, 3);
             vcg::tri::Allocator<CMeshO>::DeleteFace(m, m.face[10]);
             vcg::tri::Allocator<CMeshO>::AddVertex(m, vcg::Point3f(5, 5, 5));
         }},
    };
    for (auto &mk : makers)
        for (auto t : kTypes)
            for (int steps : {0, 3}) {
                CMeshO m;
                mk.second(m);
                FE::Stats st;
                ASSERT_NO_THROW(st = FE::Compute(m, t, steps)) << mk.first << " " << EnergyName(t);
                ExpectValid(m, mk.first + " " + EnergyName(t));
                EXPECT_TRUE(std::isfinite(st.rawMin) && std::isfinite(st.rawMax));
                for (const auto &v : m.vert)
                    if (!v.IsD())
                        for (int k = 0; k < 3; ++k) ASSERT_TRUE(std::isfinite(v.cN()[k])) << mk.first;
                for (const auto &g : FE::FaceGradients(m))
                    for (int k = 0; k < 3; ++k) ASSERT_TRUE(std::isfinite(g[k])) << mk.first;
                if (mk.first == "cones") EXPECT_EQ(st.nonManifoldVertices, 1);
                if (mk.first == "degenerate") EXPECT_EQ(st.degenerateFaces, 2);
            }
}

TEST(FeatureEnergy, PlainMeshTypeWorks)
{
    for (auto t : kTypes) {
        PMesh m;
        vcg::tri::Box(m, vcg::Box3d(vcg::Point3d(-1, -1, -1), vcg::Point3d(1, 1, 1)));
        gs_test::Subdivide(m, 3000);
        vcg::tri::FeatureEnergy<PMesh>::Compute(m, t, 0);
        double maxEdge = -1, minInterior = 2;
        for (const auto &v : m.vert) {
            if (gs_test::DistToCubeEdges(v.cP()) < 1e-9) maxEdge = std::max(maxEdge, v.cQ());
            else minInterior = std::min(minInterior, v.cQ());
        }
        EXPECT_LT(maxEdge, minInterior) << EnergyName(t);
        auto g = vcg::tri::FeatureEnergy<PMesh>::FaceGradients(m);
        EXPECT_EQ(g.size(), m.face.size());
    }
}

} // namespace

// Above MeshValidation::ConcurrentFaces() faces Compute counts the topology on a second thread
// while it computes the energy: its report must still be the mesh's (a pair of touching cones
// and a face with a repeated vertex, appended to a grid of 180,000 faces), and the energy the
// same as computed on its own. Also on a grid of 800 faces with the threshold at 0, where
// ThreadSanitizer sees both sides of a race.
TEST(FeatureEnergy, LargeMeshCountsItsTopologyOnASecondThread)
{
    for (int n : {300, 20}) {
        gs_test::ConcurrentFacesScope threads(n < 100 ? 0 : vcg::tri::MeshValidation<CMeshO>::ConcurrentFaces());
        CMeshO m;
        gs_test::MakeFlatGrid(m, n);
        CMeshO cones;
        gs_test::MakeTouchingCones(cones, 12);
        gs_test::AppendMesh(m, cones);
        auto rep0 = vcg::tri::Allocator<CMeshO>::AddFace(m, &m.vert[0], &m.vert[1], &m.vert[2]);
        rep0->V(2) = rep0->V(0); // a face that repeats a vertex (AddFace asserts on one)
        ASSERT_GT(m.fn, vcg::tri::MeshValidation<CMeshO>::ConcurrentFaces());
        const auto rep = vcg::tri::MeshValidation<CMeshO>::Inspect(m);
        ASSERT_EQ(rep.nonManifoldVertices, 1);
        ASSERT_EQ(rep.degenerateFaces, 1);
        const FE::Stats st = FE::Compute(m, FeatureEnergyType::NormalVariation, 2);
        EXPECT_EQ(st.nonManifoldVertices, rep.nonManifoldVertices);
        EXPECT_EQ(st.degenerateFaces, rep.degenerateFaces);
        std::vector<float> q;
        for (const auto &v : m.vert) q.push_back(v.cQ());
        FE::NormalVariation(m);
        FE::Normalize(m, true);
        FE::Smooth(m, 2);
        FE::Normalize(m, true);
        for (size_t i = 0; i < m.vert.size(); ++i) ASSERT_EQ(m.vert[i].cQ(), q[i]) << n << " vertex " << i;
    }
}

namespace {

/// A V-ridge of `deg` degrees between its faces' normals along x = 0.5 (a mesh line) of an
/// n x n grid of [0,1]^2: one line of vertices, 1/n of the mesh.
void MakeVRidge(CMeshO &m, int n, double deg)
{
    const double t = std::tan(deg / 2 * M_PI / 180);
    gs_test::MakeHeightPlate(m, n, n, 1.0 / n, 1.0 / n, 0, 1,
                             [t](double x, double) { return t * (0.5 - std::fabs(x - 0.5)); });
}

} // namespace

// Issue 36: the normalisation clamped the lowest 0.5 % of the vertices, so a crease on fewer
// (a 33-degree ridge on 300 x 300 and finer grids) became a constant field. The strongest
// feature maps to 0 whatever its share of the mesh; the flats stay at 1.
TEST(FeatureEnergy, ThinRidgeSurvivesOnFineGrids)
{
    for (int n : {100, 300, 600}) { // 1000 x 1000 (2M faces): the same, by hand with geometric-snake energy
        for (int steps : {0, 2}) {
            CMeshO m;
            MakeVRidge(m, n, 33);
            const FE::Stats st = FE::Compute(m, FeatureEnergyType::NormalVariation, steps);
            EXPECT_FALSE(st.constant) << n;
            EXPECT_NEAR(st.rawMin, std::cos(16.5 * M_PI / 180), 1e-3) << n;
            double ridgeMax = 0, flatMin = 1;
            for (const auto &v : m.vert) {
                const double d = std::fabs(double(v.cP()[0]) - 0.5);
                if (d < 0.25 / n) ridgeMax = std::max(ridgeMax, double(v.cQ()));
                else if (d > 0.1) flatMin = std::min(flatMin, double(v.cQ()));
            }
            EXPECT_LT(ridgeMax, 0.05) << n << " x " << n << ", " << steps << " smoothing steps";
            EXPECT_GT(flatMin, 0.95) << n << " x " << n << ", " << steps << " smoothing steps";
        }
    }
}

// A field with no feature says so (Stats::constant, for the Log, stderr and the JSON log).
TEST(FeatureEnergy, ConstantEnergyIsReported)
{
    CMeshO m;
    gs_test::MakeGridPlate(m, 20, 20, 0.05, 0.05);
    for (FeatureEnergyType t : kTypes) {
        const FE::Stats st = FE::Compute(m, t, 2);
        EXPECT_TRUE(st.constant) << EnergyName(t);
        for (const auto &v : m.vert) ASSERT_FLOAT_EQ(v.cQ(), 1.0f);
    }
    EXPECT_NE(FE::ConstantWarning(FeatureEnergyType::NormalVariation).find("constant"), std::string::npos);
    MakeVRidge(m, 20, 33);
    EXPECT_FALSE(FE::Compute(m, FeatureEnergyType::NormalVariation, 2).constant);
}
