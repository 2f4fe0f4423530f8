#ifndef VCG_EXT_SNAKE_SEGMENT_MOTION_H
#define VCG_EXT_SNAKE_SEGMENT_MOTION_H

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include <vcg_ext/embedding/kept_embeddings.h>
#include <vcg_ext/embedding/local_region.h>
#include <vcg_ext/embedding/region_walk.h>
#include <vcg_ext/embedding/virtual_boundary_param.h>
#include <vcg_ext/snake/curve.h>
#include <vcg_ext/snake/motion_rules.h>
#include <vcg_ext/snake/partition.h>
#include <vcg_ext/snake/segment_region.h>
#include <vcg_ext/snake/spline.h>
#include <vcg_ext/surface/face_path.h>
#include <vcg_ext/surface/snake_surface.h>
#include <vcg_ext/surface/surface_point.h>
#include <vcg_ext/surface/surface_projection.h>

namespace vcg {
namespace tri {

/// How a snake moves by the paper's method (Sec. 5): one segment at a time in the plane of a
/// local embedding. Owns the scratch state reused across operations: the kept embeddings
/// (SnakeKeptEmbeddings), the factored spline systems and a workspace. The naive method of
/// Sec. 4.2 is SnakeProjectionMotion; a segment's region and its embedding are made by
/// SnakeSegmentRegion; the rules both follow are SnakeMotionRules. The session
/// (creation, editing, undo, convergence) is GeometricSnake's business.
template <class MeshType>
class SnakeSegmentMotion : public SnakeMotionRules<MeshType>
{
    typedef SnakeMotionRules<MeshType> Rules;

public:
    typedef typename MeshType::FaceType FaceType;
    typedef SnakeSurface<MeshType> Surface;
    typedef SnakeEmbedding<MeshType> Embedding;

    explicit SnakeSegmentMotion(std::shared_ptr<Surface> s) : Rules(s), regions(std::move(s)) {}

    /// Embeddings that fell back to the virtual boundary (SnakeSegmentRegion::Build).
    int ConformalFallbacks() const { return regions.conformalFallbacks; }

    /// Forget the factored spline systems (parameters or samples changed).
    void ClearCache()
    {
        splines.Clear();
        ForgetEmbeddings();
    }
    /// Forget the kept embeddings (samples were edited, inserted or deleted).
    void ForgetEmbeddings() { kept.Clear(); }
    /// Samples were inserted into an open snake of `before` samples (SnakeGapRefine inserts
    /// none into closed ones): the kept embeddings follow them.
    void SamplesInserted(const std::vector<int> &inserted, int before) { kept.SamplesInserted(inserted, before); }
    /// How many embeddings are kept (one may serve several segments).
    int KeptEmbeddings() const { return kept.Count(); }
    /// A new operation (SnakeKeptEmbeddings::BeginOperation).
    void BeginOperation() { kept.BeginOperation(); }

