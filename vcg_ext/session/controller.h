#ifndef VCG_EXT_SNAKE_CONTROLLER_H
#define VCG_EXT_SNAKE_CONTROLLER_H

// The logic of the interactive edit tool, without Qt or OpenGL (so it is unit-testable):
// several snakes on one mesh (one selected), the seeds being placed, step/run, point
// editing (move, pin, insert, delete), undo/redo, export, and the session (snakes, pins,
// parameters, energy settings) saved to / restored from JSON, e.g. the sidecar file
// <mesh>.snakes.json next to the mesh, with a throttled autosave.
//
// Its parts: the energy and surface (SnakeEnergySource), the seed list being placed
// (SnakeSeedList), how a new snake is built from it (SnakeBuilder), the undo history of whole
// user actions (SnakeSessionHistory), the session file (SnakeSessionFile), and where and when it
// is saved (SnakeSidecar, SnakeAutosave).
//
// Every user input is validated: bad input throws vcg::tri::SnakeError with a message
// for the user, and leaves the controller unchanged.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <vcg_ext/energy/crease_energy.h>
#include <vcg_ext/energy/energy_source.h>
#include <vcg_ext/energy/feature_energy.h>
#include <vcg_ext/io/safe_file_write.h>
#include <vcg_ext/io/snake_io.h>
#include <vcg_ext/paths/seed_list.h>
#include <vcg_ext/paths/seed_path_cost.h>
#include <vcg_ext/paths/seed_points.h>
#include <vcg_ext/session/mesh_selection_memento.h>
#include <vcg_ext/session/session_file.h>
#include <vcg_ext/session/session_history.h>
#include <vcg_ext/session/sidecar.h>
#include <vcg_ext/session/snake_builder.h>
#include <vcg_ext/snake/error.h>
#include <vcg_ext/snake/geometric_snake.h>
#include <vcg_ext/surface/snake_surface.h>
#include <vcg_ext/surface/surface_point.h>

namespace vcg {
namespace tri {

template <class MeshType>
class SnakeController
{
public:
    typedef GeometricSnake<MeshType> Snake;
    typedef SnakeSurface<MeshType> Surface;
    typedef SnakeIO<MeshType> IO;
    typedef nlohmann::json json;

    typedef SnakeSessionFile<MeshType> SessionFile;

    /// Largest selection "use selected vertices" accepts (the ordering is quadratic).
    static int MaxSelectedSeeds() { return 5000; }

    explicit SnakeController(MeshType &m) : mesh(m) {}
    // the undo history refers to the members
    SnakeController(const SnakeController &) = delete;
    SnakeController &operator=(const SnakeController &) = delete;

    MeshType &Mesh() { return mesh; }

    // ================================================================ energy
    /// Computes the feature energy into the vertex quality (low = feature) and makes every
    /// snake slither on it. Throws on a bad type/smoothing or an unusable mesh.
    void ComputeEnergy(FeatureEnergyType type, int smoothing)
    {
        energy.Compute(type, smoothing);
        energyChanged();
    }
    /// The energy with the current settings, computed (if it is not yet) while `adjacency`,
    /// the caller's FF/VF build, runs: on a large mesh the two share the two cores
    /// (SnakeEnergySource::ComputeBeside).
    void ComputeEnergyBeside(const std::function<void()> &adjacency)
    {
        const bool before = energy.Computed();
        energy.ComputeBeside(adjacency);
        if (!before) energyChanged();
    }
    /// Any quality field can drive a snake: take the current vertex quality as the energy
    /// (low = feature) instead of computing one. Saved sessions remember it.
    void UseQualityAsEnergy()
    {
        energy.UseQuality();
        energyChanged();
    }
    bool EnergyFromQuality() const { return energy.FromQuality(); }
    bool EnergyComputed() const { return energy.Computed(); }
    FeatureEnergyType EnergyType() const { return energy.Type(); }
    /// Dihedral angle (degrees) above which an edge is a crease, for the crease energy.
    double CreaseAngle() const { return energy.CreaseAngle(); }
    void SetCreaseAngle(double deg)
    {
        if (energy.SetCreaseAngle(deg)) energyChanged();
    }
    int EnergySmoothing() const { return energy.Smoothing(); }
    /// Energy settings used when the energy is computed on demand (first snake).
    void SetEnergySettings(FeatureEnergyType type, int smoothing)
    {
        if (energy.SetSettings(type, smoothing)) energyChanged();
    }
    /// Computes the energy and builds the shared surface on another thread, for the snakes to
    /// come (SnakeEnergySource::PrepareInBackground): the edit tool starts it when it starts,
    /// so that Build does not wait for them. The mesh must not change until a call that uses
    /// the energy (those wait for it).
    void PrepareInBackground()
    {
        energy.PrepareInBackground();
        builder.PrepareInBackground();
    }
    /// The shared surface; computes the energy first if that was not done yet.
    Surface &EnsureSurface() { return *energy.EnsureSurface(); }
    bool HasSurface() const { return bool(energy.SurfacePtr()); }
    /// Warnings about the energy the snakes read, for the Log.
    std::vector<std::string> EnergyWarnings() { return energy.Warnings(); }
    /// False when the mesh lost or gained elements since the snakes were built on it.
    bool MeshMatches() const { return !HasSurface() || energy.SurfacePtr()->MatchesMesh(); }
    double MeanEdge() { return EnsureSurface().MeanEdge(); }
    /// The length unit of new snakes seeded at `seeds` (SnakeEnergySource::LengthScale).
    double LengthScale(const std::vector<SurfacePoint> &seeds = {}) { return energy.LengthScale(seeds); }

