#ifndef VCG_EXT_SNAKE_ENERGY_FIELD_H
#define VCG_EXT_SNAKE_ENERGY_FIELD_H

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/Sparse>

#include <vcg/space/box3.h>
#include <vcg/space/point3.h>
#include <vcg_ext/surface/surface_point.h>

namespace vcg {
namespace tri {

/// What a snake slithers on (Sec. 6): an energy in [0,1] (low = feature) that the engine
/// reads only through this interface, as vcglib's Geodesic reads its metric through a functor:
/// its value and its gradient at a surface point, on each level of a coarse-to-fine pyramid
/// (level 0 precise, higher levels smoother with wider basins). A new energy (e.g. one
/// evaluated at the point rather than interpolated from vertices) is a new subclass, held by
/// the SnakeSurface; the engine does not change.
template <class MeshType>
class SnakeEnergyField
{
public:
    virtual ~SnakeEnergyField() = default;
    /// Number of pyramid levels (at least 1).
    virtual int Levels() const = 0;
    /// Energy at p on `level` (0 <= level < Levels()).
    virtual double Value(int level, const SurfacePoint &p) const = 0;
    /// Gradient of the energy at p on `level`: a vector in space, tangent to p's face, in
    /// energy per unit length of the mesh. Zero where the energy is flat or undefined.
    virtual vcg::Point3d Gradient(int level, const SurfacePoint &p) const = 0;
    /// How far the wells of `level` reach (mesh length units): the distance from a feature
    /// over which that level still pulls a snake towards it. 0 for a precise level. The
    /// engine scales a level's force by its reach (its slopes are that much gentler).
    virtual double Reach(int /*level*/) const { return 0; }
    /// True when the field is linear inside each face (interpolated from vertex values): its
    /// wells then follow the mesh's zigzag fold lines, and the engine averages level 0's slope
    /// across the curve over about 1.5 triangles (SnakeSegmentMotion::acrossSlope). A field
    /// evaluated at the point itself is exact there and is read as it is.
    virtual bool FaceLinear() const { return false; }
    /// The direction straight across the nearest feature at p, on `level` (a unit vector in
    /// space, tangent to p's face, pointing away from the feature like the gradient), where the
    /// field knows it: p's nearest feature point is the foot of a perpendicular to the feature.
    /// An open end moves along it (SnakeMotionRules::acrossFeatureEnd). False if unknown.
    virtual bool AcrossFeature(int /*level*/, const SurfacePoint & /*p*/, vcg::Point3d & /*dir*/) const { return false; }
};

/// The paper's energy (Sec. 6.1): values at the vertices, linear inside each face. Level 0
/// holds the values as given; level k > 0 is a smoothing of them (Sec. 6.3) whose wells reach
/// `reach[k-1]` (a distance), each level renormalized to [0,1].
///
/// The smoothing is by distance, not by edge hops, so that a level reaches as far on a mesh
/// whose edge lengths vary 20x as on a uniform one: one implicit step of heat diffusion,
/// (M + r^2 L) u = M e, with L the cotangent Laplacian (weights clamped to [0, 1e3]: an
/// M-matrix, so u stays within the range of e) and M the lumped vertex areas. Its kernel
/// decays like exp(-d / r) away from a feature: long tails, so a coarse level still has a
/// slope several r away, where a Gaussian of the same width is flat.
///
/// Coarse levels are computed lazily, tile by tile, only where a snake reads them (issue 12:
/// solving them on the whole mesh took 6 s on 1.2M faces, for snakes that touch a few
/// percent of it). Space is cut into cubes of side 6r (tiles, fixed by the mesh's bounding
/// box, so a vertex's value does not depend on which snake asked first); a tile's values come
/// from the heat step solved on the faces of the tile and its 26 neighbours, a margin of 6r
/// where the kernel has decayed to exp(-6) = 0.25 %. When that neighbourhood holds half the
/// mesh or more, the level is solved on the whole mesh at once. The renormalization needs the
/// level's lowest and highest values: they are found where a box filter of the energy at
/// scale r is lowest and highest (cells of side r), by solving the tiles there first.
/// Not thread-safe: reads of a coarse level may fill it in.
template <class MeshType>
class VertexEnergyField : public SnakeEnergyField<MeshType>
{
public:
    typedef typename MeshType::FaceType FaceType;

