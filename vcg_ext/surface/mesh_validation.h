#ifndef VCG_EXT_MESH_VALIDATION_H
#define VCG_EXT_MESH_VALIDATION_H

// Input checks shared by the feature energy, the seed path and the snake engine.
// Everything here works on any VCG triangle mesh: no optional component (FF/VF adjacency,
// marks) is needed, so it can run first on whatever the user loaded.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include <vcg/complex/complex.h>

#include <vcg_ext/snake/error.h>

namespace vcg {
namespace tri {

template <class MeshType>
class MeshValidation
{
public:
    typedef typename MeshType::FaceType FaceType;
    typedef typename MeshType::VertexType VertexType;

    struct Report
    {
        int vertices = 0;            // live (non-deleted) vertices
        int faces = 0;               // live faces
        int nonManifoldEdges = 0;    // edges shared by more than two faces
        int nonManifoldVertices = 0; // vertices whose faces form more than one fan (e.g. two cones touching)
        int degenerateFaces = 0;     // zero-area faces (repeated or collinear vertices)
        int borderEdges = 0;         // edges with exactly one face
        int components = 0;          // connected components of the surface (through edges)
        double meanEdgeLength = 0;
    };

    /// Relative threshold for zero-area faces: twice the area divided by the longest squared edge
    /// (i.e. height / longest edge) below this is treated as degenerate. Float coordinates carry
    /// ~1e-7 relative error, so anything thinner than this cannot be told from collinear.
    static double DegenerateRatio() { return 1e-6; }

    /// Meshes with more live faces than this run two passes that share no written data on two
    /// threads (a check or a count beside the pass that writes, the energy beside the
    /// adjacency build): there, a thread costs less than 1 % of a pass.
    static int ConcurrentFaces() { return concurrentFaces(); }
    /// For tests: ThreadSanitizer keeps only the last moments of each thread's accesses, so it
    /// sees a race only between passes as short as a small mesh's; its tests lower this.
    static void SetConcurrentFaces(int faces) { concurrentFaces() = faces; }

    /// Index of a vertex pointer in m.vert (VCG's tri::Index, usable on const meshes).
    static int VIndex(const MeshType &m, const VertexType *v) { return int(v - &*m.vert.begin()); }

    /// True for faces with repeated vertices or (nearly) zero area.
    template <class F>
    static bool IsDegenerate(const F &f)
    {
        if (f.cV(0) == f.cV(1) || f.cV(1) == f.cV(2) || f.cV(2) == f.cV(0)) return true;
        const vcg::Point3d p0 = vcg::Point3d::Construct(f.cV(0)->cP());
        const vcg::Point3d e1 = vcg::Point3d::Construct(f.cV(1)->cP()) - p0;
        const vcg::Point3d e2 = vcg::Point3d::Construct(f.cV(2)->cP()) - p0;
        const vcg::Point3d e3 = e2 - e1;
        const double maxE2 = std::max(e1.SquaredNorm(), std::max(e2.SquaredNorm(), e3.SquaredNorm()));
        const double area2 = (e1 ^ e2).Norm();
        return !(maxE2 > 0) || !(area2 > DegenerateRatio() * maxE2);
    }

    /// Throws SnakeError unless the mesh is a usable triangle surface: not empty, has faces
    /// (not a point cloud), finite coordinates, and no live face referencing a deleted or
    /// missing vertex.
    static void RequireSurface(const MeshType &m)
    {
        if (m.vn <= 0 || m.vert.empty()) throw SnakeError("The mesh is empty: it has no vertices.");
        if (m.fn <= 0 || m.face.empty())
            throw SnakeError("The mesh has no faces (it is a point cloud); geometric snakes need a triangle mesh.");
        for (size_t i = 0; i < m.vert.size(); ++i) {
            const VertexType &v = m.vert[i];
            if (v.IsD()) continue;
            for (int k = 0; k < 3; ++k)
                if (!std::isfinite(double(v.cP()[k])))
                    throw SnakeError("Vertex " + std::to_string(i) +
                                     " has a NaN or infinite coordinate; clean the mesh first.");
        }
        const VertexType *vb = &*m.vert.begin();
        const VertexType *ve = vb + m.vert.size();
        for (size_t i = 0; i < m.face.size(); ++i) {
            const FaceType &f = m.face[i];
            if (f.IsD()) continue;
            for (int k = 0; k < 3; ++k) {
                const VertexType *v = f.cV(k);
                if (v == nullptr || v < vb || v >= ve)
                    throw SnakeError("Face " + std::to_string(i) + " references a vertex that is not in the mesh.");
                if (v->IsD())
                    throw SnakeError("Face " + std::to_string(i) +
                                     " references a deleted vertex; run a mesh cleaning filter first.");
            }
        }
    }

