// Mesh validation: input checks and topology counts without FF adjacency.

#include <gtest/gtest.h>

#include <limits>

#include <common/ml_mesh_type.h>

#include "generated_meshes.h"
#include "vcg_ext/surface/mesh_validation.h"

namespace {

using vcg::tri::SnakeError;
typedef vcg::tri::MeshValidation<CMeshO> MV;

TEST(MeshValidation, CleanClosedMesh)
{
    CMeshO m;
    gs_test::MakeIcosphere(m, 3);
    auto r = MV::Inspect(m);
    EXPECT_EQ(r.vertices, 642);
    EXPECT_EQ(r.faces, 1280);
    EXPECT_EQ(r.nonManifoldEdges, 0);
    EXPECT_EQ(r.nonManifoldVertices, 0);
    EXPECT_EQ(r.degenerateFaces, 0);
    EXPECT_EQ(r.borderEdges, 0);
    EXPECT_EQ(r.components, 1);
    EXPECT_GT(r.meanEdgeLength, 0.05);
    EXPECT_LT(r.meanEdgeLength, 0.2);
    EXPECT_NO_THROW(MV::RequireSurface(m));
}

TEST(MeshValidation, MeanEdgeLengthOfGrid)
{
    CMeshO m;
    gs_test::MakeFlatGrid(m, 4, 4.0); // unit quads: per face two unit edges and one sqrt(2)
    EXPECT_NEAR(MV::MeanEdgeLength(m), (2.0 + std::sqrt(2.0)) / 3.0, 1e-6);
    auto r = MV::Inspect(m);
    EXPECT_EQ(r.borderEdges, 16);
    EXPECT_EQ(r.components, 1);
}

TEST(MeshValidation, NonManifoldEdgeAndVertex)
{
    CMeshO fin;
    gs_test::MakeNonManifoldFin(fin);
    auto r = MV::Inspect(fin);
    EXPECT_EQ(r.nonManifoldEdges, 1);
    EXPECT_EQ(r.nonManifoldVertices, 0); // its vertices' faces still form one fan
    EXPECT_EQ(r.borderEdges, 6);
    CMeshO cones;
    gs_test::MakeTouchingCones(cones, 10);
    r = MV::Inspect(cones);
    EXPECT_EQ(r.nonManifoldVertices, 1);
    EXPECT_EQ(r.nonManifoldEdges, 0);
    EXPECT_EQ(r.borderEdges, 20);
    EXPECT_EQ(r.components, 1);
}

TEST(MeshValidation, DegenerateFacesAndComponents)
{
    CMeshO m;
    gs_test::MakeFromArrays(m,
                            {vcg::Point3d(0, 0, 0), vcg::Point3d(1, 0, 0), vcg::Point3d(2, 0, 0), vcg::Point3d(1, 1, 0),
                             vcg::Point3d(5, 5, 5), vcg::Point3d(6, 5, 5), vcg::Point3d(5, 6, 5)},
                            {{0, 1, 3}, {1, 2, 3}, {0, 2, 1} /*collinear*/, {4, 5, 6}, {4, 4, 5} /*repeated*/});
    auto r = MV::Inspect(m);
    EXPECT_EQ(r.degenerateFaces, 2);
    EXPECT_EQ(r.components, 2);
    EXPECT_TRUE(MV::IsDegenerate(m.face[2]));
    EXPECT_FALSE(MV::IsDegenerate(m.face[0]));

    CMeshO two, b;
    gs_test::MakeIcosphere(two, 2);
    gs_test::MakeIcosphere(b, 2);
    for (auto &v : b.vert) v.P() += vcg::Point3f(3, 0, 0);
    gs_test::AppendMesh(two, b);
    EXPECT_EQ(MV::Inspect(two).components, 2);
}

TEST(MeshValidation, DeletedElementsIgnored)
{
    CMeshO m;
    gs_test::MakeIcosphere(m, 2);
    vcg::tri::Allocator<CMeshO>::DeleteFace(m, m.face[3]);
    auto r = MV::Inspect(m);
    EXPECT_EQ(r.faces, 319);
    EXPECT_EQ(r.borderEdges, 3);
    EXPECT_EQ(r.nonManifoldVertices, 0);
    // A live face on a deleted vertex is an error.
    vcg::tri::Allocator<CMeshO>::DeleteVertex(m, *m.face[5].V(0));
    EXPECT_THROW(MV::RequireSurface(m), SnakeError);
    EXPECT_THROW(MV::Inspect(m), SnakeError);
}

TEST(MeshValidation, BadInputThrows)
{
    CMeshO empty;
    EXPECT_THROW(MV::RequireSurface(empty), SnakeError);
    EXPECT_THROW(MV::MeanEdgeLength(empty), SnakeError);
    EXPECT_EQ(MV::Inspect(empty).faces, 0); // reporting on an empty mesh is fine

    CMeshO cloud;
    vcg::tri::Allocator<CMeshO>::AddVertices(cloud, 5);
    EXPECT_THROW(MV::RequireSurface(cloud), SnakeError);
    EXPECT_EQ(MV::Inspect(cloud).vertices, 5);

    CMeshO nan;
    gs_test::MakeIcosphere(nan, 1);
    nan.vert[2].P()[0] = std::numeric_limits<float>::quiet_NaN();
    EXPECT_THROW(MV::RequireSurface(nan), SnakeError);
    EXPECT_THROW(MV::Inspect(nan), SnakeError);
    CMeshO inf;
    gs_test::MakeIcosphere(inf, 1);
    inf.vert[2].P()[2] = -std::numeric_limits<float>::infinity();
    EXPECT_THROW(MV::RequireSurface(inf), SnakeError);

    CMeshO point; // faces of zero size everywhere
    gs_test::MakeFromArrays(point, {vcg::Point3d(1, 1, 1), vcg::Point3d(1, 1, 1), vcg::Point3d(1, 1, 1)}, {{0, 1, 2}});
    EXPECT_THROW(MV::MeanEdgeLength(point), SnakeError);
}

} // namespace
