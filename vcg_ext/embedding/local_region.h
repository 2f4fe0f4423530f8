#ifndef VCG_EXT_LOCAL_REGION_H
#define VCG_EXT_LOCAL_REGION_H

#include <algorithm>
#include <array>
#include <deque>
#include <string>
#include <unordered_map>
#include <vector>

#include <vcg/simplex/face/pos.h>
#include <vcg_ext/surface/snake_surface.h>

namespace vcg {
namespace tri {

/// The local surrounding region of a snake segment (Sec. 5.2): the faces the segment crosses,
/// plus every face sharing a vertex with them, with its holes filled so that it is a
/// topological disk, ready for the embedding of Sec. 5.3.
///  - Holes made of mesh faces (the one-ring missed them) are filled with those faces.
///  - Holes of the mesh itself (a scan's gap inside the region) are closed by a virtual fan:
///    it keeps the region a disk for the embedding, but no sample can walk into it.
///  - A region that is not a disk after that (vertex stars of long slivers wrap around a bore
///    of a CAD part, a handle, a closed surface) is trimmed rather than refused: built again
///    from the crossed faces and their edge neighbours only, then from the crossed faces alone
///    (the farthest faces go first). Only when even that fails (non-manifold, inconsistently
///    oriented, or the crossed faces themselves wrap around) is it refused with a reason; the
///    caller then splits the segment (Sec. 5.1).
/// Local vertex ids: real mesh vertices first, then fan centres. Local faces: real faces
/// first (faces[i] = mesh index), then fan faces. Edge i of a local face runs from
/// tri[t][i] to tri[t][(i+1)%3], as in vcglib; adj[t][i] is the local face across it,
/// -1 for the region border, -2 for a virtual (fan) face.
template <class MeshType>
class LocalRegion
{
public:
    typedef typename MeshType::FaceType FaceType;
    typedef typename MeshType::VertexType VertexType;

    std::vector<int> faces;                   // mesh face of each real local face
    std::vector<std::array<int, 3>> tri;      // local vertex ids (real faces, then fan faces)
    std::vector<std::array<int, 3>> adj;      // across edge i (real faces only)
    std::vector<int> verts;                   // mesh vertex of each local vertex (-1: fan centre)
    std::vector<vcg::Point3d> pos;            // 3D position of each local vertex
    std::vector<int> boundary;                // outer loop (local ids), region on its left
    std::vector<double> arc;                  // per local vertex: order along the core (grown regions), else empty
    std::vector<double> depth;                // per local vertex: distance from the core along edges (grown
                                              // regions; the margin where the growth did not reach), else empty
    std::string error;
    int holesFilled = 0, meshHolesClosed = 0;
    /// How far the last region was trimmed: 0 the paper's region (vertex stars), 1 crossed
    /// faces and their edge neighbours, 2 the crossed faces only.
    int trimLevel = 0;

    int RealFaces() const { return int(faces.size()); }

    /// Local index of a mesh face, or -1 when it is not in this region. Valid until the
    /// surface's scratch marks are reused by the next region.
    int LocalFace(const SnakeSurface<MeshType> &s, int meshFace) const
    {
        if (meshFace < 0 || meshFace >= int(s.faceStamp.size()) || s.faceStamp[meshFace] != gen) return -1;
        return s.faceSlot[meshFace];
    }

    /// Builds the region around `core` faces, trimmed if the full one is not a disk. False
    /// (with `error`, the reason the full region failed) when no trimming gives a disk.
    /// `margin` > 0 (a distance): the region first reaches that far from the core on every side
    /// (metric width, not rings: on long thin triangles one ring can be narrower than one long
    /// edge); when that region is not a disk, the paper's one-ring region is tried.
    bool Build(SnakeSurface<MeshType> &s, const std::vector<int> &core, int maxFaces = 60000, double margin = 0)
    {
        std::string first;
        for (int level = margin > 0 ? -1 : 0; level <= 2; ++level) {
            if (buildAt(s, core, maxFaces, level, margin)) {
                trimLevel = std::max(0, level);
                return true;
            }
            if (level == 0) first = error;
        }
        error = first; // report why the paper's region failed
        return false;
    }

