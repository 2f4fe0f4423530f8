#ifndef VCG_EXT_STROKE_LOOP_H
#define VCG_EXT_STROKE_LOOP_H

// Contour completion (Lee, Lee, Shamir, Cohen-Or and Seidel, "Intelligent Mesh Scissoring Using
// 3D Snakes", Pacific Graphics 2004, Sec. 4): the user draws one open stroke across a part -- a
// limb, a finger, an ear -- from one side of it to the other on the side facing them; the stroke
// is completed into a closed loop round the part by the shortest way back round the hidden side.
// The way back is a minimal path between the stroke's ends (paths/seed_path.h, with the user's path
// cost) that keeps off the stroke and off the side the stroke was drawn on, except near the
// ends, where it leaves and rejoins it. The loop is the initial curve of a closed snake.

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <vcg_ext/paths/seed_path.h>
#include <vcg_ext/snake/error.h>
#include <vcg_ext/surface/surface_point.h>

namespace vcg {
namespace tri {

/// A path cost (paths/seed_path_cost.h) that refuses the edges at blocked vertices: the way back of
/// a stroke may not use them.
template <class Base>
class AvoidingPathCost
{
public:
    static constexpr bool StraightIsCheapest = false; // the straight line would cross the stroke

    AvoidingPathCost(const Base &base, const std::vector<char> &blocked) : base_(base), blocked_(blocked) {}

    double operator()(int a, int b) const
    {
        return blocked_[a] || blocked_[b] ? std::numeric_limits<double>::infinity() : base_(a, b);
    }
    double operator()(const SurfacePoint &p, int v) const { return base_(p, v); }
    double operator()(const SurfacePoint &a, const SurfacePoint &b) const { return base_(a, b); }
    double LowerBoundPerLength() const { return base_.LowerBoundPerLength(); }

private:
    const Base &base_;
    const std::vector<char> &blocked_;
};

template <class MeshType>
class StrokeLoop
{
public:
    typedef typename MeshType::FaceType FaceType;
    typedef typename MeshType::VertexType VertexType;

    struct Param
    {
        SeedPathCost cost = SeedPathCost::Length; ///< the stroke's own path and the way back
        double featureEpsilon = 0.05;             ///< of SeedPathCost::Feature
        /// The way back keeps this far from the stroke (in length units: the median edge length
        /// of the stroke's faces) ...
        double clearance = 2.0;
        /// ... and off the stroke's side (vertex normals facing the viewer by more than
        /// `facing`: the cosine to `view`), except within `endCap` length units of its ends.
        double facing = 0.2;
        double endCap = 4.0;
        /// Towards the viewer (the edit tool's view); zero: the mean normal under the stroke,
        /// the side it was drawn on.
        vcg::Point3d view = vcg::Point3d(0, 0, 0);
    };

    struct Result
    {
        std::vector<SurfacePoint> loop; ///< closed (first point not repeated): the stroke, then the way back
        int strokePoints = 0;           ///< loop[0 .. strokePoints - 1] is the stroke's path
        double strokeLength = 0, backLength = 0;
        double unit = 0; ///< the length unit of Param's distances
    };

    /// Completes the open stroke `stroke` (at least 2 surface points, in drawing order) into a
    /// loop round the part it crosses. Throws SnakeError when there is no way back (the stroke
    /// does not cross a part from one side to the other, or the mesh is cut there).
    static Result Complete(MeshType &m, const std::vector<SurfacePoint> &stroke, const Param &p = Param())
    {
        if (stroke.size() < 2)
            throw SnakeError("Geometric snake: a stroke to complete into a loop needs at least 2 points (" +
                             std::to_string(stroke.size()) + " given).");
        if (!(p.clearance >= 0) || !(p.endCap > p.clearance) || !(p.facing >= -1 && p.facing <= 1))
            throw SnakeError("Geometric snake: bad loop completion parameters (need 0 <= clearance < end cap, facing in [-1, 1]).");
        typedef typename SeedPath<MeshType>::PointResult Path;
        const Path there = SeedPath<MeshType>::ComputeFromPoints(m, stroke, false, p.cost, p.featureEpsilon);
        Result r;
        r.unit = unitOf(m, there.points);
        r.strokeLength = there.length;
        const std::vector<char> blocked = blockedVertices(m, there.points, r.unit, p);
        const SurfacePoint a = there.points.front(), b = there.points.back();
        Path back;
        try {
            if (p.cost == SeedPathCost::Feature) {
                FeaturePathCost<MeshType> base(m, p.featureEpsilon);
                back = SeedPath<MeshType>::ComputeFromPointsWith(m, {b, a}, false, AvoidingPathCost<FeaturePathCost<MeshType>>(base, blocked));
            } else {
                LengthPathCost<MeshType> base(m);
                back = SeedPath<MeshType>::ComputeFromPointsWith(m, {b, a}, false, AvoidingPathCost<LengthPathCost<MeshType>>(base, blocked));
            }
        } catch (const SnakeError &) {
            throw SnakeError("Geometric snake: the stroke cannot be completed into a loop: no way back between its "
                             "ends round the side it was not drawn on. Draw it across the part, from one side of "
                             "it to the other.");
        }
        r.backLength = back.length;
        r.loop = there.points;
        r.strokePoints = int(r.loop.size());
        for (size_t i = 1; i + 1 < back.points.size(); ++i) r.loop.push_back(back.points[i]);
        if (r.loop.size() < 3) throw SnakeError("Geometric snake: the completed loop is degenerate (the stroke is too short).");
        return r;
    }

private:
    static vcg::Point3d P(const VertexType &v) { return vcg::Point3d::Construct(v.cP()); }

