#ifndef VCG_EXT_SNAKE_POLYLINE_H
#define VCG_EXT_SNAKE_POLYLINE_H

// The snake's curve on the surface between its samples (Sec. 4.1): per gap the faces the
// straight segment of the embedding crossed and its edge crossings (SnakeGap). The motion
// traces the gaps; this reads them as one polyline of surface points, keeps them in step with
// the samples (an edited or inserted sample leaves its gaps untraced) and finds points along a gap.

#include <algorithm>
#include <vector>

#include <vcg/space/point3.h>

#include <vcg_ext/paths/path_tighten.h>
#include <vcg_ext/snake/curve.h>
#include <vcg_ext/surface/face_path.h>
#include <vcg_ext/surface/snake_surface.h>
#include <vcg_ext/surface/surface_point.h>
#include <vcg_ext/surface/surface_projection.h>

namespace vcg {
namespace tri {

template <class MeshType>
class SnakePolyline
{
public:
    typedef typename MeshType::FaceType FaceType;
    typedef SnakeSurface<MeshType> Surface;

    /// Every gap has been traced since its samples were last placed.
    static bool Traced(const SnakeCurve &c)
    {
        bool missing = false;
        for (const auto &g : c.gaps) missing |= !g.traced;
        return !missing;
    }

    /// The samples and, between them, the gaps' points (GapPoints); closed curves do not
    /// repeat the first point. Tightens the traced gaps first.
    static std::vector<SurfacePoint> Points(const Surface &surf, SnakeCurve &c)
    {
        Tighten(surf, c);
        std::vector<SurfacePoint> out;
        int n = int(c.samples.size());
        for (int i = 0; i < n; ++i) {
            out.push_back(c.samples[i].p);
            if (i < c.NumGaps())
                for (const auto &p : GapPoints(surf, c, i, false)) out.push_back(p);
        }
        return out;
    }

    static std::vector<vcg::Point3d> Positions(const Surface &surf, const std::vector<SurfacePoint> &points)
    {
        std::vector<vcg::Point3d> out;
        for (const auto &p : points) out.push_back(p.Pd(surf.Mesh()));
        return out;
    }

    /// Takes `polyline` (the samples in order and the crossings between them, as Points gives)
    /// as c's traced gaps instead of tracing them anew (GeometricSnake::KeepPolyline). Returns
    /// false, changing nothing, when the polyline does not run through the samples in order or
    /// is not on the mesh.
    static bool Keep(const Surface &surf, SnakeCurve &c, const std::vector<SurfacePoint> &polyline)
    {
        const int n = int(c.samples.size()), gaps = c.NumGaps();
        auto isSample = [&](const SurfacePoint &p, int i) {
            const SurfacePoint &s = c.samples[i % n].p;
            return p.face == s.face && (p.bary - s.bary).Norm() <= 1e-9;
        };
        if (n < 2 || polyline.empty() || !isSample(polyline[0], 0)) return false;
        for (const auto &p : polyline)
            if (!p.OnMesh(surf.Mesh())) return false;
        std::vector<std::vector<SurfacePoint>> crossings(gaps);
        size_t at = 0;
        for (int g = 0; g < gaps; ++g) {
            const bool last = c.closed && g == n - 1; // runs to the polyline's end
            size_t next = at + 1;
            while (next < polyline.size() && !(!last && isSample(polyline[next], g + 1))) ++next;
            if (!last && next == polyline.size()) return false;
            crossings[g].assign(polyline.begin() + at + 1, polyline.begin() + next);
            at = next;
        }
        if (!c.closed && at + 1 != polyline.size()) return false;
        for (int g = 0; g < gaps; ++g) {
            SnakeGap &gap = c.gaps[g];
            gap = SnakeGap();
            gap.crossings = crossings[g];
            gap.traced = true; // as read: no tightening (gap.faces empty: the motion finds them)
            gap.tracedFrom = c.samples[g].p;
            gap.tracedTo = c.samples[(g + 1) % n].p;
        }
        return true;
    }

    /// The shortest path through each traced gap's faces (paths/path_tighten.h), once per trace,
    /// where the polyline is read: the motion does not read the crossings.
    static void Tighten(const Surface &surf, SnakeCurve &c)
    {
        for (int g = 0; g < int(c.gaps.size()); ++g) TightenGap(surf, c, g);
    }
    /// Tighten for gap g only.
    static void TightenGap(const Surface &surf, SnakeCurve &c, int g)
    {
        SnakeGap &gap = c.gaps[g];
        if (gap.traced && gap.tightenPending) {
            PathTighten<MeshType>::Tighten(surf.Mesh(), gap.tracedFrom, gap.crossings, gap.tracedTo);
            gap.tightenPending = false;
        }
    }

