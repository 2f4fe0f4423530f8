#ifndef VCG_EXT_CREASE_ENERGY_H
#define VCG_EXT_CREASE_ENERGY_H

// A feature energy for CAD tessellations, defined at every surface point (beyond the paper,
// whose energies of Sec. 6.1 live at vertices and are interpolated linearly, Sec. 6.2).
//
// A B-rep tessellator puts (almost) every vertex on a crease and fills each flat face with
// fans of long slivers, so any per-vertex measure is "feature" at every vertex and has no
// valley along a crease. Here the sharp edges are found from dihedral angles, and the energy
// at a surface point p is a function of its distance d(p) to the nearest sharp edge:
//     E(p) = 1 - exp(-(d/w)^2),
// 0 on the crease, 1 (flat) inside faces, smooth, with a basin of width w. A wider w widens
// the basin by distance (this is what smoothing means for this energy), never by rings of
// slivers, whose size says nothing about the part.
//
// The distance: the straight (3D) distance to the nearest sharp edge that bounds the smooth
// patch p lies on, i.e. the sharp edges reachable from p's face without crossing a sharp edge.
// Within a flat CAD face that is exactly the geodesic distance to the face's boundary (for
// convex faces; a lower bound around reflex corners), it costs one point-segment distance per
// candidate, and, unlike the plain 3D distance to any crease, it does not leak across a thin
// wall to the creases of the other side.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/space/distance3.h>
#include <vcg/space/index/grid_static_ptr.h>
#include <vcg/space/segment3.h>

#include <vcg_ext/energy/energy_field.h>
#include <vcg_ext/snake/error.h>
#include <vcg_ext/surface/mesh_validation.h>
#include <vcg_ext/surface/surface_point.h>

namespace vcg {
namespace tri {

/// Dihedral angle (between the two face normals) above which an edge is a crease. 30
/// degrees keeps the edges of a block, a bore or a pocket (90) and fandisk's soft creases
/// (~25-60), and leaves out the facets of cylinders tessellated with 16 or more segments.
inline double DefaultCreaseAngle() { return 30.0; }

template <class MeshType>
class CreaseEnergy
{
public:
    typedef typename MeshType::FaceType FaceType;
    typedef typename MeshType::VertexType VertexType;
    typedef MeshValidation<MeshType> MV;

    static double DefaultAngle() { return DefaultCreaseAngle(); }
    /// Basin width per smoothing step, as a fraction of the bounding box diagonal: with
    /// `steps` smoothing steps, w = (1 + steps) * BaseWidth() * diagonal.
    static double BaseWidthFraction() { return 0.01; }
    static double WidthFor(double diagonal, int steps) { return (1.0 + std::max(0, steps)) * BaseWidthFraction() * diagonal; }
    /// Candidate creases are collected up to this many widths away (E = 1 - e^-9 beyond).
    static double ReachInWidths() { return 3.0; }

