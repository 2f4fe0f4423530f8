// SurfaceProjection::Closest (the naive method's projection and the engine's well probes):
// its bounding-box shortcuts must give the same face and barycentric coordinates, bit for bit,
// as a flood that computes every face's exact distance, at any scale and far from the origin.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <set>

#include "snake_test_util.h"
#include "vcg_ext/surface/surface_projection.h"

namespace {

using namespace vcg::tri;

// The flood of SurfaceProjection::Closest without shortcuts: every face reached through faces
// within `radius` of q (and the start face) is measured exactly; the first of the closest wins,
// where a later face must be closer by more than rounding (1e-12 of the coordinates and radius)
// to win.
SurfacePoint ReferenceClosest(const SnakeSurface<CMeshO> &s, int startFace, const vcg::Point3d &q, double radius,
                              int &visited)
{
    const CMeshO &m = s.Mesh();
    std::vector<int> todo(1, startFace);
    std::set<int> seen(todo.begin(), todo.end());
    const double tie = 1e-12 * (std::max({std::abs(q[0]), std::abs(q[1]), std::abs(q[2])}) + radius);
    double bestD = std::numeric_limits<double>::max();
    int bestF = startFace;
    vcg::Point3d bestP = q;
    auto tri = [&](int f) {
        const CFaceO &ff = m.face[f];
        return vcg::Triangle3<double>(vcg::Point3d::Construct(ff.cP(0)), vcg::Point3d::Construct(ff.cP(1)),
                                      vcg::Point3d::Construct(ff.cP(2)));
    };
    for (size_t next = 0; next < todo.size(); ++next) {
        const int f = todo[next];
        double d;
        vcg::Point3d c;
        vcg::TrianglePointDistance<double>(tri(f), q, d, c);
        if (d < bestD - tie) { bestD = d; bestF = f; bestP = c; }
        if (d > radius && f != startFace) continue;
        for (int k = 0; k < 3; ++k) {
            const CFaceO *h = m.face[f].cFFp(k);
            if (h == &m.face[f]) continue;
            const int hi = s.Idx(h);
            if (seen.insert(hi).second) todo.push_back(hi);
        }
    }
    visited = int(todo.size());
    vcg::Point3d b;
    if (!vcg::InterpolationParameters(tri(bestF), bestP, b)) b = vcg::Point3d(1.0 / 3, 1.0 / 3, 1.0 / 3);
    SurfacePoint sp(bestF, b);
    sp.Normalize();
    return sp;
}

// Points around the sharp edges and corners of a cube (several faces equally near, flat faces
// with q right above them, q beyond the radius of most of the flood): the same answer as the
// reference flood.
void CheckCube(double scale, double shift)
{
    CMeshO m;
    gs_test::MakeRotatedIcoCube(m, 4);
    for (auto &v : m.vert) v.P() = v.P() * scale + vcg::Point3f(shift, -shift, 0.5 * shift);
    gs_test::EnableSnakeAdjacency(m);
    SnakeSurface<CMeshO> surf(m);
    const double h = surf.MeanEdge();
    std::mt19937 rng(7);
    std::uniform_int_distribution<int> face(0, m.fn - 1);
    std::uniform_real_distribution<double> u(0, 1), off(-2, 2);
    int checked = 0, largeFloods = 0;
    for (int trial = 0; trial < 400; ++trial) {
        const int f = face(rng);
        double a = u(rng), b = u(rng);
        if (a + b > 1) a = 1 - a, b = 1 - b;
        const SurfacePoint p(f, vcg::Point3d(1 - a - b, a, b));
        const vcg::Point3d q = p.Pd(m) + vcg::Point3d(off(rng), off(rng), off(rng)) * h;
        const double radius = (trial % 2 ? 3 : 1) * h;
        int visited = 0, refVisited = 0;
        const SurfacePoint got = SurfaceProjection<CMeshO>::Closest(surf, f, q, radius, &visited);
        const SurfacePoint want = ReferenceClosest(surf, f, q, radius, refVisited);
        ASSERT_EQ(got.face, want.face) << "trial " << trial << " scale " << scale;
        for (int k = 0; k < 3; ++k) ASSERT_EQ(got.bary[k], want.bary[k]) << "trial " << trial;
        ASSERT_EQ(visited, refVisited);
        largeFloods += visited > 30;
        // never farther than the start point, and as near as the nearest face the flood holds
        EXPECT_LE((got.Pd(m) - q).Norm(), (p.Pd(m) - q).Norm() + 1e-6 * h);
        ++checked;
    }
    EXPECT_EQ(checked, 400);
    EXPECT_GT(largeFloods, 50); // the shortcuts were exercised on floods of many faces
}

TEST(SurfaceProjection, ClosestMatchesTheExactFloodAtAnyScale)
{
    CheckCube(1, 0);
    CheckCube(1e-30, 0);
    CheckCube(1e30, 0);
    CheckCube(1, 300); // far from the origin: the coordinates' rounding is larger than at 0
}

} // namespace
