// Tests of the edit tool's logic (vcg_ext/session/controller.h), without Qt or OpenGL.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include <crease_cases.h>
#include <snake_test_util.h>
#include <vcg_ext/cut/cut_session_map.h>
#include <vcg_ext/cut/mesh_cut.h>
#include <vcg_ext/session/controller.h>

using namespace vcg::tri;
using Controller = SnakeController<CMeshO>;

namespace {

// A face of the mesh having vertex v, and the barycentric coordinates of v in it.
bool FaceAtVertex(const CMeshO &m, int v, int &face, vcg::Point3d &bary)
{
    for (size_t f = 0; f < m.face.size(); ++f)
        for (int k = 0; k < 3; ++k)
            if (m.face[f].cV(k) == &m.vert[v]) {
                face = int(f);
                bary = vcg::Point3d(0, 0, 0);
                bary[k] = 1;
                return true;
            }
    return false;
}

// Seeds on the face x = 1, `off` edge lengths from the edge x = y = 1.
std::vector<int> EdgeSeeds(const CMeshO &m, double off)
{
    double h = MeshValidation<CMeshO>::MeanEdgeLength(m);
    std::vector<vcg::Point3d> pts;
    for (double z : {-0.6, -0.2, 0.2, 0.6}) pts.push_back(vcg::Point3d(1, 1 - off * h, z));
    return gs_test::NearestVertices(m, pts);
}

// An open snake built from those seeds, 2 edge lengths off the edge, and run for `ops`
// operations (none: built only).
void BuildEdgeSnake(Controller &c, const CMeshO &m, int ops = 0)
{
    c.SetSeeds(EdgeSeeds(m, 2.0));
    c.CloseSeeds(false);
    if (ops > 0) c.Run(ops);
}

double MeanEdgeError(Controller &c, int snake)
{
    auto pos = c.Get(snake).positions();
    double sum = 0;
    int n = 0;
    for (size_t i = 1; i + 1 < pos.size(); ++i, ++n) sum += gs_test::DistToCubeEdges(pos[i]);
    return n ? sum / n : 1e9;
}

std::string TempPath(const std::string &name)
{
    return std::string(::testing::TempDir()) + "/" + name;
}

} // namespace

TEST(SnakeController, PickGivesNearestVertexOfTheHitTriangle)
{
    CMeshO m;
    gs_test::MakeSnakeCube(m);
    Controller c(m);
    const auto &f = m.face[10];
    int v1 = int(f.cV(1) - &m.vert[0]);
    EXPECT_EQ(c.SeedVertexFromPick(10, vcg::Point3d(0.1, 0.8, 0.1)), v1);
    EXPECT_EQ(c.AddSeedFromPick(10, vcg::Point3d(0.1, 0.8, 0.1)), v1);
    EXPECT_EQ(c.AddSeedFromPick(10, vcg::Point3d(0.1, 0.8, 0.1)), -1); // the same point again: ignored
    EXPECT_EQ(c.Seeds().size(), 1u);
    // the seed is the clicked surface point, not the vertex
    const vcg::Point3d hit = SurfacePoint(10, vcg::Point3d(0.1, 0.8, 0.1)).Pd(m);
    EXPECT_LT((c.SeedPosition(0) - hit).Norm(), 1e-12);
    EXPECT_EQ(c.SeedPoint(0).face, 10);
    EXPECT_EQ(c.AddSeedFromPick(10, vcg::Point3d(0.2, 0.7, 0.1)), v1); // another point near the same vertex
    EXPECT_EQ(c.Seeds().size(), 2u);
}

TEST(SnakeController, ClicksInsideFacesMakeACurveThroughThemUndoableAndSaved)
{
    CMeshO m;
    gs_test::MakeSnakeCube(m, 4);
    Controller c(m);
    const std::vector<std::pair<int, vcg::Point3d>> picks{{3, {0.2, 0.3, 0.5}}, {40, {0.6, 0.3, 0.1}}};
    for (const auto &p : picks) c.AddSeedFromPick(p.first, p.second);
    const vcg::Point3d a = SurfacePoint(picks[0].first, picks[0].second).Pd(m);
    const vcg::Point3d b = SurfacePoint(picks[1].first, picks[1].second).Pd(m);
    EXPECT_EQ(c.NearestSeed(b), 1);
    // undo / redo of a click keeps the seed's surface point
    ASSERT_TRUE(c.Undo());
    EXPECT_EQ(c.Seeds().size(), 1u);
    ASSERT_TRUE(c.Redo());
    ASSERT_EQ(c.Seeds().size(), 2u);
    EXPECT_LT((c.SeedPosition(1) - b).Norm(), 1e-12);
    c.CloseSeeds(false);
    {
        const auto &s = c.Get(0);
        EXPECT_LT((s.Samples().front().p.Pd(m) - a).Norm(), 1e-9);
        EXPECT_LT((s.Samples().back().p.Pd(m) - b).Norm(), 1e-9);
        ASSERT_EQ(s.SeedPoints().size(), 2u);
    }
    // undoing the build gives the clicked seeds back, as points
    ASSERT_TRUE(c.Undo());
    EXPECT_EQ(c.SnakeCount(), 0);
    ASSERT_EQ(c.Seeds().size(), 2u);
    EXPECT_LT((c.SeedPosition(0) - a).Norm(), 1e-12);
    // the session remembers unbuilt click seeds as surface points
    Controller d(m);
    d.FromJson(c.ToJson());
    ASSERT_EQ(d.Seeds().size(), 2u);
    EXPECT_LT((d.SeedPosition(0) - a).Norm(), 1e-9);
    EXPECT_LT((d.SeedPosition(1) - b).Norm(), 1e-9);
    // removing a seed keeps the others' points; a seed list edited by hand (seed_points no
    // longer one per seed) gives vertex seeds; a seed point off the mesh is refused, nothing changes
    d.RemoveSeed(0);
    ASSERT_EQ(d.Seeds().size(), 1u);
    EXPECT_LT((d.SeedPosition(0) - b).Norm(), 1e-9);
    auto j = c.ToJson();
    j["seeds"] = {c.Seeds()[0], c.Seeds()[1], c.Seeds()[0]};
    d.FromJson(j);
    ASSERT_EQ(d.Seeds().size(), 3u);
    EXPECT_EQ(d.SeedPoint(0).face, -1);
    j = c.ToJson();
    j["seed_points"][0]["face"] = int(m.face.size()) + 5;
    EXPECT_THROW(d.FromJson(j), SnakeError);
    EXPECT_EQ(d.Seeds().size(), 3u);
    // seeds from surface points (a Pick Points file): the curve passes exactly through them
    Controller e(m);
    e.SetSeedPoints({SurfacePoint(picks[0].first, picks[0].second), SurfacePoint(picks[1].first, picks[1].second)});
    EXPECT_LT((e.SeedPosition(1) - b).Norm(), 1e-12);
    EXPECT_THROW(e.SetSeedPoints({SurfacePoint(-1, vcg::Point3d(1, 0, 0))}), SnakeError);
    EXPECT_EQ(e.Seeds().size(), 2u);
    e.CloseSeeds(false);
    EXPECT_LT((e.Get(0).Samples().front().p.Pd(m) - a).Norm(), 1e-9);
}

