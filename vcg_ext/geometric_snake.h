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
#include <vcg_ext/local_region.h>
#include <vcg_ext/region_walk.h>
#include <vcg_ext/seed_path.h>
#include <vcg_ext/snake_partition.h>
#include <vcg_ext/snake_error.h>
#include <vcg_ext/snake_spline.h>
#include <vcg_ext/snake_surface.h>
#include <vcg_ext/surface_point.h>
#include <vcg_ext/surface_projection.h>
#include <vcg_ext/virtual_boundary_param.h>

namespace vcg {
namespace tri {

/// How the snake is kept on the surface.
enum class SnakeMethod {
    LocalEmbedding = 0, ///< the paper's method: Eq. 4 in the plane of a local embedding (Sec. 4.2, 5)
    Projection3D = 1    ///< the naive method the paper rejected: Eq. 4 in space, then project (Sec. 4.2)
};

/// Snake parameters. Positions are measured in units of the mesh's mean edge length and
/// the energy lies in [0,1], so every parameter is scale-free: the same values work on any mesh.
struct SnakeParams
{
    double alpha = 0.05;         ///< tension, Eq. 2
    double beta = 0.5;           ///< rigidity, Eq. 2
    double gamma = 1.0;          ///< inverse time step of Eq. 4 (larger = smaller, stabler steps)
    double externalWeight = 1.0; ///< weight of the feature force f_x
    double spacing = 1.0;        ///< sample spacing, in mean edge lengths
    int updatesPerOperation = 5; ///< Eq. 4 updates per embedding (Sec. 7)
    int segmentSamples = 64;     ///< partition size (Sec. 5.1)
    int virtualLayers = 3;       ///< rings of virtual vertices of the embedding (Sec. 5.3)
    double maxStep = 0.5;        ///< cap on one update's move, in local edge lengths
    double convergenceTol = 0.02;///< converged: largest move per operation below this (edge lengths) ...
    int convergenceWindow = 3;   ///< ... for this many operations in a row
    SnakeMethod method = SnakeMethod::LocalEmbedding;

    /// Refuses absurd values with a message for the user.
    void Validate() const
    {
        auto bad = [](const std::string &what) { throw SnakeError("Geometric snake: " + what); };
        auto finite = [](double v) { return std::isfinite(v); };
        if (!finite(alpha) || alpha < 0 || alpha > 1e4) bad("Alpha must be in [0, 10000].");
        if (!finite(beta) || beta < 0 || beta > 1e4) bad("Beta must be in [0, 10000].");
        if (!finite(gamma) || gamma <= 0 || gamma > 1e6) bad("Gamma must be in (0, 1e6].");
        if (!finite(externalWeight) || externalWeight < 0 || externalWeight > 1e4)
            bad("ExternalWeight must be in [0, 10000].");
        if (!finite(spacing) || spacing < 0.05 || spacing > 1000) bad("Spacing must be in [0.05, 1000] edge lengths.");
        if (updatesPerOperation < 1 || updatesPerOperation > 1000) bad("Updates per operation must be in [1, 1000].");
        if (segmentSamples < 6 || segmentSamples > 100000) bad("Segment size must be in [6, 100000] samples.");
        if (virtualLayers < 1 || virtualLayers > 10) bad("Virtual layers must be in [1, 10].");
        if (!finite(maxStep) || maxStep <= 0 || maxStep > 10) bad("Max step must be in (0, 10] edge lengths.");
        if (!finite(convergenceTol) || convergenceTol <= 0 || convergenceTol > 10)
            bad("Convergence tolerance must be in (0, 10] edge lengths.");
        if (convergenceWindow < 1 || convergenceWindow > 1000) bad("Convergence window must be in [1, 1000].");
    }
};

struct SnakeSample
{
    SurfacePoint p;
    bool fixed = false;
    /// Step control (not saved): the move cap of this sample shrinks when an update raised
    /// its energy and grows back while it goes downhill, so samples settle in wells.
    double trust = 1.0;
};

/// Timings and counters, for the Log, the JSON output and the benchmarks.
struct SnakeStats
{
    int operations = 0, updates = 0, embeddings = 0, regionFailures = 0;
    bool converged = false;
    double secondsTotal = 0;
    double lastMaxMove = 0; ///< in mean edge lengths
    std::vector<double> msEmbedding, msUpdate, msOperation;
    std::vector<std::string> warnings;

