#ifndef VCG_EXT_SEED_PATH_H
#define VCG_EXT_SEED_PATH_H

// Snake initialization, Lee & Lee 2002 Section 5.5: the user picks a sequence of vertices near
// a feature and the initial (open or closed) curve joins consecutive picks with shortest paths
// along the mesh edges. The cost is a type (paths/seed_path_cost.h): plain length, or length weighted
// by the feature energy, an "intelligent scissors" path that already hugs the feature.

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <queue>
#include <string>
#include <utility>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/update/topology.h>

#include <vcg_ext/paths/seed_path_cost.h>
#include <vcg_ext/snake/error.h>
#include <vcg_ext/surface/mesh_validation.h>
#include <vcg_ext/surface/straight_walk.h>
#include <vcg_ext/surface/surface_point.h>

namespace vcg {
namespace tri {

template <class MeshType>
class SeedPath
{
public:
    typedef typename MeshType::FaceType FaceType;
    typedef typename MeshType::VertexType VertexType;
    typedef MeshValidation<MeshType> MV;

    struct Result
    {
        std::vector<int> vertices;      // path vertex indices in order; closed: first vertex not repeated
        std::vector<int> seedPositions; // index in `vertices` of each seed
        bool closed = false;
        double length = 0;              // Euclidean length of the path
    };

    /// Joins consecutive seeds (and, if closed, the last back to the first) with minimal paths
    /// along mesh edges, for the cost chosen by a user (LengthPathCost, or FeaturePathCost
    /// with featureEpsilon).
    static Result Compute(MeshType &m, const std::vector<int> &seedList, bool closed,
                          SeedPathCost cost = SeedPathCost::Length, double featureEpsilon = 0.05)
    {
        if (cost == SeedPathCost::Feature) {
            const std::vector<int> seeds = CheckedSeeds(m, seedList, closed); // seed errors first
            return ComputeWith(m, seeds, closed, FeaturePathCost<MeshType>(m, featureEpsilon));
        }
        return ComputeWith(m, seedList, closed, LengthPathCost<MeshType>(m));
    }

    /// Compute() for any cost type (see paths/seed_path_cost.h). A* with the straight-line distance
    /// times the cost's lower bound per length as heuristic, so a short path on a huge mesh
    /// only visits a small neighbourhood.
    template <class Cost>
    static Result ComputeWith(MeshType &m, const std::vector<int> &seedList, bool closed, const Cost &cost)
    {
        const std::vector<int> seeds = CheckedSeeds(m, seedList, closed);
        Search<Cost> search(m, cost);

        Result r;
        r.closed = closed;
        r.vertices.push_back(seeds[0]);
        r.seedPositions.push_back(0);
        const size_t nSeg = closed ? seeds.size() : seeds.size() - 1;
        for (size_t i = 0; i < nSeg; ++i) {
            const size_t j = (i + 1) % seeds.size();
            std::vector<int> seg;
            if (!search.Run(seeds[i], seeds[j], seg))
                throw SnakeError("Seeds " + std::to_string(i + 1) + " (vertex " + std::to_string(seeds[i]) + ") and " +
                                 std::to_string(j + 1) + " (vertex " + std::to_string(seeds[j]) +
                                 ") are on different connected components of the mesh: no path along its edges joins "
                                 "them.");
            r.vertices.insert(r.vertices.end(), seg.begin() + 1, seg.end());
            if (j != 0) r.seedPositions.push_back(int(r.vertices.size()) - 1);
        }
        for (size_t i = 0; i + 1 < r.vertices.size(); ++i) r.length += EdgeLen(m, r.vertices[i], r.vertices[i + 1]);
        if (closed) r.vertices.pop_back(); // the closing segment ended back on the first seed
        return r;
    }

    /// The seed list checked against the mesh (a closed list may repeat its first seed at the end).
    /// The most seeds one path (or snake) joins. Each pair of consecutive seeds is a shortest-path
    /// search, and 10,000 Pick Points scattered over a scan ran for minutes: a bound on the work,
    /// said up front, far above the tens of seeds a user places by hand.
    static size_t MaxSeeds() { return 1000; }
    static void CheckSeedCount(size_t n, const char *what)
    {
        if (n > MaxSeeds())
            throw SnakeError(std::to_string(n) + " " + what + " are given: one path or snake joins at most " +
                             std::to_string(MaxSeeds()) + " (each consecutive pair is a shortest-path search). "
                             "Keep every k-th seed, or split the curve into several snakes.");
    }

