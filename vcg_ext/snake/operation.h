#ifndef VCG_EXT_SNAKE_OPERATION_H
#define VCG_EXT_SNAKE_OPERATION_H

// One snake operation (Sec. 4.3, Fig. 1) and what carries over from one operation to the next:
// the two motions with their caches (kept embeddings, factored spline systems), the run control
// (convergence, energy level, watches: snake/run_control.h) and the samples the last operation
// inserted (SnakeGapRefine). GeometricSnake owns the curve (SnakeCurve) with its undo history,
// seeds and edits, and hands it to this to be moved.

#include <algorithm>
#include <memory>
#include <utility>
#include <vector>

#include <vcg/space/point3.h>

#include <vcg_ext/snake/curve.h>
#include <vcg_ext/snake/gap_refine.h>
#include <vcg_ext/snake/partition.h>
#include <vcg_ext/snake/projection_motion.h>
#include <vcg_ext/snake/run_control.h>
#include <vcg_ext/snake/segment_motion.h>
#include <vcg_ext/surface/snake_surface.h>

namespace vcg {
namespace tri {

template <class MeshType>
class SnakeOperation
{
public:
    typedef SnakeSurface<MeshType> Surface;
    typedef SnakeRunControl<MeshType> RunControl;
    typedef typename RunControl::State RunState;

    /// `surface` may be null here (the snake refuses it); it is not read before an operation.
    explicit SnakeOperation(const std::shared_ptr<Surface> &surface)
        : surf(surface.get()), motion(surface), projection(surface), run(surface.get())
    {
    }

    /// One operation on `st` (Sec. 4.3, Fig. 1): an open snake first gets a sample in every
    /// gap it stretched past twice its spacing (SnakeGapRefine, LastInserted); then partition,
    /// and for every segment build the local region, embed it, map samples and energy
    /// gradients into the plane, do up to `updatesPerOperation` updates of Eq. 4 and map back;
    /// then the overlapping segments across the borders. The run control's verdict goes into
    /// `stats`. Returns the largest sample move in length units (st.unit).
    double Step(SnakeCurve &st, SnakeStats &stats)
    {
        refine(st);
        std::vector<vcg::Point3d> before = Positions(*surf, st);
        run.Begin(st, before);
        if (st.params.method == SnakeMethod::LocalEmbedding) moveSegments(st, stats, st.params.updatesPerOperation);
        else projection.Step(st, stats, frame(st));
        std::vector<vcg::Point3d> after = Positions(*surf, st);
        const double maxMove = RunControl::CurveMove(before, after, st.closed) / st.unit;
        stats.lastMaxMove = maxMove;
        stats.operations++;
        run.End(st, stats, maxMove, after);
        return maxMove;
    }

    /// Retraces every gap of `st` (no motion): one embedding per segment.
    void Retrace(SnakeCurve &st, SnakeStats &stats) { moveSegments(st, stats, 0); }

    /// A new run (samples placed anew or edited, see SnakeRunControl::Reset for keepLevel):
    /// the regions are built around the samples where they are now.
    void Reset(bool keepLevel)
    {
        motion.ForgetEmbeddings();
        run.Reset(keepLevel);
    }
    /// The motions' caches (embeddings, spline systems) are of the snake before a change.
    void ClearCaches()
    {
        motion.ClearCache();
        projection.ClearCache();
    }

    /// The run control's parameters (SnakeRunControl::Param: the stall test).
    typename RunControl::Param &RunParam() { return run.GetParam(); }

    /// The level of the energy pyramid the next operation slithers on (SnakeRunControl::Level).
    int Level() const { return run.Level(); }
    const RunState &GetRunState() const { return run.Get(); }
    void SetRunState(const RunState &s) { run.Set(s); }

    /// The samples the last operation inserted, their indices now, ascending.
    const std::vector<int> &LastInserted() const { return inserted; }
    /// Where sample i before the last operation is now; -1 stays -1.
    int Follow(int i) const { return Refine::Follow(i, inserted); }
    /// Any other change to the curve ends what the last operation inserted.
    void ForgetInserted() { inserted.clear(); }

    /// The samples' positions in space.
    static std::vector<vcg::Point3d> Positions(const Surface &surf, const SnakeCurve &st)
    {
        std::vector<vcg::Point3d> p;
        p.reserve(st.samples.size());
        for (const auto &s : st.samples) p.push_back(s.p.Pd(surf.Mesh()));
        return p;
    }

