#ifndef VCG_EXT_FEATURE_ENERGY_H
#define VCG_EXT_FEATURE_ENERGY_H

// Feature energy E_mesh of Lee & Lee 2002, Section 6: a per-vertex scalar (stored in the
// vertex quality) with local minima on features, linearly interpolated inside faces (Sec. 6.2)
// and smoothed by neighbour averaging (Sec. 6.3).
//
// All three definitions of Sec. 6.1 are provided. Raw values are made dimensionless (scale
// independent) and then mapped robustly to [0,1]: 0 = strongest feature, 1 = flat.
// Every pass is a single linear sweep over the faces; no adjacency component is required,
// so this runs on CMeshO with all optional ("Ocf") components disabled.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <future>
#include <limits>
#include <string>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/math/quadric.h>
#include <vcg/space/plane3.h>

#include <vcg_ext/energy/crease_energy.h>
#include <vcg_ext/energy/energy_range.h>
#include <vcg_ext/energy/part_boundary_energy.h>
#include <vcg_ext/snake/error.h>
#include <vcg_ext/surface/angle_weighted_normals.h>
#include <vcg_ext/surface/mesh_validation.h>

namespace vcg {
namespace tri {

enum class FeatureEnergyType { NormalVariation = 0, CurvatureNorm = 1, QuadricError = 2, Crease = 3, PartBoundary = 4 };
/// Number of FeatureEnergyType values (valid types are 0 .. count-1).
inline int FeatureEnergyTypeCount() { return 5; }
/// Lower-case names, indexed by type, for messages and the Log.
inline const char *FeatureEnergyName(FeatureEnergyType t)
{
    static const char *const n[] = {"normal variation", "curvature norm", "quadric error", "crease distance",
                                    "part boundary"};
    return (int(t) >= 0 && int(t) < FeatureEnergyTypeCount()) ? n[int(t)] : "unknown";
}

template <class MeshType>
class FeatureEnergy
{
public:
    typedef typename MeshType::CoordType CoordType;
    typedef typename MeshType::ScalarType ScalarType;
    typedef typename MeshType::FaceType FaceType;
    typedef typename MeshType::VertexType VertexType;
    typedef MeshValidation<MeshType> MV;

    struct Stats
    {
        float rawMin = 0, rawMax = 0; // range of the raw (dimensionless) energy before normalization
        int nonManifoldVertices = 0;
        int degenerateFaces = 0;
        int creases = 0; // crease energy: number of sharp edges found
        bool constant = false; // no vertex stands out as a feature (ConstantWarning() says so)
        double seconds = 0;
    };

    /// Progress of a long computation (the smoothing rounds): called with 0..100 as it goes;
    /// returning false cancels it (Compute then throws SnakeCancelled, the mesh's vertex
    /// quality unchanged). MeshLab's callback (vcg::CallBackPos) fits through a lambda.
    typedef std::function<bool(int percent)> Progress;

    /// Robust normalization percentiles (fraction of vertices clamped at each end).
    static double LowPercentile() { return 0.005; }
    static double HighPercentile() { return 0.995; }

