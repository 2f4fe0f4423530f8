#ifndef VCG_EXT_GEOMETRIC_SNAKE_H
#define VCG_EXT_GEOMETRIC_SNAKE_H

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <vcg/space/point3.h>

#include <vcg_ext/paths/initial_curve.h>
#include <vcg_ext/paths/seed_path.h>
#include <vcg_ext/session/history.h>
#include <vcg_ext/snake/curve.h>
#include <vcg_ext/snake/error.h>
#include <vcg_ext/snake/gap_refine.h>
#include <vcg_ext/snake/polyline.h>
#include <vcg_ext/snake/run_control.h>
#include <vcg_ext/snake/operation.h>
#include <vcg_ext/surface/snake_surface.h>
#include <vcg_ext/surface/surface_point.h>

namespace vcg {
namespace tri {

/// A geometric snake on a triangle mesh (Lee & Lee 2002), with the session API used by the
/// batch filter and by the edit tool: create, step, run, edit points, pin, insert, delete,
/// change parameters, undo and redo. Samples are surface points (face + barycentric); a
/// snake never leaves the surface and never loses its pins. The operations that move it are
/// SnakeOperation's (snake/operation.h); this keeps the curve, its history and edits.
template <class MeshType>
class GeometricSnake
{
public:
    typedef typename MeshType::FaceType FaceType;
    typedef typename MeshType::VertexType VertexType;
    typedef SnakeSurface<MeshType> Surface;

    typedef SnakeGap Gap;

    GeometricSnake(std::shared_ptr<Surface> surface, const SnakeParams &params = SnakeParams())
        : surf(std::move(surface)), op(surf)
    {
        if (!surf) throw SnakeError("Geometric snake: no surface.");
        params.Validate();
        st.params = params;
    }

    // ----------------------------------------------------------------- creation
    /// Section 5.5: seeds (vertex indices) joined by shortest edge paths, then samples taken
    /// along the path at uniform spacing (Sec. 7).
    /// `lengthScale`: the snake's length unit (see LengthScale()); 0 = from the path's edges.
    void InitFromSeeds(const std::vector<int> &seeds, bool closed, SeedPathCost cost = SeedPathCost::Length,
                       double lengthScale = 0)
    {
        typename SeedPath<MeshType>::Result path = SeedPath<MeshType>::Compute(surf->Mesh(), seeds, closed, cost);
        InitFromPath(path.vertices, closed, lengthScale);
        seedVertices = seeds;
        seedPoints.clear();
        for (int v : seeds) seedPoints.push_back(surf->VertexPoint(v));
    }

    /// Samples along a vertex path (consecutive vertices share an edge). Closed paths do not
    /// repeat the first vertex (SnakeInitialCurve).
    void InitFromPath(const std::vector<int> &pathVerts, bool closed, double lengthScale = 0)
    {
        setInitial(Initial::FromVertexPath(*surf, pathVerts, closed, st.params.spacing, lengthScale), closed);
    }

    /// Seeds given as surface points (face + barycentric, e.g. snapped from coordinates or a
    /// Pick Points file): the curve starts and ends exactly at them (SeedPath::ComputeFromPoints).
    /// `lengthScale`: the snake's length unit (see LengthScale()); 0 = from the path's faces.
    /// `index`: the mesh's SeedPath::MeshIndex, if the caller keeps one (else built here).
    void InitFromSeedPoints(const std::vector<SurfacePoint> &seeds, bool closed, SeedPathCost cost = SeedPathCost::Length,
                            double lengthScale = 0, const typename SeedPath<MeshType>::MeshIndex *index = nullptr)
    {
        typename SeedPath<MeshType>::PointResult path =
            SeedPath<MeshType>::ComputeFromPoints(surf->Mesh(), seeds, closed, cost, 0.05, index);
        InitFromSurfacePath(path.points, closed, lengthScale);
        seedVertices.clear();
        seedPoints.clear();
        for (int i : path.seedPositions) seedPoints.push_back(path.points[i]);
    }

