// Every run ends by itself and says why (issue 33, vcg_ext/snake/stop.h): converged, a closed
// snake collapsing or leaving the part it surrounded, Max operations or the time limit reached,
// cancelled. One test per reason, through GeometricSnake::Run and through the controller's Run
// and the edit tool's per-operation check (SnakeRunLimits::Check), which ignored the collapse
// before (observed: lion-head's eye, 237,068 operations in 104 s, until the user pressed Esc).
#include <gtest/gtest.h>

#include <cstdio>

#include <snake_test_util.h>
#include <vcg_ext/energy/feature_energy.h>
#include <vcg_ext/session/controller.h>

using namespace vcg::tri;
using gs_test::EnableSnakeAdjacency;
using Snake = GeometricSnake<CMeshO>;
using Surface = SnakeSurface<CMeshO>;

namespace {

std::shared_ptr<Surface> WithEnergy(CMeshO &m)
{
    return gs_test::SurfaceWithEnergy(m);
}

std::vector<int> Circle(const CMeshO &m, vcg::Point3d c, double r, int count)
{
    std::vector<vcg::Point3d> pts;
    for (int i = 0; i < count; ++i) {
        const double a = 2 * M_PI * i / count;
        pts.push_back(vcg::Point3d(c[0] + r * std::cos(a), c[1] + r * std::sin(a), c[2]));
    }
    return gs_test::NearestVertices(m, pts);
}

/// The collapsing case of test_snake_robustness: a closed snake round a smooth bump, where no
/// feature holds it (as lion-head's eye socket, which the normal variation marks as feature).
void MakeBump(CMeshO &m) { gs_test::MakeBumpPlate(m, 60, 60.0, 6.0, 8.0); }

/// An open tube along z (radius r, `around` x `along` cells) whose vertex quality falls along z:
/// a force along the tube everywhere and no well anywhere, so a loop round it slides away.
void MakeSlopedTube(CMeshO &m, int around, int along, double r, double len)
{
    m.Clear();
    vcg::tri::Allocator<CMeshO>::AddVertices(m, around * (along + 1));
    for (int j = 0; j <= along; ++j)
        for (int i = 0; i < around; ++i) {
            const double a = 2 * M_PI * i / around, z = len * j / along;
            auto &v = m.vert[j * around + i];
            v.P() = vcg::Point3f(float(r * std::cos(a)), float(r * std::sin(a)), float(z));
            v.Q() = float(1.0 - 0.8 * z / len);
        }
    vcg::tri::Allocator<CMeshO>::AddFaces(m, 2 * around * along);
    int f = 0;
    for (int j = 0; j < along; ++j)
        for (int i = 0; i < around; ++i) {
            auto *a = &m.vert[j * around + i], *b = &m.vert[j * around + (i + 1) % around];
            auto *c = &m.vert[(j + 1) * around + (i + 1) % around], *d = &m.vert[(j + 1) * around + i];
            m.face[f].V(0) = a, m.face[f].V(1) = b, m.face[f].V(2) = c, ++f;
            m.face[f].V(0) = a, m.face[f].V(1) = c, m.face[f].V(2) = d, ++f;
        }
    vcg::tri::UpdateBounding<CMeshO>::Box(m);
    EnableSnakeAdjacency(m);
    vcg::tri::UpdateNormal<CMeshO>::PerFaceNormalized(m);
}

/// A closed snake seeded round the bump (MakeBump).
class BumpLoop : public ::testing::Test
{
protected:
    void SetUp() override
    {
        MakeBump(m);
        s.reset(new Snake(WithEnergy(m)));
        s->InitFromSeeds(Circle(m, vcg::Point3d(30, 30, 0), 6.0, 6), true);
    }
    CMeshO m;
    std::unique_ptr<Snake> s;
};

int Count(const std::vector<std::string> &w, const std::string &what)
{
    int n = 0;
    for (const auto &x : w) n += x.find(what) != std::string::npos;
    return n;
}

} // namespace