    static std::vector<int> CheckedSeeds(const MeshType &m, const std::vector<int> &seedList, bool closed)
    {
        CheckSeedCount(seedList.size(), "seed vertices");
        MV::RequireSurface(m);
        // A closed list may end on its first seed ("0, 80, 98, 0"): the loop closes there anyway.
        std::vector<int> seeds(seedList);
        if (closed && seeds.size() > 1 && seeds.front() == seeds.back()) seeds.pop_back();
        const int nv = int(m.vert.size());
        const size_t minSeeds = closed ? 3 : 2;
        if (seeds.size() < minSeeds)
            throw SnakeError(std::string(closed ? "A closed" : "An open") + " snake needs at least " +
                             std::to_string(minSeeds) + " distinct seed vertices (got " + std::to_string(seeds.size()) + ").");
        // Which vertices are used by a live face (seeds on isolated vertices cannot be joined).
        std::vector<char> referenced(nv, 0);
        for (const FaceType &f : m.face)
            if (!f.IsD())
                for (int k = 0; k < 3; ++k) referenced[MV::VIndex(m, f.cV(k))] = 1;
        for (size_t i = 0; i < seeds.size(); ++i) {
            const int s = seeds[i];
            const std::string who = "Seed " + std::to_string(i + 1) + " (vertex " + std::to_string(s) + ")";
            if (s < 0 || s >= nv)
                throw SnakeError(who + " is not a vertex of the mesh (valid indices are 0.." + std::to_string(nv - 1) +
                                 ").");
            if (m.vert[s].IsD()) throw SnakeError(who + " is a deleted vertex.");
            if (!referenced[s]) throw SnakeError(who + " is an isolated vertex that belongs to no face.");
        }
        for (size_t i = 0; i + 1 < seeds.size(); ++i)
            if (seeds[i] == seeds[i + 1])
                throw SnakeError("Seeds " + std::to_string(i + 1) + " and " + std::to_string(i + 2) +
                                 " are the same vertex (" + std::to_string(seeds[i]) + "); remove the repetition.");
        return seeds;
    }

    /// A path between seeds that are surface points (face + barycentric), not vertices: each
    /// seed is joined straight to the vertices of its own face, and from there along mesh
    /// edges as in Compute(); two seeds in one face are joined straight. The path starts and
    /// ends exactly at the seeds. Consecutive points of `points` always share a face.
    struct PointResult
    {
        std::vector<SurfacePoint> points; // seeds and the path vertices between them; closed: first not repeated
        std::vector<int> seedPositions;   // index in `points` of each seed
        std::vector<int> vertices;        // the mesh vertices the path runs through, in order
        bool closed = false;
        double length = 0;
    };

    /// What ComputeFromPoints builds over the whole mesh before it searches: the face across
    /// each edge (the straight walk's), one corner of each vertex, and the vertex adjacency of
    /// the search. O(mesh), with a sort of every edge: about 0.3 s of a Build on 1.2M faces
    /// (issue 37), so a caller that builds many paths on one mesh (the edit tool) keeps one
    /// while the mesh keeps its elements (Matches), and may build it on another thread.
    class MeshIndex
    {
    public:
        /// `adjacency`: with the search's vertex adjacency (else the search uses VF as without an index).
        explicit MeshIndex(const MeshType &m, bool adjacency = true)
            : walker(m), corner(m.vert.size(), std::make_pair(-1, -1)), mesh_(&m), nv_(m.vert.size()), nf_(m.face.size())
        {
            for (size_t f = 0; f < m.face.size(); ++f)
                if (!m.face[f].IsD())
                    for (int k = 0; k < 3; ++k) corner[MV::VIndex(m, m.face[f].cV(k))] = std::make_pair(int(f), k);
            if (adjacency) VertexAdjacency(m, start, adj);
        }
        /// The vertex graph from the faces: v's neighbours are adj[start[v] .. start[v + 1]),
        /// each face adding its other two corners (so an inner edge appears twice).
        static void VertexAdjacency(const MeshType &m, std::vector<int> &start, std::vector<int> &adj)
        {
            const int nv = int(m.vert.size());
            start.assign(nv + 1, 0);
            for (const FaceType &f : m.face)
                if (!f.IsD())
                    for (int k = 0; k < 3; ++k) start[MV::VIndex(m, f.cV(k)) + 1] += 2;
            for (int v = 0; v < nv; ++v) start[v + 1] += start[v];
            adj.resize(start[nv]);
            std::vector<int> fill(start.begin(), start.end() - 1);
            for (const FaceType &f : m.face)
                if (!f.IsD())
                    for (int k = 0; k < 3; ++k) {
                        const int v = MV::VIndex(m, f.cV(k));
                        adj[fill[v]++] = MV::VIndex(m, f.cV((k + 1) % 3));
                        adj[fill[v]++] = MV::VIndex(m, f.cV((k + 2) % 3));
                    }
        }
        /// Still the index of m: the same mesh with as many vertices and faces.
        bool Matches(const MeshType &m) const { return &m == mesh_ && m.vert.size() == nv_ && m.face.size() == nf_; }
        bool HasAdjacency() const { return !start.empty(); }

