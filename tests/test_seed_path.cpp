// Snake initialization from seed vertices (Lee & Lee 2002, Sec. 5.5).

#include <gtest/gtest.h>

#include <chrono>
#include <limits>
#include <random>
#include <set>

#include <common/ml_mesh_type.h>

#include "generated_meshes.h"
#include "vcg_ext/energy/feature_energy.h"
#include "vcg_ext/io/seed_list_text.h"
#include "vcg_ext/paths/seed_path.h"

namespace {

using vcg::tri::SeedListText;
using vcg::tri::SeedPathCost;
using vcg::tri::SnakeError;
typedef vcg::tri::SeedPath<CMeshO> SP;

// Plain mesh type with VF adjacency (exercises the VF code path) ...
class VVertex;
class VFace;
struct VUsed : public vcg::UsedTypes<vcg::Use<VVertex>::AsVertexType, vcg::Use<VFace>::AsFaceType> {};
class VVertex : public vcg::Vertex<VUsed, vcg::vertex::Coord3f, vcg::vertex::Normal3f, vcg::vertex::Qualityf,
                                   vcg::vertex::VFAdj, vcg::vertex::BitFlags> {};
class VFace : public vcg::Face<VUsed, vcg::face::VertexRef, vcg::face::VFAdj, vcg::face::Normal3f, vcg::face::BitFlags> {};
class VMesh : public vcg::tri::TriMesh<std::vector<VVertex>, std::vector<VFace>> {};

template <class M>
int Idx(const M &m, const typename M::VertexType *v)
{
    return int(v - &m.vert[0]);
}

template <class M>
std::set<std::pair<int, int>> EdgeSet(const M &m)
{
    std::set<std::pair<int, int>> e;
    for (const auto &f : m.face)
        if (!f.IsD())
            for (int k = 0; k < 3; ++k) {
                int a = Idx(m, f.cV(k)), b = Idx(m, f.cV((k + 1) % 3));
                e.insert({std::min(a, b), std::max(a, b)});
            }
    return e;
}

template <class M>
double Len(const M &m, int a, int b)
{
    return vcg::Distance(vcg::Point3d::Construct(m.vert[a].cP()), vcg::Point3d::Construct(m.vert[b].cP()));
}

template <class M>
double EdgeCost(const M &m, int a, int b, SeedPathCost c, double eps)
{
    double l = Len(m, a, b);
    if (c == SeedPathCost::Feature) l *= eps + 0.5 * (double(m.vert[a].cQ()) + double(m.vert[b].cQ()));
    return l;
}

// All-pairs shortest paths by Floyd-Warshall (brute force reference).
template <class M>
std::vector<std::vector<double>> AllPairs(const M &m, SeedPathCost c, double eps)
{
    const size_t n = m.vert.size();
    std::vector<std::vector<double>> d(n, std::vector<double>(n, std::numeric_limits<double>::infinity()));
    for (size_t i = 0; i < n; ++i) d[i][i] = 0;
    for (auto e : EdgeSet(m)) d[e.first][e.second] = d[e.second][e.first] = EdgeCost(m, e.first, e.second, c, eps);
    for (size_t k = 0; k < n; ++k)
        for (size_t i = 0; i < n; ++i)
            for (size_t j = 0; j < n; ++j) d[i][j] = std::min(d[i][j], d[i][k] + d[k][j]);
    return d;
}

// Checks structure (seeds where claimed, consecutive vertices adjacent) and returns per-segment costs.
template <class M>
std::vector<double> CheckPath(const M &m, const typename vcg::tri::SeedPath<M>::Result &r, const std::vector<int> &seeds,
                              bool closed, SeedPathCost c, double eps)
{
    const auto edges = EdgeSet(m);
    EXPECT_EQ(r.closed, closed);
    EXPECT_EQ(r.seedPositions.size(), seeds.size());
    for (size_t i = 0; i < seeds.size() && i < r.seedPositions.size(); ++i)
        EXPECT_EQ(r.vertices[r.seedPositions[i]], seeds[i]);
    EXPECT_EQ(r.vertices.front(), seeds.front());
    if (!closed) EXPECT_EQ(r.vertices.back(), seeds.back());
    std::vector<int> v = r.vertices;
    if (closed) v.push_back(v.front()); // closed: the curve returns to the first seed
    double len = 0;
    for (size_t i = 0; i + 1 < v.size(); ++i) {
        const int a = v[i], b = v[i + 1];
        EXPECT_TRUE(edges.count({std::min(a, b), std::max(a, b)})) << "vertices " << a << "," << b << " not adjacent";
        len += Len(m, a, b);
    }
    EXPECT_NEAR(r.length, len, 1e-9 * (1 + len));
    std::vector<double> seg;
    std::vector<int> pos = r.seedPositions;
    pos.push_back(int(v.size()) - 1);
    if (!closed) pos.pop_back();
    for (size_t s = 0; s + 1 < pos.size(); ++s) {
        double cst = 0;
        for (int i = pos[s]; i < pos[s + 1]; ++i) cst += EdgeCost(m, v[i], v[i + 1], c, eps);
        seg.push_back(cst);
    }
    return seg;
}

template <class M>
void CompareWithBruteForce(M &m, unsigned seed)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> U(0, 1);
    for (auto &v : m.vert) v.Q() = U(rng);
    std::uniform_int_distribution<int> pick(0, int(m.vert.size()) - 1);
    for (SeedPathCost c : {SeedPathCost::Length, SeedPathCost::Feature}) {
        const double eps = 0.05;
        const auto d = AllPairs(m, c, eps);
        for (int trial = 0; trial < 12; ++trial) {
            const bool closed = trial % 2;
            std::vector<int> seeds;
            const int n = 3 + trial % 3;
            while (int(seeds.size()) < n) {
                int s = pick(rng);
                if (seeds.empty() || s != seeds.back()) seeds.push_back(s);
            }
            if (closed && seeds.back() == seeds.front()) seeds.back() = (seeds.front() + 1) % int(m.vert.size());
            auto r = vcg::tri::SeedPath<M>::Compute(m, seeds, closed, c, eps);
            auto seg = CheckPath(m, r, seeds, closed, c, eps);
            ASSERT_EQ(seg.size(), closed ? seeds.size() : seeds.size() - 1);
            for (size_t i = 0; i < seg.size(); ++i) {
                const double ref = d[seeds[i]][seeds[(i + 1) % seeds.size()]];
                EXPECT_NEAR(seg[i], ref, 1e-9 * (1 + ref)) << "segment " << i << " trial " << trial;
            }
        }
    }
}

