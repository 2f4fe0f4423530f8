#ifndef VCG_EXT_SNAKE_SEED_LIST_H
#define VCG_EXT_SNAKE_SEED_LIST_H

// The seeds a user places before a snake is built (Sec. 5.5): mesh vertices, each with the
// surface point it was clicked at. On a CAD tessellation every vertex lies on some crease, so a
// click inside a triangle must not jump to one: the curve then passes exactly through the click.
// A seed placed as a vertex (a selection, a list of indices) has no click point (face -1).
//
// Every input is validated: bad input throws vcg::tri::SnakeError with a message for the user and
// leaves the list unchanged. The list is a small value (copied into each undo snapshot).

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <vcg_ext/snake/error.h>
#include <vcg_ext/surface/surface_point.h>

namespace vcg {
namespace tri {

template <class MeshType>
class SnakeSeedList
{
public:
    explicit SnakeSeedList(const MeshType &m) : mesh(&m) {}

    /// The vertex of face `face` nearest to the surface point (face, bary): the seed a click
    /// on the surface places (Sec. 5.5).
    static int VertexFromPick(const MeshType &m, int face, const vcg::Point3d &bary)
    {
        if (face < 0 || face >= int(m.face.size()) || m.face[face].IsD())
            throw SnakeError("Geometric snake: the click is not on the mesh.");
        for (int k = 0; k < 3; ++k)
            if (!std::isfinite(bary[k]) || bary[k] < -0.01 || bary[k] > 1.01)
                throw SnakeError("Geometric snake: the picked point is outside the picked triangle.");
        SurfacePoint sp(face, bary);
        sp.Normalize();
        const auto &f = m.face[face];
        const vcg::Point3d p = sp.Pd(m);
        int best = -1;
        double bd = std::numeric_limits<double>::max();
        for (int k = 0; k < 3; ++k) {
            const double d = (vcg::Point3d::Construct(f.cV(k)->cP()) - p).SquaredNorm();
            if (std::isfinite(d) && d < bd) { bd = d; best = int(f.cV(k) - &m.vert[0]); }
        }
        if (best < 0) throw SnakeError("Geometric snake: the picked triangle has invalid coordinates.");
        return best;
    }

    /// Adds the seed of a click. Returns its vertex, or -1 if the click repeats the last seed.
    int AddPick(int face, const vcg::Point3d &bary)
    {
        const int v = VertexFromPick(*mesh, face, bary);
        SurfacePoint sp(face, bary);
        sp.Normalize();
        if (!verts.empty() && Position(size() - 1) == sp.Pd(*mesh)) return -1;
        verts.push_back(v);
        at.push_back(sp);
        return v;
    }

    /// Adds vertex v as a seed. Returns v, or -1 if it repeats the last seed.
    int AddVertex(int v)
    {
        checkVertex(v);
        if (!verts.empty() && verts.back() == v && at.back().face < 0) return -1;
        verts.push_back(v);
        at.push_back(SurfacePoint());
        return v;
    }

    /// A painted stroke (surface points in drawing order): seeds along it, at least
    /// `minSpacing` x `unit` apart (the shortest paths between them follow the stroke closely).
    /// Stroke points off the mesh are skipped. Returns the number of seeds added.
    int AddStroke(const std::vector<SurfacePoint> &stroke, double minSpacing, double unit)
    {
        if (!std::isfinite(minSpacing) || minSpacing < 0) throw SnakeError("Geometric snake: bad stroke spacing.");
        std::vector<int> sv;
        std::vector<SurfacePoint> sat; // the stroke's point where it reached each vertex's triangle
        for (const auto &p : stroke) {
            int v;
            try { v = VertexFromPick(*mesh, p.face, p.bary); }
            catch (const SnakeError &) { continue; }
            if (sv.empty() || sv.back() != v) {
                sv.push_back(v);
                sat.push_back(SurfacePoint(p.face, p.bary));
                sat.back().Normalize();
            }
        }
        if (sv.empty()) throw SnakeError("Geometric snake: the stroke does not touch the mesh.");
        int added = 0, last = verts.empty() ? -1 : verts.back();
        for (size_t i = 0; i < sv.size(); ++i) {
            const int v = sv[i];
            if (v == last) continue;
            if (last >= 0 && i + 1 < sv.size() && (P(v) - P(last)).Norm() < minSpacing * unit) continue;
            verts.push_back(v);
            at.push_back(sat[i]);
            last = v;
            ++added;
        }
        return added;
    }

    /// Replaces the seeds by the selected vertices, ordered into a chain (nearest neighbour
    /// from the selected vertex farthest from their centroid; quadratic, hence `maxSeeds`).
    int FromSelection(int maxSeeds)
    {
        std::vector<int> sel;
        for (size_t i = 0; i < mesh->vert.size(); ++i)
            if (!mesh->vert[i].IsD() && mesh->vert[i].IsS()) sel.push_back(int(i));
        if (sel.size() < 2) throw SnakeError("Geometric snake: select at least 2 vertices to use them as seeds.");
        if (int(sel.size()) > maxSeeds)
            throw SnakeError("Geometric snake: " + std::to_string(sel.size()) + " vertices are selected; use at most " +
                             std::to_string(maxSeeds) + " as seeds.");
        vcg::Point3d c(0, 0, 0);
        for (int v : sel) c += P(v);
        c /= double(sel.size());
        size_t start = 0;
        for (size_t i = 1; i < sel.size(); ++i)
            if ((P(sel[i]) - c).SquaredNorm() > (P(sel[start]) - c).SquaredNorm()) start = i;
        std::vector<int> order{sel[start]};
        std::vector<char> used(sel.size(), 0);
        used[start] = 1;
        for (size_t k = 1; k < sel.size(); ++k) {
            int bi = -1;
            double bd = std::numeric_limits<double>::max();
            for (size_t i = 0; i < sel.size(); ++i)
                if (!used[i]) {
                    const double d = (P(sel[i]) - P(order.back())).SquaredNorm();
                    if (d < bd) { bd = d; bi = int(i); }
                }
            used[bi] = 1;
            order.push_back(sel[bi]);
        }
        SetVertices(order);
        return size();
    }

