#ifndef VCG_EXT_LOOP_TOPOLOGY_H
#define VCG_EXT_LOOP_TOPOLOGY_H

// Whether a loop of mesh edges can be a part's boundary (issue 33, session 34): a cut that takes
// a part off the surface is a simple cycle (no vertex twice) that separates it, the faces on
// its two sides joined by no path that does not cross it. On a surface of higher genus a simple
// cycle need not separate: the benchmark's octopus (genus 1) has a handle beside a tentacle's
// base, and the cheapest loop in the band round that tentacle ran through it (capture 1.0,
// coverage 0.70, every stage of the Run's end). The test floods the faces on the two sides of
// one of the loop's edges, one face of each in turn, across the edges off the loop: a separating
// loop is known when the smaller side ends, a non-separating one when the floods meet, so the
// cost follows the part (or the way round the handle), not the mesh. Walks the VF adjacency,
// which must be current.
//
// On a large part that is still a flood of the part at every loop a Run's end tests (session 34:
// 924/874 ms against 426/369 ms without it on bunny00 subdivided to 1.2M faces). A LoopTopology
// made once per mesh (PartBoundaryEnd::Measured, on a surface with a handle) answers by homology
// instead, in the loop's length: a cycle separates exactly when it meets every closed path of
// faces evenly (mod 2), and those paths are sums of the fans round the vertices (which a simple
// cycle meets evenly) and of a few generators, one per edge left out of a tree-cotree
// decomposition (Eppstein 2003: a spanning tree of the faces, then of the vertices across the
// other edges, every border vertex one root): 2 g + b - 1 of them on a component of genus g
// with b boundary loops. Where that argument does not hold (a non-manifold edge or vertex, a
// loop through a border vertex or with two consecutive vertices not joined by an edge) and
// for the closed path across a loop that does not separate, the flood answers.

#include <algorithm>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include <vcg/complex/complex.h>

namespace vcg {
namespace tri {

template <class MeshType>
class LoopTopology
{
public:
    typedef typename MeshType::FaceType FaceType;
    typedef typename MeshType::VertexType VertexType;

    /// True when vertex loop l (closed, consecutive vertices joined by edges) is a simple cycle
    /// that separates the surface. False for a loop with a vertex twice, two consecutive
    /// vertices not joined by an edge, or one whose two sides are joined (a handle).
    /// across (when given and the loop is simple but separates nothing): the edges, as vertex
    /// pairs, that a path of faces from one side of the loop to the other and back across its
    /// first edge crosses (each once; mod 2). A loop that crosses them an even number of times
    /// meets that closed path evenly, as a separating loop does (ValleyLoop::FindAt's second search).
    static bool SimpleSeparating(const MeshType &m, const std::vector<int> &l, std::vector<std::pair<int, int>> *across = nullptr)
    {
        return Flood(m, l, across);
    }

