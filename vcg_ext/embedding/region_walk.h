#ifndef VCG_EXT_REGION_WALK_H
#define VCG_EXT_REGION_WALK_H

#include <array>
#include <vector>

#include <Eigen/Dense>

namespace vcg {
namespace tri {

/// Straight-line walks through the embedded triangles of a local region (Sec. 5.4): where
/// a moved sample lands, whether it left the region, and which edges the straight segment
/// between two samples crosses (the final curve of Sec. 4.1 is made of those crossings).
class RegionWalk
{
public:
    struct Crossing
    {
        int face;             // local face being left
        Eigen::Vector3d bary; // the crossing point in it (one coordinate is 0)
    };
    struct Result
    {
        int face = -1;        // local face where the walk ended
        Eigen::Vector3d bary; // end point in it
        bool exited = false;  // stopped on the region border (or at a virtual face)
        std::vector<Crossing> crossings;
    };

    static Eigen::Vector3d Bary(const Eigen::Vector2d &a, const Eigen::Vector2d &b, const Eigen::Vector2d &c,
                                const Eigen::Vector2d &p)
    {
        double d = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
        if (!(std::abs(d) > 1e-300)) return Eigen::Vector3d(1.0 / 3, 1.0 / 3, 1.0 / 3);
        double l1 = ((p - a).x() * (c - a).y() - (p - a).y() * (c - a).x()) / d;
        double l2 = ((b - a).x() * (p - a).y() - (b - a).y() * (p - a).x()) / d;
        return Eigen::Vector3d(1 - l1 - l2, l1, l2);
    }

    /// Walks from point p in local face `start` towards q. Only faces with index < realFaces
    /// are walkable; adj[t][i] is the face across edge i = (tri[t][i], tri[t][(i+1)%3]).
    static Result Walk(const std::vector<Eigen::Vector2d> &uv, const std::vector<std::array<int, 3>> &tri,
                       const std::vector<std::array<int, 3>> &adj, int start, const Eigen::Vector2d &p,
                       const Eigen::Vector2d &q, bool recordCrossings)
    {
        Result r;
        Walk(uv, tri, adj, start, p, q, recordCrossings, r);
        return r;
    }

    /// The same into `r`, whose crossing list keeps its memory from one walk to the next.
    static void Walk(const std::vector<Eigen::Vector2d> &uv, const std::vector<std::array<int, 3>> &tri,
                     const std::vector<std::array<int, 3>> &adj, int start, const Eigen::Vector2d &p,
                     const Eigen::Vector2d &q, bool recordCrossings, Result &r)
    {
        r.face = -1;
        r.exited = false;
        r.crossings.clear();
        int t = start, prev = -1;
        Eigen::Vector2d cur = p;
        const int maxSteps = int(adj.size()) + 16;
        for (int step = 0; step < maxSteps; ++step) {
            const auto &T = tri[t];
            Eigen::Vector3d lq = Bary(uv[T[0]], uv[T[1]], uv[T[2]], q);
            const double eps = 1e-12;
            if (lq.minCoeff() >= -eps) {
                r.face = t;
                r.bary = clampBary(lq);
                return;
            }
            Eigen::Vector3d lc = Bary(uv[T[0]], uv[T[1]], uv[T[2]], cur);
            // first barycentric coordinate to reach 0 along cur->q: the exit edge
            int best = -1;
            double bestT = 2;
            for (int j = 0; j < 3; ++j) {
                if (!(lq[j] < -eps)) continue;
                int e = (j + 1) % 3; // edge opposite vertex j
                if (adj[t][e] == prev && prev >= 0) continue;
                double den = lc[j] - lq[j];
                double tj = den > 0 ? std::max(0.0, lc[j]) / den : 0.0;
                if (tj < bestT) { bestT = tj; best = j; }
            }
            if (best < 0) { // numerically inside
                r.face = t;
                r.bary = clampBary(lq);
                return;
            }
            bestT = std::min(1.0, std::max(0.0, bestT));
            Eigen::Vector2d x = cur + bestT * (q - cur);
            Eigen::Vector3d lx = clampBary(lc + bestT * (lq - lc));
            lx[best] = 0;
            lx /= lx.sum();
            int e = (best + 1) % 3;
            int next = adj[t][e];
            if (next < 0) {
                r.face = t;
                r.bary = lx;
                r.exited = true;
                return;
            }
            if (recordCrossings) r.crossings.push_back({t, lx});
            prev = t;
            t = next;
            cur = x;
        }
        // did not terminate (degenerate geometry): stay where we are
        r.face = t;
        r.bary = clampBary(Bary(uv[tri[t][0]], uv[tri[t][1]], uv[tri[t][2]], cur));
        r.exited = true;
    }

    static Eigen::Vector3d clampBary(Eigen::Vector3d b)
    {
        for (int i = 0; i < 3; ++i)
            if (!(b[i] > 0)) b[i] = 0;
        double s = b.sum();
        if (s > 0) return b / s;
        return Eigen::Vector3d(1.0 / 3, 1.0 / 3, 1.0 / 3);
    }
};

} // namespace tri
} // namespace vcg

#endif
