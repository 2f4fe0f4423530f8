#ifndef GS_TESTS_PART_VARIANTS_H
#define GS_TESTS_PART_VARIANTS_H

// Tessellation variants of a benchmark mesh with its people's segmentations carried over (issue
// 33, session 29): the same parts and the same people's cuts on another triangulation of the
// same surface, so that a rule tuned to the 9 meshes' tessellations shows up as one that does not
// hold on theirs (bench/eval/gs_parts --variant). Applied by part_cases.h's LoadModel to the mesh
// as read, before its parts are derived: the cuts are then built from the labels exactly as for
// the original mesh (edges between differently labelled faces), h is the new mesh's mean edge
// length and the seeds are placed on the new mesh.
//
//   refine  every face split 1-to-4 at its edges' midpoints (h halves);
//   graded  the faces whose barycentre lies below the bounding box's centre in x split twice,
//           red-green (the faces next to them in 2 or 3, no T-junctions): edge lengths vary ~4x
//           across the mesh, with slivers at the transition;
//   noise   every vertex moved along its normal by uniform noise in +-0.2 h (fixed seed), the
//           connectivity kept; noiseA (e.g. noise0.1, noise0.3): in +-A h instead.
// A split face's children keep its label in every segmentation, and a split edge's midpoint lies
// on it: a person's cut is the same curve on the refined mesh (the same length).

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <common/ml_mesh_type.h>
#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>

namespace gs_parts {

/// Splits the marked faces 1-to-4 at their edges' midpoints and an unmarked face with 1 or 2 of
/// its edges split in 2 or 3 (red-green refinement: the mesh stays conforming). Each child keeps
/// its parent's label in every segmentation of `segs`. No adjacency is needed or kept.
inline void SplitFaces(CMeshO &m, const std::vector<char> &mark, std::vector<std::vector<int>> &segs)
{
    typedef CMeshO::CoordType Coord;
    const size_t nf = m.face.size();
    const int nv0 = int(m.vert.size());
    std::vector<std::array<int, 3>> F(nf);
    for (size_t f = 0; f < nf; ++f)
        for (int k = 0; k < 3; ++k) F[f][k] = int(vcg::tri::Index(m, m.face[f].V(k)));
    std::map<std::pair<int, int>, int> mid; // edge (low, high) -> its midpoint's index
    std::vector<Coord> pos;
    auto key = [](int a, int b) { return std::make_pair(std::min(a, b), std::max(a, b)); };
    for (size_t f = 0; f < nf; ++f) {
        if (!mark[f] || m.face[f].IsD()) continue;
        for (int k = 0; k < 3; ++k) {
            const auto e = key(F[f][k], F[f][(k + 1) % 3]);
            if (mid.count(e)) continue;
            mid[e] = nv0 + int(pos.size());
            pos.push_back((m.vert[e.first].cP() + m.vert[e.second].cP()) / 2);
        }
    }
    std::vector<std::array<int, 3>> G;
    std::vector<int> parent;
    for (size_t f = 0; f < nf; ++f) {
        if (m.face[f].IsD()) continue;
        const std::array<int, 3> &v = F[f];
        int e[3], n = 0;
        for (int k = 0; k < 3; ++k) {
            auto it = mid.find(key(v[k], v[(k + 1) % 3]));
            e[k] = it == mid.end() ? -1 : it->second; // e[k]: the midpoint of edge v[k] v[k+1]
            n += e[k] >= 0;
        }
        auto add = [&](int a, int b, int c) { G.push_back({a, b, c}), parent.push_back(int(f)); };
        if (n == 0) add(v[0], v[1], v[2]);
        else if (n == 3) {
            add(v[0], e[0], e[2]), add(e[0], v[1], e[1]), add(e[2], e[1], v[2]), add(e[0], e[1], e[2]);
        } else if (n == 1) {
            int r = 0;
            while (e[r] < 0) ++r;
            const int a = v[r], b = v[(r + 1) % 3], c = v[(r + 2) % 3];
            add(a, e[r], c), add(e[r], b, c);
        } else {
            int u = 0; // the edge not split; the two after it are
            while (e[u] >= 0) ++u;
            const int r = (u + 1) % 3;
            const int a = v[r], b = v[(r + 1) % 3], c = v[(r + 2) % 3], ab = e[r], bc = e[(r + 1) % 3];
            add(ab, b, bc), add(a, ab, bc), add(a, bc, c);
        }
    }
    auto vi = vcg::tri::Allocator<CMeshO>::AddVertices(m, pos.size());
    for (size_t i = 0; i < pos.size(); ++i, ++vi) vi->P() = pos[i];
    m.face.clear();
    m.fn = 0;
    vcg::tri::Allocator<CMeshO>::AddFaces(m, G.size());
    for (size_t g = 0; g < G.size(); ++g)
        for (int k = 0; k < 3; ++k) m.face[g].V(k) = &m.vert[G[g][k]];
    for (std::vector<int> &lab : segs) {
        std::vector<int> out(G.size());
        for (size_t g = 0; g < G.size(); ++g) out[g] = lab[parent[g]];
        lab.swap(out);
    }
}

inline double MeanEdgeLength(const CMeshO &m)
{
    double el = 0;
    size_t n = 0;
    for (const auto &f : m.face)
        if (!f.IsD())
            for (int k = 0; k < 3; ++k) el += vcg::Distance(f.cP(k), f.cP((k + 1) % 3)), ++n;
    return n ? el / n : 0;
}

/// Applies tessellation variant `name` (see the top of this file; "" or "none": the mesh as it
/// is) to mesh m and its segmentations. False for an unknown name.
inline bool ApplyVariant(CMeshO &m, std::vector<std::vector<int>> &segs, const std::string &name)
{
    if (name.empty() || name == "none") return true;
    if (name == "refine") {
        SplitFaces(m, std::vector<char>(m.face.size(), 1), segs);
        return true;
    }
    if (name == "graded") {
        vcg::tri::UpdateBounding<CMeshO>::Box(m);
        const double cx = m.bbox.Center()[0];
        for (int pass = 0; pass < 2; ++pass) {
            std::vector<char> mark(m.face.size(), 0);
            for (size_t f = 0; f < m.face.size(); ++f)
                mark[f] = !m.face[f].IsD() && vcg::Barycenter(m.face[f])[0] < cx;
            SplitFaces(m, mark, segs);
        }
        return true;
    }
    if (name.compare(0, 5, "noise") == 0) {
        // "noise" = +-0.2 h; "noiseA" (e.g. noise0.1, noise0.3): +-A h, the same generator (session 33)
        const double amp = name.size() > 5 ? std::atof(name.c_str() + 5) : 0.2;
        if (!(amp > 0)) return false;
        const double h = MeanEdgeLength(m);
        vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFace(m);
        std::mt19937 rng(29); // the raw generator (its output is fixed by the standard), not a distribution
        for (auto &v : m.vert) {
            const double u = 2.0 * (double(rng()) / 4294967296.0) - 1.0; // uniform in [-1, 1)
            if (!v.IsD()) v.P() += v.cN() * CMeshO::ScalarType(amp * h * u);
        }
        return true;
    }
    return false;
}

} // namespace gs_parts

#endif
