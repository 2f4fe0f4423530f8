// Any scale (issue 8): the parameters are in mean edge lengths, so the same mesh scaled by
// 1e-30, 1 or 1e30 gives the same snake up to the scale factor. Lengths are computed in double:
// squared in float, 1e30 overflows and 1e-30 underflows.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>

#include <snake_test_util.h>

using namespace vcg::tri;
using gs_test::EnableSnakeAdjacency;

namespace {

// CMeshO's components with double coordinates, normals and quality. Scaled by 1e30 its
// coordinates are rounded by 1e-16 of the size instead of float's 6e-8: the same mesh, so any
// difference between the snakes would come from the engine (the engine is templated on the mesh).
class DVertex;
class DFace;
struct DUsed : public vcg::UsedTypes<vcg::Use<DVertex>::AsVertexType, vcg::Use<DFace>::AsFaceType> {};
class DVertex : public vcg::Vertex<DUsed, vcg::vertex::InfoOcf, vcg::vertex::Coord3d, vcg::vertex::BitFlags,
                                   vcg::vertex::Normal3d, vcg::vertex::Qualityd, vcg::vertex::Color4b,
                                   vcg::vertex::VFAdjOcf, vcg::vertex::MarkOcf, vcg::vertex::CurvaturedOcf,
                                   vcg::vertex::CurvatureDirdOcf> {};
class DFace : public vcg::Face<DUsed, vcg::face::InfoOcf, vcg::face::VertexRef, vcg::face::BitFlags,
                               vcg::face::Normal3d, vcg::face::MarkOcf, vcg::face::FFAdjOcf, vcg::face::VFAdjOcf> {};
class DMesh : public vcg::tri::TriMesh<vcg::vertex::vector_ocf<DVertex>, vcg::face::vector_ocf<DFace>> {};

struct Outcome
{
    std::vector<vcg::Point3d> samples; // divided by the scale
    double seedPathLength = 0;         // divided by the scale
    bool converged = false;
    int operations = 0;
};

// The cube [-1,1]^3 scaled by s; the snake starts 2 edge lengths inside the border of the face z = 1
// (closed) or beside the edge x = y = 1 (open).
template <class M = CMeshO>
Outcome RunCube(double s, bool closed, SnakeMethod method)
{
    using Snake = GeometricSnake<M>;
    using Surface = SnakeSurface<M>;
    M m;
    gs_test::MakeRotatedIcoCube(m, 4, s);
    EnableSnakeAdjacency(m);
    FeatureEnergy<M>::Compute(m, FeatureEnergyType::NormalVariation, 2);
    auto surf = std::make_shared<Surface>(m);
    const double h = surf->MeanEdge() / s;
    std::vector<vcg::Point3d> pts;
    if (closed) {
        const double a = 1.0 - 2 * h;
        for (auto q : std::vector<std::array<double, 2>>{{-a, -a}, {0, -a}, {a, -a}, {a, 0}, {a, a}, {0, a}, {-a, a}, {-a, 0}})
            pts.push_back(vcg::Point3d(q[0], q[1], 1.0) * s);
    } else {
        for (double z : {-0.6, -0.2, 0.2, 0.6}) pts.push_back(vcg::Point3d(1.0, 1.0 - 2 * h, z) * s);
    }
    std::vector<int> seeds = gs_test::NearestVertices(m, pts);
    Outcome o;
    o.seedPathLength = SeedPath<M>::Compute(m, seeds, closed).length / s;
    SnakeParams p;
    p.method = method;
    Snake snake(surf, p);
    snake.InitFromSeeds(seeds, closed);
    snake.Run(closed ? 300 : 150);
    o.converged = snake.Converged();
    o.operations = snake.Stats().operations;
    for (const auto &x : snake.positions()) o.samples.push_back(x / s);
    return o;
}

double Hausdorff(const std::vector<vcg::Point3d> &a, const std::vector<vcg::Point3d> &b, bool closed)
{
    double d = 0;
    for (auto &x : a) d = std::max(d, gs_test::DistToPolyline(x, b, closed));
    for (auto &x : b) d = std::max(d, gs_test::DistToPolyline(x, a, closed));
    return d;
}

// "The same result to 1e-6 relative" (issue 8): sample by sample, to 1e-6 of the mesh's size
// (its bounding-box diagonal, 2 sqrt(3) half sizes). Scales 2^-100 and 2^100 (about 8e-31 and
// 1.3e30) scale the coordinates exactly, so any difference would come from the code: the snake is
// the same to the bit. At 1e-30 and 1e30 a float mesh (CMeshO, MeshLab 2020.09) is not the same
// mesh: every coordinate is rounded to float differently (relative 6e-8 of the size, i.e. 1e-6 of
// an edge's direction on this 32-edge cube), so the feature energy differs by up to 6e-7 before
// the snake moves. Open snakes follow that perturbation continuously: `sampleTol` = 1e-6 holds. A
// closed loop with corners does not always: the step control's halving is a yes/no decision, one
// sample's decision can flip on the perturbed energy, and the loop has no single state to return
// to: it can turn along itself at no cost, and across the cube's edge the level-0 well is flat
// over the triangles that straddle it (its samples end anywhere in that band, z from 0.96 to 1).
// It then stops on another state within its convergence tolerance (0.02 edge lengths per
// operation). Stepped in lockstep (session 10): at 1e30 the loop stays within 1.1e-6 of scale 1
// to the end; at 1e-30 it does too until operation 27, where one sample's move on level 1 raised
// its energy by 0.001000 at scale 1 and by 0.000999 at 1e-30, against the step control's noise of
// 1e-3 (halved at one scale, grown at the other): 6e-5 after it. Until kept embeddings served any
// segment (issue 12) the loop took another path, with such a near-tie at operation 7 on the
// coarsest level: 3e-3 / 4.4e-3.
// For it on a float mesh `sampleTol` is that band, as at ordinary scales (see
// ExtremeScalesMoveTheFloatLoopNoMoreThanOrdinaryRounding below); on a double mesh
// (DMesh, the same mesh at every scale) it is 1e-6 (docs/evaluation.md, "Any scale").
template <class M = CMeshO>
void ExpectSameAtEveryScale(bool closed, SnakeMethod method, double sampleTol,
                            std::vector<double> scales = {std::ldexp(1.0, -100), std::ldexp(1.0, 100), 1e-30, 1e30})
{
    Outcome ref = RunCube<M>(1.0, closed, method);
    ASSERT_TRUE(ref.converged);
    // the reference really captured the feature (a collapsed snake would also be "the same")
    double spread = 0;
    for (const auto &x : ref.samples) spread = std::max(spread, (x - ref.samples.front()).Norm());
    ASSERT_GT(spread, 1.0);
    const double size = 2 * std::sqrt(3.0); // the cube's diagonal, in units of its half size
    for (double s : scales) {
        SCOPED_TRACE("scale " + std::to_string(std::log10(s)) + " decades");
        int e2 = 0;
        const bool exact = std::frexp(s, &e2) == 0.5; // a power of two
        Outcome o = RunCube<M>(s, closed, method);
        EXPECT_NEAR(o.seedPathLength, ref.seedPathLength, 1e-6 * ref.seedPathLength);
        EXPECT_TRUE(o.converged);
        ASSERT_EQ(o.samples.size(), ref.samples.size());
        double worst = 0;
        for (size_t i = 0; i < o.samples.size(); ++i) worst = std::max(worst, (o.samples[i] - ref.samples[i]).Norm());
        std::printf("scale %g: %d operations (%d at scale 1), largest sample difference %.3g of the size, "
                    "curves %.3g apart\n", s, o.operations, ref.operations, worst / size,
                    Hausdorff(o.samples, ref.samples, closed) / size);
        if (exact) {
            EXPECT_EQ(o.operations, ref.operations);
            EXPECT_EQ(worst, 0.0) << "a power-of-two scale must give the same snake to the bit";
        } else {
            EXPECT_LT(worst / size, sampleTol) << "largest difference, relative to the mesh's size";
        }
    }
}

} // namespace