    /// Computes the energy into the vertex quality, in [0,1] with 0 = strongest feature, flat = 1,
    /// then `smoothingSteps` rounds of Sec. 6.3 smoothing and a renormalization (so the feature
    /// is at 0 again). Updates face normals and angle-weighted vertex normals.
    /// The crease energy (CreaseEnergy) is already in [0,1]: its smoothing widens its basin by
    /// distance, and the vertices get its values at the vertices (creaseAngleDeg: the dihedral
    /// angle that makes an edge a crease). `progress` hears of the smoothing rounds and may
    /// cancel them (a 1.3M-face mesh smoothed 10,000 times takes minutes).
    static Stats Compute(MeshType &m, FeatureEnergyType type, int smoothingSteps,
                         double creaseAngleDeg = CreaseEnergy<MeshType>::DefaultAngle(),
                         const Progress &progress = Progress())
    {
        const auto t0 = std::chrono::steady_clock::now();
        RequireComponents(m);
        if (smoothingSteps < 0 || smoothingSteps > 100000)
            throw SnakeError("The number of feature energy smoothing steps must be between 0 and 100000 (got " +
                             std::to_string(smoothingSteps) + ").");
        Stats st;
        const double meanEdge = MeanEdgeOrZero(m);
        if (!(meanEdge > 0) || !std::isfinite(meanEdge))
            throw SnakeError("The mesh has no edge of positive finite length (all faces are collapsed to points).");
        // The topology count for the Log reads only the faces and positions, the energy writes
        // only normals and quality: on a large mesh the count runs on the second core (a third
        // of the time on 1.2M faces). Every return below waits for it.
        std::future<typename MV::Report> inspection =
            std::async(m.fn > MV::ConcurrentFaces() ? std::launch::async : std::launch::deferred,
                       [&m] { return MV::InspectChecked(m); });
        auto takeInspection = [&] {
            const typename MV::Report rep = inspection.get();
            st.nonManifoldVertices = rep.nonManifoldVertices;
            st.degenerateFaces = rep.degenerateFaces;
            st.constant = IsConstant(m);
        };

        std::vector<ScalarType> oldQuality; // put back if the smoothing is cancelled
        if (progress && smoothingSteps > 0 && type != FeatureEnergyType::Crease && type != FeatureEnergyType::PartBoundary) {
            oldQuality.reserve(m.vert.size());
            for (const VertexType &v : m.vert) oldQuality.push_back(v.cQ());
        }
        std::vector<vcg::Point3f> fn;
        AngleWeightedNormals<MeshType>::Update(m, fn);
        switch (type) {
        case FeatureEnergyType::NormalVariation: NormalVariationImpl(m, fn); break;
        case FeatureEnergyType::CurvatureNorm: CurvatureNormImpl(m, meanEdge); break;
        case FeatureEnergyType::QuadricError: QuadricErrorImpl(m, fn, meanEdge); break;
        case FeatureEnergyType::Crease: {
            CreaseEnergy<MeshType> ce;
            const double f = CreaseEnergy<MeshType>::WidthFraction(smoothingSteps); // of the local feature size
            ce.Build(m, creaseAngleDeg);
            ce.Collect(CreaseEnergy<MeshType>::ReachInWidths() * f * ce.MaxFeatureSize());
            const std::vector<double> e = ce.LocalVertexValues(f);
            for (size_t i = 0; i < m.vert.size(); ++i)
                if (!m.vert[i].IsD()) m.vert[i].Q() = ScalarType(e[i]);
            st.creases = ce.CreaseCount();
            st.rawMin = 0;
            st.rawMax = 1;
            takeInspection();
            st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            return st;
        }
        case FeatureEnergyType::PartBoundary: { // in [0,1] already; smoothing widens its fit (issue 33)
            const std::vector<double> e = PartBoundaryEnergy<MeshType>::VertexValues(m, smoothingSteps);
            for (size_t i = 0; i < m.vert.size(); ++i)
                if (!m.vert[i].IsD()) m.vert[i].Q() = ScalarType(e[i]);
            st.rawMin = 0;
            st.rawMax = 1;
            takeInspection();
            st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            return st;
        }
        default: throw SnakeError("Unknown feature energy type.");
        }

        float lo = std::numeric_limits<float>::max(), hi = -std::numeric_limits<float>::max();
        for (const VertexType &v : m.vert)
            if (!v.IsD()) {
                lo = std::min(lo, float(v.cQ()));
                hi = std::max(hi, float(v.cQ()));
            }
        st.rawMin = lo;
        st.rawMax = hi;

        Normalize(m, true);
        if (smoothingSteps > 0) {
            const int done = Smooth(m, smoothingSteps, progress);
            if (done < smoothingSteps) {
                for (size_t i = 0; i < m.vert.size(); ++i) m.vert[i].Q() = oldQuality[i];
                throw SnakeCancelled("Feature energy: cancelled after " + std::to_string(done) + " of " +
                                     std::to_string(smoothingSteps) +
                                     " smoothing rounds; the vertex quality is unchanged.");
            }
            Normalize(m, true); // smoothing lifts the minima; put the strongest feature back at 0
        }
        takeInspection();
        st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        return st;
    }