    static double Median(std::vector<double> v)
    {
        if (v.empty()) return 0;
        std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
        return v[v.size() / 2];
    }
};

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

    /// The polyline between sample i and i+1 (Sec. 4.1): the faces it crosses and the
    /// edge-crossing points, both valid after a trace.
    struct Gap
    {
        std::vector<int> faces;
        std::vector<SurfacePoint> crossings;
        bool traced = false;
    };

    GeometricSnake(std::shared_ptr<Surface> surface, const SnakeParams &params = SnakeParams())
        : surf(std::move(surface))
    {
        if (!surf) throw SnakeError("Geometric snake: no surface.");
        params.Validate();
        st.params = params;
    }

    // ----------------------------------------------------------------- creation
    /// Section 5.5: seeds (vertex indices) joined by shortest edge paths, then samples taken
    /// along the path at uniform spacing (Sec. 7).
    void InitFromSeeds(const std::vector<int> &seeds, bool closed, SeedPathCost cost = SeedPathCost::Length)
    {
        typename SeedPath<MeshType>::Result path = SeedPath<MeshType>::Compute(surf->Mesh(), seeds, closed, cost);
        InitFromPath(path.vertices, closed);
        seedVertices = seeds;
        seedPoints.clear();
        for (int v : seeds) seedPoints.push_back(vertexPoint(v));
    }

    /// Samples along a vertex path (consecutive vertices share an edge). Closed paths do not
    /// repeat the first vertex.
    void InitFromPath(const std::vector<int> &pathVerts, bool closed)
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
        double d = st.params.spacing * surf->MeanEdge();
        if (!(L > 1e-9 * surf->MeanEdge())) throw SnakeError("Geometric snake: the seed path has zero length.");
        long n = closed ? std::lround(L / d) : std::lround(L / d) + 1;
        n = std::max<long>(n, closed ? 3 : 2);
        if (n > 200000) throw SnakeError(tooManySamples(n, L, pv.size() - (closed ? 1 : 0)));
        double step = closed ? L / double(n) : L / double(n - 1);

        pushUndo();
        st.samples.clear();
        st.gaps.clear();
        st.closed = closed;
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
    void InitFromSeedPoints(const std::vector<SurfacePoint> &seeds, bool closed, SeedPathCost cost = SeedPathCost::Length)
    {
        typename SeedPath<MeshType>::PointResult path = SeedPath<MeshType>::ComputeFromPoints(surf->Mesh(), seeds, closed, cost);
        InitFromSurfacePath(path.points, closed);
        seedVertices.clear();
        seedPoints.clear();
        for (int i : path.seedPositions) seedPoints.push_back(path.points[i]);
    }

    /// Samples at uniform spacing along a polyline of surface points in which consecutive
    /// points share a face (closed: the first point is not repeated).
    void InitFromSurfacePath(const std::vector<SurfacePoint> &pathPts, bool closed)
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
        const double d = st.params.spacing * surf->MeanEdge();
        if (!(L > 1e-9 * surf->MeanEdge())) throw SnakeError("Geometric snake: the seed path has zero length.");
        long n = closed ? std::lround(L / d) : std::lround(L / d) + 1;
        n = std::max<long>(n, closed ? 3 : 2);
        if (n > 200000) throw SnakeError(tooManySamples(n, L, pv.size() - (closed ? 1 : 0)));
        const double step = closed ? L / double(n) : L / double(n - 1);

