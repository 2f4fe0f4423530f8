#ifndef VCG_EXT_SNAKE_ENERGY_FIELD_H
#define VCG_EXT_SNAKE_ENERGY_FIELD_H

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/Sparse>

#include <vcg/space/point3.h>
#include <vcg_ext/surface_point.h>

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
/// slope several r away, where a Gaussian of the same width is flat. Solved by conjugate
/// gradients, each level warm-started from the previous one: O(vertices * iterations), once.
template <class MeshType>
class VertexEnergyField : public SnakeEnergyField<MeshType>
{
public:
    typedef typename MeshType::FaceType FaceType;

    /// `energy`: one value in [0,1] per mesh vertex (deleted vertices ignored).
    /// `reach`: the reach of each coarser level in mesh length units, increasing, e.g. {2h, 4h, 8h}.
    VertexEnergyField(const MeshType &m, std::vector<float> energy, const std::vector<double> &reach = {})
        : mesh(m)
    {
        levels.push_back(std::move(energy));
        reaches.push_back(0);
        std::vector<double> r;
        for (double x : reach)
            if (x > 0 && std::isfinite(x) && (r.empty() || x > r.back())) r.push_back(x);
        if (r.empty()) return;
        Eigen::SparseMatrix<double> L;
        Eigen::VectorXd mass;
        laplacian(L, mass);
        const int n = int(levels[0].size());
        Eigen::VectorXd e0(n), u(n);
        for (int v = 0; v < n; ++v) e0[v] = levels[0][v];
        u = e0;
        const Eigen::VectorXd rhs = mass.cwiseProduct(e0);
        Eigen::SparseMatrix<double> M(n, n);
        std::vector<Eigen::Triplet<double>> diag;
        for (int v = 0; v < n; ++v) diag.emplace_back(v, v, mass[v]);
        M.setFromTriplets(diag.begin(), diag.end());
        for (double x : r) {
            const Eigen::SparseMatrix<double> A = L * (x * x) + M;
            Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper> cg;
            cg.setTolerance(1e-5);
            cg.setMaxIterations(1000);
            cg.compute(A);
            Eigen::VectorXd next = cg.solveWithGuess(rhs, u);
            if (next.allFinite()) u = next;
            std::vector<float> lv(n);
            for (int v = 0; v < n; ++v) lv[v] = mesh.vert[v].IsD() ? levels[0][v] : float(u[v]);
            normalize(lv);
            levels.push_back(std::move(lv));
            reaches.push_back(x);
        }
    }

    int Levels() const override { return int(levels.size()); }
    double Reach(int level) const override { return reaches[clampLevel(level)]; }
    bool FaceLinear() const override { return true; }
    float VertexValue(int level, int v) const { return levels[clampLevel(level)][v]; }
    const std::vector<float> &LevelValues(int level) const { return levels[clampLevel(level)]; }

    double Value(int level, const SurfacePoint &p) const override
    {
        const FaceType &f = mesh.face[p.face];
        const std::vector<float> &e = levels[clampLevel(level)];
        return p.bary[0] * e[idx(f.cV(0))] + p.bary[1] * e[idx(f.cV(1))] + p.bary[2] * e[idx(f.cV(2))];
    }

    /// The gradient of the linear interpolant inside p's face (0 on degenerate faces).
    vcg::Point3d Gradient(int level, const SurfacePoint &p) const override
    {
        const FaceType &f = mesh.face[p.face];
        const std::vector<float> &e = levels[clampLevel(level)];
        vcg::Point3d q[3];
        for (int k = 0; k < 3; ++k) q[k] = vcg::Point3d::Construct(f.cP(k));
        vcg::Point3d n = (q[1] - q[0]) ^ (q[2] - q[0]);
        double a2 = n.SquaredNorm();
        if (!(a2 > 0) || !std::isfinite(a2)) return vcg::Point3d(0, 0, 0);
        vcg::Point3d g(0, 0, 0);
        for (int k = 0; k < 3; ++k) g += (n ^ (q[(k + 2) % 3] - q[(k + 1) % 3])) * double(e[idx(f.cV(k))]); // grad of hat k
        g /= a2;
        return std::isfinite(g.SquaredNorm()) ? g : vcg::Point3d(0, 0, 0);
    }

private:
    const MeshType &mesh;
    std::vector<std::vector<float>> levels;
    std::vector<double> reaches;

    int clampLevel(int level) const { return std::max(0, std::min(level, int(levels.size()) - 1)); }
    int idx(const typename MeshType::VertexType *v) const { return int(v - &mesh.vert[0]); }

    /// The cotangent Laplacian (positive semi-definite, weights clamped to [0, 1e3]) and the
    /// lumped vertex areas (a floor keeps isolated and degenerate vertices solvable).
    void laplacian(Eigen::SparseMatrix<double> &L, Eigen::VectorXd &mass) const
    {
        const int n = int(mesh.vert.size());
        std::vector<Eigen::Triplet<double>> t;
        mass = Eigen::VectorXd::Zero(n);
        double areaSum = 0;
        int faces = 0;
        for (const auto &f : mesh.face) {
            if (f.IsD()) continue;
            vcg::Point3d q[3];
            int vi[3];
            for (int k = 0; k < 3; ++k) q[k] = vcg::Point3d::Construct(f.cP(k)), vi[k] = idx(f.cV(k));
            const double a2 = ((q[1] - q[0]) ^ (q[2] - q[0])).Norm();
            if (!(a2 > 0) || !std::isfinite(a2)) continue;
            areaSum += a2 / 2, ++faces;
            for (int k = 0; k < 3; ++k) {
                mass[vi[k]] += a2 / 6;
                const int a = vi[(k + 1) % 3], b = vi[(k + 2) % 3];
                const double c = (q[(k + 1) % 3] - q[k]) * (q[(k + 2) % 3] - q[k]) / a2; // cot of the angle at k
                const double w = 0.5 * std::min(1e3, std::max(0.0, c));
                t.emplace_back(a, b, -w), t.emplace_back(b, a, -w);
                t.emplace_back(a, a, w), t.emplace_back(b, b, w);
            }
        }
        const double floorArea = faces ? 1e-6 * areaSum / faces : 1.0;
        for (int v = 0; v < n; ++v) mass[v] = std::max(mass[v], floorArea);
        L.resize(n, n);
        L.setFromTriplets(t.begin(), t.end());
    }
    void normalize(std::vector<float> &e) const
    {
        float lo = 1, hi = 0;
        for (size_t v = 0; v < e.size(); ++v)
            if (!mesh.vert[v].IsD()) { lo = std::min(lo, e[v]); hi = std::max(hi, e[v]); }
        if (hi - lo > 1e-6f)
            for (auto &x : e) x = std::min(1.0f, std::max(0.0f, (x - lo) / (hi - lo)));
    }
};

} // namespace tri
} // namespace vcg

#endif