TEST(SeedPath, MatchesFloydWarshallCSR)
{
    CMeshO m; // no VF enabled: adjacency table built from faces
    gs_test::MakeIcosphere(m, 2);
    gs_test::AddVertexNoise(m, 0.2, 3); // break ties
    CompareWithBruteForce(m, 42);
    CMeshO g;
    gs_test::MakeFlatGrid(g, 9);
    gs_test::AddVertexNoise(g, 0.1, 4);
    CompareWithBruteForce(g, 43);
}

TEST(SeedPath, MatchesFloydWarshallVF)
{
    VMesh m; // plain type with VF adjacency
    gs_test::MakeIcosphere(m, 2);
    gs_test::AddVertexNoise(m, 0.2, 3);
    CompareWithBruteForce(m, 44);
    CMeshO c; // Ocf VF enabled
    gs_test::MakeRotatedIcoCube(c, 2);
    c.vert.EnableVFAdjacency();
    c.face.EnableVFAdjacency();
    CompareWithBruteForce(c, 45);
}

TEST(SeedPath, ClosedPathReturnsToFirstSeed)
{
    CMeshO m;
    gs_test::MakeIcosphere(m, 3);
    std::vector<int> seeds{0, 100, 300, 500};
    auto r = SP::Compute(m, seeds, true);
    EXPECT_TRUE(r.closed);
    EXPECT_NE(r.vertices.back(), r.vertices.front()); // first vertex not repeated
    const auto edges = EdgeSet(m);
    const int a = r.vertices.back(), b = r.vertices.front();
    EXPECT_TRUE(edges.count({std::min(a, b), std::max(a, b)}));
    CheckPath(m, r, seeds, true, SeedPathCost::Length, 0.05);
    auto open = SP::Compute(m, seeds, false);
    EXPECT_LT(open.length, r.length);
}

