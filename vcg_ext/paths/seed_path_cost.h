#ifndef VCG_EXT_SEED_PATH_COST_H
#define VCG_EXT_SEED_PATH_COST_H

// The costs a seed path can minimize (Lee & Lee 2002, Sec. 5.5): small types SeedPath is
// templated on, as vcglib's Geodesic takes its metric as a functor. A new cost is a new type;
// the search does not change.
//
// A cost prices a straight piece between two places on one face (two vertices of an edge, a
// surface point and a vertex of its face, two points in one face), and gives a lower bound
// of its price per unit of Euclidean length, which keeps A*'s straight-line heuristic
// admissible. `StraightIsCheapest` says whether the straight line on the surface is the best
// path (true for plain length: SeedPath then walks it across faces where it can).

#include <cmath>
#include <string>
#include <vector>

#include <vcg/complex/complex.h>

#include <vcg_ext/snake/error.h>
#include <vcg_ext/surface/mesh_validation.h>
#include <vcg_ext/surface/surface_point.h>

namespace vcg {
namespace tri {

/// The costs offered to users (filter parameter, edit tool, session files).
enum class SeedPathCost { Length = 0, Feature = 1 };

/// Euclidean length: the shortest path.
template <class MeshType>
class LengthPathCost
{
public:
    static constexpr bool StraightIsCheapest = true;

    explicit LengthPathCost(const MeshType &m) : m_(m) {}

    double operator()(int a, int b) const { return vcg::Distance(P(a), P(b)); }
    double operator()(const SurfacePoint &p, int v) const { return vcg::Distance(p.Pd(m_), P(v)); }
    double operator()(const SurfacePoint &a, const SurfacePoint &b) const { return vcg::Distance(a.Pd(m_), b.Pd(m_)); }
    double LowerBoundPerLength() const { return 1.0; }

private:
    vcg::Point3d P(int v) const { return vcg::Point3d::Construct(m_.vert[v].cP()); }
    const MeshType &m_;
};

/// Length weighted by the feature energy held in the vertex quality (in [0,1], low on a
/// feature): length * (epsilon + mean quality of the ends), an "intelligent scissors" path
/// that already hugs the feature. Epsilon > 0 keeps every piece's cost positive.
template <class MeshType>
class FeaturePathCost
{
public:
    typedef MeshValidation<MeshType> MV;
    static constexpr bool StraightIsCheapest = false;

    FeaturePathCost(const MeshType &m, double epsilon) : m_(m), eps_(epsilon)
    {
        if (!tri::HasPerVertexQuality(m))
            throw SnakeError("The feature-weighted seed path needs the feature energy in the vertex quality.");
        if (!(epsilon > 0) || !std::isfinite(epsilon))
            throw SnakeError("The feature path epsilon must be a positive number (got " + std::to_string(epsilon) + ").");
        q_.resize(m.vert.size());
        for (size_t i = 0; i < m.vert.size(); ++i) {
            const double q = double(m.vert[i].cQ());
            q_[i] = std::isfinite(q) ? std::max(0.0, q) : 1.0; // quality >= 0 keeps the bound a bound
        }
    }

    double operator()(int a, int b) const { return vcg::Distance(P(a), P(b)) * (eps_ + 0.5 * (q_[a] + q_[b])); }
    double operator()(const SurfacePoint &p, int v) const
    {
        return vcg::Distance(p.Pd(m_), P(v)) * (eps_ + 0.5 * (Quality(p) + q_[v]));
    }
    double operator()(const SurfacePoint &a, const SurfacePoint &b) const
    {
        return vcg::Distance(a.Pd(m_), b.Pd(m_)) * (eps_ + 0.5 * (Quality(a) + Quality(b)));
    }
    double LowerBoundPerLength() const { return eps_; }

private:
    vcg::Point3d P(int v) const { return vcg::Point3d::Construct(m_.vert[v].cP()); }
    /// The quality at a surface point, interpolated from its face's corners.
    double Quality(const SurfacePoint &p) const
    {
        const typename MeshType::FaceType &f = m_.face[p.face];
        double q = 0;
        for (int k = 0; k < 3; ++k) q += p.bary[k] * q_[MV::VIndex(m_, f.cV(k))];
        return q;
    }

    const MeshType &m_;
    double eps_;
    std::vector<double> q_;
};

} // namespace tri
} // namespace vcg

#endif