    /// True when every vertex has the flat value 1 (or none is live): the energy shows no feature.
    static bool IsConstant(const MeshType &m)
    {
        for (const VertexType &v : m.vert)
            if (!v.IsD() && v.cQ() < ScalarType(1 - 1e-6)) return false;
        return true;
    }

    /// The warning for a Stats::constant energy (the filter's Log, the program's stderr and JSON).
    static std::string ConstantWarning(FeatureEnergyType t)
    {
        return std::string("The feature energy (") + FeatureEnergyName(t) +
               ") is constant: no vertex stands out as a feature (a flat or evenly curved mesh, or a crease angle "
               "above every edge's), so a snake on it feels no feature force.";
    }

    /// Eq. 6: E(v) = min over faces f around v of n_v . n_f (raw, in [-1,1], 1 = flat).
    /// n_v is the angle-weighted vertex normal (Thuermer & Wuethrich): unlike the area- or
    /// uniformly-weighted normal it depends only on the surface, not on how the fan around v
    /// is triangulated, so the opening angle of the normal cone (the paper's ref. 16) does not
    /// change when a flat region is re-tessellated.
    static void NormalVariation(MeshType &m)
    {
        RequireComponents(m);
        std::vector<vcg::Point3f> fn;
        AngleWeightedNormals<MeshType>::Update(m, fn);
        NormalVariationImpl(m, fn);
    }

    /// Discrete curvature norm |k1|+|k2| (Sec. 6.1, ref. 15: Meyer et al.'s cotangent mean
    /// curvature, angle-deficit Gaussian curvature and mixed Voronoi areas, the operators of
    /// vcglib's UpdateCurvature::MeanAndGaussian). Written here as one face sweep because the
    /// vcglib version needs FF adjacency and the optional curvature component and divides by
    /// tan(angle) of degenerate faces. Raw energy = -(|k1|+|k2|) * mean edge length
    /// (dimensionless; high curvature -> low energy, flat = 0).
    static void CurvatureNorm(MeshType &m)
    {
        RequireComponents(m);
        std::vector<vcg::Point3f> fn;
        AngleWeightedNormals<MeshType>::Update(m, fn);
        CurvatureNormImpl(m, MV::MeanEdgeLength(m));
    }

    /// Garland-Heckbert quadric error (Sec. 6.1, ref. 9): E(v) = -max over edges (v,w) of the
    /// error of collapsing v into w, Q_v(p_w). Q_v is the area-weighted mean of the squared
    /// distances to the planes of v's faces (vcg::math::Quadric), so Q_v(p_w) is a length^2;
    /// dividing by the squared mean edge length makes it scale free. The half-edge collapse
    /// (placement at the kept endpoint) is used because with optimal placement a vertex lying
    /// exactly on a sharp edge can always be collapsed along the edge for free.
    static void QuadricError(MeshType &m)
    {
        RequireComponents(m);
        std::vector<vcg::Point3f> fn;
        AngleWeightedNormals<MeshType>::Update(m, fn);
        QuadricErrorImpl(m, fn, MV::MeanEdgeLength(m));
    }

