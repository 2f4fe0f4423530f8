#ifndef VCG_EXT_CUT_CUT_WORK_MESH_H
#define VCG_EXT_CUT_CUT_WORK_MESH_H

// The mesh a cut is made on before it touches the user's mesh: vertex and face indices of the
// user's mesh (deleted ones included, never used), plus the vertices and faces the embedding
// adds. Faces are split in place (vcglib's edge split of RefineE and face::TriSplit, by index),
// so the user's mesh changes only when every check has passed (mesh_cut.h commits it).

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>
#include <vector>

#include <vcg/space/point2.h>
#include <vcg/space/point3.h>

#include <vcg_ext/snake/error.h>

namespace vcg {
namespace tri {

class CutWorkMesh
{
public:
    struct Face
    {
        int v[3] = {-1, -1, -1};
        int parent = -1; ///< the user's face it lies in; -1: a deleted face of the user's mesh
    };

    std::vector<vcg::Point3d> pos; ///< every vertex, in double
    std::vector<Face> face;
    int vn0 = 0, fn0 = 0;          ///< the user's vertex and face vectors' sizes
    /// Per added vertex (index - vn0): the user's faces it lies in (1 inside a face, 2 on an edge)
    /// and, for a vertex duplicated by a cut, the vertex it copies (-1 otherwise).
    std::vector<std::vector<int>> addedOrigFaces;
    std::vector<int> copyOf;

    template <class MeshType>
    void Build(const MeshType &m)
    {
        vn0 = int(m.vert.size());
        fn0 = int(m.face.size());
        pos.resize(vn0);
        for (int i = 0; i < vn0; ++i) pos[i] = vcg::Point3d::Construct(m.vert[i].cP());
        face.resize(fn0);
        std::vector<int> count(vn0 + 1, 0);
        for (int i = 0; i < fn0; ++i) {
            const auto &f = m.face[i];
            if (f.IsD()) continue;
            for (int k = 0; k < 3; ++k) {
                face[i].v[k] = int(vcg::tri::Index(m, f.cV(k)));
                ++count[face[i].v[k] + 1];
            }
            face[i].parent = i;
        }
        // vertex -> faces (CSR) for the user's mesh; changed vertices move to `changed`
        for (int i = 0; i < vn0; ++i) count[i + 1] += count[i];
        start = count;
        inc.assign(count[vn0], 0);
        for (int i = 0; i < fn0; ++i)
            if (face[i].parent >= 0)
                for (int k = 0; k < 3; ++k) inc[count[face[i].v[k]]++] = i;
        origStart = start;
    }

    static long long EdgeKey(int a, int b)
    {
        if (a > b) std::swap(a, b);
        return (long long)a << 32 | (unsigned)b;
    }

    int VertexCount() const { return int(pos.size()); }

    /// Barycentric coordinates of x in triangle (a, b, c) (x in its plane, up to round-off).
    static vcg::Point3d Bary(const vcg::Point3d &a, const vcg::Point3d &b, const vcg::Point3d &c, const vcg::Point3d &x)
    {
        const vcg::Point3d n = (b - a) ^ (c - a);
        const double nn = n * n;
        if (!(nn > 0)) return vcg::Point3d(1.0 / 3, 1.0 / 3, 1.0 / 3);
        vcg::Point3d l(((c - b) ^ (x - b)) * n / nn, ((a - c) ^ (x - c)) * n / nn, 0);
        l[2] = 1 - l[0] - l[1];
        return l;
    }

    /// The faces around vertex v now.
    const std::vector<int> &Faces(int v) const
    {
        auto it = changed.find(v);
        if (it != changed.end()) return it->second;
        scratch.assign(inc.begin() + start[v], inc.begin() + start[v + 1]);
        return scratch;
    }
    /// Calls fn(f) for each face around vertex v (no copy: fn must not change the mesh).
    template <class Fn>
    void ForFaces(int v, Fn fn) const
    {
        auto it = changed.find(v);
        if (it != changed.end()) {
            for (int f : it->second) fn(f);
            return;
        }
        for (int i = start[v]; i < start[v + 1]; ++i) fn(inc[i]);
    }

    /// The user's faces vertex v lies in (for a vertex of the user's mesh: those around it).
    std::vector<int> OrigFaces(int v) const
    {
        if (v < vn0) return std::vector<int>(inc.begin() + origStart[v], inc.begin() + origStart[v + 1]);
        return addedOrigFaces[v - vn0];
    }

    /// The faces holding edge (a, b).
    std::vector<int> EdgeFaces(int a, int b) const
    {
        std::vector<int> out;
        for (int f : Faces(a))
            if (Has(f, b)) out.push_back(f);
        return out;
    }
    bool Has(int f, int v) const { return face[f].v[0] == v || face[f].v[1] == v || face[f].v[2] == v; }
    int Corner(int f, int v) const
    {
        for (int k = 0; k < 3; ++k)
            if (face[f].v[k] == v) return k;
        return -1;
    }

