#ifndef VCG_EXT_CUT_CUT_COMMIT_H
#define VCG_EXT_CUT_CUT_COMMIT_H

// Writes a checked CutWorkMesh into the user's mesh: the added vertices (position; colour,
// quality, normal and texture coordinate interpolated linearly in the user's face they lie in,
// as vcglib's RefineE interpolators do along an edge), the split faces' new vertices and
// per-wedge texture coordinates (interpolated in their user's face, so seams stay seams), and
// the added faces, which copy every other attribute of the face they came from (ImportData).

#include <vector>

#include <vcg/complex/complex.h>

#include <vcg_ext/cut/cut_work_mesh.h>

namespace vcg {
namespace tri {

template <class MeshType>
class CutCommit
{
public:
    typedef typename MeshType::VertexType VertexType;
    typedef typename MeshType::FaceType FaceType;
    typedef typename MeshType::ScalarType S;

    /// Barycentric coordinates of x in triangle (a, b, c) (x in its plane, up to round-off).
    static vcg::Point3d Bary(const vcg::Point3d &a, const vcg::Point3d &b, const vcg::Point3d &c,
                             const vcg::Point3d &x)
    {
        return CutWorkMesh::Bary(a, b, c, x);
    }

    static void Commit(MeshType &m, const CutWorkMesh &w)
    {
        const int vn0 = w.vn0, fn0 = w.fn0;
        // the user's faces that change, as they were (vertices and wedge texture coordinates)
        std::vector<int> touched;
        std::vector<char> isTouched(fn0, 0);
        auto touch = [&](int f) {
            if (f >= 0 && f < fn0 && !isTouched[f]) { isTouched[f] = 1; touched.push_back(f); }
        };
        for (size_t i = fn0; i < w.face.size(); ++i) touch(w.face[i].parent);
        for (int f = 0; f < fn0; ++f)
            if (w.face[f].parent >= 0)
                for (int k = 0; k < 3; ++k)
                    if (w.face[f].v[k] != int(vcg::tri::Index(m, m.face[f].cV(k)))) touch(f);
        struct Orig
        {
            int v[3];
            typename FaceType::TexCoordType wt[3];
        };
        std::vector<Orig> orig(touched.size());
        std::vector<int> slot(fn0, -1);
        const bool wedgeTex = vcg::tri::HasPerWedgeTexCoord(m);
        for (size_t i = 0; i < touched.size(); ++i) {
            const FaceType &f = m.face[touched[i]];
            slot[touched[i]] = int(i);
            for (int k = 0; k < 3; ++k) {
                orig[i].v[k] = int(vcg::tri::Index(m, f.cV(k)));
                if (wedgeTex) orig[i].wt[k] = f.cWT(k);
            }
        }
        auto baryIn = [&](int F, const vcg::Point3d &x) {
            const Orig &o = orig[slot[F]];
            return Bary(w.pos[o.v[0]], w.pos[o.v[1]], w.pos[o.v[2]], x);
        };

        // vertices
        const int added = int(w.pos.size()) - vn0;
        if (added > 0) vcg::tri::Allocator<MeshType>::AddVertices(m, added);
        for (int j = 0; j < added; ++j) {
            VertexType &v = m.vert[vn0 + j];
            const vcg::Point3d &x = w.pos[vn0 + j];
            if (w.copyOf[j] >= 0) {
                v.ImportData(m.vert[w.copyOf[j]]);
                v.P() = MeshType::CoordType::Construct(x);
                continue;
            }
            const int F = w.addedOrigFaces[j][0];
            vcg::Point3d l = baryIn(F, x);
            for (int k = 0; k < 3; ++k) l[k] = std::max(0.0, l[k]);
            l /= (l[0] + l[1] + l[2]);
            const Orig &o = orig[slot[F]];
            const VertexType *c[3] = {&m.vert[o.v[0]], &m.vert[o.v[1]], &m.vert[o.v[2]]};
            int big = 0;
            for (int k = 1; k < 3; ++k)
                if (l[k] > l[big]) big = k;
            v.ImportData(*c[big]); // flags and attributes not interpolated below
            v.P() = MeshType::CoordType::Construct(x);
            if (vcg::tri::HasPerVertexColor(m)) {
                vcg::Point4d col(0, 0, 0, 0);
                for (int k = 0; k < 3; ++k)
                    for (int h = 0; h < 4; ++h) col[h] += l[k] * c[k]->cC()[h];
                for (int h = 0; h < 4; ++h) v.C()[h] = (unsigned char)std::min(255.0, std::max(0.0, col[h] + 0.5));
            }
            if (vcg::tri::HasPerVertexQuality(m))
                v.Q() = typename VertexType::QualityType(l[0] * c[0]->cQ() + l[1] * c[1]->cQ() + l[2] * c[2]->cQ());
            if (vcg::tri::HasPerVertexNormal(m)) {
                vcg::Point3d n(0, 0, 0);
                for (int k = 0; k < 3; ++k) n += vcg::Point3d::Construct(c[k]->cN()) * l[k];
                if (n.Norm() > 0) n.Normalize();
                v.N() = VertexType::NormalType::Construct(n);
            }
            if (vcg::tri::HasPerVertexTexCoord(m)) {
                vcg::Point2d t(0, 0);
                for (int k = 0; k < 3; ++k)
                    t += vcg::Point2d(c[k]->cT().U(), c[k]->cT().V()) * l[k];
                v.T().U() = S(t[0]);
                v.T().V() = S(t[1]);
            }
        }

        // faces
        const int addedF = int(w.face.size()) - fn0;
        if (addedF > 0) vcg::tri::Allocator<MeshType>::AddFaces(m, addedF);
        auto setFace = [&](int i) {
            FaceType &f = m.face[i];
            const CutWorkMesh::Face &wf = w.face[i];
            if (i >= fn0) f.ImportData(m.face[wf.parent]);
            for (int k = 0; k < 3; ++k) f.V(k) = &m.vert[wf.v[k]];
            if (wedgeTex && slot[wf.parent] >= 0) {
                const Orig &o = orig[slot[wf.parent]];
                for (int k = 0; k < 3; ++k) {
                    vcg::Point3d l = Bary(w.pos[o.v[0]], w.pos[o.v[1]], w.pos[o.v[2]], w.pos[wf.v[k]]);
                    vcg::Point2d t(0, 0);
                    for (int h = 0; h < 3; ++h) t += vcg::Point2d(o.wt[h].U(), o.wt[h].V()) * l[h];
                    f.WT(k).U() = S(t[0]);
                    f.WT(k).V() = S(t[1]);
                    f.WT(k).N() = o.wt[0].N();
                }
            }
        };
        // the added faces first: they import the attributes of their parent before it changes
        // (ImportData does not copy vertex references or adjacency)
        for (int i = fn0; i < int(w.face.size()); ++i) setFace(i);
        for (int f : touched) setFace(f);
        // faces changed only by a cut open (vertex copies): rewired above through `touched`
    }
};

} // namespace tri
} // namespace vcg

#endif