    // ================================================================ seeds
    /// The seed list being placed (SnakeSeedList); each change below is one undo step.
    const SnakeSeedList<MeshType> &SeedList() const { return seedList; }
    /// The vertex of face `face` nearest to the surface point (face, bary): the seed a click
    /// on the surface places (Sec. 5.5).
    int SeedVertexFromPick(int face, const vcg::Point3d &bary) const
    {
        return SnakeSeedList<MeshType>::VertexFromPick(mesh, face, bary);
    }
    /// Adds the seed for a click: the surface point hit (face + barycentric), where the curve
    /// will start or pass exactly. Returns the nearest vertex of the hit triangle (the seed's
    /// vertex in Seeds()), or -1 if the click repeats the last seed.
    int AddSeedFromPick(int face, const vcg::Point3d &bary)
    {
        return editSeeds("seed", [&](SnakeSeedList<MeshType> &l) { return l.AddPick(face, bary); });
    }
    int AddSeedVertex(int v)
    {
        return editSeeds("seed", [&](SnakeSeedList<MeshType> &l) { return l.AddVertex(v); });
    }
    /// A painted stroke (surface points in drawing order): seeds along it, at least
    /// `minSpacing` mean edge lengths apart. Returns the number of seeds added.
    int AddSeedsFromStroke(const std::vector<SurfacePoint> &stroke, double minSpacing = 3.0)
    {
        const double h = energy.MeanEdge();
        return editSeeds("stroke", [&](SnakeSeedList<MeshType> &l) { return l.AddStroke(stroke, minSpacing, h); });
    }
    /// Seeds from the selected vertices, ordered into a chain. Replaces the current seeds.
    int SeedsFromSelection()
    {
        return editSeeds("selection seeds",
                         [&](SnakeSeedList<MeshType> &l) { return l.FromSelection(MaxSelectedSeeds()); });
    }
    /// Replaces the seeds (e.g. vertices picked with another tool); validated.
    void SetSeeds(const std::vector<int> &s)
    {
        editSeeds("seeds", [&](SnakeSeedList<MeshType> &l) { l.SetVertices(s); return 0; });
    }
    /// Replaces the seeds by surface points (e.g. a Pick Points file snapped with
    /// SeedPointSnap): the curve will pass exactly through them. Validated.
    void SetSeedPoints(const std::vector<SurfacePoint> &pts)
    {
        editSeeds("seeds", [&](SnakeSeedList<MeshType> &l) { l.SetPoints(pts); return 0; });
    }
    void RemoveSeed(int i)
    {
        editSeeds("remove seed", [&](SnakeSeedList<MeshType> &l) { l.Remove(i); return 0; });
    }
    bool RemoveLastSeed()
    {
        return editSeeds("remove seed", [&](SnakeSeedList<MeshType> &l) { return l.RemoveLast(); });
    }
    void ClearSeeds()
    {
        editSeeds("clear seeds", [&](SnakeSeedList<MeshType> &l) { l.Clear(); return 0; });
    }
    /// The seed nearest to p, within maxDist (-1 if none).
    int NearestSeed(const vcg::Point3d &p, double maxDist = std::numeric_limits<double>::max()) const
    {
        return seedList.Nearest(p, maxDist);
    }
    const std::vector<int> &Seeds() const { return seedList.Vertices(); }
    /// Where seed i is: the clicked surface point, or its vertex.
    vcg::Point3d SeedPosition(int i) const { return seedList.Position(i); }
    /// Seed i as a surface point, or an invalid point (face -1) for a seed placed as a vertex.
    const SurfacePoint &SeedPoint(int i) const { return seedList.Point(i); }