    /// Finds the creases (dihedral angle > angleDeg) and, for each face, the creases within
    /// `reach` of it on its smooth patch. No adjacency component of the mesh is needed.
    void Build(const MeshType &m, double angleDeg, double reach)
    {
        MV::RequireSurface(m);
        if (!std::isfinite(angleDeg) || angleDeg <= 0 || angleDeg >= 180)
            throw SnakeError("The crease angle must be between 0 and 180 degrees (got " + std::to_string(angleDeg) + ").");
        if (!std::isfinite(reach) || reach <= 0) throw SnakeError("The crease energy needs a positive basin width.");
        mesh = &m;
        angle = angleDeg;
        const int nf = int(m.face.size());
        faceN.assign(nf, vcg::Point3d(0, 0, 0));
        for (int f = 0; f < nf; ++f) {
            const FaceType &ff = m.face[f];
            if (ff.IsD() || MV::IsDegenerate(ff)) continue;
            faceN[f] = ((P(ff, 1) - P(ff, 0)) ^ (P(ff, 2) - P(ff, 0))).Normalize();
        }
        // Edges by sorting (vertex pair, face, side): works on any mesh type.
        struct E { int a, b, f, k; };
        std::vector<E> edges;
        edges.reserve(size_t(nf) * 3);
        for (int f = 0; f < nf; ++f) {
            const FaceType &ff = m.face[f];
            if (ff.IsD()) continue;
            for (int k = 0; k < 3; ++k) {
                int a = MV::VIndex(m, ff.cV(k)), b = MV::VIndex(m, ff.cV((k + 1) % 3));
                if (a == b) continue;
                if (a > b) std::swap(a, b);
                edges.push_back({a, b, f, k});
            }
        }
        std::sort(edges.begin(), edges.end(), [](const E &x, const E &y) {
            return x.a != y.a ? x.a < y.a : (x.b != y.b ? x.b < y.b : x.f < y.f);
        });
        across.assign(nf, {-1, -1, -1});
        sharpOf.assign(nf, {-1, -1, -1});
        segs.clear();
        const double cosT = std::cos(angleDeg * M_PI / 180.0);
        for (size_t i = 0; i < edges.size();) {
            size_t j = i + 1;
            while (j < edges.size() && edges[j].a == edges[i].a && edges[j].b == edges[i].b) ++j;
            if (j - i == 2) {
                const E &x = edges[i], &y = edges[i + 1];
                const vcg::Point3d &n0 = faceN[x.f], &n1 = faceN[y.f];
                const bool degenerate = n0.SquaredNorm() == 0 || n1.SquaredNorm() == 0;
                if (!degenerate && n0 * n1 < cosT) { // a crease: both faces see it, neither crosses it
                    const int s = addSeg(m, x.a, x.b);
                    sharpOf[x.f][x.k] = sharpOf[y.f][y.k] = s;
                } else {
                    across[x.f][x.k] = y.f;
                    across[y.f][y.k] = x.f;
                }
            } else if (j - i > 2) { // non-manifold edge: a crease for every face on it
                const int s = addSeg(m, edges[i].a, edges[i].b);
                for (size_t t = i; t < j; ++t) sharpOf[edges[t].f][edges[t].k] = s;
            }
            i = j;
        }
        collectCandidates(m, reach);
    }

    int CreaseCount() const { return int(segs.size()); }
    double Angle() const { return angle; }
    /// The crease edges as segments (for drawing, tests).
    const std::vector<vcg::Segment3d> &Creases() const { return segs; }

    /// Distance from the surface point p to the nearest crease of its patch (infinity if
    /// none within reach); `closest` receives the nearest crease point.
    double Distance(const SurfacePoint &p, vcg::Point3d *closest = nullptr) const
    {
        const vcg::Point3d x = p.Pd(*mesh);
        double best = std::numeric_limits<double>::infinity();
        for (int c = candStart[p.face]; c < candStart[p.face + 1]; ++c) {
            vcg::Point3d q;
            double d;
            vcg::SegmentPointDistance<double>(segs[cand[c]], x, q, d);
            if (d < best) {
                best = d;
                if (closest) *closest = q;
            }
        }
        return best;
    }

    /// E(p) = 1 - exp(-(d/w)^2) for basin width w.
    double Value(const SurfacePoint &p, double w) const
    {
        const double d = Distance(p);
        if (!std::isfinite(d)) return 1.0;
        const double t = d / w;
        return 1.0 - std::exp(-t * t);
    }

    /// Gradient of E at p, in space, tangent to p's face: dE/dd * (x - c)/d, projected.
    vcg::Point3d Gradient(const SurfacePoint &p, double w) const
    {
        vcg::Point3d c(0, 0, 0); // set by Distance whenever d is finite
        const double d = Distance(p, &c);
        if (!std::isfinite(d) || !(d > 0)) return vcg::Point3d(0, 0, 0);
        const vcg::Point3d x = p.Pd(*mesh);
        // dE/dd = 2 d / w^2 exp(-(d/w)^2); times the unit direction (x - c) / d.
        vcg::Point3d g = (x - c) * (2.0 / (w * w) * std::exp(-(d / w) * (d / w)));
        const vcg::Point3d &n = faceN[p.face];
        g -= n * (g * n);
        return g;
    }

    /// The energy at every vertex (through one of its faces), e.g. for the vertex quality.
    std::vector<double> VertexValues(double w) const
    {
        const MeshType &m = *mesh;
        std::vector<double> v(m.vert.size(), 1.0);
        std::vector<char> done(m.vert.size(), 0);
        for (size_t f = 0; f < m.face.size(); ++f) {
            if (m.face[f].IsD()) continue;
            for (int k = 0; k < 3; ++k) {
                const int vi = MV::VIndex(m, m.face[f].cV(k));
                const double e = Value(SurfacePoint::AtCorner(int(f), k), w);
                v[vi] = done[vi] ? std::min(v[vi], e) : e;
                done[vi] = 1;
            }
        }
        return v;
    }

private:
    const MeshType *mesh = nullptr;
    double angle = 0;
    std::vector<vcg::Point3d> faceN;
    std::vector<std::array<int, 3>> across;  // face across each edge on the same patch, -1 if none
    std::vector<std::array<int, 3>> sharpOf; // crease index of each face edge, -1 if not a crease
    std::vector<vcg::Segment3d> segs;
    std::vector<int> candStart, cand;        // per face: the creases within reach on its patch