double MeanEdgeDist(const CMeshO &m, const std::vector<int> &path)
{
    double s = 0;
    for (int v : path) s += gs_test::DistToCubeEdges(vcg::Point3d::Construct(m.vert[v].cP()));
    return s / path.size();
}

int Nearest(const CMeshO &m, const vcg::Point3d &p)
{
    int best = 0;
    for (size_t i = 0; i < m.vert.size(); ++i)
        if (vcg::Distance(vcg::Point3d::Construct(m.vert[i].cP()), p) <
            vcg::Distance(vcg::Point3d::Construct(m.vert[best].cP()), p))
            best = int(i);
    return best;
}

TEST(SeedPath, FeatureCostFollowsCubeEdge)
{
    CMeshO m;
    gs_test::MakeRotatedIcoCube(m, 4);
    vcg::tri::FeatureEnergy<CMeshO>::Compute(m, vcg::tri::FeatureEnergyType::NormalVariation, 0);
    const double L = vcg::tri::MeshValidation<CMeshO>::MeanEdgeLength(m);
    // Two seeds near the same cube edge (x = y = 1), a third and fourth on other edges.
    const std::vector<int> seeds{Nearest(m, {1, 1, -0.7}), Nearest(m, {1, 1, 0.7}), Nearest(m, {-1, 1, 0.7})};
    auto byLength = SP::Compute(m, seeds, false, SeedPathCost::Length);
    auto byFeature = SP::Compute(m, seeds, false, SeedPathCost::Feature);
    CheckPath(m, byFeature, seeds, false, SeedPathCost::Feature, 0.05);
    const double dl = MeanEdgeDist(m, byLength.vertices), df = MeanEdgeDist(m, byFeature.vertices);
    std::printf("mean distance to cube edges: length path %.3f L, feature path %.3f L\n", dl / L, df / L);
    EXPECT_LT(df, 0.8 * dl);
    EXPECT_LT(df, 0.5 * L);
    EXPECT_GE(byFeature.length, byLength.length - 1e-9); // the Euclidean one is the shortest
}

// A cost is a type (paths/seed_path_cost.h): one written here, a length that is 50x dearer where
// z > -0.15, steers the path around that region without touching the search.
struct AvoidBandCost
{
    static constexpr bool StraightIsCheapest = false;
    const CMeshO &m;
    double Price(const vcg::Point3d &a, const vcg::Point3d &b) const
    {
        return vcg::Distance(a, b) * ((a[2] + b[2]) / 2 > -0.15 ? 50.0 : 1.0);
    }
    vcg::Point3d P(int v) const { return vcg::Point3d::Construct(m.vert[v].cP()); }
    double operator()(int a, int b) const { return Price(P(a), P(b)); }
    double operator()(const vcg::tri::SurfacePoint &p, int v) const { return Price(p.Pd(m), P(v)); }
    double operator()(const vcg::tri::SurfacePoint &a, const vcg::tri::SurfacePoint &b) const
    {
        return Price(a.Pd(m), b.Pd(m));
    }
    double LowerBoundPerLength() const { return 1.0; }
};

