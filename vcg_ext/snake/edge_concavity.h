#ifndef VCG_EXT_EDGE_CONCAVITY_H
#define VCG_EXT_EDGE_CONCAVITY_H

// How far the surface bends inwards across a mesh edge (issue 33): the valley loop's crease
// term (valley_loop.h, ValleyLoop::Param::concavityWeight) prices an edge by its concave
// dihedral angle, read from the faces' own normals, from normals averaged over a few rings
// (the sign at a scale, Param::concavityRings), or from feature-preserving filtered normals
// (crease_normals.h); an edge whose apex lies within the scalar's rounding of the other face's
// plane is flat (Param::flatTolerance).

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <vcg/complex/complex.h>

#include <vcg_ext/snake/crease_normals.h>
#include <vcg_ext/snake/part_salience.h>

namespace vcg {
namespace tri {

template <class MeshType>
class EdgeConcavity
{
public:
    typedef typename MeshType::FaceType FaceType;
    typedef typename MeshType::VertexType VertexType;
    /// Unit face normals by face (CreaseNormals::Filtered); empty: the faces' own.
    typedef typename CreaseNormals<MeshType>::Normals FaceNormals;

    /// Angle with the normals of fn (CreaseNormals::Filtered) when it has the faces: the angle
    /// between them where they turn towards each other across the edge ((n1 - n0) . (b1 - b0)
    /// < 0, b the faces' barycentres), 0 otherwise; the other cases below when fn is empty.
    static double Angle(const MeshType &m, const FaceType *f0, const FaceType *f1, int rings, double flat,
                               const FaceNormals &fn, bool signOnly)
    {
        if (fn.empty()) return Angle(m, f0, f1, rings, flat);
        if (!f0 || !f1) return 0;
        const auto i0 = fn.find(f0), i1 = fn.find(f1);
        if (i0 == fn.end() || i1 == fn.end()) return Angle(m, f0, f1, rings, flat);
        const vcg::Point3d &n0 = i0->second, &n1 = i1->second;
        if (!(n0.Norm() > 0 && n1.Norm() > 0)) return 0; // a zero-area face keeps no normal: no crease, as unfiltered
        const vcg::Point3d b0 = vcg::Point3d::Construct(vcg::Barycenter(*f0)), b1 = vcg::Point3d::Construct(vcg::Barycenter(*f1));
        if (!((n1 - n0) * (b1 - b0) < 0)) return 0;
        if (signOnly) return Angle(f0, f1, flat);
        return std::acos(std::max(-1.0, std::min(1.0, n0 * n1)));
    }

    /// Angle where the surface is concave across the edge at a scale as well: with
    /// rings > 0, 0 unless f0's and f1's normals, each averaged by area over the faces within
    /// `rings` rings (sharing a vertex, repeatedly), turn towards each other across the edge
    /// ((n1 - n0) . (b1 - b0) < 0, b the faces' barycentres: the sign of the normal curvature
    /// across it).
    static double Angle(const MeshType &m, const FaceType *f0, const FaceType *f1, int rings, double flat)
    {
        if (rings <= 0) return Angle(f0, f1, flat);
        if (!f0 || !f1) return 0;
        vcg::Point3d n0 = SmoothNormal(m, f0, rings), n1 = SmoothNormal(m, f1, rings);
        if (!(n0.Norm() > 0 && n1.Norm() > 0)) return 0;
        n0.Normalize(), n1.Normalize();
        const vcg::Point3d b0 = vcg::Point3d::Construct(vcg::Barycenter(*f0)), b1 = vcg::Point3d::Construct(vcg::Barycenter(*f1));
        if (!((n1 - n0) * (b1 - b0) < 0)) return 0;
        return Angle(f0, f1, flat);
    }

    /// Sum of the (area-weighted) normals of the faces within `rings` rings of f (VF adjacency).
    static vcg::Point3d SmoothNormal(const MeshType &m, const FaceType *f, int rings)
    {
        std::vector<const FaceType *> seen{f}, front{f}, next;
        for (int r = 0; r < rings; ++r) {
            next.clear();
            for (const FaceType *g : front)
                for (int k = 0; k < 3; ++k)
                    PartSalience<MeshType>::ForFaces(m, int(g->cV(k) - &m.vert[0]), [&](const FaceType *h, int) {
                        if (std::find(seen.begin(), seen.end(), h) == seen.end()) seen.push_back(h), next.push_back(h);
                    });
            front.swap(next);
        }
        vcg::Point3d n(0, 0, 0);
        for (const FaceType *g : seen) n += vcg::Point3d::Construct(vcg::TriangleNormal(*g));
        return n;
    }

    /// The dihedral angle at the edge shared by f0 and f1 when the surface bends inwards there
    /// (f1's third vertex above f0's plane, outward normals), 0 when it is convex or flat or
    /// the edge has one face, or when the apex lies within `flat` times the scalar's rounding of
    /// f0's plane (ValleyLoop::Param::flatTolerance). (Not vcg::face::DihedralAngleRad: that one is in the
    /// mesh's scalar, float for CMeshO, and needs FF adjacency.)
    static double Angle(const FaceType *f0, const FaceType *f1, double flat)
    {
        if (!f0 || !f1) return 0;
        vcg::Point3d n0 = vcg::Point3d::Construct(vcg::TriangleNormal(*f0));
        vcg::Point3d n1 = vcg::Point3d::Construct(vcg::TriangleNormal(*f1));
        if (!(n0.Norm() > 0 && n1.Norm() > 0)) return 0;
        n0.Normalize(), n1.Normalize();
        for (int k = 0; k < 3; ++k) {
            const VertexType *c = f1->cV(k);
            if (c == f0->cV(0) || c == f0->cV(1) || c == f0->cV(2)) continue;
            const double up = n0 * (vcg::Point3d::Construct(c->cP()) - vcg::Point3d::Construct(f0->cP(0)));
            double tol = 0;
            if (flat > 0) {
                // the rounding of a coordinate of this magnitude in the mesh's scalar
                double mag = 0;
                for (int j = 0; j < 3; ++j)
                    for (int d = 0; d < 3; ++d) mag = std::max(mag, std::abs(double(f0->cP(j)[d])));
                for (int d = 0; d < 3; ++d) mag = std::max(mag, std::abs(double(c->cP()[d])));
                typedef typename MeshType::ScalarType S;
                tol = flat * double(std::numeric_limits<S>::epsilon()) * mag;
            }
            return up > tol ? std::acos(std::max(-1.0, std::min(1.0, n0 * n1))) : 0.0;
        }
        return 0;
    }
};

} // namespace tri
} // namespace vcg

#endif
