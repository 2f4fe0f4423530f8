#ifndef VCG_EXT_SNAKE_ENERGY_FIELD_H
#define VCG_EXT_SNAKE_ENERGY_FIELD_H

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

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
};

/// The paper's energy (Sec. 6.1): values at the vertices, linear inside each face. Level 0
/// holds the values as given; level k > 0 holds them smoothed by `rounds[k]` rounds of
/// Laplacian averaging over mesh edges (Sec. 6.3), each level renormalized to [0,1].
template <class MeshType>
class VertexEnergyField : public SnakeEnergyField<MeshType>
{
public:
    typedef typename MeshType::FaceType FaceType;

    /// `energy`: one value in [0,1] per mesh vertex (deleted vertices ignored).
    /// `rounds`: the extra smoothing rounds of each coarser level, increasing, e.g. {8, 32}.
    VertexEnergyField(const MeshType &m, std::vector<float> energy, const std::vector<int> &rounds = {})
        : mesh(m)
    {
        levels.push_back(std::move(energy));
        std::vector<float> cur = levels[0];
        int done = 0;
        for (int r : rounds) {
            if (r <= done) continue;
            smooth(cur, r - done);
            done = r;
            std::vector<float> lv = cur;
            normalize(lv);
            levels.push_back(std::move(lv));
        }
    }

    int Levels() const override { return int(levels.size()); }
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

    int clampLevel(int level) const { return std::max(0, std::min(level, int(levels.size()) - 1)); }
    int idx(const typename MeshType::VertexType *v) const { return int(v - &mesh.vert[0]); }

    /// Sec. 6.3: each round moves every vertex halfway to the mean of its edge neighbours;
    /// each edge is seen from both faces, so the weights are symmetric.
    void smooth(std::vector<float> &e, int rounds) const
    {
        std::vector<double> sum(e.size());
        std::vector<int> cnt(e.size());
        for (int it = 0; it < rounds; ++it) {
            std::fill(sum.begin(), sum.end(), 0.0);
            std::fill(cnt.begin(), cnt.end(), 0);
            for (const auto &f : mesh.face) {
                if (f.IsD()) continue;
                for (int k = 0; k < 3; ++k) {
                    int a = idx(f.cV(k)), b = idx(f.cV((k + 1) % 3));
                    sum[a] += e[b]; ++cnt[a];
                    sum[b] += e[a]; ++cnt[b];
                }
            }
            for (size_t v = 0; v < e.size(); ++v)
                if (cnt[v] > 0) e[v] = float(0.5 * e[v] + 0.5 * sum[v] / cnt[v]);
        }
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
