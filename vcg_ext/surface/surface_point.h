#ifndef VCG_EXT_SURFACE_POINT_H
#define VCG_EXT_SURFACE_POINT_H

#include <cmath>
#include <vcg/space/point3.h>

namespace vcg {
namespace tri {

/// A point on a triangle mesh: a face index and barycentric coordinates in it.
/// This is the only way points on the surface are stored; xyz is derived (P()).
/// Face indices (not pointers) so that a point survives a reallocation of the face
/// vector and can be written to JSON.
struct SurfacePoint
{
    int face = -1;
    vcg::Point3d bary = vcg::Point3d(1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0);

    SurfacePoint() = default;
    SurfacePoint(int f, const vcg::Point3d &b) : face(f), bary(b) {}

    bool IsValid() const
    {
        return face >= 0 && std::isfinite(bary[0]) && std::isfinite(bary[1]) && std::isfinite(bary[2]);
    }

    /// A valid point of a live face of m, its coordinates in the triangle up to round-off
    /// (user input: clicks, files, other tools).
    template <class MeshType>
    bool OnMesh(const MeshType &m) const
    {
        if (!IsValid() || face >= int(m.face.size()) || m.face[face].IsD()) return false;
        for (int k = 0; k < 3; ++k)
            if (bary[k] < -0.01 || bary[k] > 1.01) return false;
        return true;
    }

    /// The point at a mesh vertex: the corner `corner` (0..2) of face `f`.
    static SurfacePoint AtCorner(int f, int corner)
    {
        vcg::Point3d b(0, 0, 0);
        b[corner] = 1.0;
        return SurfacePoint(f, b);
    }

    /// Position in space, derived from the face's vertices.
    template <class MeshType>
    typename MeshType::CoordType P(const MeshType &m) const
    {
        typedef typename MeshType::ScalarType S;
        const auto &f = m.face[face];
        return f.cV(0)->cP() * S(bary[0]) + f.cV(1)->cP() * S(bary[1]) + f.cV(2)->cP() * S(bary[2]);
    }

    template <class MeshType>
    vcg::Point3d Pd(const MeshType &m) const
    {
        const auto &f = m.face[face];
        return vcg::Point3d::Construct(f.cV(0)->cP()) * bary[0] + vcg::Point3d::Construct(f.cV(1)->cP()) * bary[1] +
               vcg::Point3d::Construct(f.cV(2)->cP()) * bary[2];
    }

    /// The same point expressed in face `f`, which must hold every vertex the point depends
    /// on (a point on an edge or at a vertex lies in several faces). False if it does not.
    template <class MeshType>
    bool InFace(const MeshType &m, int f, SurfacePoint &out) const
    {
        const auto &src = m.face[face];
        const auto &dst = m.face[f];
        vcg::Point3d b(0, 0, 0);
        for (int k = 0; k < 3; ++k) {
            if (!(bary[k] > 1e-12)) continue;
            int j = 0;
            while (j < 3 && dst.cV(j) != src.cV(k)) ++j;
            if (j == 3) return false;
            b[j] += bary[k];
        }
        out = SurfacePoint(f, b);
        out.Normalize();
        return true;
    }

    /// Clamp tiny negative round-off and renormalize so the coordinates sum to 1.
    void Normalize()
    {
        double s = 0;
        for (int i = 0; i < 3; ++i) {
            if (!(bary[i] > 0)) bary[i] = 0;
            s += bary[i];
        }
        if (s > 0) bary /= s;
        else bary = vcg::Point3d(1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0);
    }
};

} // namespace tri
} // namespace vcg

#endif
