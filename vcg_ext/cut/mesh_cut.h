#ifndef VCG_EXT_CUT_MESH_CUT_H
#define VCG_EXT_CUT_MESH_CUT_H

// Cutting a mesh along curves on its surface (snakes): the curves are embedded exactly
// (curve_embedding.h), the sides flooded (cut_sides.h), the result checked (cut_check.h), and
// only then written into the user's mesh (cut_commit.h). Modes: select one side, select it by
// the faces' centroids without changing the mesh, split into two meshes, or cut open (the
// curves' edges become boundary edges). A refused or failed cut leaves the mesh as it was.

#include <algorithm>
#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include <vcg/complex/algorithms/update/selection.h>
#include <vcg/complex/append.h>
#include <vcg/complex/complex.h>

#include <vcg_ext/cut/curve_embedding.h>
#include <vcg_ext/cut/cut_check.h>
#include <vcg_ext/cut/cut_commit.h>
#include <vcg_ext/cut/cut_open.h>
#include <vcg_ext/cut/cut_point_map.h>
#include <vcg_ext/cut/cut_sides.h>
#include <vcg_ext/cut/cut_work_mesh.h>
#include <vcg_ext/snake/error.h>
#include <unordered_set>

namespace vcg {
namespace tri {

enum class CutMode {
    Select = 0,     ///< embed the curves; the chosen side becomes the face (and vertex) selection
    SelectOnly = 1, ///< select the user's faces whose centroid is on the chosen side; the mesh is unchanged
    Split = 2,      ///< two meshes, the chosen side ("inside") and the rest ("outside")
    CutOpen = 3     ///< the curves' edges become boundary edges (an open curve ending inside: a slit)
};

enum class CutSide {
    Smaller = 0, ///< the side of smaller area
    Larger = 1,  ///< the side of larger area
    Inside = 2,  ///< the side the first curve's normal points away from (the side the Balloon inflates);
                 ///< the left of an open curve
    Outside = 3  ///< the other one; the right of an open curve
};

template <class MeshType>
class MeshCut
{
public:
    struct Param
    {
        CutMode mode = CutMode::Select;
        CutSide side = CutSide::Smaller;
        double snap = 1e-6; ///< CurveEmbedding::Param::snap
    };

    struct Result
    {
        /// Per face of the mesh after the cut (Split: of the embedded mesh, before it is split):
        /// 1 on the chosen side, 0 elsewhere.
        std::vector<int> faceSide;
        int addedVertices = 0, addedFaces = 0, curveVertices = 0;
        int facesInside = 0, facesOutside = 0;
        double areaInside = 0, areaOutside = 0;
        bool chosenLeft = true;
        /// Select and CutOpen: surface points of the mesh before the cut to the mesh after it
        /// (the user's snakes); SelectOnly and Split leave the mesh as it was (an empty map).
        CutPointMap points;
        /// Select and CutOpen: each curve as embedded, its vertices as surface points of the mesh
        /// after the cut (a snake cut along keeps it as its polyline: CutSessionMap::KeepCurve).
        std::vector<std::vector<SurfacePoint>> chains;
        double msEmbed = 0, msSides = 0, msCheck = 0, msCommit = 0, msSplit = 0;
        double msPart[2] = {0, 0}; ///< Split: writing the inside and the outside part (in msSplit)
    };

    static std::string ModeName(CutMode m)
    {
        static const char *const n[] = {"select", "select only", "split", "cut open"};
        return n[int(m)];
    }

private:
    struct Work;

public:
    /// A cut embedded, flooded and checked on a work mesh, not yet written into the user's mesh
    /// (Plan): its caller learns before anything changes whether the mesh will (an edit tool
    /// copies the mesh for its undo only then), and Apply writes it without tracing anew.
    class Planned
    {
    public:
        /// The user's mesh gets vertices or faces (Select with a curve not yet along its edges,
        /// CutOpen always); false: only the selection changes (SelectOnly, Select along edges).
        bool ChangesMesh() const
        {
            return mode == CutMode::CutOpen ||
                   (mode == CutMode::Select && (wk->r.addedVertices > 0 || wk->r.addedFaces > 0));
        }
        int AddedVertices() const { return wk->r.addedVertices; }
        int AddedFaces() const { return wk->r.addedFaces; }

    private:
        friend class MeshCut;
        std::unique_ptr<Work> wk;
        CutMode mode = CutMode::Select;
    };

    /// Select, SelectOnly and CutOpen without changing m: the curves embedded into a work mesh
    /// (the same tracing Apply does) and the sides flooded; refusals throw here.
    static Planned Plan(const MeshType &m, const std::vector<CutCurve> &curves, const Param &p)
    {
        if (p.mode == CutMode::Split) throw SnakeError("Cut: use MeshCut::Split for the split mode.");
        Planned pl;
        pl.wk.reset(new Work(prepare(m, curves, p)));
        pl.mode = p.mode;
        return pl;
    }

