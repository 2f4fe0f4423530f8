#ifndef VCG_EXT_CUT_CUT_POINT_MAP_H
#define VCG_EXT_CUT_CUT_POINT_MAP_H

// Surface points (face + barycentric) of a mesh before a cut, as surface points of the mesh
// after it (select and cut-open modes change the mesh in place). A face the embedding did not
// split keeps its index and its corners (a cut open may give a corner a copy at the same
// place), so its points stay as they are; a split face keeps its index for one of its
// sub-faces and adds the others at the end: a point of it goes to the sub-face that holds it,
// with its coordinates there. The points of the user's snakes, seeds and pins survive the cut.

#include <algorithm>
#include <unordered_map>
#include <vector>

#include <vcg/space/point3.h>

#include <vcg_ext/cut/cut_work_mesh.h>
#include <vcg_ext/surface/surface_point.h>

namespace vcg {
namespace tri {

class CutPointMap
{
public:
    /// Built from the work mesh before it is committed: the user's faces were still as in
    /// `m` (the old corners are read from it).
    template <class MeshType>
    void Build(const MeshType &m, const CutWorkMesh &w)
    {
        split.clear();
        fn0 = w.fn0;
        for (const auto &it : w.SplitParents()) {
            Split &s = split[it.first];
            for (int k = 0; k < 3; ++k) s.corner[k] = vcg::Point3d::Construct(m.face[it.first].cV(k)->cP());
            for (int g : w.Children(it.first)) {
                Child c;
                c.face = g;
                for (int k = 0; k < 3; ++k) c.p[k] = w.pos[w.face[g].v[k]];
                s.children.push_back(c);
            }
        }
    }

    /// How many of the user's faces were split.
    size_t SplitFaces() const { return split.size(); }

    /// The point p of the mesh before the cut on the mesh after it (the same point in space,
    /// up to round-off). Points off the old mesh's faces are returned unchanged.
    SurfacePoint Map(const SurfacePoint &p) const
    {
        if (p.face < 0 || p.face >= fn0) return p;
        auto it = split.find(p.face);
        if (it == split.end()) return p;
        const Split &s = it->second;
        const vcg::Point3d x = s.corner[0] * p.bary[0] + s.corner[1] * p.bary[1] + s.corner[2] * p.bary[2];
        SurfacePoint best;
        double bestMin = -1e300;
        for (const Child &c : s.children) {
            const vcg::Point3d l = CutWorkMesh::Bary(c.p[0], c.p[1], c.p[2], x);
            const double mn = std::min(l[0], std::min(l[1], l[2]));
            if (mn > bestMin) {
                bestMin = mn;
                best = SurfacePoint(c.face, l);
            }
        }
        // inside one sub-face up to round-off: clamp the tiny negative coordinates
        for (int k = 0; k < 3; ++k) best.bary[k] = std::max(0.0, best.bary[k]);
        const double sum = best.bary[0] + best.bary[1] + best.bary[2];
        if (sum > 0) best.bary /= sum;
        return best;
    }

    /// Every point of v mapped.
    void MapAll(std::vector<SurfacePoint> &v) const
    {
        for (SurfacePoint &p : v) p = Map(p);
    }

private:
    struct Child
    {
        int face;
        vcg::Point3d p[3];
    };
    struct Split
    {
        vcg::Point3d corner[3];
        std::vector<Child> children;
    };
    std::unordered_map<int, Split> split;
    int fn0 = 0;
};

} // namespace tri
} // namespace vcg

#endif