    /// The generators of mesh m's closed paths of faces (tree-cotree; reads the FF adjacency,
    /// which must be current). None on a mesh with a non-manifold edge or vertex (Separating
    /// then floods).
    explicit LoopTopology(const MeshType &m) : mesh(&m), nf(int(m.face.size())), nv(int(m.vert.size()))
    {
        if (!tri::HasFFAdjacency(m) || m.face.empty() || !Manifold(m)) return;
        // the spanning tree of the faces (depth first: a subtree is an interval of tin)
        parentEdge.assign(nf, -1), tin.assign(nf, -1), tout.assign(nf, -1), arc.assign(3 * nf, 0);
        int clock = 0;
        std::vector<std::pair<const FaceType *, int>> stack;
        for (int i = 0; i < nf; ++i) {
            if (m.face[i].IsD() || tin[i] >= 0) continue;
            tin[i] = clock++, stack.assign(1, {&m.face[i], 0});
            while (!stack.empty()) {
                auto &top = stack.back();
                const FaceType *f = top.first;
                if (top.second == 3) {
                    tout[fi(f)] = clock, stack.pop_back();
                    continue;
                }
                const int k = top.second++;
                const FaceType *g = f->cFFp(k);
                if (g == f || tin[fi(g)] >= 0) continue;
                const int j = f->cFFi(k);
                tin[fi(g)] = clock++, parentEdge[fi(g)] = j, arc[3 * fi(g) + j] = arc[3 * fi(f) + k] = 1;
                stack.push_back({g, 0});
            }
        }
        // the spanning tree of the vertices across the edges no face tree arc crosses, the
        // border vertices one root (nv); an edge it cannot take is a generator's
        std::vector<int> root(nv + 1);
        for (int v = 0; v <= nv; ++v) root[v] = v;
        auto find = [&](int v) {
            while (root[v] != v) v = root[v] = root[root[v]];
            return v;
        };
        for (int v = 0; v < nv; ++v)
            if (border[v]) root[v] = nv;
        for (int i = 0; i < nf; ++i) {
            const FaceType &f = m.face[i];
            if (f.IsD()) continue;
            for (int k = 0; k < 3; ++k) {
                const FaceType *g = f.cFFp(k);
                if (g == &f || fi(g) < i || arc[3 * i + k]) continue; // a border, seen, a tree arc
                const int a = find(vi(f.cV(k))), b = find(vi(f.cV((k + 1) % 3)));
                if (a != b) {
                    root[a] = b;
                    continue;
                }
                const int id = int(generator.size());
                generator.push_back({i, fi(g)});
                left[3 * i + k] = id, left[3 * fi(g) + f.cFFi(k)] = id;
            }
        }
        valid = true;
    }

    /// SimpleSeparating's answer, by homology when it can (see above); `across` (when given and
    /// the loop does not separate) by the flood. m: the mesh this was made on, unchanged since.
    bool Separating(const MeshType &m, const std::vector<int> &l, std::vector<std::pair<int, int>> *across = nullptr) const
    {
        if (!Simple(l)) return false;
        if (!valid || &m != mesh || int(m.face.size()) != nf || int(m.vert.size()) != nv) return Flood(m, l, across);
        std::vector<char> odd(generator.size(), 0); // the loop's crossings of each generator, mod 2
        const int n = int(l.size());
        for (int i = 0; i < n; ++i) {
            const int a = l[i], b = l[(i + 1) % n];
            if (border[a]) return Flood(m, l, across);
            const FaceType *f = nullptr;
            int k = -1, faces = 0;
            ForFaces(m, a, [&](const FaceType *g) {
                for (int j = 0; j < 3; ++j)
                    if (vi(g->cV(j)) == b) ++faces;
                for (int j = 0; j < 3 && !f; ++j)
                    if (vi(g->cV(j)) == a && vi(g->cV((j + 1) % 3)) == b) f = g, k = j;
                for (int j = 0; j < 3 && !f; ++j)
                    if (vi(g->cV(j)) == b && vi(g->cV((j + 1) % 3)) == a) f = g, k = j;
            });
            if (faces != 2) return Flood(m, l, across); // no edge, or two edges a b
            const auto it = left.find(3 * fi(f) + k);
            if (it != left.end()) {
                odd[it->second] ^= 1;
                continue;
            }
            if (!arc[3 * fi(f) + k]) continue; // an edge of the vertices' tree: in no generator
            // a face tree arc: in the generators whose path joins a face inside the subtree
            // below it to one outside
            const FaceType *child = parentEdge[fi(f)] == k ? f : f->cFFp(k);
            for (size_t g = 0; g < generator.size(); ++g)
                odd[g] ^= char(Below(generator[g].first, child) != Below(generator[g].second, child));
        }
        for (char o : odd)
            if (o) return across ? Flood(m, l, across) : false;
        return true;
    }

    /// The number of generators (2 g + b - 1 on a connected surface of genus g with b > 0
    /// boundary loops, 2 g on a closed one); -1 when the flood answers for every loop.
    int Generators() const { return valid ? int(generator.size()) : -1; }

    /// True when the loop has at least 3 vertices and none twice (the part of SimpleSeparating
    /// that needs no flood).
    static bool Simple(const std::vector<int> &l)
    {
        if (l.size() < 3) return false;
        std::unordered_set<int> seen;
        for (int v : l)
            if (!seen.insert(v).second) return false;
        return true;
    }

