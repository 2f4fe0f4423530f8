#ifndef VCG_EXT_TRIANGLE_SOUP_H
#define VCG_EXT_TRIANGLE_SOUP_H

// Triangle soups: meshes whose faces do not share vertices, each corner having its own copy
// of the position (STL files, some OBJ/PLY exporters). On such a mesh no two faces are
// adjacent, so a snake can never cross from one face to the next, and every energy sees each
// triangle alone. They are detected and reported (naming MeshLab's own cleaning filter), and
// merged only when the user asks, with vcglib's Clean::RemoveDuplicateVertex.

#include <algorithm>
#include <string>
#include <tuple>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/clean.h>

#include "mesh_validation.h"
#include "snake_error.h"

namespace vcg {
namespace tri {

template <class MeshType>
class TriangleSoup
{
public:
    typedef typename MeshType::VertexType VertexType;
    typedef MeshValidation<MeshType> MV;

    struct Report
    {
        int vertices = 0;  ///< live vertices used by a face
        int duplicates = 0; ///< vertices at exactly the position of another used vertex
        bool soup = false;  ///< so many that the faces are (mostly) not connected
    };

    /// A mesh is a soup when at least this fraction of its used vertices are copies.
    static double SoupFraction() { return 0.2; }

    /// Counts used vertices that repeat the exact position of another used vertex. O(n log n).
    static Report Inspect(const MeshType &m)
    {
        Report r;
        std::vector<char> used(m.vert.size(), 0);
        for (const auto &f : m.face)
            if (!f.IsD())
                for (int k = 0; k < 3; ++k) used[MV::VIndex(m, f.cV(k))] = 1;
        std::vector<std::tuple<double, double, double>> p;
        for (size_t i = 0; i < m.vert.size(); ++i)
            if (used[i] && !m.vert[i].IsD())
                p.emplace_back(double(m.vert[i].cP()[0]), double(m.vert[i].cP()[1]), double(m.vert[i].cP()[2]));
        r.vertices = int(p.size());
        std::sort(p.begin(), p.end());
        for (size_t i = 1; i < p.size(); ++i)
            if (p[i] == p[i - 1]) ++r.duplicates;
        r.soup = r.vertices > 0 && r.duplicates >= SoupFraction() * r.vertices;
        return r;
    }

    /// The message for a soup (the filters put it in their error).
    static std::string Message(const Report &r)
    {
        return "The mesh is a triangle soup: " + std::to_string(r.duplicates) + " of its " + std::to_string(r.vertices) +
               " vertices repeat the position of another one (as in STL files), so its faces are not connected "
               "and a snake cannot cross from one face to the next. Merge them first with MeshLab's Filters > "
               "Cleaning and Repairing > Merge Close Vertices, or turn on \"Merge duplicate vertices\" here.";
    }

    /// What the filters do: nothing for a mesh that is not a soup (returns -1); a soup is
    /// refused with Message() unless `merge`, then merged (returns the vertices merged).
    static int Handle(MeshType &m, bool merge)
    {
        const Report r = Inspect(m);
        if (!r.soup) return -1;
        if (!merge) throw SnakeError(Message(r));
        return Merge(m);
    }

    /// Merges vertices at identical positions (vcglib's Clean::RemoveDuplicateVertex), drops
    /// the vertices left unused and the faces that became degenerate, and compacts the mesh.
    /// Returns the number of vertices merged.
    static int Merge(MeshType &m)
    {
        const int merged = Clean<MeshType>::RemoveDuplicateVertex(m);
        Clean<MeshType>::RemoveUnreferencedVertex(m);
        Clean<MeshType>::RemoveDegenerateFace(m);
        Allocator<MeshType>::CompactEveryVector(m);
        return merged;
    }
};

} // namespace tri
} // namespace vcg

#endif