TEST(SeedPath, CostIsATypeTheSearchIsTemplatedOn)
{
    CMeshO m;
    gs_test::MakeIcosphere(m, 3);
    // two seeds near the pole y = 1, on the plane z = 0
    const int a = Nearest(m, {-0.3, 0.95, 0}), b = Nearest(m, {0.3, 0.95, 0});
    const auto plain = SP::ComputeWith(m, {a, b}, false, vcg::tri::LengthPathCost<CMeshO>(m));
    const auto avoid = SP::ComputeWith(m, {a, b}, false, AvoidBandCost{m});
    EXPECT_EQ(plain.vertices, SP::Compute(m, {a, b}, false).vertices); // the enum picks the same type
    auto meanInnerZ = [&](const std::vector<int> &path) {
        double z = 0;
        for (size_t i = 1; i + 1 < path.size(); ++i) z += m.vert[path[i]].cP()[2];
        return z / std::max<size_t>(1, path.size() - 2);
    };
    EXPECT_GT(meanInnerZ(plain.vertices), -0.1);  // the shortest path runs near z = 0 ...
    EXPECT_LT(meanInnerZ(avoid.vertices), -0.15); // ... the other keeps out of the dear region
    EXPECT_GT(avoid.length, plain.length); // by a detour
}

TEST(SeedListText, Parse)
{
    EXPECT_EQ(SeedListText::Parse("12, 40,77"), (std::vector<int>{12, 40, 77}));
    EXPECT_EQ(SeedListText::Parse("  1 2\t3 "), (std::vector<int>{1, 2, 3}));
    EXPECT_EQ(SeedListText::Parse("1;2 ; 3,"), (std::vector<int>{1, 2, 3}));
    EXPECT_EQ(SeedListText::Parse("0"), (std::vector<int>{0}));
    EXPECT_TRUE(SeedListText::Parse("").empty());
    EXPECT_TRUE(SeedListText::Parse("   ").empty());
    for (const char *bad : {"a", "1,,2", "-3", "1.5", "12 x", "99999999999", ",1", "1 - 2", "0x10"})
        EXPECT_THROW(SeedListText::Parse(bad), SnakeError) << bad;
}

