#ifndef VCG_EXT_CUT_CURVE_EMBEDDING_H
#define VCG_EXT_CUT_CURVE_EMBEDDING_H

// Embeds curves on the surface into the mesh exactly: afterwards each curve runs along mesh
// edges through a chain of vertices. The curve's points (face + barycentric, surface/surface_point.h)
// and every crossing of a mesh edge become vertices, whatever edges earlier passes of the
// curve split (several crossings of one edge): the segment between two consecutive points lies
// in one face of the user's mesh, and is walked through that face's sub-faces in the face's
// plane, splitting each sub-edge it crosses. Points and crossings closer than Param::snap x the
// face's longest edge to a vertex or an edge snap to it (no slivers). Unlike vcglib's CoM this
// never moves the curve by more than that, and refuses (SnakeError) instead of losing a loop:
// a curve that crosses or touches itself, leaves its faces, or crosses a non-manifold edge.

#include <cmath>
#include <string>
#include <unordered_set>
#include <vector>

#include <vcg_ext/cut/cut_work_mesh.h>
#include <vcg_ext/snake/error.h>
#include <vcg_ext/surface/surface_point.h>

namespace vcg {
namespace tri {

/// A curve on the surface: consecutive points share a face of the mesh (as a snake's polyline,
/// snake/polyline.h, or a chain of vertices and edge crossings). Closed curves do not repeat
/// their first point.
struct CutCurve
{
    std::vector<SurfacePoint> points;
    bool closed = false;
};

/// A curve embedded in a CutWorkMesh: the chain of its vertices (closed: the first not repeated).
struct EmbeddedCurve
{
    std::vector<int> chain;
    bool closed = false;
};

template <class MeshType>
class CurveEmbedding
{
public:
    struct Param
    {
        /// Points and crossings this close to a vertex or an edge (times the longest edge of
        /// their face) go onto it.
        double snap = 1e-6;
    };

    CurveEmbedding(const MeshType &mesh, CutWorkMesh &work, const Param &param) : m(mesh), w(work), p(param) {}

    std::vector<EmbeddedCurve> Embed(const std::vector<CutCurve> &curves)
    {
        if (!(p.snap >= 0 && p.snap < 0.1)) throw SnakeError("Cut: the snap tolerance must be in [0, 0.1).");
        std::vector<EmbeddedCurve> out;
        for (size_t c = 0; c < curves.size(); ++c) out.push_back(embed(curves[c], int(c)));
        return out;
    }

    const std::unordered_set<long long> &CurveEdges() const { return curveEdges; }

private:
    const MeshType &m;
    CutWorkMesh &w;
    Param p;
    std::unordered_set<long long> curveEdges;
    std::unordered_set<int> onCurve;

    /// A curve point on the user's mesh: its position, its faces, the vertex it is at (or -1).
    struct Target
    {
        vcg::Point3d q;
        std::vector<int> faces;
        int vertex = -1;
    };

    struct Frame
    {
        vcg::Point3d o, e1, e2;
        double tol = 0;
        vcg::Point2d operator()(const vcg::Point3d &x) const { return vcg::Point2d((x - o) * e1, (x - o) * e2); }
    };

    static double cross(const vcg::Point2d &a, const vcg::Point2d &b) { return a[0] * b[1] - a[1] * b[0]; }

    [[noreturn]] static void fail(const std::string &why, int curve, int point)
    {
        throw SnakeError("Cut: " + why + " (curve " + std::to_string(curve + 1) + ", point " + std::to_string(point) +
                         "). The mesh was not changed.");
    }

    Frame frame(int F) const
    {
        const auto &f = m.face[F];
        vcg::Point3d a = vcg::Point3d::Construct(f.cV(0)->cP()), b = vcg::Point3d::Construct(f.cV(1)->cP()),
                     c = vcg::Point3d::Construct(f.cV(2)->cP());
        Frame fr;
        fr.o = a;
        fr.e1 = (b - a).Normalize();
        vcg::Point3d n = (b - a) ^ (c - a);
        fr.e2 = (n.Normalize() ^ fr.e1).Normalize();
        fr.tol = p.snap * std::max((b - a).Norm(), std::max((c - b).Norm(), (a - c).Norm()));
        return fr;
    }