        SurfaceStraightWalk<MeshType> walker;
        std::vector<std::pair<int, int>> corner; // (face, corner) of each vertex, (-1, -1) if in none
        std::vector<int> start, adj;             // vertex v's neighbours: adj[start[v] .. start[v + 1])

    private:
        const MeshType *mesh_;
        size_t nv_, nf_;
    };

    /// `index`: a MeshIndex kept by the caller (built here if null or of another mesh).
    static PointResult ComputeFromPoints(MeshType &m, const std::vector<SurfacePoint> &seeds, bool closed,
                                         SeedPathCost cost = SeedPathCost::Length, double featureEpsilon = 0.05,
                                         const MeshIndex *index = nullptr)
    {
        if (cost == SeedPathCost::Feature) {
            CheckSeedPoints(m, seeds, closed); // seed errors first
            return ComputeFromPointsWith(m, seeds, closed, FeaturePathCost<MeshType>(m, featureEpsilon), index);
        }
        return ComputeFromPointsWith(m, seeds, closed, LengthPathCost<MeshType>(m), index);
    }

    /// ComputeFromPoints() for any cost type. Where the cost says the straight line is
    /// cheapest, the straight line on the surface is walked across faces first (on a flat CAD
    /// face, the seeds' own polyline).
    template <class Cost>
    static PointResult ComputeFromPointsWith(MeshType &m, const std::vector<SurfacePoint> &seeds, bool closed,
                                             const Cost &cost, const MeshIndex *index = nullptr)
    {
        CheckSeedPoints(m, seeds, closed);
        std::unique_ptr<MeshIndex> own;
        if (!index || !index->Matches(m)) {
            own.reset(new MeshIndex(m, false));
            index = own.get();
        }
        // One incident face per vertex, to express path vertices as surface points.
        const std::vector<std::pair<int, int>> &corner = index->corner;
        Search<Cost> search(m, cost, index->HasAdjacency() ? index : nullptr);
        const SurfaceStraightWalk<MeshType> &walker = index->walker;
        PointResult r;
        r.closed = closed;
        r.points.push_back(Clean(seeds[0]));
        r.seedPositions.push_back(0);
        const size_t nSeg = closed ? seeds.size() : seeds.size() - 1;
        for (size_t i = 0; i < nSeg; ++i) {
            const size_t j = (i + 1) % seeds.size();
            const SurfacePoint a = Clean(seeds[i]), b = Clean(seeds[j]);
            std::vector<std::pair<int, double>> src, dst;
            for (int k = 0; k < 3; ++k) {
                const int va = MV::VIndex(m, m.face[a.face].cV(k)), vb = MV::VIndex(m, m.face[b.face].cV(k));
                src.emplace_back(va, cost(a, va));
                dst.emplace_back(vb, cost(b, vb));
            }
            std::vector<SurfacePoint> walk;
            if (Cost::StraightIsCheapest && walker.Walk(a, b, walk)) {
                for (size_t w = 1; w < walk.size(); ++w) r.points.push_back(walk[w]);
                if (j != 0 || !closed) r.seedPositions.push_back(int(r.points.size()) - 1);
                else r.points.pop_back(); // closed: the walk came back onto the first seed
                continue;
            }
            std::vector<int> seg;
            double viaEdges = search.RunPoints(src, dst, b.Pd(m), seg);
            const double direct = a.face == b.face ? cost(a, b) : std::numeric_limits<double>::infinity();
            if (direct <= viaEdges) seg.clear();
            if (!std::isfinite(direct) && !std::isfinite(viaEdges)) // (both infinite: no path at all)
                throw SnakeError("Seed points " + std::to_string(i + 1) + " and " + std::to_string(j + 1) +
                                 " are on different connected components of the mesh: no path along its edges "
                                 "joins them.");
            // A seed lying on a vertex is not repeated as that vertex.
            auto same = [&](const SurfacePoint &x, const SurfacePoint &y) { return x.Pd(m) == y.Pd(m); };
            for (int v : seg) {
                if (r.vertices.empty() || r.vertices.back() != v) r.vertices.push_back(v);
                const SurfacePoint pv = SurfacePoint::AtCorner(corner[v].first, corner[v].second);
                if (!same(pv, r.points.back())) r.points.push_back(pv);
            }
            if (j != 0 || !closed) {
                if (int(r.points.size()) - 1 > r.seedPositions.back() && same(r.points.back(), b)) r.points.back() = b;
                else r.points.push_back(b);
                r.seedPositions.push_back(int(r.points.size()) - 1);
            } else if (int(r.points.size()) - 1 > r.seedPositions.back() && same(r.points.back(), b)) {
                r.points.pop_back(); // closed: the path came back onto the first seed
            }
        }
        for (size_t i = 0; i + 1 < r.points.size(); ++i) r.length += (r.points[i + 1].Pd(m) - r.points[i].Pd(m)).Norm();
        if (closed) r.length += (r.points.front().Pd(m) - r.points.back().Pd(m)).Norm();
        return r;
    }