    /// Samples at uniform spacing along a polyline of surface points in which consecutive
    /// points share a face (closed: the first point is not repeated). `lengthScale`: the
    /// snake's length unit; 0 = the median edge of the faces the path crosses.
    void InitFromSurfacePath(const std::vector<SurfacePoint> &pathPts, bool closed, double lengthScale = 0)
    {
        setInitial(Initial::FromSurfacePath(*surf, pathPts, closed, st.params.spacing, lengthScale), closed);
    }

    /// Restores samples (e.g. from JSON). Gaps are re-projected on the next operation.
    /// `lengthScale`: the snake's length unit (LengthScale()); 0 = the median edge length of
    /// the samples' faces.
    void InitFromSamples(const std::vector<SnakeSample> &samples, bool closed, double lengthScale = 0)
    {
        if (int(samples.size()) < (closed ? 3 : 2)) throw SnakeError("Geometric snake: too few samples.");
        if (long(samples.size()) > Initial::MaxSamples())
            throw SnakeError("Geometric snake: " + std::to_string(samples.size()) + " samples are too many (at most " +
                             std::to_string(Initial::MaxSamples()) + ").");
        for (const auto &s : samples) checkPoint(s.p);
        if (!(lengthScale > 0) || !std::isfinite(lengthScale)) lengthScale = Initial::UnitOf(*surf, samples);
        pushUndo();
        st.samples = samples;
        st.closed = closed;
        st.unit = lengthScale;
        st.gaps.assign(numGaps(), Gap());
        st.builtSpacing = Refine::MedianGap(*surf, st);
        if (initialSamples.empty()) {
            initialSamples = st.samples;
            initialPolyline = Polyline();
        }
        resetRun();
    }

    /// Takes `polyline` (the samples in order and the crossings between them, as Polyline()
    /// gives) as the traced curve instead of tracing the gaps anew: a snake moved onto a cut
    /// mesh (cut/cut_session_map.h) keeps the curve that was embedded, which a new trace on the
    /// split faces only approximates. Returns false, changing nothing, when the polyline does
    /// not run through the samples in order or is not on the mesh.
    bool KeepPolyline(const std::vector<SurfacePoint> &polyline) { return Line::Keep(*surf, st, polyline); }

    // ----------------------------------------------------------------- motion
    /// One snake operation (Sec. 4.3, Fig. 1: SnakeOperation::Step; an open snake first gets
    /// a sample in every gap it stretched past twice its spacing, LastInserted). Returns the
    /// largest sample move in local length units (LengthScale()).
    double Step()
    {
        if (st.samples.empty()) throw SnakeError("Geometric snake: the snake has no samples.");
        if (!surf->MatchesMesh()) throw SnakeError("Geometric snake: the mesh changed since the snake was created.");
        pushUndo();
        auto t0 = SnakeClock::Now();
        const double maxMove = op.Step(st, stats);
        // the operation's time includes the convergence and well tests (issue 12: they are
        // part of what one operation costs)
        double ms = SnakeClock::MsSince(t0);
        stats.msOperation.push_back(ms);
        stats.secondsTotal += ms / 1000.0;
        return maxMove;
    }

    /// Operations until converged or `maxOperations`. `progress(op)` may return false to stop.
    bool Run(int maxOperations, const std::function<bool(int)> &progress = nullptr)
    {
        if (maxOperations < 0 || maxOperations > 10000000) throw SnakeError("Geometric snake: absurd operation limit.");
        SnakeRunLimits lim;
        lim.maxOperations = maxOperations;
        return Run(lim, progress) == SnakeStop::Converged;
    }

