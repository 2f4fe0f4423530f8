// Undo of a cut (issue 34; vcg_ext/session/mesh_undo.h): the edit tool's Select inside (exact)
// and Cut open add vertices and faces, which MeshLab 2020.09 cannot undo. The tool keeps the
// mesh before the cut, the session and its history as one step: Undo brings the mesh back
// exactly (counts, positions, faces, selection, colour, quality, texture coordinates) and the
// snakes as they were; Redo the cut mesh.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>
#include <string>

#include <snake_test_util.h>
#include <vcg_ext/cut/mesh_cut.h>
#include <vcg_ext/session/controller.h>
#include <vcg_ext/session/mesh_undo.h>

using namespace vcg::tri;
using Controller = SnakeController<CMeshO>;
using Undo = SnakeMeshUndo<CMeshO, Controller::KeptHistory>;

namespace {

// Everything of the mesh the undo must bring back, as text (compared exactly).
std::string Dump(const CMeshO &m)
{
    std::ostringstream o;
    o.precision(9);
    o << m.vn << " " << m.fn << " " << m.vert.size() << " " << m.face.size() << " " << m.textures.size() << "\n";
    for (const auto &v : m.vert)
        o << v.cP()[0] << " " << v.cP()[1] << " " << v.cP()[2] << " " << v.IsS() << " " << v.cQ() << " "
          << int(v.cC()[0]) << " " << v.cN()[2] << "\n";
    const CVertexO *v0 = &m.vert[0];
    for (const auto &f : m.face) {
        for (int k = 0; k < 3; ++k) o << f.cV(k) - v0 << " " << f.cWT(k).U() << " " << f.cWT(k).V() << " ";
        o << f.IsS() << " " << f.cQ() << " " << int(f.cC()[1]) << "\n";
    }
    return o.str();
}

// A 12 x 12 irregular plate with colour, quality, per-face colour and quality, texture
// coordinates and a selection, and a session with a closed snake round its middle.
void MakePlateWithSnake(CMeshO &m, Controller &ctl)
{
    gs_test::MakeGridPlate(m, 12, 12, 1.0, 1.0, 0.25, 7);
    gs_test::EnableSnakeAdjacency(m);
    m.face.EnableColor();
    m.face.EnableQuality();
    m.face.EnableWedgeTexCoord();
    m.textures.push_back("plate.png");
    for (size_t i = 0; i < m.vert.size(); ++i) {
        m.vert[i].Q() = float(i) * 0.5f;
        m.vert[i].C() = vcg::Color4b(i % 250, 10, 20, 255);
        if (i % 7 == 0) m.vert[i].SetS();
    }
    for (size_t i = 0; i < m.face.size(); ++i) {
        CFaceO &f = m.face[i];
        f.Q() = float(i);
        f.C() = vcg::Color4b(1, i % 200, 3, 255);
        if (i % 5 == 0) f.SetS();
        for (int k = 0; k < 3; ++k) f.WT(k) = vcg::TexCoord2f(f.V(k)->P()[0] / 12, f.V(k)->P()[1] / 12);
    }
    std::vector<SurfacePoint> loop;
    for (int cell : {3 * 12 + 3, 3 * 12 + 8, 8 * 12 + 8, 8 * 12 + 3}) loop.push_back(SurfacePoint(2 * cell, {1 / 3., 1 / 3., 1 / 3.}));
    ctl.CreateSnakeFromSeedPoints(loop, true);
}

MeshCut<CMeshO>::Result CutSelectInside(CMeshO &m, Controller &ctl)
{
    MeshCut<CMeshO>::Param p;
    p.mode = CutMode::Select;
    p.side = CutSide::Inside;
    CutCurve c;
    c.points = ctl.SelectedSnake()->Polyline();
    c.closed = true;
    return MeshCut<CMeshO>::Apply(m, {c}, p);
}

} // namespace