    /// Sec. 6.3: `steps` rounds of averaging each vertex with its one-ring (the vertex itself
    /// included, so the filter is a low pass without odd/even oscillation). Like vcglib's
    /// Smooth::VertexQualityLaplacian but one face sweep per round and no dependence on border
    /// flags or FF adjacency. Returns the rounds done: fewer than `steps` if `progress` said
    /// stop (the vertex quality is then left as it was).
    static int Smooth(MeshType &m, int steps, const Progress &progress = Progress())
    {
        if (steps <= 0) return 0;
        const size_t nv = m.vert.size();
        std::vector<double> q(nv, 1.0), sum(nv);
        std::vector<int> cnt(nv, 0);
        for (size_t i = 0; i < nv; ++i)
            if (!m.vert[i].IsD()) q[i] = FiniteOr(m.vert[i].cQ(), 1.0);
        std::vector<int> ev; // edge endpoints (a,b) of live faces, each face edge once per face
        ev.reserve(m.face.size() * 6);
        for (const FaceType &f : m.face) {
            if (f.IsD()) continue;
            for (int k = 0; k < 3; ++k) {
                const int a = MV::VIndex(m, f.cV(k)), b = MV::VIndex(m, f.cV((k + 1) % 3));
                if (a == b) continue;
                ev.push_back(a);
                ev.push_back(b);
                ++cnt[a];
                ++cnt[b];
            }
        }
        int shown = -1;
        for (int s = 0; s < steps; ++s) {
            if (progress) {
                const int pct = int(int64_t(100) * s / steps);
                if (pct != shown && !progress(shown = pct)) return s;
            }
            // Interior edges are seen from both faces, so the vertex gets weight 2 like each neighbour.
            for (size_t i = 0; i < nv; ++i) sum[i] = 2.0 * q[i];
            for (size_t e = 0; e < ev.size(); e += 2) {
                sum[ev[e]] += q[ev[e + 1]];
                sum[ev[e + 1]] += q[ev[e]];
            }
            for (size_t i = 0; i < nv; ++i)
                if (cnt[i] > 0) q[i] = sum[i] / double(2 + cnt[i]);
        }
        for (size_t i = 0; i < nv; ++i)
            if (!m.vert[i].IsD()) m.vert[i].Q() = ScalarType(q[i]);
        if (progress) progress(100);
        return steps;
    }

    /// Robust map of the vertex quality to [0,1] by EnergyRange (the flat level at
    /// HighPercentile() of all values, the strongest features at LowPercentile() of the non-flat
    /// ones). lowIsFeature: low raw values -> 0; otherwise high raw values -> 0. A field with no
    /// value off the flat level has no feature and becomes 1 everywhere, as do NaN values.
    /// Returns false for such a constant field.
    static bool Normalize(MeshType &m, bool lowIsFeature)
    {
        const double sign = lowIsFeature ? 1.0 : -1.0;
        std::vector<double> vals;
        vals.reserve(m.vert.size());
        for (const VertexType &v : m.vert)
            if (!v.IsD() && std::isfinite(double(v.cQ()))) vals.push_back(sign * double(v.cQ()));
        if (vals.empty()) return false;
        const EnergyRange r = EnergyRange::Of(vals, LowPercentile());
        for (VertexType &v : m.vert)
            if (!v.IsD()) v.Q() = ScalarType(r.Map(sign * double(v.cQ())));
        return !r.constant;
    }

    /// 3D gradient of the piecewise-linear quality inside face f (Sec. 6.2: constant per face).
    /// Zero for degenerate faces; never NaN.
    static CoordType FaceGradient(const FaceType &f)
    {
        if (MV::IsDegenerate(f)) return CoordType(0, 0, 0);
        vcg::Point3d p[3];
        double q[3];
        for (int k = 0; k < 3; ++k) {
            p[k] = vcg::Point3d::Construct(f.cV(k)->cP());
            q[k] = double(f.cV(k)->cQ());
            if (!std::isfinite(q[k])) return CoordType(0, 0, 0);
        }
        const vcg::Point3d cr = (p[1] - p[0]) ^ (p[2] - p[0]);
        const double area2 = cr.Norm();
        const vcg::Point3d N = cr / area2;
        // grad(lambda_i) = N x (edge opposite i) / (2A)
        const vcg::Point3d g =
            ((N ^ (p[2] - p[1])) * q[0] + (N ^ (p[0] - p[2])) * q[1] + (N ^ (p[1] - p[0])) * q[2]) / area2;
        if (!std::isfinite(g[0]) || !std::isfinite(g[1]) || !std::isfinite(g[2])) return CoordType(0, 0, 0);
        return CoordType::Construct(g);
    }

