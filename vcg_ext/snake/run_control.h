#ifndef VCG_EXT_SNAKE_RUN_CONTROL_H
#define VCG_EXT_SNAKE_RUN_CONTROL_H

// When a run of snake operations stops, and on which level of the energy pyramid it slithers
// (beyond the paper: coarse-to-fine capture, issue 9): the convergence test, the level schedule
// with its well test, and the watch that stops a closed snake collapsing where no feature holds
// it. Its State is part of what undo restores (GeometricSnake::Memento).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <numeric>
#include <vector>

#include <vcg_ext/snake/curve.h>
#include <vcg_ext/surface/snake_surface.h>
#include <vcg_ext/surface/surface_projection.h>

namespace vcg {
namespace tri {

template <class MeshType>
class SnakeRunControl
{
public:
    typedef SnakeSurface<MeshType> Surface;
    typedef std::vector<vcg::Point3d> Positions;

    struct State
    {
        int stage = -1;              ///< energy level (-1: chosen by startLevel() at the next operation)
        bool settledOutside = false; ///< settled on a coarse level outside its wells once already
        double runLength = -1, lastLength = -1; ///< closed snakes: length at the run's start, after the last operation
        vcg::Point3d runCentre{0, 0, 0};          ///< closed snakes: centroid of the samples at the run's start
        std::deque<double> moves, travels;
        std::deque<Positions> positions;
        std::deque<double> energies; ///< level 0: the samples' mean energy after each of the last operations (stall test)

        size_t Bytes() const
        {
            size_t b = sizeof(*this) + (moves.size() + travels.size() + energies.size()) * sizeof(double);
            for (const auto &q : positions) b += q.capacity() * sizeof(vcg::Point3d);
            return b;
        }
    };

    /// The stall test (session 29, docs/method.md "Session 29"): on a noisy fine mesh level 0
    /// is a field of noise dips about one local edge apart, and every operation a different
    /// handful of samples hops to a neighbouring dip; the convergence and oscillation tests
    /// (updateConvergence) are maxima over the samples, so they never fire although the loop as
    /// a whole hardly moves, and the Run ends at its limit. The curve as a whole has stalled when, on level 0, the samples' mean net
    /// move over the last 2 x window operations is below `meanMove` x the convergence
    /// tolerance (the hops are a few samples' moves: the mean of a curve that goes somewhere is
    /// its move) and the mean energy on the curve no longer falls (fell by less than `fall`
    /// over those operations: a loop still drifting down the noise goes on). The Run then ends
    /// as converged: the curve moves no more than one that passed the worst-sample test.
    struct Param
    {
        bool stall = true;     ///< the stall test on (off: the worst-sample tests alone, as before session 29)
        double meanMove = 1.0; ///< mean net move per sample over 2 x window operations, x convergenceTol
        double fall = 0.002;   ///< the mean energy (in [0, 1]) fell by less than this over 2 x window operations
    };

    explicit SnakeRunControl(const Surface *s) : surf(s) {}

    Param &GetParam() { return param; }
    const Param &GetParam() const { return param; }

    const State &Get() const { return state; }
    void Set(const State &s) { state = s; }

    /// A new run (samples placed anew, edited, new parameters): the level is chosen again at
    /// the next operation. The last length stays: a collapse is measured against it.
    /// keepLevel (a point edit: a sample moved, pinned, inserted or deleted): the run goes on
    /// on the level it had reached. The rest of the curve was already captured there, and on
    /// level 0 startLevel's well test fails on shallow wells (fandisk's curved crease beside its
    /// fillet: 0 of 42 samples in level-0 wells by 0.005-0.03 of energy, after converging
    /// there), so every pin sent the whole snake back to the coarsest level, whose wells merge
    /// the crease with the fillet: a pin 6 edge lengths off the crease pulled the far end 4.5
    /// edge lengths off it (issue 37).
    void Reset(bool keepLevel = false)
    {
        const double last = state.lastLength;
        const int stage = state.stage;
        state = State();
        state.lastLength = last;
        if (keepLevel) state.stage = stage;
    }

    /// The level the snake slithers on: the coarsest while capturing, one finer each time its
    /// samples sit in wells of the current one, 0 (precise) to settle.
    int Level() const
    {
        const int top = surf->Levels() - 1;
        return state.stage < 0 ? top : std::min(state.stage, top);
    }

