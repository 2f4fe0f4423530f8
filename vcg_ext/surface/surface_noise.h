#ifndef VCG_EXT_SURFACE_SURFACE_NOISE_H
#define VCG_EXT_SURFACE_SURFACE_NOISE_H

// The surface's noise in units of its edge length: over vertices sampled evenly (interior, VF
// adjacency), least-squares height fits z = ax^2 + bxy + cy^2 + dx + ey + f of the vertex's
// rings in the frame of its area-weighted normal, coordinates over the one-ring's mean edge
// length; the median. Session 32 (FitResidual): the two rings' RMS residual, noise and the
// shape finer than two rings together (a scan's detail, a CAD crease). Session 33 (Level): the
// shape's part grows with the fit's radius and the noise's does not, so the fits of 2, 3 and 4
// rings separate them and Level reads the noise's rms. It gates the crease term's filtered
// normals (crease_normals.h; docs/method.md "Session 32: the crease filter gated by the
// surface's noise" and "Session 33: the noise gate on the noise's rms").

#include <algorithm>
#include <cmath>
#include <iterator>
#include <vector>

#include <Eigen/Dense>
#include <vcg/complex/complex.h>

namespace vcg {
namespace tri {

template <class MeshType>
class SurfaceNoise
{
public:
    typedef typename MeshType::FaceType FaceType;
    typedef typename MeshType::VertexType VertexType;

    struct Param
    {
        /// Vertices sampled evenly (every vert.size() / samples-th one): the median is stable
        /// well below the benchmark meshes' sizes. Level fits three neighbourhoods (up to ~60
        /// points) per vertex: 500 of them cost about what session 32's 2000 two-ring fits did.
        /// (FitResidual's figures in docs/method.md were taken with 2000.)
        int samples = 500;
        /// A vertex whose two rings hold fewer vertices (a boundary, a sliver fan) is skipped:
        /// the six coefficients need a margin of points to leave a residual.
        int minPoints = 12;
    };

    /// The noise's rms along the normal, in units of the local edge length h (session 33): at
    /// each sampled vertex the quadric height fit of its 2, 3 and 4 rings leaves residual
    /// variances v_k = RSS_k / (n_k - 6) (unbiased for noise: independent of the neighbourhood's
    /// size), while what is left of the shape grows with the neighbourhood's rms radius r_k as
    /// r_k^a, a between 2 (a kink: |x| less its best quadric grows as r) and 6 (a smooth surface:
    /// the cubic term, r^3). v_k = s^2 + c r_k^a: a from the growth 3 -> 4 rings against 2 -> 3,
    /// then s^2 = v_2 less the shape extrapolated to the 2 rings' radius; the median of s. On
    /// uniform noise +-A h it reads the noise's rms A/sqrt(3) h within ~15 %, and a clean
    /// surface's curvature, its tessellation (refined, graded) or a CAD crease leaves <= 0.045 h.
    /// 0 when no vertex qualifies; the mesh's VF adjacency must be current.
    static double Level(const MeshType &m, const Param &par = Param())
    {
        std::vector<const VertexType *> seen, front, next;
        return MedianOverSamples(m, par, [&](const VertexType &v, const vcg::Point3d &n, double h) {
            const vcg::Point3d p = vcg::Point3d::Construct(v.cP());
            seen.assign(1, &v), front.assign(1, &v);
            double var[3], rad[3];
            for (int k = 1; k <= 4; ++k) {
                Grow(front, seen, next);
                front.swap(next);
                if (k < 2) continue;
                if (k == 2 && int(seen.size()) < par.minPoints) return -1.0;
                const Fit f = FitQuadric(p, n, h, seen);
                var[k - 2] = f.rss / double(f.n - 6), rad[k - 2] = f.r2;
                if (!(std::isfinite(var[k - 2]) && f.n > 6)) return -1.0;
            }
            return std::sqrt(std::max(0.0, NoiseVariance(var, rad)));
        });
    }