    /// FaceGradient for every face (indexed like m.face; zero for deleted faces).
    static std::vector<CoordType> FaceGradients(const MeshType &m)
    {
        std::vector<CoordType> g(m.face.size(), CoordType(0, 0, 0));
        for (size_t i = 0; i < m.face.size(); ++i)
            if (!m.face[i].IsD()) g[i] = FaceGradient(m.face[i]);
        return g;
    }


private:
    static void NormalVariationImpl(MeshType &m, const std::vector<vcg::Point3f> &fn)
    {
        const size_t nv = m.vert.size();
        std::vector<float> e(nv, 1.0f); // vertices without faces: flat
        for (size_t fi = 0; fi < m.face.size(); ++fi) {
            const FaceType &f = m.face[fi];
            if (f.IsD()) continue;
            const vcg::Point3f &nf = fn[fi];
            if (nf.SquaredNorm() == 0) continue; // degenerate face: no direction to compare with
            for (int k = 0; k < 3; ++k) {
                const VertexType *v = f.cV(k);
                const vcg::Point3f nv3 = vcg::Point3f::Construct(v->cN());
                const float d = nv3 * nf;
                float &ev = e[MV::VIndex(m, v)];
                if (d < ev) ev = d;
            }
        }
        for (size_t i = 0; i < nv; ++i)
            if (!m.vert[i].IsD()) m.vert[i].Q() = ScalarType(std::max(-1.0f, std::min(1.0f, e[i])));
    }

    static void CurvatureNormImpl(MeshType &m, double L)
    {
        const size_t nv = m.vert.size();
        std::vector<double> area(nv, 0.0), angleSum(nv, 0.0);
        std::vector<vcg::Point3d> lap(nv, vcg::Point3d(0, 0, 0));
        std::vector<int64_t> fanA(nv, 0);
        std::vector<uint64_t> fanB(nv, 0);
        for (const FaceType &f : m.face) {
            if (f.IsD()) continue;
            if (f.cV(0) == f.cV(1) || f.cV(1) == f.cV(2) || f.cV(2) == f.cV(0)) continue;
            int id[3];
            vcg::Point3d p[3];
            for (int k = 0; k < 3; ++k) {
                id[k] = MV::VIndex(m, f.cV(k));
                p[k] = vcg::Point3d::Construct(f.cV(k)->cP());
            }
            // Border detection without adjacency: around a closed, consistently oriented fan every
            // neighbour appears once as "next" and once as "prev", so these signed sums vanish.
            for (int k = 0; k < 3; ++k) {
                const int nx = id[(k + 1) % 3], pv = id[(k + 2) % 3];
                fanA[id[k]] += int64_t(nx) - int64_t(pv);
                fanB[id[k]] += Mix(uint64_t(nx)) - Mix(uint64_t(pv));
            }
            const vcg::Point3d cr = (p[1] - p[0]) ^ (p[2] - p[0]);
            const double area2 = cr.Norm();
            double ang[3], cot[3];
            for (int k = 0; k < 3; ++k) {
                const vcg::Point3d a = p[(k + 1) % 3] - p[k], b = p[(k + 2) % 3] - p[k];
                ang[k] = std::atan2((a ^ b).Norm(), a * b); // robust even for slivers
                angleSum[id[k]] += ang[k];
                cot[k] = area2 > 0 ? (a * b) / area2 : 0.0;
            }
            if (MV::IsDegenerate(f)) continue; // angles counted; cotangents/areas would blow up
            // Mixed Voronoi area (Meyer et al., Fig. 4).
            const bool obtuse = ang[0] >= M_PI / 2 || ang[1] >= M_PI / 2 || ang[2] >= M_PI / 2;
            for (int k = 0; k < 3; ++k) {
                const int i1 = (k + 1) % 3, i2 = (k + 2) % 3;
                if (!obtuse)
                    area[id[k]] += ((p[i2] - p[k]).SquaredNorm() * cot[i1] + (p[i1] - p[k]).SquaredNorm() * cot[i2]) / 8.0;
                else
                    area[id[k]] += area2 / 2.0 * (ang[k] >= M_PI / 2 ? 0.5 : 0.25);
                // Cotangent Laplacian: edge (k,i1) is opposite corner i2.
                lap[id[k]] += (p[k] - p[i1]) * cot[i2] + (p[k] - p[i2]) * cot[i1];
            }
        }
        for (size_t i = 0; i < nv; ++i) {
            VertexType &v = m.vert[i];
            if (v.IsD()) continue;
            double c = 0;
            if (area[i] > 0) {
                // Mean curvature from the normal component only: at borders the in-plane part
                // of the one-sided Laplacian is not curvature.
                const vcg::Point3d n = vcg::Point3d::Construct(v.cN());
                const double H = (lap[i] * n) / (4.0 * area[i]);
                const bool border = fanA[i] != 0 || fanB[i] != 0;
                const double K = border ? 0.0 : (2.0 * M_PI - angleSum[i]) / area[i];
                // |k1|+|k2| = 2|H| if k1,k2 have the same sign (K >= 0), else |k1-k2| = 2 sqrt(H^2-K).
                c = 2.0 * std::max(std::fabs(H), std::sqrt(std::max(0.0, H * H - K)));
            }
            const double e = -c * L;
            v.Q() = ScalarType(std::isfinite(e) ? e : 0.0);
        }
    }