TEST(AnyScale, ClosedSnakeOnTheCubeFaceIsTheSame)
{
    // on the float mesh: within the flat band of the level-0 well across the cube's edges
    // (0.75 edge lengths), as at ordinary scales (ExtremeScalesMoveTheFloatLoopNoMoreThanOrdinaryRounding).
    // Measured: 6.0e-5 of the size at 1e-30 and 3.3e-7 at 1e30 (0.0030 and 0.0044 before session
    // 10); it collapsed to a point at 1e30 before lengths were computed in double.
    ExpectSameAtEveryScale(true, SnakeMethod::LocalEmbedding, 0.75 * (2.0 / 32) / (2 * std::sqrt(3.0)));
}

// The same mesh at every scale (coordinates in double): every snake is the same to 1e-6, the
// closed loop too (measured 1.9e-13 / 1.3e-13) and the projection method (8e-16 / 1.8e-15; it was
// 5.5e-4 / 9.5e-4 while its closest face flipped on ties, see ProjectionMethodIsTheSame).
TEST(AnyScale, ClosedSnakesOnADoubleMeshAreTheSame)
{
    ExpectSameAtEveryScale<DMesh>(true, SnakeMethod::LocalEmbedding, 1e-6);
    ExpectSameAtEveryScale<DMesh>(true, SnakeMethod::Projection3D, 1e-6);
}

TEST(AnyScale, OpenSnakesOnADoubleMeshAreTheSame)
{
    ExpectSameAtEveryScale<DMesh>(false, SnakeMethod::LocalEmbedding, 1e-6);
    ExpectSameAtEveryScale<DMesh>(false, SnakeMethod::Projection3D, 1e-6);
}

TEST(AnyScale, OpenSnakeOnTheCubeEdgeIsTheSame)
{
    ExpectSameAtEveryScale(false, SnakeMethod::LocalEmbedding, 1e-6); // measured 4.3e-7 at 1e-30
}