TEST(SnakeController, BadInputThrowsAndChangesNothing)
{
    CMeshO m;
    gs_test::MakeSnakeCube(m, 3);
    Controller c(m);
    EXPECT_THROW(c.AddSeedFromPick(-1, vcg::Point3d(1, 0, 0)), SnakeError);
    EXPECT_THROW(c.AddSeedFromPick(int(m.face.size()), vcg::Point3d(1, 0, 0)), SnakeError);
    EXPECT_THROW(c.AddSeedFromPick(0, vcg::Point3d(NAN, 0, 0)), SnakeError);
    EXPECT_THROW(c.AddSeedFromPick(0, vcg::Point3d(5, -4, 0)), SnakeError);
    EXPECT_THROW(c.AddSeedVertex(-3), SnakeError);
    EXPECT_THROW(c.AddSeedVertex(int(m.vert.size())), SnakeError);
    EXPECT_TRUE(c.Seeds().empty());
    EXPECT_THROW(c.CloseSeeds(false), SnakeError); // no seeds
    c.AddSeedVertex(0);
    EXPECT_THROW(c.CloseSeeds(false), SnakeError); // one seed
    EXPECT_EQ(c.Seeds().size(), 1u);               // kept, to be completed
    EXPECT_EQ(c.SnakeCount(), 0);
    EXPECT_THROW(c.Step(), SnakeError);             // no snake
    EXPECT_THROW(c.MoveSample(0, SurfacePoint(0, vcg::Point3d(1, 0, 0)), false), SnakeError);
    EXPECT_THROW(c.Select(0), SnakeError);
    EXPECT_THROW(c.Export(TempPath("none.json"), true), SnakeError);
    SnakeParams p;
    p.alpha = -1;
    EXPECT_THROW(c.SetParams(p), SnakeError);
    p = SnakeParams();
    p.spacing = NAN;
    EXPECT_THROW(c.SetParams(p), SnakeError);
    EXPECT_EQ(c.Params().alpha, SnakeParams().alpha);
    EXPECT_THROW(c.ComputeEnergy(FeatureEnergyType(7), 2), SnakeError);
    EXPECT_THROW(c.ComputeEnergy(FeatureEnergyType::NormalVariation, -1), SnakeError);
    EXPECT_THROW(c.RemoveSeed(5), SnakeError);
    EXPECT_FALSE(c.Load(TempPath("does_not_exist.snakes.json")));
}

TEST(SnakeController, SeedsBuildSnakeAndStepsConvergeOnCubeEdge)
{
    CMeshO m;
    gs_test::MakeSnakeCube(m, 4);
    Controller c(m);
    std::vector<int> seeds = EdgeSeeds(m, 2.0);
    for (int v : seeds) {
        int f;
        vcg::Point3d b;
        ASSERT_TRUE(FaceAtVertex(m, v, f, b));
        EXPECT_EQ(c.AddSeedFromPick(f, b), v);
    }
    int s = c.CloseSeeds(false);
    EXPECT_EQ(s, 0);
    EXPECT_EQ(c.SnakeCount(), 1);
    EXPECT_EQ(c.Selected(), 0);
    EXPECT_TRUE(c.Seeds().empty());
    EXPECT_GE(c.Get(0).SampleCount(), 5);
    const double h = c.MeanEdge();
    double before = MeanEdgeError(c, 0);
    EXPECT_GT(before, 1.0 * h);
    double mv = c.Step();
    EXPECT_TRUE(std::isfinite(mv));
    EXPECT_GT(mv, 0);
    EXPECT_LT(MeanEdgeError(c, 0), before); // the first operation moves toward the edge
    c.Run(300);
    EXPECT_TRUE(c.Converged());
    // Against the edge as the mesh has it (its straddling triangles chamfer the exact edge
    // up to about half an edge length deep), and against the exact edge.
    std::vector<vcg::Point3d> onMesh = gs_test::ProjectOntoMesh(m, gs_test::CubeEdgeLine(1.0, 0.95));
    auto pos = c.Get(0).positions();
    gs_test::CurveError e = gs_test::MeasureCurve(pos, h, [&](const vcg::Point3d &x) { return gs_test::DistToPolyline(x, onMesh); });
    EXPECT_LT(e.mean, 0.25) << "p95 " << e.p95 << " max " << e.max;
    double after = MeanEdgeError(c, 0);
    EXPECT_LT(after, 0.5 * h) << "before " << before / h << " h, after " << after / h << " h";
    EXPECT_GE(c.LastOperationMs(), 0.0);
}