    /// Samples were inserted between others (their indices now, ascending: SnakeGapRefine): the
    /// positions kept for the convergence test get them too, halfway between their neighbours
    /// (on the curve as it was), so that a curve that did not move still compares as unmoved.
    void SamplesInserted(const std::vector<int> &inserted)
    {
        for (auto &p : state.positions)
            for (int k : inserted)
                if (k > 0 && k <= int(p.size())) p.insert(p.begin() + k, k < int(p.size()) ? (p[k - 1] + p[k]) / 2 : p[k - 1]);
        for (int k : inserted)
            if (k >= 0 && k <= int(wellMiss.size())) wellMiss.insert(wellMiss.begin() + k, 0);
    }

    /// Before an operation, with the samples where they are.
    void Begin(const SnakeCurve &st, const Positions &pos)
    {
        if (state.runLength < 0 && st.closed) {
            state.runLength = state.lastLength = LoopLength(pos, true);
            state.runCentre = Centroid(pos);
        }
        if (state.stage < 0) state.stage = startLevel(st, pos);
    }

    /// After an operation that moved the curve by `maxMove` length units: convergence, the
    /// switch to a finer level (it resets the samples' step control), the collapse and the
    /// left-part watches; then the engine's verdict in stats.stop (snake/stop.h).
    void End(SnakeCurve &st, SnakeStats &stats, double maxMove, const Positions &pos)
    {
        updateConvergence(st, stats, maxMove, pos);
        checkCollapse(st, stats, pos);
        checkLeftPart(st, stats, pos);
        if (stats.stopped) return; // stop and stopMessage were set by the watch that stopped it
        stats.stop = stats.converged ? SnakeStop::Converged : SnakeStop::Running;
        stats.stopMessage = stats.converged ? "converged" : "";
    }

    static vcg::Point3d Centroid(const Positions &p)
    {
        vcg::Point3d c(0, 0, 0);
        for (const auto &x : p) c += x;
        return p.empty() ? c : c / double(p.size());
    }

    /// How far the curve moved: each new sample's distance to the old curve near it. Sliding
    /// along the curve does not change the curve, so it does not count.
    static double CurveMove(const Positions &a, const Positions &b, bool closed)
    {
        return WorstMove(SampleMoves(a, b, closed), a.size(), b.size());
    }

    /// CurveMove from SampleMoves(a, b) already measured (d), a and b holding na and nb samples.
    static double WorstMove(const std::vector<double> &d, size_t na, size_t nb)
    {
        if (d.size() != na || nb != na) return 1e9;
        double worst = 0;
        for (double v : d) worst = std::max(worst, v);
        return worst;
    }

    /// CurveMove for each sample of b: its distance to the old curve a near it (empty if the
    /// sample counts differ).
    static std::vector<double> SampleMoves(const Positions &a, const Positions &b, bool closed)
    {
        const int n = int(a.size());
        std::vector<double> out;
        if (int(b.size()) != n) return out;
        out.reserve(n);
        for (int i = 0; i < n; ++i) {
            double best = (b[i] - a[i]).Norm();
            for (int j = i - 2; j <= i + 1; ++j) {
                int j0 = j, j1 = j + 1;
                if (closed) { j0 = (j0 + n) % n; j1 = (j1 + n) % n; }
                else if (j0 < 0 || j1 >= n) continue;
                const vcg::Point3d d = a[j1] - a[j0];
                const double L2 = d.SquaredNorm();
                const double t = L2 > 0 ? std::max(0.0, std::min(1.0, ((b[i] - a[j0]) * d) / L2)) : 0.0;
                best = std::min(best, (b[i] - (a[j0] + d * t)).Norm());
            }
            out.push_back(best);
        }
        return out;
    }

    /// Length of the sample polygon.
    static double LoopLength(const Positions &p, bool closed)
    {
        double L = 0;
        for (size_t i = 0; i + (closed ? 0 : 1) < p.size(); ++i) L += (p[(i + 1) % p.size()] - p[i]).Norm();
        return L;
    }

private:
    const Surface *surf;
    Param param;
    State state;
    // inWells' probe order, a cost heuristic and not the run's state: per sample, the side whose
    // probe found no well last time (1: ahead across, 2: behind), 0 if none
    mutable std::vector<unsigned char> wellMiss;

