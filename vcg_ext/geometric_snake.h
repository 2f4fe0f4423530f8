#ifndef VCG_EXT_GEOMETRIC_SNAKE_H
#define VCG_EXT_GEOMETRIC_SNAKE_H

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <deque>
#include <functional>
#include <map>
#include <numeric>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include <Eigen/Dense>

#include <vcg_ext/face_path.h>
#include <vcg_ext/path_tighten.h>
#include <vcg_ext/seed_path.h>
#include <vcg_ext/snake_curve.h>
#include <vcg_ext/snake_error.h>
#include <vcg_ext/snake_history.h>
#include <vcg_ext/snake_partition.h>
#include <vcg_ext/snake_segment_motion.h>
#include <vcg_ext/snake_surface.h>
#include <vcg_ext/surface_point.h>
#include <vcg_ext/surface_projection.h>

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
        : surf(std::move(surface)), motion(surf)
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
        for (int v : seeds) seedPoints.push_back(vertexPoint(v));
    }

    /// Samples along a vertex path (consecutive vertices share an edge). Closed paths do not
    /// repeat the first vertex.
    void InitFromPath(const std::vector<int> &pathVerts, bool closed, double lengthScale = 0)
    {
        MeshType &m = surf->Mesh();
        std::vector<int> pv = pathVerts;
        if (closed) pv.push_back(pv.front());
        if (pv.size() < 2) throw SnakeError("Geometric snake: the seed path is too short.");
        for (int v : pv)
            if (v < 0 || v >= int(m.vert.size()) || m.vert[v].IsD())
                throw SnakeError("Geometric snake: the seed path has an invalid vertex.");
        std::vector<double> cum(pv.size(), 0.0);
        for (size_t i = 1; i < pv.size(); ++i) cum[i] = cum[i - 1] + dist(pv[i - 1], pv[i]);
        double L = cum.back();
        // The snake's length unit: the median edge length along its seed path, so that one
        // set of parameters fits meshes whose edge lengths vary by 10-100x.
        std::vector<double> pathEdges;
        for (size_t i = 1; i < pv.size(); ++i) pathEdges.push_back(cum[i] - cum[i - 1]);
        const double unit = (lengthScale > 0 && std::isfinite(lengthScale)) ? lengthScale : medianPositive(pathEdges);
        double d = st.params.spacing * unit;
        if (!(L > 1e-9 * surf->MeanEdge())) throw SnakeError("Geometric snake: the seed path has zero length.");
        long n = closed ? std::lround(L / d) : std::lround(L / d) + 1;
        n = std::max<long>(n, closed ? 3 : 2);
        if (n > 200000) throw SnakeError(tooManySamples(n, L, unit, pv.size() - (closed ? 1 : 0)));
        double step = closed ? L / double(n) : L / double(n - 1);

        pushUndo();
        st.samples.clear();
        st.gaps.clear();
        st.closed = closed;
        st.unit = unit;
        std::vector<double> sampleArc;
        size_t e = 0;
        for (long k = 0; k < n; ++k) {
            double s = std::min(L, k * step);
            while (e + 2 < pv.size() && cum[e + 1] < s) ++e;
            double len = cum[e + 1] - cum[e];
            double t = len > 0 ? (s - cum[e]) / len : 0.0;
            t = std::min(1.0, std::max(0.0, t));
            SnakeSample smp;
            smp.p = pointOnEdge(pv[e], pv[e + 1], t);
            st.samples.push_back(smp);
            sampleArc.push_back(s);
        }
        // Gaps: the path edges and vertices between consecutive samples (the initial curve).
        int gapsN = numGaps();
        st.gaps.assign(gapsN, Gap());
        for (int g = 0; g < gapsN; ++g) {
            double s0 = sampleArc[g], s1 = (g + 1 < n) ? sampleArc[g + 1] : L;
            Gap &gap = st.gaps[g];
            const double eps = 1e-12 * L; // relative: any scale
            for (size_t i = 0; i + 1 < pv.size(); ++i) {
                if (cum[i + 1] < s0 - eps || cum[i] > s1 + eps) continue;
                for (int f : edgeFaces(pv[i], pv[i + 1])) gap.faces.push_back(f);
                if (cum[i] > s0 + eps && cum[i] < s1 - eps) gap.crossings.push_back(vertexPoint(pv[i]));
            }
            gap.traced = true;
        }
        initialSamples = st.samples;
        initialPolyline = Polyline();
        resetRun();
    }

    /// Seeds given as surface points (face + barycentric, e.g. snapped from coordinates or a
    /// Pick Points file): the curve starts and ends exactly at them (SeedPath::ComputeFromPoints).
    /// `lengthScale`: the snake's length unit (see LengthScale()); 0 = from the path's faces.
    void InitFromSeedPoints(const std::vector<SurfacePoint> &seeds, bool closed, SeedPathCost cost = SeedPathCost::Length,
                            double lengthScale = 0)
    {
        typename SeedPath<MeshType>::PointResult path = SeedPath<MeshType>::ComputeFromPoints(surf->Mesh(), seeds, closed, cost);
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
        const MeshType &m = surf->Mesh();
        std::vector<SurfacePoint> pv;
        for (const auto &p : pathPts) {
            checkPoint(p);
            if (pv.empty() || p.Pd(m) != pv.back().Pd(m)) pv.push_back(p);
        }
        if (closed && pv.size() > 1 && pv.front().Pd(m) == pv.back().Pd(m)) pv.pop_back();
        if (closed) pv.push_back(pv.front());
        if (pv.size() < 2) throw SnakeError("Geometric snake: the seed path is too short.");
        // The face each piece lies in, and both ends expressed in it.
        const size_t np = pv.size() - 1;
        std::vector<int> pieceFace(np);
        std::vector<std::pair<SurfacePoint, SurfacePoint>> ends(np);
        for (size_t i = 0; i < np; ++i) {
            pieceFace[i] = commonFace(pv[i], pv[i + 1]);
            if (pieceFace[i] < 0) throw SnakeError("Geometric snake: consecutive seed path points share no face.");
            pv[i].InFace(m, pieceFace[i], ends[i].first);
            pv[i + 1].InFace(m, pieceFace[i], ends[i].second);
        }
        std::vector<double> cum(pv.size(), 0.0);
        for (size_t i = 1; i < pv.size(); ++i) cum[i] = cum[i - 1] + (pv[i].Pd(m) - pv[i - 1].Pd(m)).Norm();
        const double L = cum.back();
        // The length unit: the median edge of the faces the path crosses (the pieces
        // themselves can be far longer than any edge on a CAD face).
        const double unit = (lengthScale > 0 && std::isfinite(lengthScale)) ? lengthScale : medianPositive(faceEdges(pieceFace));
        const double d = st.params.spacing * unit;
        if (!(L > 1e-9 * surf->MeanEdge())) throw SnakeError("Geometric snake: the seed path has zero length.");
        long n = closed ? std::lround(L / d) : std::lround(L / d) + 1;
        n = std::max<long>(n, closed ? 3 : 2);
        if (n > 200000) throw SnakeError(tooManySamples(n, L, unit, pv.size() - (closed ? 1 : 0)));
        const double step = closed ? L / double(n) : L / double(n - 1);

        pushUndo();
        st.samples.clear();
        st.gaps.clear();
        st.closed = closed;
        st.unit = unit;
        std::vector<double> sampleArc;
        size_t e = 0;
        for (long k = 0; k < n; ++k) {
            const double s = (!closed && k == n - 1) ? L : std::min(L, k * step);
            while (e + 2 < pv.size() && cum[e + 1] < s) ++e;
            const double len = cum[e + 1] - cum[e];
            const double t = std::min(1.0, std::max(0.0, len > 0 ? (s - cum[e]) / len : 0.0));
            SnakeSample smp;
            smp.p = SurfacePoint(pieceFace[e], ends[e].first.bary * (1 - t) + ends[e].second.bary * t);
            smp.p.Normalize();
            st.samples.push_back(smp);
            sampleArc.push_back(s);
        }
        const int gapsN = numGaps();
        st.gaps.assign(gapsN, Gap());
        const double eps = 1e-12 * L; // relative: any scale
        for (int g = 0; g < gapsN; ++g) {
            const double s0 = sampleArc[g], s1 = (g + 1 < n) ? sampleArc[g + 1] : L;
            Gap &gap = st.gaps[g];
            for (size_t i = 0; i < np; ++i) {
                if (cum[i + 1] < s0 - eps || cum[i] > s1 + eps) continue;
                gap.faces.push_back(pieceFace[i]);
                if (cum[i] > s0 + eps && cum[i] < s1 - eps) gap.crossings.push_back(pv[i]);
            }
            gap.traced = true;
        }
        initialSamples = st.samples;
        initialPolyline = Polyline();
        resetRun();
    }

    /// Restores samples (e.g. from JSON). Gaps are re-projected on the next operation.
    /// `lengthScale`: the snake's length unit (LengthScale()); 0 = the median edge length of
    /// the samples' faces.
    void InitFromSamples(const std::vector<SnakeSample> &samples, bool closed, double lengthScale = 0)
    {
        if (int(samples.size()) < (closed ? 3 : 2)) throw SnakeError("Geometric snake: too few samples.");
        if (samples.size() > 200000)
            throw SnakeError("Geometric snake: " + std::to_string(samples.size()) + " samples are too many (at most 200000).");
        for (const auto &s : samples) checkPoint(s.p);
        if (!(lengthScale > 0) || !std::isfinite(lengthScale)) {
            std::vector<int> faces;
            for (const auto &s : samples) faces.push_back(s.p.face);
            lengthScale = medianPositive(faceEdges(faces));
        }
        pushUndo();
        st.samples = samples;
        st.closed = closed;
        st.unit = lengthScale;
        st.gaps.assign(numGaps(), Gap());
        if (initialSamples.empty()) {
            initialSamples = st.samples;
            initialPolyline = Polyline();
        }
        resetRun();
    }

    // ----------------------------------------------------------------- motion
    /// One snake operation (Sec. 4.3, Fig. 1): partition, then for every segment build the
    /// local region, embed it, map samples and energy gradients into the plane, do up to
    /// `updatesPerOperation` updates of Eq. 4 and map back; then the overlapping segments
    /// across the borders. Returns the largest sample move in local length units (LengthScale()).
    double Step()
    {
        if (st.samples.empty()) throw SnakeError("Geometric snake: the snake has no samples.");
        if (!surf->MatchesMesh()) throw SnakeError("Geometric snake: the mesh changed since the snake was created.");
        pushUndo();
        auto t0 = clock::now();
        std::vector<vcg::Point3d> before = positions();
        if (runLength < 0 && st.closed) runLength = lastLength = loopLength(before, true);
        if (stage < 0) stage = startLevel();
        if (st.params.method == SnakeMethod::LocalEmbedding) stepEmbedding();
        else motion.StepProjection(st, stats, frame());
        std::vector<vcg::Point3d> after = positions();
        double maxMove = curveMove(before, after) / st.unit;
        stats.lastMaxMove = maxMove;
        stats.operations++;
        updateConvergence(maxMove, after);
        checkCollapse(after);
        // the operation's time includes the convergence and well tests (issue 12: they are
        // part of what one operation costs)
        double ms = msSince(t0);
        stats.msOperation.push_back(ms);
        stats.secondsTotal += ms / 1000.0;
        return maxMove;
    }

    /// Operations until converged or `maxOperations`. `progress(op)` may return false to stop.
    bool Run(int maxOperations, const std::function<bool(int)> &progress = nullptr)
    {
        if (maxOperations < 0 || maxOperations > 10000000) throw SnakeError("Geometric snake: absurd operation limit.");
        pushUndo();
        bool keep = history.Suspend(true); // one undo step for the whole run
        for (int op = 0; op < maxOperations && !stats.converged && !stats.stopped; ++op) {
            Step();
            if (progress && !progress(op)) break;
        }
        history.Suspend(keep);
        return stats.converged;
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
        invalidateAround(i);
        resetRun();
    }

    /// Point fixing.
    void SetFixed(int i, bool fixed)
    {
        checkIndex(i);
        pushUndo();
        st.samples[i].fixed = fixed;
        resetRun();
    }

    /// Inserts a sample in the middle of gap i (between samples i and i+1); returns its index.
    int InsertSample(int gap)
    {
        if (gap < 0 || gap >= numGaps()) throw SnakeError("Geometric snake: no gap " + std::to_string(gap) + ".");
        tightenGaps();
        std::vector<SurfacePoint> pts = gapPoints(gap);
        std::vector<vcg::Point3d> xyz;
        for (auto &p : pts) xyz.push_back(p.Pd(surf->Mesh()));
        double L = 0;
        for (size_t k = 1; k < xyz.size(); ++k) L += (xyz[k] - xyz[k - 1]).Norm();
        SurfacePoint mid = pts.front();
        double acc = 0;
        for (size_t k = 1; k < xyz.size(); ++k) {
            double l = (xyz[k] - xyz[k - 1]).Norm();
            if (acc + l >= L / 2 && l > 0) {
                double t = (L / 2 - acc) / l;
                mid = interpolate(pts[k - 1], pts[k], t);
                break;
            }
            acc += l;
        }
        pushUndo();
        SnakeSample s;
        s.p = mid;
        st.samples.insert(st.samples.begin() + gap + 1, s);
        st.gaps[gap] = Gap();
        st.gaps.insert(st.gaps.begin() + gap + 1, Gap());
        resetRun();
        return gap + 1;
    }

    void DeleteSample(int i)
    {
        checkIndex(i);
        if (int(st.samples.size()) <= (st.closed ? 3 : 2))
            throw SnakeError("Geometric snake: cannot delete, the snake would have too few samples.");
        pushUndo();
        st.samples.erase(st.samples.begin() + i);
        int n = int(st.samples.size());
        if (st.closed) {
            st.gaps.erase(st.gaps.begin() + i);
            st.gaps[(i - 1 + n) % n] = Gap();
        } else {
            int g = std::min(i, int(st.gaps.size()) - 1);
            st.gaps.erase(st.gaps.begin() + g);
            if (i - 1 >= 0 && i - 1 < int(st.gaps.size())) st.gaps[i - 1] = Gap();
        }
        resetRun();
    }

    void SetParams(const SnakeParams &p)
    {
        p.Validate();
        pushUndo();
        st.params = p;
        motion.ClearCache();
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
        motion.ClearCache();
        resetRun();
        return true;
    }
    bool Redo()
    {
        if (!history.Redo(st)) return false;
        motion.ClearCache();
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
    int EnergyStage() const { return energyLevel(); }
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
        bool missing = false;
        for (const auto &g : st.gaps) missing |= !g.traced;
        if (missing && st.samples.size() >= 2) retrace();
        tightenGaps();
        std::vector<SurfacePoint> out;
        int n = int(st.samples.size());
        for (int i = 0; i < n; ++i) {
            out.push_back(st.samples[i].p);
            if (i < numGaps())
                for (const auto &c : gapPoints(i, false)) out.push_back(c);
        }
        return out;
    }

    std::vector<vcg::Point3d> PolylinePositions()
    {
        std::vector<vcg::Point3d> out;
        for (const auto &p : Polyline()) out.push_back(p.Pd(surf->Mesh()));
        return out;
    }