    /// Points strictly inside gap i (edge crossings); falls back to the shared-edge
    /// midpoints of the face path when the gap was never traced.
    static std::vector<SurfacePoint> GapPoints(const Surface &surf, const SnakeCurve &c, int g, bool withEnds = true)
    {
        const SnakeGap &gap = c.gaps[g];
        int n = int(c.samples.size());
        std::vector<SurfacePoint> out;
        if (withEnds) out.push_back(c.samples[g].p);
        if (gap.traced) {
            for (const auto &p : gap.crossings) out.push_back(p);
        } else {
            std::vector<int> fp = FacePath<MeshType>::Find(surf, c.samples[g].p.face, c.samples[(g + 1) % n].p.face);
            std::vector<SurfacePoint> mid;
            for (size_t k = 0; k + 1 < fp.size(); ++k) {
                const FaceType &f = surf.Mesh().face[fp[k]];
                for (int e = 0; e < 3; ++e)
                    if (surf.Idx(f.cFFp(e)) == fp[k + 1]) {
                        vcg::Point3d b(0, 0, 0);
                        b[e] = 0.5;
                        b[(e + 1) % 3] = 0.5;
                        mid.push_back(SurfacePoint(fp[k], b));
                    }
            }
            // the shortest path through those faces, not their edges' midpoints (on slivers
            // these lie far from both samples)
            PathTighten<MeshType>::Tighten(surf.Mesh(), c.samples[g].p, mid, c.samples[(g + 1) % n].p);
            out.insert(out.end(), mid.begin(), mid.end());
        }
        if (withEnds) out.push_back(c.samples[(g + 1) % n].p);
        return out;
    }

    /// The point halfway along gap g (by length on the polyline), where an inserted sample goes.
    /// Tightens the gap first.
    static SurfacePoint GapMiddle(const Surface &surf, SnakeCurve &c, int g)
    {
        TightenGap(surf, c, g);
        std::vector<SurfacePoint> pts = GapPoints(surf, c, g);
        std::vector<vcg::Point3d> xyz = Positions(surf, pts);
        double L = 0;
        for (size_t k = 1; k < xyz.size(); ++k) L += (xyz[k] - xyz[k - 1]).Norm();
        SurfacePoint mid = pts.front();
        double acc = 0;
        for (size_t k = 1; k < xyz.size(); ++k) {
            double l = (xyz[k] - xyz[k - 1]).Norm();
            if (acc + l >= L / 2 && l > 0) {
                double t = (L / 2 - acc) / l;
                mid = interpolate(surf, c.unit, pts[k - 1], pts[k], t);
                break;
            }
            acc += l;
        }
        return mid;
    }

    /// Sample i moved: both gaps at it must be traced anew.
    static void InvalidateAround(SnakeCurve &c, int i)
    {
        int n = int(c.samples.size());
        if (c.closed) {
            c.gaps[i] = SnakeGap();
            c.gaps[(i - 1 + n) % n] = SnakeGap();
        } else {
            if (i < int(c.gaps.size())) c.gaps[i] = SnakeGap();
            if (i - 1 >= 0) c.gaps[i - 1] = SnakeGap();
        }
    }

    /// A sample was inserted into gap g (it is sample g + 1 now): the gap splits into two
    /// untraced ones.
    static void SplitGap(SnakeCurve &c, int g)
    {
        c.gaps[g] = SnakeGap();
        c.gaps.insert(c.gaps.begin() + g + 1, SnakeGap());
    }

    /// Sample i was erased (the samples are already one fewer): its two gaps become one
    /// untraced gap.
    static void MergeGaps(SnakeCurve &c, int i)
    {
        int n = int(c.samples.size());
        if (c.closed) {
            c.gaps.erase(c.gaps.begin() + i);
            c.gaps[(i - 1 + n) % n] = SnakeGap();
        } else {
            int g = std::min(i, int(c.gaps.size()) - 1);
            c.gaps.erase(c.gaps.begin() + g);
            if (i - 1 >= 0 && i - 1 < int(c.gaps.size())) c.gaps[i - 1] = SnakeGap();
        }
    }

private:
    /// Point between two surface points that share a face (consecutive polyline points).
    static SurfacePoint interpolate(const Surface &surf, double unit, const SurfacePoint &a, const SurfacePoint &b,
                                    double t)
    {
        const MeshType &m = surf.Mesh();
        vcg::Point3d pa = a.Pd(m), pb = b.Pd(m);
        vcg::Point3d q = pa * (1 - t) + pb * t;
        return SurfaceProjection<MeshType>::Closest(surf, a.face, q, 2 * (pb - pa).Norm() + unit);
    }
};

} // namespace tri
} // namespace vcg

#endif
