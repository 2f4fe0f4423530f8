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
#include <vcg_ext/snake/partition.h>
#include <vcg_ext/snake/polyline.h>
#include <vcg_ext/snake/projection_motion.h>
#include <vcg_ext/snake/run_control.h>
#include <vcg_ext/snake/segment_motion.h>
#include <vcg_ext/surface/snake_surface.h>
#include <vcg_ext/surface/surface_point.h>

namespace vcg {
namespace tri {

/// A geometric snake on a triangle mesh (Lee & Lee 2002), with the session API used by the
/// batch filter and by the edit tool: create, step, run, edit points, pin, insert, delete,
/// change parameters, undo and redo. Samples are surface points (face + barycentric); a
/// snake never leaves the surface and never loses its pins.
template <class MeshType>
class GeometricSnake
{
public:
    typedef typename MeshType::FaceType FaceType;
    typedef typename MeshType::VertexType VertexType;
    typedef SnakeSurface<MeshType> Surface;

    typedef SnakeGap Gap;

    GeometricSnake(std::shared_ptr<Surface> surface, const SnakeParams &params = SnakeParams())
        : surf(std::move(surface)), motion(surf), projection(surf), run(surf.get())
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
    bool KeepPolyline(const std::vector<SurfacePoint> &polyline)
    {
        const int n = int(st.samples.size()), gaps = numGaps();
        auto isSample = [&](const SurfacePoint &p, int i) {
            const SurfacePoint &s = st.samples[i % n].p;
            return p.face == s.face && (p.bary - s.bary).Norm() <= 1e-9;
        };
        if (n < 2 || polyline.empty() || !isSample(polyline[0], 0)) return false;
        for (const auto &p : polyline)
            if (!p.OnMesh(surf->Mesh())) return false;
        std::vector<std::vector<SurfacePoint>> crossings(gaps);
        size_t at = 0;
        for (int g = 0; g < gaps; ++g) {
            const bool last = st.closed && g == n - 1; // runs to the polyline's end
            size_t next = at + 1;
            while (next < polyline.size() && !(!last && isSample(polyline[next], g + 1))) ++next;
            if (!last && next == polyline.size()) return false;
            crossings[g].assign(polyline.begin() + at + 1, polyline.begin() + next);
            at = next;
        }
        if (!st.closed && at + 1 != polyline.size()) return false;
        for (int g = 0; g < gaps; ++g) {
            Gap &gap = st.gaps[g];
            gap = Gap();
            gap.crossings = crossings[g];
            gap.traced = true; // as read: no tightening (gap.faces empty: the motion finds them)
            gap.tracedFrom = st.samples[g].p;
            gap.tracedTo = st.samples[(g + 1) % n].p;
        }
        return true;
    }