    Target locate(const SurfacePoint &sp0, int curve, int point) const
    {
        if (!sp0.OnMesh(m)) fail("a curve point is not on this mesh (face index out of range, deleted face or "
                                 "barycentric coordinates outside the triangle)", curve, point);
        SurfacePoint sp = sp0;
        sp.Normalize();
        const auto &f = m.face[sp.face];
        int nz = 0, last = -1;
        for (int k = 0; k < 3; ++k)
            if (sp.bary[k] < p.snap) sp.bary[k] = 0;
            else { ++nz; last = k; }
        sp.Normalize();
        Target t;
        t.q = sp.Pd(m);
        if (nz == 1) {
            t.vertex = int(vcg::tri::Index(m, f.cV(last)));
            t.faces = w.OrigFaces(t.vertex);
        } else if (nz == 2) {
            int a = -1, b = -1;
            for (int k = 0; k < 3; ++k)
                if (sp.bary[k] > 0) (a < 0 ? a : b) = int(vcg::tri::Index(m, f.cV(k)));
            for (int g : w.OrigFaces(a)) {
                const auto &G = m.face[g];
                for (int k = 0; k < 3; ++k)
                    if (int(vcg::tri::Index(m, G.cV(k))) == b) t.faces.push_back(g);
            }
        } else {
            t.faces = {sp.face};
        }
        return t;
    }

    EmbeddedCurve embed(const CutCurve &c, int ci)
    {
        EmbeddedCurve e;
        e.closed = c.closed;
        const int n = int(c.points.size());
        if (n < (c.closed ? 3 : 2)) fail("the curve has too few points to cut along", ci, 0);
        Target t0 = locate(c.points[0], ci, 0);
        int u = t0.vertex >= 0 ? t0.vertex : insertAt(c.points[0].face, t0.q, ci, 0);
        const int first = u;
        e.chain.push_back(u);
        onCurve.insert(u);
        for (int i = 1; i <= n; ++i) {
            if (i == n && !c.closed) break;
            Target t;
            if (i < n) t = locate(c.points[i], ci, i);
            else {
                t.q = w.pos[first];
                t.vertex = first;
                t.faces = w.OrigFaces(first);
            }
            if (u == first && i > 1 && i < n) {
                // back at the start before the last point (the closing points snapped onto it):
                // the rest must stay there, else the curve touches itself
                if (t.vertex != first && (t.q - w.pos[first]).Norm() > frame(t.faces[0]).tol)
                    fail("the curve crosses or touches itself", ci, i);
                continue;
            }
            u = walk(u, t, e.chain, c.closed ? first : -1, ci, i % n);
        }
        if (c.closed) {
            if (e.chain.size() < 4 || e.chain.back() != first)
                fail("the closed curve encloses no area once embedded (shorter than the snap tolerance)", ci, 0);
            e.chain.pop_back();
        } else if (e.chain.size() < 2) {
            fail("the open curve has no length once embedded", ci, 0);
        }
        return e;
    }

    /// A vertex at q inside the user's face F (its sub-face holding q; snapped to a vertex or edge).
    int insertAt(int F, const vcg::Point3d &q, int ci, int pi)
    {
        Frame fr = frame(F);
        const vcg::Point2d Q = fr(q);
        int best = -1;
        double bestD = -1e300;
        for (int c : w.Children(F)) {
            double d = 1e300;
            for (int k = 0; k < 3; ++k) {
                vcg::Point2d a = fr(w.pos[w.face[c].v[k]]), b = fr(w.pos[w.face[c].v[(k + 1) % 3]]);
                double l = (b - a).Norm();
                d = std::min(d, l > 0 ? cross(b - a, Q - a) / l : 0.0);
            }
            if (d > bestD) { bestD = d; best = c; }
        }
        if (best < 0 || bestD < -fr.tol - 1e-9 * fr.tol / std::max(p.snap, 1e-300))
            fail("a curve point lies outside its face", ci, pi);
        return insertInFace(best, fr, q, ci, pi);
    }

    int insertInFace(int f, const Frame &fr, const vcg::Point3d &q, int ci, int pi)
    {
        const vcg::Point2d Q = fr(q);
        for (int k = 0; k < 3; ++k) {
            int v = w.face[f].v[k];
            if ((fr(w.pos[v]) - Q).Norm() <= fr.tol) return v;
        }
        for (int k = 0; k < 3; ++k) {
            int a = w.face[f].v[k], b = w.face[f].v[(k + 1) % 3];
            vcg::Point2d A = fr(w.pos[a]), B = fr(w.pos[b]);
            double l = (B - A).Norm();
            if (l > 0 && std::abs(cross(B - A, Q - A)) / l <= fr.tol) {
                double t = std::min(1.0, std::max(0.0, ((Q - A) * (B - A)) / (l * l)));
                return splitEdge(a, b, t, ci, pi);
            }
        }
        return w.SplitFace(f, q);
    }