    /// Session 32's level: the median RMS residual of the two rings' quadric fit, in h. It is the
    /// noise and the shape finer than two rings together (a scan's detail, a CAD crease, a coarse
    /// limb's curvature: 0.069 h on the armadillo, 0.094 h on the bearings): kept for diagnostics.
    static double FitResidual(const MeshType &m, const Param &par = Param())
    {
        std::vector<const VertexType *> seen, front, next;
        return MedianOverSamples(m, par, [&](const VertexType &v, const vcg::Point3d &n, double h) {
            seen.assign(1, &v), front.assign(1, &v);
            for (int k = 1; k <= 2; ++k) Grow(front, seen, next), front.swap(next);
            if (int(seen.size()) < par.minPoints) return -1.0;
            const Fit f = FitQuadric(vcg::Point3d::Construct(v.cP()), n, h, seen);
            return std::sqrt(f.rss / f.n);
        });
    }

    /// s^2 of v_k = s^2 + c r_k^a for the variances var[] and mean squared radii r2[] of the 2, 3
    /// and 4 rings' fits (Level): a clamped to [2, 6]; a residual that does not grow from 2 to 3
    /// rings is all noise.
    static double NoiseVariance(const double var[3], const double r2[3])
    {
        const double d1 = var[1] - var[0], d2 = var[2] - var[1];
        if (!(d1 > 0)) return var[0];
        const double l0 = 0.5 * std::log(r2[0]), l1 = 0.5 * std::log(r2[1]), l2 = 0.5 * std::log(r2[2]);
        auto growth = [&](double a) { return (std::exp(a * l2) - std::exp(a * l1)) / (std::exp(a * l1) - std::exp(a * l0)); };
        const double R = d2 / d1;
        double lo = 2, hi = 6, a;
        if (!(l0 < l1 && l1 < l2)) a = 6;
        else if (R <= growth(lo)) a = lo;
        else if (R >= growth(hi)) a = hi;
        else {
            for (int it = 0; it < 30; ++it) {
                const double mid = 0.5 * (lo + hi);
                (growth(mid) < R ? lo : hi) = mid;
            }
            a = 0.5 * (lo + hi);
        }
        const double s0 = std::exp(a * l0), s1 = std::exp(a * l1);
        return var[0] - d1 * s0 / (s1 - s0);
    }

private:
    /// fn(face, the vertex's index in it) for the live faces round v (VF adjacency).
    template <class Fn>
    static void Around(const VertexType *v, Fn fn)
    {
        for (const FaceType *f = v->cVFp(), *next = nullptr; f; f = next) {
            const int z = (f->cV(0) == v) ? 0 : (f->cV(1) == v ? 1 : 2);
            next = f->cVFp(z);
            if (!f->IsD()) fn(f, z);
        }
    }

    struct Fit
    {
        double rss = 0; ///< the residual sum of squares, in h^2
        int n = 0;      ///< the points fitted
        double r2 = 0;  ///< their mean squared distance from the normal's axis, in h^2
    };

    /// The vertex's area-weighted normal and one-ring mean edge length; false at a vertex
    /// without faces.
    static bool Frame(const VertexType &v, vcg::Point3d &n, double &h)
    {
        if (v.IsD() || !v.cVFp()) return false;
        n = vcg::Point3d(0, 0, 0), h = 0;
        int hn = 0;
        Around(&v, [&](const FaceType *f, int z) {
            n += vcg::Point3d::Construct(vcg::TriangleNormal(*f));
            h += vcg::Distance(v.cP(), f->cV((z + 1) % 3)->cP()), ++hn;
        });
        if (hn < 3 || n.Norm() <= 0 || h <= 0) return false;
        h /= hn;
        n.Normalize();
        return true;
    }

