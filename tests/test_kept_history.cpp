// The edit tool's undo history outlives the tool (issue 37): MeshLab ends the tool when any
// filter starts; the history is kept per mesh (vcg_ext/session/kept_histories.h) and adopted by
// the next session on the same mesh, unless the mesh (vcg_ext/session/mesh_fingerprint.h) or the
// session changed meanwhile.
#include <gtest/gtest.h>

#include <chrono>
#include <utility>

#include <snake_test_util.h>
#include <vcg_ext/session/controller.h>
#include <vcg_ext/session/kept_histories.h>
#include <vcg_ext/session/mesh_fingerprint.h>

using namespace vcg::tri;
using Controller = SnakeController<CMeshO>;
using Fingerprint = SnakeMeshFingerprint;

namespace {

// Seeds on the face x = 1, two edge lengths from the edge x = y = 1 (a crease to slither onto).
std::vector<int> EdgeSeeds(const CMeshO &m)
{
    const double h = MeshValidation<CMeshO>::MeanEdgeLength(m);
    std::vector<vcg::Point3d> pts;
    for (double z : {-0.6, -0.2, 0.2, 0.6}) pts.push_back(vcg::Point3d(1, 1 - 2 * h, z));
    return gs_test::NearestVertices(m, pts);
}

} // namespace

TEST(SnakeMeshFingerprint, SeesEveryChangeTheSnakesDependOnAndNothingElse)
{
    CMeshO m;
    gs_test::MakeSnakeCube(m, 3);
    const Fingerprint f = Fingerprint::Of(m);
    EXPECT_EQ(f, Fingerprint::Of(m));
    EXPECT_EQ(f.Change(Fingerprint::Of(m)), "");

    // MeshLab's Select All (flags), a new quality or colour: the same mesh for the snakes
    for (auto &fc : m.face) fc.SetS();
    for (auto &v : m.vert) { v.SetS(); v.Q() = 7; v.C() = vcg::Color4b::Red; }
    EXPECT_EQ(f, Fingerprint::Of(m));

    CMeshO moved;
    gs_test::MakeSnakeCube(moved, 3);
    moved.vert[5].P()[0] += 1e-6f;
    EXPECT_EQ(f.Change(Fingerprint::Of(moved)), "vertices were moved");

    CMeshO flipped; // Invert Faces Orientation: the same counts, other vertex order
    gs_test::MakeSnakeCube(flipped, 3);
    std::swap(flipped.face[3].V(1), flipped.face[3].V(2));
    EXPECT_EQ(f.Change(Fingerprint::Of(flipped)), "faces were changed or deleted (the same counts, other vertices)");

    CMeshO deleted; // a face deleted in place (not compacted): the slots stay, the live count drops
    gs_test::MakeSnakeCube(deleted, 3);
    Allocator<CMeshO>::DeleteFace(deleted, deleted.face[0]);
    EXPECT_NE(f.Change(Fingerprint::Of(deleted)).find("added or removed"), std::string::npos);

    CMeshO grown;
    gs_test::MakeSnakeCube(grown, 3);
    Allocator<CMeshO>::AddVertex(grown, vcg::Point3f(0, 0, 0));
    const std::string why = f.Change(Fingerprint::Of(grown));
    EXPECT_NE(why.find(std::to_string(m.vn) + " vertices and " + std::to_string(m.fn) + " faces then, " +
                       std::to_string(m.vn + 1) + " and " + std::to_string(m.fn) + " now"),
              std::string::npos)
        << why;
}

TEST(SnakeMeshFingerprint, TakesMillisecondsOnALargeMesh)
{
    CMeshO m;
    gs_test::MakeRotatedIcoCube(m, 6); // ~82k faces
    const auto t0 = std::chrono::steady_clock::now();
    const Fingerprint f = Fingerprint::Of(m);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    std::printf("fingerprint of %d vertices, %d faces: %.1f ms\n", m.vn, m.fn, ms);
    EXPECT_EQ(f.fn, m.fn);
    EXPECT_GT(m.fn, 80000);
}

