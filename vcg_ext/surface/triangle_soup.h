#ifndef VCG_EXT_TRIANGLE_SOUP_H
#define VCG_EXT_TRIANGLE_SOUP_H

// Triangle soups: meshes whose faces do not share vertices, each corner having its own copy
// of the position (STL files, some OBJ/PLY exporters). On such a mesh no two faces are
// adjacent, so a snake can never cross from one face to the next, and every energy sees each
// triangle alone. They are detected and reported (naming MeshLab's own cleaning filter), and
// merged only when the user asks, with vcglib's Clean::RemoveDuplicateVertex.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <tuple>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/clean.h>

#include <vcg_ext/snake/error.h>
#include <vcg_ext/surface/mesh_validation.h>

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
        double far = 0, size = 0; ///< largest |coordinate| and bounding box diagonal of the used vertices
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
        vcg::Box3d box;
        for (const auto &q : p) {
            box.Add(vcg::Point3d(std::get<0>(q), std::get<1>(q), std::get<2>(q)));
            r.far = std::max({r.far, std::fabs(std::get<0>(q)), std::fabs(std::get<1>(q)), std::fabs(std::get<2>(q))});
        }
        r.size = p.empty() ? 0 : box.Diag();
        std::sort(p.begin(), p.end());
        for (size_t i = 1; i < p.size(); ++i)
            if (p[i] == p[i - 1]) ++r.duplicates;
        r.soup = r.vertices > 0 && r.duplicates >= SoupFraction() * r.vertices;
        return r;
    }

    /// The message for a soup (the filters put it in their error).
    static std::string Message(const Report &r)
    {
        // Far from the origin, single-precision (float) coordinates step coarsely: a unit cube at 1e7
        // (steps of 1) has its distinct vertices merged when the file is read.
        const double step = r.far * 1.2e-7;
        if (step > 1e-3 * r.size) {
            char buf[512];
            std::snprintf(buf, sizeof buf,
                          "The mesh lies %.3g from the origin but is only %.3g across: there, the single-precision "
                          "(float) coordinates MeshLab and the program keep step by about %.3g, so %d of its %d "
                          "vertices fell onto the position of another one when it was read, and its faces are no "
                          "longer connected. Move the mesh near the origin first (e.g. MeshLab's Filters > Normals, "
                          "Curvatures and Orientation > Transform: Translate, Center, set Origin), in the program "
                          "that made it.", r.far, r.size, step, r.duplicates, r.vertices);
            return buf;
        }
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