    static vcg::Point3d P(const FaceType &f, int k) { return vcg::Point3d::Construct(f.cV(k)->cP()); }
    int addSeg(const MeshType &m, int a, int b)
    {
        segs.push_back(vcg::Segment3d(vcg::Point3d::Construct(m.vert[a].cP()), vcg::Point3d::Construct(m.vert[b].cP())));
        return int(segs.size()) - 1;
    }

    /// The smooth patches: faces joined across edges that are not creases.
    std::vector<int> patches(const MeshType &m) const
    {
        const int nf = int(m.face.size());
        std::vector<int> patch(nf, -1), stack;
        int count = 0;
        for (int f = 0; f < nf; ++f) {
            if (m.face[f].IsD() || patch[f] >= 0) continue;
            patch[f] = count;
            stack.assign(1, f);
            while (!stack.empty()) {
                const int g = stack.back();
                stack.pop_back();
                for (int k = 0; k < 3; ++k) {
                    const int h = across[g][k];
                    if (h >= 0 && patch[h] < 0) {
                        patch[h] = count;
                        stack.push_back(h);
                    }
                }
            }
            ++count;
        }
        return patch;
    }

    /// The creases in vcglib's grid, each with the patches it bounds (one when the crease
    /// ends inside a smooth region, whose faces on both sides are joined around its end).
    class PatchCreaseGrid
    {
    public:
        struct Crease
        {
            typedef double ScalarType;
            int id = -1;
            vcg::Segment3d seg;
            std::vector<int> patches;
            bool IsD() const { return false; }
            void GetBBox(vcg::Box3d &b) const { b = seg.BBox(); }
            bool Bounds(int p) const { return std::find(patches.begin(), patches.end(), p) != patches.end(); }
        };
        PatchCreaseGrid(const MeshType &m, const std::vector<vcg::Segment3d> &segs,
                        const std::vector<std::array<int, 3>> &sharpOf, const std::vector<int> &patch)
        {
            creases.resize(segs.size());
            for (size_t s = 0; s < segs.size(); ++s) {
                creases[s].id = int(s);
                creases[s].seg = segs[s];
            }
            for (size_t f = 0; f < m.face.size(); ++f)
                for (int k = 0; k < 3; ++k)
                    if (sharpOf[f][k] >= 0 && !creases[sharpOf[f][k]].Bounds(patch[f]))
                        creases[sharpOf[f][k]].patches.push_back(patch[f]);
            if (creases.empty()) return;
            // The grid spans the whole mesh and a margin, so every query point lies inside it
            // (vcglib turns coordinates into int cell indices, and its cells are half open: a
            // point on the box's far side was in none, and its nearest crease was not found).
            vcg::Box3d box;
            for (const auto &v : m.vert)
                if (!v.IsD()) box.Add(vcg::Point3d::Construct(v.cP()));
            box.Offset(0.01 * box.Diag());
            grid.Set(creases.begin(), creases.end(), box);
        }
        /// The distance from c to the nearest crease bounding patch p, infinity if beyond maxDist.
        double Nearest(const vcg::Point3d &c, int p, double maxDist)
        {
            if (creases.empty()) return std::numeric_limits<double>::infinity();
            double d = maxDist;
            vcg::Point3d q;
            Distance fn{p};
            NoMarker marker;
            return grid.GetClosest(fn, marker, c, maxDist, d, q) ? d : std::numeric_limits<double>::infinity();
        }
        /// The creases bounding patch p within r of c (a crease may be listed more than once).
        void Within(const vcg::Point3d &c, int p, double r, std::vector<int> &out)
        {
            out.clear();
            NoMarker marker;
            grid.GetInBox(marker, vcg::Box3d(c, r), inBox);
            for (Crease *o : inBox) {
                if (!o->Bounds(p)) continue;
                vcg::Point3d q;
                double d;
                vcg::SegmentPointDistance<double>(o->seg, c, q, d);
                if (d <= r) out.push_back(o->id);
            }
        }

