#ifndef VCG_EXT_PATCH_CREASE_GRID_H
#define VCG_EXT_PATCH_CREASE_GRID_H

// The crease edges of a mesh in vcglib's static grid, each tagged with the smooth patches it
// bounds, for the crease energy (energy/crease_energy.h): its distance is to the nearest crease
// *of the point's own patch*, so every query here is filtered by patch (nearest crease, nearest
// crease facing a direction, creases within a radius). A spatial index is a concept of its own,
// apart from the energy that reads it.

#include <algorithm>
#include <array>
#include <limits>
#include <vector>

#include <vcg/space/box3.h>
#include <vcg/space/distance3.h>
#include <vcg/space/index/grid_static_ptr.h>
#include <vcg/space/segment3.h>

namespace vcg {
namespace tri {

/// The creases in vcglib's grid, each with the patches it bounds (one when the crease
/// ends inside a smooth region, whose faces on both sides are joined around its end).
template <class MeshType>
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
    /// The distance from the middle m of crease s to the nearest other crease bounding patch
    /// p whose point nearest to m lies within 60 degrees of the unit direction u (infinity
    /// if none within maxDist).
    double Facing(int s, const vcg::Point3d &m, const vcg::Point3d &u, int p, double maxDist)
    {
        if (creases.empty()) return std::numeric_limits<double>::infinity();
        double d = maxDist;
        vcg::Point3d q;
        FacingDistance fn{p, s, u};
        NoMarker marker;
        return grid.GetClosest(fn, marker, m, maxDist, d, q) ? d : std::numeric_limits<double>::infinity();
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
    struct FacingDistance
    {
        int patch, self;
        vcg::Point3d dir;
        typedef vcg::Point3d QueryType;
        static const vcg::Point3d &Pos(const QueryType &p) { return p; }
        bool operator()(const Crease &o, const vcg::Point3d &p, double &minDist, vcg::Point3d &q) const
        {
            if (o.id == self || !o.Bounds(patch)) return false;
            double d;
            vcg::SegmentPointDistance<double>(o.seg, p, q, d);
            if (!(d <= minDist) || !(d > 0) || (q - p) * dir < 0.5 * d) return false;
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

} // namespace tri
} // namespace vcg

#endif
