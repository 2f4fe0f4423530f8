#ifndef VCG_EXT_SEED_PATH_H
#define VCG_EXT_SEED_PATH_H

// Snake initialization, Lee & Lee 2002 Section 5.5: the user picks a sequence of vertices near
// a feature and the initial (open or closed) curve joins consecutive picks with shortest paths
// along the mesh edges. Optionally the edge cost is weighted by the feature energy (vertex
// quality in [0,1], low = feature), an "intelligent scissors" path that already hugs the feature.

#include <algorithm>
#include <array>
#include <cctype>
#include <climits>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <string>
#include <utility>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/update/topology.h>
#include <vcg/space/triangle3.h>

#include "mesh_validation.h"
#include "snake_error.h"
#include "surface_point.h"

namespace vcg {
namespace tri {

enum class SeedPathCost { Length = 0, Feature = 1 };

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
    /// along mesh edges. Cost: Euclidean edge length, or with SeedPathCost::Feature
    /// length * (featureEpsilon + mean quality of the two endpoints). A* with the straight-line
    /// distance (times featureEpsilon for the feature cost, a lower bound since quality >= 0) as
    /// heuristic, so a short path on a huge mesh only visits a small neighbourhood.
    static Result Compute(MeshType &m, const std::vector<int> &seeds, bool closed,
                          SeedPathCost cost = SeedPathCost::Length, double featureEpsilon = 0.05)
    {
        MV::RequireSurface(m);
        const int nv = int(m.vert.size());
        const size_t minSeeds = closed ? 3 : 2;
        if (seeds.size() < minSeeds)
            throw SnakeError(std::string("A ") + (closed ? "closed" : "open") + " snake needs at least " +
                             std::to_string(minSeeds) + " seed vertices (got " + std::to_string(seeds.size()) + ").");
        if (cost == SeedPathCost::Feature) {
            if (!tri::HasPerVertexQuality(m))
                throw SnakeError("The feature-weighted seed path needs the feature energy in the vertex quality.");
            if (!(featureEpsilon > 0) || !std::isfinite(featureEpsilon))
                throw SnakeError("The feature path epsilon must be a positive number (got " +
                                 std::to_string(featureEpsilon) + ").");
        }

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
        if (closed && seeds.front() == seeds.back())
            throw SnakeError("The last seed repeats the first (vertex " + std::to_string(seeds.front()) +
                             "); a closed snake is closed automatically, do not repeat the first seed.");

        Search search(m, cost, featureEpsilon);

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

    static PointResult ComputeFromPoints(MeshType &m, const std::vector<SurfacePoint> &seeds, bool closed,
                                         SeedPathCost cost = SeedPathCost::Length, double featureEpsilon = 0.05)
    {
        MV::RequireSurface(m);
        const size_t minSeeds = closed ? 3 : 2;
        if (seeds.size() < minSeeds)
            throw SnakeError(std::string("A ") + (closed ? "closed" : "open") + " snake needs at least " +
                             std::to_string(minSeeds) + " seed points (got " + std::to_string(seeds.size()) + ").");
        if (cost == SeedPathCost::Feature && !tri::HasPerVertexQuality(m))
            throw SnakeError("The feature-weighted seed path needs the feature energy in the vertex quality.");
        if (!(featureEpsilon > 0) || !std::isfinite(featureEpsilon))
            throw SnakeError("The feature path epsilon must be a positive number.");
        for (size_t i = 0; i < seeds.size(); ++i) {
            const SurfacePoint &s = seeds[i];
            if (!s.IsValid() || s.face >= int(m.face.size()) || m.face[s.face].IsD() || MV::IsDegenerate(m.face[s.face]))
                throw SnakeError("Seed point " + std::to_string(i + 1) + " is not on a usable face of the mesh.");
        }
        // One incident face per vertex, to express path vertices as surface points.
        std::vector<std::pair<int, int>> corner(m.vert.size(), std::make_pair(-1, -1));
        for (size_t f = 0; f < m.face.size(); ++f)
            if (!m.face[f].IsD())
                for (int k = 0; k < 3; ++k) corner[MV::VIndex(m, m.face[f].cV(k))] = std::make_pair(int(f), k);

        Search search(m, cost, featureEpsilon);
        StraightWalk walker(m);
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
                src.emplace_back(va, search.PointCost(a, va));
                dst.emplace_back(vb, search.PointCost(b, vb));
            }
            // Better than the edge path where it exists: the straight line on the surface (on a
            // flat CAD face, the seeds' own polyline), walked face by face.
            std::vector<SurfacePoint> walk;
            if (cost == SeedPathCost::Length && walker.Walk(a, b, walk)) {
                for (size_t w = 1; w < walk.size(); ++w) r.points.push_back(walk[w]);
                if (j != 0 || !closed) r.seedPositions.push_back(int(r.points.size()) - 1);
                else r.points.pop_back(); // closed: the walk came back onto the first seed
                continue;
            }
            std::vector<int> seg;
            double viaEdges = search.RunPoints(src, dst, b.Pd(m), seg);
            const double direct = a.face == b.face ? search.PointCost(a, b) : std::numeric_limits<double>::infinity();
            if (direct <= viaEdges) seg.clear();
            else if (!std::isfinite(viaEdges))
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

    /// "12, 40,77" -> {12,40,77}. Separators: whitespace and/or one ',' or ';'. Empty text gives
    /// no seeds. Throws SnakeError on anything else (negative numbers, letters, ",,").
    static std::vector<int> ParseSeeds(const std::string &text)
    {
        std::vector<int> out;
        size_t i = 0;
        const size_t n = text.size();
        auto skipWs = [&]() {
            while (i < n && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
        };
        auto junk = [&](const std::string &why) {
            return SnakeError("Cannot read the seed list \"" + text + "\": " + why +
                              ". Write vertex indices separated by commas, e.g. \"12, 40, 77\".");
        };
        skipWs();
        while (i < n) {
            if (text[i] == '-') throw junk("vertex indices cannot be negative");
            if (text[i] == '+') ++i;
            if (i >= n || !std::isdigit(static_cast<unsigned char>(text[i])))
                throw junk(std::string("unexpected character '") + (i < n ? text[i] : ' ') + "' at position " +
                           std::to_string(i + 1));
            long long v = 0;
            while (i < n && std::isdigit(static_cast<unsigned char>(text[i]))) {
                v = v * 10 + (text[i] - '0');
                if (v > INT_MAX) throw junk("a vertex index is too large");
                ++i;
            }
            out.push_back(int(v));
            skipWs();
            if (i < n && (text[i] == ',' || text[i] == ';')) {
                ++i;
                skipWs();
                if (i < n && (text[i] == ',' || text[i] == ';')) throw junk("empty entry between separators");
            } else if (i < n && !std::isdigit(static_cast<unsigned char>(text[i])) && text[i] != '+' && text[i] != '-') {
                throw junk(std::string("unexpected character '") + text[i] + "' at position " + std::to_string(i + 1));
            }
        }
        return out;
    }

private:
    /// The straight line between two surface points, walked across faces: in each face the
    /// walk heads for the target (projected onto the face's plane) and leaves through an
    /// edge into the face across it. Exact on flat regions; gives up (false) at a border, a
    /// non-manifold edge, or when the walk grows longer than twice the straight distance.
    class StraightWalk
    {
    public:
        explicit StraightWalk(const MeshType &m) : m_(m)
        {
            struct E { int a, b, f, k; };
            std::vector<E> e;
            for (size_t f = 0; f < m.face.size(); ++f) {
                if (m.face[f].IsD()) continue;
                for (int k = 0; k < 3; ++k) {
                    int a = MV::VIndex(m, m.face[f].cV(k)), b = MV::VIndex(m, m.face[f].cV((k + 1) % 3));
                    if (a > b) std::swap(a, b);
                    e.push_back({a, b, int(f), k});
                }
            }
            std::sort(e.begin(), e.end(), [](const E &x, const E &y) { return x.a != y.a ? x.a < y.a : x.b < y.b; });
            across_.assign(m.face.size(), {-1, -1, -1});
            for (size_t i = 0; i < e.size();) {
                size_t j = i + 1;
                while (j < e.size() && e[j].a == e[i].a && e[j].b == e[i].b) ++j;
                if (j - i == 2) {
                    across_[e[i].f][e[i].k] = e[i + 1].f;
                    across_[e[i + 1].f][e[i + 1].k] = e[i].f;
                }
                i = j;
            }
        }

        bool Walk(const SurfacePoint &a, const SurfacePoint &b, std::vector<SurfacePoint> &out) const
        {
            out.assign(1, a);
            const vcg::Point3d B = b.Pd(m_);
            const double straight = (B - a.Pd(m_)).Norm();
            SurfacePoint cur = a;
            double len = 0;
            int prevFace = -1;
            for (int it = 0; it < 100000; ++it) {
                SurfacePoint bb;
                if (b.InFace(m_, cur.face, bb)) {
                    len += (B - cur.Pd(m_)).Norm();
                    out.push_back(b);
                    return len <= 2 * straight + 1e-12;
                }
                const auto &f = m_.face[cur.face];
                vcg::Point3d p[3];
                for (int k = 0; k < 3; ++k) p[k] = vcg::Point3d::Construct(f.cV(k)->cP());
                vcg::Point3d n = (p[1] - p[0]) ^ (p[2] - p[0]);
                if (!(n.Norm() > 0)) return false;
                n.Normalize();
                const vcg::Point3d x = cur.Pd(m_);
                vcg::Point3d d = B - x;
                d -= n * (d * n);
                if (!(d.Norm() > 1e-12 * std::max(1.0, straight))) return false;
                // The edge the ray x + t d leaves through: in barycentric terms, the first
                // coordinate that reaches 0 (among those that decrease).
                vcg::Point3d bd; // barycentric direction
                {
                    vcg::Triangle3<double> t(p[0], p[1], p[2]);
                    vcg::Point3d b1;
                    vcg::InterpolationParameters(t, x + d, b1); // false just means "outside": wanted here
                    if (!std::isfinite(b1[0]) || !std::isfinite(b1[1]) || !std::isfinite(b1[2])) return false;
                    bd = b1 - cur.bary;
                }
                int exitK = -1;
                double tBest = std::numeric_limits<double>::infinity();
                for (int k = 0; k < 3; ++k) {
                    if (!(bd[k] < -1e-15)) continue;
                    const double tk = std::max(0.0, cur.bary[k]) / -bd[k];
                    // leaving back into the face we came from is not progress
                    const int edge = (k + 1) % 3; // edge opposite corner k
                    if (tk <= 1e-12 && across_[cur.face][edge] == prevFace) continue;
                    if (tk < tBest) { tBest = tk; exitK = k; }
                }
                if (exitK < 0) return false;
                vcg::Point3d eb = cur.bary + bd * tBest;
                eb[exitK] = 0;
                SurfacePoint ex(cur.face, eb);
                ex.Normalize();
                const int edge = (exitK + 1) % 3;
                const int g = across_[cur.face][edge];
                if (g < 0) return false;
                len += (ex.Pd(m_) - x).Norm();
                if (len > 2 * straight + 1e-12) return false;
                if ((ex.Pd(m_) - out.back().Pd(m_)).Norm() > 0) out.push_back(ex);
                SurfacePoint next;
                if (!ex.InFace(m_, g, next)) return false;
                prevFace = cur.face;
                cur = next;
            }
            return false;
        }

    private:
        const MeshType &m_;
        std::vector<std::array<int, 3>> across_;
    };

    static SurfacePoint Clean(SurfacePoint p)
    {
        p.Normalize();
        return p;
    }

    static double EdgeLen(const MeshType &m, int a, int b)
    {
        return vcg::Distance(vcg::Point3d::Construct(m.vert[a].cP()), vcg::Point3d::Construct(m.vert[b].cP()));
    }

    /// A* over the vertex graph. Neighbours come from vcglib's VF adjacency when the mesh has it
    /// (refreshed here, so a stale VF cannot mislead), else from a compact table built from faces.
    class Search
    {
    public:
        Search(MeshType &m, SeedPathCost cost, double eps)
            : m_(m), feature_(cost == SeedPathCost::Feature), eps_(eps), hScale_(feature_ ? eps : 1.0)
        {
            const int nv = int(m.vert.size());
            g_.assign(nv, std::numeric_limits<double>::infinity());
            parent_.assign(nv, -1);
            done_.assign(nv, 0);
            if (feature_) {
                q_.resize(nv);
                for (int i = 0; i < nv; ++i) {
                    const double q = double(m.vert[i].cQ());
                    q_[i] = std::isfinite(q) ? std::max(0.0, q) : 1.0; // heuristic needs cost >= eps*len
                }
            }
            useVF_ = tri::HasPerVertexVFAdjacency(m) && tri::HasPerFaceVFAdjacency(m);
            if (useVF_) {
                UpdateTopology<MeshType>::VertexFace(m);
            } else {
                start_.assign(nv + 1, 0);
                for (const FaceType &f : m.face)
                    if (!f.IsD())
                        for (int k = 0; k < 3; ++k) start_[MV::VIndex(m, f.cV(k)) + 1] += 2;
                for (int v = 0; v < nv; ++v) start_[v + 1] += start_[v];
                adj_.resize(start_[nv]);
                std::vector<int> fill(start_.begin(), start_.end() - 1);
                for (const FaceType &f : m.face)
                    if (!f.IsD())
                        for (int k = 0; k < 3; ++k) {
                            const int v = MV::VIndex(m, f.cV(k));
                            adj_[fill[v]++] = MV::VIndex(m, f.cV((k + 1) % 3));
                            adj_[fill[v]++] = MV::VIndex(m, f.cV((k + 2) % 3));
                        }
            }
        }

        /// Cost of the straight piece from surface point p to vertex v (same cost as an edge).
        double PointCost(const SurfacePoint &p, int v) const
        {
            double c = vcg::Distance(p.Pd(m_), P(v));
            if (feature_) c *= eps_ + 0.5 * (PointQuality(p) + q_[v]);
            return c;
        }
        double PointCost(const SurfacePoint &a, const SurfacePoint &b) const
        {
            double c = vcg::Distance(a.Pd(m_), b.Pd(m_));
            if (feature_) c *= eps_ + 0.5 * (PointQuality(a) + PointQuality(b));
            return c;
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
                const vcg::Point3d pu = P(u);
                ForNeighbours(u, [&](int w) {
                    if (done_[w] || w == u) return;
                    double c = vcg::Distance(pu, P(w));
                    if (feature_) c *= eps_ + 0.5 * (q_[u] + q_[w]);
                    const double ng = g_[u] + c;
                    if (ng < g_[w]) {
                        if (g_[w] == std::numeric_limits<double>::infinity()) touched_.push_back(w);
                        g_[w] = ng;
                        parent_[w] = u;
                        open.emplace(ng + hScale_ * vcg::Distance(P(w), goal), w);
                    }
                });
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
                const vcg::Point3d pu = P(u);
                ForNeighbours(u, [&](int w) {
                    if (done_[w] || w == u) return;
                    double c = vcg::Distance(pu, P(w));
                    if (feature_) c *= eps_ + 0.5 * (q_[u] + q_[w]);
                    const double ng = g_[u] + c;
                    if (ng < g_[w]) {
                        if (g_[w] == std::numeric_limits<double>::infinity()) touched_.push_back(w);
                        g_[w] = ng;
                        parent_[w] = u;
                        open.emplace(ng + H(w, pt), w);
                    }
                });
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
        double PointQuality(const SurfacePoint &p) const
        {
            const FaceType &f = m_.face[p.face];
            double q = 0;
            for (int k = 0; k < 3; ++k) q += p.bary[k] * q_[MV::VIndex(m_, f.cV(k))];
            return q;
        }
        vcg::Point3d P(int v) const { return vcg::Point3d::Construct(m_.vert[v].cP()); }
        double H(int v, const vcg::Point3d &pt) const { return hScale_ * vcg::Distance(P(v), pt); }

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
                for (int k = start_[u]; k < start_[u + 1]; ++k) fn(adj_[k]);
            }
        }

        MeshType &m_;
        bool feature_;
        double eps_, hScale_;
        bool useVF_ = false;
        std::vector<double> g_, q_;
        std::vector<int> parent_, touched_, start_, adj_;
        std::vector<char> done_;
    };
};

} // namespace tri
} // namespace vcg

#endif
