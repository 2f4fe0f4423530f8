#ifndef VCG_EXT_SURFACE_STRAIGHT_WALK_H
#define VCG_EXT_SURFACE_STRAIGHT_WALK_H

// The straight line between two surface points, walked across faces. On a flat CAD face it
// is the exact shortest path, where paths along edges zigzag through the fans of slivers.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/space/triangle3.h>

#include <vcg_ext/surface/mesh_validation.h>
#include <vcg_ext/surface/surface_point.h>

namespace vcg {
namespace tri {

/// The straight line between two surface points, walked across faces: in each face the
/// walk heads for the target (projected onto the face's plane) and leaves through an
/// edge into the face across it. Exact on flat regions; gives up (false) at a border, a
/// non-manifold edge, or when the walk grows longer than twice the straight distance.
template <class MeshType>
class SurfaceStraightWalk
{
public:
    typedef MeshValidation<MeshType> MV;

    explicit SurfaceStraightWalk(const MeshType &m) : m_(m)
    {
        struct E { int a, b, f, k; };
        std::vector<E> e;
        for (size_t f = 0; f < m.face.size(); ++f) {
            if (m.face[f].IsD()) continue;
            for (int k = 0; k < 3; ++k) {
                int a = MV::VIndex(m, m.face[f].cV(k)), b = MV::VIndex(m, m.face[f].cV((k + 1) % 3));
                if (a > b) std::swap(a, b);
                e.push_back({a, b, int(f), k});
            }
        }
        std::sort(e.begin(), e.end(), [](const E &x, const E &y) { return x.a != y.a ? x.a < y.a : x.b < y.b; });
        across_.assign(m.face.size(), {-1, -1, -1});
        for (size_t i = 0; i < e.size();) {
            size_t j = i + 1;
            while (j < e.size() && e[j].a == e[i].a && e[j].b == e[i].b) ++j;
            if (j - i == 2) {
                across_[e[i].f][e[i].k] = e[i + 1].f;
                across_[e[i + 1].f][e[i + 1].k] = e[i].f;
            }
            i = j;
        }
    }

    bool Walk(const SurfacePoint &a, const SurfacePoint &b, std::vector<SurfacePoint> &out) const
    {
        out.assign(1, a);
        const vcg::Point3d B = b.Pd(m_);
        const double straight = (B - a.Pd(m_)).Norm();
        SurfacePoint cur = a;
        double len = 0;
        int prevFace = -1;
        for (int it = 0; it < 100000; ++it) {
            SurfacePoint bb;
            if (b.InFace(m_, cur.face, bb)) {
                len += (B - cur.Pd(m_)).Norm();
                out.push_back(b);
                return len <= 2 * straight + 1e-12;
            }
            const auto &f = m_.face[cur.face];
            vcg::Point3d p[3];
            for (int k = 0; k < 3; ++k) p[k] = vcg::Point3d::Construct(f.cV(k)->cP());
            vcg::Point3d n = (p[1] - p[0]) ^ (p[2] - p[0]);
            if (!(n.Norm() > 0)) return false;
            n.Normalize();
            const vcg::Point3d x = cur.Pd(m_);
            vcg::Point3d d = B - x;
            d -= n * (d * n);
            if (!(d.Norm() > 1e-12 * std::max(1.0, straight))) return false;
            // The edge the ray x + t d leaves through: in barycentric terms, the first
            // coordinate that reaches 0 (among those that decrease).
            vcg::Point3d bd; // barycentric direction
            {
                vcg::Triangle3<double> t(p[0], p[1], p[2]);
                vcg::Point3d b1;
                vcg::InterpolationParameters(t, x + d, b1); // false just means "outside": wanted here
                if (!std::isfinite(b1[0]) || !std::isfinite(b1[1]) || !std::isfinite(b1[2])) return false;
                bd = b1 - cur.bary;
            }
            int exitK = -1;
            double tBest = std::numeric_limits<double>::infinity();
            for (int k = 0; k < 3; ++k) {
                if (!(bd[k] < -1e-15)) continue;
                const double tk = std::max(0.0, cur.bary[k]) / -bd[k];
                // leaving back into the face we came from is not progress
                const int edge = (k + 1) % 3; // edge opposite corner k
                if (tk <= 1e-12 && across_[cur.face][edge] == prevFace) continue;
                if (tk < tBest) { tBest = tk; exitK = k; }
            }
            if (exitK < 0) return false;
            vcg::Point3d eb = cur.bary + bd * tBest;
            eb[exitK] = 0;
            SurfacePoint ex(cur.face, eb);
            ex.Normalize();
            const int edge = (exitK + 1) % 3;
            const int g = across_[cur.face][edge];
            if (g < 0) return false;
            len += (ex.Pd(m_) - x).Norm();
            if (len > 2 * straight + 1e-12) return false;
            if ((ex.Pd(m_) - out.back().Pd(m_)).Norm() > 0) out.push_back(ex);
            SurfacePoint next;
            if (!ex.InFace(m_, g, next)) return false;
            prevFace = cur.face;
            cur = next;
        }
        return false;
    }

private:
    const MeshType &m_;
    std::vector<std::array<int, 3>> across_;
};

} // namespace tri
} // namespace vcg

#endif
