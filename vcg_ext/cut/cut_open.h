#ifndef VCG_EXT_CUT_CUT_OPEN_H
#define VCG_EXT_CUT_CUT_OPEN_H

// Cutting open along embedded curves: at every curve vertex the faces around it fall into
// fans separated by the curve's edges (two for a vertex inside a separating curve, one at the
// tip of a slit); every fan but the first gets its own copy of the vertex, so the curve's edges
// become boundary edges (as vcglib's CutMeshAlongSelectedFaceEdges, on the work mesh).

#include <unordered_set>
#include <vector>

#include <vcg_ext/cut/curve_embedding.h>
#include <vcg_ext/cut/cut_work_mesh.h>

namespace vcg {
namespace tri {

class CutOpen
{
public:
    static void Open(CutWorkMesh &w, const std::vector<EmbeddedCurve> &curves,
                     const std::unordered_set<long long> &curveEdges)
    {
        std::unordered_set<int> done;
        for (const auto &c : curves)
            for (int v : c.chain) {
                if (!done.insert(v).second) continue;
                const std::vector<std::vector<int>> fans = Fans(w, v, curveEdges);
                for (size_t g = 1; g < fans.size(); ++g) {
                    const int copy = w.AddVertex(w.pos[v], w.OrigFaces(v), v);
                    for (int f : fans[g]) w.Rewire(f, v, copy);
                }
            }
    }

    /// The faces around v grouped by the edges at v they share, not crossing curve edges.
    static std::vector<std::vector<int>> Fans(const CutWorkMesh &w, int v, const std::unordered_set<long long> &curveEdges)
    {
        const std::vector<int> fs = w.Faces(v);
        std::vector<int> group(fs.size(), -1);
        std::vector<std::vector<int>> out;
        for (size_t s = 0; s < fs.size(); ++s) {
            if (group[s] >= 0) continue;
            out.emplace_back();
            std::vector<size_t> stack{s};
            group[s] = int(out.size()) - 1;
            while (!stack.empty()) {
                const size_t i = stack.back();
                stack.pop_back();
                out.back().push_back(fs[i]);
                for (size_t j = 0; j < fs.size(); ++j) {
                    if (group[j] >= 0) continue;
                    for (int k = 0; k < 3; ++k) {
                        const int x = w.face[fs[j]].v[k];
                        if (x == v || !w.Has(fs[i], x) || curveEdges.count(CutWorkMesh::EdgeKey(v, x))) continue;
                        group[j] = group[s];
                        stack.push_back(j);
                        break;
                    }
                }
            }
        }
        return out;
    }
};

} // namespace tri
} // namespace vcg

#endif