        pushUndo();
        st.samples.clear();
        st.gaps.clear();
        st.closed = closed;
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
    void InitFromSamples(const std::vector<SnakeSample> &samples, bool closed)
    {
        if (int(samples.size()) < (closed ? 3 : 2)) throw SnakeError("Geometric snake: too few samples.");
        if (samples.size() > 200000)
            throw SnakeError("Geometric snake: " + std::to_string(samples.size()) + " samples are too many (at most 200000).");
        for (const auto &s : samples) checkPoint(s.p);
        pushUndo();
        st.samples = samples;
        st.closed = closed;
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
    /// across the borders. Returns the largest sample move in mean edge lengths.
    double Step()
    {
        if (st.samples.empty()) throw SnakeError("Geometric snake: the snake has no samples.");
        if (!surf->MatchesMesh()) throw SnakeError("Geometric snake: the mesh changed since the snake was created.");
        pushUndo();
        auto t0 = clock::now();
        std::vector<vcg::Point3d> before = positions();
        if (st.params.method == SnakeMethod::LocalEmbedding) stepEmbedding();
        else stepProjection();
        std::vector<vcg::Point3d> after = positions();
        double maxMove = curveMove(before, after) / surf->MeanEdge();
        stats.lastMaxMove = maxMove;
        stats.operations++;
        double ms = msSince(t0);
        stats.msOperation.push_back(ms);
        stats.secondsTotal += ms / 1000.0;
        updateConvergence(maxMove, after);
        return maxMove;
    }

    /// Operations until converged or `maxOperations`. `progress(op)` may return false to stop.
    bool Run(int maxOperations, const std::function<bool(int)> &progress = nullptr)
    {
        if (maxOperations < 0 || maxOperations > 10000000) throw SnakeError("Geometric snake: absurd operation limit.");
        pushUndo();
        bool keep = keepUndo;
        keepUndo = false; // one undo step for the whole run
        for (int op = 0; op < maxOperations && !stats.converged; ++op) {
            Step();
            if (progress && !progress(op)) break;
        }
        keepUndo = keep;
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
        splines.clear();
        resetRun();
    }

    /// The surface's energy was replaced (another energy type or smoothing): start afresh.
    void EnergyChanged() { resetRun(); }

    // ----------------------------------------------------------------- undo / redo
    bool CanUndo() const { return !undoStack.empty(); }
    bool CanRedo() const { return !redoStack.empty(); }
    bool Undo()
    {
        if (undoStack.empty()) return false;
        redoStack.push_back(st);
        st = undoStack.back();
        undoStack.pop_back();
        splines.clear();
        resetRun();
        return true;
    }
    bool Redo()
    {
        if (redoStack.empty()) return false;
        undoStack.push_back(st);
        st = redoStack.back();
        redoStack.pop_back();
        splines.clear();
        resetRun();
        return true;
    }

    // ----------------------------------------------------------------- access
    const std::vector<SnakeSample> &Samples() const { return st.samples; }
    int SampleCount() const { return int(st.samples.size()); }
    bool Closed() const { return st.closed; }
    const SnakeParams &Params() const { return st.params; }
    const SnakeStats &Stats() const { return stats; }
    bool Converged() const { return stats.converged; }
    /// 1 while capturing on the coarse (smoothed) energy, 0 while settling on the precise one.
    int EnergyStage() const { return coarseStage ? 1 : 0; }
    Surface &GetSurface() { return *surf; }
    std::shared_ptr<Surface> SurfacePtr() const { return surf; }
    const std::vector<int> &SeedVertices() const { return seedVertices; }
    /// The seeds as surface points (for vertex seeds: the vertex, in one of its faces).
    const std::vector<SurfacePoint> &SeedPoints() const { return seedPoints; }
    const std::vector<SnakeSample> &InitialSamples() const { return initialSamples; }
    const std::vector<SurfacePoint> &InitialPolyline() const { return initialPolyline; }
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
    struct State
    {
        std::vector<SnakeSample> samples;
        std::vector<Gap> gaps;
        bool closed = false;
        SnakeParams params;
    };
    typedef SnakeSegment Segment;

    std::shared_ptr<Surface> surf;
    State st;
    std::deque<State> undoStack, redoStack;
    bool keepUndo = true;
    SnakeStats stats;
    std::vector<int> seedVertices;
    std::vector<SurfacePoint> seedPoints;
    std::vector<SnakeSample> initialSamples;
    std::vector<SurfacePoint> initialPolyline;
    bool coarseStage = true;
    std::deque<double> moveHistory, travelHistory;
    std::deque<std::vector<vcg::Point3d>> posHistory;
    std::map<std::tuple<int, bool, std::vector<bool>>, SnakeSpline> splines;
    LocalRegion<MeshType> region;

    static double msSince(clock::time_point t0)
    {
        return std::chrono::duration<double, std::milli>(clock::now() - t0).count();
    }
    /// The "too many samples" message, blaming the spacing or the length of the path.
    std::string tooManySamples(long n, double L, size_t pathPoints) const
    {
        const double edges = L / surf->MeanEdge();
        char buf[320];
        if (st.params.spacing < 1.0 && edges <= 200000)
            std::snprintf(buf, sizeof buf, "Geometric snake: the sample spacing (%g edge lengths) is too small for "
                          "this path: it would need %ld samples (at most 200000). Raise the spacing.",
                          st.params.spacing, n);
        else
            std::snprintf(buf, sizeof buf, "Geometric snake: the seed path is too long for one snake: %zu points, "
                          "%.0f mean edge lengths, %ld samples at spacing %g (at most 200000). Use fewer or "
                          "closer seeds, or a larger spacing.", pathPoints, edges, n, st.params.spacing);
        return buf;
    }
    int numGaps() const
    {
        int n = int(st.samples.size());
        return st.closed ? n : std::max(0, n - 1);
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
    void pushUndo()
    {
        if (!keepUndo) return;
        undoStack.push_back(st);
        if (undoStack.size() > 200) undoStack.pop_front();
        redoStack.clear();
    }
    /// End condition of open snakes: with free ends the tension term would shrink the
    /// snake towards its middle, so an end sample moves only across the curve (its
    /// tangential component is removed); it still follows the feature force sideways.
    bool isOpenEnd(int i) const { return !st.closed && (i == 0 || i == int(st.samples.size()) - 1); }

    int energyLevel() const { return (coarseStage && surf->Levels() > 1) ? 1 : 0; }

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
        for (auto &smp : st.samples) smp.trust = 1.0;
        coarseStage = true;
        stats.converged = false;
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
        return SurfaceProjection<MeshType>::Closest(*surf, a.face, q, 2 * (pb - pa).Norm() + surf->MeanEdge());
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
            for (size_t k = 0; k + 1 < fp.size(); ++k) {
                const FaceType &f = surf->Mesh().face[fp[k]];
                for (int e = 0; e < 3; ++e)
                    if (surf->Idx(f.cFFp(e)) == fp[k + 1]) {
                        vcg::Point3d b(0, 0, 0);
                        b[e] = 0.5;
                        b[(e + 1) % 3] = 0.5;
                        out.push_back(SurfacePoint(fp[k], b));
                    }
            }
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
        for (auto &s : segs) moveSegment(s, st.params.updatesPerOperation, 0);
        for (auto &s : overlaps) moveSegment(s, st.params.updatesPerOperation, 0);
    }

    /// Retraces every gap (no motion): one embedding per segment.
    void retrace()
    {
        std::vector<Segment> overlaps;
        std::vector<Segment> segs = partition(overlaps);
        for (auto &s : segs) moveSegment(s, 0, 0);
        for (auto &s : overlaps) moveSegment(s, 0, 0);
    }

    int gapIndex(int a, int b) const
    {
        int n = int(st.samples.size());
        if (b == (a + 1) % n && (st.closed || a + 1 < n)) return a;
        return -1;
    }

    void moveSegment(const Segment &seg, int updates, int depth)
    {
        const int k = int(seg.idx.size());
        if (k < 2) return;
        const MeshType &m = surf->Mesh();
        const int level = energyLevel();
        auto t0 = clock::now();
        // Sec. 5.2: the faces the segment crosses ...
        std::vector<int> core;
        for (int j = 0; j < k; ++j) core.push_back(st.samples[seg.idx[j]].p.face);
        bool wholeClosed = st.closed && k == int(st.samples.size()) && seg.idx.front() == 0 && !seg.fixFirst;
        int gapsInSeg = wholeClosed ? k : k - 1;
        for (int j = 0; j < gapsInSeg; ++j) {
            int g = gapIndex(seg.idx[j], seg.idx[(j + 1) % k]);
            if (g < 0) continue;
            Gap &gap = st.gaps[g];
            if (gap.faces.empty())
                gap.faces = FacePath<MeshType>::Find(*surf, st.samples[seg.idx[j]].p.face, st.samples[seg.idx[(j + 1) % k]].p.face);
            core.insert(core.end(), gap.faces.begin(), gap.faces.end());
        }
        // ... plus their vertex neighbours, holes filled (LocalRegion), then Sec. 5.3.
        VirtualBoundaryParam::Result emb;
        bool ok = region.Build(*surf, core);
        if (ok) ok = VirtualBoundaryParam::Embed(region.pos, region.tri, region.boundary, surf->MeanEdge(),
                                                 st.params.virtualLayers, emb);
        if (!ok) {
            if (k >= 8 && depth < 6) { // split the segment (Sec. 5.1) and try the halves
                Segment a, b;
                int mid = k / 2;
                a.idx.assign(seg.idx.begin(), seg.idx.begin() + mid + 1);
                b.idx.assign(seg.idx.begin() + mid, seg.idx.end());
                a.fixFirst = seg.fixFirst; a.fixLast = true;
                b.fixFirst = true; b.fixLast = seg.fixLast;
                moveSegment(a, updates, depth + 1);
                moveSegment(b, updates, depth + 1);
                return;
            }
            stats.regionFailures++;
            std::string why = region.error.empty() ? emb.error : region.error;
            if (stats.warnings.size() < 20) stats.warnings.push_back("a segment could not move: " + why);
            return;
        }
        stats.embeddings++;
        stats.msEmbedding.push_back(msSince(t0));

        // Sec. 5.4: samples into the plane by barycentric coordinates.
        std::vector<int> lf(k);
        Eigen::MatrixXd X(k, 2);
        for (int j = 0; j < k; ++j) {
            const SurfacePoint &p = st.samples[seg.idx[j]].p;
            lf[j] = region.LocalFace(*surf, p.face);
            if (lf[j] < 0) { // cannot happen: sample faces are in the core
                stats.regionFailures++;
                return;
            }
            X.row(j) = toPlane(emb, lf[j], p.bary).transpose();
        }
        // Sec. 6.2: energy gradients of the embedded faces, computed once per embedding.
        std::vector<Eigen::Vector2d> grad(region.RealFaces());
        std::vector<char> gradDone(region.RealFaces(), 0);
        auto gradient = [&](int t) -> const Eigen::Vector2d & {
            if (!gradDone[t]) {
                gradDone[t] = 1;
                const auto &T = region.tri[t];
                const FaceType &f = m.face[region.faces[t]];
                Eigen::Matrix2d J;
                J.col(0) = emb.uv[T[1]] - emb.uv[T[0]];
                J.col(1) = emb.uv[T[2]] - emb.uv[T[0]];
                double e0 = surf->EnergyAt(level, surf->Idx(f.cV(0))), e1 = surf->EnergyAt(level, surf->Idx(f.cV(1))),
                       e2 = surf->EnergyAt(level, surf->Idx(f.cV(2)));
                double det = J.determinant();
                if (std::abs(det) > 1e-12) grad[t] = J.transpose().inverse() * Eigen::Vector2d(e1 - e0, e2 - e0);
                else grad[t].setZero();
            }
            return grad[t];
        };
        std::vector<bool> fixed(k);
        for (int j = 0; j < k; ++j)
            fixed[j] = st.samples[seg.idx[j]].fixed || (j == 0 && seg.fixFirst) || (j == k - 1 && seg.fixLast);
        Eigen::MatrixXd B(k, 3); // barycentric coordinates of each sample in its local face
        for (int j = 0; j < k; ++j) {
            const auto &b = st.samples[seg.idx[j]].p.bary;
            B.row(j) << b[0], b[1], b[2];
        }
        if (updates > 0) {
            SnakeSpline &spline = splineFor(k, wholeClosed, fixed);
            Eigen::MatrixXd F(k, 2);
            for (int u = 0; u < updates; ++u) {
                auto tu = clock::now();
                for (int j = 0; j < k; ++j) {
                    // Only the feature force across the curve: along a feature valley the
                    // energy still varies a little, and its tangential part would slide the
                    // samples towards the strongest spots (corners) and bunch them there.
                    Eigen::Vector2d f = st.params.externalWeight * gradient(lf[j]);
                    Eigen::Vector2d t = (X.row(wholeClosed ? (j + 1) % k : std::min(j + 1, k - 1)) -
                                         X.row(wholeClosed ? (j - 1 + k) % k : std::max(j - 1, 0))).transpose();
                    if (t.norm() > 0) { t.normalize(); f -= f.dot(t) * t; }
                    F.row(j) = f.transpose();
                }
                Eigen::MatrixXd Xn = spline.Update(X, F);
                bool left = false;
                for (int j = 0; j < k; ++j) {
                    if (fixed[j]) continue;
                    Eigen::Vector2d d = (Xn.row(j) - X.row(j)).transpose();
                    if (!d.allFinite()) continue;
                    if (isOpenEnd(seg.idx[j]) && k >= 2) { // open ends move across the curve only
                        Eigen::Vector2d t = (X.row(j == 0 ? 1 : k - 2) - X.row(j)).transpose();
                        if (t.norm() > 0) { t.normalize(); d -= d.dot(t) * t; }
                    }
                    double cap = st.params.maxStep * st.samples[seg.idx[j]].trust * localEdge(emb, lf[j]);
                    double len = d.norm();
                    if (len > cap) d *= cap / len;
                    if (len == 0) continue;
                    RegionWalk::Result w = RegionWalk::Walk(emb.uv, region.tri, region.adj, lf[j], X.row(j).transpose(),
                                                            X.row(j).transpose() + d, false);
                    // The energy is piecewise linear, so its force does not vanish at the bottom
                    // of a well and a sample would bounce across it by |f|/gamma: a move that
                    // raised the sample's energy halves its step cap, a downhill one restores it.
                    double eOld = surf->EnergyAt(level, SurfacePoint(region.faces[lf[j]], toPoint(B.row(j))));
                    double eNew = surf->EnergyAt(level, SurfacePoint(region.faces[w.face], toPoint(w.bary)));
                    double &trust = st.samples[seg.idx[j]].trust;
                    trust = eNew > eOld + 1e-9 ? std::max(0.01, trust * 0.5) : std::min(1.0, trust * 1.1);
                    lf[j] = w.face;
                    B.row(j) = w.bary.transpose();
                    X.row(j) = toPlane(emb, w.face, vcg::Point3d(w.bary[0], w.bary[1], w.bary[2])).transpose();
                    left |= w.exited;
                }
                stats.updates++;
                stats.msUpdate.push_back(msSince(tu));
                if (left) break; // the curve reached the region border: re-embed (Sec. 5.4)
            }
        }
        // Map back by barycentric coordinates.
        for (int j = 0; j < k; ++j) {
            SnakeSample &s = st.samples[seg.idx[j]];
            if (fixed[j] && s.fixed) continue; // pinned samples are held exactly
            s.p.face = region.faces[lf[j]];
            s.p.bary = vcg::Point3d(B(j, 0), B(j, 1), B(j, 2));
            s.p.Normalize();
        }
        // Trace the straight segments between samples across the embedded triangles (Sec. 4.1).
        for (int j = 0; j < gapsInSeg; ++j) {
            int a = j, b = (j + 1) % k;
            int g = gapIndex(seg.idx[a], seg.idx[b]);
            if (g < 0) continue;
            RegionWalk::Result w = RegionWalk::Walk(emb.uv, region.tri, region.adj, lf[a], X.row(a).transpose(),
                                                    X.row(b).transpose(), true);
            Gap &gap = st.gaps[g];
            gap = Gap();
            if (w.exited) { // leaves the region (non-convex border): re-project next time
                gap.faces = FacePath<MeshType>::Find(*surf, st.samples[seg.idx[a]].p.face, st.samples[seg.idx[b]].p.face);
                continue;
            }
            gap.faces.push_back(region.faces[lf[a]]);
            for (const auto &c : w.crossings) {
                gap.crossings.push_back(SurfacePoint(region.faces[c.face], vcg::Point3d(c.bary[0], c.bary[1], c.bary[2])));
                gap.faces.push_back(region.faces[c.face]);
            }
            gap.faces.push_back(region.faces[w.face]);
            gap.faces.push_back(region.faces[lf[b]]);
            gap.traced = true;
        }
    }

    template <class V>
    static vcg::Point3d toPoint(const V &b) { return vcg::Point3d(b[0], b[1], b[2]); }

    static Eigen::Vector2d toPlane(const VirtualBoundaryParam::Result &emb, const std::array<int, 3> &T,
                                   const vcg::Point3d &b)
    {
        return b[0] * emb.uv[T[0]] + b[1] * emb.uv[T[1]] + b[2] * emb.uv[T[2]];
    }
    Eigen::Vector2d toPlane(const VirtualBoundaryParam::Result &emb, int t, const vcg::Point3d &b) const
    {
        return toPlane(emb, region.tri[t], b);
    }
    double localEdge(const VirtualBoundaryParam::Result &emb, int t) const
    {
        const auto &T = region.tri[t];
        return ((emb.uv[T[1]] - emb.uv[T[0]]).norm() + (emb.uv[T[2]] - emb.uv[T[1]]).norm() +
                (emb.uv[T[0]] - emb.uv[T[2]]).norm()) / 3.0;
    }

    SnakeSpline &splineFor(int k, bool closed, const std::vector<bool> &fixed)
    {
        auto key = std::make_tuple(k, closed, fixed);
        if (splines.size() > 64) splines.clear();
        SnakeSpline &s = splines[key];
        s.Setup(k, closed, st.params.alpha, st.params.beta, st.params.gamma, fixed);
        return s;
    }

    // ----- the naive method (Sec. 4.2): Eq. 4 in space, then projection onto the surface
    void stepProjection()
    {
        const MeshType &m = surf->Mesh();
        const int n = int(st.samples.size());
        const double h = surf->MeanEdge();
        std::vector<bool> fixed(n);
        for (int i = 0; i < n; ++i) fixed[i] = st.samples[i].fixed;
        SnakeSpline &spline = splineFor(n, st.closed, fixed);
        Eigen::MatrixXd X(n, 3), F(n, 3);
        for (int u = 0; u < st.params.updatesPerOperation; ++u) {
            auto tu = clock::now();
            for (int i = 0; i < n; ++i) {
                vcg::Point3d p = st.samples[i].p.Pd(m) / h;
                X.row(i) << p[0], p[1], p[2];
                vcg::Point3d g = faceGradient3D(st.samples[i].p.face) * h; // per edge length
                F.row(i) << st.params.externalWeight * g[0], st.params.externalWeight * g[1],
                    st.params.externalWeight * g[2];
            }
            for (int i = 0; i < n; ++i) { // the feature force across the curve only (see moveSegment)
                int a = st.closed ? (i - 1 + n) % n : std::max(i - 1, 0), b = st.closed ? (i + 1) % n : std::min(i + 1, n - 1);
                Eigen::Vector3d t = (X.row(b) - X.row(a)).transpose();
                if (t.norm() > 0) { t.normalize(); F.row(i) -= F.row(i).dot(t.transpose()) * t.transpose(); }
            }
            Eigen::MatrixXd Xn = spline.Update(X, F);
            for (int i = 0; i < n; ++i) {
                if (fixed[i]) continue;
                Eigen::Vector3d d = (Xn.row(i) - X.row(i)).transpose();
                if (!d.allFinite()) continue;
                if (isOpenEnd(i) && n >= 2) {
                    Eigen::Vector3d t = (X.row(i == 0 ? 1 : n - 2) - X.row(i)).transpose();
                    if (t.norm() > 0) { t.normalize(); d -= d.dot(t) * t; }
                }
                double len = d.norm(), cap = st.params.maxStep * st.samples[i].trust * faceEdge(st.samples[i].p.face) / h;
                if (len > cap) d *= cap / len;
                Eigen::Vector3d q = X.row(i).transpose() + d;
                vcg::Point3d target(q[0] * h, q[1] * h, q[2] * h);
                SurfacePoint np = SurfaceProjection<MeshType>::Closest(*surf, st.samples[i].p.face, target,
                                                                       d.norm() * h + 1.5 * h);
                double &trust = st.samples[i].trust; // same step control as the embedding method
                trust = surf->EnergyAt(energyLevel(), np) > surf->EnergyAt(energyLevel(), st.samples[i].p) + 1e-9
                            ? std::max(0.01, trust * 0.5) : std::min(1.0, trust * 1.1);
                st.samples[i].p = np;
            }
            stats.updates++;
            stats.msUpdate.push_back(msSince(tu));
        }
        for (auto &g : st.gaps) g = Gap(); // traced lazily by Polyline()
    }

    double faceEdge(int f) const
    {
        const FaceType &ff = surf->Mesh().face[f];
        const vcg::Point3d p0 = vcg::Point3d::Construct(ff.cP(0)), p1 = vcg::Point3d::Construct(ff.cP(1)),
                           p2 = vcg::Point3d::Construct(ff.cP(2));
        return (vcg::Distance(p0, p1) + vcg::Distance(p1, p2) + vcg::Distance(p2, p0)) / 3.0;
    }

    /// Gradient of the linear energy inside a face, in space (0 on degenerate faces).
    vcg::Point3d faceGradient3D(int f) const
    {
        const FaceType &ff = surf->Mesh().face[f];
        const double h = surf->MeanEdge(); // in mean edge lengths, so the degeneracy bound is scale-free
        vcg::Point3d p[3];
        double e[3];
        for (int k = 0; k < 3; ++k) {
            p[k] = vcg::Point3d::Construct(ff.cP(k)) / h;
            e[k] = surf->EnergyAt(energyLevel(), surf->Idx(ff.cV(k)));
        }
        vcg::Point3d n = (p[1] - p[0]) ^ (p[2] - p[0]);
        double a2 = n.SquaredNorm();
        if (!(a2 > 1e-30)) return vcg::Point3d(0, 0, 0);
        vcg::Point3d g(0, 0, 0);
        for (int k = 0; k < 3; ++k) g += (n ^ (p[(k + 2) % 3] - p[(k + 1) % 3])) * e[k]; // grad of hat k = n x e_k / |n|^2
        return g / (a2 * h);
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
            double net = curveMove(posHistory.front(), posHistory.back()) / surf->MeanEdge();
            double travelled = std::accumulate(travelHistory.begin(), travelHistory.end(), 0.0);
            oscillating = net < 2 * tol || (net < 5 * tol && net < 0.25 * travelled);
        }
        stats.converged = still || oscillating;
        if (stats.converged && energyLevel() == 1) { // captured: now settle on the precise energy
            coarseStage = false; // keep the settled step caps: the samples are already close
            stats.converged = false;
            moveHistory.clear();
            posHistory.clear();
        }
    }
};

} // namespace tri
} // namespace vcg

#endif
