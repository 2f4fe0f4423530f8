#ifndef VCG_EXT_SURFACE_SURFACE_NOISE_H
#define VCG_EXT_SURFACE_SURFACE_NOISE_H

// The surface's noise in units of its edge length (session 32): over vertices sampled evenly
// (interior, VF adjacency), the RMS residual of the least-squares height fit
// z = ax^2 + bxy + cy^2 + dx + ey + f of the vertex's two rings in the frame of its
// area-weighted normal, over the one-ring's mean edge length; the median. A quadric follows
// the curvature of a clean surface to third order (a smooth limb two rings wide leaves
// little), while noise along the normal stays in the residual: +-0.2 h uniform (rms 0.115 h)
// leaves ~0.09 h. It gates the crease term's filtered normals (crease_normals.h,
// docs/method.md "Session 32: the crease filter gated by the surface's noise").

#include <algorithm>
#include <cmath>
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
        /// well below the benchmark meshes' sizes, and the cost stays that of a few thousand fits.
        int samples = 2000;
        /// A vertex whose two rings hold fewer vertices (a boundary, a sliver fan) is skipped:
        /// the six coefficients need a margin of points to leave a residual.
        int minPoints = 12;
    };

    /// The median residual (0 when no vertex qualifies); the mesh's VF adjacency must be current.
    static double Level(const MeshType &m, const Param &par = Param())
    {
        std::vector<double> res;
        const size_t step = std::max<size_t>(1, m.vert.size() / size_t(std::max(1, par.samples)));
        std::vector<const VertexType *> ring, seen;
        for (size_t vi = 0; vi < m.vert.size(); vi += step) {
            const VertexType &v = m.vert[vi];
            if (v.IsD() || !v.cVFp()) continue;
            vcg::Point3d n(0, 0, 0);
            ring.clear();
            double h = 0;
            int hn = 0;
            Around(&v, [&](const FaceType *f, int z) {
                n += vcg::Point3d::Construct(vcg::TriangleNormal(*f));
                for (int k = 1; k < 3; ++k) ring.push_back(f->cV((z + k) % 3));
                h += vcg::Distance(v.cP(), f->cV((z + 1) % 3)->cP()), ++hn;
            });
            if (hn < 3 || n.Norm() <= 0) continue;
            h /= hn;
            n.Normalize();
            std::sort(ring.begin(), ring.end());
            ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
            seen = ring;
            for (const VertexType *q : ring)
                Around(q, [&](const FaceType *f, int) {
                    for (int k = 0; k < 3; ++k) seen.push_back(f->cV(k));
                });
            std::sort(seen.begin(), seen.end());
            seen.erase(std::unique(seen.begin(), seen.end()), seen.end());
            if (int(seen.size()) < par.minPoints || h <= 0) continue;
            const double r = Residual(vcg::Point3d::Construct(v.cP()), n, h, seen);
            if (std::isfinite(r)) res.push_back(r);
        }
        if (res.empty()) return 0;
        std::nth_element(res.begin(), res.begin() + res.size() / 2, res.end());
        return res[res.size() / 2];
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

    /// The RMS residual of the quadric height fit of `pts` round p in the frame of unit normal
    /// n, coordinates in units of h.
    static double Residual(const vcg::Point3d &p, const vcg::Point3d &n, double h, const std::vector<const VertexType *> &pts)
    {
        vcg::Point3d u = std::fabs(n[0]) < 0.9 ? vcg::Point3d(1, 0, 0) : vcg::Point3d(0, 1, 0);
        u = (u - n * (u * n)).Normalize();
        const vcg::Point3d w = n ^ u;
        Eigen::Matrix<double, 6, 6> A = Eigen::Matrix<double, 6, 6>::Zero();
        Eigen::Matrix<double, 6, 1> B = Eigen::Matrix<double, 6, 1>::Zero();
        std::vector<Eigen::Matrix<double, 6, 1>> rows;
        std::vector<double> zs;
        for (const VertexType *q : pts) {
            const vcg::Point3d d = (vcg::Point3d::Construct(q->cP()) - p) / h;
            const double x = d * u, y = d * w, z = d * n;
            Eigen::Matrix<double, 6, 1> r;
            r << x * x, x * y, y * y, x, y, 1;
            A += r * r.transpose(), B += r * z;
            rows.push_back(r), zs.push_back(z);
        }
        const Eigen::Matrix<double, 6, 1> c = A.ldlt().solve(B);
        double e = 0;
        for (size_t i = 0; i < rows.size(); ++i) e += std::pow(rows[i].dot(c) - zs[i], 2);
        return std::sqrt(e / rows.size());
    }
};

} // namespace tri
} // namespace vcg

#endif