    /// `energy`: one value in [0,1] per mesh vertex (deleted vertices ignored).
    /// `reach`: the reach of each coarser level in mesh length units, increasing, e.g. {2h, 4h, 8h}.
    VertexEnergyField(const MeshType &m, std::vector<float> energy, const std::vector<double> &reach = {})
        : mesh(m), base(std::move(energy))
    {
        for (double x : reach)
            if (x > 0 && std::isfinite(x) && (coarse.empty() || x > coarse.back().reach)) {
                coarse.emplace_back();
                coarse.back().reach = x;
            }
    }

    int Levels() const override { return 1 + int(coarse.size()); }
    double Reach(int level) const override
    {
        const int l = clampLevel(level);
        return l == 0 ? 0.0 : coarse[l - 1].reach;
    }
    bool FaceLinear() const override { return true; }
    /// The value at vertex v on `level` (computes the coarse level's tile around v if needed).
    float VertexValue(int level, int v) const
    {
        const int l = clampLevel(level);
        if (l == 0) return base[v];
        const Level &L = ensureVertex(l - 1, v);
        return L.Normalized(L.raw[v]);
    }
    /// Number of vertices whose value on `level` is computed so far (all of them on level 0).
    int ComputedVertices(int level) const
    {
        const int l = clampLevel(level);
        if (l == 0) return int(base.size());
        const Level &L = coarse[l - 1];
        return int(std::count(L.done.begin(), L.done.end(), 1));
    }

    double Value(int level, const SurfacePoint &p) const override
    {
        const FaceType &f = mesh.face[p.face];
        double v[3];
        faceValues(level, f, v);
        return p.bary[0] * v[0] + p.bary[1] * v[1] + p.bary[2] * v[2];
    }

    /// The gradient of the linear interpolant inside p's face (0 on degenerate faces).
    vcg::Point3d Gradient(int level, const SurfacePoint &p) const override
    {
        const FaceType &f = mesh.face[p.face];
        vcg::Point3d q[3];
        for (int k = 0; k < 3; ++k) q[k] = vcg::Point3d::Construct(f.cP(k));
        vcg::Point3d n = (q[1] - q[0]) ^ (q[2] - q[0]);
        double a2 = n.SquaredNorm();
        if (!(a2 > 0) || !std::isfinite(a2)) return vcg::Point3d(0, 0, 0);
        double v[3];
        faceValues(level, f, v);
        vcg::Point3d g(0, 0, 0);
        for (int k = 0; k < 3; ++k) g += (n ^ (q[(k + 2) % 3] - q[(k + 1) % 3])) * v[k]; // grad of hat k
        g /= a2;
        return std::isfinite(g.SquaredNorm()) ? g : vcg::Point3d(0, 0, 0);
    }

private:
    /// A dense grid of cubes over the mesh's bounding box; the side grows when the grid would
    /// pass `maxCells` (a mesh of a few huge and many tiny faces), at the cost of larger tiles.
    struct Grid
    {
        vcg::Point3d origin;
        double side = 1;
        int dim[3] = {1, 1, 1};
        void Init(const vcg::Box3d &b, double s, double maxCells)
        {
            origin = b.min;
            side = s;
            for (;;) {
                double cells = 1;
                for (int a = 0; a < 3; ++a) cells *= std::floor(b.Dim()[a] / side) + 1;
                if (cells <= maxCells) break;
                side *= 1.26;
            }
            for (int a = 0; a < 3; ++a) dim[a] = int(std::floor(b.Dim()[a] / side)) + 1;
        }
        int Coord(const vcg::Point3d &p, int a) const
        {
            const double x = std::floor((p[a] - origin[a]) / side);
            return x < 0 ? 0 : (x >= dim[a] ? dim[a] - 1 : int(x));
        }
        int Cell(const vcg::Point3d &p) const { return Id(Coord(p, 0), Coord(p, 1), Coord(p, 2)); }
        int Id(int x, int y, int z) const { return (z * dim[1] + y) * dim[0] + x; }
        int Count() const { return dim[0] * dim[1] * dim[2]; }
    };
    /// One coarse level: raw heat-step values where done[v], its tiles (a Grid of side 6r)
    /// with the faces binned by the tile of their centroid, and its renormalization range
    /// (known once `ready`).
    struct Level
    {
        double reach = 0;
        bool ready = false;
        double lo = 0, hi = 1;
        std::vector<float> raw;
        std::vector<char> done;
        Grid tiles;
        std::vector<int> binStart, binFaces; // faces of tile t: binFaces[binStart[t] .. binStart[t+1])
        float Normalized(float u) const
        {
            if (!(hi - lo > 1e-6)) return u;
            return float(std::min(1.0, std::max(0.0, (u - lo) / (hi - lo))));
        }
    };

