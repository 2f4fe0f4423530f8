#ifndef VCG_EXT_CUT_CUT_SIDES_H
#define VCG_EXT_CUT_CUT_SIDES_H

// The two sides of embedded curves: the faces left of the curves' edges (the edge runs along
// the face's own order) and those right of them, each flooded over the mesh without crossing a
// curve edge. The curves separate the surface when no flood reaches the other side's faces (a
// torus meridian does not, nor an open curve that ends inside the mesh). Each flood visits only
// its side's faces: linear in the part's size.

#include <cmath>
#include <string>
#include <unordered_set>
#include <vector>

#include <vcg_ext/cut/curve_embedding.h>
#include <vcg_ext/cut/cut_work_mesh.h>
#include <vcg_ext/snake/error.h>

namespace vcg {
namespace tri {

class CutSides
{
public:
    enum Label : unsigned char { None = 0, Left = 1, Right = 2 };

    struct Result
    {
        std::vector<unsigned char> label; ///< per face of the work mesh
        std::vector<int> leftSeeds, rightSeeds;
        double areaLeft = 0, areaRight = 0; ///< flooded so far (final once the side is complete)
        int facesLeft = 0, facesRight = 0;
        bool separated = true;
        bool complete[2] = {false, false}; ///< left, right flooded to their end
        std::vector<int> stack[2];
        std::vector<int> faces[2]; ///< left, right: the faces flooded so far, in flood order
        std::vector<char> onCurve;
        const std::unordered_set<long long> *curveEdges = nullptr;
        /// +1 when the first curve runs counter-clockwise seen from the front of its left side
        /// (its vector area agrees with the normals along it), as GeometricSnake::orientation
        /// decides the Balloon's outside: then its inside is on its left.
        double orientation = 1;
    };

    static long long Key(int a, int b) { return CutWorkMesh::EdgeKey(a, b); }

    /// The faces on each side of every curve edge; refuses a non-manifold curve edge or vertex.
    static void Seeds(const CutWorkMesh &w, const std::vector<EmbeddedCurve> &curves, Result &r)
    {
        for (size_t c = 0; c < curves.size(); ++c) {
            const auto &ch = curves[c].chain;
            const int n = int(ch.size()), ne = curves[c].closed ? n : n - 1;
            for (int i = 0; i < ne; ++i) {
                const int a = ch[i], b = ch[(i + 1) % n];
                const std::vector<int> fs = w.EdgeFaces(a, b);
                if (fs.empty() || fs.size() > 2)
                    throw SnakeError("Cut: the mesh is not manifold along the cut (an edge of the curve has " +
                                     std::to_string(fs.size()) + " faces). The mesh was not changed.");
                for (int f : fs) {
                    const int k = w.Corner(f, a);
                    (w.face[f].v[(k + 1) % 3] == b ? r.leftSeeds : r.rightSeeds).push_back(f);
                }
            }
            for (int v : ch)
                if (!ManifoldVertex(w, v))
                    throw SnakeError("Cut: the mesh is not manifold along the cut (the curve passes through a "
                                     "vertex where separate sheets of faces meet). The mesh was not changed.");
        }
    }

    /// The faces around v form one fan (joined through the edges at v).
    static bool ManifoldVertex(const CutWorkMesh &w, int v)
    {
        std::vector<int> fs = w.Faces(v);
        if (fs.empty()) return false;
        std::vector<char> seen(fs.size(), 0);
        std::vector<int> stack{0};
        seen[0] = 1;
        int count = 1;
        while (!stack.empty()) {
            const int i = stack.back();
            stack.pop_back();
            for (size_t j = 0; j < fs.size(); ++j) {
                if (seen[j]) continue;
                // share an edge at v: a second common vertex
                int common = 0;
                for (int k = 0; k < 3; ++k)
                    if (w.face[fs[j]].v[k] != v && w.Has(fs[i], w.face[fs[j]].v[k])) ++common;
                if (common > 0) {
                    seen[j] = 1;
                    ++count;
                    stack.push_back(int(j));
                }
            }
        }
        return count == int(fs.size());
    }