    /// Replaces the seeds by vertices (e.g. picked with another tool).
    void SetVertices(const std::vector<int> &v)
    {
        for (int x : v) checkVertex(x);
        verts = v;
        at.assign(v.size(), SurfacePoint());
    }

    /// Replaces the seeds by surface points (e.g. a Pick Points file snapped with SeedPointSnap).
    void SetPoints(const std::vector<SurfacePoint> &pts)
    {
        std::vector<int> v;
        std::vector<SurfacePoint> a;
        for (const auto &p : pts) {
            checkSurfacePoint(p);
            v.push_back(VertexFromPick(*mesh, p.face, p.bary));
            a.push_back(p);
            a.back().Normalize();
        }
        verts = v;
        at = a;
    }

    /// Vertices with their click points (face -1: none), e.g. from a session file; a point list
    /// that does not match the vertices one to one is ignored (a hand-edited seed list).
    void Set(const std::vector<int> &v, const std::vector<SurfacePoint> &points)
    {
        for (int x : v) checkVertex(x);
        for (const auto &p : points)
            if (p.face >= 0) checkSurfacePoint(p);
        verts = v;
        at = points.size() == v.size() ? points : std::vector<SurfacePoint>(v.size());
    }

    void Remove(int i)
    {
        if (i < 0 || i >= size()) throw SnakeError("Geometric snake: no seed " + std::to_string(i) + ".");
        verts.erase(verts.begin() + i);
        at.erase(at.begin() + i);
    }
    bool RemoveLast()
    {
        if (verts.empty()) return false;
        verts.pop_back();
        at.pop_back();
        return true;
    }
    void Clear()
    {
        verts.clear();
        at.clear();
    }

    /// The seed nearest to p, within maxDist (-1 if none).
    int Nearest(const vcg::Point3d &p, double maxDist = std::numeric_limits<double>::max()) const
    {
        int best = -1;
        double bd = maxDist;
        for (int i = 0; i < size(); ++i) {
            const double d = (Position(i) - p).Norm();
            if (d <= bd) { bd = d; best = i; }
        }
        return best;
    }

    int size() const { return int(verts.size()); }
    bool empty() const { return verts.empty(); }
    const std::vector<int> &Vertices() const { return verts; }
    /// Seed i as clicked, or an invalid point (face -1) for a seed placed as a vertex.
    const SurfacePoint &Point(int i) const { return at.at(i); }
    /// Where seed i is: the click, or its vertex.
    vcg::Point3d Position(int i) const
    {
        const SurfacePoint &sp = at.at(i);
        return sp.face >= 0 ? sp.Pd(*mesh) : P(verts.at(i));
    }
    /// Every seed is at its vertex (placed as one, or clicked exactly on it): the curve is then
    /// the paper's vertex path.
    bool AtVertices() const
    {
        for (int i = 0; i < size(); ++i)
            if (at[i].face >= 0 && at[i].Pd(*mesh) != P(verts[i])) return false;
        return true;
    }
    /// The seeds as surface points (a vertex seed: the vertex, as a corner of one of its faces
    /// of `surf`, a SnakeSurface of the mesh).
    template <class SurfaceType>
    std::vector<SurfacePoint> Points(const SurfaceType &surf) const
    {
        std::vector<SurfacePoint> pts = at;
        for (int i = 0; i < size(); ++i)
            if (pts[i].face < 0) pts[i] = surf.VertexPoint(verts[i]);
        return pts;
    }
    size_t Bytes() const { return sizeof(*this) + verts.capacity() * sizeof(int) + at.capacity() * sizeof(SurfacePoint); }

    bool operator==(const SnakeSeedList &o) const
    {
        if (verts != o.verts || at.size() != o.at.size()) return false;
        for (size_t i = 0; i < at.size(); ++i)
            if (at[i].face != o.at[i].face || (at[i].face >= 0 && at[i].bary != o.at[i].bary)) return false;
        return true;
    }
    bool operator!=(const SnakeSeedList &o) const { return !(*this == o); }

private:
    const MeshType *mesh;
    std::vector<int> verts;
    std::vector<SurfacePoint> at; // per seed: the clicked surface point, or face -1

    vcg::Point3d P(int v) const { return vcg::Point3d::Construct(mesh->vert[v].cP()); }
    void checkVertex(int v) const
    {
        if (v < 0 || v >= int(mesh->vert.size()) || mesh->vert[v].IsD())
            throw SnakeError("Geometric snake: vertex " + std::to_string(v) + " is not on the mesh.");
        const vcg::Point3d p = P(v);
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
            throw SnakeError("Geometric snake: vertex " + std::to_string(v) + " has invalid coordinates.");
    }
    void checkSurfacePoint(const SurfacePoint &p) const
    {
        if (!p.OnMesh(*mesh)) throw SnakeError("Geometric snake: the point is not on the mesh.");
    }
};

} // namespace tri
} // namespace vcg

#endif