    /// Operations until the run ends (snake/stop.h): converged, stopped by the engine (a closed
    /// snake collapsing or leaving its part), a limit reached, or `progress(op)` returned false.
    /// The reason and its message are also in Stats().stop / stopMessage (EndRun).
    SnakeStop Run(const SnakeRunLimits &lim, const std::function<bool(int)> &progress = nullptr)
    {
        lim.Validate();
        pushUndo();
        bool keep = history.Suspend(true); // one undo step for the whole run
        const auto t0 = SnakeClock::Now();
        int ops = 0;
        SnakeStop why;
        // a snake that ended its last run on its own (converged, stopped) is not moved again
        while ((why = lim.Check(stats.stop, ops, SnakeClock::MsSince(t0) / 1000)) == SnakeStop::Running) {
            Step();
            ++ops;
            if (progress && !progress(ops - 1)) { // cancelled, unless the operation ended the run anyway
                why = lim.Check(stats.stop, 0, 0);
                if (why == SnakeStop::Running) why = SnakeStop::Cancelled;
                break;
            }
        }
        history.Suspend(keep);
        EndRun(why, lim.Message(why, ops, SnakeClock::MsSince(t0) / 1000));
        return why;
    }

    /// Records how a run driven from outside (the edit tool's time-sliced Run) ended: the
    /// reason, and for a limit or a cancel its message (the engine's own reasons keep theirs).
    /// A limit reached goes into the warnings too, as a collapse does.
    void EndRun(SnakeStop why, const std::string &message = std::string())
    {
        if (why == SnakeStop::Running || why == stats.stop) return;
        stats.stop = why;
        stats.stopMessage = !message.empty() ? message : why == SnakeStop::Cancelled ? "stopped by the user" : "";
        if (SnakeStopIsProblem(why) && stats.warnings.size() < 20) stats.warnings.push_back(stats.stopMessage);
    }

    /// Replaces a closed snake's curve by a loop of mesh vertices (each next to the previous
    /// one), resampled at the snake's spacing, as the last part of the run that placed it
    /// (snake/valley_loop.h): the run's end, its statistics, its undo step (the state before
    /// the run) and the snake's initial curve are kept.
    void SetClosedVertexLoop(const std::vector<int> &loop)
    {
        if (!st.closed || loop.size() < 3) throw SnakeError("Geometric snake: a loop of vertices needs a closed snake.");
        const SnakeStats keepStats = stats;
        typename Initial::Result r = Initial::FromVertexPath(*surf, loop, true, st.params.spacing, st.unit);
        st.samples = std::move(r.samples);
        st.gaps = std::move(r.gaps);
        resetRun();
        stats = keepStats;
    }

    // ----------------------------------------------------------------- editing (Sec. 5.5)
    /// Point editing: moves sample i; its neighbours follow through the spline energy.
    /// The region of the next operation is enlarged by the projection of the segments to
    /// the neighbours (Sec. 5.2, Fig. 4).
    void MoveSample(int i, const SurfacePoint &p, bool fix = false)
    {
        checkIndex(i);
        checkPoint(p);
        pushUndo();
        st.samples[i].p = p;
        st.samples[i].p.Normalize();
        if (fix) st.samples[i].fixed = true;
        Line::InvalidateAround(st, i);
        resetRun(true);
    }

    /// Point fixing.
    void SetFixed(int i, bool fixed)
    {
        checkIndex(i);
        pushUndo();
        st.samples[i].fixed = fixed;
        resetRun(true);
    }

    /// Inserts a sample in the middle of gap i (between samples i and i+1); returns its index.
    int InsertSample(int gap)
    {
        if (gap < 0 || gap >= numGaps()) throw SnakeError("Geometric snake: no gap " + std::to_string(gap) + ".");
        const SurfacePoint mid = Line::GapMiddle(*surf, st, gap);
        pushUndo();
        SnakeSample s;
        s.p = mid;
        st.samples.insert(st.samples.begin() + gap + 1, s);
        Line::SplitGap(st, gap);
        resetRun(true);
        return gap + 1;
    }

    void DeleteSample(int i)
    {
        checkIndex(i);
        if (int(st.samples.size()) <= (st.closed ? 3 : 2))
            throw SnakeError("Geometric snake: cannot delete, the snake would have too few samples.");
        pushUndo();
        st.samples.erase(st.samples.begin() + i);
        Line::MergeGaps(st, i);
        resetRun(true);
    }

