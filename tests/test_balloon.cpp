// The side of a closed snake the tool shows as inside (issue 33: GeometricSnake::InsideDirections,
// the side a negative Balloon deflates the loop towards, a positive one inflates it away from):
// on a plate with two concentric circular ridges (radii 12 and 28 edge lengths), a loop seeded
// on the circle of radius 20 either way round has its inside towards the centre.
#include <gtest/gtest.h>

#include <cstdio>

#include <snake_test_util.h>
#include <vcg_ext/energy/feature_energy.h>

using namespace vcg::tri;
using gs_test::EnableSnakeAdjacency;
using Snake = GeometricSnake<CMeshO>;
using Surface = SnakeSurface<CMeshO>;

namespace {

const double kSize = 80, kInner = 12, kOuter = 28, kWidth = 2, kHeight = 2;
const vcg::Point3d kCentre(kSize / 2, kSize / 2, 0);


/// Two tent-profile ridges round the centre (1 edge length cells, jittered triangulation).
std::shared_ptr<Surface> MakeRidges(CMeshO &m)
{
    gs_test::MakeHeightPlate(m, 80, 80, 1.0, 1.0, 0.2, 5, [](double x, double y) {
        const double r = std::hypot(x - kCentre[0], y - kCentre[1]);
        return kHeight * (std::max(0.0, 1 - std::abs(r - kInner) / kWidth) + std::max(0.0, 1 - std::abs(r - kOuter) / kWidth));
    });
    return gs_test::SurfaceWithEnergy(m);
}

std::vector<int> Circle(const CMeshO &m, double r, int count, bool clockwise)
{
    std::vector<vcg::Point3d> pts;
    for (int i = 0; i < count; ++i) {
        const double a = (clockwise ? -2 : 2) * M_PI * i / count;
        pts.push_back(kCentre + vcg::Point3d(r * std::cos(a), r * std::sin(a), 0));
    }
    return gs_test::NearestVertices(m, pts);
}

} // namespace

class BalloonDirection : public ::testing::TestWithParam<bool> {}; // seeds clockwise or not

// The side the tool draws as inside points to the centre of a loop, whichever way it was seeded.
TEST_P(BalloonDirection, InsideDirectionsPointIntoTheLoop)
{
    CMeshO m;
    auto surf = MakeRidges(m);
    Snake s(surf);
    s.InitFromSeeds(Circle(m, 20, 8, GetParam()), true);
    const std::vector<vcg::Point3d> in = s.InsideDirections(), p = s.positions();
    ASSERT_EQ(in.size(), p.size());
    int inward = 0;
    for (size_t i = 0; i < p.size(); ++i) {
        vcg::Point3d toCentre = kCentre - p[i];
        toCentre[2] = 0;
        inward += in[i] * toCentre.Normalize() > 0.5; // the initial curve is a polygon of edge paths
    }
    EXPECT_EQ(inward, int(p.size()));
    Snake open(surf);
    open.InitFromSeeds(Circle(m, 20, 3, GetParam()), false);
    EXPECT_TRUE(open.InsideDirections().empty());
}

INSTANTIATE_TEST_SUITE_P(SeedOrder, BalloonDirection, ::testing::Values(false, true));