    const MeshType &mesh;
    std::vector<float> base;
    mutable std::vector<Level> coarse;
    // shared by the levels, built at the first read of a coarse level
    mutable vcg::Box3d box;
    mutable std::vector<vcg::Point3d> centre; // face centroids (deleted faces: none)
    mutable std::vector<double> vertMass;     // lumped vertex areas, for the box filter
    mutable std::vector<int> liveFaces, localOf, localStamp;
    mutable int stamp = 0;

    int clampLevel(int level) const { return std::max(0, std::min(level, int(coarse.size()))); }
    int idx(const typename MeshType::VertexType *v) const { return int(v - &mesh.vert[0]); }
    vcg::Point3d vpos(int v) const { return vcg::Point3d::Construct(mesh.vert[v].cP()); }
    static double MaxCells() { return 4e6; }

    void faceValues(int level, const FaceType &f, double v[3]) const
    {
        const int l = clampLevel(level);
        if (l == 0) {
            for (int k = 0; k < 3; ++k) v[k] = base[idx(f.cV(k))];
            return;
        }
        for (int k = 0; k < 3; ++k) {
            const Level &L = ensureVertex(l - 1, idx(f.cV(k)));
            v[k] = L.Normalized(L.raw[idx(f.cV(k))]);
        }
    }

    const Level &ensureVertex(int k, int v) const
    {
        Level &L = coarse[k];
        if (L.done.empty() || !L.done[v]) {
            prepare(k);
            if (!L.done[v]) solveTile(k, L.tiles.Cell(vpos(v)));
            if (!L.done[v]) { // a vertex on no face: nothing to smooth
                L.raw[v] = base[v];
                L.done[v] = 1;
            }
        }
        return L;
    }

    /// Face centroids, vertex areas and the bounding box, once.
    void prepareShared() const
    {
        if (!localOf.empty() || mesh.vert.empty()) return;
        const size_t nv = mesh.vert.size();
        box.SetNull();
        for (const auto &v : mesh.vert)
            if (!v.IsD()) box.Add(vcg::Point3d::Construct(v.cP()));
        if (box.IsNull()) box.Add(vcg::Point3d(0, 0, 0));
        centre.assign(mesh.face.size(), vcg::Point3d(0, 0, 0));
        vertMass.assign(nv, 0.0);
        for (size_t fi = 0; fi < mesh.face.size(); ++fi) {
            const FaceType &f = mesh.face[fi];
            if (f.IsD()) continue;
            liveFaces.push_back(int(fi));
            const vcg::Point3d q0 = vcg::Point3d::Construct(f.cP(0)), q1 = vcg::Point3d::Construct(f.cP(1)),
                               q2 = vcg::Point3d::Construct(f.cP(2));
            centre[fi] = (q0 + q1 + q2) / 3.0;
            const double a = ((q1 - q0) ^ (q2 - q0)).Norm() / 6;
            if (std::isfinite(a))
                for (int j = 0; j < 3; ++j) vertMass[idx(f.cV(j))] += a;
        }
        localOf.assign(nv, -1);
        localStamp.assign(nv, 0);
    }