TEST(SnakeMeshUndo, UndoOfACutBringsBackTheMeshTheSnakesAndTheHistoryExactly)
{
    CMeshO m;
    Controller ctl(m);
    MakePlateWithSnake(m, ctl);
    const std::string before = Dump(m);
    const int vn = m.vn, fn = m.fn;
    const std::string session = ctl.ToJson().dump();
    ASSERT_EQ(ctl.UndoSteps(), 1u); // the Build

    // the tool: keep the step, cut, start the session afresh on the cut mesh
    Undo undo;
    std::string why;
    ASSERT_TRUE(undo.Push(m, session, ctl.TakeHistory(), "select inside", why)) << why;
    const MeshCut<CMeshO>::Result r = CutSelectInside(m, ctl);
    ASSERT_GT(r.addedVertices, 0);
    ASSERT_GT(r.addedFaces, 0);
    ASSERT_EQ(m.vn, vn + r.addedVertices);
    const std::string cut = Dump(m);
    ASSERT_NE(cut, before);

    // Undo: the mesh, its attributes and selection as they were, the session and its history
    std::string s = "the cut session";
    Controller::KeptHistory h;
    ASSERT_TRUE(undo.Undo(m, s, h));
    EXPECT_EQ(m.vn, vn);
    EXPECT_EQ(m.fn, fn);
    EXPECT_EQ(Dump(m), before);
    EXPECT_EQ(m.textures.size(), 1u); // not appended twice
    EXPECT_EQ(s, session);
    EXPECT_EQ(h.UndoCount(), 1u);
    EXPECT_FALSE(undo.CanUndo());
    ASSERT_TRUE(undo.CanRedo());

    // the snakes come back on the restored mesh, and Ctrl+Z goes on into the Build
    UpdateTopology<CMeshO>::FaceFace(m);
    UpdateTopology<CMeshO>::VertexFace(m);
    Controller back(m);
    back.FromJson(nlohmann::json::parse(s));
    back.AdoptHistory(std::move(h));
    // the same snakes on the same faces (a session read back is re-embedded: compare its samples)
    const nlohmann::json was = nlohmann::json::parse(session), now = back.ToJson();
    ASSERT_EQ(back.SnakeCount(), 1);
    const nlohmann::json &a = now["snakes"][0]["samples"], &b = was["snakes"][0]["samples"];
    ASSERT_EQ(a.size(), b.size());
    for (size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i]["face"], b[i]["face"]);
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[i]["bary"][k].get<double>(), b[i]["bary"][k].get<double>(), 1e-12);
    }
    EXPECT_EQ(now["snakes"][0]["closed"], was["snakes"][0]["closed"]);
    EXPECT_EQ(now["mesh"], was["mesh"]);
    ASSERT_TRUE(back.CanUndo());
    EXPECT_EQ(back.UndoLabel(), "build");
    // the history handed back is the new session's now: Redo of the cut gets it and the cut session
    h = back.TakeHistory();
    s = back.ToJson().dump();

    // Redo: the cut mesh again, and the session it had
    std::string rs = s;
    Controller::KeptHistory rh = std::move(h);
    ASSERT_TRUE(undo.Redo(m, rs, rh));
    EXPECT_EQ(Dump(m), cut);
    EXPECT_EQ(rs, "the cut session");
    EXPECT_TRUE(undo.CanUndo());
    ASSERT_TRUE(undo.Undo(m, rs, rh));
    EXPECT_EQ(Dump(m), before);
}

