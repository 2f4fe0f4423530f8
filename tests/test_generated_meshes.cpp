// Checks the synthetic mesh generators of generated_meshes.h. With GS_WRITE_DATA set in the
// environment it also (re)writes the small meshes in data/ (icocube.ply, icocylinder.ply,
// fandisk.ply).

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

#include <common/ml_mesh_type.h>

#include "generated_meshes.h"
#include "vcg_ext/surface/mesh_validation.h"

#ifndef GS_SHARED_MESH_DIR
#define GS_SHARED_MESH_DIR GS_DATA_DIR "/../../shared/data/meshes"
#endif

namespace {

class GVertex;
class GFace;
struct GUsed : public vcg::UsedTypes<vcg::Use<GVertex>::AsVertexType, vcg::Use<GFace>::AsFaceType> {};
class GVertex : public vcg::Vertex<GUsed, vcg::vertex::Coord3d, vcg::vertex::Normal3d, vcg::vertex::Qualityd,
                                   vcg::vertex::BitFlags> {};
class GFace : public vcg::Face<GUsed, vcg::face::VertexRef, vcg::face::BitFlags> {};
class GMesh : public vcg::tri::TriMesh<std::vector<GVertex>, std::vector<GFace>> {};

vcg::Point3d Pos(const CVertexO &v) { return vcg::Point3d::Construct(v.cP()); }

TEST(GeneratedMeshes, IcosphereIsUnitSphere)
{
    CMeshO m;
    gs_test::MakeIcosphere(m, 3);
    EXPECT_EQ(m.fn, 1280);
    EXPECT_EQ(m.vn, 642);
    for (const auto &v : m.vert) EXPECT_NEAR(Pos(v).Norm(), 1.0, 1e-6);
    auto r = vcg::tri::MeshValidation<CMeshO>::Inspect(m);
    EXPECT_EQ(r.borderEdges, 0);
    EXPECT_EQ(r.nonManifoldEdges, 0);
    EXPECT_EQ(r.components, 1);
}

TEST(GeneratedMeshes, RotatedIcoCubeLiesOnCubeAndStraddlesEdges)
{
    CMeshO m;
    const double half = 2.0;
    gs_test::MakeRotatedIcoCube(m, 3, half);
    EXPECT_EQ(m.fn, 1280);
    for (const auto &v : m.vert) {
        const vcg::Point3d p = Pos(v);
        EXPECT_NEAR(std::max(std::fabs(p[0]), std::max(std::fabs(p[1]), std::fabs(p[2]))), half, 1e-5);
    }
    // Faces whose vertices lie on different cube faces straddle a cube edge.
    int straddling = 0;
    for (const auto &f : m.face) {
        int side[3];
        for (int k = 0; k < 3; ++k) {
            const vcg::Point3d p = vcg::Point3d::Construct(f.cP(k));
            int ax = 0;
            for (int a = 1; a < 3; ++a)
                if (std::fabs(p[a]) > std::fabs(p[ax])) ax = a;
            side[k] = ax * 2 + (p[ax] > 0);
        }
        if (side[0] != side[1] || side[1] != side[2]) ++straddling;
    }
    EXPECT_GT(straddling, 50);
    // No vertex is exactly on an edge (the rotation is generic).
    double minD = 1e9;
    for (const auto &v : m.vert) minD = std::min(minD, gs_test::DistToCubeEdges(Pos(v), half));
    EXPECT_GT(minD, 1e-6);
}

TEST(GeneratedMeshes, OctahedronAndCylinderProjections)
{
    CMeshO o;
    gs_test::MakeRotatedIcoOctahedron(o, 3, 1.5);
    for (const auto &v : o.vert) {
        const vcg::Point3d p = Pos(v);
        EXPECT_NEAR(std::fabs(p[0]) + std::fabs(p[1]) + std::fabs(p[2]), 1.5, 1e-5);
    }
    CMeshO c;
    gs_test::MakeRotatedIcoCylinder(c, 3, 0.5, 2.0);
    int onSide = 0, onCap = 0;
    for (const auto &v : c.vert) {
        const vcg::Point3d p = Pos(v);
        const double rho = std::sqrt(p[0] * p[0] + p[1] * p[1]);
        const bool side = std::fabs(rho - 0.5) < 1e-5 && std::fabs(p[2]) <= 2.0 + 1e-5;
        const bool cap = std::fabs(std::fabs(p[2]) - 2.0) < 1e-5 && rho <= 0.5 + 1e-5;
        EXPECT_TRUE(side || cap);
        onSide += side;
        onCap += cap;
    }
    EXPECT_GT(onSide, 10);
    EXPECT_GT(onCap, 10);
}

TEST(GeneratedMeshes, FlatGrid)
{
    CMeshO m;
    gs_test::MakeFlatGrid(m, 10, 2.0);
    EXPECT_EQ(m.vn, 121);
    EXPECT_EQ(m.fn, 200);
    for (const auto &v : m.vert) EXPECT_EQ(v.cP()[2], 0.0f);
    for (const auto &f : m.face) EXPECT_NEAR(f.cN()[2], 1.0, 1e-6); // faces up
    EXPECT_NEAR(m.bbox.Diag(), 2.0 * std::sqrt(2.0), 1e-5);
    auto r = vcg::tri::MeshValidation<CMeshO>::Inspect(m);
    EXPECT_EQ(r.borderEdges, 40);
}

TEST(GeneratedMeshes, NoiseIsDeterministicAndSized)
{
    CMeshO a, b, ref;
    gs_test::MakeIcosphere(ref, 3);
    gs_test::MakeIcosphere(a, 3);
    gs_test::MakeIcosphere(b, 3);
    const double L = vcg::tri::MeshValidation<CMeshO>::MeanEdgeLength(ref);
    gs_test::AddVertexNoise(a, 0.1, 7);
    gs_test::AddVertexNoise(b, 0.1, 7);
    for (size_t i = 0; i < a.vert.size(); ++i) {
        EXPECT_EQ(a.vert[i].cP(), b.vert[i].cP());
        EXPECT_NEAR(vcg::Distance(Pos(a.vert[i]), Pos(ref.vert[i])), 0.1 * L, 1e-5);
    }
    CMeshO c;
    gs_test::MakeIcosphere(c, 3);
    gs_test::AddVertexNoise(c, 0.1, 8);
    EXPECT_NE(a.vert[5].cP(), c.vert[5].cP());
}

TEST(GeneratedMeshes, DistanceFunctions)
{
    using vcg::Point3d;
    EXPECT_NEAR(gs_test::DistToCubeEdges(Point3d(1, 1, 0.3)), 0.0, 1e-12);
    EXPECT_NEAR(gs_test::DistToCubeEdges(Point3d(0, 0, 0)), std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(gs_test::DistToCubeEdges(Point3d(1, 0, 0)), 1.0, 1e-12);
    EXPECT_NEAR(gs_test::DistToCubeEdges(Point3d(2, 2, 2), 2.0), 0.0, 1e-12);
    EXPECT_NEAR(gs_test::DistToCubeEdges(Point3d(1.5, 1.5, 3)), std::sqrt(0.5 + 4.0), 1e-12); // past a corner
    EXPECT_NEAR(gs_test::DistToOctahedronEdges(Point3d(0.5, 0.5, 0)), 0.0, 1e-12);
    EXPECT_NEAR(gs_test::DistToOctahedronEdges(Point3d(0, 0, 0)), 1.0 / std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(gs_test::DistToCylinderRims(Point3d(0, 1, 1)), 0.0, 1e-12);
    EXPECT_NEAR(gs_test::DistToCylinderRims(Point3d(0, 0, 1)), 1.0, 1e-12);
    EXPECT_NEAR(gs_test::DistToCylinderRims(Point3d(2, 0, 0), 1.0, 1.0), std::sqrt(2.0), 1e-12);
}

TEST(GeneratedMeshes, SubdivideWithAndWithoutFF)
{
    CMeshO m; // Ocf: Subdivide enables FF itself and uses vcglib's Refine
    gs_test::MakeIcosphere(m, 2);
    gs_test::Subdivide(m, 1000);
    EXPECT_EQ(m.fn, 1280);
    EXPECT_EQ(m.vn, 642);
    GMesh p; // no FF adjacency at all: fallback path
    gs_test::MakeIcosphere(p, 2);
    gs_test::Subdivide(p, 1000);
    EXPECT_EQ(p.fn, 1280);
    EXPECT_EQ(p.vn, 642);
    auto r = vcg::tri::MeshValidation<GMesh>::Inspect(p);
    EXPECT_EQ(r.borderEdges, 0);
    EXPECT_EQ(r.components, 1);
}

TEST(GeneratedMeshes, HandMadeNonManifold)
{
    CMeshO cones, fin;
    gs_test::MakeTouchingCones(cones, 8);
    gs_test::MakeNonManifoldFin(fin);
    auto rc = vcg::tri::MeshValidation<CMeshO>::Inspect(cones);
    EXPECT_EQ(rc.nonManifoldVertices, 1);
    EXPECT_EQ(rc.borderEdges, 16);
    auto rf = vcg::tri::MeshValidation<CMeshO>::Inspect(fin);
    EXPECT_EQ(rf.nonManifoldEdges, 1);
    EXPECT_EQ(rf.borderEdges, 6);
}

TEST(GeneratedMeshes, DataFiles)
{
    const std::string dir = GS_DATA_DIR;
    if (std::getenv("GS_WRITE_DATA")) {
        CMeshO cube, cyl, fan;
        gs_test::MakeRotatedIcoCube(cube, 4);
        gs_test::MakeRotatedIcoCylinder(cyl, 4);
        ASSERT_TRUE(gs_test::SaveMesh(cube, dir + "/icocube.ply"));
        ASSERT_TRUE(gs_test::SaveMesh(cyl, dir + "/icocylinder.ply"));
        ASSERT_TRUE(gs_test::LoadMesh(fan, std::string(GS_SHARED_MESH_DIR) + "/fandisk.off"));
        ASSERT_TRUE(gs_test::SaveMesh(fan, dir + "/fandisk.ply"));
    }
    for (const char *name : {"icocube.ply", "icocylinder.ply", "fandisk.ply"}) {
        CMeshO m;
        ASSERT_TRUE(gs_test::LoadMesh(m, dir + "/" + name)) << name;
        EXPECT_GT(m.fn, 1000) << name;
        auto r = vcg::tri::MeshValidation<CMeshO>::Inspect(m);
        EXPECT_EQ(r.borderEdges, 0) << name;
        EXPECT_EQ(r.nonManifoldEdges, 0) << name;
        EXPECT_EQ(r.components, 1) << name;
        std::ifstream f(dir + "/" + name, std::ios::binary | std::ios::ate);
        EXPECT_LT(f.tellg(), std::streamoff(1 << 20)) << name;
    }
    CMeshO cube;
    ASSERT_TRUE(gs_test::LoadMesh(cube, dir + "/icocube.ply"));
    EXPECT_EQ(cube.fn, 5120);
    for (const auto &v : cube.vert) {
        const vcg::Point3d p = Pos(v);
        EXPECT_NEAR(std::max(std::fabs(p[0]), std::max(std::fabs(p[1]), std::fabs(p[2]))), 1.0, 1e-5);
    }
}

} // namespace