    /// First read of level k: bin the faces by tile (a counting sort), then find the
    /// renormalization range where a box filter of the energy at scale r is lowest and highest.
    void prepare(int k) const
    {
        Level &L = coarse[k];
        if (L.ready) return;
        prepareShared();
        const size_t nv = mesh.vert.size();
        const double r = L.reach;
        L.raw.assign(nv, 1.0f);
        L.done.assign(nv, 0);
        for (size_t v = 0; v < nv; ++v)
            if (mesh.vert[v].IsD()) L.raw[v] = base[v], L.done[v] = 1;
        L.tiles.Init(box, 6 * r, MaxCells());
        L.binStart.assign(L.tiles.Count() + 1, 0);
        for (int fi : liveFaces) ++L.binStart[L.tiles.Cell(centre[fi]) + 1];
        for (int t = 0; t < L.tiles.Count(); ++t) L.binStart[t + 1] += L.binStart[t];
        L.binFaces.resize(liveFaces.size());
        std::vector<int> fill(L.binStart.begin(), L.binStart.end() - 1);
        for (int fi : liveFaces) L.binFaces[fill[L.tiles.Cell(centre[fi])]++] = fi;

        // the box filter: mean energy of cells of side r (cells with little surface skipped)
        Grid cells;
        cells.Init(box, r, MaxCells());
        std::vector<double> m(cells.Count(), 0.0), me(cells.Count(), 0.0);
        std::vector<int> rep(cells.Count(), -1);
        for (size_t v = 0; v < nv; ++v) {
            if (mesh.vert[v].IsD() || !(vertMass[v] > 0)) continue;
            const int c = cells.Cell(vpos(v));
            m[c] += vertMass[v], me[c] += vertMass[v] * base[v];
            if (rep[c] < 0) rep[c] = int(v);
        }
        int loV = -1, hiV = -1;
        for (double minMass : {0.5 * cells.side * cells.side, 0.0}) {
            double best = 2, worst = -1;
            for (int c = 0; c < cells.Count(); ++c) {
                if (rep[c] < 0 || !(m[c] > minMass)) continue;
                const double e = me[c] / m[c];
                if (e < best) best = e, loV = rep[c];
                if (e > worst) worst = e, hiV = rep[c];
            }
            if (loV >= 0) break;
        }
        // the extremes of the level near those cells: the heat step solved on a box of
        // +-6r around them, read within +-2r (4r from the cut: its effect is below 2 %)
        double lo = 1e300, hi = -1e300;
        for (int v : {loV, hiV}) {
            if (v < 0) continue;
            std::vector<int> faces;
            vcg::Box3d around(vpos(v), 6 * r);
            const bool global = regionFaces(L, around, faces);
            std::vector<int> verts;
            Eigen::VectorXd u;
            heatStep(r, faces, verts, u);
            if (global) store(L, verts, u, -1);
            const vcg::Box3d near(vpos(v), 2 * r);
            for (size_t i = 0; i < verts.size(); ++i)
                if (global || near.IsIn(vpos(verts[i]))) lo = std::min(lo, u[i]), hi = std::max(hi, u[i]);
            if (global) break; // exact range from the whole mesh
        }
        if (lo <= hi) L.lo = lo, L.hi = hi;
        L.ready = true;
    }

    /// The faces whose centroid lies in `b` (all live faces, sorted, when that is half the
    /// mesh or more: returns true).
    bool regionFaces(const Level &L, const vcg::Box3d &b, std::vector<int> &faces) const
    {
        faces.clear();
        const Grid &g = L.tiles;
        for (int z = g.Coord(b.min, 2); z <= g.Coord(b.max, 2); ++z)
            for (int y = g.Coord(b.min, 1); y <= g.Coord(b.max, 1); ++y)
                for (int x = g.Coord(b.min, 0); x <= g.Coord(b.max, 0); ++x) {
                    const int t = g.Id(x, y, z);
                    for (int i = L.binStart[t]; i < L.binStart[t + 1]; ++i)
                        if (b.IsIn(centre[L.binFaces[i]])) faces.push_back(L.binFaces[i]);
                }
        if (2 * faces.size() < liveFaces.size()) return false;
        faces = liveFaces;
        return true;
    }