    /// Floods the two sides in turn, the one of less area so far first, until one is complete:
    /// that is the smaller side (up to one face's area), found in time linear in its size.
    /// `curveEdges` holds the curves' edges (CurveEmbedding::CurveEdges). The other side is
    /// complete only after Complete().
    static Result Compute(const CutWorkMesh &w, const std::vector<EmbeddedCurve> &curves,
                          const std::unordered_set<long long> &curveEdges)
    {
        Result r;
        Seeds(w, curves, r);
        r.label.assign(w.face.size(), None);
        r.onCurve.assign(w.pos.size(), 0);
        for (const auto &c : curves)
            for (int v : c.chain) r.onCurve[v] = 1;
        r.curveEdges = &curveEdges;
        for (int side = 0; side < 2; ++side)
            for (int f : side == 0 ? r.leftSeeds : r.rightSeeds) {
                const unsigned char lab = side == 0 ? Left : Right;
                if (r.label[f] == lab) continue;
                if (r.label[f] != None) r.separated = false;
                r.label[f] = lab;
                r.stack[side].push_back(f);
                r.faces[side].push_back(f);
                (side == 0 ? r.areaLeft : r.areaRight) += w.Area(f);
                ++(side == 0 ? r.facesLeft : r.facesRight);
            }
        while (r.separated && !r.stack[0].empty() && !r.stack[1].empty())
            expand(w, r, r.areaLeft <= r.areaRight ? 0 : 1);
        if (r.separated) r.complete[r.stack[0].empty() ? 0 : 1] = true;
        r.orientation = Orientation(w, curves.empty() ? EmbeddedCurve() : curves[0], r);
        return r;
    }

    /// Floods side `lab` (Left or Right) to its end.
    static void Complete(const CutWorkMesh &w, Result &r, unsigned char lab)
    {
        const int side = lab == Left ? 0 : 1;
        while (r.separated && !r.stack[side].empty()) expand(w, r, side);
        r.complete[side] = r.separated;
    }

    /// The first curve's vector area against the normals of the faces along it (see Result).
    static double Orientation(const CutWorkMesh &w, const EmbeddedCurve &c, const Result &r)
    {
        if (c.chain.size() < 3) return 1;
        vcg::Point3d cen(0, 0, 0), area(0, 0, 0), normal(0, 0, 0);
        for (int v : c.chain) cen += w.pos[v];
        cen /= double(c.chain.size());
        for (size_t i = 0; i < c.chain.size(); ++i)
            area += (w.pos[c.chain[i]] - cen) ^ (w.pos[c.chain[(i + 1) % c.chain.size()]] - cen);
        for (int f : r.leftSeeds) normal += vcg::Point3d(w.Normal(f)).Normalize();
        for (int f : r.rightSeeds) normal += vcg::Point3d(w.Normal(f)).Normalize();
        return area * normal >= 0 ? 1.0 : -1.0;
    }

private:
    /// One face of side `side` off its stack: its neighbours across non-curve edges join it.
    static void expand(const CutWorkMesh &w, Result &r, int side)
    {
        const unsigned char lab = side == 0 ? Left : Right;
        const int f = r.stack[side].back();
        r.stack[side].pop_back();
        for (int k = 0; k < 3; ++k) {
            const int a = w.face[f].v[k], b = w.face[f].v[(k + 1) % 3];
            if (r.onCurve[a] && r.onCurve[b] && r.curveEdges->count(Key(a, b))) continue;
            w.ForFaces(a, [&](int g) {
                if (g == f || r.label[g] == lab || !w.Has(g, b)) return;
                if (r.label[g] != None) {
                    r.separated = false;
                    return;
                }
                r.label[g] = lab;
                r.stack[side].push_back(g);
                r.faces[side].push_back(g);
                (side == 0 ? r.areaLeft : r.areaRight) += w.Area(g);
                ++(side == 0 ? r.facesLeft : r.facesRight);
            });
        }
    }
};

} // namespace tri
} // namespace vcg

#endif