    int splitEdge(int a, int b, double t, int ci, int pi)
    {
        if (curveEdges.count(CutWorkMesh::EdgeKey(a, b))) fail("the curve crosses or touches itself", ci, pi);
        return w.SplitEdge(a, b, t);
    }

    void step(int u, int x, std::vector<int> &chain, int closing, int ci, int pi)
    {
        if (u == x) return;
        if (!curveEdges.insert(CutWorkMesh::EdgeKey(u, x)).second) fail("the curve runs over itself", ci, pi);
        if (onCurve.count(x) && x != closing) fail("the curve crosses or touches itself", ci, pi);
        onCurve.insert(x);
        chain.push_back(x);
    }

    /// From vertex u to the target, splitting every sub-edge crossed; returns the target's vertex.
    int walk(int u, const Target &t, std::vector<int> &chain, int closing, int ci, int pi)
    {
        if (t.vertex == u) return u;
        std::vector<int> uf = w.OrigFaces(u);
        int F = -1;
        for (int g : t.faces)
            if (std::find(uf.begin(), uf.end(), g) != uf.end()) { F = g; break; }
        if (F < 0) fail("two consecutive curve points share no face of this mesh: the curve is not on this mesh", ci, pi);
        const Frame fr = frame(F);
        const vcg::Point2d Q = fr(t.q);
        const int from = u;
        for (int guard = 0; guard < 100000; ++guard) {
            const vcg::Point2d U = fr(w.pos[u]);
            const vcg::Point2d d = Q - U;
            if (d.Norm() <= fr.tol && (t.vertex < 0 || t.vertex == u)) return u;
            if (u == closing && u != from) fail("the curve crosses or touches itself", ci, pi); // through its start
            std::vector<int> fs;
            for (int f : w.Faces(u))
                if (w.face[f].parent == F) fs.push_back(f);
            if (fs.empty()) fail("the curve leaves its face", ci, pi);
            // along an edge from u
            bool moved = false;
            for (int f : fs) {
                const int k = w.Corner(f, u);
                for (int nb : {w.face[f].v[(k + 1) % 3], w.face[f].v[(k + 2) % 3]}) {
                    const vcg::Point2d e = fr(w.pos[nb]) - U;
                    const double el = e.Norm();
                    if (el == 0) continue;
                    const double off = cross(e, d) / el, along = (e * d) / el;
                    if (nb == t.vertex || (std::abs(off) <= fr.tol && along > 0 && t.vertex < 0) ||
                        (std::abs(off) <= fr.tol && along > el + fr.tol)) {
                        if (nb == t.vertex || std::abs(along - el) <= fr.tol) {
                            step(u, nb, chain, closing, ci, pi);
                            return nb;
                        }
                        if (along > el) {
                            step(u, nb, chain, closing, ci, pi);
                            u = nb;
                        } else {
                            const int x = splitEdge(u, nb, along / el, ci, pi);
                            step(u, x, chain, closing, ci, pi);
                            return x;
                        }
                        moved = true;
                        break;
                    }
                }
                if (moved) break;
            }
            if (moved) continue;
            // through the face whose corner at u holds the direction
            for (int f : fs) {
                const int k = w.Corner(f, u);
                const int a = w.face[f].v[(k + 1) % 3], b = w.face[f].v[(k + 2) % 3];
                const vcg::Point2d A = fr(w.pos[a]), B = fr(w.pos[b]);
                if (!(cross(A - U, d) > 0 && cross(d, B - U) > 0)) continue;
                const vcg::Point2d ab = B - A;
                const double l = ab.Norm();
                const double s = cross(ab, Q - A) / l; // > 0: Q on u's side of (a, b)
                if (s > fr.tol && t.vertex < 0) {
                    const int x = insertInFace(f, fr, t.q, ci, pi);
                    step(u, x, chain, closing, ci, pi);
                    return x;
                }
                const bool ends = s >= -fr.tol && t.vertex < 0; // the target is on (a, b)
                double tt = ends ? ((Q - A) * ab) / (l * l) : cross(U - A, d) / cross(ab, d);
                tt = std::min(1.0, std::max(0.0, tt));
                int x;
                if (tt * l <= fr.tol) x = a;
                else if ((1 - tt) * l <= fr.tol) x = b;
                else x = splitEdge(a, b, tt, ci, pi);
                step(u, x, chain, closing, ci, pi);
                if (ends) return x;
                u = x;
                moved = true;
                break;
            }
            if (!moved) fail("the curve leaves its face (it is not on this mesh, or the face is degenerate)", ci, pi);
        }
        fail("the curve could not be embedded (too many crossings)", ci, pi);
    }
};

} // namespace tri
} // namespace vcg

#endif
