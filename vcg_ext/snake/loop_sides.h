#ifndef VCG_EXT_SNAKE_LOOP_SIDES_H
#define VCG_EXT_SNAKE_LOOP_SIDES_H

// The sides of a closed edge loop on a mesh, flooded from the loop so that the cost follows the
// smaller side (the part a loop cuts off), not the mesh: part salience's part areas
// (part_salience.h), the bend across a loop (loop_bend.h) and the loop across a part
// (part_boundary_end.h) read them. Split from part_salience.h (session 37).

#include <algorithm>
#include <deque>
#include <unordered_map>
#include <vector>

#include <vcg/complex/complex.h>

namespace vcg {
namespace tri {

/// The sides of a loop of vertex indices: the mesh's vertices without the loop's, joined by
/// edges, each with the area of its faces (a face goes to the side of its vertices off the
/// loop). Every side is flooded from the loop breadth first, all in turn, so the side with
/// fewer vertices ends first and Step() can stop there: the cost follows the part the loop
/// cuts off, not the mesh. Walks the VF adjacency, which must be current. Pieces of the mesh
/// the loop does not touch are no side.
template <class MeshType>
class SidesOfLoop
{
public:
    typedef typename MeshType::FaceType FaceType;

    SidesOfLoop(const MeshType &m, const std::vector<int> &loop) : m(m)
    {
        for (int v : loop) label[v] = -1;
        for (int v : loop) // the faces no side holds (each counted from its least vertex)
            ForFaces(m, v, [&](const FaceType *f, int) {
                const int a = index(m, f->cV(0)), b = index(m, f->cV(1)), c = index(m, f->cV(2));
                if (v == std::min(a, std::min(b, c)) && OnLoop(a) && OnLoop(b) && OnLoop(c))
                    loopArea += vcg::DoubleArea(*f) / 2;
            });
        // each vertex beside the loop starts a flood of its own; floods that meet join
        for (int v : loop)
            ForFaces(m, v, [&](const FaceType *f, int z) {
                for (int k = 1; k < 3; ++k) {
                    const int u = index(m, f->cV((z + k) % 3));
                    if (label.count(u)) continue;
                    label[u] = int(up.size());
                    up.push_back(int(up.size())), pending.push_back(1), area.push_back(0.0), last.push_back(u);
                    queue.push_back(u), ++growing;
                }
            });
    }

    /// Floods one vertex; false when every side has ended.
    bool Step()
    {
        if (queue.empty()) return false;
        const int v = queue.front();
        queue.pop_front();
        ++visited;
        const int r = Root(label[v]);
        ForFaces(m, v, [&](const FaceType *f, int z) {
            int owner = -1; // the face's first vertex off the loop counts its area, once
            for (int k = 0; k < 3 && owner < 0; ++k)
                if (!OnLoop(index(m, f->cV(k)))) owner = index(m, f->cV(k));
            if (owner == v) {
                const double a = vcg::DoubleArea(*f) / 2;
                area[r] += a, known += a;
            }
            for (int k = 1; k < 3; ++k) {
                const int u = index(m, f->cV((z + k) % 3));
                const auto it = label.find(u);
                if (it == label.end()) {
                    label[u] = r, ++pending[r], queue.push_back(u);
                } else if (it->second >= 0) {
                    const int ru = Root(it->second);
                    if (ru != r) up[ru] = r, pending[r] += pending[ru], area[r] += area[ru], --growing;
                }
            }
        });
        last[r] = v;
        if (--pending[r] == 0) ended.push_back(r), --growing;
        return true;
    }

    /// v's side, -1 on the loop, -2 not reached yet.
    int Side(int v)
    {
        const auto it = label.find(v);
        return it == label.end() ? -2 : (it->second < 0 ? -1 : Root(it->second));
    }
    bool OnLoop(int v) const
    {
        const auto it = label.find(v);
        return it != label.end() && it->second < 0;
    }
    bool Ended(int side) const { return side >= 0 && pending[side] == 0; }
    /// Every flood joined into one still growing: the loop's neighbours are all one side, the
    /// loop cuts nothing off (each side holds a neighbour: its flood ends or joins). Known
    /// once the floods round the loop meet, not when the mesh is flooded.
    bool OneSide() const { return growing == 1 && ended.empty(); }
    /// The one side still growing (growing == 1).
    int GrowingSide() { return Root(label[queue.front()]); }

    std::vector<int> ended;    ///< sides whose flood has ended (whole)
    int growing = 0;           ///< sides still growing
    std::vector<double> area;  ///< by side: the area flooded so far
    std::vector<int> last;     ///< by side: the vertex flooded last (the farthest from the loop)
    double known = 0;          ///< the area flooded so far, all sides
    double loopArea = 0;       ///< the area of the faces whose vertices are all on the loop
    size_t visited = 0;        ///< vertices flooded

    /// fn(face, v's index in it) for the live faces round vertex v (VF adjacency).
    template <class Fn>
    static void ForFaces(const MeshType &m, int v, Fn fn)
    {
        const typename MeshType::VertexType *p = &m.vert[v];
        for (const FaceType *f = p->cVFp(), *next = nullptr; f; f = next) {
            const int z = (f->cV(0) == p) ? 0 : (f->cV(1) == p ? 1 : 2);
            next = f->cVFp(z);
            if (!f->IsD()) fn(f, z);
        }
    }

private:
    static int index(const MeshType &m, const typename MeshType::VertexType *v) { return int(v - &m.vert[0]); }
    int Root(int c)
    {
        while (up[c] != c) c = up[c] = up[up[c]];
        return c;
    }
    const MeshType &m;
    std::unordered_map<int, int> label; // vertex -> its flood's first side (-1: on the loop)
    std::vector<int> up, pending;       // union-find of floods; vertices queued per side
    std::deque<int> queue;
};

} // namespace tri
} // namespace vcg

#endif
