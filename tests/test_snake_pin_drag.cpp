// A pinned drag (issue 37, observation 5): a converged open snake on a crease of fandisk, a middle
// sample moved several edge lengths across the crease and pinned there, Run again: the ends stay
// where they were, on the crease, the samples away from the pin go back onto it, and the curve
// does not zig-zag beside the pin. Before the fix, every point edit sent the run back to the
// coarsest energy level, which merges the crease with the fillet beside it: a pin 6 edge lengths
// off pulled the far end 4.5 edge lengths off the crease (projection method) or slid it 5.7 along
// (embedding method), with turns of up to 168 degrees.
#include <gtest/gtest.h>

#include <cstdio>

#include <capture_cases.h>
#include <vcg_ext/session/controller.h>

using namespace vcg::tri;
using Controller = SnakeController<CMeshO>;
typedef vcg::Point3d P3;

namespace {

/// The turning angle at b of the polygon a b c, in space.
double TurnDeg(const P3 &a, const P3 &b, const P3 &c)
{
    const P3 u = b - a, v = c - b;
    if (!(u.Norm() > 0) || !(v.Norm() > 0)) return 0;
    return vcg::math::ToDeg(std::acos(std::max(-1.0, std::min(1.0, (u * v) / (u.Norm() * v.Norm())))));
}

/// Mesh vertices `off` (+- 0.5 h) from the crease, nearest to p: the nearest one, and the
/// nearest on the other side of p (the drags across the crease, to either side).
std::vector<SurfacePoint> AcrossTargets(const CMeshO &m, const std::vector<P3> &crease, const P3 &p, double off, double h)
{
    int best[2] = {-1, -1};
    double bestD[2] = {1e300, 1e300};
    P3 dir0(0, 0, 0);
    for (int pass = 0; pass < 2; ++pass)
        for (size_t v = 0; v < m.vert.size(); ++v) {
            const P3 x = P3::Construct(m.vert[v].cP());
            const double d = (x - p).Norm();
            if (d > 3 * off || d >= bestD[pass] || std::abs(gs_test::DistToPolyline(x, crease) - off) > 0.5 * h) continue;
            if (pass == 1 && (x - p) * dir0 > 0) continue;
            bestD[pass] = d, best[pass] = int(v);
            if (pass == 0) dir0 = x - p;
        }
    std::vector<SurfacePoint> out;
    for (int b : best)
        for (size_t f = 0; b >= 0 && f < m.face.size(); ++f) {
            int k = 0;
            while (k < 3 && m.face[f].cV(k) != &m.vert[b]) ++k;
            if (k < 3) {
                out.push_back(SurfacePoint::AtCorner(int(f), k));
                break;
            }
        }
    return out;
}

struct DragCase
{
    SnakeMethod method;
    const char *name;
};

} // namespace

class PinnedDrag : public ::testing::TestWithParam<DragCase> {};

// On fandisk's four longest creases that have cases (capture_cases.h: the snakes seeded 1 edge length off),
// a middle sample is moved 5 edge lengths across the crease, to either side, and pinned.
TEST_P(PinnedDrag, TheRestReturnsToTheCreaseAndTheEndsHold)
{
    CMeshO m;
    ASSERT_TRUE(gs_test::LoadMesh(m, std::string(GS_DATA_DIR) + "/fandisk.ply"));
    gs_test::EnableSnakeAdjacency(m);
    const double h = MeshValidation<CMeshO>::MeanEdgeLength(m), D = 5.0;
    std::vector<gs_capture::Case> cases = gs_capture::MakeChainCases(m, {1.0}, 4);
    ASSERT_GE(cases.size(), 3u);
    int drags = 0;
    for (const auto &cs : cases)
        for (int side : {0, 1}) {
            Controller c(m);
            SnakeParams q;
            q.method = GetParam().method;
            c.SetNewSnakeParams(q);
            c.SetSeeds(cs.seeds);
            c.CloseSeeds(false);
            c.Run(2000);
            ASSERT_TRUE(c.Converged()) << cs.shape;
            auto &s = c.Get(0);
            auto dist = [&](const P3 &x) { return gs_test::DistToPolyline(x, cs.truth) / h; };
            std::vector<P3> before = s.positions();
            const int n = int(before.size()), k = n / 2;
            const std::vector<SurfacePoint> targets = AcrossTargets(m, cs.truth, before[k], D * h, h);
            if (side >= int(targets.size())) continue;
            const SurfacePoint target = targets[side];
            c.MoveSample(k, target, true);
            const double pinOff = dist(s.Samples()[k].p.Pd(m));
            ++drags;
            const int ops = c.Run(2000);
            std::vector<P3> p = s.positions();
            // the curve stretched round the pin gets samples there (SnakeGapRefine): the pin is
            // the one fixed sample
            const int n2 = int(p.size());
            ASSERT_GE(n2, n);
            int pk = -1;
            for (int i = 0; i < n2; ++i)
                if (s.Samples()[i].fixed) pk = i;
            ASSERT_GE(pk, 0);
            std::vector<double> arc(n2, 0.0);
            for (int i = 1; i < n2; ++i) arc[i] = arc[i - 1] + (p[i] - p[i - 1]).Norm();
            double far = 0, turn = 0;
            for (int i = 0; i < n2; ++i) {
                if (std::abs(arc[i] - arc[pk]) > 8 * h) far = std::max(far, dist(p[i]));
                if (i > 0 && i + 1 < n2 && std::abs(i - pk) > 2 + (n2 - n)) turn = std::max(turn, TurnDeg(p[i - 1], p[i], p[i + 1]));
            }
            const double endMoved = std::max((p.front() - before.front()).Norm(), (p.back() - before.back()).Norm()) / h;
            const double endOff = std::max(dist(p.front()), dist(p.back()));
            std::printf("%s %s side %d: pin %.2f h off, %d operations, converged %d; ends %.2f h off, moved %.2f h; "
                        "farther than 8 h from the pin: %.2f h off at most; largest turn past 2 samples from the pin %.1f deg; %d -> %d samples\n",
                        GetParam().name, cs.shape.c_str(), side, pinOff, ops, int(c.Converged()), endOff, endMoved, far, turn, n, n2);
            EXPECT_TRUE(c.Converged()) << cs.shape << " side " << side;
            EXPECT_LT(endMoved, 0.5) << cs.shape << " side " << side;
            EXPECT_LT(endOff, 0.35) << cs.shape << " side " << side;
            EXPECT_LT(far, 0.5) << cs.shape << " side " << side;
            EXPECT_LT(turn, 60.0) << cs.shape << " side " << side;
        }
    EXPECT_GE(drags, 5);
}

INSTANTIATE_TEST_SUITE_P(Methods, PinnedDrag,
                         ::testing::Values(DragCase{SnakeMethod::LocalEmbedding, "embedding"},
                                           DragCase{SnakeMethod::Projection3D, "projection"}),
                         [](const ::testing::TestParamInfo<DragCase> &i) { return std::string(i.param.name); });