    /// Stores the solved values of the vertices in tile t (of all of them if t < 0).
    void store(Level &L, const std::vector<int> &verts, const Eigen::VectorXd &u, int t) const
    {
        for (size_t i = 0; i < verts.size(); ++i) {
            const int v = verts[i];
            if (L.done[v] || (t >= 0 && L.tiles.Cell(vpos(v)) != t)) continue;
            L.raw[v] = float(u[i]);
            L.done[v] = 1;
        }
    }

    /// Solves the heat step of level k on tile t and a margin of one tile (6r) around it, and
    /// stores the values of t's vertices (of every vertex when that region is half the mesh).
    void solveTile(int k, int t) const
    {
        Level &L = coarse[k];
        const Grid &g = L.tiles;
        const int x = t % g.dim[0], y = (t / g.dim[0]) % g.dim[1], z = t / (g.dim[0] * g.dim[1]);
        vcg::Box3d b(g.origin + vcg::Point3d(x - 1, y - 1, z - 1) * g.side,
                     g.origin + vcg::Point3d(x + 2, y + 2, z + 2) * g.side);
        std::vector<int> faces, verts;
        const bool global = regionFaces(L, b, faces);
        Eigen::VectorXd u;
        heatStep(L.reach, faces, verts, u);
        store(L, verts, u, global ? -1 : t);
    }

    /// (M + r^2 L) u = M e on the given faces (the cut is a free, zero-flux border), by
    /// conjugate gradients from u = e. `verts` receives the vertices, in the order of u.
    void heatStep(double r, const std::vector<int> &faces, std::vector<int> &verts, Eigen::VectorXd &u) const
    {
        if (++stamp == 0x7fffffff) std::fill(localStamp.begin(), localStamp.end(), 0), stamp = 1;
        verts.clear();
        auto local = [&](int v) {
            if (localStamp[v] != stamp) localStamp[v] = stamp, localOf[v] = int(verts.size()), verts.push_back(v);
            return localOf[v];
        };
        std::vector<Eigen::Triplet<double>> t;
        t.reserve(faces.size() * 9);
        std::vector<double> mass;
        double areaSum = 0;
        int used = 0;
        const double r2 = r * r;
        for (int fi : faces) {
            const FaceType &f = mesh.face[fi];
            vcg::Point3d q[3];
            int vi[3];
            for (int k = 0; k < 3; ++k) q[k] = vcg::Point3d::Construct(f.cP(k)), vi[k] = local(idx(f.cV(k)));
            if (mass.size() < verts.size()) mass.resize(verts.size(), 0.0);
            const double a2 = ((q[1] - q[0]) ^ (q[2] - q[0])).Norm();
            if (!(a2 > 0) || !std::isfinite(a2)) continue;
            areaSum += a2 / 2, ++used;
            for (int k = 0; k < 3; ++k) {
                mass[vi[k]] += a2 / 6;
                const int a = vi[(k + 1) % 3], b = vi[(k + 2) % 3];
                const double c = (q[(k + 1) % 3] - q[k]) * (q[(k + 2) % 3] - q[k]) / a2; // cot of the angle at k
                const double w = 0.5 * std::min(1e3, std::max(0.0, c)) * r2;
                t.emplace_back(a, b, -w), t.emplace_back(b, a, -w);
                t.emplace_back(a, a, w), t.emplace_back(b, b, w);
            }
        }
        const int n = int(verts.size());
        mass.resize(n, 0.0);
        // a floor keeps isolated and degenerate vertices solvable
        const double floorArea = used ? 1e-6 * areaSum / used : 1.0;
        Eigen::VectorXd e(n), rhs(n);
        for (int i = 0; i < n; ++i) {
            mass[i] = std::max(mass[i], floorArea);
            t.emplace_back(i, i, mass[i]);
            e[i] = base[verts[i]];
            rhs[i] = mass[i] * e[i];
        }
        Eigen::SparseMatrix<double> A(n, n);
        A.setFromTriplets(t.begin(), t.end());
        Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper> cg;
        cg.setTolerance(1e-5);
        cg.setMaxIterations(1000);
        cg.compute(A);
        u = cg.solveWithGuess(rhs, e);
        if (!u.allFinite()) u = e;
    }
};

} // namespace tri
} // namespace vcg

#endif