    /// Closes the seed list: builds the initial snake at once (Sec. 5.5), selects it and
    /// clears the seeds. On error nothing changes (the seeds stay, to be fixed).
    int CloseSeeds(bool closed)
    {
        const int need = closed ? 3 : 2;
        if (seedList.size() < need)
            throw SnakeError(std::string("Geometric snake: ") + (closed ? "a closed" : "an open") + " snake needs at least " +
                             std::to_string(need) + " seeds (" + std::to_string(seedList.size()) + " placed).");
        EnsureSurface();
        checkMesh();
        addSnake(builder.FromSeeds(seedList, closed, params, seedCost), true);
        return selected;
    }

    /// Builds a snake from seeds given as surface points (e.g. snapped from coordinates or a
    /// Pick Points file, SeedPointSnap): the curve starts and ends exactly at them. Selects it.
    int CreateSnakeFromSeedPoints(const std::vector<SurfacePoint> &pts, bool closed)
    {
        EnsureSurface();
        checkMesh();
        addSnake(builder.FromSeedPoints(pts, closed, params, seedCost), false);
        return selected;
    }

    /// Contour completion (paths/stroke_loop.h): the open stroke `stroke` across a part becomes a
    /// closed snake round it, the stroke plus the way back round the hidden side. `view`:
    /// towards the viewer (zero: the side the stroke lies on). Selects it.
    int CreateLoopFromStroke(const std::vector<SurfacePoint> &stroke, const vcg::Point3d &view = vcg::Point3d(0, 0, 0))
    {
        addSnake(loopSnake(stroke, view), false);
        return selected;
    }

    /// The seeds placed so far, an open stroke across a part, completed into a closed snake
    /// round it (CreateLoopFromStroke); the seeds are used up. On error nothing changes.
    int CompleteSeedsToLoop(const vcg::Point3d &view = vcg::Point3d(0, 0, 0))
    {
        if (seedList.size() < 2)
            throw SnakeError("Geometric snake: completing a stroke into a loop needs at least 2 seeds across the part (" +
                             std::to_string(seedList.size()) + " placed).");
        addSnake(loopSnake(seedList.Points(EnsureSurface()), view), true);
        return selected;
    }

    // ================================================================ snakes
    int SnakeCount() const { return int(snakes.size()); }
    int Selected() const { return selected; }
    void Select(int i)
    {
        checkSnake(i);
        selected = i;
        touch("select");
    }
    Snake &Get(int i)
    {
        checkSnake(i);
        return *snakes[i];
    }
    Snake *SelectedSnake() { return (selected >= 0 && selected < int(snakes.size())) ? snakes[selected].get() : nullptr; }
    void DeleteSnake(int i)
    {
        checkSnake(i);
        record("delete snake");
        snakes.erase(snakes.begin() + i);
        history.SnakeRemoved(i);
        if (selected >= int(snakes.size())) selected = int(snakes.size()) - 1;
        touch("delete snake");
    }
    void DeleteAllSnakes()
    {
        if (snakes.empty()) return;
        record("delete all snakes");
        snakes.clear();
        history.AllChanged();
        selected = -1;
        touch("delete all snakes");
    }