// What the edit tool does when MeshLab ends it and the user starts it again: the session goes
// to JSON, the history to the store; a new controller restores the JSON and adopts the history.
TEST(SnakeKeptHistory, UndoGoesOnInTheNextSessionOnTheSameMesh)
{
    CMeshO m;
    gs_test::MakeSnakeCube(m, 4);
    Controller c1(m);
    c1.SetSeeds(EdgeSeeds(m));
    c1.CloseSeeds(false);
    const std::string built = c1.ToJson().dump();
    c1.Run(2000);
    ASSERT_TRUE(c1.Converged());
    const std::string converged = c1.ToJson().dump();
    ASSERT_NE(built, converged);
    const size_t steps = c1.UndoSteps(); // seeds, build, run

    SnakeKeptHistories<int, Controller::KeptHistory> store;
    store.Keep(7, c1.TakeHistory(), Fingerprint::Of(m), converged);
    EXPECT_FALSE(c1.CanUndo()) << "the history left the controller";
    EXPECT_EQ(store.Steps(7), steps);

    // the next start: the session comes back from the text the tool left on the mesh (its
    // snakes' curves and pins, not their stats), the history from the store
    Controller c2(m);
    c2.FromJson(nlohmann::json::parse(converged));
    const std::string resumed = c2.ToJson().dump();
    Controller::KeptHistory h;
    std::string why;
    ASSERT_EQ(store.Take(7, Fingerprint::Of(m), converged, h, why), decltype(store)::Outcome::Taken) << why;
    EXPECT_EQ(store.Size(), 0u);
    c2.AdoptHistory(std::move(h));
    EXPECT_EQ(c2.UndoSteps(), steps);
    EXPECT_EQ(c2.UndoLabel(), "run");
    ASSERT_TRUE(c2.Undo());
    EXPECT_EQ(c2.ToJson().dump(), built) << "Undo takes back the Run made before the tool ended, exactly";
    EXPECT_FALSE(c2.Converged());
    ASSERT_TRUE(c2.Redo());
    EXPECT_EQ(c2.ToJson().dump(), resumed);
    ASSERT_TRUE(c2.Undo());
    ASSERT_TRUE(c2.Undo()); // the Build
    EXPECT_EQ(c2.SnakeCount(), 0);
    EXPECT_EQ(c2.SeedList().size(), 4);
    // and the history goes on recording in the new session: Build, Run as before
    ASSERT_TRUE(c2.Redo());
    EXPECT_EQ(c2.ToJson().dump(), built);
    c2.Run(2000);
    EXPECT_EQ(c2.UndoLabel(), "run");
    EXPECT_FALSE(c2.CanRedo());
    const auto curve = [](const std::string &j) { return nlohmann::json::parse(j)["snakes"][0]["polyline"]; };
    EXPECT_EQ(curve(c2.ToJson().dump()), curve(converged));
}

TEST(SnakeKeptHistory, DroppedWhenTheMeshOrTheSessionChangedMeanwhile)
{
    CMeshO m;
    gs_test::MakeSnakeCube(m, 3);
    SnakeUndo<int> h;
    h.Push(1, 4, "build");
    h.Push(2, 4, "run");
    SnakeKeptHistories<std::pair<const void *, int>, SnakeUndo<int>> store;
    const auto key = std::make_pair(static_cast<const void *>(&m), 0);
    const Fingerprint f = Fingerprint::Of(m);
    SnakeUndo<int> out;
    std::string why;

    EXPECT_EQ(store.Take(key, f, "s", out, why), decltype(store)::Outcome::None);
    EXPECT_EQ(why, "");

    store.Keep(key, h, f, "session");
    EXPECT_EQ(store.Steps(key), 2u);
    ASSERT_EQ(store.Take(key, f, "session", out, why), decltype(store)::Outcome::Taken);
    EXPECT_EQ(out.UndoCount(), 2u);
    EXPECT_EQ(out.UndoLabel(), "run");
    EXPECT_FALSE(store.Has(key)) << "taken once";

    // a filter moved vertices (same counts): dropped, and the user is told why
    store.Keep(key, h, f, "session");
    m.vert[0].P()[1] += 0.01f;
    EXPECT_EQ(store.Take(key, Fingerprint::Of(m), "session", out, why), decltype(store)::Outcome::Dropped);
    EXPECT_EQ(why, "the mesh changed while the tool was away: vertices were moved");
    EXPECT_FALSE(store.Has(key));

    // the snakes on the mesh changed (a filter made a snake): dropped
    store.Keep(key, h, Fingerprint::Of(m), "session");
    EXPECT_EQ(store.Take(key, Fingerprint::Of(m), "session with another snake", out, why),
              decltype(store)::Outcome::Dropped);
    EXPECT_NE(why.find("snakes of this mesh were changed"), std::string::npos);

    // closing a mesh drops its history, the others stay
    const auto other = std::make_pair(static_cast<const void *>(&m), 1);
    store.Keep(key, h, f, "a");
    store.Keep(other, h, f, "b");
    EXPECT_EQ(store.DropIf([&](const std::pair<const void *, int> &k) { return k.second == 0; }), 1u);
    EXPECT_FALSE(store.Has(key));
    EXPECT_TRUE(store.Has(other));
}