    /// True when every connected component of the surface has genus 0 (a sphere, or a disc with
    /// holes): there every simple cycle of edges separates the surface (the Jordan curve
    /// theorem), so SimpleSeparating's flood can be skipped. By the Euler characteristic,
    /// V - E + F = sum over the components of 2 - 2 g - b (b: boundary loops, the components of
    /// the border edges). Reads the FF adjacency, which must be current (SnakeSurface's). False
    /// when in doubt: no FF adjacency, a non-manifold edge (a pinched vertex reads as a handle).
    static bool Planar(const MeshType &m)
    {
        if (!tri::HasFFAdjacency(m) || m.face.empty()) return false;
        const int nv = int(m.vert.size()), nf = int(m.face.size());
        std::vector<char> used(nv, 0), reached(nf, 0);
        std::vector<int> root(nv, -1); // union-find over the border edges' vertices
        auto find = [&](int v) {
            while (root[v] != v) v = root[v] = root[root[v]];
            return v;
        };
        long long F = 0, border = 0, V = 0, components = 0, loops = 0;
        std::vector<const FaceType *> stack;
        for (int i = 0; i < nf; ++i) {
            const FaceType &f0 = m.face[i];
            if (f0.IsD() || reached[i]) continue;
            ++components;
            reached[i] = 1;
            stack.assign(1, &f0);
            while (!stack.empty()) {
                const FaceType *f = stack.back();
                stack.pop_back();
                ++F;
                for (int k = 0; k < 3; ++k) {
                    const int a = int(tri::Index(m, f->cV(k))), b = int(tri::Index(m, f->cV((k + 1) % 3)));
                    used[a] = 1;
                    const FaceType *g = f->cFFp(k);
                    if (g == f) { // a border edge: its vertices in one boundary loop
                        ++border;
                        for (int v : {a, b})
                            if (root[v] < 0) root[v] = v, ++loops;
                        const int ra = find(a), rb = find(b);
                        if (ra != rb) root[ra] = rb, --loops;
                        continue;
                    }
                    if (g == nullptr || g->IsD() || g->cFFp(f->cFFi(k)) != f) return false;
                    const int j = int(g - &m.face[0]);
                    if (!reached[j]) reached[j] = 1, stack.push_back(g);
                }
            }
        }
        for (char u : used) V += u;
        const long long E = (3 * F + border) / 2;
        return 2 * components - loops - (V - E + F) == 0;
    }

private:
    const MeshType *mesh;
    int nf, nv;
    bool valid = false;
    std::vector<char> border;            // per vertex
    std::vector<int> parentEdge, tin, tout; // the face tree: per face, the edge to its parent; its subtree
    std::vector<char> arc;               // per face edge: a face tree arc
    std::vector<std::pair<int, int>> generator;  // the two faces of each left edge
    std::unordered_map<int, int> left;   // face edge -> its generator

    int fi(const FaceType *f) const { return int(tri::Index(*mesh, f)); }
    int vi(const VertexType *v) const { return int(tri::Index(*mesh, v)); }
    bool Below(int f, const FaceType *top) const { return tin[fi(top)] <= tin[f] && tin[f] < tout[fi(top)]; }

    /// Every edge between two faces that see each other across it (or a border), every
    /// vertex's faces one fan; fills `border`.
    bool Manifold(const MeshType &m)
    {
        border.assign(nv, 0);
        std::vector<int> degree(nv, 0);
        std::vector<std::pair<const FaceType *, int>> one(nv, {nullptr, 0});
        for (const FaceType &f : m.face) {
            if (f.IsD()) continue;
            for (int k = 0; k < 3; ++k) {
                const FaceType *g = f.cFFp(k);
                if (g == nullptr || g->IsD()) return false;
                if (g == &f) border[vi(f.cV(k))] = border[vi(f.cV((k + 1) % 3))] = 1;
                else if (g->cFFp(f.cFFi(k)) != &f) return false;
                const int v = vi(f.cV(k));
                ++degree[v], one[v] = {&f, k};
            }
        }
        for (int v = 0; v < nv; ++v) {
            if (!degree[v]) continue;
            // round v across its edges, both ways from one face until a border or back
            int count = 1;
            bool closed = false;
            for (int way = 0; way < 2 && !closed; ++way) {
                const FaceType *f = one[v].first;
                int e = way ? (one[v].second + 2) % 3 : one[v].second; // an edge of f at v
                for (;;) {
                    const FaceType *g = f->cFFp(e);
                    if (g == f) break;
                    if (g == one[v].first) {
                        closed = true;
                        break;
                    }
                    const int j = f->cFFi(e);
                    e = vi(g->cV(j)) == v ? (j + 2) % 3 : (j + 1) % 3; // g's other edge at v
                    f = g;
                    if (++count > degree[v]) return false;
                }
            }
            if (count != degree[v]) return false;
        }
        return true;
    }