    /// +1 when the closed curve runs counter-clockwise seen from the front of the surface it
    /// encloses (its vector area agrees with the normals of the faces under it), else -1.
    static double Orientation(const Surface &surf, const SnakeCurve &st)
    {
        std::vector<vcg::Point3d> p = Positions(surf, st);
        vcg::Point3d area(0, 0, 0), normal(0, 0, 0), c(0, 0, 0);
        for (const auto &x : p) c += x;
        c /= double(p.size());
        for (size_t i = 0; i < p.size(); ++i) area += (p[i] - c) ^ (p[(i + 1) % p.size()] - c);
        for (const auto &s : st.samples) normal += surf.FaceNormal(s.p.face);
        return area * normal >= 0 ? 1.0 : -1.0;
    }

    /// Closed curves: per sample, the unit direction on the surface towards the inside of the
    /// loop, the side it runs round counter-clockwise seen from the front of the faces under it
    /// (Orientation: the side a negative balloon deflates it to). Empty for open curves.
    static std::vector<vcg::Point3d> InsideDirections(const Surface &surf, const SnakeCurve &st)
    {
        const int n = int(st.samples.size());
        if (!st.closed || n < 3) return {};
        const std::vector<vcg::Point3d> p = Positions(surf, st);
        const double o = Orientation(surf, st);
        std::vector<vcg::Point3d> in(n);
        for (int i = 0; i < n; ++i) {
            in[i] = (surf.FaceNormal(st.samples[i].p.face) ^ (p[(i + 1) % n] - p[(i - 1 + n) % n])) * o; // -(tangent x normal)
            const double l = in[i].Norm();
            in[i] = l > 0 ? in[i] / l : vcg::Point3d(0, 0, 0);
        }
        return in;
    }

private:
    typedef SnakeGapRefine<MeshType> Refine;

    const Surface *surf;
    SnakeSegmentMotion<MeshType> motion;
    SnakeProjectionMotion<MeshType> projection;
    RunControl run;
    std::vector<int> inserted; // by the last operation (LastInserted)

    /// Before an operation: an open snake that lengthened gets samples in its long gaps
    /// (SnakeGapRefine inserts none into a closed one); the kept embeddings and the
    /// convergence test follow them.
    void refine(SnakeCurve &st)
    {
        const int before = int(st.samples.size());
        inserted = Refine::Refine(*surf, st);
        if (inserted.empty()) return;
        motion.SamplesInserted(inserted, before);
        run.SamplesInserted(inserted);
    }

    SnakeMotionFrame frame(const SnakeCurve &st) const
    {
        SnakeMotionFrame f;
        f.level = run.Level();
        f.unit = st.unit;
        // a coarse level's slopes are gentler by its reach: scale its force back up
        const double reach = surf->EnergyField().Reach(f.level);
        if (reach > 0 && st.unit > 0) f.gain = std::min(16.0, std::max(1.0, reach / st.unit));
        if (st.closed && st.params.balloon != 0) f.outside = Orientation(*surf, st);
        return f;
    }

    // ----- partitioning (Sec. 5.1): snake/partition.h, checked before any sample moves
    std::vector<SnakeSegment> partition(const SnakeCurve &st, std::vector<SnakeSegment> &overlaps) const
    {
        const int n = int(st.samples.size());
        SnakePartition::Result r = SnakePartition::Compute(n, st.closed, st.params.segmentSamples,
                                                           SnakePartition::Corners(Positions(*surf, st), st.closed));
        SnakePartition::Check(r, n, st.closed);
        overlaps = std::move(r.overlaps);
        return std::move(r.segments);
    }

    // ----- the embedding method (Sec. 5.2 - 5.4): every segment, then the overlapping ones
    // across the borders, each with `updates` updates of Eq. 4 (0: its gaps only retraced)
    void moveSegments(SnakeCurve &st, SnakeStats &stats, int updates)
    {
        std::vector<SnakeSegment> overlaps;
        std::vector<SnakeSegment> segs = partition(st, overlaps);
        motion.BeginOperation();
        // the frame per segment: the balloon's side (Orientation) follows what the segments
        // before moved (once per operation changed 11 of 36 runs of gs_parts --balloon 0.5)
        for (auto &s : segs) motion.Move(st, stats, s, updates, frame(st));
        for (auto &s : overlaps) motion.Move(st, stats, s, updates, frame(st));
    }
};

} // namespace tri
} // namespace vcg

#endif