private:
    typedef std::chrono::steady_clock clock;
    typedef SnakeSegment Segment;

    std::shared_ptr<Surface> surf;
    SnakeSegmentMotion<MeshType> motion;
    SnakeCurve st;
    SnakeHistory<SnakeCurve> history;
    SnakeStats stats;
    std::vector<int> seedVertices;
    std::vector<SurfacePoint> seedPoints;
    std::vector<SnakeSample> initialSamples;
    std::vector<SurfacePoint> initialPolyline;
    int stage = -1; // energy level (-1: chosen by startLevel() at the next operation)
    bool settledOutside = false; // settled on a coarse level outside its wells once already
    double runLength = -1, lastLength = -1; // closed snakes: length at the start of the run, after the last operation
    std::deque<double> moveHistory, travelHistory;
    std::deque<std::vector<vcg::Point3d>> posHistory;
    // inWells' probe order, a cost heuristic and not the snake's state: per sample, the side
    // whose probe found no well last time (1: ahead across, 2: behind), 0 if none
    mutable std::vector<unsigned char> wellMiss;

public:
    /// Everything a user sees of the snake (curve, pins, parameters, counters, convergence),
    /// for an undo history kept outside the snake (vcg_ext/snake_undo.h, SnakeController).
    struct Memento
    {
        decltype(st) curve;
        SnakeStats stats;
        int stage = -1;
        decltype(moveHistory) moves, travels;
        decltype(posHistory) positions;
        std::vector<int> seeds;
        std::vector<SurfacePoint> seedPoints;
        std::vector<SnakeSample> initialSamples;
        std::vector<SurfacePoint> initialPolyline;
        double runLength = -1, lastLength = -1;
    };
    Memento Save() const
    {
        return Memento{st, stats, stage, moveHistory, travelHistory, posHistory, seedVertices, seedPoints,
                       initialSamples, initialPolyline, runLength, lastLength};
    }
    void Restore(const Memento &m)
    {
        st = m.curve;
        stats = m.stats;
        stage = m.stage;
        moveHistory = m.moves;
        travelHistory = m.travels;
        posHistory = m.positions;
        seedVertices = m.seeds;
        seedPoints = m.seedPoints;
        initialSamples = m.initialSamples;
        initialPolyline = m.initialPolyline;
        runLength = m.runLength;
        lastLength = m.lastLength;
        motion.ClearCache();
    }