    void SetParams(const SnakeParams &p)
    {
        p.Validate();
        pushUndo();
        st.params = p;
        op.ClearCaches();
        resetRun();
    }

    /// The surface's energy was replaced (another energy type or smoothing): start afresh.
    void EnergyChanged() { resetRun(); }

    // ----------------------------------------------------------------- undo / redo
    bool CanUndo() const { return history.CanUndo(); }
    bool CanRedo() const { return history.CanRedo(); }
    bool Undo()
    {
        if (!history.Undo(st)) return false;
        op.ForgetInserted();
        op.ClearCaches();
        resetRun();
        return true;
    }
    bool Redo()
    {
        if (!history.Redo(st)) return false;
        op.ForgetInserted();
        op.ClearCaches();
        resetRun();
        return true;
    }

    // ----------------------------------------------------------------- access
    const std::vector<SnakeSample> &Samples() const { return st.samples; }
    int SampleCount() const { return int(st.samples.size()); }
    bool Closed() const { return st.closed; }
    const SnakeParams &Params() const { return st.params; }
    /// The snake's length unit: spacing, step caps and tolerances are measured in it. The
    /// median edge length of its seed path (a local scale: meshes mix sizes).
    double LengthScale() const { return st.unit; }
    const SnakeStats &Stats() const { return stats; }
    bool Converged() const { return stats.converged; }
    /// The run control's parameters (SnakeRunControl::Param: the stall test, session 29); not
    /// saved, not undone.
    typename SnakeRunControl<MeshType>::Param &RunParam() { return op.RunParam(); }
    /// The level of the energy pyramid the snake slithers on: the coarsest while capturing,
    /// one finer each time its samples sit in wells of the current one, 0 (precise) to settle.
    int EnergyStage() const { return op.Level(); }
    Surface &GetSurface() { return *surf; }
    std::shared_ptr<Surface> SurfacePtr() const { return surf; }
    const std::vector<int> &SeedVertices() const { return seedVertices; }
    /// The seeds as surface points (for vertex seeds: the vertex, in one of its faces).
    const std::vector<SurfacePoint> &SeedPoints() const { return seedPoints; }
    const std::vector<SnakeSample> &InitialSamples() const { return initialSamples; }
    const std::vector<SurfacePoint> &InitialPolyline() const { return initialPolyline; }
    /// The traced gaps; their crossings are the shortest path through their faces only once
    /// Polyline() has been read since the last operation (the motion reads their faces).
    const std::vector<Gap> &Gaps() const { return st.gaps; }
    /// The samples the last operation inserted (SnakeGapRefine: an open snake that lengthens
    /// keeps its density), their indices now, ascending; empty after any other change.
    const std::vector<int> &LastInserted() const { return op.LastInserted(); }
    /// Where sample i before the last operation is now (a host holding a sample index, the one
    /// being dragged or edited, follows it); -1 stays -1.
    int FollowSample(int i) const { return op.Follow(i); }

    /// Closed snakes: per sample, the unit direction on the surface towards the inside of the
    /// loop (the side a negative Balloon deflates it to; a positive one pushes it away from it),
    /// for the tool to show (SnakeOperation::InsideDirections). Empty for open snakes.
    std::vector<vcg::Point3d> InsideDirections() const { return Operation::InsideDirections(*surf, st); }

    std::vector<vcg::Point3d> positions() const { return Operation::Positions(*surf, st); }

    /// The curve on the surface (Sec. 4.1): the samples and, between them, the points where
    /// the straight segment in the embedding crosses mesh edges. Closed curves do not repeat
    /// the first point. Untraced gaps are traced first.
    std::vector<SurfacePoint> Polyline()
    {
        if (!Line::Traced(st) && st.samples.size() >= 2) op.Retrace(st, stats);
        return Line::Points(*surf, st);
    }

    std::vector<vcg::Point3d> PolylinePositions() { return Line::Positions(*surf, Polyline()); }

private:
    typedef SnakeOperation<MeshType> Operation;
    typedef SnakePolyline<MeshType> Line; // the curve between the samples: the gaps
    typedef SnakeGapRefine<MeshType> Refine;