    static bool Flood(const MeshType &m, const std::vector<int> &l, std::vector<std::pair<int, int>> *across)
    {
        const int n = int(l.size());
        if (!Simple(l)) return false;
        std::unordered_set<long long> edges;
        const long long nv = (long long)m.vert.size();
        auto key = [nv](int a, int b) { return (long long)std::min(a, b) * nv + std::max(a, b); };
        for (int i = 0; i < n; ++i) edges.insert(key(l[i], l[(i + 1) % n]));
        // the faces on the two sides of the edge l[0] l[1]
        std::vector<const FaceType *> start;
        ForFaces(m, l[0], [&](const FaceType *f) {
            for (int k = 0; k < 3; ++k)
                if (int(tri::Index(m, f->cV(k))) == l[1]) start.push_back(f);
        });
        if (start.size() != 2) return false; // no edge, a border or a non-manifold edge
        std::unordered_map<const FaceType *, int> side;
        std::unordered_map<const FaceType *, std::pair<const FaceType *, long long>> from; // the flood's tree
        std::vector<const FaceType *> queue[2];
        size_t head[2] = {0, 0};
        for (int s = 0; s < 2; ++s) side[start[s]] = s, queue[s].push_back(start[s]);
        for (;;) {
            for (int s = 0; s < 2; ++s) {
                if (head[s] == queue[s].size()) return true; // one side ended: it is cut off
                const FaceType *f = queue[s][head[s]++];
                for (int k = 0; k < 3; ++k) {
                    const int a = int(tri::Index(m, f->cV(k))), b = int(tri::Index(m, f->cV((k + 1) % 3)));
                    if (edges.count(key(a, b))) continue;
                    const FaceType *met = nullptr;
                    ForFaces(m, a, [&](const FaceType *g) {
                        if (g == f || met) return;
                        bool hasB = false;
                        for (int j = 0; j < 3; ++j) hasB = hasB || int(tri::Index(m, g->cV(j))) == b;
                        if (!hasB) return;
                        const auto it = side.find(g);
                        if (it == side.end()) side[g] = s, from[g] = {f, key(a, b)}, queue[s].push_back(g);
                        else if (it->second != s) met = g;
                    });
                    if (!met) continue;
                    // the two sides are one: the closed path f .. start[s], start[1-s] .. met, f
                    if (across) {
                        std::unordered_set<long long> odd;
                        auto toggle = [&](long long e) {
                            if (!odd.erase(e)) odd.insert(e);
                        };
                        toggle(key(a, b)), toggle(key(l[0], l[1]));
                        for (const FaceType *x : {f, met})
                            for (auto it = from.find(x); it != from.end(); it = from.find(it->second.first)) toggle(it->second.second);
                        across->clear();
                        for (long long e : odd) across->push_back({int(e / nv), int(e % nv)});
                    }
                    return false;
                }
            }
        }
    }

    template <class Fn>
    static void ForFaces(const MeshType &m, int v, Fn fn)
    {
        const VertexType &x = m.vert[v];
        for (const FaceType *f = x.cVFp(), *next = nullptr; f; f = next) {
            const int z = (f->cV(0) == &x) ? 0 : (f->cV(1) == &x ? 1 : 2);
            next = f->cVFp(z);
            if (!f->IsD()) fn(f);
        }
    }
};

} // namespace tri
} // namespace vcg

#endif
