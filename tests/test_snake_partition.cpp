// Partitioning of a snake into segments (paper Sec. 5.1, vcg_ext/snake/partition.h): every
// segment lies inside the snake and the segments cover it, for any length, corners and pins.
// Built with _GLIBCXX_ASSERTIONS (tests/CMakeLists.txt): an out-of-bounds sample index in the
// engine aborts here even in a release build.
#include <gtest/gtest.h>

#include <chrono>
#include <random>

#include <snake_test_util.h>
#include <vcg_ext/io/snake_io.h>
#include <vcg_ext/snake/partition.h>

using namespace vcg::tri;
using gs_test::EnableSnakeAdjacency;
using Snake = GeometricSnake<CMeshO>;
using Surface = SnakeSurface<CMeshO>;

namespace {

// Independent of SnakePartition::Check: indices in range and consecutive, every sample and
// every gap in a segment, borders held on both sides, sizes near the requested size.
void ExpectValid(const SnakePartition::Result &r, int n, bool closed, int S, const std::string &what)
{
    SCOPED_TRACE(what);
    ASSERT_FALSE(r.segments.empty());
    const int gaps = closed ? n : n - 1;
    std::vector<int> sampleHits(n, 0), gapHits(gaps, 0);
    auto inside = [&](const SnakeSegment &s) {
        for (size_t j = 0; j < s.idx.size(); ++j) {
            ASSERT_GE(s.idx[j], 0);
            ASSERT_LT(s.idx[j], n);
            if (j > 0) ASSERT_EQ(s.idx[j], (s.idx[j - 1] + 1) % n) << "not consecutive at " << j;
            if (j > 0 && !closed) ASSERT_GT(s.idx[j], s.idx[j - 1]);
        }
        ASSERT_LE(int(s.idx.size()), n);
    };
    for (const auto &s : r.segments) {
        inside(s);
        ASSERT_GE(s.idx.size(), std::min<size_t>(3, n));
        for (size_t j = 0; j < s.idx.size(); ++j) {
            sampleHits[s.idx[j]]++;
            if (j > 0) gapHits[s.idx[j - 1]]++;
        }
        if (SnakePartition::IsWholeLoop(s, n, closed)) gapHits[n - 1]++;
    }
    for (const auto &s : r.overlaps) {
        inside(s);
        ASSERT_GE(s.idx.size(), 3u);
        EXPECT_TRUE(!closed || (s.fixFirst && s.fixLast));
    }
    for (int i = 0; i < n; ++i) ASSERT_GE(sampleHits[i], 1) << "sample " << i << " in no segment";
    for (int g = 0; g < gaps; ++g) ASSERT_EQ(gapHits[g], 1) << "gap " << g << " not in exactly one segment";
    if (r.segments.size() > 1) {
        // consecutive segments share their border sample, held on both sides, with an overlap across it
        EXPECT_EQ(r.overlaps.size(), closed ? r.segments.size() : r.segments.size() - 1);
        for (size_t k = 0; k < r.segments.size(); ++k) {
            const SnakeSegment &a = r.segments[k];
            EXPECT_LE(int(a.idx.size()), 2 * S + 2) << "segment " << k;
            if (k + 1 == r.segments.size() && !closed) {
                EXPECT_EQ(a.idx.back(), n - 1);
                EXPECT_FALSE(a.fixLast);
                continue;
            }
            const SnakeSegment &b = r.segments[(k + 1) % r.segments.size()];
            EXPECT_EQ(a.idx.back(), b.idx.front());
            EXPECT_TRUE(a.fixLast && b.fixFirst);
        }
        if (!closed) {
            EXPECT_EQ(r.segments.front().idx.front(), 0);
            EXPECT_FALSE(r.segments.front().fixFirst);
        }
    }
    EXPECT_NO_THROW(SnakePartition::Check(r, n, closed));
}

} // namespace

