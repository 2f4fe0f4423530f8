#ifndef VCG_EXT_SURFACE_PROJECTION_H
#define VCG_EXT_SURFACE_PROJECTION_H

#include <algorithm>
#include <vector>
#include <limits>
#include <unordered_set>

#include <vcg/space/distance3.h>
#include <vcg/space/triangle3.h>
#include <vcg_ext/snake_surface.h>

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
        // a flood over a few dozen faces: a vector searched linearly is faster than a hash set
        // (this runs twice per sample in GeometricSnake's well test and once per update of the
        // naive method); a hash set takes over if the flood grows large
        std::vector<int> todo(1, startFace);
        std::unordered_set<int> seenLarge;
        auto firstVisit = [&](int f) {
            if (todo.size() < 64) return std::find(todo.begin(), todo.end(), f) == todo.end();
            if (seenLarge.empty()) seenLarge.insert(todo.begin(), todo.end());
            return seenLarge.insert(f).second;
        };
        double bestD = std::numeric_limits<double>::max();
        int bestF = startFace;
        vcg::Point3d bestP = q;
        for (size_t next = 0; next < todo.size(); ++next) {
            const int f = todo[next];
            const FaceType &ff = m.face[f];
            vcg::Triangle3<double> t(vcg::Point3d::Construct(ff.cV(0)->cP()), vcg::Point3d::Construct(ff.cV(1)->cP()),
                                     vcg::Point3d::Construct(ff.cV(2)->cP()));
            double d;
            vcg::Point3d c;
            vcg::TrianglePointDistance<double>(t, q, d, c);
            if (d < bestD) { bestD = d; bestF = f; bestP = c; }
            if (d > radius && f != startFace) continue;
            for (int k = 0; k < 3; ++k) {
                const FaceType *h = ff.cFFp(k);
                if (h == nullptr || h == &ff || h->IsD()) continue;
                const int hi = s.Idx(h);
                if (firstVisit(hi)) todo.push_back(hi);
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