    /// Throws unless there are enough seed points, each on a usable face.
    static void CheckSeedPoints(const MeshType &m, const std::vector<SurfacePoint> &seeds, bool closed)
    {
        CheckSeedCount(seeds.size(), "seed points");
        MV::RequireSurface(m);
        const size_t minSeeds = closed ? 3 : 2;
        if (seeds.size() < minSeeds)
            throw SnakeError(std::string(closed ? "A closed" : "An open") + " snake needs at least " +
                             std::to_string(minSeeds) + " seed points (got " + std::to_string(seeds.size()) + ").");
        for (size_t i = 0; i < seeds.size(); ++i) {
            const SurfacePoint &s = seeds[i];
            if (!s.IsValid() || s.face >= int(m.face.size()) || m.face[s.face].IsD() || MV::IsDegenerate(m.face[s.face]))
                throw SnakeError("Seed point " + std::to_string(i + 1) + " is not on a usable face of the mesh.");
        }
    }

private:
    static SurfacePoint Clean(SurfacePoint p)
    {
        p.Normalize();
        return p;
    }

    static double EdgeLen(const MeshType &m, int a, int b)
    {
        return vcg::Distance(vcg::Point3d::Construct(m.vert[a].cP()), vcg::Point3d::Construct(m.vert[b].cP()));
    }

    /// A* over the vertex graph for a cost type. Neighbours come from a MeshIndex's table, or
    /// vcglib's VF adjacency when the mesh has it (refreshed here, so a stale VF cannot
    /// mislead), else from a compact table built from faces.
    template <class Cost>
    class Search
    {
    public:
        Search(MeshType &m, const Cost &cost, const MeshIndex *index = nullptr)
            : m_(m), cost_(cost), hScale_(cost.LowerBoundPerLength())
        {
            const int nv = int(m.vert.size());
            g_.assign(nv, std::numeric_limits<double>::infinity());
            parent_.assign(nv, -1);
            done_.assign(nv, 0);
            if (index) {
                startP_ = &index->start;
                adjP_ = &index->adj;
                return;
            }
            useVF_ = tri::HasPerVertexVFAdjacency(m) && tri::HasPerFaceVFAdjacency(m);
            if (useVF_)
                UpdateTopology<MeshType>::VertexFace(m);
            else
                MeshIndex::VertexAdjacency(m, start_, adj_);
        }

