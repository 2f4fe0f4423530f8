#ifndef VCG_EXT_LOOP_BEND_H
#define VCG_EXT_LOOP_BEND_H

// How the surface bends across an edge loop (issue 33, session 28): the minima rule (Hoffman and
// Richards) puts part boundaries where the surface is concave *across* the boundary; the
// part-boundary energy reads the concavity whatever its direction, so a ring up a limb with a
// wrinkle or a knuckle's crease is as deep as the limb's base. Across a ring up a straight limb
// the surface does not bend; across the limb's base it bends inwards. Used at the Run's end
// (PartBoundaryEnd::Param::crossBend, part_boundary_end.h).

#include <algorithm>
#include <functional>
#include <queue>
#include <unordered_map>
#include <vector>

#include <vcg_ext/snake/part_salience.h>
#include <vcg_ext/surface/angle_weighted_normals.h>

namespace vcg {
namespace tri {

template <class MeshType>
class LoopBend
{
public:
    typedef typename MeshType::FaceType FaceType;

    /// Floods the loop's sides until the body is known: the one side still growing once it is
    /// larger than every side that ended, or the largest when all ended (as part salience
    /// does: the cost follows the part). Returns it, -1 when the loop cuts nothing off. A
    /// vertex not reached (Side -2) lies on the body's side.
    static int Body(typename PartSalience<MeshType>::Sides &s)
    {
        for (;;) {
            if (s.OneSide()) return -1; // known before the flood ends
            if (s.growing == 1 && !s.ended.empty()) {
                double M = 0;
                for (int c : s.ended) M = std::max(M, s.area[c]);
                if (s.area[s.GrowingSide()] > M) return s.GrowingSide();
            }
            if (!s.Step()) break;
        }
        if (s.ended.size() < 2) return -1;
        int body = -1;
        for (int c : s.ended)
            if (body < 0 || s.area[c] > s.area[body]) body = c;
        return body;
    }

    /// The bend across the loop at distance d h (the minima rule's sign of the curvature
    /// across it): per loop vertex v, the centroids cP, cB of the vertices at edge distance
    /// (d - h/2, d + h/2] on the part's and the body's side whose nearest loop vertex is v,
    /// and ((cP + cB) / 2 - v) . n_v, n_v the angle-weighted outward normal (the energies',
    /// angle_weighted_normals.h), in h; the median over the loop's vertices that have both.
    /// Positive: concave across the loop (a valley), about 0 on a ring up a limb of even width,
    /// negative on a convex ridge.
    static double Bend(const MeshType &m, const std::vector<int> &vl, double h, double d, bool *ok = nullptr)
    {
        if (ok) *ok = false;
        if (vl.size() < 3) return 0;
        typename PartSalience<MeshType>::Sides s(m, vl);
        return Bend(m, vl, s, Body(s), h, d, ok);
    }

    /// Bend with vl's sides s already flooded until the body is known (body = Body(s)): a
    /// caller that reads the sides too floods them once.
    static double Bend(const MeshType &m, const std::vector<int> &vl, typename PartSalience<MeshType>::Sides &s, int body,
                       double h, double d, bool *ok = nullptr)
    {
        typedef PartSalience<MeshType> PS;
        if (ok) *ok = false;
        if (vl.size() < 3 || body < 0) return 0;
        std::unordered_map<int, double> dist;
        std::unordered_map<int, int> src;
        typedef std::pair<double, int> QE;
        std::priority_queue<QE, std::vector<QE>, std::greater<QE>> q;
        for (size_t i = 0; i < vl.size(); ++i) dist[vl[i]] = 0, src[vl[i]] = int(i), q.push({0, vl[i]});
        const double lo = (d - 0.5) * h, hi = (d + 0.5) * h;
        std::vector<vcg::Point3d> cp(vl.size(), vcg::Point3d(0, 0, 0)), cb(vl.size(), vcg::Point3d(0, 0, 0));
        std::vector<int> np(vl.size(), 0), nb(vl.size(), 0);
        while (!q.empty()) {
            const QE e = q.top();
            q.pop();
            if (e.first > dist[e.second]) continue;
            if (e.first > hi) break;
            if (e.first > lo) {
                const int c = s.Side(e.second), i = src[e.second];
                const vcg::Point3d p = vcg::Point3d::Construct(m.vert[e.second].cP());
                if (c == body || c == -2) cb[i] += p, ++nb[i];
                else if (c >= 0) cp[i] += p, ++np[i];
            }
            PS::ForFaces(m, e.second, [&](const FaceType *f, int z) {
                for (int k = 1; k < 3; ++k) {
                    const int b = int(f->cV((z + k) % 3) - &m.vert[0]);
                    if (s.OnLoop(b)) continue;
                    const double l = vcg::Distance(m.vert[e.second].cP(), m.vert[b].cP());
                    const auto it = dist.find(b);
                    if (it == dist.end() || e.first + l < it->second)
                        dist[b] = e.first + l, src[b] = src[e.second], q.push({e.first + l, b});
                }
            });
        }
        std::vector<double> bend;
        for (size_t i = 0; i < vl.size(); ++i) {
            if (!np[i] || !nb[i]) continue;
            const vcg::Point3d n = AngleWeightedNormals<MeshType>::At(m.vert[vl[i]]);
            if (!(n.Norm() > 0)) continue;
            const vcg::Point3d mid = (cp[i] / double(np[i]) + cb[i] / double(nb[i])) * 0.5;
            bend.push_back(((mid - vcg::Point3d::Construct(m.vert[vl[i]].cP())) * n) / h);
        }
        if (bend.empty()) return 0;
        std::nth_element(bend.begin(), bend.begin() + bend.size() / 2, bend.end());
        if (ok) *ok = true;
        return bend[bend.size() / 2];
    }
};

} // namespace tri
} // namespace vcg

#endif
