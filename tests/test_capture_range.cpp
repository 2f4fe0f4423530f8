// Capture range (issue 9): snakes seeded 1..6 edge lengths to one side of a crease must slither
// onto it: >= 95 % of the cases up to 4 edge lengths, >= 80 % at 6, with both methods, on the
// projected icospheres and on fandisk (tests/capture_cases.h). A sparse set of the cases of the
// evaluation's sweep (bench/eval/gs_eval --stages capture), to stay fast.
// GS_CAPTURE_VERBOSE=1 prints every case.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

#include <capture_cases.h>

using namespace vcg::tri;
using Surface = SnakeSurface<CMeshO>;

namespace {

struct Tally
{
    std::map<double, std::pair<int, int>> byOffset; // offset -> (captured, cases)
    void Add(double off, bool ok) { auto &t = byOffset[off]; t.first += ok; t.second += 1; }
    double Share(double lo, double hi) const
    {
        int c = 0, n = 0;
        for (auto &kv : byOffset)
            if (kv.first >= lo && kv.first <= hi) c += kv.second.first, n += kv.second.second;
        return n ? double(c) / n : 0;
    }
    int Cases(double lo, double hi) const
    {
        int n = 0;
        for (auto &kv : byOffset)
            if (kv.first >= lo && kv.first <= hi) n += kv.second.second;
        return n;
    }
};

void RunAll(const std::vector<gs_capture::Case> &cases, std::shared_ptr<Surface> surf,
            SnakeMethod method, Tally &t)
{
    const bool verbose = std::getenv("GS_CAPTURE_VERBOSE") != nullptr;
    for (const auto &c : cases) {
        gs_capture::Result r = gs_capture::Run(surf, c, method);
        t.Add(c.offset, r.Captured());
        if (verbose || !r.Captured())
            std::printf("[capture] %-10s %-6s %-10s offset %.0f: capture %3.0f %% coverage %3.0f %% mean %.2f h, %d ops%s%s\n",
                        c.shape.c_str(), c.closed ? "closed" : "open",
                        method == SnakeMethod::LocalEmbedding ? "embedding" : "projection", c.offset, 100 * r.capture,
                        100 * r.coverage, r.meanDist, r.operations, r.converged ? "" : " (not converged)",
                        r.Captured() ? "" : "  MISSED");
    }
}

void CheckShares(const char *what, const Tally &t)
{
    for (auto &kv : t.byOffset)
        std::printf("[capture] %s offset %.0f: %d / %d captured\n", what, kv.first, kv.second.first, kv.second.second);
    ASSERT_GT(t.Cases(0, 4), 0);
    ASSERT_GT(t.Cases(6, 6), 0);
    EXPECT_GE(t.Share(0, 4), 0.95) << what << ": captured up to 4 edge lengths";
    EXPECT_GE(t.Share(6, 6), 0.80) << what << ": captured at 6 edge lengths";
}

class CaptureRange : public ::testing::TestWithParam<SnakeMethod> {};

} // namespace

TEST_P(CaptureRange, ProjectedIcospheresAndFandisk)
{
    const SnakeMethod method = GetParam();
    const bool full = std::getenv("GS_CAPTURE_FULL") != nullptr;
    const std::vector<double> offsets = full ? std::vector<double>{1, 2, 3, 4, 5, 6} : std::vector<double>{2, 4, 6};
    Tally t;
    struct Shape { const char *name; int subdiv; };
    for (Shape sh : {Shape{"cube", 4}, Shape{"octahedron", 5}, Shape{"cylinder", 4}}) {
        CMeshO m;
        gs_capture::BuildShape(m, sh.name, sh.subdiv);
        FeatureEnergy<CMeshO>::Compute(m, FeatureEnergyType::NormalVariation, 2);
        auto surf = std::make_shared<Surface>(m);
        std::vector<gs_capture::Case> cases;
        for (bool closed : {false, true})
            for (double off : offsets) {
                gs_capture::Case c;
                if (gs_capture::MakeGeneratedCase(m, sh.name, closed, off, c)) cases.push_back(c);
            }
        RunAll(cases, surf, method, t);
    }
    {
        CMeshO m;
        ASSERT_TRUE(gs_test::LoadMesh(m, std::string(GS_DATA_DIR) + "/fandisk.ply"));
        gs_test::EnableSnakeAdjacency(m);
        FeatureEnergy<CMeshO>::Compute(m, FeatureEnergyType::NormalVariation, 2);
        auto surf = std::make_shared<Surface>(m);
        RunAll(gs_capture::MakeChainCases(m, offsets, full ? 4 : 2), surf, method, t);
    }
    CheckShares(method == SnakeMethod::LocalEmbedding ? "embedding" : "projection", t);
}

INSTANTIATE_TEST_SUITE_P(Methods, CaptureRange,
                         ::testing::Values(SnakeMethod::LocalEmbedding, SnakeMethod::Projection3D),
                         [](const ::testing::TestParamInfo<SnakeMethod> &i) {
                             return i.param == SnakeMethod::LocalEmbedding ? std::string("Embedding")
                                                                           : std::string("Projection");
                         });
