#ifndef VCG_EXT_SNAKE_CONTROLLER_H
#define VCG_EXT_SNAKE_CONTROLLER_H

// The logic of the interactive edit tool, without Qt or OpenGL (so it is unit-testable): the
// operations on several snakes on one mesh (one selected): the seeds being placed (SnakeSeedList)
// and the snakes built from them (SnakeBuilder), step/run, point editing (move, pin, insert,
// delete), parameters and export. They work on a SnakeSession (session/snake_session.h: the
// energy, the snakes, seeds and parameters, the rule every change follows, the undo of whole
// user actions) that is saved to / restored from JSON, e.g. the sidecar file
// <mesh>.snakes.json next to the mesh, with a throttled autosave (SnakeStoredSession,
// session/stored_session.h).
//
// Every user input is validated: bad input throws vcg::tri::SnakeError with a message
// for the user, and leaves the controller unchanged.

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <vcg_ext/io/snake_io.h>
#include <vcg_ext/paths/seed_list.h>
#include <vcg_ext/paths/seed_path_cost.h>
#include <vcg_ext/paths/seed_points.h>
#include <vcg_ext/session/snake_builder.h>
#include <vcg_ext/session/stored_session.h>
#include <vcg_ext/snake/error.h>
#include <vcg_ext/snake/geometric_snake.h>
#include <vcg_ext/surface/snake_surface.h>
#include <vcg_ext/surface/surface_point.h>

namespace vcg {
namespace tri {

template <class MeshType>
class SnakeController : public SnakeStoredSession<MeshType>
{
    typedef SnakeStoredSession<MeshType> Base;

public:
    typedef typename Base::Snake Snake;
    typedef typename Base::IO IO;
    typedef typename Base::Action Action;

    /// Largest selection "use selected vertices" accepts (the ordering is quadratic).
    static int MaxSelectedSeeds() { return 5000; }

    explicit SnakeController(MeshType &m) : Base(m) {}

    // ================================================================ energy
    // (its settings: SnakeSession)
    /// Computes the energy and builds the shared surface on another thread, for the snakes to
    /// come (SnakeEnergySource::PrepareInBackground): the edit tool starts it when it starts,
    /// so that Build does not wait for them. The mesh must not change until a call that uses
    /// the energy (those wait for it).
    void PrepareInBackground()
    {
        energy.PrepareInBackground();
        builder.PrepareInBackground();
    }

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
        this->EnsureSurface();
        checkMesh();
        addSnake(builder.FromSeeds(seedList, closed, params, seedCost), true);
        return selected;
    }

    /// Builds a snake from seeds given as surface points (e.g. snapped from coordinates or a
    /// Pick Points file, SeedPointSnap): the curve starts and ends exactly at them. Selects it.
    int CreateSnakeFromSeedPoints(const std::vector<SurfacePoint> &pts, bool closed)
    {
        this->EnsureSurface();
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
        addSnake(loopSnake(seedList.Points(this->EnsureSurface()), view), true);
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
        Snake &s = selSample(i);
        record("move sample");
        s.MoveSample(i, p, pin);
        touch("move sample");
    }
    void SetFixed(int i, bool fixed)
    {
        Snake &s = selSample(i);
        record(fixed ? "pin" : "unpin");
        s.SetFixed(i, fixed);
        touch(fixed ? "pin" : "unpin");
    }
    bool TogglePin(int i)
    {
        Snake &s = selSample(i);
        bool f = !s.Samples()[i].fixed;
        SetFixed(i, f);
        return f;
    }
    /// Inserts a sample after sample i (before it for the last sample of an open snake).
    int InsertSampleAfter(int i)
    {
        Snake &s = selSample(i);
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
        Snake &s = selSample(i);
        if (s.SampleCount() <= (s.Closed() ? 3 : 2))
            throw SnakeError("Geometric snake: cannot delete, the snake would have too few samples.");
        record("delete sample");
        s.DeleteSample(i);
        touch("delete sample");
    }

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

    // ================================================================ status
    double LastOperationMs() const { return lastOpMs; }

private:
    using Base::checkMesh;
    using Base::energy;
    using Base::energyChanged;
    using Base::history;
    using Base::mesh;
    using Base::params;
    using Base::record;
    using Base::seedCost;
    using Base::seedList;
    using Base::selected;
    using Base::snakes;
    using Base::touch;

    double lastOpMs = 0;
    double computeMs = 0;
    // builds new snakes, keeping the seed paths' index across builds; last: its background
    // build ends first
    SnakeBuilder<MeshType> builder{mesh, energy};

    std::unique_ptr<Snake> loopSnake(const std::vector<SurfacePoint> &stroke, const vcg::Point3d &view)
    {
        this->EnsureSurface();
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
    Snake &sel()
    {
        Snake *s = SelectedSnake();
        if (!s) throw SnakeError("Geometric snake: no snake selected (place seeds and close them first).");
        return *s;
    }
    // the selected snake, which has a sample i
    Snake &selSample(int i)
    {
        Snake &s = sel();
        if (i < 0 || i >= s.SampleCount()) throw SnakeError("Geometric snake: no sample " + std::to_string(i) + ".");
        return s;
    }
};

} // namespace tri
} // namespace vcg

#endif