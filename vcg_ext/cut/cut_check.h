#ifndef VCG_EXT_CUT_CUT_CHECK_H
#define VCG_EXT_CUT_CUT_CHECK_H

// The checks a cut passes before the user's mesh is changed: the curves' edges form their
// chains, no face is degenerate or turned over, the sides are what the floods found and the
// areas add up to the mesh's. A failed check is an error (SnakeError), never a quiet change.

#include <cmath>
#include <string>
#include <vector>

#include <vcg/complex/algorithms/stat.h>

#include <vcg_ext/cut/curve_embedding.h>
#include <vcg_ext/cut/cut_sides.h>
#include <vcg_ext/cut/cut_work_mesh.h>
#include <vcg_ext/snake/error.h>

namespace vcg {
namespace tri {

class CutCheck
{
public:
    /// Relative tolerance of the area sums.
    static double AreaTolerance() { return 1e-9; }

    [[noreturn]] static void Fail(const std::string &what)
    {
        throw SnakeError("Cut: the check after the cut failed (" + what +
                         "); the mesh was not changed. Please report this mesh and curve.");
    }

    /// Vertex v has a boundary edge (an edge with one face).
    static bool OnBoundary(const CutWorkMesh &w, int v)
    {
        for (int f : w.Faces(v))
            for (int k = 0; k < 3; ++k) {
                const int x = w.face[f].v[k];
                if (x != v && w.EdgeFaces(v, x).size() == 1) return true;
            }
        return false;
    }

    /// After the embedding and the flood of the chosen side `chosen` (when the curves separate).
    static void Embedded(const CutWorkMesh &w, const std::vector<EmbeddedCurve> &curves, const CutSides::Result &s,
                         unsigned char chosen, double totalArea)
    {
        for (const auto &c : curves) {
            const int n = int(c.chain.size()), ne = c.closed ? n : n - 1;
            for (int i = 0; i < ne; ++i) {
                const size_t k = w.EdgeFaces(c.chain[i], c.chain[(i + 1) % n]).size();
                if (k < 1 || k > 2) Fail("a curve edge is not an edge of one or two faces");
            }
        }
        double sum = 0, sumChosen = 0;
        const double mean = totalArea / std::max(1, w.fn0);
        for (size_t f = 0; f < w.face.size(); ++f)
            if (w.face[f].parent >= 0) {
                const double a = w.Area(int(f));
                sum += a;
                if (s.label[f] == chosen) sumChosen += a;
            }
        for (const auto &pk : w.SplitParents()) {
            const std::vector<int> faces = w.Children(pk.first);
            vcg::Point3d np(0, 0, 0); // the user's face's normal: its pieces' normals add up to it
            for (int g : faces) np += w.Normal(g);
            for (int g : faces) {
                const double a = w.Area(g);
                if (!(a >= 1e-12 * mean)) Fail("a face of area " + std::to_string(a) + " was made");
                if (!(w.Normal(g) * np > 0)) Fail("a face was turned over");
            }
        }
        if (!(std::abs(sum - totalArea) <= AreaTolerance() * totalArea)) Fail("the area changed");
        if (!s.separated) return;
        const bool left = chosen == CutSides::Left;
        if (!s.complete[left ? 0 : 1]) Fail("the chosen side was not flooded to its end");
        for (int f : left ? s.leftSeeds : s.rightSeeds)
            if (s.label[f] != chosen) Fail("a face beside the curve is not on its side");
        for (int f : left ? s.rightSeeds : s.leftSeeds)
            if (s.label[f] == chosen) Fail("a face beside the curve is on both sides");
        if (!(std::abs(sumChosen - (left ? s.areaLeft : s.areaRight)) <= AreaTolerance() * totalArea))
            Fail("the chosen side's area is not the flood's");
    }

    static void AfterOpen(const CutWorkMesh &w, const std::vector<EmbeddedCurve> &curves, double totalArea)
    {
        for (const auto &c : curves) {
            const int n = int(c.chain.size()), ne = c.closed ? n : n - 1;
            for (int i = 0; i < ne; ++i)
                if (w.EdgeFaces(c.chain[i], c.chain[(i + 1) % n]).size() > 1)
                    Fail("a curve edge was not opened");
        }
        double sum = 0;
        for (size_t f = 0; f < w.face.size(); ++f)
            if (w.face[f].parent >= 0) sum += w.Area(int(f));
        if (!(std::abs(sum - totalArea) <= AreaTolerance() * totalArea)) Fail("the area changed");
    }

    template <class MeshType>
    static void Parts(MeshType &inside, MeshType &outside, double areaIn, double areaOut, double total)
    {
        auto area = [](const MeshType &m) { // in double: a float sum of a million faces drifts
            double a = 0;
            for (const auto &f : m.face)
                if (!f.IsD()) a += double(vcg::DoubleArea(f)) / 2;
            return a;
        };
        const double ai = area(inside), ao = area(outside);
        const double tol = 1e-6 * total; // the parts are in the mesh's precision (float)
        if (!(std::abs(ai - areaIn) <= tol && std::abs(ao - areaOut) <= tol))
            Fail("the parts' areas are not the sides'");
    }

};

} // namespace tri
} // namespace vcg

#endif