    /// Select, SelectOnly and CutOpen: changes m (SelectOnly: only its selection).
    static Result Apply(MeshType &m, const std::vector<CutCurve> &curves, const Param &p)
    {
        return Apply(m, Plan(m, curves, p));
    }

    /// Writes a Plan of m (m not changed since) into m.
    static Result Apply(MeshType &m, Planned plan)
    {
        if (!plan.wk) throw SnakeError("Cut: no plan to apply.");
        Work &wk = *plan.wk;
        if (int(m.vert.size()) != wk.w.vn0 || int(m.face.size()) != wk.w.fn0)
            throw SnakeError("Cut: the mesh changed since the cut was planned. The mesh was not changed.");
        Result &r = wk.r;
        if (plan.mode == CutMode::SelectOnly) {
            selectByCentroid(m, wk);
            return r;
        }
        auto t0 = clock::now();
        if (plan.mode == CutMode::CutOpen) {
            CutOpen::Open(wk.w, wk.curves, wk.curveEdges);
            CutCheck::AfterOpen(wk.w, wk.curves, wk.totalArea);
            r.addedVertices = int(wk.w.pos.size()) - wk.w.vn0; // with the copies of the curve's vertices
        }
        r.msCheck += ms(t0);
        t0 = clock::now();
        r.points.Build(m, wk.w);
        for (const EmbeddedCurve &c : wk.curves) {
            r.chains.emplace_back();
            for (int v : c.chain) { // in one of its faces (the work mesh's are the mesh's after the commit)
                const std::vector<int> &fs = wk.w.Faces(v);
                vcg::Point3d b(0, 0, 0);
                if (!fs.empty()) b[wk.w.Corner(fs.front(), v)] = 1;
                r.chains.back().push_back(SurfacePoint(fs.empty() ? -1 : fs.front(), b));
            }
        }
        CutCommit<MeshType>::Commit(m, wk.w);
        r.msCommit = ms(t0);
        markSides(m, wk);
        return r;
    }

    /// Split: `inside` gets the chosen side, `outside` the rest; m is not changed.
    static Result Split(MeshType &m, const std::vector<CutCurve> &curves, const Param &p, MeshType &inside,
                        MeshType &outside)
    {
        if (m.vn != int(m.vert.size()) || m.fn != int(m.face.size()))
            throw SnakeError("Cut: the mesh has deleted vertices or faces; compact it first. The mesh was not changed.");
        Work wk = prepare(m, curves, p);
        auto t0 = clock::now();
        // each part is written straight from the user's mesh and the work mesh: the faces its
        // flood found and the vertices they use, nothing else, so it costs in proportion to
        // its own size. The chosen side is flooded to its end (prepare); the other side is its
        // complement (faces no flood reached, of other connected components, included): the
        // other side's flood when it is complete and the two cover the mesh, else a scan of
        // the labels, when the other side is the larger one.
        const CutWorkMesh &w = wk.w;
        CutSides::Result &s = wk.sides;
        const int in = wk.chosen == CutSides::Left ? 0 : 1;
        const std::vector<int> &inFaces = s.faces[in];
        std::vector<int> &outFaces = s.faces[1 - in];
        if (!(s.complete[1 - in] && inFaces.size() + outFaces.size() == w.face.size())) {
            outFaces.clear();
            outFaces.reserve(w.face.size() - inFaces.size());
            for (size_t f = 0; f < w.face.size(); ++f)
                if (s.label[f] != wk.chosen) outFaces.push_back(int(f));
        }
        const CutCommit<MeshType> src(m, w);
        Result &r = wk.r;
        r.faceSide.assign(w.face.size(), 0);
        for (int f : inFaces) r.faceSide[f] = 1;
        r.facesInside = int(inFaces.size());
        r.facesOutside = int(outFaces.size());
        r.msCommit = ms(t0);
        t0 = clock::now();
        // work vertex -> part vertex: one table over the work mesh's vertices for both parts,
        // filled once per split (in msSplit); writePart resets the entries its part set, so
        // each part costs in proportion to its own size
        std::vector<int> slot(w.pos.size(), -1);
        for (int part = 0; part < 2; ++part) {
            const auto tp = clock::now();
            writePart(w, src, part == 0 ? inFaces : outFaces, m, part == 0 ? inside : outside, slot);
            r.msPart[part] = ms(tp);
        }
        r.msSplit = ms(t0);
        CutCheck::Parts(inside, outside, wk.r.areaInside, wk.r.areaOutside, wk.totalArea);
        return wk.r;
    }