    /// Throws SnakeError if a live face uses the same vertex twice. vcglib's adjacency
    /// (UpdateTopology::FaceFace / VertexFace), which the snakes need, asserts on such faces
    /// and would abort MeshLab; the message says how to clean them.
    static void RequireAdjacencySafe(const MeshType &m)
    {
        int bad = 0, first = -1;
        for (size_t i = 0; i < m.face.size(); ++i) {
            const FaceType &f = m.face[i];
            if (f.IsD()) continue;
            if (f.cV(0) == f.cV(1) || f.cV(1) == f.cV(2) || f.cV(2) == f.cV(0)) {
                if (first < 0) first = int(i);
                ++bad;
            }
        }
        if (bad > 0)
            throw SnakeError(std::to_string(bad) + " faces (the first is face " + std::to_string(first) +
                             ") use the same vertex twice. A snake walks from face to face across their edges, "
                             "which such a face breaks (the feature energy and the seed path only skip it, so they "
                             "accept the mesh). Remove them first: Filters > Cleaning and Repairing > "
                             "Remove Zero Area Faces (or Remove Duplicate Faces).");
    }

    /// Mean length of the edges of live faces (interior edges are counted once per face, which
    /// is the same weighting as counting them once). Throws SnakeError if it is not positive.
    static double MeanEdgeLength(const MeshType &m)
    {
        if (m.fn <= 0) throw SnakeError("The mesh has no faces, so it has no edge length.");
        double sum = 0;
        size_t n = 0;
        for (const FaceType &f : m.face) {
            if (f.IsD()) continue;
            for (int k = 0; k < 3; ++k) {
                sum += vcg::Distance(vcg::Point3d::Construct(f.cV(k)->cP()),
                                     vcg::Point3d::Construct(f.cV((k + 1) % 3)->cP()));
                ++n;
            }
        }
        const double mean = n ? sum / double(n) : 0.0;
        if (!(mean > 0) || !std::isfinite(mean))
            throw SnakeError("The mesh has no edge of positive finite length (all faces are collapsed to points "
                             "or coordinates are invalid).");
        return mean;
    }

    /// Counts topological problems. Works without FF adjacency: per vertex, the corners of its
    /// faces are grouped into fans through shared edges (linear in the number of faces, no
    /// global sort). Empty meshes and point clouds give a report of zeros; NaN coordinates throw.
    static Report Inspect(MeshType &m)
    {
        Report r;
        r.vertices = m.vn;
        r.faces = m.fn;
        if (m.vn <= 0 || m.fn <= 0) return r;
        RequireSurface(m);
        return InspectChecked(m);
    }