        /// Multi-source, multi-target A*: sources (vertex, initial cost), targets (vertex, cost
        /// from it to the goal point `goal`). Returns the total cost (infinity if unreachable)
        /// and the vertices of the best path in `path`.
        double RunPoints(const std::vector<std::pair<int, double>> &src, const std::vector<std::pair<int, double>> &dst,
                         const vcg::Point3d &goal, std::vector<int> &path)
        {
            reset();
            typedef std::pair<double, int> Entry;
            std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
            for (const auto &s : src)
                if (s.second < g_[s.first]) {
                    if (g_[s.first] == std::numeric_limits<double>::infinity()) touched_.push_back(s.first);
                    g_[s.first] = s.second;
                    parent_[s.first] = -1;
                    open.emplace(s.second + hScale_ * vcg::Distance(P(s.first), goal), s.first);
                }
            const int goalNode = -2;
            double bestTotal = std::numeric_limits<double>::infinity();
            int bestLast = -1;
            while (!open.empty()) {
                const Entry e = open.top();
                open.pop();
                if (e.second == goalNode) break; // the goal was reached at the lowest cost
                const int u = e.second;
                if (done_[u]) continue;
                done_[u] = 1;
                for (const auto &t : dst)
                    if (t.first == u && g_[u] + t.second < bestTotal) {
                        bestTotal = g_[u] + t.second;
                        bestLast = u;
                        open.emplace(bestTotal, goalNode);
                    }
                relax(u, goal, open);
            }
            path.clear();
            if (bestLast < 0) return std::numeric_limits<double>::infinity();
            for (int v = bestLast; v != -1; v = parent_[v]) path.push_back(v);
            std::reverse(path.begin(), path.end());
            return bestTotal;
        }

        /// Fills path (source..target) and returns true, or false if target is unreachable.
        bool Run(int source, int target, std::vector<int> &path)
        {
            reset();
            const vcg::Point3d pt = P(target);
            typedef std::pair<double, int> Entry;
            std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
            g_[source] = 0;
            touched_.push_back(source);
            open.emplace(H(source, pt), source);
            bool found = false;
            while (!open.empty()) {
                const int u = open.top().second;
                open.pop();
                if (done_[u]) continue;
                done_[u] = 1;
                if (u == target) {
                    found = true;
                    break;
                }
                relax(u, pt, open);
            }
            path.clear();
            if (!found) return false;
            for (int v = target; v != -1; v = parent_[v]) path.push_back(v);
            std::reverse(path.begin(), path.end());
            return true;
        }

    private:
        void reset()
        {
            for (int v : touched_) {
                g_[v] = std::numeric_limits<double>::infinity();
                parent_[v] = -1;
                done_[v] = 0;
            }
            touched_.clear();
        }
        vcg::Point3d P(int v) const { return vcg::Point3d::Construct(m_.vert[v].cP()); }
        double H(int v, const vcg::Point3d &pt) const { return hScale_ * vcg::Distance(P(v), pt); }
        /// One A* expansion of u: relaxes its edges at the cost's price and queues the improved
        /// neighbours with the heuristic towards goal.
        template <class Queue>
        void relax(int u, const vcg::Point3d &goal, Queue &open)
        {
            ForNeighbours(u, [&](int w) {
                if (done_[w] || w == u) return;
                const double ng = g_[u] + cost_(u, w);
                if (ng < g_[w]) {
                    if (g_[w] == std::numeric_limits<double>::infinity()) touched_.push_back(w);
                    g_[w] = ng;
                    parent_[w] = u;
                    open.emplace(ng + H(w, goal), w);
                }
            });
        }

        template <class F>
        void ForNeighbours(int u, F &&fn)
        {
            if (useVF_) {
                for (vcg::face::VFIterator<FaceType> vfi(&m_.vert[u]); !vfi.End(); ++vfi) {
                    if (vfi.F()->IsD()) continue;
                    fn(MV::VIndex(m_, vfi.F()->cV1(vfi.I())));
                    fn(MV::VIndex(m_, vfi.F()->cV2(vfi.I())));
                }
            } else {
                const std::vector<int> &start = *startP_, &adj = *adjP_;
                for (int k = start[u]; k < start[u + 1]; ++k) fn(adj[k]);
            }
        }

        MeshType &m_;
        const Cost &cost_;
        double hScale_;
        bool useVF_ = false;
        std::vector<double> g_;
        std::vector<int> parent_, touched_, start_, adj_;
        const std::vector<int> *startP_ = &start_, *adjP_ = &adj_; // start_/adj_ or a MeshIndex's
        std::vector<char> done_;
    };
};

} // namespace tri
} // namespace vcg

#endif