    private:
        struct Distance
        {
            int patch;
            typedef vcg::Point3d QueryType;
            static const vcg::Point3d &Pos(const QueryType &p) { return p; }
            bool operator()(const Crease &o, const vcg::Point3d &p, double &minDist, vcg::Point3d &q) const
            {
                if (!o.Bounds(patch)) return false;
                double d;
                vcg::SegmentPointDistance<double>(o.seg, p, q, d);
                if (!(d <= minDist)) return false;
                minDist = d;
                return true;
            }
        };
        struct NoMarker // a crease in several cells is looked at again: harmless
        {
            void UnMarkAll() const {}
            bool IsMarked(const Crease *) const { return false; }
            void Mark(const Crease *) const {}
        };
        std::vector<Crease> creases;
        std::vector<Crease *> inBox;
        vcg::GridStaticPtr<Crease, double> grid;
    };

    /// For each face f of patch P (centroid c, radius rad): the creases bounding P whose
    /// distance to c is at most d + 2 rad, d the nearest one's, if d <= reach + rad. A crease
    /// farther than that is farther than the nearest from every point of f (both are within rad
    /// of c), so Distance is exact for every point of f within reach. Two queries of vcglib's
    /// grid per face: a walk over the patch from every face, bounded to 4096 faces, took a
    /// minute on the 70k-face bunny00 (9 sharp edges) and stopped short of creases on dense
    /// meshes.
    void collectCandidates(const MeshType &m, double reach)
    {
        const int nf = int(m.face.size());
        candStart.assign(nf + 1, 0);
        cand.clear();
        const std::vector<int> patch = patches(m);
        PatchCreaseGrid grid(m, segs, sharpOf, patch);
        std::vector<int> seen(segs.size(), -1), near;
        for (int f = 0; f < nf; ++f) {
            candStart[f] = int(cand.size());
            if (m.face[f].IsD()) continue;
            const FaceType &ff = m.face[f];
            const vcg::Point3d c = (P(ff, 0) + P(ff, 1) + P(ff, 2)) / 3.0;
            double rad = 0;
            for (int k = 0; k < 3; ++k) rad = std::max(rad, (P(ff, k) - c).Norm());
            const double d = grid.Nearest(c, patch[f], reach + rad);
            if (!std::isfinite(d)) continue;
            grid.Within(c, patch[f], d + 2 * rad, near);
            for (int s : near)
                if (seen[s] != f) {
                    seen[s] = f;
                    cand.push_back(s);
                }
        }
        candStart[nf] = int(cand.size());
    }
};

/// The crease energy as the snakes read it (SnakeEnergyField): evaluated at each sample, not
/// interpolated from vertices. Level 0 has basin width w, level 1 (capture) 3w: the snakes
/// first slither on the wide basins, then settle in the narrow ones.
template <class MeshType>
class CreaseEnergyField : public SnakeEnergyField<MeshType>
{
public:
    /// Basin widths of the levels for `steps` smoothing steps (see CreaseEnergy::WidthFor).
    static std::vector<double> Widths(const MeshType &m, int steps)
    {
        vcg::Box3d b;
        for (const auto &v : m.vert)
            if (!v.IsD()) b.Add(vcg::Point3d::Construct(v.cP()));
        const double w = CreaseEnergy<MeshType>::WidthFor(b.Diag(), steps);
        return {w, CaptureFactor() * w};
    }
    static double CaptureFactor() { return 3.0; }

    CreaseEnergyField(const MeshType &m, double angleDeg, const std::vector<double> &levelWidths) : widths(levelWidths)
    {
        if (widths.empty()) throw SnakeError("The crease energy needs at least one basin width.");
        crease.Build(m, angleDeg, CreaseEnergy<MeshType>::ReachInWidths() * *std::max_element(widths.begin(), widths.end()));
    }
    int Levels() const override { return int(widths.size()); }
    double Value(int level, const SurfacePoint &p) const override { return crease.Value(p, width(level)); }
    vcg::Point3d Gradient(int level, const SurfacePoint &p) const override { return crease.Gradient(p, width(level)); }
    const CreaseEnergy<MeshType> &Creases() const { return crease; }

private:
    CreaseEnergy<MeshType> crease;
    std::vector<double> widths;
    double width(int level) const { return widths[std::max(0, std::min(level, int(widths.size()) - 1))]; }
};

} // namespace tri
} // namespace vcg

#endif