    /// Inspect() for a mesh that already passed RequireSurface().
    static Report InspectChecked(const MeshType &m)
    {
        Report r;
        r.vertices = m.vn;
        r.faces = m.fn;
        const int nv = int(m.vert.size());
        const int nf = int(m.face.size());

        // Vertex indices of the live faces with three distinct vertices (faces with a repeated
        // vertex have no meaningful edges and are left out of the topology).
        std::vector<int> fv;
        fv.reserve(size_t(m.fn) * 3);
        double edgeSum = 0;
        size_t edgeCnt = 0;
        for (int i = 0; i < nf; ++i) {
            const FaceType &f = m.face[i];
            if (f.IsD()) continue;
            for (int k = 0; k < 3; ++k) {
                edgeSum += vcg::Distance(vcg::Point3d::Construct(f.cV(k)->cP()),
                                         vcg::Point3d::Construct(f.cV((k + 1) % 3)->cP()));
                ++edgeCnt;
            }
            if (IsDegenerate(f)) ++r.degenerateFaces;
            if (f.cV(0) != f.cV(1) && f.cV(1) != f.cV(2) && f.cV(2) != f.cV(0))
                for (int k = 0; k < 3; ++k) fv.push_back(VIndex(m, f.cV(k)));
        }
        r.meanEdgeLength = edgeCnt ? edgeSum / double(edgeCnt) : 0.0;
        const int nt = int(fv.size() / 3);

        // Vertex -> corners table (counting sort); a corner is t*3+k.
        std::vector<int> start(nv + 1, 0);
        for (int c = 0; c < 3 * nt; ++c) ++start[fv[c] + 1];
        for (int v = 0; v < nv; ++v) start[v + 1] += start[v];
        std::vector<int> corners(start[nv]);
        {
            std::vector<int> fill(start.begin(), start.end() - 1);
            for (int c = 0; c < 3 * nt; ++c) corners[fill[fv[c]]++] = c;
        }

        // Surface components: union-find over vertices through face edges.
        std::vector<int> comp(nv);
        std::iota(comp.begin(), comp.end(), 0);
        for (int t = 0; t < nt; ++t) {
            const int a = Find(comp, fv[3 * t]);
            const int b = Find(comp, fv[3 * t + 1]);
            const int c = Find(comp, fv[3 * t + 2]);
            comp[b] = a;
            comp[c] = a;
        }

        std::vector<int64_t> key; // (neighbour vertex << 32) | local corner, sorted per vertex
        std::vector<int> local;
        for (int v = 0; v < nv; ++v) {
            const int k0 = start[v], kn = start[v + 1] - start[v];
            if (kn == 0) continue;
            if (Find(comp, v) == v) ++r.components;
            key.clear();
            for (int j = 0; j < kn; ++j) {
                const int c = corners[k0 + j], t = c / 3, k = c % 3;
                key.push_back((int64_t(fv[3 * t + (k + 1) % 3]) << 32) | j);
                key.push_back((int64_t(fv[3 * t + (k + 2) % 3]) << 32) | j);
            }
            // Valences are small: insertion sort beats std::sort here.
            for (size_t a = 1; a < key.size(); ++a) {
                const int64_t x = key[a];
                size_t b = a;
                for (; b > 0 && key[b - 1] > x; --b) key[b] = key[b - 1];
                key[b] = x;
            }
            local.resize(kn);
            std::iota(local.begin(), local.end(), 0);
            for (size_t a = 0; a < key.size();) {
                const int64_t nb = key[a] >> 32;
                size_t b = a + 1;
                while (b < key.size() && (key[b] >> 32) == nb) ++b;
                const size_t run = b - a; // number of faces sharing edge (v, nb)
                if (nb > v) {             // count each edge once, from its lower endpoint
                    if (run == 1) ++r.borderEdges;
                    if (run > 2) ++r.nonManifoldEdges;
                }
                const int ra = Find(local, int(key[a] & 0xffffffff));
                for (size_t c = a + 1; c < b; ++c) local[Find(local, int(key[c] & 0xffffffff))] = ra;
                a = b;
            }
            int fans = 0;
            for (int j = 0; j < kn; ++j)
                if (Find(local, j) == j) ++fans;
            if (fans > 1) ++r.nonManifoldVertices;
        }
        return r;
    }

private:
    static int &concurrentFaces()
    {
        static int faces = 100000;
        return faces;
    }
    static int Find(std::vector<int> &p, int x)
    {
        while (p[x] != x) {
            p[x] = p[p[x]];
            x = p[x];
        }
        return x;
    }
};

} // namespace tri
} // namespace vcg

#endif
