// Embeddings that last (issue 12, the paper's Sec. 4.2: one embedding serves several updates).
// SnakeSegmentMotion keeps a segment's region and embedding while the samples stay within half
// the region's margin of its core, and a kept embedding serves whichever segment the samples
// form: the partition's borders move with the curve's corners, and each move of a border used
// to make every segment new (the 300-sample loop on bunny00: half of its 1.46 embeddings per
// operation).
#include <gtest/gtest.h>

#include <numeric>

#include <snake_test_util.h>

using namespace vcg::tri;

namespace {

struct Strip
{
    CMeshO m;
    std::shared_ptr<SnakeSurface<CMeshO>> surf;
    SnakeCurve st;
    SnakeStats stats;
    SnakeMotionFrame fr;
    std::unique_ptr<SnakeSegmentMotion<CMeshO>> motion;

    // An open snake of about 50 samples, one edge length apart, along the middle row of a
    // jittered 60 x 20 plate.
    Strip()
    {
        gs_test::MakeGridPlate(m, 60, 20, 1.0, 1.0, 0.2, 3);
        gs_test::EnableSnakeAdjacency(m);
        FeatureEnergy<CMeshO>::Compute(m, FeatureEnergyType::NormalVariation, 0);
        surf = std::make_shared<SnakeSurface<CMeshO>>(m);
        GeometricSnake<CMeshO> s(surf);
        s.InitFromSeeds(gs_test::NearestVertices(m, {vcg::Point3d(5, 10, 0), vcg::Point3d(55, 10, 0)}), false);
        st.samples = s.Samples();
        st.closed = false;
        st.params = s.Params();
        st.unit = s.LengthScale();
        st.gaps.assign(st.NumGaps(), SnakeGap());
        fr.unit = st.unit;
        motion.reset(new SnakeSegmentMotion<CMeshO>(surf));
    }
    int Samples() const { return int(st.samples.size()); }
    // Retraces samples [from, to] (no update: the samples stay where they are).
    void Retrace(int from, int to)
    {
        SnakeSegment seg;
        for (int i = from; i <= to; ++i) seg.idx.push_back(i);
        seg.fixFirst = seg.fixLast = true;
        motion->Move(st, stats, seg, 0, fr);
    }
};

} // namespace

TEST(KeptEmbeddings, ASegmentWhoseBordersMovedUsesTheKeptEmbedding)
{
    Strip s;
    ASSERT_GT(s.Samples(), 40);
    s.motion->BeginOperation();
    s.Retrace(0, 30);
    EXPECT_EQ(s.stats.embeddings, 1);
    // the next operation's partition moved the border by two samples: the same samples, and
    // the one before them, lie in the kept region's core
    s.motion->BeginOperation();
    s.Retrace(1, 28);
    EXPECT_EQ(s.stats.embeddings, 1);
    EXPECT_EQ(s.stats.reuses, 1);
    // ... and so does its first segment again
    s.Retrace(0, 30);
    EXPECT_EQ(s.stats.embeddings, 1);
    EXPECT_EQ(s.stats.reuses, 2);
}

TEST(KeptEmbeddings, SamplesBeyondHalfTheMarginNeedANewEmbedding)
{
    Strip s;
    s.motion->BeginOperation();
    s.Retrace(0, 30);
    // a segment reaching 10 samples (10 edge lengths) past the core: beyond any margin
    s.motion->BeginOperation();
    s.Retrace(5, 40);
    EXPECT_EQ(s.stats.embeddings, 2);
    EXPECT_EQ(s.stats.reuses, 0);
    // a segment elsewhere on the snake, overlapping neither
    s.Retrace(42, s.Samples() - 1);
    EXPECT_EQ(s.stats.embeddings, 3);
}

TEST(KeptEmbeddings, EmbeddingsNoSegmentUsedForTwoOperationsAreDropped)
{
    Strip s;
    s.motion->BeginOperation();
    s.Retrace(0, 30);
    for (int op = 0; op < 3; ++op) { // the snake moved on: another stretch only
        s.motion->BeginOperation();
        s.Retrace(35, s.Samples() - 1);
    }
    EXPECT_EQ(s.stats.embeddings, 2);
    EXPECT_EQ(s.motion->KeptEmbeddings(), 1);
    s.Retrace(0, 30);
    EXPECT_EQ(s.stats.embeddings, 3);
}

// A kept embedding serves a segment it was not made for exactly as well: the samples retraced in
// it are where they were, to rounding, and so are the gaps' crossings.
TEST(KeptEmbeddings, AnAdoptedEmbeddingMapsTheSamplesBackToThemselves)
{
    Strip s;
    s.motion->BeginOperation();
    s.Retrace(0, 30);
    std::vector<SnakeSample> before = s.st.samples;
    s.motion->BeginOperation();
    s.Retrace(2, 27);
    ASSERT_EQ(s.stats.reuses, 1);
    for (int i = 0; i < s.Samples(); ++i) {
        EXPECT_EQ(s.st.samples[i].p.face, before[i].p.face) << i;
        EXPECT_LT((s.st.samples[i].p.Pd(s.m) - before[i].p.Pd(s.m)).Norm(), 1e-9) << i;
    }
    for (int g = 2; g < 27; ++g) EXPECT_TRUE(s.st.gaps[g].tightenPending || s.st.gaps[g].traced) << g;
}
