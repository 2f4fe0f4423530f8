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
//
// The width (issue 38): a length of the feature itself, not of the bounding box (a box
// fraction spans several features on a part whose features are small against its size, and
// is narrower than the seeds' offset where they are large), nor of the edges (on a CAD
// tessellation they are slivers as long as the part). Each side of each crease has a local
// feature size s: how far its smooth patch reaches across it, i.e. the distance from the
// crease's middle to the nearest other crease of that patch seen within 60 degrees of the
// direction straight into the patch (the facing crease of a flat strip, the far side of a
// bore or a cap: about the radius of a circle, whatever its number of segments; a crease's
// neighbours along its own chain are never in that cone). A point takes the width of its
// nearest crease: w = f s on its own side (LocalWidth: for the snakes' capture level, capped
// at SideCap() times the crease's own scale, its narrower side; for their precise level the
// own scale), so the basin reaches across the patch, and its ridge is where the nearest
// crease changes (the medial axis): neighbouring creases never share a basin, whatever the
// width. The snakes read it through CreaseEnergyField (energy/crease_energy_field.h).

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/space/distance3.h>
#include <vcg/space/segment3.h>

#include <vcg_ext/energy/patch_crease_grid.h>
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
    /// Basin width per smoothing step, as a fraction of the local feature size s (see the top):
    /// with `steps` smoothing steps, w = (1 + steps) * WidthPerStep() * s. The default smoothing
    /// (2) gives s / 6, and the snakes' capture level (3 w, CreaseEnergyField) s / 2: its slope
    /// reaches the medial axis between two creases.
    static double WidthPerStep() { return 1.0 / 18.0; }
    static double WidthFraction(int steps) { return (1.0 + std::max(0, steps)) * WidthPerStep(); }
    /// The feature size of a crease side that faces no other crease of its patch (an open
    /// sheet): this fraction of the bounding box diagonal (the width of earlier versions).
    static double LoneSizeFraction() { return 0.18; }
    /// Candidate creases are collected up to this many widths away (E = 1 - e^-9 beyond).
    static double ReachInWidths() { return 3.0; }

    /// Finds the creases (dihedral angle > angleDeg) and, for each face, the creases within
    /// `reach` of it on its smooth patch. No adjacency component of the mesh is needed.
    void Build(const MeshType &m, double angleDeg, double reach)
    {
        Build(m, angleDeg);
        Collect(reach);
    }
    /// Finds the creases and their local feature sizes (Collect must follow before Distance).
    void Build(const MeshType &m, double angleDeg)
    {
        MV::RequireSurface(m);
        if (!std::isfinite(angleDeg) || angleDeg <= 0 || angleDeg >= 180)
            throw SnakeError("The crease angle must be between 0 and 180 degrees (got " + std::to_string(angleDeg) + ").");
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
        patch = patches(m);
        grid = std::make_shared<PatchCreaseGrid<MeshType>>(m, segs, sharpOf, patch);
        featureSizes(m);
    }
    /// Collects, for each face, the creases within `reach` of it on its smooth patch.
    void Collect(double reach)
    {
        if (!mesh) throw SnakeError("The crease energy is not built.");
        if (!std::isfinite(reach) || reach <= 0) throw SnakeError("The crease energy needs a positive basin width.");
        collectCandidates(*mesh, reach);
    }

    int CreaseCount() const { return int(segs.size()); }
    double Angle() const { return angle; }
    /// The crease edges as segments (for drawing, tests).
    const std::vector<vcg::Segment3d> &Creases() const { return segs; }

    /// Distance from the surface point p to the nearest crease of its patch (infinity if
    /// none within reach); `closest` receives the nearest crease point.
    /// `which` receives the crease's index (-1 if none).
    double Distance(const SurfacePoint &p, vcg::Point3d *closest = nullptr, int *which = nullptr) const
    {
        const vcg::Point3d x = p.Pd(*mesh);
        double best = std::numeric_limits<double>::infinity();
        if (which) *which = -1;
        for (int c = candStart[p.face]; c < candStart[p.face + 1]; ++c) {
            vcg::Point3d q;
            double d;
            vcg::SegmentPointDistance<double>(segs[cand[c]], x, q, d);
            if (d < best) {
                best = d;
                if (closest) *closest = q;
                if (which) *which = cand[c];
            }
        }
        return best;
    }

    /// The local feature size of crease c on the side of smooth patch `side` (see the top).
    double FeatureSize(int c, int side) const
    {
        double s = std::numeric_limits<double>::infinity();
        for (const auto &x : sizes[c])
            if (x.first == side) s = std::min(s, x.second);
        return std::isfinite(s) ? s : CreaseSize(c);
    }
    /// The crease's own scale: the smaller of its sides' feature sizes.
    double CreaseSize(int c) const
    {
        double s = std::numeric_limits<double>::infinity();
        for (const auto &x : sizes[c]) s = std::min(s, x.second);
        return std::isfinite(s) ? s : loneSize;
    }
    /// The largest feature size of any crease side.
    double MaxFeatureSize() const { return maxSize; }
    /// The feature size that p's nearest crease has on p's side (the largest if none in reach).
    double FeatureSizeAt(const SurfacePoint &p) const
    {
        int c;
        Distance(p, nullptr, &c);
        return c < 0 ? maxSize : FeatureSize(c, patch[p.face]);
    }
    /// The scale of p's nearest crease (CreaseSize; the median one if none in reach).
    double CreaseSizeAt(const SurfacePoint &p) const
    {
        int c;
        Distance(p, nullptr, &c);
        return c < 0 ? MedianCreaseSize() : CreaseSize(c);
    }
    /// The median crease scale, weighted by length (the bounding box's lone size if none).
    double MedianCreaseSize() const
    {
        std::vector<std::pair<double, double>> v;
        double total = 0;
        for (size_t c = 0; c < segs.size(); ++c) {
            v.push_back({CreaseSize(int(c)), segs[c].Length()});
            total += v.back().second;
        }
        if (v.empty()) return loneSize;
        std::sort(v.begin(), v.end());
        double acc = 0;
        for (const auto &x : v)
            if ((acc += x.second) >= total / 2) return x.first;
        return v.back().first;
    }

    /// What a local width is a fraction of: the feature size of p's nearest crease on p's side
    /// (how far the basin may reach), or that crease's own scale, the smaller of its sides
    /// (CreaseSize: a valley as sharp on a wide face as on the narrow one beside it).
    enum class Scale { Side, Crease };
    /// The side's size is taken at most SideCap() times the crease's own scale: a basin as wide
    /// as a 50:1 sliver face is long has so gentle a slope near the crease that the snakes
    /// stopped where they were seeded (bench/eval/gs_creases, a stepped shaft's shoulder rims).
    static double SideCap() { return 4.0; }
    double LocalWidth(int c, const SurfacePoint &p, double fraction, Scale scale) const
    {
        const double own = CreaseSize(c);
        return fraction * (scale == Scale::Side ? std::min(FeatureSize(c, patch[p.face]), SideCap() * own) : own);
    }

    /// E(p) with the local width w = LocalWidth: 1 - exp(-(d/w)^2).
    double LocalValue(const SurfacePoint &p, double fraction, Scale scale = Scale::Side) const
    {
        int c;
        const double d = Distance(p, nullptr, &c);
        if (!std::isfinite(d)) return 1.0;
        const double t = d / LocalWidth(c, p, fraction, scale);
        return 1.0 - std::exp(-t * t);
    }
    /// Its gradient (the width is constant within the basin of one crease).
    vcg::Point3d LocalGradient(const SurfacePoint &p, double fraction, Scale scale = Scale::Side) const
    {
        vcg::Point3d c(0, 0, 0);
        int which;
        const double d = Distance(p, &c, &which);
        if (!std::isfinite(d) || !(d > 0)) return vcg::Point3d(0, 0, 0);
        return gradient(p, c, d, LocalWidth(which, p, fraction, scale));
    }

    /// The unit direction from p's nearest crease point c to p, in p's face plane, when c is the
    /// foot of a perpendicular: x - c within AcrossCos() of square to that crease edge. At a
    /// crease's end or a corner c is a vertex and x - c may run along the crease (an open end
    /// moved that way slid along a pocket rim); on the crease itself there is no direction.
    bool AcrossDirection(const SurfacePoint &p, vcg::Point3d &dir) const
    {
        vcg::Point3d c(0, 0, 0);
        int which;
        const double d = Distance(p, &c, &which);
        if (!std::isfinite(d) || !(d > 0) || which < 0) return false;
        const vcg::Point3d u = (p.Pd(*mesh) - c) / d, e = segs[which].P1() - segs[which].P0();
        const double len = e.Norm();
        if (!(len > 0) || std::abs(u * e) > AcrossCos() * len) return false;
        const vcg::Point3d &n = faceN[p.face];
        dir = u - n * (u * n);
        const double l = dir.Norm();
        if (!(l > 1e-6)) return false;
        dir /= l;
        return true;
    }
    /// AcrossDirection: the largest cosine between x - c and the crease edge (15 degrees off square).
    static double AcrossCos() { return 0.26; }

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
        return gradient(p, c, d, w);
    }

    /// The energy at every vertex (through one of its faces), e.g. for the vertex quality,
    /// with the local width `fraction` * feature size (LocalValue).
    std::vector<double> LocalVertexValues(double fraction) const
    {
        return vertexValues([&](const SurfacePoint &p) { return LocalValue(p, fraction); });
    }

    /// The energy at every vertex (through one of its faces), e.g. for the vertex quality.
    std::vector<double> VertexValues(double w) const
    {
        return vertexValues([&](const SurfacePoint &p) { return Value(p, w); });
    }