    /// Moves one segment (Sec. 5.2 - 5.4): local region, embedding, up to `updates` updates of
    /// Eq. 4 in the plane, back by barycentric coordinates, then retraces its gaps (Sec. 4.1).
    /// `updates` = 0 only retraces. `level`: energy level; `unit`: the snake's length unit.
    void Move(SnakeCurve &st, SnakeStats &stats, const SnakeSegment &seg, int updates, const SnakeMotionFrame &fr,
              int depth = 0)
    {
        const int level = fr.level;
        const double unit = fr.unit;
        const bool faceLinear = surf->EnergyField().FaceLinear();
        const int k = int(seg.idx.size());
        if (k < 2) return;
        auto t0 = SnakeClock::Now();
        bool wholeClosed = st.closed && k == int(st.samples.size()) && seg.idx.front() == 0 && !seg.fixFirst;
        int gapsInSeg = wholeClosed ? k : k - 1;
        // Sec. 4.2: one embedding serves several updates, here several operations: an embedding
        // is kept while the samples of a segment stay well inside it, and it serves whichever
        // segment they form (the partition's borders move with the corners of the curve).
        std::vector<int> &lf = work.lf;
        Eigen::MatrixXd &X = work.X;
        lf.resize(k);
        X.resize(k, 2);
        Embedding *embedding = nullptr;
        const bool reused = kept.Acquire(st, seg, lf, X, embedding);
        if (reused) stats.reuses++;
        Embedding &E = *embedding;
        if (!reused) {
            E.valid = false;
            if (!regions.Build(st, seg, gapsInSeg, unit, E, lf, X)) { // Sec. 5.2 - 5.3
                if (k >= 8 && depth < 6) { // split the segment (Sec. 5.1) and try the halves
                    SnakeSegment a, b;
                    int mid = k / 2;
                    a.idx.assign(seg.idx.begin(), seg.idx.begin() + mid + 1);
                    b.idx.assign(seg.idx.begin() + mid, seg.idx.end());
                    a.fixFirst = seg.fixFirst; a.fixLast = true;
                    b.fixFirst = true; b.fixLast = seg.fixLast;
                    Move(st, stats, a, updates, fr, depth + 1);
                    Move(st, stats, b, updates, fr, depth + 1);
                    return;
                }
                stats.regionFailures++;
                std::string why = E.region.error.empty() ? E.emb.error : E.region.error;
                if (stats.warnings.size() < 20) stats.warnings.push_back("a segment could not move: " + why);
                return;
            }
            stats.embeddings++;
            stats.msEmbedding.push_back(SnakeClock::MsSince(t0));
        }
        const LocalRegion<MeshType> &region = E.region;
        const VirtualBoundaryParam::Result &emb = E.emb;

        // Sec. 6.2: the energy gradient at a sample, mapped into the plane. The field gives it
        // in space; its derivatives along two face edges are invariant, so in the plane it is
        // J^-T (g . e1, g . e2) with J the embedded edges. J^-T is kept per face with the embedding.
        auto gradient = [&](int lev, int t, const Eigen::RowVector3d &bary) -> Eigen::Vector2d {
            const auto &T = region.tri[t];
            vcg::Point3d g = surf->EnergyGradient(lev, SurfacePoint(region.faces[t], toPoint(bary)));
            Eigen::Vector2d d(g * (region.pos[T[1]] - region.pos[T[0]]), g * (region.pos[T[2]] - region.pos[T[0]]));
            return E.JinvT(t) * d;
        };
        // an open end's way straight across the feature (acrossFeatureEnd): the field's direction
        // in space (`a`), mapped into the plane as a vector (not a gradient), unit length
        auto acrossFeature = [&](int lev, int t, const Eigen::RowVector3d &bary, Eigen::Vector2d &u, vcg::Point3d &a) -> bool {
            if (!surf->EnergyField().AcrossFeature(lev, SurfacePoint(region.faces[t], toPoint(bary)), a)) return false;
            const auto &T = region.tri[t];
            const vcg::Point3d e1 = region.pos[T[1]] - region.pos[T[0]], e2 = region.pos[T[2]] - region.pos[T[0]];
            Eigen::Matrix2d G;
            G << e1 * e1, e1 * e2, e1 * e2, e2 * e2;
            if (!(std::abs(G.determinant()) > 1e-30)) return false;
            const Eigen::Vector2d ab = G.inverse() * Eigen::Vector2d(a * e1, a * e2);
            u = ab[0] * (E.emb.uv[T[1]] - E.emb.uv[T[0]]) + ab[1] * (E.emb.uv[T[2]] - E.emb.uv[T[0]]);
            const double l = u.norm();
            if (!(l > 0) || !u.allFinite()) return false;
            u /= l;
            return true;
        };
        std::vector<bool> fixed(k);
        for (int j = 0; j < k; ++j)
            fixed[j] = st.samples[seg.idx[j]].fixed || (j == 0 && seg.fixFirst) || (j == k - 1 && seg.fixLast);
        Eigen::MatrixXd &B = work.B; // barycentric coordinates of each sample in its local face
        B.resize(k, 3);
        for (int j = 0; j < k; ++j) {
            const auto &b = st.samples[seg.idx[j]].p.bary;
            B.row(j) << b[0], b[1], b[2];
        }
        if (updates > 0) {
            SnakeSpline &spline = splines.For(k, wholeClosed, st.params.alpha, st.params.beta, st.params.gamma, fixed);
            Eigen::MatrixXd &F = work.F;
            F.resize(k, 2);
            std::vector<double> &slope = work.slope;
            slope.assign(k, 0.0);
            std::vector<Eigen::Vector2d> &across = work.across, &pull = work.pull, &crossing = work.crossing;
            across.assign(k, Eigen::Vector2d::Zero());
            pull.assign(k, Eigen::Vector2d::Zero());
            crossing.assign(k, Eigen::Vector2d::Zero());
            std::vector<vcg::Point3d> &crossingSpace = work.crossingSpace;
            crossingSpace.assign(k, vcg::Point3d(0, 0, 0));
            for (int u = 0; u < updates; ++u) {
                auto tu = SnakeClock::Now();
                for (int j = 0; j < k; ++j) {
                    // Only the feature force across the curve: along a feature valley the
                    // energy still varies a little, and its tangential part would slide the
                    // samples towards the strongest spots (corners) and bunch them there.
                    const int lev = SampleLevel(st.samples[seg.idx[j]], level);
                    const double gain = lev == level ? fr.gain : 1.0;
                    const Eigen::Vector2d g = gradient(lev, lf[j], B.row(j));
                    slope[j] = g.norm();
                    if (lev > 0 && faceLinear) pull[j] = g; // alongPullBlend
                    else if (st.IsOpenEnd(seg.idx[j]) && !acrossFeature(lev, lf[j], B.row(j), crossing[j], crossingSpace[j]))
                        crossing[j].setZero();
                    Eigen::Vector2d f = st.params.externalWeight * gain * g;
                    Eigen::Vector2d t = (X.row(wholeClosed ? (j + 1) % k : std::min(j + 1, k - 1)) -
                                         X.row(wholeClosed ? (j - 1 + k) % k : std::max(j - 1, 0))).transpose();
                    if (t.norm() > 0) {
                        t.normalize();
                        // (an end moving straight across the feature takes the whole pull: it
                        // cannot slide along the feature, acrossFeatureEnd)
                        if (crossing[j].norm() == 0) f -= f.dot(t) * t;
                        across[j] = Eigen::Vector2d(t.y(), -t.x());
                        if (lev == 0 && faceLinear) { // the across slope, averaged (see acrossSlope)
                            const Eigen::Vector2d nrm(t.y(), -t.x());
                            double a;
                            if (acrossSlope(E, lf[j], X.row(j).transpose(), nrm, a))
                                f = st.params.externalWeight * gain * a * nrm;
                        }
                        // balloon (beyond the paper, as in image snakes): a pressure along the
                        // outward normal; f is a gradient, so it pushes against it
                        if (fr.outside != 0)
                            f -= balloonPressure(st.params, fr, SurfacePoint(region.faces[lf[j]], toPoint(B.row(j)))) *
                                 Eigen::Vector2d(t.y(), -t.x());
                    }
                    F.row(j) = f.transpose();
                }
                Eigen::MatrixXd &Xn = work.Xn;
                spline.Update(X, F, Xn);
                bool left = false;
                for (int j = 0; j < k; ++j) {
                    if (fixed[j]) continue;
                    Eigen::Vector2d d = (Xn.row(j) - X.row(j)).transpose();
                    if (!d.allFinite()) continue;
                    if (st.IsOpenEnd(seg.idx[j]))
                        d = pull[j].norm() > 0 ? alongPullBlend(d, pull[j], Rules::template acrossEnd<Eigen::Vector2d>(X, j, d))
                            : crossing[j].norm() > 0 ? acrossFeatureEnd(d, crossing[j])
                                                     : Rules::template acrossEnd<Eigen::Vector2d>(X, j, d);
                    double len = d.norm();
                    double cap = len > 0 ? st.params.maxStep * st.samples[seg.idx[j]].trust * E.WidthAlong(lf[j], d / len) : 0;
                    if (len > cap) d *= cap / len;
                    if (len == 0) continue;
                    RegionWalk::Result &w = work.walk;
                    RegionWalk::Walk(emb.uv, region.tri, region.adj, lf[j], X.row(j).transpose(), X.row(j).transpose() + d,
                                     false, w);
                    if (st.IsOpenEnd(seg.idx[j]) && pull[j].norm() == 0 && crossing[j].norm() > 0)
                        straightInSpace(E, lf[j], B.row(j), d, crossing[j], crossingSpace[j], w);
                    SnakeSample &smp = st.samples[seg.idx[j]];
                    const int lev = SampleLevel(smp, level);
                    const SurfacePoint pOld(region.faces[lf[j]], toPoint(B.row(j))), pNew(region.faces[w.face], toPoint(w.bary));
                    double eOld = surf->EnergyAt(lev, pOld);
                    double eNew = surf->EnergyAt(lev, pNew);
                    UpdateTrust(smp.trust, lev, eOld, eNew, slope[j] * std::min(len, cap));
                    if (level > 0 && !st.closed) { // open snakes only (HoldAtWell)
                        const Eigen::Vector2d x1 = E.ToPlane(w.face, w.bary);
                        const Eigen::Vector2d x0 = X.row(j).transpose();
                        smp.heldFine = HoldAtWell(smp.heldFine, pOld, pNew, d, across[j], Eigen::Vector2d(-across[j].y(), across[j].x()),
                                                  level, [&](const Eigen::Vector2d &v, bool ahead, SurfacePoint &q) {
                                                      return planeProbe(E, ahead ? w.face : lf[j], ahead ? x1 : x0, v, q);
                                                  });
                    }
                    lf[j] = w.face;
                    B.row(j) = w.bary.transpose();
                    X.row(j) = E.ToPlane(w.face, w.bary).transpose();
                    left |= w.exited;
                }
                stats.updates++;
                stats.msUpdate.push_back(SnakeClock::MsSince(tu));
                if (left) { // the curve reached the region border: re-embed (Sec. 5.4)
                    E.valid = false;
                    break;
                }
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
            int g = st.GapIndex(seg.idx[a], seg.idx[b]);
            if (g < 0) continue;
            RegionWalk::Result &w = work.walk;
            RegionWalk::Walk(emb.uv, region.tri, region.adj, lf[a], X.row(a).transpose(), X.row(b).transpose(), true, w);
            SnakeGap &gap = st.gaps[g]; // cleared, not replaced: its lists keep their memory
            gap.faces.clear();
            gap.crossings.clear();
            gap.traced = false;
            gap.tightenPending = false;
            if (w.exited) { // leaves the region (non-convex border): re-project next time
                E.valid = false;
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
            // straight in the plane is not shortest on the surface where the embedding is
            // distorted (slivers): the shortest path through the same faces (paths/path_tighten.h),
            // taken when the polyline is read (GeometricSnake::tightenGaps)
            gap.tightenPending = true;
            gap.tracedFrom = st.samples[seg.idx[a]].p;
            gap.tracedTo = st.samples[seg.idx[b]].p;
            gap.traced = true;
        }
    }

private:
    template <class V>
    static vcg::Point3d toPoint(const V &b) { return vcg::Point3d(b[0], b[1], b[2]); }

    /// The precise level is linear in each face: across a crease it is a V whose slope does
    /// not fade at the bottom, so every sample is pulled with full force onto the mesh's own
    /// fold line, which zigzags between the vertices nearest the feature, and the rigidity
    /// (beta) cannot straighten the curve: turns of 11-18 degrees between segments on a
    /// straight crease (level 0 alone). The slope across the curve is taken instead as the central difference
    /// of the energy from -r to +r, r = kAcrossReach times the width of the sample's triangle
    /// in that direction (at most that times the length unit): the mean slope over that
    /// stretch, i.e. level 0 box-smoothed across the curve over about one and a half triangles.
    /// Near the bottom it fades linearly, a spring, and beta wins against the zigzag; farther
    /// out it is the slope itself. False when a probe leaves the region.
    bool acrossSlope(Embedding &E, int t, const Eigen::Vector2d &x, const Eigen::Vector2d &nrm, double &slope)
    {
        const double r = Rules::kAcrossReach * std::min(E.WidthAlong(t, nrm), 1.0); // plane units: 1 = the length unit
        double lo, hi;
        if (!acrossEnergies(E, t, x, nrm, r, lo, hi)) return false;
        slope = (hi - lo) / (2 * r);
        return true;
    }
    /// An open end moving straight across its feature (acrossFeatureEnd) moves straight in space:
    /// the plane move d (along the way across, `u` in the plane, `a` in space) is taken as the
    /// space step it is in the end's own face, and the end goes to the surface point nearest
    /// x + s a. The plane walk bends wherever the embedding is not conformal: on a cap of 50:1
    /// slivers the same way across maps 90 degrees apart in neighbouring faces, and an end that
    /// crossed them walked along the rim (ear-clipped cap, 85 % of the span covered). Where the
    /// point is not in the region the walk `w` stands.
    void straightInSpace(Embedding &E, int t, const Eigen::RowVector3d &bary, const Eigen::Vector2d &d,
                         const Eigen::Vector2d &u, const vcg::Point3d &a, RegionWalk::Result &w)
    {
        const auto &T = E.region.tri[t];
        Eigen::Matrix2d J;
        J.col(0) = E.emb.uv[T[1]] - E.emb.uv[T[0]];
        J.col(1) = E.emb.uv[T[2]] - E.emb.uv[T[0]];
        if (!(std::abs(J.determinant()) > 1e-30) || !(a.SquaredNorm() > 0)) return;
        const Eigen::Vector2d ab = J.inverse() * (d.dot(u) * u);
        const vcg::Point3d v = (E.region.pos[T[1]] - E.region.pos[T[0]]) * ab[0] + (E.region.pos[T[2]] - E.region.pos[T[0]]) * ab[1];
        const double step = v * a;
        if (!std::isfinite(step) || step == 0) return;
        const SurfacePoint p0(E.region.faces[t], toPoint(bary));
        const SurfacePoint q = SurfaceProjection<MeshType>::Closest(*surf, p0.face, p0.Pd(surf->Mesh()) + a * step,
                                                                    1.5 * std::abs(step));
        const int tq = q.face < 0 ? -1 : E.LocalFace(q.face);
        if (tq < 0 || tq >= E.region.RealFaces()) return;
        w.face = tq;
        w.bary = Eigen::Vector3d(q.bary[0], q.bary[1], q.bary[2]);
    }
    /// The surface point at x + v (plane), walking from local face t; false when it leaves the region.
    bool planeProbe(Embedding &E, int t, const Eigen::Vector2d &x, const Eigen::Vector2d &v, SurfacePoint &q)
    {
        RegionWalk::Result &w = work.probe;
        RegionWalk::Walk(E.emb.uv, E.region.tri, E.region.adj, t, x, x + v, false, w);
        if (w.exited) return false;
        q = SurfacePoint(E.region.faces[w.face], toPoint(w.bary));
        return true;
    }

    /// Level-0 energy at x -/+ r nrm (plane), walking from local face t.
    bool acrossEnergies(Embedding &E, int t, const Eigen::Vector2d &x, const Eigen::Vector2d &nrm, double r, double &lo,
                        double &hi)
    {
        if (!(r > 0)) return false;
        double e[2];
        for (int side = 0; side < 2; ++side) {
            RegionWalk::Result &w = work.probe;
            RegionWalk::Walk(E.emb.uv, E.region.tri, E.region.adj, t, x, x + (side ? r : -r) * nrm, false, w);
            if (w.exited) return false;
            e[side] = surf->EnergyAt(0, SurfacePoint(E.region.faces[w.face], toPoint(w.bary)));
        }
        lo = e[0], hi = e[1];
        return true;
    }


    using Rules::surf;
    using Rules::UpdateTrust;
    using Rules::SampleLevel;
    using Rules::HoldAtWell;
    using Rules::alongPullBlend;
    using Rules::acrossFeatureEnd;
    using Rules::balloonPressure;
    SnakeKeptEmbeddings<MeshType> kept;
    SnakeSegmentRegion<MeshType> regions;
    SnakeSplineCache splines;
    struct Workspace // reused by every segment move: no allocation in the steady state
    {
        std::vector<int> lf;
        Eigen::MatrixXd X, B, F, Xn;
        RegionWalk::Result walk, probe;
        std::vector<Eigen::Vector2d> across, pull; // the curve's normal, the coarse gradient (plane)
        std::vector<Eigen::Vector2d> crossing;     // an open end's way across the feature (acrossFeatureEnd) ...
        std::vector<vcg::Point3d> crossingSpace;   // ... and in space
        std::vector<double> slope;                 // the energy's slope at each sample
    } work;
};

} // namespace tri
} // namespace vcg

#endif
