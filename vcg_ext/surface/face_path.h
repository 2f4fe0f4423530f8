#ifndef VCG_EXT_FACE_PATH_H
#define VCG_EXT_FACE_PATH_H

#include <algorithm>
#include <queue>
#include <unordered_map>
#include <vector>

#include <vcg_ext/surface/snake_surface.h>

namespace vcg {
namespace tri {

/// Projection of the 3D segment between two surface points onto the mesh, as a sequence of
/// edge-adjacent faces: A* over the face graph (FF adjacency) with centroid distances.
/// Used where no embedding has traced the segment yet: after a sample was dragged far (the
/// region enlargement of Sec. 5.2, Fig. 4) or inserted. Bounded, so it never walks the mesh.
template <class MeshType>
class FacePath
{
public:
    typedef typename MeshType::FaceType FaceType;

    /// Faces from `from` to `to` inclusive; {from, to} if none was found within `maxVisit`.
    static std::vector<int> Find(const SnakeSurface<MeshType> &s, int from, int to, int maxVisit = 20000)
    {
        if (from == to) return {from};
        const MeshType &m = s.Mesh();
        auto centre = [&](int f) {
            const FaceType &ff = m.face[f];
            return (vcg::Point3d::Construct(ff.cV(0)->cP()) + vcg::Point3d::Construct(ff.cV(1)->cP()) +
                    vcg::Point3d::Construct(ff.cV(2)->cP())) / 3.0;
        };
        const vcg::Point3d goal = centre(to);
        struct Node { double f; int face; bool operator<(const Node &o) const { return f > o.f; } };
        std::priority_queue<Node> open;
        std::unordered_map<int, std::pair<double, int>> best; // face -> (g, parent)
        best[from] = {0.0, -1};
        open.push({(centre(from) - goal).Norm(), from});
        int visited = 0;
        while (!open.empty() && visited < maxVisit) {
            Node n = open.top();
            open.pop();
            if (n.face == to) break;
            ++visited;
            double g = best[n.face].first;
            vcg::Point3d c = centre(n.face);
            const FaceType &ff = m.face[n.face];
            for (int k = 0; k < 3; ++k) {
                const FaceType *h = ff.cFFp(k);
                if (h == nullptr || h == &ff || h->IsD()) continue;
                int hi = s.Idx(h);
                vcg::Point3d ch = centre(hi);
                double ng = g + (ch - c).Norm();
                auto it = best.find(hi);
                if (it != best.end() && it->second.first <= ng) continue;
                best[hi] = {ng, n.face};
                open.push({ng + (ch - goal).Norm(), hi});
            }
        }
        if (!best.count(to)) return {from, to};
        std::vector<int> path;
        for (int f = to; f != -1; f = best[f].second) path.push_back(f);
        std::reverse(path.begin(), path.end());
        return path;
    }
};

} // namespace tri
} // namespace vcg

#endif
