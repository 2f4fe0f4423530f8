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
                if (index(m, f->cV(k)) == l[1]) start.push_back(f);
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
                    const int a = index(m, f->cV(k)), b = index(m, f->cV((k + 1) % 3));
                    if (edges.count(key(a, b))) continue;
                    const FaceType *met = nullptr;
                    ForFaces(m, a, [&](const FaceType *g) {
                        if (g == f || met) return;
                        bool hasB = false;
                        for (int j = 0; j < 3; ++j) hasB = hasB || index(m, g->cV(j)) == b;
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
                    const int a = index(m, f->cV(k)), b = index(m, f->cV((k + 1) % 3));
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
    static int index(const MeshType &m, const VertexType *v) { return int(v - &m.vert[0]); }
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
