#ifndef VCG_EXT_CUT_CUT_COMMIT_H
#define VCG_EXT_CUT_CUT_COMMIT_H

// Writes a checked CutWorkMesh into the user's mesh (or its vertices and faces into another
// mesh, for the parts of a split): the added vertices (position; colour,
// quality, normal and texture coordinate interpolated linearly in the user's face they lie in,
// as vcglib's RefineE interpolators do along an edge), the split faces' new vertices and
// per-wedge texture coordinates (interpolated in their user's face, so seams stay seams), and
// the added faces, which copy every other attribute of the face they came from (ImportData).

#include <unordered_map>
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

    /// Writes w into m (m as w was built from): the added vertices and faces at the end.
    static void Commit(MeshType &m, const CutWorkMesh &w)
    {
        const CutCommit src(m, w);
        const int vn0 = w.vn0, fn0 = w.fn0;
        const int added = int(w.pos.size()) - vn0;
        if (added > 0) vcg::tri::Allocator<MeshType>::AddVertices(m, added);
        for (int j = vn0; j < int(w.pos.size()); ++j) src.Vertex(m.vert[j], j);
        const int addedF = int(w.face.size()) - fn0;
        if (addedF > 0) vcg::tri::Allocator<MeshType>::AddFaces(m, addedF);
        auto setFace = [&](int i, bool import) {
            const CutWorkMesh::Face &wf = w.face[i];
            src.Face(m.face[i], i, &m.vert[wf.v[0]], &m.vert[wf.v[1]], &m.vert[wf.v[2]], import);
        };
        // the added faces first: they import the attributes of their parent before it changes
        // (ImportData does not copy vertex references or adjacency)
        for (int i = fn0; i < int(w.face.size()); ++i) setFace(i, true);
        // the user's faces split, or rewired by a cut open (vertex copies)
        for (int f : src.touched) setFace(f, false);
    }

    /// The user's mesh m and the work mesh w built from it, before anything is written: the
    /// attributes of w's vertices and faces can be written into m (Commit) or another mesh
    /// (MeshCut::Split's parts).
    CutCommit(const MeshType &m, const CutWorkMesh &w) : src(m), w(w)
    {
        const int fn0 = w.fn0;
        // the user's faces that change, as they were (vertices and wedge texture coordinates):
        // those split and those a cut open rewired, found from the changes alone (a split's
        // parts cost in proportion to themselves, not to the mesh)
        auto touch = [&](int f) {
            if (f >= 0 && f < fn0 && slot.emplace(f, int(touched.size())).second) touched.push_back(f);
        };
        for (size_t i = fn0; i < w.face.size(); ++i) touch(w.face[i].parent);
        for (int f : w.Rewired()) touch(f);
        orig.resize(touched.size());
        wedgeTex = vcg::tri::HasPerWedgeTexCoord(m);
        for (size_t i = 0; i < touched.size(); ++i) {
            const FaceType &f = m.face[touched[i]];
            for (int k = 0; k < 3; ++k) {
                orig[i].v[k] = int(vcg::tri::Index(m, f.cV(k)));
                if (wedgeTex) orig[i].wt[k] = f.cWT(k);
            }
        }
    }

    /// v becomes w's vertex i: a user's vertex is copied; an added vertex takes its position,
    /// and colour, quality, normal and texture coordinate interpolated linearly in the user's
    /// face it lies in; a cut open's copy takes its original's.
    void Vertex(VertexType &v, int i) const
    {
        const vcg::Point3d &x = w.pos[i];
        if (i < w.vn0) {
            v.ImportData(src.vert[i]);
            return;
        }
        const int j = i - w.vn0;
        if (w.copyOf[j] >= 0) {
            Vertex(v, w.copyOf[j]); // (its original may be an added vertex, not written yet)
            v.P() = MeshType::CoordType::Construct(x);
            return;
        }
        const int F = w.addedOrigFaces[j][0];
        const Orig &o = orig[slot.at(F)];
        vcg::Point3d l = Bary(w.pos[o.v[0]], w.pos[o.v[1]], w.pos[o.v[2]], x);
        for (int k = 0; k < 3; ++k) l[k] = std::max(0.0, l[k]);
        l /= (l[0] + l[1] + l[2]);
        const VertexType *c[3] = {&src.vert[o.v[0]], &src.vert[o.v[1]], &src.vert[o.v[2]]};
        int big = 0;
        for (int k = 1; k < 3; ++k)
            if (l[k] > l[big]) big = k;
        v.ImportData(*c[big]); // flags and attributes not interpolated below
        v.P() = MeshType::CoordType::Construct(x);
        if (vcg::tri::HasPerVertexColor(src)) {
            vcg::Point4d col(0, 0, 0, 0);
            for (int k = 0; k < 3; ++k)
                for (int h = 0; h < 4; ++h) col[h] += l[k] * c[k]->cC()[h];
            for (int h = 0; h < 4; ++h) v.C()[h] = (unsigned char)std::min(255.0, std::max(0.0, col[h] + 0.5));
        }
        if (vcg::tri::HasPerVertexQuality(src))
            v.Q() = typename VertexType::QualityType(l[0] * c[0]->cQ() + l[1] * c[1]->cQ() + l[2] * c[2]->cQ());
        if (vcg::tri::HasPerVertexNormal(src)) {
            vcg::Point3d n(0, 0, 0);
            for (int k = 0; k < 3; ++k) n += vcg::Point3d::Construct(c[k]->cN()) * l[k];
            if (n.Norm() > 0) n.Normalize();
            v.N() = VertexType::NormalType::Construct(n);
        }
        if (vcg::tri::HasPerVertexTexCoord(src)) {
            vcg::Point2d t(0, 0);
            for (int k = 0; k < 3; ++k) t += vcg::Point2d(c[k]->cT().U(), c[k]->cT().V()) * l[k];
            v.T().U() = S(t[0]);
            v.T().V() = S(t[1]);
        }
    }

    /// f becomes w's face i on the vertices a, b, c (w's vertices i.v[0..2] written somewhere):
    /// with `import`, the attributes of the user's face it lies in; the per-wedge texture
    /// coordinates of a changed face interpolated in it (seams stay seams).
    void Face(FaceType &f, int i, VertexType *a, VertexType *b, VertexType *c, bool import) const
    {
        const CutWorkMesh::Face &wf = w.face[i];
        if (import) f.ImportData(src.face[wf.parent]);
        f.V(0) = a;
        f.V(1) = b;
        f.V(2) = c;
        if (!wedgeTex) return;
        const auto it = slot.find(wf.parent);
        if (it == slot.end()) return;
        const Orig &o = orig[it->second];
        for (int k = 0; k < 3; ++k) {
            vcg::Point3d l = Bary(w.pos[o.v[0]], w.pos[o.v[1]], w.pos[o.v[2]], w.pos[wf.v[k]]);
            vcg::Point2d t(0, 0);
            for (int h = 0; h < 3; ++h) t += vcg::Point2d(o.wt[h].U(), o.wt[h].V()) * l[h];
            f.WT(k).U() = S(t[0]);
            f.WT(k).V() = S(t[1]);
            f.WT(k).N() = o.wt[0].N();
        }
    }

private:
    struct Orig
    {
        int v[3];
        typename FaceType::TexCoordType wt[3];
    };
    const MeshType &src;
    const CutWorkMesh &w;
    std::vector<int> touched; ///< the user's faces that change
    std::vector<Orig> orig;   ///< per touched face, as it was
    std::unordered_map<int, int> slot; ///< per touched user's face, its index in orig
    bool wedgeTex = false;
};

} // namespace tri
} // namespace vcg

#endif