TEST(SnakePartition, RandomSnakesAreCoveredBySegmentsInsideThem)
{
    std::mt19937 rng(20021);
    std::uniform_real_distribution<double> u(0, 1);
    int cases = 0, multi = 0;
    for (int t = 0; t < 3000; ++t) {
        const bool closed = t % 2 == 1;
        const int n = std::max(closed ? 3 : 2, int(std::exp(u(rng) * std::log(10000.0))) + (t % 7 == 0 ? 0 : 2));
        const int S = t % 5 == 0 ? 6 + int(u(rng) * 6) : 6 + int(u(rng) * 200);
        // corners: none, a few, dense runs, or every sample (a snake going back and forth)
        std::vector<int> corners;
        const int mode = t % 4;
        const double density = mode == 0 ? 0 : mode == 1 ? 0.01 : mode == 2 ? 0.3 : 1.0;
        for (int i = 0; i < n; ++i)
            if (u(rng) < density) corners.push_back(i);
        if (mode == 2) // plus corners piled up near the end, where they pushed borders past it
            for (int i = std::max(0, n - 3 * S); i < n; ++i) corners.push_back(i);
        std::shuffle(corners.begin(), corners.end(), rng);
        SnakePartition::Result r = SnakePartition::Compute(n, closed, S, corners);
        ExpectValid(r, n, closed, S, "n=" + std::to_string(n) + " S=" + std::to_string(S) + (closed ? " closed" : " open") +
                                         " corners=" + std::to_string(corners.size()));
        if (HasFatalFailure()) return;
        ++cases;
        multi += r.segments.size() > 1;
    }
    EXPECT_EQ(cases, 3000);
    EXPECT_GT(multi, 1500); // most cases really are partitioned
}

TEST(SnakePartition, EveryLengthFromThreeToFiveHundred)
{
    for (int closed = 0; closed < 2; ++closed)
        for (int S : {6, 7, 8, 13, 64})
            for (int n = 3; n <= 500; ++n) {
                std::vector<int> all(n);
                for (int i = 0; i < n; ++i) all[i] = i;
                ExpectValid(SnakePartition::Compute(n, closed, S, {}), n, closed, S, "no corners n=" + std::to_string(n));
                ExpectValid(SnakePartition::Compute(n, closed, S, all), n, closed, S, "all corners n=" + std::to_string(n));
                if (HasFatalFailure()) return;
            }
}

TEST(SnakePartition, BordersKeepAwayFromCorners)
{
    // one sharp corner exactly where the even border would be (sample 64 of 129, 2 segments)
    for (bool closed : {false, true}) {
        const int n = closed ? 128 : 129;
        SnakePartition::Result r = SnakePartition::Compute(n, closed, 64, {64});
        for (const auto &s : r.segments)
            for (int end : {s.idx.front(), s.idx.back()})
                if (end != 0 && end != n - 1) EXPECT_GE(std::abs(end - 64), 16) << "border at " << end;
    }
}

TEST(SnakePartition, CheckRefusesBrokenPartitions)
{
    SnakePartition::Result r = SnakePartition::Compute(200, false, 64, {});
    EXPECT_NO_THROW(SnakePartition::Check(r, 200, false));
    SnakePartition::Result past = r;
    past.segments.back().idx.push_back(200); // one past the end: what the old partition did
    EXPECT_THROW(SnakePartition::Check(past, 200, false), SnakeError);
    SnakePartition::Result hole = r;
    hole.segments.erase(hole.segments.begin() + 1);
    EXPECT_THROW(SnakePartition::Check(hole, 200, false), SnakeError);
    SnakePartition::Result jump = r;
    jump.overlaps[0].idx[2] += 1;
    EXPECT_THROW(SnakePartition::Check(jump, 200, false), SnakeError);
}

TEST(SnakePartition, LongSnakeWithCornersEverywhereIsFast)
{
    // the old partition looked at every corner for every border: quadratic, a hang at 100,000 samples
    const int n = 200000;
    std::vector<int> all(n);
    for (int i = 0; i < n; ++i) all[i] = i;
    auto t0 = std::chrono::steady_clock::now();
    for (bool closed : {false, true}) ExpectValid(SnakePartition::Compute(n, closed, 6, all), n, closed, 6, "200k");
    double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_LT(s, 30.0); // measured ~0.15 s; the old quadratic search would take hours
}

namespace {

std::shared_ptr<Surface> PrepareSnakeGrid(CMeshO &m, int n)
{
    gs_test::MakeFlatGrid(m, n);
    EnableSnakeAdjacency(m);
    FeatureEnergy<CMeshO>::Compute(m, FeatureEnergyType::NormalVariation, 2);
    return std::make_shared<Surface>(m);
}

void ExpectSnakeSane(Snake &s, int n)
{
    ASSERT_EQ(s.SampleCount(), n);
    for (const auto &x : s.Samples()) {
        ASSERT_TRUE(x.p.IsValid());
        vcg::Point3d q = x.p.Pd(s.GetSurface().Mesh());
        ASSERT_TRUE(std::isfinite(q[0]) && std::isfinite(q[1]) && std::isfinite(q[2]));
    }
}

} // namespace