    std::shared_ptr<Surface> surf;
    Operation op; // moves the curve; keeps the motions' caches and the run control
    SnakeCurve st;
    SnakeHistory<SnakeCurve> history;
    SnakeStats stats;
    std::vector<int> seedVertices;
    std::vector<SurfacePoint> seedPoints;
    std::vector<SnakeSample> initialSamples;
    std::vector<SurfacePoint> initialPolyline;

public:
    /// Everything a user sees of the snake (curve, pins, parameters, counters, convergence),
    /// for an undo history kept outside the snake (vcg_ext/session/undo.h, SnakeController).
    struct Memento
    {
        decltype(st) curve;
        SnakeStats stats;
        typename Operation::RunState run;
        std::vector<int> seeds;
        std::vector<SurfacePoint> seedPoints;
        std::vector<SnakeSample> initialSamples;
        std::vector<SurfacePoint> initialPolyline;

        /// The memory it holds (the undo history is bounded by memory).
        size_t Bytes() const
        {
            size_t b = sizeof(*this) + curve.samples.capacity() * sizeof(SnakeSample) +
                       initialSamples.capacity() * sizeof(SnakeSample) +
                       (initialPolyline.capacity() + seedPoints.capacity()) * sizeof(SurfacePoint) +
                       seeds.capacity() * sizeof(int) + run.Bytes();
            for (const auto &g : curve.gaps)
                b += sizeof(g) + g.faces.capacity() * sizeof(int) + g.crossings.capacity() * sizeof(SurfacePoint);
            b += (stats.msEmbedding.capacity() + stats.msUpdate.capacity() + stats.msOperation.capacity()) * sizeof(double);
            return b;
        }
    };
    Memento Save() const
    {
        return Memento{st, stats, op.GetRunState(), seedVertices, seedPoints, initialSamples, initialPolyline};
    }
    void Restore(const Memento &m)
    {
        st = m.curve;
        stats = m.stats;
        op.SetRunState(m.run);
        seedVertices = m.seeds;
        seedPoints = m.seedPoints;
        initialSamples = m.initialSamples;
        initialPolyline = m.initialPolyline;
        op.ForgetInserted();
        op.ClearCaches();
    }

private:

    typedef SnakeInitialCurve<MeshType> Initial;
    // a new curve (Sec. 5.5, 7): the initial one of the snake, its gaps traced
    void setInitial(typename Initial::Result r, bool closed)
    {
        pushUndo();
        st.samples = std::move(r.samples);
        st.gaps = std::move(r.gaps);
        st.closed = closed;
        st.unit = r.unit;
        st.builtSpacing = Refine::MedianGap(*surf, st);
        initialSamples = st.samples;
        initialPolyline = Polyline();
        resetRun();
    }
    int numGaps() const { return st.NumGaps(); }
    void checkIndex(int i) const
    {
        if (i < 0 || i >= int(st.samples.size()))
            throw SnakeError("Geometric snake: no sample " + std::to_string(i) + " (the snake has " +
                             std::to_string(st.samples.size()) + ").");
    }
    void checkPoint(const SurfacePoint &p) const { Initial::CheckPoint(*surf, p); }
    void pushUndo()
    {
        history.Push(st);
        op.ForgetInserted(); // every change ends what the last operation inserted
    }

    /// keepLevel: a point edit (Sec. 5.5), the run goes on on the energy level it had reached
    /// (SnakeRunControl::Reset).
    void resetRun(bool keepLevel = false)
    {
        op.Reset(keepLevel); // samples were placed anew: regions are built around them
        for (auto &smp : st.samples) {
            smp.trust = 1.0;
            smp.heldFine = false;
        }
        stats.converged = false;
        stats.stopped = false;
        stats.stop = SnakeStop::Running;
        stats.stopMessage.clear();
    }
};

} // namespace tri
} // namespace vcg

#endif