TEST_F(BumpLoop, CollapsingLoopStopsWithItsReasonOnce)
{
    SnakeRunLimits lim;
    lim.maxOperations = 100000;
    const SnakeStop why = s->Run(lim);
    std::printf("bump: %d operations, stop %s: %s\n", s->Stats().operations, SnakeStopKey(why), s->Stats().stopMessage.c_str());
    EXPECT_EQ(why, SnakeStop::Collapsed);
    EXPECT_EQ(s->Stats().stop, SnakeStop::Collapsed);
    EXPECT_LT(s->Stats().operations, 300);
    EXPECT_NE(s->Stats().stopMessage.find("collapsing"), std::string::npos);
    EXPECT_TRUE(SnakeStopIsProblem(why));
    EXPECT_FALSE(s->Converged());
    // Run again: it stops at once, and the warning is not repeated
    const int ops = s->Stats().operations;
    EXPECT_EQ(s->Run(lim), SnakeStop::Collapsed);
    EXPECT_LE(s->Stats().operations - ops, 1);
    EXPECT_EQ(Count(s->Stats().warnings, "collapsing"), 1);
}

// The edit tool's Run steps through the controller and asks SnakeRunLimits::Check after every
// operation; the controller's Run does the same. Before, both went on while the loop sat
// collapsed (they looked only at convergence): the controller's Run used up its whole limit.
TEST(RunStop, ControllerAndToolLoopEndOnACollapse)
{
    CMeshO m;
    MakeBump(m);
    WithEnergy(m);
    SnakeController<CMeshO> c(m);
    c.UseQualityAsEnergy();
    c.SetSeeds(Circle(m, vcg::Point3d(30, 30, 0), 6.0, 6));
    c.CloseSeeds(true);
    const int ops = c.Run(20000);
    std::printf("controller: %d operations, stop %s\n", ops, SnakeStopKey(c.SelectedSnake()->Stats().stop));
    EXPECT_LT(ops, 300);
    EXPECT_EQ(c.SelectedSnake()->Stats().stop, SnakeStop::Collapsed);
    // the tool's loop: Step, then Check, from the operation count at the Run's start
    SnakeRunLimits lim;
    lim.maxOperations = 20000;
    lim.seconds = 600;
    const int ops0 = c.SelectedSnake()->Stats().operations;
    const auto t0 = SnakeClock::Now();
    SnakeStop why = SnakeStop::Running;
    while (why == SnakeStop::Running) {
        c.Step();
        why = lim.Check(c.SelectedSnake()->Stats().stop, c.SelectedSnake()->Stats().operations - ops0,
                        SnakeClock::MsSince(t0) / 1000);
    }
    EXPECT_EQ(why, SnakeStop::Collapsed);
    EXPECT_LE(c.SelectedSnake()->Stats().operations - ops0, 1);
}

TEST(RunStop, ConvergedIsAReasonAndNotAProblem)
{
    CMeshO m;
    gs_test::MakeRotatedIcoCylinder(m, 4);
    auto surf = WithEnergy(m);
    SnakeParams p;
    p.balloon = 0.3;
    Snake s(surf, p);
    s.InitFromSeeds(Circle(m, vcg::Point3d(0, 0, 1), 0.3, 6), true);
    const SnakeStop why = s.Run(SnakeRunLimits());
    std::printf("cap: %d operations, stop %s\n", s.Stats().operations, SnakeStopKey(why));
    EXPECT_EQ(why, SnakeStop::Converged);
    EXPECT_TRUE(s.Converged());
    EXPECT_FALSE(SnakeStopIsProblem(why));
    EXPECT_EQ(s.Stats().stopMessage, "converged");
}

