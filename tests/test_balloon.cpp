// The side of a closed snake the tool shows as inside (issue 33: GeometricSnake::InsideDirections,
// the side a negative Balloon deflates the loop towards, a positive one inflates it away from):
// on a plate with two concentric circular ridges (radii 12 and 28 edge lengths), a loop seeded
// on the circle of radius 20 either way round has its inside towards the centre. And the outcome
// Balloon's sign gives a loop seeded outside a single ridge (BalloonOutcome).
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

namespace {

/// A plate with one circular tent ridge of radius kInner round the centre.
std::shared_ptr<Surface> MakeInnerRidge(CMeshO &m)
{
    gs_test::MakeHeightPlate(m, 80, 80, 1.0, 1.0, 0.2, 5, [](double x, double y) {
        const double r = std::hypot(x - kCentre[0], y - kCentre[1]);
        return kHeight * std::max(0.0, 1 - std::abs(r - kInner) / kWidth);
    });
    return gs_test::SurfaceWithEnergy(m);
}

} // namespace

// Balloon changes the outcome as the help says (README "Balloon", issue 33): a loop seeded 10
// edge lengths outside a ridge (radius 12, seeds on radius 22) ends on the ridge inside it with a
// negative Balloon (-0.3) and inflates away from it with a positive one (+0.3). Measured (150
// operations, the limit, for both: a ballooned loop never quite stops; 1.7 s CPU in all): -0.3
// mean radius 10.7, at most 2.5 off the ridge; +0.3 mean radius 30.7; 0 converges on the ridge
// after 98 operations (mean radius 11.9, at most 0.41 off: the coarse-to-fine capture reaches it
// without Balloon).
// Not asserted, as it does not hold today (issue 33): a positive Balloon from 18 edge lengths
// inside a ridge of radius 28 (seeds on radius 10) passes it (mean radius 31.8, 13.4 off), and a
// negative one from inside does not leave it (the capture pulls the loop out onto it).
TEST(BalloonOutcome, NegativeEndsOnTheFeatureInsidePositiveInflatesAway)
{
    CMeshO m;
    auto surf = MakeInnerRidge(m);
    for (double balloon : {-0.3, 0.0, 0.3}) {
        SnakeParams p;
        p.balloon = balloon;
        Snake s(surf, p);
        s.InitFromSeeds(Circle(m, 22, 8, false), true);
        SnakeRunLimits lim;
        lim.maxOperations = 150;
        const SnakeStop why = s.Run(lim);
        double mean = 0, off = 0;
        const std::vector<vcg::Point3d> pl = s.PolylinePositions();
        for (const auto &x : pl) {
            const double r = std::hypot(x[0] - kCentre[0], x[1] - kCentre[1]);
            mean += r / pl.size();
            off = std::max(off, std::fabs(r - kInner));
        }
        std::printf("balloon %+.1f: %s after %d operations, mean radius %.2f, at most %.2f off the ridge\n", balloon,
                    SnakeStopKey(why), s.Stats().operations, mean, off);
        EXPECT_NE(why, SnakeStop::Running);
        if (balloon < 0) {
            EXPECT_NEAR(mean, kInner, 2.0);
            EXPECT_LT(off, 4.0);
        } else if (balloon == 0) {
            EXPECT_EQ(why, SnakeStop::Converged);
            EXPECT_LT(off, 1.0);
        } else {
            EXPECT_GT(mean, 26.0); // moved out, away from the ridge
        }
    }
}