private:
    typedef std::vector<std::pair<int, double>> Sizes; // (patch, feature size) of each side

    const MeshType *mesh = nullptr;
    double angle = 0;
    std::vector<vcg::Point3d> faceN;
    std::vector<std::array<int, 3>> across;  // face across each edge on the same patch, -1 if none
    std::vector<std::array<int, 3>> sharpOf; // crease index of each face edge, -1 if not a crease
    std::vector<vcg::Segment3d> segs;
    std::vector<int> patch;                  // smooth patch of each face
    std::vector<Sizes> sizes;                // per crease
    double loneSize = 1, maxSize = 1;
    std::vector<int> candStart, cand;        // per face: the creases within reach on its patch
    std::shared_ptr<PatchCreaseGrid<MeshType>> grid; // the creases, by patch

    /// dE/dd * (x - c)/d for the width w, projected onto p's face.
    vcg::Point3d gradient(const SurfacePoint &p, const vcg::Point3d &c, double d, double w) const
    {
        const vcg::Point3d x = p.Pd(*mesh);
        // dE/dd = 2 d / w^2 exp(-(d/w)^2); times the unit direction (x - c) / d.
        vcg::Point3d g = (x - c) * (2.0 / (w * w) * std::exp(-(d / w) * (d / w)));
        const vcg::Point3d &n = faceN[p.face];
        g -= n * (g * n);
        return g;
    }

    template <class F>
    std::vector<double> vertexValues(F value) const
    {
        const MeshType &m = *mesh;
        std::vector<double> v(m.vert.size(), 1.0);
        std::vector<char> done(m.vert.size(), 0);
        for (size_t f = 0; f < m.face.size(); ++f) {
            if (m.face[f].IsD()) continue;
            for (int k = 0; k < 3; ++k) {
                const int vi = MV::VIndex(m, m.face[f].cV(k));
                const double e = value(SurfacePoint::AtCorner(int(f), k));
                v[vi] = done[vi] ? std::min(v[vi], e) : e;
                done[vi] = 1;
            }
        }
        return v;
    }

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
        std::vector<int> out(nf, -1), stack;
        int count = 0;
        for (int f = 0; f < nf; ++f) {
            if (m.face[f].IsD() || out[f] >= 0) continue;
            out[f] = count;
            stack.assign(1, f);
            while (!stack.empty()) {
                const int g = stack.back();
                stack.pop_back();
                for (int k = 0; k < 3; ++k) {
                    const int h = across[g][k];
                    if (h >= 0 && out[h] < 0) {
                        out[h] = count;
                        stack.push_back(h);
                    }
                }
            }
            ++count;
        }
        return out;
    }

    /// The local feature size of each side of each crease (see the top): from the crease's
    /// middle into each face that has it as an edge, the distance to the nearest crease of
    /// that face's patch facing it. One query of vcglib's grid per side.
    void featureSizes(const MeshType &m)
    {
        vcg::Box3d box;
        for (const auto &v : m.vert)
            if (!v.IsD()) box.Add(vcg::Point3d::Construct(v.cP()));
        loneSize = std::max(LoneSizeFraction() * box.Diag(), std::numeric_limits<double>::min());
        sizes.assign(segs.size(), Sizes());
        for (size_t f = 0; f < m.face.size(); ++f) {
            if (m.face[f].IsD()) continue;
            for (int k = 0; k < 3; ++k) {
                const int s = sharpOf[f][k];
                if (s < 0) continue;
                const vcg::Point3d a = P(m.face[f], k), b = P(m.face[f], (k + 1) % 3);
                vcg::Point3d u = faceN[f] ^ (b - a); // into the face (counter-clockwise faces)
                if (!(u.Norm() > 0)) continue;
                u /= u.Norm();
                const double d = grid->Facing(s, (a + b) * 0.5, u, patch[f], box.Diag());
                const double size = std::isfinite(d) ? d : loneSize;
                bool found = false;
                for (auto &x : sizes[s])
                    if (x.first == patch[f]) x.second = std::min(x.second, size), found = true;
                if (!found) sizes[s].push_back({patch[f], size});
            }
        }
        maxSize = 0;
        for (const auto &v : sizes)
            for (const auto &x : v) maxSize = std::max(maxSize, x.second);
        if (!(maxSize > 0)) maxSize = loneSize;
    }

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
        PatchCreaseGrid<MeshType> &grid = *this->grid;
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

} // namespace tri
} // namespace vcg

#endif