    // ----------------------------------------------------------------- motion
    /// One snake operation (Sec. 4.3, Fig. 1): partition, then for every segment build the
    /// local region, embed it, map samples and energy gradients into the plane, do up to
    /// `updatesPerOperation` updates of Eq. 4 and map back; then the overlapping segments
    /// across the borders. An open snake first gets a sample in every gap it stretched past
    /// twice its spacing (SnakeGapRefine, LastInserted). Returns the largest sample move in
    /// local length units (LengthScale()).
    double Step()
    {
        if (st.samples.empty()) throw SnakeError("Geometric snake: the snake has no samples.");
        if (!surf->MatchesMesh()) throw SnakeError("Geometric snake: the mesh changed since the snake was created.");
        pushUndo();
        auto t0 = SnakeClock::Now();
        refine();
        std::vector<vcg::Point3d> before = positions();
        run.Begin(st, before);
        if (st.params.method == SnakeMethod::LocalEmbedding) stepEmbedding();
        else projection.Step(st, stats, frame());
        std::vector<vcg::Point3d> after = positions();
        const double maxMove = RunControl::CurveMove(before, after, st.closed) / st.unit;
        stats.lastMaxMove = maxMove;
        stats.operations++;
        run.End(st, stats, maxMove, after);
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
        clearCaches();
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
        inserted.clear();
        clearCaches();
        resetRun();
        return true;
    }
    bool Redo()
    {
        if (!history.Redo(st)) return false;
        inserted.clear();
        clearCaches();
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
    /// The level of the energy pyramid the snake slithers on: the coarsest while capturing,
    /// one finer each time its samples sit in wells of the current one, 0 (precise) to settle.
    int EnergyStage() const { return run.Level(); }
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
    const std::vector<int> &LastInserted() const { return inserted; }
    /// Where sample i before the last operation is now (a host holding a sample index, the one
    /// being dragged or edited, follows it); -1 stays -1.
    int FollowSample(int i) const { return Refine::Follow(i, inserted); }

    /// Closed snakes: per sample, the unit direction on the surface towards the inside of the
    /// loop (the side a negative Balloon deflates it to; a positive one pushes it away from it),
    /// for the tool to show. The inside is the side the loop runs round counter-clockwise, seen
    /// from the front of the faces under it (orientation()). Empty for open snakes.
    std::vector<vcg::Point3d> InsideDirections() const
    {
        const int n = int(st.samples.size());
        if (!st.closed || n < 3) return {};
        const std::vector<vcg::Point3d> p = positions();
        const double o = orientation();
        std::vector<vcg::Point3d> in(n);
        for (int i = 0; i < n; ++i) {
            in[i] = (surf->FaceNormal(st.samples[i].p.face) ^ (p[(i + 1) % n] - p[(i - 1 + n) % n])) * o; // -(tangent x normal)
            const double l = in[i].Norm();
            in[i] = l > 0 ? in[i] / l : vcg::Point3d(0, 0, 0);
        }
        return in;
    }

    std::vector<vcg::Point3d> positions() const
    {
        std::vector<vcg::Point3d> p;
        p.reserve(st.samples.size());
        for (const auto &s : st.samples) p.push_back(s.p.Pd(surf->Mesh()));
        return p;
    }

    /// The curve on the surface (Sec. 4.1): the samples and, between them, the points where
    /// the straight segment in the embedding crosses mesh edges. Closed curves do not repeat
    /// the first point. Untraced gaps are traced first.
    std::vector<SurfacePoint> Polyline()
    {
        if (!Line::Traced(st) && st.samples.size() >= 2) retrace();
        return Line::Points(*surf, st);
    }

    std::vector<vcg::Point3d> PolylinePositions() { return Line::Positions(*surf, Polyline()); }

private:
    // the motions' caches (embeddings, spline systems) are of the snake before a change
    void clearCaches()
    {
        motion.ClearCache();
        projection.ClearCache();
    }
    typedef SnakeSegment Segment;
    typedef SnakeRunControl<MeshType> RunControl;
    typedef SnakePolyline<MeshType> Line; // the curve between the samples: the gaps
    typedef SnakeGapRefine<MeshType> Refine;

    std::shared_ptr<Surface> surf;
    SnakeSegmentMotion<MeshType> motion;
    SnakeProjectionMotion<MeshType> projection;
    SnakeCurve st;
    SnakeHistory<SnakeCurve> history;
    SnakeStats stats;
    std::vector<int> seedVertices;
    std::vector<SurfacePoint> seedPoints;
    std::vector<SnakeSample> initialSamples;
    std::vector<SurfacePoint> initialPolyline;
    RunControl run;
    std::vector<int> inserted; // by the last operation (LastInserted)

public:
    /// Everything a user sees of the snake (curve, pins, parameters, counters, convergence),
    /// for an undo history kept outside the snake (vcg_ext/session/undo.h, SnakeController).
    struct Memento
    {
        decltype(st) curve;
        SnakeStats stats;
        typename RunControl::State run;
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
        return Memento{st, stats, run.Get(), seedVertices, seedPoints, initialSamples, initialPolyline};
    }
    void Restore(const Memento &m)
    {
        st = m.curve;
        stats = m.stats;
        run.Set(m.run);
        seedVertices = m.seeds;
        seedPoints = m.seedPoints;
        initialSamples = m.initialSamples;
        initialPolyline = m.initialPolyline;
        inserted.clear();
        clearCaches();
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
        inserted.clear(); // every change ends what the last operation inserted
    }

    /// Before an operation: an open snake that lengthened gets samples in its long gaps
    /// (SnakeGapRefine); the kept embeddings and the convergence test follow them.
    void refine()
    {
        const int before = int(st.samples.size());
        inserted = Refine::Refine(*surf, st);
        if (inserted.empty()) return;
        motion.SamplesInserted(inserted, before, st.closed);
        run.SamplesInserted(inserted);
    }

    SnakeMotionFrame frame() const
    {
        SnakeMotionFrame f;
        f.level = run.Level();
        f.unit = st.unit;
        // a coarse level's slopes are gentler by its reach: scale its force back up
        const double reach = surf->EnergyField().Reach(f.level);
        if (reach > 0 && st.unit > 0) f.gain = std::min(16.0, std::max(1.0, reach / st.unit));
        if (st.closed && st.params.balloon != 0) f.outside = orientation();
        return f;
    }

    /// +1 when the closed curve runs counter-clockwise seen from the front of the surface it
    /// encloses (its vector area agrees with the normals of the faces under it), else -1.
    double orientation() const
    {
        std::vector<vcg::Point3d> p = positions();
        vcg::Point3d area(0, 0, 0), normal(0, 0, 0), c(0, 0, 0);
        for (const auto &x : p) c += x;
        c /= double(p.size());
        for (size_t i = 0; i < p.size(); ++i) area += (p[i] - c) ^ (p[(i + 1) % p.size()] - c);
        for (const auto &s : st.samples) normal += surf->FaceNormal(s.p.face);
        return area * normal >= 0 ? 1.0 : -1.0;
    }

    /// keepLevel: a point edit (Sec. 5.5), the run goes on on the energy level it had reached
    /// (SnakeRunControl::Reset).
    void resetRun(bool keepLevel = false)
    {
        motion.ForgetEmbeddings(); // samples were placed anew: regions are built around them
        for (auto &smp : st.samples) {
            smp.trust = 1.0;
            smp.heldFine = false;
        }
        run.Reset(keepLevel);
        stats.converged = false;
        stats.stopped = false;
        stats.stop = SnakeStop::Running;
        stats.stopMessage.clear();
    }
    // ----- partitioning (Sec. 5.1): snake/partition.h, checked before any sample moves
    std::vector<Segment> partition(std::vector<Segment> &overlaps) const
    {
        const int n = int(st.samples.size());
        SnakePartition::Result r =
            SnakePartition::Compute(n, st.closed, st.params.segmentSamples, SnakePartition::Corners(positions(), st.closed));
        SnakePartition::Check(r, n, st.closed);
        overlaps = std::move(r.overlaps);
        return std::move(r.segments);
    }

    // ----- the embedding method (Sec. 5.2 - 5.4)
    void stepEmbedding()
    {
        std::vector<Segment> overlaps;
        std::vector<Segment> segs = partition(overlaps);
        motion.BeginOperation();
        for (auto &s : segs) motion.Move(st, stats, s, st.params.updatesPerOperation, frame());
        for (auto &s : overlaps) motion.Move(st, stats, s, st.params.updatesPerOperation, frame());
    }

    /// Retraces every gap (no motion): one embedding per segment.
    void retrace()
    {
        std::vector<Segment> overlaps;
        std::vector<Segment> segs = partition(overlaps);
        motion.BeginOperation();
        for (auto &s : segs) motion.Move(st, stats, s, 0, frame());
        for (auto &s : overlaps) motion.Move(st, stats, s, 0, frame());
    }
};

} // namespace tri
} // namespace vcg

#endif
