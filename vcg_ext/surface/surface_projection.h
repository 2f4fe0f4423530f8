#ifndef VCG_EXT_SURFACE_PROJECTION_H
#define VCG_EXT_SURFACE_PROJECTION_H

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <vcg/space/distance3.h>
#include <vcg/space/triangle3.h>
#include <vcg_ext/surface/snake_surface.h>

namespace vcg {
namespace tri {

/// Closest point on the surface to a point in space, searched locally around a face that
/// is known to be near (the previous position of a snake sample). This is what the naive
/// method of Sec. 4.2 pays at every update; it is done efficiently (a bounded flood over the
/// faces within `radius`, exact point-triangle distance from vcglib) so that the comparison
/// with the embedding method is fair.
template <class MeshType>
class SurfaceProjection
{
public:
    typedef typename MeshType::FaceType FaceType;

    static SurfacePoint Closest(const SnakeSurface<MeshType> &s, int startFace, const vcg::Point3d &q, double radius,
                                int *visitedOut = nullptr)
    {
        const MeshType &m = s.Mesh();
        // The flood visits every face reached through faces within `radius` of q (and the start
        // face); the closest of them wins, the first one visited on a tie. Marks in the surface's
        // flood stamps instead of a set; the queue is the surface's too (no allocation).
        const int gen = s.NewFloodGeneration();
        std::vector<int> &todo = s.floodTodo;
        std::vector<int> &stamp = s.floodStamp;
        todo.clear();
        todo.push_back(startFace);
        stamp[startFace] = gen;
        // Most faces of the flood need no exact point-triangle distance: their bounding box
        // is farther from q than the best face so far (no win), and their farthest corner is
        // within `radius` (expand) or their box beyond it (stop). Those bounds decide only
        // with a margin far above rounding (relative to the coordinates), so the faces won and
        // expanded are the same as with the exact distance everywhere.
        const double slack = 1e-9 * (std::max({std::abs(q[0]), std::abs(q[1]), std::abs(q[2])}) + radius);
        const double rIn = std::max(0.0, radius - slack), rOut = radius + slack;
        const double rIn2 = rIn * rIn, rOut2 = rOut * rOut;
        // A point beyond an edge of a convex part is equally close to both faces of the edge:
        // its two distances differ in their last bits only, so "the closer face" would flip with
        // any rounding of the coordinates (the mesh scaled by 1e30 is rounded differently) and
        // the next update would start from the other face. A face wins only by more than that
        // rounding; on a tie the first one visited, which does not depend on the scale.
        const double tie = 1e-3 * slack;
        double bestD = std::numeric_limits<double>::max();
        int bestF = startFace;
        vcg::Point3d bestP = q;
        for (size_t next = 0; next < todo.size(); ++next) {
            const int f = todo[next];
            const FaceType &ff = m.face[f];
            const vcg::Point3d v0 = vcg::Point3d::Construct(ff.cV(0)->cP()), v1 = vcg::Point3d::Construct(ff.cV(1)->cP()),
                               v2 = vcg::Point3d::Construct(ff.cV(2)->cP());
            double box2 = 0; // squared distance from q to the face's bounding box: <= the distance to the face
            for (int a = 0; a < 3; ++a) {
                const double lo = std::min({v0[a], v1[a], v2[a]}), hi = std::max({v0[a], v1[a], v2[a]});
                const double g = q[a] < lo ? lo - q[a] : (q[a] > hi ? q[a] - hi : 0.0);
                box2 += g * g;
            }
            const double far2 = std::max({(v0 - q).SquaredNorm(), (v1 - q).SquaredNorm(), (v2 - q).SquaredNorm()});
            const double bound = bestD + slack; // the start face sets bestD: nothing to beat before it
            const bool mayWin = bestD > 0 && !(box2 > bound * bound);
            bool expand = true, exact = mayWin;
            if (f != startFace && !(far2 < rIn2)) {
                if (box2 > rOut2) expand = false;
                else exact = true; // near the radius: the exact distance decides
            }
            if (exact) {
                vcg::Triangle3<double> t(v0, v1, v2);
                double d;
                vcg::Point3d c;
                vcg::TrianglePointDistance<double>(t, q, d, c);
                if (d < bestD - tie) { bestD = d; bestF = f; bestP = c; }
                if (f != startFace && !(far2 < rIn2) && !(box2 > rOut2)) expand = !(d > radius);
            }
            if (!expand) continue;
            for (int k = 0; k < 3; ++k) {
                const FaceType *h = ff.cFFp(k);
                if (h == nullptr || h == &ff || h->IsD()) continue;
                const int hi = s.Idx(h);
                if (stamp[hi] != gen) {
                    stamp[hi] = gen;
                    todo.push_back(hi);
                }
            }
        }
        if (visitedOut) *visitedOut = int(todo.size());
        const FaceType &ff = m.face[bestF];
        vcg::Triangle3<double> t(vcg::Point3d::Construct(ff.cV(0)->cP()), vcg::Point3d::Construct(ff.cV(1)->cP()),
                                 vcg::Point3d::Construct(ff.cV(2)->cP()));
        vcg::Point3d b;
        if (!vcg::InterpolationParameters(t, bestP, b)) b = vcg::Point3d(1.0 / 3, 1.0 / 3, 1.0 / 3);
        SurfacePoint sp(bestF, b);
        sp.Normalize();
        return sp;
    }
};

} // namespace tri
} // namespace vcg

#endif