    int AddVertex(const vcg::Point3d &p, std::vector<int> origFaces, int copy = -1)
    {
        pos.push_back(p);
        std::sort(origFaces.begin(), origFaces.end());
        origFaces.erase(std::unique(origFaces.begin(), origFaces.end()), origFaces.end());
        addedOrigFaces.push_back(origFaces);
        copyOf.push_back(copy);
        changed[int(pos.size()) - 1];
        return int(pos.size()) - 1;
    }

    /// Splits edge (a, b) at a + t (b - a), in both faces holding it; returns the new vertex.
    int SplitEdge(int a, int b, double t)
    {
        std::vector<int> fs = EdgeFaces(a, b);
        if (fs.empty() || fs.size() > 2)
            throw SnakeError("Cut: the curve crosses an edge of the mesh that is not manifold (" +
                             std::to_string(fs.size()) + " faces on it); the mesh was not changed.");
        std::vector<int> orig;
        for (int f : fs) orig.push_back(face[f].parent);
        const int x = AddVertex(pos[a] * (1 - t) + pos[b] * t, orig);
        for (int f : fs) {
            // f = (p, q, r) with the edge as p -> q: f becomes (p, x, r), a new face (x, q, r)
            int k = 0;
            while (!((face[f].v[k] == a && face[f].v[(k + 1) % 3] == b) ||
                     (face[f].v[k] == b && face[f].v[(k + 1) % 3] == a)))
                ++k;
            const int q = face[f].v[(k + 1) % 3], r = face[f].v[(k + 2) % 3];
            Face g;
            g.v[0] = x;
            g.v[1] = q;
            g.v[2] = r;
            g.parent = face[f].parent;
            face[f].v[(k + 1) % 3] = x;
            addFace(g);
            detach(q, f);
            attach(x, f);
        }
        return x;
    }

    /// Splits face f at an inner point p (face::TriSplit by index); returns the new vertex.
    int SplitFace(int f, const vcg::Point3d &p)
    {
        const int x = AddVertex(p, {face[f].parent});
        const int v0 = face[f].v[0], v1 = face[f].v[1], v2 = face[f].v[2];
        face[f].v[2] = x;
        Face g1, g2;
        g1.v[0] = v1; g1.v[1] = v2; g1.v[2] = x; g1.parent = face[f].parent;
        g2.v[0] = v2; g2.v[1] = v0; g2.v[2] = x; g2.parent = face[f].parent;
        detach(v2, f);
        attach(x, f);
        addFace(g1);
        addFace(g2);
        return x;
    }

    /// Replaces vertex `from` by `to` in face f.
    void Rewire(int f, int from, int to)
    {
        rewired.push_back(f);
        face[f].v[Corner(f, from)] = to;
        detach(from, f);
        attach(to, f);
    }

    /// The sub-faces of the user's face `parent` (itself while it is not split).
    std::vector<int> Children(int parent) const
    {
        auto it = children.find(parent);
        if (it == children.end()) return {parent};
        std::vector<int> out{parent};
        out.insert(out.end(), it->second.begin(), it->second.end());
        return out;
    }

    /// The faces Rewire changed (in order, repeats possible).
    const std::vector<int> &Rewired() const { return rewired; }

    /// The user's faces that were split, with their added sub-faces.
    const std::unordered_map<int, std::vector<int>> &SplitParents() const { return children; }

    double Area(int f) const
    {
        const Face &F = face[f];
        return ((pos[F.v[1]] - pos[F.v[0]]) ^ (pos[F.v[2]] - pos[F.v[0]])).Norm() / 2;
    }
    vcg::Point3d Normal(int f) const
    {
        const Face &F = face[f];
        return (pos[F.v[1]] - pos[F.v[0]]) ^ (pos[F.v[2]] - pos[F.v[0]]);
    }

private:
    std::vector<int> inc, start, origStart;
    std::unordered_map<int, std::vector<int>> changed;
    std::unordered_map<int, std::vector<int>> children;
    std::vector<int> rewired;
    mutable std::vector<int> scratch;

    std::vector<int> &own(int v)
    {
        auto it = changed.find(v);
        if (it != changed.end()) return it->second;
        std::vector<int> &l = changed[v];
        l.assign(inc.begin() + start[v], inc.begin() + start[v + 1]);
        return l;
    }
    void attach(int v, int f) { own(v).push_back(f); }
    void detach(int v, int f)
    {
        std::vector<int> &l = own(v);
        l.erase(std::remove(l.begin(), l.end(), f), l.end());
    }
    int addFace(const Face &g)
    {
        face.push_back(g);
        const int gi = int(face.size()) - 1;
        for (int k = 0; k < 3; ++k) attach(g.v[k], gi);
        children[g.parent].push_back(gi);
        return gi;
    }
};

} // namespace tri
} // namespace vcg

#endif