TEST(SeedPath, BadInputThrows)
{
    CMeshO m;
    gs_test::MakeIcosphere(m, 2);
    const int n = int(m.vert.size());
    EXPECT_THROW(SP::Compute(m, {}, false), SnakeError);
    EXPECT_THROW(SP::Compute(m, {3}, false), SnakeError);
    EXPECT_THROW(SP::Compute(m, {3, 9}, true), SnakeError); // closed needs 3
    EXPECT_THROW(SP::Compute(m, {3, -1}, false), SnakeError);
    EXPECT_THROW(SP::Compute(m, {3, n}, false), SnakeError);
    EXPECT_THROW(SP::Compute(m, {3, 9, 9, 20}, false), SnakeError); // repeated consecutive
    // a closed list ending on its first seed is the same loop (as in the snake filter, issue 8)
    EXPECT_EQ(SP::Compute(m, {3, 9, 20, 3}, true).vertices, SP::Compute(m, {3, 9, 20}, true).vertices);
    EXPECT_THROW(SP::Compute(m, {3, 9, 3}, true), SnakeError); // only 2 distinct seeds
    EXPECT_NO_THROW(SP::Compute(m, {3, 9, 20, 3}, false));           // fine for an open curve
    EXPECT_THROW(SP::Compute(m, {3, 9}, false, SeedPathCost::Feature, 0.0), SnakeError);
    EXPECT_THROW(SP::Compute(m, {3, 9}, false, SeedPathCost::Feature, std::nan("")), SnakeError);
    try {
        SP::Compute(m, {3, n + 5}, false);
        FAIL();
    } catch (const SnakeError &e) {
        EXPECT_NE(std::string(e.what()).find("Seed 2"), std::string::npos) << e.what(); // names the seed
    }

    // Two components: two separate spheres.
    CMeshO two, other;
    gs_test::MakeIcosphere(two, 2);
    gs_test::MakeIcosphere(other, 2);
    for (auto &v : other.vert) v.P() += vcg::Point3f(5, 0, 0);
    gs_test::AppendMesh(two, other);
    EXPECT_NO_THROW(SP::Compute(two, {0, 50}, false));
    EXPECT_THROW(SP::Compute(two, {0, n + 3}, false), SnakeError);
    EXPECT_THROW(SP::Compute(two, {0, 20, n + 3}, true), SnakeError);

    // Isolated (unreferenced) vertex and deleted vertex.
    CMeshO iso;
    gs_test::MakeIcosphere(iso, 2);
    vcg::tri::Allocator<CMeshO>::AddVertex(iso, vcg::Point3f(3, 3, 3));
    EXPECT_THROW(SP::Compute(iso, {0, n}, false), SnakeError);
    CMeshO del;
    gs_test::MakeIcosphere(del, 2);
    for (auto &f : del.face)
        if (!f.IsD() && (f.V(0) == &del.vert[7] || f.V(1) == &del.vert[7] || f.V(2) == &del.vert[7]))
            vcg::tri::Allocator<CMeshO>::DeleteFace(del, f);
    vcg::tri::Allocator<CMeshO>::DeleteVertex(del, del.vert[7]);
    EXPECT_THROW(SP::Compute(del, {0, 7}, false), SnakeError);
    EXPECT_NO_THROW(SP::Compute(del, {0, 8}, false)); // the hole is walked around

    // Empty mesh, point cloud, NaN coordinates.
    CMeshO empty;
    EXPECT_THROW(SP::Compute(empty, {0, 1}, false), SnakeError);
    CMeshO cloud;
    vcg::tri::Allocator<CMeshO>::AddVertices(cloud, 10);
    EXPECT_THROW(SP::Compute(cloud, {0, 1}, false), SnakeError);
    CMeshO nan;
    gs_test::MakeIcosphere(nan, 2);
    nan.vert[30].P()[2] = std::numeric_limits<float>::quiet_NaN();
    EXPECT_THROW(SP::Compute(nan, {0, 1}, false), SnakeError);
}

TEST(SeedPath, NonManifoldDegenerateAndBorderMeshes)
{
    auto check = [](CMeshO &m, const std::vector<int> &seeds, bool closed) {
        for (SeedPathCost c : {SeedPathCost::Length, SeedPathCost::Feature}) {
            for (auto &v : m.vert) v.Q() = 0.5f;
            SP::Result r;
            ASSERT_NO_THROW(r = SP::Compute(m, seeds, closed, c));
            EXPECT_TRUE(std::isfinite(r.length));
            CheckPath(m, r, seeds, closed, c, 0.05);
        }
    };
    CMeshO cones; // path through the non-manifold apex (vertex 0) from one cone to the other
    gs_test::MakeTouchingCones(cones, 8);
    check(cones, {1, 9 + 4}, false);
    check(cones, {1, 5, 12}, true);
    CMeshO fin;
    gs_test::MakeNonManifoldFin(fin);
    check(fin, {2, 3, 4}, true);
    CMeshO deg; // zero-length edge (vertices 1 and 2 coincide) and a collinear face
    gs_test::MakeFromArrays(deg,
                            {vcg::Point3d(0, 0, 0), vcg::Point3d(1, 0, 0), vcg::Point3d(1, 0, 0), vcg::Point3d(2, 0, 0),
                             vcg::Point3d(1, 1, 0)},
                            {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {0, 3, 1}});
    check(deg, {0, 3}, false);
    check(deg, {0, 2, 4}, true);
    CMeshO grid; // borders
    gs_test::MakeFlatGrid(grid, 6);
    check(grid, {0, 6, 48}, true);
}