    /// Where a run starts: the finest level whose wells the samples already sit in (on level 0
    /// also with a mean energy below 0.7: feature-like, not a noise dip), else the coarsest. A
    /// snake seeded on a feature is not dragged off it by a coarse level, which merges it with
    /// a parallel feature a few edges away into one well between them.
    int startLevel(const SnakeCurve &st, const Positions &pos) const
    {
        const int top = surf->Levels() - 1;
        for (int l = 0; l < top; ++l) {
            if (l == 0) {
                double e = 0;
                for (const auto &s : st.samples) e += surf->EnergyAt(0, s.p);
                if (e >= 0.7 * double(st.samples.size())) continue;
            }
            if (inWells(st, pos, l)) return l;
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
    bool inWells(const SnakeCurve &st, const Positions &p, int level) const
    {
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
                // The probe is d from the sample, so its closest point lies within d of it; 1.5 d
                // leaves room for the search around bends (3 d flooded 4x the faces, same answers).
                const SurfacePoint q = SurfaceProjection<MeshType>::Closest(*surf, s.p.face, p[i] + across * (side * d), 1.5 * d);
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
    static double heldShare(const SnakeCurve &st)
    {
        int free = 0, held = 0;
        for (const auto &s : st.samples)
            if (!s.fixed) ++free, held += s.heldFine;
        return free ? double(held) / free : 0.0;
    }

    // Convergence: the largest move per operation stays below the tolerance for `window`
    // operations, or -- robust to oscillation and jitter -- the curve as a whole has not moved
    // farther than twice the tolerance over the last 2 * window operations.
    void updateConvergence(SnakeCurve &st, SnakeStats &stats, double maxMove, const Positions &pos)
    {
        const double tol = st.params.convergenceTol;
        const int W = st.params.convergenceWindow;
        state.moves.push_back(maxMove);
        while (int(state.moves.size()) > W) state.moves.pop_front();
        state.travels.push_back(maxMove);
        while (int(state.travels.size()) > 2 * W) state.travels.pop_front();
        const bool still = int(state.moves.size()) == W &&
                           std::all_of(state.moves.begin(), state.moves.end(), [&](double v) { return v < tol; });
        state.positions.push_back(pos);
        while (int(state.positions.size()) > 2 * W + 1) state.positions.pop_front();
        bool oscillating = false;
        std::vector<double> netMoves; // each sample's net move over the window: the stall test reads them too
        if (int(state.positions.size()) == 2 * W + 1) {
            // net displacement of the curve over the window against the way travelled: a curve
            // that only jitters in place (a sample bouncing at a corner) has gone nowhere
            const Positions &a = state.positions.front(), &b = state.positions.back();
            netMoves = SampleMoves(a, b, st.closed);
            const double net = WorstMove(netMoves, a.size(), b.size()) / st.unit;
            const double travelled = std::accumulate(state.travels.begin(), state.travels.end(), 0.0);
            oscillating = net < 2 * tol || (net < 5 * tol && net < 0.25 * travelled);
        }
        const int level = Level();
        const bool stall = level == 0 && stalled(st, tol, W, netMoves); // every level-0 operation: its energy window stays aligned
        stats.converged = still || oscillating || stall;
        if (level == 0) return;
        // On a coarse level the snake only has to reach its wells: it steps down to the next
        // finer level as soon as its samples sit in them and it moves by less than 0.3 units per
        // operation, settled or not (the cusp of a smoothed well keeps it bouncing by about that
        // much). From level 1 to level 0 it settles first: level 0 is flat across the chamfer
        // that triangles straddling a crease cut, so samples stay about where they land in it.
        // Settling outside the wells is a stall: retry once with full steps, then step down
        // anyway (a snake held by its own tension, or no well there). Samples held at level-0
        // wells (SnakeMotionRules::HoldAtWell) already move on level 0 and count as in the
        // wells; once all are held, the whole snake goes there. Not sooner: stretches that lag
        // behind (a loop seeded far up an octahedron's corners while its middle reached the
        // equator) need the coarse levels' reach. Every switch resets the step control.
        if (heldShare(st) >= 1.0) {
            state.stage = 0;
            state.settledOutside = false;
        } else if (((level == 1 ? stats.converged : maxMove < 0.3) && inWells(st, pos, level)) ||
                   (stats.converged && state.settledOutside)) {
            state.stage = level - 1;
            state.settledOutside = false;
        } else if (stats.converged) {
            state.settledOutside = true;
        } else {
            return;
        }
        for (auto &smp : st.samples) smp.trust = 1.0;
        stats.converged = false;
        state.moves.clear();
        state.travels.clear();
        state.positions.clear();
        state.energies.clear();
    }

    /// The stall test (Param): called on level 0 after state.positions took this operation's
    /// positions; d: SampleMoves from the window's first positions to its last, as the
    /// oscillation test measured them (empty until the window is full). Measuring them again
    /// here was 80 % of the test's cost (bench_geometric_snake BM_StallTest, session 30).
    bool stalled(const SnakeCurve &st, double tol, int W, const std::vector<double> &d)
    {
        if (!param.stall || st.samples.empty()) return false;
        double e = 0;
        for (const auto &s : st.samples) e += surf->EnergyAt(0, s.p);
        e /= double(st.samples.size());
        state.energies.push_back(e);
        while (int(state.energies.size()) > 2 * W + 1) state.energies.pop_front();
        if (int(state.positions.size()) != 2 * W + 1 || int(state.energies.size()) != 2 * W + 1) return false;
        if (d.empty()) return false;
        double mean = 0;
        for (double v : d) mean += v;
        mean /= double(d.size()) * st.unit;
        const double fell = state.energies.front() - e;
        return mean < param.meanMove * tol && fell < param.fall;
    }

    /// A closed snake that shrinks where no feature holds it would end as a point and report
    /// convergence: stop it instead and say so. Collapsing: still shrinking (or settled) after
    /// losing three quarters of its length since the run started, or less than 2 length units
    /// long. Its samples then sit on top of each other, whatever the energy there.
    void checkCollapse(const SnakeCurve &st, SnakeStats &stats, const Positions &pos)
    {
        if (!st.closed || pos.size() < 3) return;
        const double L = LoopLength(pos, true);
        if (state.runLength < 0) state.runLength = std::max(L, state.lastLength);
        const bool shrinking = state.lastLength > 0 && L < state.lastLength - 1e-6 * st.unit;
        state.lastLength = L;
        const bool tiny = L < 2 * st.unit;
        if (!(tiny || ((shrinking || stats.converged) && L < 0.25 * state.runLength))) return;
        double e = 0; // for the message alone (it was read after every operation)
        for (const auto &s : st.samples) e += surf->EnergyAt(0, s.p);
        e /= double(st.samples.size());
        char msg[300];
        std::snprintf(msg, sizeof msg,
                      "the closed snake is collapsing where no feature holds it (length %.3g, %.0f %% of its length "
                      "at the start, mean energy %.2f): stopped. Seed it closer to the feature, or inflate it with "
                      "a positive Balloon.", L, 100.0 * L / std::max(state.runLength, 1e-300), e);
        stopRun(stats, SnakeStop::Collapsed, msg);
    }

    /// A closed snake that slides along a part (a loop round a finger drifting to the palm or
    /// to the tip) is no longer round the part it was seeded around: stop it instead of letting
    /// it settle somewhere else. Left: its centroid is farther from where it started than twice
    /// the sum of the two radii (length / 2 pi), and at least 8 length units -- a loop that
    /// settles on a boundary a few rings away, or inflates round its start, never moves so far.
    void checkLeftPart(const SnakeCurve &st, SnakeStats &stats, const Positions &pos)
    {
        if (!st.closed || pos.size() < 3 || stats.stopped || state.runLength <= 0) return;
        const double r0 = state.runLength / (2 * M_PI), r = LoopLength(pos, true) / (2 * M_PI);
        const double d = (Centroid(pos) - state.runCentre).Norm();
        if (!(d > 2 * (r0 + r) && d > 8 * st.unit)) return;
        char msg[300];
        std::snprintf(msg, sizeof msg,
                      "the closed snake left the part it surrounded (its centre moved %.3g length units, its radius "
                      "%.3g at the start, %.3g now): stopped. Seed it closer to the part's boundary, or pin a "
                      "sample there.", d / st.unit, r0 / st.unit, r / st.unit);
        stopRun(stats, SnakeStop::LeftPart, msg);
    }

    /// The engine's stop: once per run in the warnings (a Run again repeats it only if it
    /// stops again after moving on).
    static void stopRun(SnakeStats &stats, SnakeStop why, const std::string &msg)
    {
        const bool again = stats.stopped && stats.stop == why;
        stats.stopped = true;
        stats.converged = false;
        stats.stop = why;
        stats.stopMessage = msg;
        if (!again && stats.warnings.size() < 20) stats.warnings.push_back(msg);
    }
};

} // namespace tri
} // namespace vcg

#endif