    /// The median edge length of the faces under the path.
    static double unitOf(const MeshType &m, const std::vector<SurfacePoint> &pts)
    {
        std::vector<double> e;
        for (const auto &s : pts) {
            const FaceType &f = m.face[s.face];
            for (int k = 0; k < 3; ++k) e.push_back(vcg::Distance(P(*f.cV(k)), P(*f.cV((k + 1) % 3))));
        }
        std::nth_element(e.begin(), e.begin() + e.size() / 2, e.end());
        return e[e.size() / 2] > 0 ? e[e.size() / 2] : 1.0;
    }

    /// Vertices the way back may not use: near the stroke or facing its side, outside the caps
    /// round its ends.
    static std::vector<char> blockedVertices(const MeshType &m, const std::vector<SurfacePoint> &path, double unit,
                                             const Param &p)
    {
        std::vector<vcg::Point3d> pl;
        for (const auto &s : path) pl.push_back(s.Pd(m));
        // per-vertex normals, area weighted, of the faces (the mesh's own are left as they are)
        std::vector<vcg::Point3d> vn(m.vert.size(), vcg::Point3d(0, 0, 0));
        for (const FaceType &f : m.face) {
            if (f.IsD()) continue;
            const vcg::Point3d n = (P(*f.cV(1)) - P(*f.cV(0))) ^ (P(*f.cV(2)) - P(*f.cV(0)));
            for (int k = 0; k < 3; ++k) vn[tri::Index(m, f.cV(k))] += n;
        }
        vcg::Point3d view = p.view;
        if (!(view.Norm() > 0)) // the side the stroke was drawn on
            for (const auto &s : path) {
                const FaceType &f = m.face[s.face];
                view += ((P(*f.cV(1)) - P(*f.cV(0))) ^ (P(*f.cV(2)) - P(*f.cV(0)))).Normalize();
            }
        if (view.Norm() > 0) view.Normalize();
        const double clear = p.clearance * unit, cap = p.endCap * unit;
        vcg::Box3d box;
        for (const auto &x : pl) box.Add(x);
        box.Offset(clear);
        std::vector<char> blocked(m.vert.size(), 0);
        for (size_t v = 0; v < m.vert.size(); ++v) {
            if (m.vert[v].IsD()) continue;
            const vcg::Point3d x = P(m.vert[v]);
            if (vcg::Distance(x, pl.front()) < cap || vcg::Distance(x, pl.back()) < cap) continue;
            const double l = vn[v].Norm();
            if (l > 0 && (vn[v] / l) * view > p.facing) {
                blocked[v] = 1;
                continue;
            }
            if (!box.IsIn(x)) continue;
            for (size_t i = 0; i + 1 < pl.size() && !blocked[v]; ++i) blocked[v] = distToSegment(x, pl[i], pl[i + 1]) < clear;
        }
        return blocked;
    }

    static double distToSegment(const vcg::Point3d &x, const vcg::Point3d &a, const vcg::Point3d &b)
    {
        const vcg::Point3d d = b - a;
        const double L2 = d.SquaredNorm();
        const double t = L2 > 0 ? std::max(0.0, std::min(1.0, ((x - a) * d) / L2)) : 0.0;
        return vcg::Distance(x, a + d * t);
    }
};

} // namespace tri
} // namespace vcg

#endif
