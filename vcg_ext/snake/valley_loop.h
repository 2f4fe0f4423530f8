#ifndef VCG_EXT_VALLEY_LOOP_H
#define VCG_EXT_VALLEY_LOOP_H

// The cheapest loop of mesh edges in a band around a closed snake (issue 33): once a closed
// snake has settled in a part's valley, the loop of edges within `bandWidth` of it that goes
// round the same way (homotopic to it in the band) and minimizes sum(length * (E + lambda)),
// E the per-vertex feature energy averaged on the edge. People draw part boundaries as the
// shortest way round the part through its concave ground (the minima rule plus the cut's
// length, Lee et al., "Mesh Scissoring with Minima Rule and Part Salience", CAGD 2005); the
// snake, smooth and held by its tension and rigidity, settles where its own energy balances,
// and on a thin limb (a cut of 15-30 edges) it cuts corners of the valley by about an edge.
//
// The minimum over loops that wind round once is a shortest path in the band's double cover:
// a seam (where the arc length of the nearest snake point wraps round) switches
// sheets; for each vertex beside the seam, Dijkstra from it on sheet 0 to itself on sheet 1.
// The band is found by testing every vertex in the loop's bounding box against every loop
// segment: fine on the benchmark's meshes (7k-25k vertices), not measured on large ones.

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <vector>

#include <vcg/complex/complex.h>

#include <vcg_ext/energy/feature_energy.h>
#include <vcg_ext/snake/stop.h>

namespace vcg {
namespace tri {

template <class MeshType>
class ValleyLoop
{
public:
    typedef typename MeshType::FaceType FaceType;

    struct Param
    {
        /// Band half-width, in the snake's length units. On the benchmark's 220 loops
        /// (bench/eval/gs_parts) 1.5, 2, 2.5 and 3 units gave 47, 55, 49 and 44 %: wider bands
        /// reach other valleys, or cover a thin part's tip so that they are no longer a ring.
        double bandWidth = 2.0;
        /// Length cost added to the energy (in [0,1]): 1 weighs the loop's length as much as its
        /// depth. 0, 0.2, 1, 3 and 100 (the shortest loop in the band) gave 46, 54, 55, 50 and 44 %.
        double lambda = 1.0;
    };

    /// The rule every host follows (the program, the filters, the edit tool, bench/eval/gs_parts):
    /// a closed snake that converged on the part-boundary energy ends on the cheapest loop of
    /// edges round it. Returns true when the snake was replaced by that loop (it is kept as it
    /// is when the band holds no loop, or only one shorter than half the snake).
    template <class SnakeType>
    static bool FinishRun(SnakeType &s, FeatureEnergyType type, bool energyFromQuality, const Param &par = Param())
    {
        if (!s.Closed() || energyFromQuality || type != FeatureEnergyType::PartBoundary ||
            s.Stats().stop != SnakeStop::Converged)
            return false;
        const std::vector<vcg::Point3d> loop = s.PolylinePositions();
        const std::vector<float> &ef = s.GetSurface().Energy();
        const std::vector<double> e(ef.begin(), ef.end());
        const MeshType &m = s.GetSurface().Mesh();
        const std::vector<int> vl = Find(m, loop, e, s.LengthScale(), par);
        double len = 0, len0 = 0;
        for (size_t i = 0; i < vl.size(); ++i) len += vcg::Distance(m.vert[vl[i]].cP(), m.vert[vl[(i + 1) % vl.size()]].cP());
        for (size_t i = 0; i < loop.size(); ++i) len0 += vcg::Distance(loop[i], loop[(i + 1) % loop.size()]);
        if (vl.size() < 3 || !(len > 0.5 * len0)) return false;
        s.SetClosedVertexLoop(vl);
        return true;
    }