private:

    static double msSince(clock::time_point t0)
    {
        return std::chrono::duration<double, std::milli>(clock::now() - t0).count();
    }
    /// The "too many samples" message, blaming the spacing or the length of the path.
    std::string tooManySamples(long n, double L, double unit, size_t pathPoints) const
    {
        const double edges = L / unit;
        char buf[320];
        if (st.params.spacing < 1.0 && edges <= 200000)
            std::snprintf(buf, sizeof buf, "Geometric snake: the sample spacing (%g edge lengths) is too small for "
                          "this path: it would need %ld samples (at most 200000). Raise the spacing.",
                          st.params.spacing, n);
        else
            std::snprintf(buf, sizeof buf, "Geometric snake: the seed path is too long for one snake: %zu points, "
                          "%.0f local edge lengths, %ld samples at spacing %g (at most 200000). Use fewer or "
                          "closer seeds, or a larger spacing.", pathPoints, edges, n, st.params.spacing);
        return buf;
    }
    int numGaps() const { return st.NumGaps(); }
    /// The edge lengths of the given faces, in double.
    std::vector<double> faceEdges(const std::vector<int> &faces) const
    {
        const MeshType &m = surf->Mesh();
        std::vector<double> l;
        for (int f : faces)
            for (int k = 0; k < 3; ++k)
                l.push_back(vcg::Distance(vcg::Point3d::Construct(m.face[f].cP(k)),
                                          vcg::Point3d::Construct(m.face[f].cP((k + 1) % 3))));
        return l;
    }
    /// Median of the positive values (the mesh's mean edge length if there is none).
    double medianPositive(std::vector<double> v) const
    {
        v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !(x > 0) || !std::isfinite(x); }), v.end());
        if (v.empty()) return surf->MeanEdge();
        std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
        return v[v.size() / 2];
    }
    double dist(int a, int b) const
    {
        const MeshType &m = surf->Mesh(); // in double: a float square over- or underflows at 1e30 / 1e-30
        return vcg::Distance(vcg::Point3d::Construct(m.vert[a].cP()), vcg::Point3d::Construct(m.vert[b].cP()));
    }
    void checkIndex(int i) const
    {
        if (i < 0 || i >= int(st.samples.size()))
            throw SnakeError("Geometric snake: no sample " + std::to_string(i) + " (the snake has " +
                             std::to_string(st.samples.size()) + ").");
    }
    void checkPoint(const SurfacePoint &p) const
    {
        if (!p.IsValid() || !surf->FaceUsable(p.face))
            throw SnakeError("Geometric snake: the point is not on the mesh (face " + std::to_string(p.face) + ").");
    }
    void pushUndo() { history.Push(st); }

    SnakeMotionFrame frame() const
    {
        SnakeMotionFrame f;
        f.level = energyLevel();
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

    /// Length of the sample polygon.
    static double loopLength(const std::vector<vcg::Point3d> &p, bool closed)
    {
        double L = 0;
        for (size_t i = 0; i + (closed ? 0 : 1) < p.size(); ++i) L += (p[(i + 1) % p.size()] - p[i]).Norm();
        return L;
    }

    /// A closed snake that shrinks where no feature holds it would end as a point and report
    /// convergence: stop it instead and say so. Collapsing: still shrinking (or settled) after
    /// losing three quarters of its length since the run started, or less than 2 length units
    /// long. Its samples then sit on top of each other, whatever the energy there.
    void checkCollapse(const std::vector<vcg::Point3d> &pos)
    {
        if (!st.closed || pos.size() < 3) return;
        double L = loopLength(pos, true);
        if (runLength < 0) runLength = std::max(L, lastLength);
        bool shrinking = lastLength > 0 && L < lastLength - 1e-6 * st.unit;
        lastLength = L;
        double e = 0;
        for (const auto &s : st.samples) e += surf->EnergyAt(0, s.p);
        e /= double(st.samples.size());
        bool tiny = L < 2 * st.unit;
        if (!(tiny || ((shrinking || stats.converged) && L < 0.25 * runLength))) return;
        stats.stopped = true;
        stats.converged = false;
        char msg[300];
        std::snprintf(msg, sizeof msg,
                      "the closed snake is collapsing where no feature holds it (length %.3g, %.0f %% of its length "
                      "at the start, mean energy %.2f): stopped. Seed it closer to the feature, or inflate it with "
                      "a positive Balloon.", L, 100.0 * L / std::max(runLength, 1e-300), e);
        if (stats.warnings.size() < 20) stats.warnings.push_back(msg);
    }

    int energyLevel() const
    {
        const int top = surf->Levels() - 1;
        return stage < 0 ? top : std::min(stage, top);
    }

    /// Where a run starts: the finest level whose wells the samples already sit in (on level 0
    /// also with a mean energy below 0.7: feature-like, not a noise dip), else the coarsest. A
    /// snake seeded on a feature is not dragged off it by a coarse level, which merges it with
    /// a parallel feature a few edges away into one well between them.
    int startLevel() const
    {
        const int top = surf->Levels() - 1;
        for (int l = 0; l < top; ++l) {
            if (l == 0) {
                double e = 0;
                for (const auto &s : st.samples) e += surf->EnergyAt(0, s.p);
                if (e >= 0.7 * double(st.samples.size())) continue;
            }
            if (inWells(l)) return l;
        }
        return top;
    }

    /// The samples sit in wells of `level`: across the curve, the energy rises on both sides
    /// (probes one length unit away, projected onto the surface) at >= 90 % of the free samples.
    /// The probes stop as soon as the answer is known (it runs after most operations on a
    /// coarse level: two projections per sample cost more than the operation itself). The
    /// answer is a count, so the order of the probes does not change it: the samples (and the
    /// side) that were out of a well at the last call go first, and a snake still outside its
    /// wells is told so after a few probes instead of most of them.
    /// On a coarse level, samples held at level-0 wells (SnakeSample::heldFine) count as in.
    bool inWells(int level) const
    {
        const std::vector<vcg::Point3d> p = positions();
        const int n = int(p.size());
        if (int(wellMiss.size()) != n) wellMiss.assign(n, 0);
        std::vector<std::pair<int, vcg::Point3d>> probes; // free samples with a direction across the curve
        probes.reserve(n);
        int held = 0;
        for (int pass = 0; pass < 2; ++pass) // last call's misses first
            for (int i = 0; i < n; ++i) {
                const SnakeSample &s = st.samples[i];
                if (s.fixed || (wellMiss[i] != 0) != (pass == 0)) continue;
                if (level > 0 && s.heldFine) {
                    ++held;
                    continue;
                }
                const int a = st.closed ? (i - 1 + n) % n : std::max(i - 1, 0);
                const int b = st.closed ? (i + 1) % n : std::min(i + 1, n - 1);
                vcg::Point3d across = surf->FaceNormal(s.p.face) ^ (p[b] - p[a]);
                if (!(across.Norm() > 0)) continue;
                probes.emplace_back(i, across.Normalize());
            }
        const int count = int(probes.size());
        const double need = 0.9 * (count + held);
        int in = held;
        for (int k = 0; k < count; ++k) {
            if (in >= need) return true;
            if (in + (count - k) < need) return false;
            const int i = probes[k].first;
            const vcg::Point3d &across = probes[k].second;
            const SnakeSample &s = st.samples[i];
            const double e = surf->EnergyAt(level, s.p), d = st.unit;
            bool rises = true;
            for (const double side : {wellMiss[i] == 2 ? -1.0 : 1.0, wellMiss[i] == 2 ? 1.0 : -1.0}) {
                const SurfacePoint q = SurfaceProjection<MeshType>::Closest(*surf, s.p.face, p[i] + across * (side * d), 3 * d);
                if (!(e <= surf->EnergyAt(level, q) + 1e-6)) {
                    rises = false;
                    wellMiss[i] = side > 0 ? 1 : 2;
                    break;
                }
            }
            if (rises) wellMiss[i] = 0;
            in += rises;
        }
        return count == 0 || in >= need;
    }

    /// The share of the free samples held on level 0 (SnakeSample::heldFine).
    double heldShare() const
    {
        int free = 0, held = 0;
        for (const auto &s : st.samples)
            if (!s.fixed) ++free, held += s.heldFine;
        return free ? double(held) / free : 0.0;
    }

    /// How far the curve moved: each new sample's distance to the old curve near it. Sliding
    /// along the curve does not change the curve, so it does not count.
    double curveMove(const std::vector<vcg::Point3d> &a, const std::vector<vcg::Point3d> &b) const
    {
        const int n = int(a.size());
        if (int(b.size()) != n) return 1e9;
        double worst = 0;
        for (int i = 0; i < n; ++i) {
            double best = (b[i] - a[i]).Norm();
            for (int j = i - 2; j <= i + 1; ++j) {
                int j0 = j, j1 = j + 1;
                if (st.closed) { j0 = (j0 + n) % n; j1 = (j1 + n) % n; }
                else if (j0 < 0 || j1 >= n) continue;
                vcg::Point3d d = a[j1] - a[j0];
                double L2 = d.SquaredNorm();
                double t = L2 > 0 ? std::max(0.0, std::min(1.0, ((b[i] - a[j0]) * d) / L2)) : 0.0;
                best = std::min(best, (b[i] - (a[j0] + d * t)).Norm());
            }
            worst = std::max(worst, best);
        }
        return worst;
    }

    void resetRun()
    {
        motion.ForgetEmbeddings(); // samples were placed anew: regions are built around them
        for (auto &smp : st.samples) {
            smp.trust = 1.0;
            smp.heldFine = false;
        }
        stage = -1;
        settledOutside = false;
        stats.converged = false;
        stats.stopped = false;
        runLength = -1;
        moveHistory.clear();
        travelHistory.clear();
        posHistory.clear();
    }
    void invalidateAround(int i)
    {
        int n = int(st.samples.size());
        if (st.closed) {
            st.gaps[i] = Gap();
            st.gaps[(i - 1 + n) % n] = Gap();
        } else {
            if (i < int(st.gaps.size())) st.gaps[i] = Gap();
            if (i - 1 >= 0) st.gaps[i - 1] = Gap();
        }
    }

    // ----- points on mesh edges and vertices
    SurfacePoint vertexPoint(int v) const
    {
        const MeshType &m = surf->Mesh();
        vcg::face::VFIterator<FaceType> vfi(const_cast<VertexType *>(&m.vert[v]));
        return SurfacePoint::AtCorner(surf->Idx(vfi.F()), vfi.I());
    }
    std::vector<int> edgeFaces(int a, int b) const
    {
        const MeshType &m = surf->Mesh();
        std::vector<int> out;
        for (vcg::face::VFIterator<FaceType> vfi(const_cast<VertexType *>(&m.vert[a])); !vfi.End(); ++vfi)
            for (int k = 0; k < 3; ++k)
                if (vfi.F()->V(k) == &m.vert[b]) out.push_back(surf->Idx(vfi.F()));
        return out;
    }
    /// A face holding both surface points (each may lie on an edge or at a vertex), or -1.
    int commonFace(const SurfacePoint &a, const SurfacePoint &b) const
    {
        const MeshType &m = surf->Mesh();
        SurfacePoint tmp;
        for (int f : {a.face, b.face})
            if (a.InFace(m, f, tmp) && b.InFace(m, f, tmp)) return f;
        for (int k = 0; k < 3; ++k) {
            if (!(a.bary[k] > 1e-12)) continue;
            for (vcg::face::VFIterator<FaceType> vfi(const_cast<FaceType *>(&m.face[a.face])->V(k)); !vfi.End(); ++vfi) {
                const int f = surf->Idx(vfi.F());
                if (!vfi.F()->IsD() && a.InFace(m, f, tmp) && b.InFace(m, f, tmp)) return f;
            }
        }
        return -1;
    }

    /// The point (1-t) a + t b on mesh edge ab, expressed in a face containing that edge.
    SurfacePoint pointOnEdge(int a, int b, double t) const
    {
        const MeshType &m = surf->Mesh();
        for (vcg::face::VFIterator<FaceType> vfi(const_cast<VertexType *>(&m.vert[a])); !vfi.End(); ++vfi)
            for (int k = 0; k < 3; ++k)
                if (vfi.F()->V(k) == &m.vert[b]) {
                    vcg::Point3d bary(0, 0, 0);
                    bary[vfi.I()] = 1 - t;
                    bary[k] = t;
                    return SurfacePoint(surf->Idx(vfi.F()), bary);
                }
        throw SnakeError("Geometric snake: the seed path uses a missing edge.");
    }
    /// Point between two surface points that share a face (consecutive polyline points).
    SurfacePoint interpolate(const SurfacePoint &a, const SurfacePoint &b, double t) const
    {
        const MeshType &m = surf->Mesh();
        vcg::Point3d pa = a.Pd(m), pb = b.Pd(m);
        vcg::Point3d q = pa * (1 - t) + pb * t;
        return SurfaceProjection<MeshType>::Closest(*surf, a.face, q, 2 * (pb - pa).Norm() + st.unit);
    }

    /// The shortest path through each traced gap's faces (path_tighten.h), once per trace,
    /// where the polyline is read: the motion does not read the crossings.
    void tightenGaps()
    {
        for (auto &gap : st.gaps)
            if (gap.traced && gap.tightenPending) {
                PathTighten<MeshType>::Tighten(surf->Mesh(), gap.tracedFrom, gap.crossings, gap.tracedTo);
                gap.tightenPending = false;
            }
    }

    /// Points strictly inside gap i (edge crossings); falls back to the shared-edge
    /// midpoints of the face path when the gap was never traced.
    std::vector<SurfacePoint> gapPoints(int g, bool withEnds = true) const
    {
        const Gap &gap = st.gaps[g];
        int n = int(st.samples.size());
        std::vector<SurfacePoint> out;
        if (withEnds) out.push_back(st.samples[g].p);
        if (gap.traced) {
            for (const auto &c : gap.crossings) out.push_back(c);
        } else {
            std::vector<int> fp = FacePath<MeshType>::Find(*surf, st.samples[g].p.face, st.samples[(g + 1) % n].p.face);
            std::vector<SurfacePoint> mid;
            for (size_t k = 0; k + 1 < fp.size(); ++k) {
                const FaceType &f = surf->Mesh().face[fp[k]];
                for (int e = 0; e < 3; ++e)
                    if (surf->Idx(f.cFFp(e)) == fp[k + 1]) {
                        vcg::Point3d b(0, 0, 0);
                        b[e] = 0.5;
                        b[(e + 1) % 3] = 0.5;
                        mid.push_back(SurfacePoint(fp[k], b));
                    }
            }
            // the shortest path through those faces, not their edges' midpoints (on slivers
            // these lie far from both samples)
            PathTighten<MeshType>::Tighten(surf->Mesh(), st.samples[g].p, mid, st.samples[(g + 1) % n].p);
            out.insert(out.end(), mid.begin(), mid.end());
        }
        if (withEnds) out.push_back(st.samples[(g + 1) % n].p);
        return out;
    }

    // ----- partitioning (Sec. 5.1): snake_partition.h, checked before any sample moves
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
        for (auto &s : segs) motion.Move(st, stats, s, st.params.updatesPerOperation, frame());
        for (auto &s : overlaps) motion.Move(st, stats, s, st.params.updatesPerOperation, frame());
    }

    /// Retraces every gap (no motion): one embedding per segment.
    void retrace()
    {
        std::vector<Segment> overlaps;
        std::vector<Segment> segs = partition(overlaps);
        for (auto &s : segs) motion.Move(st, stats, s, 0, frame());
        for (auto &s : overlaps) motion.Move(st, stats, s, 0, frame());
    }

    // ----- convergence: the largest move per operation stays below the tolerance for
    // `window` operations, or -- robust to oscillation and jitter -- the curve as a whole
    // has not moved farther than twice the tolerance over the last 2 * window operations.
    void updateConvergence(double maxMove, const std::vector<vcg::Point3d> &pos)
    {
        const double tol = st.params.convergenceTol;
        const int W = st.params.convergenceWindow;
        moveHistory.push_back(maxMove);
        while (int(moveHistory.size()) > W) moveHistory.pop_front();
        travelHistory.push_back(maxMove);
        while (int(travelHistory.size()) > 2 * W) travelHistory.pop_front();
        bool still = int(moveHistory.size()) == W &&
                     std::all_of(moveHistory.begin(), moveHistory.end(), [&](double v) { return v < tol; });
        posHistory.push_back(pos);
        while (int(posHistory.size()) > 2 * W + 1) posHistory.pop_front();
        bool oscillating = false;
        if (int(posHistory.size()) == 2 * W + 1) {
            // net displacement of the curve over the window against the way travelled: a curve
            // that only jitters in place (a sample bouncing at a corner) has gone nowhere
            double net = curveMove(posHistory.front(), posHistory.back()) / st.unit;
            double travelled = std::accumulate(travelHistory.begin(), travelHistory.end(), 0.0);
            oscillating = net < 2 * tol || (net < 5 * tol && net < 0.25 * travelled);
        }
        stats.converged = still || oscillating;
        const int level = energyLevel();
        if (level > 0) {
            // On a coarse level the snake only has to reach its wells: it steps down to the
            // next finer level as soon as its samples sit in them and it moves by less than 0.3
            // units per operation, settled or not (the cusp of a smoothed well keeps it bouncing
            // by about that much). From level 1 to level 0 it settles first: level 0 is flat
            // across the chamfer that triangles straddling a crease cut, so samples stay about
            // where they land in it. Settling outside the wells is a stall: retry once with full
            // steps, then step down anyway (a snake held by its own tension, or no well there).
            // Samples held at level-0 wells (SnakeSegmentMotion::HoldAtWell) already move on level
            // 0 and count as in the wells; once all are held, the whole snake goes there. Not
            // sooner: stretches that lag behind (a loop seeded far up an octahedron's corners
            // while its middle reached the equator) need the coarse levels' reach.
            // Every switch resets the step control.
            if (heldShare() >= 1.0) {
                stage = 0;
                settledOutside = false;
            } else if (((level == 1 ? stats.converged : maxMove < 0.3) && inWells(level)) || (stats.converged && settledOutside)) {
                stage = level - 1;
                settledOutside = false;
            } else if (stats.converged) {
                settledOutside = true;
            } else {
                return;
            }
            for (auto &smp : st.samples) smp.trust = 1.0;
            stats.converged = false;
            moveHistory.clear();
            travelHistory.clear();
            posHistory.clear();
        }
    }
};

} // namespace tri
} // namespace vcg

#endif
