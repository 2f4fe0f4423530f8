// The edit tool's exact "select inside" twice along the same snake (issue 34): the first select
// embeds the snake's polyline and moves the session's snakes onto the new faces (CutPointMap,
// CutSessionMap, as EditGeometricSnakePlugin::afterMeshCut does); the snake restored there
// runs along the embedded curve, so the second select adds nothing and selects the same faces.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include <snake_test_util.h>
#include <vcg_ext/cut/cut_session_map.h>
#include <vcg_ext/cut/mesh_cut.h>
#include <vcg_ext/session/controller.h>

using namespace vcg::tri;
using Controller = SnakeController<CMeshO>;

#define GS_SHARED_MESH_DIR GS_DATA_DIR "/../../shared/data/meshes"

namespace {

CutCurve CurveOf(Controller &c)
{
    CutCurve curve;
    curve.points = c.Get(0).Polyline();
    curve.closed = c.Get(0).Closed();
    return curve;
}

std::vector<int> SelectedFaces(const CMeshO &m)
{
    std::vector<int> s;
    for (size_t f = 0; f < m.face.size(); ++f)
        if (!m.face[f].IsD() && m.face[f].IsS()) s.push_back(int(f));
    return s;
}

/// Selects inside the controller's first snake, maps the session onto the cut mesh and selects
/// again along the restored snake: the second select must find the curve embedded already.
void ExpectSecondSelectAddsNothing(CMeshO &m, Controller &c)
{
    const Controller::json before = c.ToJson();
    const MeshCut<CMeshO>::Result first = MeshCut<CMeshO>::Apply(m, {CurveOf(c)}, MeshCut<CMeshO>::Param());
    ASSERT_GT(first.addedVertices, 0);
    const std::vector<int> selected = SelectedFaces(m);
    ASSERT_FALSE(selected.empty());
    UpdateTopology<CMeshO>::FaceFace(m);
    UpdateTopology<CMeshO>::VertexFace(m);
    UpdateNormal<CMeshO>::PerVertexNormalizedPerFaceNormalized(m);
    Controller d(m);
    d.FromJson(CutSessionMap<CMeshO>::Map(before, first.points, m));
    ASSERT_EQ(d.SnakeCount(), 1);
    // the snake cut along keeps the embedded curve (traced anew on the split faces it moves by a
    // few percent of an edge and the second select refuses it, or splits faces again)
    EXPECT_TRUE(CutSessionMap<CMeshO>::KeepCurve(d, 0, first.chains[0], m));
    // ... and keeps it through the session file (a layer switch, a restart): saved, read back
    // as the tool reads it (SnakeController::Load, the lean parser)
    const std::string file = testing::TempDir() + "gs_cut_remap_session.json";
    d.Save(file);
    Controller e(m);
    ASSERT_TRUE(e.Load(file));
    std::remove(file.c_str());
    ASSERT_EQ(e.SnakeCount(), 1);
    EXPECT_EQ(CurveOf(e).points.size(), CurveOf(d).points.size());
    // a file without the embedded curve (older) still loads; its snake is traced anew
    Controller::json old = d.ToJson();
    ASSERT_TRUE(old["snakes"][0].contains("embedded"));
    old["snakes"][0].erase("embedded");
    Controller o(m);
    o.FromJson(old);
    EXPECT_EQ(o.SnakeCount(), 1);
    const size_t vn = m.vert.size(), fn = m.face.size();
    EXPECT_FALSE(MeshCut<CMeshO>::Plan(m, {CurveOf(e)}, MeshCut<CMeshO>::Param()).ChangesMesh());
    const MeshCut<CMeshO>::Result again = MeshCut<CMeshO>::Apply(m, {CurveOf(e)}, MeshCut<CMeshO>::Param());
    EXPECT_EQ(again.addedVertices, 0);
    EXPECT_EQ(again.addedFaces, 0);
    EXPECT_EQ(m.vert.size(), vn);
    EXPECT_EQ(m.face.size(), fn);
    EXPECT_EQ(again.curveVertices, first.curveVertices);
    EXPECT_EQ(SelectedFaces(m), selected);
    EXPECT_NEAR(again.areaInside, first.areaInside, 1e-9 * (first.areaInside + first.areaOutside));
}

} // namespace

TEST(MeshCutRemap, SecondSelectAlongTheRemappedSnakeAddsNothingOnACube)
{
    CMeshO m;
    gs_test::MakeRotatedIcoCube(m, 4);
    gs_test::EnableSnakeAdjacency(m);
    Controller c(m);
    c.SetSeeds(gs_test::NearestVertices(m, {vcg::Point3d(1, -0.5, -0.5), vcg::Point3d(1, 0.5, -0.5),
                                            vcg::Point3d(1, 0.5, 0.5), vcg::Point3d(1, -0.5, 0.5)}));
    c.CloseSeeds(true);
    c.Run(40); // the samples leave the vertices: the polyline crosses edges inside faces
    ExpectSecondSelectAddsNothing(m, c);
}

TEST(MeshCutRemap, SecondSelectAlongTheRemappedSnakeAddsNothingOnAScan)
{
    CMeshO m;
    ASSERT_TRUE(gs_test::LoadMesh(m, GS_SHARED_MESH_DIR "/bunny00.off"));
    gs_test::EnableSnakeAdjacency(m);
    UpdateBounding<CMeshO>::Box(m);
    const vcg::Point3d top = vcg::Point3d::Construct(m.bbox.Center()) +
                             vcg::Point3d(0, 0.3 * m.bbox.DimY(), 0);
    const double r = 0.2 * m.bbox.Diag();
    std::vector<vcg::Point3d> ring;
    for (int i = 0; i < 6; ++i)
        ring.push_back(top + vcg::Point3d(r * std::cos(2 * M_PI * i / 6), 0, r * std::sin(2 * M_PI * i / 6)));
    Controller c(m);
    c.SetSeeds(gs_test::NearestVertices(m, ring));
    c.CloseSeeds(true);
    c.Run(3); // (longer runs fold this loop over itself, which the cut refuses)
    ExpectSecondSelectAddsNothing(m, c);
}