TEST(SnakeController, PinHoldsExactlyAndUndoRedoRestore)
{
    CMeshO m;
    gs_test::MakeSnakeCube(m, 4);
    Controller c(m);
    BuildEdgeSnake(c, m);
    Controller::Snake &s = c.Get(0);
    int k = s.SampleCount() / 2;

    // Move sample k somewhere else on the surface and pin it there.
    SurfacePoint target(5, vcg::Point3d(0.2, 0.3, 0.5));
    target = s.Samples()[k].p; // start from its own face ...
    target.bary = vcg::Point3d(0.25, 0.25, 0.5);
    c.MoveSample(k, target, true);
    EXPECT_TRUE(s.Samples()[k].fixed);
    vcg::Point3d pinned = s.Samples()[k].p.Pd(m);
    auto beforeStep = s.positions();
    for (int i = 0; i < 20; ++i) c.Step();
    EXPECT_EQ(s.Samples()[k].p.Pd(m), pinned); // exactly
    EXPECT_TRUE(s.Samples()[k].fixed);

    // Undo of one operation restores the positions before it, redo re-applies it.
    auto p1 = s.positions();
    c.Step();
    auto p2 = s.positions();
    ASSERT_TRUE(c.Undo());
    EXPECT_EQ(s.positions(), p1);
    ASSERT_TRUE(c.Redo());
    EXPECT_EQ(s.positions(), p2);

    // Unpin, toggle, insert and delete.
    EXPECT_FALSE(c.TogglePin(k));
    EXPECT_FALSE(s.Samples()[k].fixed);
    int n = s.SampleCount();
    int ins = c.InsertSampleAfter(k);
    EXPECT_EQ(ins, k + 1);
    EXPECT_EQ(s.SampleCount(), n + 1);
    c.DeleteSample(ins);
    EXPECT_EQ(s.SampleCount(), n);
    ASSERT_TRUE(c.Undo());
    EXPECT_EQ(s.SampleCount(), n + 1);

    // Undo goes back to the seeds before the Build, redo builds the snake again.
    std::vector<int> seeds = EdgeSeeds(m, 2.0);
    while (c.SnakeCount() > 0 && c.Undo()) {}
    EXPECT_EQ(c.SnakeCount(), 0);
    EXPECT_EQ(c.Seeds(), seeds);
    EXPECT_EQ(c.UndoLabel(), "seeds");
    while (c.Redo()) {}
    ASSERT_EQ(c.SnakeCount(), 1);
    EXPECT_EQ(c.Get(0).SampleCount(), n);
    EXPECT_NO_THROW(c.Step());
    (void)beforeStep;
    (void)p1;
}

// Undo in the units a user thinks in: Build, Run (to convergence), drag (several moves grouped
// into one action) and a second Run are four steps; three undos return to the converged state
// before the drag, exactly (curve, pins, counters, convergence), and redo replays them.
TEST(SnakeController, UndoTakesBackWholeRunsAndDrags)
{
    CMeshO m;
    gs_test::MakeSnakeCube(m, 4);
    Controller c(m);
    BuildEdgeSnake(c, m);
    const int built = int(c.UndoSteps()); // the seeds, the Build
    EXPECT_EQ(built, 2);
    int ops = c.Run(2000);
    ASSERT_TRUE(c.Converged()) << ops << " operations";
    EXPECT_GT(ops, 3);
    EXPECT_EQ(int(c.UndoSteps()), built + 1) << "a whole Run is one undo step";
    EXPECT_EQ(c.UndoLabel(), "run");
    const std::string converged = c.ToJson().dump();
    const int convergedOps = c.Get(0).Stats().operations;

    // a drag: several moves of one sample, one undo step
    Controller::Snake &s = c.Get(0);
    int k = s.SampleCount() / 2;
    c.BeginAction("drag");
    SurfacePoint p = s.Samples()[k].p;
    for (double w : {0.2, 0.4, 0.6}) {
        p.bary = vcg::Point3d(w, (1 - w) / 2, (1 - w) / 2);
        c.MoveSample(k, p, true);
    }
    c.EndAction();
    EXPECT_EQ(int(c.UndoSteps()), built + 2);
    EXPECT_EQ(c.UndoLabel(), "drag");
    c.Run(2000);
    EXPECT_EQ(int(c.UndoSteps()), built + 3);
    const std::string rerun = c.ToJson().dump();

    ASSERT_TRUE(c.Undo()); // the second Run
    ASSERT_TRUE(c.Undo()); // the drag
    EXPECT_EQ(c.ToJson().dump(), converged) << "back to the converged snake before the drag";
    EXPECT_EQ(c.Get(0).Stats().operations, convergedOps);
    EXPECT_TRUE(c.Converged());
    ASSERT_TRUE(c.Undo()); // the first Run
    EXPECT_EQ(c.Get(0).Stats().operations, 0);
    EXPECT_FALSE(c.Converged());
    ASSERT_TRUE(c.Redo());
    ASSERT_TRUE(c.Redo());
    ASSERT_TRUE(c.Redo());
    EXPECT_EQ(c.ToJson().dump(), rerun);
    EXPECT_FALSE(c.CanRedo());

    // an action that changes nothing leaves no step; a new action drops the redo branch
    c.Undo();
    c.BeginAction("nothing");
    c.EndAction();
    EXPECT_TRUE(c.CanRedo());
    c.TogglePin(0);
    EXPECT_FALSE(c.CanRedo());
}