// Power-of-two scales round nothing, so the 3D update + projection method, too, must give the same
// snake to the bit. It did not (0.016 of the size at 2^+-100) while the level-0 slope across the
// curve took its face normal from a float cross product: 2^200 overflows and 2^-200 underflows in
// float, so the slope was not averaged at those scales.
TEST(AnyScale, ProjectionMethodIsExactAtPowerOfTwoScales)
{
    ExpectSameAtEveryScale(false, SnakeMethod::Projection3D, 0, {std::ldexp(1.0, -100), std::ldexp(1.0, 100)});
}

// At 1e+-30 (coordinates rounded to float differently) the 3D update + projection method's open
// end stopped 0.4-0.6 edge lengths from where it stops at scale 1 (7.3e-3 / 5.5e-3 of the size):
// on the coarse levels it moved along the direction of the coarse gradient alone, which turns
// with the rounding near a well's bottom, and a yes/no decision (the step control's halving)
// flipped at operation 1. Session 6 blended that move with the move across the end's tangent, as
// the embedding method's end does (SnakeMotionRules::alongPullBlend): 9.5e-4 / 3.3e-4. The rest
// was the projection's closest face: a sample beyond an edge of the cube is as close to both
// faces of the edge, and the closer of the two flipped with the rounding. A face now wins only by
// more than rounding (SurfaceProjection::Closest): 3.9e-8 / 1.3e-8.
TEST(AnyScale, ProjectionMethodIsTheSame)
{
    ExpectSameAtEveryScale(false, SnakeMethod::Projection3D, 1e-6);
}

TEST(AnyScale, TinySeedPathIsNotZeroLength)
{
    // a 1e-30 cube was refused with "the seed path has zero length" (lengths squared in float)
    using Snake = GeometricSnake<CMeshO>;
    using Surface = SnakeSurface<CMeshO>;
    CMeshO m;
    gs_test::MakeRotatedIcoCube(m, 3, 1e-30);
    EnableSnakeAdjacency(m);
    FeatureEnergy<CMeshO>::Compute(m, FeatureEnergyType::NormalVariation, 2);
    auto surf = std::make_shared<Surface>(m);
    Snake s(surf);
    EXPECT_NO_THROW(s.InitFromPath({0, int(m.vert[0].cVFp()->cV1(m.vert[0].cVFi()) - &m.vert[0])}, false));
    EXPECT_GE(s.SampleCount(), 2);
}

// Is the closed loop's difference at 1e+-30 a matter of scale? No: it is its response to the
// float rounding of the input, which every scale that is not a power of two changes (1.1 moves
// it 300 times farther than 1e-30). The loop ends in one of a few states within the flat band of
// the level-0 well across the cube's edges (its convergence tolerance lets it stop anywhere in
// it). Measured (session 15), largest sample difference from scale 1, of the size: 1.7e-3 at
// 0.1, 1.8e-3 at 1/3 and 0.9, 1.8e-2 at 1.1 (curves 9e-3 apart, half an edge length), 2.0e-7 at
// 3, 3.2e-7 at 7, 6.0e-5 at 10; 6.0e-5 at 1e-30, 2.3e-4 at 1e-20, 1.3e-7 at 1e20, 3.3e-7 at 1e30.
TEST(AnyScale, ExtremeScalesMoveTheFloatLoopNoMoreThanOrdinaryRounding)
{
    const Outcome ref = RunCube<CMeshO>(1.0, true, SnakeMethod::LocalEmbedding);
    ASSERT_TRUE(ref.converged);
    const double size = 2 * std::sqrt(3.0), h = 2.0 / 32; // the cube's diagonal and edge length
    auto apart = [&](double s) {
        const Outcome o = RunCube<CMeshO>(s, true, SnakeMethod::LocalEmbedding);
        EXPECT_TRUE(o.converged) << "scale " << s;
        EXPECT_EQ(o.samples.size(), ref.samples.size()) << "scale " << s;
        double worst = 0;
        for (size_t i = 0; i < o.samples.size() && i < ref.samples.size(); ++i)
            worst = std::max(worst, (o.samples[i] - ref.samples[i]).Norm());
        const double curves = Hausdorff(o.samples, ref.samples, true);
        EXPECT_LT(curves, 0.75 * h) << "scale " << s << ": the loop left the band across the cube's edges";
        std::printf("scale %g: %d operations (%d at scale 1), largest sample difference %.3g of the size, "
                    "curves %.3g apart\n", s, o.operations, ref.operations, worst / size, curves / size);
        return worst / size;
    };
    double ordinary = 0, extreme = 0;
    for (double s : {0.1, 1.0 / 3, 0.9, 1.1, 3.0, 7.0, 10.0}) ordinary = std::max(ordinary, apart(s));
    for (double s : {1e-30, 1e-20, 1e20, 1e30}) extreme = std::max(extreme, apart(s));
    std::printf("largest sample difference from scale 1: ordinary scales %.3g, extreme scales %.3g of the size\n",
                ordinary, extreme);
    EXPECT_LE(extreme, ordinary) << "an extreme scale moved the loop more than float rounding at ordinary scales";
    // the premise: float rounding alone moves the loop by far more than 1e-6 (were it not so,
    // ClosedSnakeOnTheCubeFaceIsTheSame could ask for 1e-6)
    EXPECT_GT(ordinary, 1e-4);
}