TEST(SnakePartition, GridPlaneWithSeventySixSeedsBackAndForth)
{
    // issue 8: a batch snake on a 100x100 grid plane with 76 seeds going back and forth read
    // past the samples (sharp corners pushed the last borders beyond the end)
    CMeshO m;
    auto surf = PrepareSnakeGrid(m, 100);
    std::vector<int> seeds;
    for (int i = 0; i < 76; ++i) seeds.push_back(50 * 101 + 40 + (i % 2) * 5); // 5 edges back and forth
    for (bool closed : {false, true}) {
        SCOPED_TRACE(closed ? "closed" : "open");
        if (closed) seeds.push_back(30 * 101 + 50); // a closed seed list must not end on the first seed
        Snake s(surf);
        s.InitFromSeeds(seeds, closed);
        const int n = s.SampleCount();
        ASSERT_GT(n, 250);
        auto r = SnakePartition::Compute(n, closed, s.Params().segmentSamples,
                                         SnakePartition::Corners(s.positions(), closed));
        ExpectValid(r, n, closed, s.Params().segmentSamples, "engine snake");
        for (int op = 0; op < 2; ++op) s.Step();
        ExpectSnakeSane(s, n);
        EXPECT_FALSE(s.Polyline().empty());
    }
}

TEST(SnakePartition, RandomPinsAndCornersThroughTheEngine)
{
    // zig-zag snakes (a corner at most samples) with random pins: pins hold, nothing leaves the snake
    CMeshO m;
    auto surf = PrepareSnakeGrid(m, 60);
    std::mt19937 rng(7);
    for (int t = 0; t < 12; ++t) {
        const bool closed = t % 2 == 1;
        std::vector<int> seeds;
        const int count = 3 + int(rng() % 20);
        for (int i = 0; i < count; ++i) {
            int row = 5 + int(rng() % 50), col = 5 + int(rng() % 50);
            int v = row * 61 + col;
            if (!seeds.empty() && seeds.back() == v) continue;
            seeds.push_back(v);
        }
        if (closed && seeds.front() == seeds.back()) seeds.pop_back();
        if (int(seeds.size()) < (closed ? 3 : 2)) continue;
        SnakeParams p;
        p.segmentSamples = 6 + int(rng() % 40);
        Snake s(surf, p);
        s.InitFromSeeds(seeds, closed);
        const int n = s.SampleCount();
        std::vector<std::pair<int, SurfacePoint>> pins;
        for (int i = 0; i < n; ++i)
            if (rng() % 10 == 0) {
                s.SetFixed(i, true);
                pins.push_back({i, s.Samples()[i].p});
            }
        s.Step();
        ExpectSnakeSane(s, n);
        for (auto &pin : pins) {
            EXPECT_EQ(s.Samples()[pin.first].p.face, pin.second.face);
            EXPECT_EQ(s.Samples()[pin.first].p.bary, pin.second.bary);
        }
    }
}

TEST(SnakePartition, SidecarOfTenThousandZigZagSamplesRestores)
{
    // issue 8: a sidecar of 10,000 samples crashed meshlabserver through FromJson -> Polyline ->
    // retrace -> partition. Samples zig-zag between two faces, so every sample is a corner.
    CMeshO m;
    auto surf = PrepareSnakeGrid(m, 100);
    nlohmann::json j;
    j["closed"] = false;
    j["samples"] = nlohmann::json::array();
    for (int i = 0; i < 10000; ++i) {
        int face = 2 * (50 * 100 + 40 + (i % 2) * 3);
        j["samples"].push_back({{"face", face}, {"bary", {0.2, 0.3, 0.5}}, {"fixed", i % 97 == 0}});
    }
    Snake s(surf);
    auto t0 = std::chrono::steady_clock::now();
    SnakeIO<CMeshO>::FromJson(s, nlohmann::json::parse(j.dump()));
    ASSERT_EQ(s.SampleCount(), 10000);
    std::vector<SurfacePoint> pl = s.Polyline();
    double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_GE(pl.size(), 10000u);
    for (const auto &p : pl) ASSERT_TRUE(p.IsValid());
    ExpectSnakeSane(s, 10000);
    EXPECT_LT(secs, 60.0); // measured ~0.2 s: a bound against a hang only (the machine is shared)
}