TEST(SeedPath, ShortPathOnLargeMeshIsLocal)
{
    // A* should not touch the whole mesh for a short path: check it is fast on ~330k faces.
    CMeshO m;
    gs_test::MakeIcosphere(m, 7);
    const int a = 0;
    int b = -1;
    const double L = vcg::tri::MeshValidation<CMeshO>::MeanEdgeLength(m);
    for (size_t i = 1; i < m.vert.size(); ++i)
        if (vcg::Distance(m.vert[i].cP(), m.vert[a].cP()) > 20 * L &&
            vcg::Distance(m.vert[i].cP(), m.vert[a].cP()) < 25 * L) {
            b = int(i);
            break;
        }
    ASSERT_GE(b, 0);
    const auto t0 = std::chrono::steady_clock::now();
    auto r = SP::Compute(m, {a, b}, false);
    const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_LT(r.length, 30 * L);
    EXPECT_LT(sec, 0.5);
}

} // namespace

// Seed points on two pieces of a mesh that no edge joins are refused with a message (issue 33:
// before, with no path along the edges and the points in different faces, the "path" silently
// became the straight segment between them, across the gap).
TEST(SeedPath, PointsOnDisconnectedPiecesAreRefused)
{
    CMeshO m;
    vcg::tri::Allocator<CMeshO>::AddVertices(m, 6);
    const float xy[6][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 0, 0}, {6, 0, 0}, {5, 1, 0}};
    for (int i = 0; i < 6; ++i) m.vert[i].P() = vcg::Point3f(xy[i][0], xy[i][1], xy[i][2]);
    vcg::tri::Allocator<CMeshO>::AddFace(m, &m.vert[0], &m.vert[1], &m.vert[2]);
    vcg::tri::Allocator<CMeshO>::AddFace(m, &m.vert[3], &m.vert[4], &m.vert[5]);
    const vcg::tri::SurfacePoint a(0, vcg::Point3d(1 / 3.0, 1 / 3.0, 1 / 3.0)), b(1, vcg::Point3d(1 / 3.0, 1 / 3.0, 1 / 3.0));
    try {
        vcg::tri::SeedPath<CMeshO>::ComputeFromPoints(m, {a, b}, false);
        FAIL() << "a path across the gap";
    } catch (const SnakeError &e) {
        EXPECT_NE(std::string(e.what()).find("different connected components"), std::string::npos) << e.what();
    }
}

// A MeshIndex kept across paths (the edit tool's Builds, issue 37) gives the paths built
// without one, point for point, for both costs; an index of a mesh that changed is not used.
TEST(SeedPath, KeptMeshIndexGivesTheSamePaths)
{
    CMeshO m;
    gs_test::MakeIcosphere(m, 4);
    typedef vcg::tri::SeedPath<CMeshO> P;
    vcg::tri::FeatureEnergy<CMeshO>::Compute(m, vcg::tri::FeatureEnergyType::NormalVariation, 1);
    const P::MeshIndex index(m);
    EXPECT_TRUE(index.Matches(m));
    std::mt19937 rng(7);
    std::uniform_int_distribution<int> face(0, int(m.face.size()) - 1);
    for (int trial = 0; trial < 10; ++trial) {
        std::vector<vcg::tri::SurfacePoint> seeds;
        for (int k = 0; k < 3; ++k) seeds.emplace_back(face(rng), vcg::Point3d(0.2, 0.3, 0.5));
        for (SeedPathCost cost : {SeedPathCost::Length, SeedPathCost::Feature}) {
            const P::PointResult a = P::ComputeFromPoints(m, seeds, trial % 2 == 1, cost);
            const P::PointResult b = P::ComputeFromPoints(m, seeds, trial % 2 == 1, cost, 0.05, &index);
            ASSERT_EQ(a.points.size(), b.points.size()) << trial;
            for (size_t i = 0; i < a.points.size(); ++i) EXPECT_EQ(a.points[i].Pd(m), b.points[i].Pd(m)) << trial << " " << i;
            EXPECT_EQ(a.vertices, b.vertices);
        }
    }
    vcg::tri::Allocator<CMeshO>::AddVertices(m, 1);
    EXPECT_FALSE(index.Matches(m));
}