    /// Enables on dst the optional (ocf) per-wedge texture coordinate, per-vertex texture
    /// coordinate, per-face colour and quality that src has enabled; nothing for other meshes.
    static void EnableLike(MeshType &dst, const MeshType &src)
    {
        enableWT(dst.face, src.face, 0);
        enableFC(dst.face, src.face, 0);
        enableFQ(dst.face, src.face, 0);
        enableVT(dst.vert, src.vert, 0);
    }

private:
    template <class C> static auto enableWT(C &d, const C &s, int) -> decltype(d.EnableWedgeTexCoord(), void())
    { if (s.IsWedgeTexCoordEnabled() && !d.IsWedgeTexCoordEnabled()) d.EnableWedgeTexCoord(); }
    template <class C> static void enableWT(C &, const C &, long) {}
    template <class C> static auto enableFC(C &d, const C &s, int) -> decltype(d.EnableColor(), void())
    { if (s.IsColorEnabled() && !d.IsColorEnabled()) d.EnableColor(); }
    template <class C> static void enableFC(C &, const C &, long) {}
    template <class C> static auto enableFQ(C &d, const C &s, int) -> decltype(d.EnableQuality(), void())
    { if (s.IsQualityEnabled() && !d.IsQualityEnabled()) d.EnableQuality(); }
    template <class C> static void enableFQ(C &, const C &, long) {}
    template <class C> static auto enableVT(C &d, const C &s, int) -> decltype(d.EnableTexCoord(), void())
    { if (s.IsTexCoordEnabled() && !d.IsTexCoordEnabled()) d.EnableTexCoord(); }
    template <class C> static void enableVT(C &, const C &, long) {}

    /// One part of a split: the work mesh's `faces` and their vertices into dst; slot[v] is the
    /// part's index of work vertex v, -1 until it has one, and -1 again on return.
    static void writePart(const CutWorkMesh &w, const CutCommit<MeshType> &src, const std::vector<int> &faces,
                          const MeshType &m, MeshType &dst, std::vector<int> &slot)
    {
        dst.Clear();
        // the optional components MeshLab's meshes hold (texture coordinates, face colour and
        // quality) come along into the parts
        EnableLike(dst, m);
        std::vector<int> verts;
        for (int f : faces)
            for (int k = 0; k < 3; ++k) {
                int &i = slot[w.face[f].v[k]];
                if (i < 0) {
                    i = int(verts.size());
                    verts.push_back(w.face[f].v[k]);
                }
            }
        if (!verts.empty()) vcg::tri::Allocator<MeshType>::AddVertices(dst, verts.size());
        for (size_t i = 0; i < verts.size(); ++i) src.Vertex(dst.vert[i], verts[i]);
        if (!faces.empty()) vcg::tri::Allocator<MeshType>::AddFaces(dst, faces.size());
        for (size_t i = 0; i < faces.size(); ++i) {
            const CutWorkMesh::Face &wf = w.face[faces[i]];
            src.Face(dst.face[i], faces[i], &dst.vert[slot[wf.v[0]]], &dst.vert[slot[wf.v[1]]],
                     &dst.vert[slot[wf.v[2]]], true);
        }
        for (int v : verts) slot[v] = -1;
        vcg::tri::UpdateSelection<MeshType>::Clear(dst);
        vcg::tri::UpdateBounding<MeshType>::Box(dst);
    }

    typedef std::chrono::steady_clock clock;
    static double ms(clock::time_point t0) { return std::chrono::duration<double, std::milli>(clock::now() - t0).count(); }

    struct Work
    {
        CutWorkMesh w;
        std::vector<EmbeddedCurve> curves;
        std::unordered_set<long long> curveEdges;
        CutSides::Result sides;
        unsigned char chosen = CutSides::Left;
        double totalArea = 0;
        Result r;
    };