TEST_F(BumpLoop, MaxOperationsEndsTheRunAndAnotherRunGoesOn)
{
    SnakeRunLimits lim;
    lim.maxOperations = 3;
    EXPECT_EQ(s->Run(lim), SnakeStop::MaxOperations);
    EXPECT_EQ(s->Stats().operations, 3);
    EXPECT_EQ(s->Stats().stop, SnakeStop::MaxOperations);
    EXPECT_NE(s->Stats().stopMessage.find("Max operations (3)"), std::string::npos) << s->Stats().stopMessage;
    EXPECT_EQ(Count(s->Stats().warnings, "Max operations"), 1);
    EXPECT_FALSE(s->Run(3)); // the old interface: not converged
    EXPECT_EQ(s->Stats().operations, 6) << "a limit of the last run does not end the next one";
}

TEST_F(BumpLoop, TimeLimitEndsTheRun)
{
    SnakeRunLimits lim;
    lim.maxOperations = 100000;
    lim.seconds = 1e-9; // reached by the first operation
    EXPECT_EQ(s->Run(lim), SnakeStop::TimeLimit);
    EXPECT_EQ(s->Stats().operations, 1);
    EXPECT_NE(s->Stats().stopMessage.find("time limit"), std::string::npos) << s->Stats().stopMessage;
    EXPECT_TRUE(SnakeStopIsProblem(SnakeStop::TimeLimit));
    lim.seconds = -1;
    EXPECT_THROW(s->Run(lim), SnakeError);
}

TEST_F(BumpLoop, CancelledByTheCallerIsNotAProblem)
{
    EXPECT_EQ(s->Run(SnakeRunLimits(), [](int op) { return op < 1; }), SnakeStop::Cancelled);
    EXPECT_EQ(s->Stats().operations, 2);
    EXPECT_FALSE(SnakeStopIsProblem(SnakeStop::Cancelled));
    EXPECT_EQ(s->Stats().stopMessage, "stopped by the user");
}

// A loop round a tube, pushed along it by an energy that falls along the tube and holds it
// nowhere: it would slide off the part for ever (and off the tube's end); it stops once it is
// clearly elsewhere, with its reason.
TEST(RunStop, LoopSlidingAlongItsPartStops)
{
    CMeshO m;
    MakeSlopedTube(m, 32, 120, 1.0, 24.0);
    auto surf = std::make_shared<Surface>(m);
    Snake s(surf);
    std::vector<int> ring;
    for (int i = 0; i < 32; i += 4) ring.push_back(10 * 32 + i); // z = 2
    s.InitFromSeeds(ring, true);
    SnakeRunLimits lim;
    lim.maxOperations = 2000;
    const SnakeStop why = s.Run(lim);
    vcg::Point3d c(0, 0, 0);
    for (const auto &x : s.positions()) c += x;
    c /= double(s.SampleCount());
    std::printf("tube: %d operations, stop %s, centre z %.2f: %s\n", s.Stats().operations, SnakeStopKey(why), c[2],
                s.Stats().stopMessage.c_str());
    EXPECT_EQ(why, SnakeStop::LeftPart);
    EXPECT_GT(c[2], 2 + 4.0) << "stops only once the loop is clearly away from where it started";
    EXPECT_LT(c[2], 22.0) << "and before it reaches the tube's end";
    EXPECT_NE(s.Stats().stopMessage.find("left the part"), std::string::npos);
}

TEST(RunStop, KeysAndSummaries)
{
    EXPECT_STREQ(SnakeStopKey(SnakeStop::Collapsed), "collapsed");
    EXPECT_STREQ(SnakeStopKey(SnakeStop::MaxOperations), "max_operations");
    EXPECT_STREQ(SnakeStopKey(SnakeStop::TimeLimit), "time_limit");
    EXPECT_STREQ(SnakeStopKey(SnakeStop::LeftPart), "left_part");
    EXPECT_EQ(std::string(SnakeStopSummary(SnakeStop::Converged)), "converged");
    EXPECT_NE(std::string(SnakeStopSummary(SnakeStop::MaxOperations)).find("NOT converged"), std::string::npos);
}