    /// One ring more: `next` = the vertices adjacent to `front` not in `seen` (sorted), added to
    /// `seen` (kept sorted).
    static void Grow(const std::vector<const VertexType *> &front, std::vector<const VertexType *> &seen,
                     std::vector<const VertexType *> &next)
    {
        std::vector<const VertexType *> adj;
        for (const VertexType *q : front)
            Around(q, [&](const FaceType *f, int) {
                for (int k = 0; k < 3; ++k) adj.push_back(f->cV(k));
            });
        std::sort(adj.begin(), adj.end());
        adj.erase(std::unique(adj.begin(), adj.end()), adj.end());
        std::sort(seen.begin(), seen.end());
        next.clear();
        std::set_difference(adj.begin(), adj.end(), seen.begin(), seen.end(), std::back_inserter(next));
        const size_t old = seen.size();
        seen.insert(seen.end(), next.begin(), next.end());
        std::inplace_merge(seen.begin(), seen.begin() + old, seen.end());
    }

    /// The median of fn(v, its normal, its one-ring mean edge length) over the vertices sampled
    /// evenly (every vert.size() / samples-th one) that have faces; a value that is not finite
    /// and >= 0 (fn's -1: too few rings, a singular fit) skips the vertex.
    template <class Fn>
    static double MedianOverSamples(const MeshType &m, const Param &par, Fn fn)
    {
        std::vector<double> res;
        const size_t step = std::max<size_t>(1, m.vert.size() / size_t(std::max(1, par.samples)));
        for (size_t vi = 0; vi < m.vert.size(); vi += step) {
            vcg::Point3d n;
            double h = 0;
            if (!Frame(m.vert[vi], n, h)) continue;
            const double x = fn(m.vert[vi], n, h);
            if (std::isfinite(x) && x >= 0) res.push_back(x);
        }
        return Median(res);
    }

    static double Median(std::vector<double> &res)
    {
        if (res.empty()) return 0;
        std::nth_element(res.begin(), res.begin() + res.size() / 2, res.end());
        return res[res.size() / 2];
    }

    /// The least-squares height fit z = ax^2 + bxy + cy^2 + dx + ey + f of `pts` round p in the
    /// frame of unit normal n, coordinates in units of h.
    static Fit FitQuadric(const vcg::Point3d &p, const vcg::Point3d &n, double h, const std::vector<const VertexType *> &pts)
    {
        vcg::Point3d u = std::fabs(n[0]) < 0.9 ? vcg::Point3d(1, 0, 0) : vcg::Point3d(0, 1, 0);
        u = (u - n * (u * n)).Normalize();
        const vcg::Point3d w = n ^ u;
        Eigen::Matrix<double, 6, 6> A = Eigen::Matrix<double, 6, 6>::Zero();
        Eigen::Matrix<double, 6, 1> B = Eigen::Matrix<double, 6, 1>::Zero();
        double r2 = 0;
        for (const VertexType *q : pts) {
            const vcg::Point3d d = (vcg::Point3d::Construct(q->cP()) - p) / h;
            const double x = d * u, y = d * w, z = d * n;
            Eigen::Matrix<double, 6, 1> r;
            r << x * x, x * y, y * y, x, y, 1;
            A += r * r.transpose(), B += r * z, r2 += x * x + y * y;
        }
        const Eigen::Matrix<double, 6, 1> c = A.ldlt().solve(B);
        Fit f;
        f.n = int(pts.size());
        f.rss = 0;
        for (const VertexType *q : pts) {
            const vcg::Point3d d = (vcg::Point3d::Construct(q->cP()) - p) / h;
            const double x = d * u, y = d * w, z = d * n;
            const double e = c[0] * x * x + c[1] * x * y + c[2] * y * y + c[3] * x + c[4] * y + c[5] - z;
            f.rss += e * e;
        }
        f.r2 = f.n ? r2 / f.n : 0;
        return f;
    }
};

} // namespace tri
} // namespace vcg

#endif