    /// One operation of the selected snake; returns its largest move (mean edge lengths).
    double Step()
    {
        Snake &s = sel();
        checkMesh();
        const bool pushed = record("step");
        const auto t0 = SnakeClock::Now();
        double mv;
        try {
            mv = s.Step();
        } catch (...) {
            if (pushed) history.DropLast();
            throw;
        }
        lastOpMs = SnakeClock::MsSince(t0);
        computeMs += lastOpMs;
        for (const auto &x : s.Samples()) {
            vcg::Point3d p = x.p.Pd(mesh);
            if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]) || !std::isfinite(mv)) {
                s.Undo(); // the engine's own one-operation step back
                if (pushed) history.DropLast();
                throw SnakeError("Geometric snake: the operation produced invalid coordinates and was undone.");
            }
        }
        touch("step");
        return mv;
    }
    /// Operations of the selected snake until the run ends (snake/stop.h: converged, stopped by
    /// the engine, maxOps or `seconds` reached); returns operations done. The reason is in the
    /// snake's Stats().stop.
    int Run(int maxOps, double seconds = 0)
    {
        if (maxOps < 0 || maxOps > 1000000) throw SnakeError("Geometric snake: the operation limit must be in [0, 1000000].");
        SnakeRunLimits lim;
        lim.maxOperations = maxOps;
        lim.seconds = seconds;
        lim.Validate();
        Action run(*this, "run");
        const auto t0 = SnakeClock::Now();
        int ops = 0;
        SnakeStop why;
        while ((why = lim.Check(sel().Stats().stop, ops, SnakeClock::MsSince(t0) / 1000)) == SnakeStop::Running) {
            Step();
            ++ops;
        }
        sel().EndRun(why, lim.Message(why, ops, SnakeClock::MsSince(t0) / 1000));
        return ops;
    }
    bool Converged() { return SelectedSnake() && SelectedSnake()->Converged(); }
    /// Where sample i of the selected snake before its last operation is now: an operation
    /// inserts samples into an open snake that lengthened (GeometricSnake::LastInserted), so a
    /// host that holds a sample index across Steps (the sample being edited or dragged) follows
    /// it after each one. -1 stays -1.
    int FollowSample(int i) const
    {
        const Snake *s = (selected >= 0 && selected < int(snakes.size())) ? snakes[selected].get() : nullptr;
        return s ? s->FollowSample(i) : i;
    }

    /// The sample nearest to p (3D), over all snakes (ties: the selected one first).
    bool NearestSample(const vcg::Point3d &p, int &snake, int &sample,
                       double maxDist = std::numeric_limits<double>::max()) const
    {
        snake = sample = -1;
        double bd = maxDist;
        for (int k = 0; k < int(snakes.size()); ++k) {
            int si = (selected >= 0) ? (k + selected) % int(snakes.size()) : k;
            const auto &smp = snakes[si]->Samples();
            for (int i = 0; i < int(smp.size()); ++i) {
                double d = (smp[i].p.Pd(mesh) - p).Norm();
                if (d < bd) { bd = d; snake = si; sample = i; }
            }
        }
        return snake >= 0;
    }

    // --- point editing on the selected snake (Sec. 5.5)
    void MoveSample(int i, const SurfacePoint &p, bool pin)
    {
        checkSurfacePoint(p);
        Snake &s = sel();
        if (i < 0 || i >= s.SampleCount()) throw SnakeError("Geometric snake: no sample " + std::to_string(i) + ".");
        record("move sample");
        s.MoveSample(i, p, pin);
        touch("move sample");
    }
    void SetFixed(int i, bool fixed)
    {
        Snake &s = sel();
        if (i < 0 || i >= s.SampleCount()) throw SnakeError("Geometric snake: no sample " + std::to_string(i) + ".");
        record(fixed ? "pin" : "unpin");
        s.SetFixed(i, fixed);
        touch(fixed ? "pin" : "unpin");
    }
    bool TogglePin(int i)
    {
        Snake &s = sel();
        if (i < 0 || i >= s.SampleCount()) throw SnakeError("Geometric snake: no sample " + std::to_string(i) + ".");
        bool f = !s.Samples()[i].fixed;
        SetFixed(i, f);
        return f;
    }
    /// Inserts a sample after sample i (before it for the last sample of an open snake).
    int InsertSampleAfter(int i)
    {
        Snake &s = sel();
        if (i < 0 || i >= s.SampleCount()) throw SnakeError("Geometric snake: no sample " + std::to_string(i) + ".");
        int gap = (!s.Closed() && i == s.SampleCount() - 1) ? i - 1 : i;
        const bool pushed = record("insert sample");
        int r;
        try { r = s.InsertSample(gap); }
        catch (...) { if (pushed) history.DropLast(); throw; }
        touch("insert sample");
        return r;
    }
    void DeleteSample(int i)
    {
        Snake &s = sel();
        if (i < 0 || i >= s.SampleCount()) throw SnakeError("Geometric snake: no sample " + std::to_string(i) + ".");
        if (s.SampleCount() <= (s.Closed() ? 3 : 2))
            throw SnakeError("Geometric snake: cannot delete, the snake would have too few samples.");
        record("delete sample");
        s.DeleteSample(i);
        touch("delete sample");
    }

    // --- undo / redo of whole user actions (SnakeSessionHistory)
    /// Groups every change until the matching EndAction into one undo step (a Run, a drag);
    /// groups nest. An action that changes nothing leaves no step.
    void BeginAction(const std::string &label) { history.BeginAction(label); }
    void EndAction() { history.EndAction(); }
    bool InAction() const { return history.InAction(); }
    /// BeginAction / EndAction for a scope.
    struct Action
    {
        SnakeController &c;
        Action(SnakeController &ctl, const std::string &label) : c(ctl) { c.BeginAction(label); }
        ~Action() { c.EndAction(); }
    };

    bool CanUndo() const { return history.CanUndo(); }
    bool CanRedo() const { return history.CanRedo(); }
    /// The action Undo / Redo would take back / do again, e.g. "run" ("" if none).
    std::string UndoLabel() const { return history.UndoLabel(); }
    std::string RedoLabel() const { return history.RedoLabel(); }
    /// Returns to the session as it was before the last action (all snakes, seeds, selection).
    bool Undo()
    {
        if (!history.Undo(makeSnake(), saveSelection(), loadSelection())) return false;
        touch("undo");
        return true;
    }
    bool Redo()
    {
        if (!history.Redo(makeSnake(), saveSelection(), loadSelection())) return false;
        touch("redo");
        return true;
    }
    /// A change of the mesh's face and vertex selection made by `change()` (e.g. a cut's Select
    /// inside): one undo step that brings the selection back. Nothing is recorded if change()
    /// leaves the selection as it was, or throws (the selection is then put back).
    template <class Change>
    void ChangeSelection(const std::string &label, Change change)
    {
        auto before = std::make_shared<const Selection>(Selection::Save(mesh));
        try {
            change();
        } catch (...) {
            before->Restore(mesh);
            throw;
        }
        if (Selection::Save(mesh) == *before) return;
        history.RecordMesh(label, std::move(before));
        ++selectionRevision;
        touch(label.c_str());
    }
    /// Increases whenever the controller changes the mesh's selection (ChangeSelection, or an
    /// undo / redo of it): the view redraws the selection then.
    long SelectionRevision() const { return selectionRevision; }
    /// The undo history, to keep while the edit tool is away (SnakeKeptHistories): taken out
    /// (this controller's history is left empty) and adopted by the next controller on the same
    /// mesh once it has restored the session this one saved.
    typedef typename SnakeSessionHistory<Snake, SnakeSeedList<MeshType>, MeshSelectionMemento<MeshType>>::KeptSteps KeptHistory;
    KeptHistory TakeHistory() { return history.Take(); }
    void AdoptHistory(KeptHistory h) { history.Adopt(std::move(h)); }
    /// Memory bound of the history (default 100 MB) and its current estimate.
    void SetUndoLimit(size_t bytes) { history.SetLimit(bytes); }
    size_t UndoBytes() const { return history.Bytes(); }
    size_t UndoSteps() const { return history.Steps(); }
    /// Compute time of all operations so far (ms): a Run's wall time is compared to it.
    double ComputeMs() const { return computeMs; }

    /// Parameters of new snakes; also applied to the selected snake.
    void SetParams(const SnakeParams &p)
    {
        p.Validate();
        Snake *s = SelectedSnake();
        const bool same = IO::ParamsJson(p) == IO::ParamsJson(params) && (!s || IO::ParamsJson(s->Params()) == IO::ParamsJson(p));
        if (same) return;
        record("parameters");
        if (s) s->SetParams(p);
        params = p;
        touch("parameters");
    }
    const SnakeParams &Params() const { return params; }
    /// Parameters of the snakes built from now on only (the selected snake keeps its own,
    /// and its convergence).
    void SetNewSnakeParams(const SnakeParams &p)
    {
        p.Validate();
        params = p;
    }
    void SetSeedCost(SeedPathCost c)
    {
        if (int(c) < 0 || int(c) > 1) throw SnakeError("Geometric snake: unknown seed path cost.");
        seedCost = c;
    }
    SeedPathCost SeedCost() const { return seedCost; }

    // ================================================================ output
    /// Curves by extension (.json/.obj/.ply): the selected snake or all.
    void Export(const std::string &path, bool all, const std::vector<ProtectedFile> &keep = {})
    {
        std::vector<Snake *> out;
        if (all) for (auto &s : snakes) out.push_back(s.get());
        else if (SelectedSnake()) out.push_back(SelectedSnake());
        if (out.empty()) throw SnakeError("Geometric snake: there is no snake to export.");
        if (path.empty()) throw SnakeError("Geometric snake: no file name given.");
        IO::WriteCurves(path, out, keep);
    }

    /// The whole session (SnakeSessionFile): energy settings, parameters, seeds, snakes with pins.
    json ToJson()
    {
        SessionFile f(mesh);
        f.energyFromQuality = energy.FromQuality();
        f.energyType = energy.Type();
        f.energySmoothing = energy.Smoothing();
        f.creaseAngle = energy.CreaseAngle();
        f.params = params;
        f.seedCost = seedCost;
        f.selected = selected;
        f.seeds = seedList;
        json j = f.HeaderJson(mesh);
        for (auto &s : snakes) j["snakes"].push_back(IO::ToJson(*s));
        return j;
    }

    /// Restores a session saved by ToJson on this mesh. All or nothing: on error (other
    /// mesh, broken file) the controller is unchanged and a SnakeError says why.
    void FromJson(const json &j)
    {
        SessionFile f = SessionFile::Read(mesh, j);
        if (energy.Apply(f.energyFromQuality, f.energyType, f.energySmoothing, f.creaseAngle)) energyChanged();
        const std::shared_ptr<Surface> &surface = energy.EnsureSurface();
        checkMesh();
        std::vector<std::unique_ptr<Snake>> nsn;
        for (const auto &fs : f.snakes) {
            std::unique_ptr<Snake> s(new Snake(surface, fs.params));
            s->InitFromSamples(fs.samples, fs.closed, fs.lengthScale);
            // the curve a cut embedded, as saved (false, the snake traced anew, if it no longer fits)
            if (!fs.embedded.empty()) s->KeepPolyline(fs.embedded);
            nsn.push_back(std::move(s));
        }
        snakes = std::move(nsn);
        history.Clear();
        selected = f.selected;
        params = f.params;
        seedList = f.seeds;
        seedCost = f.seedCost;
        touch("load");
    }

    /// Writes the session safely (SafeFileWrite: temporary file, then rename): a crash or a
    /// full disk never leaves a half-written session behind.
    void Save(const std::string &path)
    {
        if (path.empty()) throw SnakeError("Geometric snake: no file name to save the session to.");
        SafeFileWrite::Write(path, ToJson().dump(1) + "\n");
        autosave.Saved(revision);
    }

    /// Loads a session file; false if there is none, throws if it is unusable. Only what the
    /// session needs is kept while reading (SnakeIO::ParseLean): memory about the file's size.
    bool Load(const std::string &path)
    {
        std::error_code ec;
        if (!std::filesystem::exists(path, ec)) return false;
        FromJson(IO::ParseFileLean(path));
        autosave.Saved(revision);
        return true;
    }

    typedef SnakeAutosave::Status SidecarStatus;
    /// Starts the session of the mesh file `meshPath`: restores its sidecar (if `restore` and it
    /// exists) and autosaves to it from now on. A sidecar that cannot be read (broken, truncated,
    /// made on another mesh, too large) is never touched: the session autosaves to a new
    /// SnakeSidecar::RecoveryPath() file instead, and the message says so (SnakeAutosave::Open).
    /// That holds too when the session came from the mesh (`restore` false): a sidecar of the mesh
    /// as it is on disk is not this mesh's once a cut added faces (issue 34), and keeps its curves.
    SidecarStatus OpenSidecar(const std::string &meshPath, bool restore, std::time_t now = std::time(nullptr))
    {
        return autosave.Open(meshPath, restore, now, [this](const std::string &side, bool load) {
            if (load)
                Load(side);
            else
                SessionFile::Read(mesh, IO::ParseFileLean(side)); // readable, and of this mesh?
        });
    }

    /// Autosave target (empty: none) and minimum interval between two autosaves.
    void SetAutosave(const std::string &path, double minIntervalSeconds = 1.0) { autosave.Set(path, minIntervalSeconds); }
    const std::string &AutosavePath() const { return autosave.Path(); }
    /// Saves if something changed since the last save and (unless forced) the interval
    /// has passed. Returns true if it wrote. Throws SnakeError if writing fails.
    bool Autosave(bool force = false)
    {
        if (!autosave.Due(revision, force)) return false;
        Save(autosave.Path());
        return true;
    }
    bool Dirty() const { return autosave.Dirty(revision); }

    // ================================================================ status
    /// Increases with every change (for redraws, autosave and auto-export).
    long Revision() const { return revision; }
    const std::string &LastOperation() const { return lastOp; }
    double LastOperationMs() const { return lastOpMs; }

