#ifndef VCG_EXT_PATH_TIGHTEN_H
#define VCG_EXT_PATH_TIGHTEN_H

// The shortest path through a given strip of faces (beyond the paper). A snake's curve
// between two samples is the straight segment in the local embedding (Sec. 4.1). The
// embedding is near-isometric on smooth regions, but around a crease of a CAD tessellation
// (long slivers fanning to far corners, strips as long as the part) it can be far from it,
// and the straight segment then wanders away from the samples it joins -- down a bore's
// wall, out to a corner of the face -- although both samples lie on the crease. Keeping the
// faces the segment crossed and only sliding each crossing along its edge to the position
// that makes the path shortest gives the locally shortest (geodesic) path in that strip.

#include <algorithm>
#include <cmath>
#include <vector>

#include <vcg/space/point3.h>

#include <vcg_ext/surface/surface_point.h>

namespace vcg {
namespace tri {

template <class MeshType>
class PathTighten
{
public:
    /// `crossings`: the points where a path from a to b crosses mesh edges, in order, each
    /// on the edge its face shares with the next crossing's face (b's face after the last
    /// one); a crossing whose faces share no edge stays where it is. Moves each along its edge so
    /// that a - crossings - b is as short as possible (Gauss-Seidel over the exact optimum
    /// of one crossing between its two neighbours, found by unfolding about the edge).
    /// Returns the length after tightening.
    static double Tighten(const MeshType &m, const SurfacePoint &a, std::vector<SurfacePoint> &crossings,
                          const SurfacePoint &b)
    {
        const int n = int(crossings.size());
        const vcg::Point3d pa = a.Pd(m), pb = b.Pd(m);
        if (n == 0) return (pb - pa).Norm();
        std::vector<vcg::Point3d> e0(n), e1(n), p(n);
        std::vector<int> i0(n), i1(n);
        std::vector<double> t(n);
        std::vector<char> held(n, 0);
        for (int i = 0; i < n; ++i) {
            const SurfacePoint &c = crossings[i];
            const auto &f = m.face[c.face];
            const auto &g = m.face[i + 1 < n ? crossings[i + 1].face : b.face];
            int j = -1; // the corner opposite the shared edge
            for (int k = 0; k < 3 && j < 0; ++k) {
                const auto *u = f.cV((k + 1) % 3), *v = f.cV((k + 2) % 3);
                bool hu = false, hv = false;
                for (int l = 0; l < 3; ++l) {
                    hu |= g.cV(l) == u;
                    hv |= g.cV(l) == v;
                }
                if (hu && hv && &f != &g) j = k;
            }
            if (j < 0) { // no shared edge (the path passes a vertex): keep the point
                held[i] = 1;
                j = 0;
            }
            i0[i] = (j + 1) % 3;
            i1[i] = (j + 2) % 3;
            e0[i] = vcg::Point3d::Construct(f.cV(i0[i])->cP());
            e1[i] = vcg::Point3d::Construct(f.cV(i1[i])->cP());
            // start from the point of the edge nearest to the chord a-b: exact where the strip
            // is flat and the chord crosses it, a good start elsewhere
            t[i] = nearestToChord(e0[i], e1[i], pa, pb);
            p[i] = held[i] ? c.Pd(m) : e0[i] * (1 - t[i]) + e1[i] * t[i];
        }
        double scale = (pb - pa).Norm();
        for (int i = 0; i < n; ++i) scale = std::max(scale, (e1[i] - e0[i]).Norm());
        // to 1e-7 of the strip's size, the precision of float coordinates (1e-12 took a fifth
        // of a 300-sample operation: this runs for every traced gap of every operation, and a
        // path near a vertex converges slowly)
        const double eps = 1e-7 * std::max(scale, 1e-300);
        const int sweeps = 4 * n + 50;
        for (int it = 0; it < sweeps; ++it) {
            double moved = 0;
            for (int i = 0; i < n; ++i) {
                if (held[i]) continue;
                const vcg::Point3d &A = i > 0 ? p[i - 1] : pa;
                const vcg::Point3d &C = i + 1 < n ? p[i + 1] : pb;
                const double nt = bestOnEdge(e0[i], e1[i], A, C, t[i]);
                const vcg::Point3d q = e0[i] * (1 - nt) + e1[i] * nt;
                moved = std::max(moved, (q - p[i]).Norm());
                t[i] = nt;
                p[i] = q;
            }
            if (moved <= eps) break;
        }
        double len = 0;
        vcg::Point3d prev = pa;
        for (int i = 0; i < n; ++i) {
            if (!held[i]) {
                vcg::Point3d bary(0, 0, 0);
                bary[i0[i]] = 1 - t[i];
                bary[i1[i]] = t[i];
                crossings[i].bary = bary;
            }
            len += (p[i] - prev).Norm();
            prev = p[i];
        }
        return len + (pb - prev).Norm();
    }

private:
    /// The t in [0,1] of the point of segment e0-e1 nearest to segment a-b (Ericson,
    /// Real-Time Collision Detection, 5.1.9).
    static double nearestToChord(const vcg::Point3d &e0, const vcg::Point3d &e1, const vcg::Point3d &a,
                                 const vcg::Point3d &b)
    {
        const vcg::Point3d d1 = e1 - e0, d2 = b - a, r = e0 - a;
        const double aa = d1 * d1, ee = d2 * d2, f = d2 * r;
        if (!(aa > 0)) return 0.5;
        const double c = d1 * r;
        if (!(ee > 0)) return std::min(1.0, std::max(0.0, -c / aa));
        const double bb = d1 * d2, den = aa * ee - bb * bb;
        double s = den > 1e-12 * aa * ee ? std::min(1.0, std::max(0.0, (bb * f - c * ee) / den)) : 0.0;
        const double u = (bb * s + f) / ee;
        if (u < 0) s = std::min(1.0, std::max(0.0, -c / aa));
        else if (u > 1) s = std::min(1.0, std::max(0.0, (bb - c) / aa));
        return std::isfinite(s) ? s : 0.5;
    }

    /// The t in [0,1] of the point of segment e0-e1 that minimizes |P - A| + |P - C|: with
    /// axial positions a, c and distances ra, rc from the edge's line, the unfolded straight
    /// line crosses it at a + (c - a) ra / (ra + rc).
    static double bestOnEdge(const vcg::Point3d &e0, const vcg::Point3d &e1, const vcg::Point3d &A,
                             const vcg::Point3d &C, double current)
    {
        vcg::Point3d u = e1 - e0;
        const double L = u.Norm();
        if (!(L > 0) || !std::isfinite(L)) return current;
        u /= L;
        const double a = (A - e0) * u, c = (C - e0) * u;
        const double ra = (A - e0 - u * a).Norm(), rc = (C - e0 - u * c).Norm();
        const double s = (ra + rc > 0) ? a + (c - a) * ra / (ra + rc) : 0.5 * (a + c);
        const double t = s / L;
        return std::isfinite(t) ? std::min(1.0, std::max(0.0, t)) : current;
    }
};

} // namespace tri
} // namespace vcg

#endif