    static Work prepare(const MeshType &m, const std::vector<CutCurve> &curves, const Param &p)
    {
        if (curves.empty()) throw SnakeError("Cut: no curve to cut along.");
        if (m.fn == 0) throw SnakeError("Cut: the mesh has no faces.");
        Work wk;
        auto t0 = clock::now();
        wk.w.Build(m);
        for (size_t f = 0; f < wk.w.face.size(); ++f)
            if (wk.w.face[f].parent >= 0) wk.totalArea += wk.w.Area(int(f));
        typename CurveEmbedding<MeshType>::Param ep;
        ep.snap = p.snap;
        CurveEmbedding<MeshType> emb(m, wk.w, ep);
        wk.curves = emb.Embed(curves);
        wk.curveEdges = emb.CurveEdges();
        wk.r.msEmbed = ms(t0);
        t0 = clock::now();
        bool open = false, endsInside = false;
        for (const auto &c : wk.curves)
            if (!c.closed) {
                open = true;
                for (int v : {c.chain.front(), c.chain.back()})
                    if (!CutCheck::OnBoundary(wk.w, v)) endsInside = true;
            }
        const bool needSides = p.mode != CutMode::CutOpen;
        if (needSides && endsInside)
            throw SnakeError("Cut: the open curve ends inside the mesh, so it has no two sides to " +
                             std::string(p.mode == CutMode::Split ? "split into" : "select") +
                             " (only \"cut open\" makes a slit). Extend it to the mesh's boundary or close it. "
                             "The mesh was not changed.");
        wk.sides = CutSides::Compute(wk.w, wk.curves, wk.curveEdges);
        if (needSides && !wk.sides.separated)
            throw SnakeError(std::string("Cut: the curve does not separate the surface into two sides (") +
                             (open ? "its sides join around it" : "a loop around a handle or a tube, such as a "
                                                                  "torus's meridian") +
                             "). The mesh was not changed.");
        CutSides::Result &s = wk.sides;
        const bool smallerIsLeft = s.complete[0];
        bool left;
        switch (p.side) {
        case CutSide::Smaller: left = smallerIsLeft; break;
        case CutSide::Larger: left = !smallerIsLeft; break;
        case CutSide::Inside: left = s.orientation > 0 || open; break;
        default: left = !(s.orientation > 0 || open); break;
        }
        wk.chosen = left ? CutSides::Left : CutSides::Right;
        wk.r.chosenLeft = left;
        if (s.separated) CutSides::Complete(wk.w, s, wk.chosen);
        wk.r.msSides = ms(t0);
        t0 = clock::now();
        CutCheck::Embedded(wk.w, wk.curves, s, wk.chosen, wk.totalArea);
        wk.r.msCheck = ms(t0);
        wk.r.addedVertices = int(wk.w.pos.size()) - wk.w.vn0;
        wk.r.addedFaces = int(wk.w.face.size()) - wk.w.fn0;
        for (const auto &c : wk.curves) wk.r.curveVertices += int(c.chain.size());
        wk.r.areaInside = left ? s.areaLeft : s.areaRight;
        wk.r.areaOutside = wk.totalArea - wk.r.areaInside;
        wk.r.facesInside = left ? s.facesLeft : s.facesRight;
        return wk;
    }

    /// faceSide, the face selection and the vertex selection: the faces f with in(f).
    template <class InFn>
    static void select(MeshType &m, Result &r, InFn in)
    {
        r.faceSide.assign(m.face.size(), 0);
        vcg::tri::UpdateSelection<MeshType>::FaceClear(m);
        vcg::tri::UpdateSelection<MeshType>::VertexClear(m);
        r.facesInside = r.facesOutside = 0;
        for (size_t f = 0; f < m.face.size(); ++f) {
            if (m.face[f].IsD()) continue;
            if (!in(int(f))) {
                ++r.facesOutside;
                continue;
            }
            r.faceSide[f] = 1;
            m.face[f].SetS();
            for (int k = 0; k < 3; ++k) m.face[f].V(k)->SetS();
            ++r.facesInside;
        }
    }

    /// The selection from the work mesh's labels (its faces are the mesh's after the commit).
    static void markSides(MeshType &m, Work &wk)
    {
        const auto &lab = wk.sides.label;
        select(m, wk.r, [&](int f) { return wk.sides.separated && f < int(lab.size()) && lab[f] == wk.chosen; });
    }

    /// SelectOnly: each user's face takes the side of its sub-face holding its centroid.
    static void selectByCentroid(MeshType &m, Work &wk)
    {
        Result &r = wk.r;
        const auto &split = wk.w.SplitParents();
        select(m, r, [&](int f) {
            int lab = wk.sides.label[f];
            auto it = split.find(f);
            if (it != split.end()) {
                const vcg::Point3d c = (vcg::Point3d::Construct(m.face[f].cV(0)->cP()) +
                                        vcg::Point3d::Construct(m.face[f].cV(1)->cP()) +
                                        vcg::Point3d::Construct(m.face[f].cV(2)->cP())) / 3.0;
                double best = -1e300;
                for (int g : wk.w.Children(f)) {
                    const auto &G = wk.w.face[g];
                    vcg::Point3d l = CutCommit<MeshType>::Bary(wk.w.pos[G.v[0]], wk.w.pos[G.v[1]], wk.w.pos[G.v[2]], c);
                    const double mn = std::min(l[0], std::min(l[1], l[2]));
                    if (mn > best) { best = mn; lab = wk.sides.label[g]; }
                }
            }
            return lab == wk.chosen;
        });
        r.areaInside = 0;
        for (size_t f = 0; f < m.face.size(); ++f)
            if (r.faceSide[f]) r.areaInside += vcg::DoubleArea(m.face[f]) / 2;
        r.areaOutside = wk.totalArea - r.areaInside;
        r.addedVertices = r.addedFaces = 0;
    }
};

} // namespace tri
} // namespace vcg

#endif