    /// The margin the last region reached around its core (0: one ring only).
    double margin = 0;

private:
    /// Every vertex within `radius` of the core's vertices (Dijkstra along mesh edges from all
    /// of them at once) with its face star: a band of metric width around the segment.
    void grow(SnakeSurface<MeshType> &s, const std::vector<int> &core, double radius, int maxFaces)
    {
        MeshType &m = s.Mesh();
        typedef std::pair<double, int> Item;
        std::vector<Item> &heap = s.heapScratch;
        heap.clear();
        auto reach = [&](int v, double d, int src) {
            if (s.vertMark[v] == gen && s.vertDist[v] <= d) return;
            s.vertMark[v] = gen;
            s.vertDist[v] = d;
            s.vertSrc[v] = src;
            heap.push_back(Item(-d, v));
            std::push_heap(heap.begin(), heap.end());
        };
        for (size_t i = 0; i < core.size(); ++i)
            if (s.FaceUsable(core[i]))
                for (int k = 0; k < 3; ++k) reach(s.Idx(m.face[core[i]].V(k)), 0.0, int(i));
        while (!heap.empty() && int(faces.size()) <= maxFaces) {
            std::pop_heap(heap.begin(), heap.end());
            const Item it = heap.back();
            heap.pop_back();
            const int v = it.second;
            const double d = -it.first;
            if (d > s.vertDist[v]) continue; // stale entry
            VertexType *vp = &m.vert[v];
            for (vcg::face::VFIterator<FaceType> vfi(vp); !vfi.End(); ++vfi) {
                FaceType *f = vfi.F();
                add(s, s.Idx(f));
                for (int k = 1; k <= 2; ++k) {
                    VertexType *w = f->V((vfi.I() + k) % 3);
                    const double dw = d + vcg::Distance(vcg::Point3d::Construct(vp->cP()), vcg::Point3d::Construct(w->cP()));
                    if (dw < radius) reach(s.Idx(w), dw, s.vertSrc[v]);
                }
            }
        }
    }

    bool buildAt(SnakeSurface<MeshType> &s, const std::vector<int> &core, int maxFaces, int level, double radius)
    {
        MeshType &m = s.Mesh();
        clear();
        gen = s.NewGeneration();
        margin = 0;
        if (level < 0) {
            grow(s, core, radius, maxFaces);
            margin = radius;
        }
        for (int f : core) {
            if (!s.FaceUsable(f)) continue;
            if (level <= 0) {
                for (int k = 0; k < 3; ++k) {
                    VertexType *v = m.face[f].V(k);
                    int vi = s.Idx(v);
                    if (s.vertStamp[vi] == gen) continue; // star already taken
                    s.vertStamp[vi] = gen;
                    s.vertSlot[vi] = -1; // not yet a local vertex
                    for (vcg::face::VFIterator<FaceType> vfi(v); !vfi.End(); ++vfi) add(s, s.Idx(vfi.F()));
                }
            } else if (level == 1) {
                for (int k = 0; k < 3; ++k) {
                    FaceType *g = m.face[f].FFp(k);
                    if (g != nullptr && g != &m.face[f]) add(s, s.Idx(g));
                }
            }
            add(s, f);
        }
        if (faces.empty()) return fail("empty region");
        if (int(faces.size()) > maxFaces) return fail("region too large");

        // Fill holes until the region has a single boundary loop (Sec. 5.2).
        std::vector<std::vector<int>> loops; // mesh vertex ids
        std::vector<std::vector<bool>> loopOnMeshBorder;
        for (int round = 0;; ++round) {
            if (!boundaryLoops(s, loops, loopOnMeshBorder)) {
                // The border touches itself at a vertex: take that vertex's whole star.
                if (pinched < 0 || round > 8) return false;
                for (vcg::face::VFIterator<FaceType> vfi(&m.vert[pinched]); !vfi.End(); ++vfi) add(s, s.Idx(vfi.F()));
                error.clear();
                continue;
            }
            if (loops.empty()) return fail("the region is a closed surface");
            if (loops.size() == 1 || round > 4) break;
            // the longest loop is the outer one; every other loop is a hole
            size_t outer = 0;
            for (size_t i = 1; i < loops.size(); ++i)
                if (loops[i].size() > loops[outer].size()) outer = i;
            bool filledFaces = false;
            for (size_t i = 0; i < loops.size(); ++i) {
                if (i == outer) continue;
                bool allBorder = std::all_of(loopOnMeshBorder[i].begin(), loopOnMeshBorder[i].end(), [](bool b) { return b; });
                if (allBorder) continue; // a hole of the mesh: closed by a fan below
                if (!fillHole(s, loops[i], int(faces.size()) * 2 + 64, maxFaces))
                    return fail("the region is not a disk (the segment wraps around the surface)");
                filledFaces = true;
                ++holesFilled;
            }
            if (!filledFaces) break;
        }
        size_t outer = 0;
        for (size_t i = 1; i < loops.size(); ++i)
            if (loops[i].size() > loops[outer].size()) outer = i;
        for (size_t i = 0; i < loops.size(); ++i)
            if (i != outer && !std::all_of(loopOnMeshBorder[i].begin(), loopOnMeshBorder[i].end(), [](bool b) { return b; }))
                return fail("the region is not a disk");

        // Local vertices and faces.
        for (int f : faces)
            for (int k = 0; k < 3; ++k) {
                int v = s.Idx(m.face[f].V(k));
                if (s.vertStamp[v] != gen || s.vertSlot[v] < 0) {
                    s.vertStamp[v] = gen;
                    s.vertSlot[v] = int(verts.size());
                    verts.push_back(v);
                    pos.push_back(vcg::Point3d::Construct(m.vert[v].cP()));
                }
            }
        for (int f : faces) {
            std::array<int, 3> t;
            for (int k = 0; k < 3; ++k) t[k] = s.vertSlot[s.Idx(m.face[f].V(k))];
            tri.push_back(t);
        }
        adj.assign(faces.size(), {-1, -1, -1});
        for (size_t t = 0; t < faces.size(); ++t) {
            for (int k = 0; k < 3; ++k) {
                int g = neighbour(s, faces[t], k);
                if (g >= 0) adj[t][k] = s.faceSlot[g];
            }
        }
        // Close the mesh's own holes with virtual fans (their faces are not walkable).
        for (size_t i = 0; i < loops.size(); ++i) {
            if (i == outer) continue;
            vcg::Point3d c(0, 0, 0);
            for (int v : loops[i]) c += pos[s.vertSlot[v]];
            c /= double(loops[i].size());
            int ci = int(verts.size());
            verts.push_back(-1);
            pos.push_back(c);
            for (size_t j = 0; j < loops[i].size(); ++j) {
                int a = s.vertSlot[loops[i][j]], b = s.vertSlot[loops[i][(j + 1) % loops[i].size()]];
                tri.push_back({b, a, ci}); // the hole is on the right of a->b
                markVirtualEdge(a, b);
            }
            ++meshHolesClosed;
        }
        for (int v : loops[outer]) boundary.push_back(s.vertSlot[v]);
        // A disk: V - E + F = 1 with E = (3F + B) / 2.
        long F = long(tri.size()), B = long(boundary.size()), V = long(verts.size());
        if (V - (3 * F + B) / 2 + F != 1) return fail("the region is not a disk");
        if (level < 0) arcKeys(s);
        return true;
    }

