// The shape diameter function (vcg_ext/surface/shape_diameter.h) and its use in part salience
// (vcg_ext/snake/part_salience.h, Param::widthExponent; issue 33, session 26).

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <generated_meshes.h>
#include <snake_test_util.h>
#include <vcg_ext/snake/part_salience.h>
#include <vcg_ext/surface/shape_diameter.h>

using namespace vcg::tri;

namespace {

/// A closed surface of revolution round z from a profile (rho, z) whose first and last points
/// lie on the axis (poles): rings of n vertices, outward-facing triangles. ringOf[v]: v's
/// profile index.
void MakeSdRevolution(CMeshO &m, const std::vector<std::pair<double, double>> &profile, int n, std::vector<int> &ringOf)
{
    m.Clear();
    const int np = int(profile.size());
    std::vector<std::vector<int>> id(np);
    for (int i = 0; i < np; ++i) {
        const int k = (i == 0 || i == np - 1) ? 1 : n;
        for (int j = 0; j < k; ++j) {
            const double a = 2 * M_PI * j / n;
            auto vi = Allocator<CMeshO>::AddVertices(m, 1);
            vi->P() = Point3m(profile[i].first * std::cos(a), profile[i].first * std::sin(a), profile[i].second);
            id[i].push_back(int(m.vert.size()) - 1);
            ringOf.push_back(i);
        }
    }
    auto at = [&](int i, int j) { return id[i].size() == 1 ? id[i][0] : id[i][((j % n) + n) % n]; };
    auto face = [&](int a, int b, int c) { Allocator<CMeshO>::AddFace(m, &m.vert[a], &m.vert[b], &m.vert[c]); };
    for (int i = 0; i + 1 < np; ++i)
        for (int j = 0; j < n; ++j) {
            const int A = at(i, j), B = at(i, j + 1), C = at(i + 1, j + 1), D = at(i + 1, j);
            if (i + 1 < np - 1) face(A, C, D); // (B - A) x (D - A) points outwards
            if (i > 0) face(A, B, C);
        }
    gs_test::EnableSnakeAdjacency(m);
}

std::vector<int> SdRing(const std::vector<int> &ringOf, int i)
{
    std::vector<int> r;
    for (int v = 0; v < int(ringOf.size()); ++v)
        if (ringOf[v] == i) r.push_back(v);
    return r;
}

// A sphere of radius 1: along the inward normal alone (one ray) the diameter is 2, to the
// tessellation's error; rays that leave the region read the region's radius.
TEST(ShapeDiameter, ReadsASpheresDiameterAlongTheInwardNormal)
{
    CMeshO m;
    std::vector<std::pair<double, double>> profile;
    const int k = 40;
    for (int i = 0; i <= k; ++i) profile.push_back({std::sin(M_PI * i / k), -std::cos(M_PI * i / k)});
    std::vector<int> ringOf;
    MakeSdRevolution(m, profile, 64, ringOf);
    ShapeDiameter<CMeshO>::Param par;
    par.rays = 1;
    const std::vector<int> eq = SdRing(ringOf, k / 2); // the equator: its opposite vertex is on it
    ShapeDiameter<CMeshO>::Region whole(m, eq, vcg::Point3d(0, 0, 0), 10.0, par);
    EXPECT_EQ(whole.Faces(), m.face.size());
    for (int v : eq) EXPECT_NEAR(whole.At(v), 2.0, 0.01);
    // the cone of 16 rays reads the chords 2 cos(theta), theta up to 60 degrees: at most 2
    ShapeDiameter<CMeshO>::Region cone(m, eq, vcg::Point3d(0, 0, 0), 10.0);
    const double d = cone.At(eq[0]);
    EXPECT_GT(d, 2.0 * std::cos(M_PI / 3));
    EXPECT_LT(d, 2.0);
    // a region of radius 0.5 round the point holds none of the far side
    ShapeDiameter<CMeshO>::Region near(m, {eq[0]}, vcg::Point3d::Construct(m.vert[eq[0]].cP()), 0.5, par);
    EXPECT_LT(near.Faces(), m.face.size() / 4);
    EXPECT_DOUBLE_EQ(near.At(eq[0]), 0.5);
}

// A cone (a limb tapering to a tip) standing on a thick disc (the body), flat ground where
// they meet: no valley there. A loop 7 rings up the cone and candidates moved into the body
// all cost 1 per length; on a cone L / sqrt(A) is the same at every ring, so salience alone
// keeps the loop; the width across the loop (the cone's diameter against the disc's
// thickness) moves it to the ring where the cone meets the disc (within 2 rings).
TEST(ShapeDiameter, MovesASalienceLoopToWhereALimbMeetsAWiderBody)
{
    CMeshO m;
    const double h = 0.1, Rb = 2.0, H = 1.5, rb = 0.5, Hc = 2.0;
    std::vector<std::pair<double, double>> profile;
    for (int i = 0; i < 20; ++i) profile.push_back({Rb * i / 20, 0.0});    // the bottom
    for (int i = 0; i < 15; ++i) profile.push_back({Rb, H * i / 15});      // the side
    for (int i = 0; i < 15; ++i) profile.push_back({Rb - (Rb - rb) * i / 15, H}); // the top
    const int junction = int(profile.size());
    for (int i = 0; i <= 20; ++i) profile.push_back({rb * (20 - i) / 20, H + Hc * i / 20}); // the cone
    std::vector<int> ringOf;
    MakeSdRevolution(m, profile, 48, ringOf);
    const std::vector<int> loop = SdRing(ringOf, junction + 7);
    // a candidate: the ring nearest (in the profile) to the guide's mean point, cost 1 per length
    auto find = [&](const std::vector<vcg::Point3d> &guide, const std::vector<int> &, double &c, bool, std::vector<int> *,
                    double *) {
        double rho = 0, z = 0;
        for (const auto &p : guide) rho += std::hypot(p[0], p[1]), z += p[2];
        rho /= guide.size(), z /= guide.size();
        int best = 1;
        for (int i = 1; i + 1 < int(profile.size()); ++i)
            if (std::hypot(profile[i].first - rho, profile[i].second - z) <
                std::hypot(profile[best].first - rho, profile[best].second - z))
                best = i;
        const std::vector<int> r = SdRing(ringOf, best);
        c = PartSalience<CMeshO>::Length(m, r);
        return r;
    };
    auto inBand = [](const vcg::Point3d &) { return false; };
    PartSalience<CMeshO>::Param par;
    const double cost = PartSalience<CMeshO>::Length(m, loop);
    par.widthExponent = 0;
    EXPECT_EQ(PartSalience<CMeshO>::Choose(m, loop, cost, h, par, find, inBand), loop);
    par.widthExponent = 0.5;
    const std::vector<int> got = PartSalience<CMeshO>::Choose(m, loop, cost, h, par, find, inBand);
    ASSERT_FALSE(got.empty());
    const int ring = ringOf[got[0]];
    std::vector<int> sorted = got;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(sorted, SdRing(ringOf, ring)); // one whole ring
    // at the junction or up to 2 rings (0.2 units, 0.4 of the cone's radius there) up the cone:
    // rays from the cone's base run down into the disc, so the jump in width is read from
    // where the cone is still thin against where the disc is (the candidate at the junction
    // itself reads the disc on both sides)
    EXPECT_GE(ring, junction);
    EXPECT_LE(ring, junction + 2);
}

} // namespace