TEST(SnakeMeshUndo, BoundedByCountAndMemoryAndSaysWhyAStepIsNotKept)
{
    CMeshO m;
    gs_test::MakeGridPlate(m, 20, 20, 1.0, 1.0);
    const size_t b = Undo::MeshBytes(m);
    std::string why;

    Undo::Param small;
    small.byteLimit = b - 1; // a copy of this mesh does not fit
    Undo tiny(small);
    EXPECT_FALSE(tiny.Push(m, "", Controller::KeptHistory(), "cut open", why));
    EXPECT_NE(why.find("too large"), std::string::npos) << why;
    EXPECT_FALSE(tiny.CanUndo());

    Undo undo; // at most two cuts
    for (int k = 0; k < 3; ++k) {
        EXPECT_TRUE(undo.Push(m, std::to_string(k), Controller::KeptHistory(), "cut " + std::to_string(k), why));
        Allocator<CMeshO>::AddVertices(m, 1); // the "cut"
    }
    EXPECT_EQ(undo.UndoCount(), 2u);
    EXPECT_EQ(undo.UndoLabel(), "cut 2");
    EXPECT_LE(undo.Bytes(), 2 * Undo::MeshBytes(m));
    std::string s;
    Controller::KeptHistory h;
    ASSERT_TRUE(undo.Undo(m, s, h));
    ASSERT_TRUE(undo.Undo(m, s, h));
    EXPECT_EQ(s, "1");
    EXPECT_EQ(size_t(m.vn), 21u * 21u + 1);
    EXPECT_FALSE(undo.Undo(m, s, h)); // the first cut is gone: nothing changes
    EXPECT_EQ(size_t(m.vn), 21u * 21u + 1);

    // a mesh with deleted elements is not kept (a copy would renumber the faces the snakes are on)
    Allocator<CMeshO>::DeleteFace(m, m.face[0]);
    EXPECT_FALSE(undo.Push(m, "", Controller::KeptHistory(), "cut", why));
    EXPECT_NE(why.find("deleted"), std::string::npos) << why;
    // a new step drops the redo side
    EXPECT_FALSE(undo.CanRedo());
}

TEST(SnakeMeshUndo, TheSidecarOfTheUncutMeshSurvivesTheCutAndTheCutSessionGoesToARecoveryFile)
{
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / ("gs_mesh_undo_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string mesh = (dir / "plate.ply").string(), side = SnakeSidecar::Path(mesh);
    std::ofstream(mesh) << "the mesh on disk";

    CMeshO m;
    Controller ctl(m);
    MakePlateWithSnake(m, ctl);
    ctl.OpenSidecar(mesh, true, 1764000000);
    ASSERT_EQ(ctl.AutosavePath(), side);
    ASSERT_TRUE(ctl.Autosave(true)); // the tool saves the session before the cut
    std::stringstream was;
    was << std::ifstream(side).rdbuf();

    // the cut, then the session goes on on the cut mesh (from the mesh, not the sidecar)
    const std::string session = ctl.ToJson().dump();
    ASSERT_GT(CutSelectInside(m, ctl).addedFaces, 0);
    UpdateTopology<CMeshO>::FaceFace(m);
    UpdateTopology<CMeshO>::VertexFace(m);
    Controller after(m);
    const Controller::SidecarStatus st = after.OpenSidecar(mesh, false, 1764000000);
    EXPECT_TRUE(st.unreadable) << "the sidecar of the uncut mesh would be overwritten";
    EXPECT_NE(after.AutosavePath(), side);
    EXPECT_NE(after.AutosavePath().find("plate.ply.snakes.recovered-"), std::string::npos) << after.AutosavePath();
    after.SetSeeds({5, 40});
    ASSERT_TRUE(after.Autosave(true));
    std::stringstream now;
    now << std::ifstream(side).rdbuf();
    EXPECT_EQ(now.str(), was.str()) << "the sidecar of the uncut mesh changed";
    // the cut mesh's session is recoverable from its file
    Controller back(m);
    EXPECT_TRUE(back.Load(after.AutosavePath()));
    EXPECT_EQ(back.Seeds().size(), 2u);
    // and the uncut mesh's from the sidecar
    CMeshO m2;
    Controller c2(m2);
    MakePlateWithSnake(m2, c2);
    EXPECT_TRUE(c2.Load(side));
    EXPECT_EQ(c2.SnakeCount(), 1);
    (void)session;
    fs::remove_all(dir);
}