    /// Vertex indices of the cheapest edge loop round `loop` (closed polyline), or empty when
    /// the band holds none (e.g. it is not a ring). `energy` is indexed like m.vert; h is the
    /// length unit of the band.
    static std::vector<int> Find(const MeshType &m, const std::vector<vcg::Point3d> &loop,
                                 const std::vector<double> &energy, double h, const Param &par = Param())
    {
        if (loop.size() < 3 || !(h > 0) || energy.size() != m.vert.size()) return {};
        std::vector<double> cum(loop.size() + 1, 0);
        for (size_t i = 0; i < loop.size(); ++i) cum[i + 1] = cum[i] + vcg::Distance(loop[i], loop[(i + 1) % loop.size()]);
        const double L = cum.back();
        // the band: vertices within bandWidth * h of the loop, numbered compactly, each with
        // the arc length (from loop[0]) of its nearest loop point
        const double w = par.bandWidth * h;
        vcg::Box3d bb;
        for (const auto &p : loop) bb.Add(p);
        bb.Offset(w);
        std::vector<int> id(m.vert.size(), -1), vert;
        std::vector<double> arc;
        for (size_t v = 0; v < m.vert.size(); ++v) {
            if (m.vert[v].IsD()) continue;
            const vcg::Point3d p = vcg::Point3d::Construct(m.vert[v].cP());
            if (!bb.IsIn(p)) continue;
            double at = 0;
            if (DistToLoop(p, loop, cum, at) > w) continue;
            id[v] = int(vert.size());
            vert.push_back(int(v));
            arc.push_back(at);
        }
        const int nb = int(vert.size());
        std::vector<std::vector<int>> adj(nb);
        for (const FaceType &f : m.face) {
            if (f.IsD()) continue;
            for (int k = 0; k < 3; ++k) {
                const int a = id[f.cV(k) - &m.vert[0]], b = id[f.cV((k + 1) % 3) - &m.vert[0]];
                if (a < 0 || b < 0) continue;
                adj[a].push_back(b); // an interior edge twice (once per face): harmless
                adj[b].push_back(a);
            }
        }
        // the seam: where the nearest loop point's arc length wraps from L to 0
        auto cross = [&](int a, int b) {
            const double d = arc[b] - arc[a];
            return d < -0.5 * L ? 1 : (d > 0.5 * L ? -1 : 0);
        };
        std::vector<int> starts;
        for (int v = 0; v < nb; ++v)
            for (int u : adj[v])
                if (cross(v, u) == 1) {
                    starts.push_back(v);
                    break;
                }
        const double inf = std::numeric_limits<double>::infinity();
        double bestCost = inf;
        std::vector<int> best;
        std::vector<double> dist(2 * nb);
        std::vector<int> prev(2 * nb);
        typedef std::pair<double, int> QE;
        for (int s : starts) {
            std::fill(dist.begin(), dist.end(), inf);
            std::fill(prev.begin(), prev.end(), -1);
            std::priority_queue<QE, std::vector<QE>, std::greater<QE>> q;
            dist[s] = 0;
            q.push({0, s});
            const int target = nb + s;
            while (!q.empty()) {
                const QE e = q.top();
                q.pop();
                if (e.first > dist[e.second] || e.first >= bestCost) continue;
                if (e.second == target) break;
                const int a = e.second % nb, sheet = e.second / nb;
                for (int b : adj[a]) {
                    const int ns = sheet + cross(a, b);
                    if (ns < 0 || ns > 1) continue;
                    const double len = vcg::Distance(m.vert[vert[a]].cP(), m.vert[vert[b]].cP());
                    const double c = e.first + len * (0.5 * (energy[vert[a]] + energy[vert[b]]) + par.lambda);
                    const int to = ns * nb + b;
                    if (c < dist[to]) dist[to] = c, prev[to] = e.second, q.push({c, to});
                }
            }
            if (dist[target] < bestCost) {
                bestCost = dist[target];
                best.clear();
                for (int x = prev[target]; x >= 0 && x != s; x = prev[x]) best.push_back(vert[x % nb]);
                best.push_back(vert[s]);
                std::reverse(best.begin(), best.end());
            }
        }
        return best;
    }

private:
    static double DistToLoop(const vcg::Point3d &p, const std::vector<vcg::Point3d> &l, const std::vector<double> &cum, double &at)
    {
        double d = std::numeric_limits<double>::infinity();
        for (size_t i = 0; i < l.size(); ++i) {
            const vcg::Point3d &a = l[i], &b = l[(i + 1) % l.size()];
            const vcg::Point3d ab = b - a;
            const double L2 = ab.SquaredNorm();
            const double u = L2 > 0 ? std::max(0.0, std::min(1.0, ((p - a) * ab) / L2)) : 0;
            const double di = vcg::Distance(p, a + ab * u);
            if (di < d) d = di, at = cum[i] + u * std::sqrt(L2);
        }
        return d;
    }
};

} // namespace tri
} // namespace vcg

#endif
