#ifndef VCG_EXT_ANGLE_WEIGHTED_NORMALS_H
#define VCG_EXT_ANGLE_WEIGHTED_NORMALS_H

// Unit face normals and angle-weighted unit vertex normals (Thuermer & Wuethrich) in one face
// sweep, in double precision, skipping degenerate faces: the normals the feature energies of
// Sec. 6.1 (energy/feature_energy.h) compare, computed as vcglib's UpdateNormal would, but fused
// for the 1M-face time budget and without NaN. A normal pass over the mesh, kept apart from the
// energies that read it.

#include <algorithm>
#include <cmath>
#include <vector>

#include <vcg/complex/complex.h>

#include <vcg_ext/surface/mesh_validation.h>

namespace vcg {
namespace tri {

template <class MeshType>
class AngleWeightedNormals
{
public:
    typedef MeshValidation<MeshType> MV;
    typedef typename MeshType::FaceType FaceType;
    typedef typename MeshType::VertexType VertexType;

    /// Unit face normals (returned in fn, indexed like m.face, zero for degenerate faces; also
    /// stored in the mesh if it has face normals) and angle-weighted unit vertex normals
    /// (Thuermer & Wuethrich). Same result as vcglib's UpdateNormal::PerFaceNormalized +
    /// PerVertexAngleWeighted + NormalizePerVertex, fused into one face sweep in double
    /// precision for the 1M-face time budget, and skipping degenerate faces so no NaN appears.
    static void Update(MeshType &m, std::vector<vcg::Point3f> &fn)
    {
        const size_t nv = m.vert.size(), nf = m.face.size();
        fn.assign(nf, vcg::Point3f(0, 0, 0));
        std::vector<vcg::Point3d> acc(nv, vcg::Point3d(0, 0, 0));
        for (size_t fi = 0; fi < nf; ++fi) {
            const FaceType &f = m.face[fi];
            vcg::Point3d n;
            double a[3];
            if (f.IsD() || !Corners(f, n, a)) continue;
            fn[fi] = vcg::Point3f::Construct(n);
            for (int k = 0; k < 3; ++k) acc[MV::VIndex(m, f.cV(k))] += n * a[k];
        }
        for (size_t i = 0; i < nv; ++i) {
            VertexType &v = m.vert[i];
            if (v.IsD()) continue;
            const double len = acc[i].Norm();
            v.N() = VertexType::NormalType::Construct(len > 0 ? acc[i] / len : vcg::Point3d(0, 0, 0));
        }
        if (tri::HasPerFaceNormal(m))
            for (size_t fi = 0; fi < nf; ++fi)
                if (!m.face[fi].IsD()) m.face[fi].N() = FaceType::NormalType::Construct(fn[fi]);
    }

    /// The angle-weighted unit normal at vertex v alone, as Update computes it (up to the order
    /// of the sum), from the live faces round v (VF adjacency, so no mesh is needed), without
    /// writing anything: for a const mesh read at a few vertices, so the cost follows them, not
    /// the mesh. Zero where every face round v is degenerate.
    static vcg::Point3d At(const VertexType &v)
    {
        vcg::Point3d acc(0, 0, 0);
        for (const FaceType *f = v.cVFp(), *next = nullptr; f; f = next) {
            const int z = (f->cV(0) == &v) ? 0 : (f->cV(1) == &v ? 1 : 2);
            next = f->cVFp(z);
            vcg::Point3d n;
            double a[3];
            if (!f->IsD() && Corners(*f, n, a)) acc += n * a[z];
        }
        const double len = acc.Norm();
        return len > 0 ? acc / len : vcg::Point3d(0, 0, 0);
    }

private:
    /// Face f's unit normal n and its angles a[k] at its vertices k; false for a degenerate face.
    static bool Corners(const FaceType &f, vcg::Point3d &n, double a[3])
    {
        const vcg::Point3d p0 = vcg::Point3d::Construct(f.cV(0)->cP());
        const vcg::Point3d p1 = vcg::Point3d::Construct(f.cV(1)->cP());
        const vcg::Point3d p2 = vcg::Point3d::Construct(f.cV(2)->cP());
        const vcg::Point3d e0 = p1 - p0, e1 = p2 - p1, e2 = p0 - p2;
        const double l0 = e0.SquaredNorm(), l1 = e1.SquaredNorm(), l2 = e2.SquaredNorm();
        const vcg::Point3d cr = e0 ^ (p2 - p0);
        const double area2 = cr.Norm();
        const double maxE2 = std::max(l0, std::max(l1, l2));
        // Same test as MeshValidation::IsDegenerate (zero-area or repeated-vertex faces).
        if (!(maxE2 > 0) || !(area2 > MV::DegenerateRatio() * maxE2)) return false;
        n = cr / area2;
        const double s0 = std::sqrt(l0), s1 = std::sqrt(l1), s2 = std::sqrt(l2);
        a[0] = FastAcos(Clamp1(-(e0 * e2) / (s0 * s2)));
        a[1] = FastAcos(Clamp1(-(e0 * e1) / (s0 * s1)));
        a[2] = FastAcos(Clamp1(-(e1 * e2) / (s1 * s2)));
        return true;
    }

    /// acos with |error| <= 2e-8 rad (Abramowitz & Stegun 4.4.46); libm's acos was the
    /// bottleneck of the normal pass and the angle weights need nowhere near full precision.
    static double FastAcos(double x)
    {
        const double ax = std::fabs(x);
        double p = -0.0012624911;
        p = p * ax + 0.0066700901;
        p = p * ax - 0.0170881256;
        p = p * ax + 0.0308918810;
        p = p * ax - 0.0501743046;
        p = p * ax + 0.0889789874;
        p = p * ax - 0.2145988016;
        p = p * ax + 1.5707963050;
        const double r = std::sqrt(std::max(0.0, 1.0 - ax)) * p;
        return x >= 0 ? r : M_PI - r;
    }

    static double Clamp1(double x) { return x > 1.0 ? 1.0 : (x < -1.0 ? -1.0 : (x == x ? x : 0.0)); }
};

} // namespace tri
} // namespace vcg

#endif