    /// arc[v]: the position along the core (its faces are in curve order) of the core vertex
    /// nearest to local vertex v; vertices the growth did not reach take a neighbour's.
    /// depth[v]: v's distance from the core (the growth's), at most the margin.
    void arcKeys(const SnakeSurface<MeshType> &s)
    {
        arc.assign(verts.size(), -1.0);
        depth.assign(verts.size(), margin);
        for (size_t v = 0; v < verts.size(); ++v)
            if (verts[v] >= 0 && s.vertMark[verts[v]] == gen) {
                arc[v] = s.vertSrc[verts[v]];
                depth[v] = std::min(margin, s.vertDist[verts[v]]);
            }
        for (int pass = 0; pass < 3; ++pass)
            for (const auto &t : tri)
                for (int k = 0; k < 3; ++k)
                    if (arc[t[k]] < 0) arc[t[k]] = std::max(arc[t[(k + 1) % 3]], arc[t[(k + 2) % 3]]);
        for (double &a : arc) a = std::max(a, 0.0);
    }

    int gen = 0;
    int pinched = -1; // a vertex where the region border touches itself

    void clear()
    {
        faces.clear(); tri.clear(); adj.clear(); verts.clear(); pos.clear(); boundary.clear(); arc.clear(); depth.clear();
        error.clear(); holesFilled = meshHolesClosed = 0;
    }
    bool fail(const std::string &why) { error = why; return false; }

    void add(SnakeSurface<MeshType> &s, int f)
    {
        if (!s.FaceUsable(f) || s.faceStamp[f] == gen) return;
        s.faceStamp[f] = gen;
        s.faceSlot[f] = int(faces.size());
        faces.push_back(f);
    }
    bool inRegion(const SnakeSurface<MeshType> &s, int f) const { return f >= 0 && s.faceStamp[f] == gen; }

    /// The face across edge k of mesh face f when it is a proper (manifold, consistently
    /// oriented) neighbour inside the region; -1 otherwise.
    int neighbour(SnakeSurface<MeshType> &s, int f, int k) const
    {
        MeshType &m = s.Mesh();
        FaceType *ff = &m.face[f];
        FaceType *g = ff->FFp(k);
        if (g == nullptr || g == ff) return -1;
        int gi = s.Idx(g);
        if (!inRegion(s, gi)) return -1;
        int j = ff->FFi(k);
        if (g->FFp(j) != ff) return -1; // non-manifold edge
        if (g->V(j) != ff->V((k + 1) % 3)) return -1; // inconsistent orientation
        return gi;
    }