// The history is bounded by memory, not by a count: with a small limit old steps go,
// the newest stays.
TEST(SnakeController, UndoHistoryIsBoundedByMemory)
{
    CMeshO m;
    gs_test::MakeSnakeCube(m, 4);
    Controller c(m);
    BuildEdgeSnake(c, m);
    for (int i = 0; i < 300; ++i) c.Step();
    EXPECT_EQ(c.UndoSteps(), 302u) << "more than 200 steps are kept under the default 100 MB";
    EXPECT_LT(c.UndoBytes(), size_t(100) << 20);
    const size_t perStep = c.UndoBytes() / c.UndoSteps();
    c.SetUndoLimit(20 * perStep);
    c.Step();
    EXPECT_LE(c.UndoBytes(), 20 * perStep + perStep);
    EXPECT_GE(c.UndoSteps(), 10u);
    EXPECT_LE(c.UndoSteps(), 22u);
    int undone = 0;
    while (c.Undo()) ++undone;
    EXPECT_GE(undone, 10);
    EXPECT_EQ(c.SnakeCount(), 1) << "the oldest steps (seeds, build) were dropped";
}

TEST(SnakeController, SaveLoadRoundTripKeepsSnakesPinsAndParams)
{
    CMeshO m;
    gs_test::MakeSnakeCube(m, 3);
    Controller c(m);
    SnakeParams p;
    p.alpha = 0.2;
    p.beta = 0.7;
    p.spacing = 1.5;
    c.SetParams(p);
    c.SetSeeds(EdgeSeeds(m, 1.0));
    c.CloseSeeds(false);
    c.Step();
    c.SetFixed(1, true);
    // A second, closed snake around the cube's middle.
    std::vector<vcg::Point3d> ring{{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
    c.SetSeeds(gs_test::NearestVertices(m, ring));
    c.CloseSeeds(true);
    c.Select(0);
    c.AddSeedVertex(3); // seeds in progress are kept too

    std::string path = SnakeSidecar::Path(TempPath("cube.ply"));
    EXPECT_EQ(path, TempPath("cube.ply") + ".snakes.json");
    c.Save(path);
    EXPECT_FALSE(c.Dirty());

    CMeshO m2;
    gs_test::MakeSnakeCube(m2, 3);
    Controller d(m2);
    ASSERT_TRUE(d.Load(path));
    ASSERT_EQ(d.SnakeCount(), 2);
    EXPECT_EQ(d.Selected(), 0);
    EXPECT_EQ(d.Seeds(), std::vector<int>{3});
    EXPECT_DOUBLE_EQ(d.Params().alpha, 0.2);
    EXPECT_DOUBLE_EQ(d.Params().spacing, 1.5);
    for (int k = 0; k < 2; ++k) {
        auto &a = c.Get(k), &b = d.Get(k);
        ASSERT_EQ(a.SampleCount(), b.SampleCount());
        EXPECT_EQ(a.Closed(), b.Closed());
        for (int i = 0; i < a.SampleCount(); ++i) {
            EXPECT_EQ(a.Samples()[i].fixed, b.Samples()[i].fixed);
            EXPECT_EQ(a.Samples()[i].p.face, b.Samples()[i].p.face);
            EXPECT_NEAR((a.Samples()[i].p.Pd(m) - b.Samples()[i].p.Pd(m2)).Norm(), 0.0, 1e-9);
        }
    }
    EXPECT_TRUE(d.Get(0).Samples()[1].fixed);
    EXPECT_TRUE(d.Get(1).Closed());
    // The restored pin still holds.
    vcg::Point3d pin = d.Get(0).Samples()[1].p.Pd(m2);
    d.Step();
    EXPECT_EQ(d.Get(0).Samples()[1].p.Pd(m2), pin);
    EXPECT_FALSE(d.Undo() && d.Get(0).SampleCount() == 0);
    std::remove(path.c_str());
}

TEST(SnakeController, LoadRejectsOtherMeshAndBrokenFilesWithoutChange)
{
    CMeshO m;
    gs_test::MakeSnakeCube(m, 3);
    Controller c(m);
    c.SetSeeds(EdgeSeeds(m, 1.0));
    c.CloseSeeds(false);
    std::string path = TempPath("other.snakes.json");
    c.Save(path);

    CMeshO small;
    gs_test::MakeSnakeCube(small, 2);
    Controller d(small);
    d.AddSeedVertex(1);
    EXPECT_THROW(d.Load(path), SnakeError);
    EXPECT_EQ(d.SnakeCount(), 0);
    EXPECT_EQ(d.Seeds().size(), 1u);

    for (const char *text : {"{", "[]", "{\"format\":\"nope\"}",
                             "{\"format\":\"geometric-snake-session\",\"version\":1,\"mesh\":{\"vertices\":1}}"}) {
        std::ofstream(path) << text;
        EXPECT_THROW(d.Load(path), SnakeError) << text;
        EXPECT_EQ(d.SnakeCount(), 0);
    }
    // A sample on a face the mesh does not have.
    nlohmann::json j = c.ToJson();
    j["snakes"][0]["samples"][0]["face"] = 999999;
    CMeshO m3;
    gs_test::MakeSnakeCube(m3, 3);
    Controller e(m3);
    EXPECT_THROW(e.FromJson(j), SnakeError);
    EXPECT_EQ(e.SnakeCount(), 0);
    std::remove(path.c_str());
}

TEST(SnakeController, AutosaveIsThrottledAndForced)
{
    CMeshO m;
    gs_test::MakeSnakeCube(m, 3);
    Controller c(m);
    std::string path = TempPath("auto.snakes.json");
    std::remove(path.c_str());
    c.SetAutosave(path, 3600.0);
    EXPECT_FALSE(c.Autosave()); // nothing changed
    c.SetSeeds(EdgeSeeds(m, 1.0));
    c.CloseSeeds(false);
    EXPECT_TRUE(c.Autosave());   // first save
    c.Step();
    EXPECT_FALSE(c.Autosave());  // within the interval
    EXPECT_TRUE(c.Dirty());
    EXPECT_TRUE(c.Autosave(true));
    EXPECT_FALSE(c.Dirty());
    CMeshO m2;
    gs_test::MakeSnakeCube(m2, 3);
    Controller d(m2);
    EXPECT_TRUE(d.Load(path));
    EXPECT_EQ(d.Get(0).positions().size(), c.Get(0).positions().size());
    std::remove(path.c_str());
}

TEST(SnakeController, ExportSelectedOrAll)
{
    CMeshO m;
    gs_test::MakeSnakeCube(m, 3);
    Controller c(m);
    c.SetSeeds(EdgeSeeds(m, 1.0));
    c.CloseSeeds(false);
    std::vector<vcg::Point3d> ring{{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
    c.SetSeeds(gs_test::NearestVertices(m, ring));
    c.CloseSeeds(true);
    std::string js = TempPath("sel.json"), all = TempPath("all.json"), obj = TempPath("all.obj"), ply = TempPath("all.ply");
    c.Export(js, false);
    c.Export(all, true);
    c.Export(obj, true);
    c.Export(ply, true);
    nlohmann::json a = nlohmann::json::parse(std::ifstream(js));
    EXPECT_TRUE(a.at("closed").get<bool>());
    nlohmann::json b = nlohmann::json::parse(std::ifstream(all));
    EXPECT_EQ(b.at("snakes").size(), 2u);
    std::ifstream o(obj);
    std::string line;
    int lines = 0;
    while (std::getline(o, line)) lines += (line.rfind("l ", 0) == 0);
    EXPECT_EQ(lines, 2);
    EXPECT_THROW(c.Export(TempPath("x.txt"), true), SnakeError);
    for (auto &p : {js, all, obj, ply}) std::remove(p.c_str());
}

TEST(SnakeController, SelectionStrokeAndSeedEditing)
{
    CMeshO m;
    gs_test::MakeSnakeCube(m, 4);
    Controller c(m);
    EXPECT_THROW(c.SeedsFromSelection(), SnakeError); // nothing selected
    std::vector<int> seeds = EdgeSeeds(m, 2.0);
    // Selected in scrambled order: the chain puts them back in order along the line.
    for (int v : {seeds[2], seeds[0], seeds[3], seeds[1]}) m.vert[v].SetS();
    EXPECT_EQ(c.SeedsFromSelection(), 4);
    std::vector<int> got = c.Seeds();
    EXPECT_TRUE(got == seeds || got == std::vector<int>(seeds.rbegin(), seeds.rend()));
    EXPECT_EQ(c.NearestSeed(vcg::Point3d::Construct(m.vert[seeds[1]].cP())),
              got == seeds ? 1 : 2);
    c.RemoveSeed(0);
    EXPECT_EQ(c.Seeds().size(), 3u);
    EXPECT_TRUE(c.RemoveLastSeed());
    c.ClearSeeds();
    EXPECT_TRUE(c.Seeds().empty());

    // A stroke through the faces around many vertices gives few, well spaced seeds.
    std::vector<SurfacePoint> stroke;
    for (size_t f = 0; f < m.face.size(); f += 7) stroke.push_back(SurfacePoint(int(f), vcg::Point3d(0.3, 0.3, 0.4)));
    stroke.push_back(SurfacePoint(-5, vcg::Point3d(1, 0, 0))); // off the mesh: skipped
    int n = c.AddSeedsFromStroke(stroke);
    EXPECT_GT(n, 1);
    EXPECT_LT(n, int(stroke.size()));
    for (size_t i = 1; i < c.Seeds().size(); ++i) EXPECT_NE(c.Seeds()[i], c.Seeds()[i - 1]);
    EXPECT_THROW(c.AddSeedsFromStroke({SurfacePoint(-1, vcg::Point3d(1, 0, 0))}), SnakeError);
}

TEST(SnakeController, SeveralSnakesSelectDeleteAndNearestSample)
{
    CMeshO m;
    gs_test::MakeSnakeCube(m, 3);
    Controller c(m);
    c.SetSeeds(EdgeSeeds(m, 1.0));
    c.CloseSeeds(false);
    std::vector<vcg::Point3d> ring{{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
    c.SetSeeds(gs_test::NearestVertices(m, ring));
    c.CloseSeeds(true);
    EXPECT_EQ(c.Selected(), 1);
    int sn, si;
    vcg::Point3d p = c.Get(0).Samples()[2].p.Pd(m);
    ASSERT_TRUE(c.NearestSample(p, sn, si));
    EXPECT_EQ(sn, 0);
    EXPECT_EQ(si, 2);
    EXPECT_FALSE(c.NearestSample(vcg::Point3d(10, 10, 10), sn, si, 0.1));
    auto before = c.Get(0).positions();
    c.Step(); // steps the selected snake only
    EXPECT_EQ(c.Get(0).positions(), before);
    c.DeleteSnake(1);
    EXPECT_EQ(c.SnakeCount(), 1);
    EXPECT_EQ(c.Selected(), 0);
    c.DeleteAllSnakes();
    EXPECT_EQ(c.SelectedSnake(), nullptr);
    EXPECT_THROW(c.Step(), SnakeError);
}

TEST(SnakeController, BoundaryAndSeveralComponents)
{
    CMeshO a, b;
    gs_test::MakeFlatGrid(a, 20);
    gs_test::MakeSnakeCube(b, 2);
    gs_test::AppendMesh(a, b);
    gs_test::EnableSnakeAdjacency(a);
    Controller c(a);
    // Seeds on two components cannot be joined: an error, not a crash.
    c.AddSeedVertex(0);
    c.AddSeedVertex(int(a.vert.size()) - 1);
    EXPECT_THROW(c.CloseSeeds(false), SnakeError);
    c.ClearSeeds();
    // An open snake on the flat grid with a boundary (flat energy: it only smooths).
    c.AddSeedVertex(0);
    c.AddSeedVertex(20);
    ASSERT_NO_THROW(c.CloseSeeds(false));
    for (int i = 0; i < 10; ++i) {
        ASSERT_NO_THROW(c.Step());
        for (auto &p : c.Get(0).positions())
            for (int k = 0; k < 3; ++k) ASSERT_TRUE(std::isfinite(p[k]));
    }
}

// Building a second snake leaves the first one as it was, converged included.
TEST(SnakeController, BuildingASecondSnakeKeepsTheFirstConverged)
{
    CMeshO m;
    gs_test::MakeSnakeCube(m, 4);
    Controller c(m);
    BuildEdgeSnake(c, m, 2000);
    ASSERT_TRUE(c.Get(0).Converged());
    SnakeParams p = c.Params();
    p.alpha = 0.2;
    c.SetNewSnakeParams(p);
    std::vector<vcg::Point3d> ring{{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
    c.SetSeeds(gs_test::NearestVertices(m, ring));
    c.CloseSeeds(true);
    EXPECT_TRUE(c.Get(0).Converged());
    EXPECT_DOUBLE_EQ(c.Get(1).Params().alpha, 0.2);
    EXPECT_DOUBLE_EQ(c.Get(0).Params().alpha, SnakeParams().alpha);
}

// A seed list that mixes a click and a vertex seed becomes surface points through
// SnakeSurface::VertexPoint; a vertex no face uses (left over in the file) has no such point:
// a clear error, the seeds kept, no snake (it read past the vertex's empty face list before).
TEST(SnakeController, VertexSeedWithoutFacesIsRefused)
{
    CMeshO m;
    gs_test::MakeSnakeCube(m);
    const int lone = int(m.vert.size());
    vcg::tri::Allocator<CMeshO>::AddVertex(m, CMeshO::CoordType(3, 3, 3));
    gs_test::EnableSnakeAdjacency(m);
    Controller c(m);
    c.AddSeedFromPick(10, vcg::Point3d(0.2, 0.7, 0.1));
    c.AddSeedVertex(lone);
    try {
        c.CloseSeeds(false);
        FAIL() << "a seed at a vertex without faces was accepted";
    } catch (const vcg::tri::SnakeError &e) {
        EXPECT_NE(std::string(e.what()).find("belongs to no face"), std::string::npos) << e.what();
    }
    EXPECT_EQ(c.SnakeCount(), 0);
    EXPECT_EQ(c.Seeds().size(), 2u);
}

// The mesh's selection changed through the controller (the Cut section's Select inside) is one
// undo step among the snakes' own, in order; the snakes are untouched by it.
TEST(SnakeController, SelectionChangesAreUndoneInOrderWithTheSnakes)
{
    CMeshO m;
    gs_test::MakeSnakeCube(m, 4);
    Controller c(m);
    BuildEdgeSnake(c, m, 2000);
    ASSERT_EQ(c.UndoLabel(), "run");
    const std::string ran = c.ToJson().dump();
    auto selected = [&m] {
        std::vector<int> f;
        for (size_t i = 0; i < m.face.size(); ++i)
            if (m.face[i].IsS()) f.push_back(int(i));
        return f;
    };
    auto selectEvery = [&m](int step) {
        for (size_t i = 0; i < m.face.size(); ++i) (i % step == 0) ? m.face[i].SetS() : m.face[i].ClearS();
        for (auto &v : m.vert) v.ClearS();
        for (auto &f : m.face)
            if (f.IsS())
                for (int k = 0; k < 3; ++k) f.V(k)->SetS();
    };
    const long rev0 = c.SelectionRevision();
    c.ChangeSelection("select inside", [&] { selectEvery(3); });
    const std::vector<int> sel3 = selected();
    ASSERT_FALSE(sel3.empty());
    EXPECT_EQ(c.UndoLabel(), "select inside");
    EXPECT_EQ(c.ToJson().dump(), ran);
    EXPECT_EQ(c.SelectionRevision(), rev0 + 1);
    c.TogglePin(0); // a change of the snake after it
    const std::string pinned = c.ToJson().dump();
    ASSERT_NE(pinned, ran);

    ASSERT_TRUE(c.Undo()); // the pin; the selection stays
    EXPECT_EQ(c.ToJson().dump(), ran);
    EXPECT_EQ(selected(), sel3);
    ASSERT_TRUE(c.Undo()); // the selection
    EXPECT_TRUE(selected().empty());
    for (const auto &v : m.vert) EXPECT_FALSE(v.IsS());
    EXPECT_EQ(c.ToJson().dump(), ran);
    EXPECT_EQ(c.UndoLabel(), "run");
    EXPECT_GT(c.SelectionRevision(), rev0 + 1);
    ASSERT_TRUE(c.Redo());
    EXPECT_EQ(selected(), sel3);
    ASSERT_TRUE(c.Redo());
    EXPECT_EQ(c.ToJson().dump(), pinned);
    EXPECT_EQ(selected(), sel3);

    // a second selection over the first: undo goes back to the first, not to none
    c.ChangeSelection("select outside", [&] { selectEvery(5); });
    ASSERT_TRUE(c.Undo());
    EXPECT_EQ(selected(), sel3);
    ASSERT_TRUE(c.Redo());
    EXPECT_NE(selected(), sel3);

    // no change, no step; a throwing change leaves the selection and the history as they were
    const size_t steps = c.UndoSteps();
    const std::vector<int> now = selected();
    c.ChangeSelection("same", [] {});
    EXPECT_EQ(c.UndoSteps(), steps);
    EXPECT_THROW(c.ChangeSelection("bad", [&] {
        selectEvery(2);
        throw SnakeError("refused");
    }),
                 SnakeError);
    EXPECT_EQ(selected(), now);
    EXPECT_EQ(c.UndoSteps(), steps);
}

// A cut embeds the snake into the mesh (new vertices and faces): the session saved before it,
// mapped through the cut, restores on the mesh after it with every sample where it was.
TEST(SnakeController, SessionMapsOntoTheMeshAfterACut)
{
    CMeshO m;
    gs_test::MakeSnakeCube(m, 4);
    Controller c(m);
    c.SetSeeds(gs_test::NearestVertices(m, {vcg::Point3d(1, -0.5, -0.5), vcg::Point3d(1, 0.5, -0.5),
                                            vcg::Point3d(1, 0.5, 0.5), vcg::Point3d(1, -0.5, 0.5)}));
    c.CloseSeeds(true);
    c.Run(40); // the samples leave the vertices
    const std::vector<vcg::Point3d> pos = c.Get(0).positions();
    int inFaces = 0;
    for (const auto &s : c.Get(0).Samples())
        inFaces += std::max(s.p.bary[0], std::max(s.p.bary[1], s.p.bary[2])) < 1 - 1e-9;
    ASSERT_GT(inFaces, 3);
    const Controller::json before = c.ToJson();
    CutCurve curve;
    curve.points = c.Get(0).Polyline();
    curve.closed = true;
    const size_t fn = m.face.size();
    const MeshCut<CMeshO>::Result r = MeshCut<CMeshO>::Apply(m, {curve}, MeshCut<CMeshO>::Param());
    ASSERT_GT(m.face.size(), fn);
    EXPECT_THROW(Controller(m).FromJson(before), SnakeError); // the old session: another mesh now
    UpdateTopology<CMeshO>::FaceFace(m);
    UpdateTopology<CMeshO>::VertexFace(m);
    const Controller::json after = CutSessionMap<CMeshO>::Map(before, r.points, m);
    Controller d(m);
    d.FromJson(after);
    ASSERT_EQ(d.SnakeCount(), 1);
    const std::vector<vcg::Point3d> now = d.Get(0).positions();
    ASSERT_EQ(now.size(), pos.size());
    for (size_t i = 0; i < pos.size(); ++i) EXPECT_LT((now[i] - pos[i]).Norm(), 1e-6) << "sample " << i;
    int moved = 0;
    for (size_t i = 0; i < d.Get(0).Samples().size(); ++i) moved += d.Get(0).Samples()[i].p.face != c.Get(0).Samples()[i].p.face;
    EXPECT_GT(moved, 0); // samples in split faces went to their sub-faces
}

// The edit tool prepares the energy and the surface on another thread when it starts (issue
// 37): the snake built afterwards is the one built without it, the energy settings chosen
// meanwhile win, and a controller dropped while preparing waits for the thread (ASan, TSan).
TEST(SnakeController, PreparingInBackgroundBuildsTheSameSnakeOnASecondThread)
{
    CMeshO m;
    gs_test::MakeSnakeCube(m, 4);
    std::vector<vcg::Point3d> plain;
    {
        Controller c(m);
        BuildEdgeSnake(c, m, 50);
        plain = c.Get(0).positions();
    }
    Controller c(m);
    c.PrepareInBackground();
    c.PrepareInBackground(); // once
    c.SetSeeds(EdgeSeeds(m, 2.0)); // seeds are placed meanwhile
    c.CloseSeeds(false);
    EXPECT_TRUE(c.HasSurface());
    EXPECT_TRUE(c.EnergyComputed());
    c.Run(50);
    const std::vector<vcg::Point3d> pre = c.Get(0).positions();
    ASSERT_EQ(pre.size(), plain.size());
    for (size_t i = 0; i < pre.size(); ++i) EXPECT_LT((pre[i] - plain[i]).Norm(), 1e-12) << i;

    Controller d(m);
    d.PrepareInBackground();
    d.SetEnergySettings(FeatureEnergyType::Crease, 0); // waits, then recomputes with these
    EXPECT_EQ(d.EnergyType(), FeatureEnergyType::Crease);
    EXPECT_TRUE(d.HasSurface());
    {
        Controller dropped(m);
        dropped.PrepareInBackground();
    }
}

namespace {

// The open snake of gs_creases' strip-cap case (tests/crease_cases.h): seeded 4 chain edges
// inside the top rim of the tessellated stepped shaft, whose cap is a strip of slivers, with
// the crease energy; it lengthens ~1.6x on its way to the rim, and gets samples as it does.
int BuildStretchingSnake(Controller &c, CMeshO &m)
{
    const int n = 64;
    const double e = 2 * M_PI * 10 / n;
    gs_crease::MakeSteppedShaft(m, n, 10, 50 * e, 10 - 3 * e, 35 * e, gs_crease::CapStyle::Strip);
    gs_test::EnableSnakeAdjacency(m);
    const std::vector<gs_crease::Chain> ch = gs_crease::SharpChains(m);
    int top = -1;
    for (size_t i = 0; i < ch.size(); ++i)
        if (gs_test::DistToPolyline(vcg::Point3d(10 - 3 * e, 0, 85 * e), ch[i].pts, ch[i].closed) < 0.01) top = int(i);
    gs_crease::Case k;
    if (top < 0 || !gs_crease::MakeCase(m, ch, top, 4, false, k)) return -1;
    c.SetEnergySettings(FeatureEnergyType::Crease, 2);
    return c.CreateSnakeFromSeedPoints(SeedPointSnap<CMeshO>::Snap(m, k.seeds, 2, false).points, false);
}

} // namespace

// The edit tool holds sample indices across operations (the sample being edited, the one being
// dragged), and an operation inserts samples into an open snake that lengthened: the indices
// follow their samples (FollowSample), so a pin, insert or drag after a Run step hits the sample
// the user chose. The sample pinned here stays pinned where it was; the old index points to
// another sample once samples went in before it.
TEST(SnakeController, HeldSampleIndicesFollowSamplesInsertedByOperations)
{
    CMeshO m;
    Controller c(m);
    ASSERT_EQ(BuildStretchingSnake(c, m), 0);
    Controller::Snake &s = c.Get(0);
    const int n0 = s.SampleCount();
    int pinned = n0 / 2, last = n0 - 1, none = -1;
    c.SetFixed(pinned, true);
    const SurfacePoint pin = s.Samples()[pinned].p;
    const int pinned0 = pinned;
    int opsWithInsertions = 0;
    for (int op = 0; op < 150 && !c.Converged(); ++op) {
        const std::vector<vcg::Point3d> before = s.positions();
        c.Step();
        const std::vector<int> &ins = s.LastInserted();
        ASSERT_EQ(s.SampleCount(), int(before.size() + ins.size()));
        opsWithInsertions += !ins.empty();
        // the samples that were not inserted are the old ones, in order
        std::vector<int> old;
        for (int i = 0; i < s.SampleCount(); ++i)
            if (!std::binary_search(ins.begin(), ins.end(), i)) old.push_back(i);
        ASSERT_EQ(old.size(), before.size());
        for (int i = 0; i < int(before.size()); ++i) ASSERT_EQ(c.FollowSample(i), old[i]) << i;
        for (int k : ins) { // inserted between two old samples, never at an end
            EXPECT_GT(k, 0);
            EXPECT_LT(k, s.SampleCount() - 1);
        }
        pinned = c.FollowSample(pinned);
        last = c.FollowSample(last);
        none = c.FollowSample(none);
        ASSERT_TRUE(s.Samples()[pinned].fixed) << "operation " << op;
        EXPECT_EQ(s.Samples()[pinned].p.face, pin.face);
        EXPECT_EQ(s.Samples()[pinned].p.bary, pin.bary);
    }
    EXPECT_GT(opsWithInsertions, 3);
    EXPECT_GT(pinned, pinned0) << "samples went in before the pinned one";
    EXPECT_FALSE(s.Samples()[pinned0].fixed) << "its old index is another sample now";
    EXPECT_EQ(last, s.SampleCount() - 1);
    EXPECT_EQ(none, -1);
    // any other change ends what the last operation inserted
    c.SetFixed(pinned, false);
    EXPECT_TRUE(s.LastInserted().empty());
    EXPECT_EQ(c.FollowSample(3), 3);
}

// The edit tool's wall-time Run (host_edit_gui_tool, part 4): the session restored with an open
// snake as built (seeded across the cube's front face, 2.2 edge lengths below its top edge),
// its spacing lowered to the finest 0.05 edge lengths and a convergence window of 300
// operations, then a Run of 300 operations. The spacing applies when a snake is built: the
// snake keeps the density it was built with (SnakeGapRefine), instead of growing ~20x, and its
// kept embeddings serve the Run (an embedding per segment rebuilt at every operation made 24
// operations in 56 s).
TEST(SnakeController, LoweringTheSpacingOfABuiltSnakeDoesNotDensifyIt)
{
    CMeshO m;
    ASSERT_TRUE(gs_test::LoadMesh(m, std::string(GS_DATA_DIR) + "/icocube.ply"));
    gs_test::EnableSnakeAdjacency(m);
    Controller c(m);
    const double h = c.MeanEdge();
    std::vector<vcg::Point3d> clicks;
    for (double x : {-0.6, -0.2, 0.2, 0.6}) clicks.push_back(vcg::Point3d(x, 1 - 2.2 * h, 1));
    c.CreateSnakeFromSeedPoints(SeedPointSnap<CMeshO>::Snap(m, clicks, 2, false).points, false);
    const int built = c.Get(0).SampleCount();
    nlohmann::json j = c.ToJson();
    for (auto *p : {&j["params"], &j["snakes"][0]["params"]}) {
        (*p)["spacing"] = 0.05;
        (*p)["convergence_window"] = 300;
    }
    Controller d(m);
    d.FromJson(j);
    ASSERT_EQ(d.Get(0).Params().spacing, 0.05);
    const Controller::Snake &s = d.Get(0);
    {
        Controller::Action run(d, "run"); // as the tool's Run: operations one by one
        for (int op = 0; op < 300; ++op) {
            d.Step();
            ASSERT_LE(s.SampleCount(), 2 * built) << "operation " << op << ", built with " << built;
        }
    }
    std::printf("[spacing] built with %d samples, %d after 300 operations at spacing 0.05; %d embeddings built, %d "
                "reuses\n", built, s.SampleCount(), s.Stats().embeddings, s.Stats().reuses);
    EXPECT_EQ(s.Stats().operations, 300);
    EXPECT_FALSE(s.Converged()); // the window of 300 operations is not full
    EXPECT_LE(s.Stats().embeddings, 30) << s.Stats().reuses << " reuses";
    // the snake moved to the edge (it does not sit still because it does not refine)
    EXPECT_LT(MeanEdgeError(d, 0), 0.5 * h);
}
