// Open snakes near other features (issue 9): their ends hold and the span the user seeded stays
// covered, no end hooks towards a nearby second crease, and the final curve is smooth.
// Generated meshes with exact answers: plates whose height field has straight or circular
// creases that cut through the triangles, with a parallel crease a few edge lengths away.
#include <gtest/gtest.h>

#include <cstdio>

#include <snake_test_util.h>

using namespace vcg::tri;
using gs_test::EnableSnakeAdjacency;
using Snake = GeometricSnake<CMeshO>;
using Surface = SnakeSurface<CMeshO>;

namespace {

const double kCreaseTurn = 45.0; // degrees between the faces' normals across each crease: a CAD chamfer

/// An exact feature curve moved onto the mesh, with arc length along it.
struct Feature
{
    std::vector<vcg::Point3d> pts;
    std::vector<double> arc;

    Feature(CMeshO &m, const std::vector<vcg::Point3d> &exact) : pts(gs_test::ProjectOntoMesh(m, exact))
    {
        arc.assign(pts.size(), 0.0);
        for (size_t i = 1; i < pts.size(); ++i) arc[i] = arc[i - 1] + (pts[i] - pts[i - 1]).Norm();
    }
    double Dist(const vcg::Point3d &p) const { return gs_test::DistToPolyline(p, pts); }
    /// Arc length of the feature's point closest to p.
    double Param(const vcg::Point3d &p) const
    {
        double best = 1e300, t = 0;
        for (size_t i = 0; i + 1 < pts.size(); ++i) {
            vcg::Point3d d = pts[i + 1] - pts[i];
            double L2 = d.SquaredNorm();
            double u = L2 > 0 ? std::max(0.0, std::min(1.0, ((p - pts[i]) * d) / L2)) : 0.0;
            double dd = (p - (pts[i] + d * u)).Norm();
            if (dd < best) { best = dd; t = arc[i] + u * (arc[i + 1] - arc[i]); }
        }
        return t;
    }
};

/// What the acceptance asks of an open snake's final curve, in the snake's local length unit.
struct EndReport
{
    double coverage = 0;  ///< fraction of the feature between the first and last seed covered
    double endDist = 0;   ///< the farther of the two end samples from the feature
    double hook = 0;      ///< the farthest of the last 3 samples at either end from the feature
    double p95 = 0;       ///< all samples
    double maxTurnDeg = 0;///< largest turning angle between consecutive segments (MaxTurningDeg)
};

/// The largest turning angle between consecutive segments of the sample polygon (the straight
/// pieces between samples, Sec. 4.1), seen along `up`: the creases here run on height fields,
/// and seen from above the turning is the curve's own, not that of the facets under it.
double MaxTurningDeg(const std::vector<vcg::Point3d> &p, const vcg::Point3d &up)
{
    auto flat = [&](vcg::Point3d d) { return d - up * (d * up); };
    double worst = 0;
    for (size_t i = 1; i + 1 < p.size(); ++i) {
        vcg::Point3d a = flat(p[i] - p[i - 1]), b = flat(p[i + 1] - p[i]);
        if (!(a.Norm() > 0) || !(b.Norm() > 0)) continue;
        double c = (a * b) / (a.Norm() * b.Norm());
        worst = std::max(worst, vcg::math::ToDeg(std::acos(std::max(-1.0, std::min(1.0, c)))));
    }
    return worst;
}

EndReport Measure(Snake &s, const Feature &f, const vcg::Point3d &seedFirst, const vcg::Point3d &seedLast)
{
    EndReport r;
    const double u = s.LengthScale();
    std::vector<vcg::Point3d> p = s.positions();
    double t0 = f.Param(seedFirst), t1 = f.Param(seedLast);
    if (t0 > t1) std::swap(t0, t1);
    double c0 = f.Param(p.front()), c1 = f.Param(p.back());
    if (c0 > c1) std::swap(c0, c1);
    r.coverage = std::max(0.0, std::min(t1, c1) - std::max(t0, c0)) / (t1 - t0);
    r.endDist = std::max(f.Dist(p.front()), f.Dist(p.back())) / u;
    const int n = int(p.size());
    for (int i = 0; i < std::min(3, n); ++i)
        r.hook = std::max({r.hook, f.Dist(p[i]) / u, f.Dist(p[n - 1 - i]) / u});
    r.p95 = gs_test::MeasureCurve(p, u, [&](const vcg::Point3d &x) { return f.Dist(x); }).p95;
    r.maxTurnDeg = MaxTurningDeg(p, vcg::Point3d(0, 0, 1));
    return r;
}

struct EndCase
{
    SnakeMethod method;
    double offset; // seeds this many edge lengths off the crease (away from any second one)
    const char *name;
};

std::shared_ptr<Surface> PrepareEnds(CMeshO &m)
{
    return gs_test::SurfaceWithEnergy(m);
}

// ----- a straight crease with a chamfer: a second, parallel crease `gap` cells beside it

// The plate [0,80] x [0,40] of unit cells (a regular grid), folded along
// the line through (40,20) at 17 degrees to the grid and again `gap` cells beside it: a
// chamfered step, both creases cutting through triangles.
struct ChamferPlate
{
    double ang = vcg::math::ToRad(17.0), gap = 3.0;
    vcg::Point3d c{40, 20, 0};
    vcg::Point3d dir() const { return vcg::Point3d(std::cos(ang), std::sin(ang), 0); }
    double across(double x, double y) const { return -(x - c[0]) * std::sin(ang) + (y - c[1]) * std::cos(ang); }
    double height(double x, double y) const
    {
        return std::tan(vcg::math::ToRad(kCreaseTurn)) * std::max(0.0, std::min(gap, across(x, y)));
    }
    void Make(CMeshO &m) const
    {
        gs_test::MakeHeightPlate(m, 80, 40, 1.0, 1.0, 0.0, 11, [this](double x, double y) { return height(x, y); });
    }
    /// Point at `along` cells along the crease and `off` cells across it (negative: the flat side).
    vcg::Point3d At(double along, double off) const
    {
        vcg::Point3d n(-std::sin(ang), std::cos(ang), 0);
        vcg::Point3d p = c + dir() * along + n * off;
        p[2] = height(p[0], p[1]);
        return p;
    }
};

class StraightCreaseEnds : public ::testing::TestWithParam<EndCase> {};

/// Runs an open snake seeded `offset` cells off the chamfer's first crease, on the side away
/// from the second one, and measures its final curve. `fineOnly`: level 0 alone, no pyramid.
EndReport RunOnChamfer(const EndCase &c, bool fineOnly = false)
{
    ChamferPlate plate;
    CMeshO m;
    plate.Make(m);
    auto surf = PrepareEnds(m);
    if (fineOnly) surf->SetCaptureSmoothing(0);
    std::vector<vcg::Point3d> line;
    for (int i = 0; i <= 400; ++i) line.push_back(plate.At(-35 + 70.0 * i / 400, 0));
    Feature f(m, line);
    SnakeParams p;
    p.method = c.method;
    Snake s(surf, p);
    std::vector<vcg::Point3d> picks;
    for (double a : {-24.0, -8.0, 8.0, 24.0}) picks.push_back(plate.At(a, -c.offset));
    std::vector<int> seeds = gs_test::NearestVertices(m, picks);
    s.InitFromSeeds(seeds, false);
    s.Run(500);
    const vcg::Point3d first = vcg::Point3d::Construct(m.vert[seeds.front()].cP());
    const vcg::Point3d last = vcg::Point3d::Construct(m.vert[seeds.back()].cP());
    EndReport r = Measure(s, f, first, last);
    std::printf("%s: %d samples, %d operations, converged %d: coverage %.3f, end %.3f, hook %.3f, p95 %.3f "
                "local edges, largest turn %.1f deg\n", c.name, s.SampleCount(), s.Stats().operations,
                int(s.Converged()), r.coverage, r.endDist, r.hook, r.p95, r.maxTurnDeg);
    EXPECT_TRUE(s.Converged()) << c.name;
    return r;
}

// Observed: the last 2-3 samples of an open snake hooked off towards the nearby second crease
// (and whole stretches of the curve zigzagged between the two creases, or it ended on the
// second crease: p95 4.0-4.1 local edges): the coarse levels merge the two creases into one well
// between them, and the snake, pulled across the first crease into that well, rolled down
// either side at the switch to level 0. Now a sample of an open snake that crosses a
// feature-like level-0 well running along the curve, which the coarse level leads past, is held
// on level 0 (SnakeMotionRules::HoldAtWell). Seeded 3 cells off, the ends then still slid 2
// cells along the crease in the first coarse operations (coverage 0.943): they moved across
// their tangent, up to 28 degrees off the crease on the seed path's staircase; on coarse levels
// an end now moves along the coarse gradient (SnakeMotionRules::alongPullBlend).
TEST_P(StraightCreaseEnds, EndsHoldSpanStaysNoHook)
{
    const EndCase c = GetParam();
    const EndReport r = RunOnChamfer(c);
    EXPECT_GE(r.coverage, 0.95) << c.name;
    EXPECT_LT(r.endDist, 0.35) << c.name;
    EXPECT_LT(r.hook, 0.35) << c.name << ": an end hooks off the crease";
    EXPECT_LT(r.p95, 0.35) << c.name;
    EXPECT_LT(r.maxTurnDeg, 10.0) << c.name << ": the curve is jagged";
}

INSTANTIATE_TEST_SUITE_P(
    Chamfer, StraightCreaseEnds,
    ::testing::Values(EndCase{SnakeMethod::LocalEmbedding, 0, "embedding_on"},
                      EndCase{SnakeMethod::LocalEmbedding, 2, "embedding_2off"},
                      EndCase{SnakeMethod::LocalEmbedding, 3, "embedding_3off"},
                      EndCase{SnakeMethod::Projection3D, 0, "projection_on"},
                      EndCase{SnakeMethod::Projection3D, 2, "projection_2off"},
                      EndCase{SnakeMethod::Projection3D, 3, "projection_3off"}),
    [](const ::testing::TestParamInfo<EndCase> &i) { return std::string(i.param.name); });

// Observed: on the chamfer's straight crease, on level 0 alone (no coarse level to mislead
// it), the final curve turned by 11-18 degrees between consecutive segments: level 0 is linear
// in each face, its V-shaped wells pull every sample with full force onto the mesh's zigzag
// fold line, and beta cannot straighten it. The slope across the curve is now averaged over about
// one and a half triangles (snake/segment_motion.h, acrossSlope).
class StraightCreaseSmooth : public ::testing::TestWithParam<EndCase> {};

TEST_P(StraightCreaseSmooth, TurnsStayBelowTenDegrees)
{
    const EndCase c = GetParam();
    const EndReport r = RunOnChamfer(c, true);
    EXPECT_LT(r.maxTurnDeg, 10.0) << c.name << ": the curve is jagged";
    EXPECT_LT(r.p95, 0.35) << c.name;
    EXPECT_LT(r.hook, 0.35) << c.name;
    EXPECT_GE(r.coverage, 0.95) << c.name;
}

INSTANTIATE_TEST_SUITE_P(
    ChamferFineOnly, StraightCreaseSmooth,
    ::testing::Values(EndCase{SnakeMethod::LocalEmbedding, 0, "embedding_on"},
                      EndCase{SnakeMethod::LocalEmbedding, 1, "embedding_1off"},
                      EndCase{SnakeMethod::Projection3D, 0, "projection_on"},
                      EndCase{SnakeMethod::Projection3D, 1, "projection_1off"}),
    [](const ::testing::TestParamInfo<EndCase> &i) { return std::string(i.param.name); });

// ----- a curved crease: the top rim of the capped cylinder (rotated icosphere: triangles
// straddle it), an open arc of 135 degrees seeded on or below it
class CurvedCreaseEnds : public ::testing::TestWithParam<EndCase> {};

TEST_P(CurvedCreaseEnds, EndsHoldSpanStays)
{
    const EndCase c = GetParam();
    CMeshO m;
    gs_test::MakeRotatedIcoCylinder(m, 4);
    auto surf = PrepareEnds(m);
    const double h = surf->MeanEdge();
    std::vector<vcg::Point3d> rim;
    for (int i = 0; i <= 600; ++i) {
        double a = -0.4 + (0.75 * M_PI + 0.8) * i / 600;
        rim.push_back(vcg::Point3d(std::cos(a), std::sin(a), 1.0));
    }
    Feature f(m, rim);
    SnakeParams p;
    p.method = c.method;
    Snake s(surf, p);
    std::vector<vcg::Point3d> picks;
    for (int i = 0; i < 4; ++i) {
        double a = 0.75 * M_PI * i / 3;
        picks.push_back(vcg::Point3d(std::cos(a), std::sin(a), 1.0 - c.offset * h));
    }
    std::vector<int> seeds = gs_test::NearestVertices(m, picks);
    s.InitFromSeeds(seeds, false);
    s.Run(500);
    EndReport r = Measure(s, f, vcg::Point3d::Construct(m.vert[seeds.front()].cP()),
                          vcg::Point3d::Construct(m.vert[seeds.back()].cP()));
    std::printf("%s: %d samples, %d operations, converged %d: coverage %.3f, end %.3f, hook %.3f, p95 %.3f "
                "local edges, largest turn %.1f deg\n", c.name, s.SampleCount(), s.Stats().operations,
                int(s.Converged()), r.coverage, r.endDist, r.hook, r.p95, r.maxTurnDeg);
    EXPECT_TRUE(s.Converged()) << c.name;
    EXPECT_GE(r.coverage, 0.95) << c.name;
    EXPECT_LT(r.endDist, 0.35) << c.name;
    EXPECT_LT(r.hook, 0.35) << c.name;
    EXPECT_LT(r.p95, 0.35) << c.name;
}

INSTANTIATE_TEST_SUITE_P(
    CylinderRim, CurvedCreaseEnds,
    ::testing::Values(EndCase{SnakeMethod::LocalEmbedding, 0, "embedding_on"},
                      EndCase{SnakeMethod::LocalEmbedding, 2, "embedding_2off"},
                      EndCase{SnakeMethod::Projection3D, 0, "projection_on"},
                      EndCase{SnakeMethod::Projection3D, 2, "projection_2off"}),
    [](const ::testing::TestParamInfo<EndCase> &i) { return std::string(i.param.name); });

} // namespace