private:
    MeshType &mesh;
    SnakeEnergySource<MeshType> energy{mesh};
    std::vector<std::unique_ptr<Snake>> snakes;
    int selected = -1;
    SnakeSeedList<MeshType> seedList{mesh};
    SnakeParams params;
    SeedPathCost seedCost = SeedPathCost::Length;
    long revision = 0;
    std::string lastOp;
    double lastOpMs = 0;
    SnakeAutosave autosave;
    double computeMs = 0;

    typedef MeshSelectionMemento<MeshType> Selection;
    SnakeSessionHistory<Snake, SnakeSeedList<MeshType>, Selection> history{{snakes, selected, seedList, params}};
    long selectionRevision = 0;
    auto saveSelection()
    {
        return [this] { return std::make_shared<const Selection>(Selection::Save(mesh)); };
    }
    auto loadSelection()
    {
        return [this](const Selection &s) {
            if (s.Restore(mesh)) ++selectionRevision;
        };
    }
    // builds new snakes, keeping the seed paths' index across builds; last: its background
    // build ends first
    SnakeBuilder<MeshType> builder{mesh, energy};

    bool record(const char *label) { return history.Record(label); }
    // builds the snakes an undo brings back
    auto makeSnake()
    {
        return [this](const SnakeParams &p) { return std::unique_ptr<Snake>(new Snake(energy.EnsureSurface(), p)); };
    }
    std::unique_ptr<Snake> loopSnake(const std::vector<SurfacePoint> &stroke, const vcg::Point3d &view)
    {
        EnsureSurface();
        checkMesh();
        return builder.LoopFromStroke(stroke, view, params, seedCost);
    }
    // a new snake, built from the seeds (`fromSeeds`: they are used up) or points: selected
    void addSnake(std::unique_ptr<Snake> sn, bool fromSeeds)
    {
        record("build");
        snakes.push_back(std::move(sn));
        history.SnakeAdded();
        selected = int(snakes.size()) - 1;
        if (fromSeeds) seedList.Clear();
        touch("create snake");
    }

    void touch(const char *op)
    {
        ++revision;
        lastOp = op;
    }
    /// A new energy: the snakes start afresh on it, and their mementos are outdated.
    void energyChanged()
    {
        for (auto &s : snakes) s->EnergyChanged();
        history.AllChanged();
        touch("energy");
    }
    void checkSnake(int i) const
    {
        if (i < 0 || i >= int(snakes.size()))
            throw SnakeError("Geometric snake: no snake " + std::to_string(i) + " (there are " +
                             std::to_string(snakes.size()) + ").");
    }
    void checkSurfacePoint(const SurfacePoint &p) const
    {
        if (!p.OnMesh(mesh)) throw SnakeError("Geometric snake: the point is not on the mesh.");
    }
    /// A change of the seed list: applied to a copy, so bad input (an exception) leaves the
    /// list as it was; one undo step if it changed anything.
    template <class Edit>
    auto editSeeds(const char *label, Edit edit)
    {
        SnakeSeedList<MeshType> next = seedList;
        auto r = edit(next);
        if (next != seedList) {
            record(label);
            seedList = std::move(next);
            touch(label);
        }
        return r;
    }
    void checkMesh() const
    {
        if (!MeshMatches())
            throw SnakeError("Geometric snake: the mesh changed (vertices or faces were added or removed) since the "
                             "snakes were built; restart the tool.");
    }
    Snake &sel()
    {
        Snake *s = SelectedSnake();
        if (!s) throw SnakeError("Geometric snake: no snake selected (place seeds and close them first).");
        return *s;
    }
};

} // namespace tri
} // namespace vcg

#endif