    static void QuadricErrorImpl(MeshType &m, const std::vector<vcg::Point3f> &fn, double L)
    {
        (void)fn;
        const size_t nv = m.vert.size();
        typedef vcg::math::Quadric<double> Quadricd;
        Quadricd zero;
        zero.SetZero();
        std::vector<Quadricd> Q(nv, zero);
        std::vector<double> W(nv, 0.0);
        for (const FaceType &f : m.face) {
            if (f.IsD() || MV::IsDegenerate(f)) continue;
            const vcg::Point3d p0 = vcg::Point3d::Construct(f.cV(0)->cP());
            const vcg::Point3d cr = (vcg::Point3d::Construct(f.cV(1)->cP()) - p0) ^
                                    (vcg::Point3d::Construct(f.cV(2)->cP()) - p0);
            const double a = cr.Norm() / 2.0;
            vcg::Plane3d pl;
            pl.SetDirection(cr / (2.0 * a));
            pl.SetOffset(pl.Direction() * p0);
            Quadricd q;
            q.ByPlane(pl);
            q *= a;
            for (int k = 0; k < 3; ++k) {
                const int i = MV::VIndex(m, f.cV(k));
                Q[i] += q;
                W[i] += a;
            }
        }
        std::vector<double> err(nv, 0.0);
        for (const FaceType &f : m.face) {
            if (f.IsD()) continue;
            for (int k = 0; k < 3; ++k) {
                const int a = MV::VIndex(m, f.cV(k)), b = MV::VIndex(m, f.cV((k + 1) % 3));
                if (a == b) continue;
                const vcg::Point3d pa = vcg::Point3d::Construct(f.cV(k)->cP());
                const vcg::Point3d pb = vcg::Point3d::Construct(f.cV((k + 1) % 3)->cP());
                if (W[a] > 0) err[a] = std::max(err[a], Q[a].Apply(pb) / W[a]);
                if (W[b] > 0) err[b] = std::max(err[b], Q[b].Apply(pa) / W[b]);
            }
        }
        const double L2 = L * L;
        for (size_t i = 0; i < nv; ++i) {
            if (m.vert[i].IsD()) continue;
            const double e = -std::max(0.0, err[i]) / L2;
            m.vert[i].Q() = ScalarType(std::isfinite(e) ? e : 0.0);
        }
    }

    /// MeshValidation::MeanEdgeLength, 0 where it has none (Compute says why in its own words).
    static double MeanEdgeOrZero(const MeshType &m)
    {
        try {
            return MV::MeanEdgeLength(m);
        } catch (const SnakeError &) {
            return 0.0;
        }
    }

    static void RequireComponents(MeshType &m)
    {
        MV::RequireSurface(m);
        if (!tri::HasPerVertexQuality(m))
            throw SnakeError("The mesh type has no per-vertex quality to store the feature energy in.");
        if (!tri::HasPerVertexNormal(m))
            throw SnakeError("The mesh type has no per-vertex normal, needed by the feature energy.");
    }

    static uint64_t Mix(uint64_t x)
    {
        x += 0x9e3779b97f4a7c15ULL;
        x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
        x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
        return x ^ (x >> 31);
    }

    template <class T>
    static double FiniteOr(T v, double dflt)
    {
        return std::isfinite(double(v)) ? double(v) : dflt;
    }
};

} // namespace tri
} // namespace vcg

#endif