    void markVirtualEdge(int a, int b)
    {
        for (size_t t = 0; t < faces.size(); ++t)
            for (int k = 0; k < 3; ++k)
                if (adj[t][k] == -1 && tri[t][k] == a && tri[t][(k + 1) % 3] == b) adj[t][k] = -2;
    }

    /// Boundary loops (mesh vertex ids, region on the left). False on a pinched
    /// (non-manifold) boundary vertex.
    bool boundaryLoops(SnakeSurface<MeshType> &s, std::vector<std::vector<int>> &loops,
                       std::vector<std::vector<bool>> &onMeshBorder)
    {
        MeshType &m = s.Mesh();
        loops.clear();
        onMeshBorder.clear();
        pinched = -1;
        std::unordered_map<int, std::pair<int, bool>> next; // v0 -> (v1, edge is a mesh border)
        next.reserve(faces.size());
        for (int f : faces) {
            FaceType *ff = &m.face[f];
            for (int k = 0; k < 3; ++k) {
                if (neighbour(s, f, k) >= 0) continue;
                FaceType *g = ff->FFp(k);
                if (g != nullptr && g != ff && inRegion(s, s.Idx(g))) {
                    // neighbour present but the edge is non-manifold or flips orientation
                    int j = ff->FFi(k);
                    if (g->FFp(j) == ff) return fail("inconsistently oriented faces in the region");
                    return fail("non-manifold edge in the region");
                }
                bool border = (g == nullptr || g == ff || g->IsD());
                int v0 = s.Idx(ff->V(k)), v1 = s.Idx(ff->V((k + 1) % 3));
                if (!next.emplace(v0, std::make_pair(v1, border)).second) {
                    pinched = v0;
                    return fail("non-manifold vertex on the region border");
                }
            }
        }
        while (!next.empty()) {
            auto it = next.begin();
            int start = it->first, v = start;
            std::vector<int> loop;
            std::vector<bool> border;
            for (size_t guard = 0; guard <= faces.size() * 3 + 3; ++guard) {
                auto e = next.find(v);
                if (e == next.end()) return fail("open region border");
                loop.push_back(v);
                border.push_back(e->second.second);
                int w = e->second.first;
                next.erase(e);
                v = w;
                if (v == start) break;
            }
            if (v != start) return fail("open region border");
            loops.push_back(loop);
            onMeshBorder.push_back(border);
        }
        return true;
    }

    /// Adds the faces inside a hole loop: flood fill over faces outside the region that
    /// touch the loop; refuses if the fill grows past `cap` (then it is the outside).
    bool fillHole(SnakeSurface<MeshType> &s, const std::vector<int> &loop, int cap, int maxFaces)
    {
        MeshType &m = s.Mesh();
        std::unordered_map<int, int> loopIdx;
        for (int v : loop) loopIdx[v] = 1;
        std::vector<int> seedFaces;
        for (int f : faces) {
            FaceType *ff = &m.face[f];
            for (int k = 0; k < 3; ++k) {
                FaceType *g = ff->FFp(k);
                if (g == nullptr || g == ff || g->IsD()) continue;
                int gi = s.Idx(g);
                if (inRegion(s, gi)) continue;
                if (loopIdx.count(s.Idx(ff->V(k))) && loopIdx.count(s.Idx(ff->V((k + 1) % 3)))) seedFaces.push_back(gi);
            }
        }
        std::vector<int> fill;
        std::unordered_map<int, int> seen;
        std::deque<int> q;
        for (int g : seedFaces)
            if (seen.emplace(g, 1).second) q.push_back(g);
        while (!q.empty()) {
            int g = q.front();
            q.pop_front();
            fill.push_back(g);
            if (int(fill.size()) > cap || int(faces.size() + fill.size()) > maxFaces) return false;
            FaceType *gg = &m.face[g];
            for (int k = 0; k < 3; ++k) {
                FaceType *h = gg->FFp(k);
                if (h == nullptr || h == gg || h->IsD()) continue;
                int hi = s.Idx(h);
                if (inRegion(s, hi)) continue;
                if (seen.emplace(hi, 1).second) q.push_back(hi);
            }
        }
        for (int g : fill) add(s, g);
        return true;
    }
};

} // namespace tri
} // namespace vcg

#endif
