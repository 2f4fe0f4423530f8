#ifndef VCG_EXT_SNAKE_CREASE_NORMALS_H
#define VCG_EXT_SNAKE_CREASE_NORMALS_H

// The face normals the valley loop's crease term reads (valley_loop.h, sessions 31-32): on a
// noisy surface, feature-preserving filtered normals, so that noise on a flank is smoothed but
// a crease sharper than the threshold is not averaged across. The filter is vcglib's
// Smooth::FaceNormalAngleThreshold rule (each normal replaced by the sum of its vertex-adjacent
// faces' normals within the threshold angle, weighed (cos - threshold cos)^2), run over a set
// of faces of a const mesh so that its cost follows the band, and gated by the surface's noise
// (SurfaceNoise): a clean mesh reads its raw normals. docs/method.md, "Session 31: ..." and
// "Session 32: the crease filter gated by the surface's noise".

#include <algorithm>
#include <cmath>
#include <functional>
#include <unordered_map>
#include <vector>

#include <vcg/complex/complex.h>

#include <vcg_ext/snake/part_salience.h>
#include <vcg_ext/surface/surface_noise.h>

namespace vcg {
namespace tri {

template <class MeshType>
class CreaseNormals
{
public:
    typedef typename MeshType::FaceType FaceType;

    struct Param
    {
        /// Passes of the filter over the band's faces; the edge's angle and its sign
        /// ((n1 - n0) . (b1 - b0) < 0) are read from the filtered normals. 0: the raw normals,
        /// as before session 31. On by default since session 32, gated by noiseMin (8 passes
        /// with the relative threshold below; on the noisy variant 3, 5, 8, 12 passes: 128,
        /// 144, 150, 143).
        int iterations = 8;
        /// The threshold angle's cosine (without `relative`).
        double cos = 0.866;
        /// With the filter on: only the sign is read from the filtered normals, the angle is
        /// the edge's raw one-ring one (as concavityRings gates it with area-averaged normals).
        /// (Named `gate` until session 33; the gate by the surface's noise is noiseMin.)
        bool signOnly = false;
        /// > 0: the threshold angle is this factor times the median angle between the filtered
        /// faces' vertex-adjacent pairs (raw normals; at most 90 degrees) instead of acos(cos),
        /// so that a noisy surface gets a wider threshold than a clean one's shallow crease
        /// (session 31). 0: the fixed cos.
        double relative = 2;
        /// With relative: the median over the whole mesh (MedianAngle: its faces sampled evenly,
        /// at most 2000, each with its vertex-adjacent faces) instead of the filtered set, so
        /// that the band and a loop's own faces (CostParts) get the same threshold.
        bool relativeWhole = true;
        /// With relative: the threshold angle is at least this (radians), so that a clean mesh
        /// keeps a fixed one and only a noisier one gets a wider threshold. 0: none.
        double relativeMin = 0;
        /// With relative and relativeWhole, > 0: the passes are the mesh's median angle over
        /// this (radians), at least 1 and at most `iterations`: a rougher surface is filtered
        /// further. 0: the count.
        double passAngle = 0;
        /// > 0: the filter runs only where the mesh is noisy (sessions 32-33): when
        /// SurfaceNoise::Level(m), the rms of the surface's noise along the normal in units of
        /// the local edge length (the residual of a quadric fit less the shape's part, which
        /// grows with the fit's radius), is below this, the crease term reads the raw normals
        /// (no pass), so a clean mesh's rows are those without the filter. 0: no gate. 0.06 h is
        /// about the rms of uniform noise +-0.1 h (0.058 h). Measured: the 9 benchmark meshes
        /// 0-0.041 (the armadillo, a scan, highest), refined / graded <= 0.034, the CAD-like
        /// <= 0.003, the real scans <= 0.047 (armadillo.off); uniform noise +-0.1 h 0.042-0.070,
        /// +-0.2 h 0.089-0.119, +-0.3 h 0.139-0.173 (docs/method.md, "Session 33: ..."). On
        /// bench/eval/gs_parts (--energy part --rings 2,3, success_h0): the 9 meshes 168, noise
        /// 150, refine 154, graded 167, every row as with session 32's gate (0.085 over the
        /// two-ring residual); CAD-like 20/24 (session 32: 21, its bearings filtered as noisy).
        double noiseMin = 0.06;
        /// The mesh's measures, taken once where a caller prices many sets of faces on one
        /// mesh (Measured): SurfaceNoise::Level and MedianAngle. A host takes them once per
        /// mesh (PartBoundaryEnd::Measured: SnakeSession::RunEndParam, gs_parts; session 33),
        /// PartBoundaryEnd::FinishRun those it was not given. < 0: measured at each Filtered
        /// call (a lone call, e.g. a diagnostic's CostParts). They belong to the mesh they
        /// were measured on.
        double noiseLevel = -1;
        double medianAngle = -1;
    };

    /// Unit face normals by face; empty: the faces' own (the filter off or gated).
    typedef std::unordered_map<const FaceType *, vcg::Point3d> Normals;

    /// par with the mesh's measures that Filtered reads filled in (those still < 0): the noise
    /// level when the filter is on and gated, the median angle when it runs and needs it.
    static Param Measured(const MeshType &m, Param par)
    {
        if (par.iterations <= 0) return par;
        if (par.noiseMin > 0 && par.noiseLevel < 0) par.noiseLevel = SurfaceNoise<MeshType>::Level(m);
        if (par.noiseMin > 0 && par.noiseLevel < par.noiseMin) return par;
        if (par.relative > 0 && par.relativeWhole && par.medianAngle < 0) par.medianAngle = MedianAngle(m);
        return par;
    }

    /// The median angle between vertex-adjacent faces' raw normals over the mesh's faces
    /// sampled evenly (at most 2000, each with its vertex-adjacent faces); -1 when there is no
    /// such pair.
    static double MedianAngle(const MeshType &m)
    {
        std::vector<double> ang;
        const size_t step = std::max<size_t>(1, m.face.size() / 2000);
        for (size_t i = 0; i < m.face.size(); i += step) {
            const FaceType &f = m.face[i];
            if (f.IsD()) continue;
            const vcg::Point3d nf = Unit(f);
            Around(m, &f, [&](const FaceType *h) {
                if (h != &f) ang.push_back(std::acos(std::max(-1.0, std::min(1.0, nf * Unit(*h)))));
            });
        }
        return Median(ang);
    }

    /// The normals of `faces` after par.iterations passes of the thresholded filter (vcglib's
    /// Smooth::FaceNormalAngleThreshold, which writes the normals of the whole mesh: here the
    /// mesh is const and the cost must follow the band). The passes run over the faces within
    /// as many rings of `faces` (vertex-adjacent), so a face of `faces` gets the value a pass
    /// over the whole mesh would give it, whatever set it comes with. Empty when the filter is
    /// off or the surface's noise is below par.noiseMin.
    static Normals Filtered(const MeshType &m, const std::vector<const FaceType *> &faces, const Param &par)
    {
        Normals out;
        int iters = par.iterations;
        if (iters <= 0 || faces.empty()) return out;
        if (par.noiseMin > 0 && (par.noiseLevel >= 0 ? par.noiseLevel : SurfaceNoise<MeshType>::Level(m)) < par.noiseMin)
            return out;
        double median = -1; // for par.relative
        if (par.relative > 0 && par.relativeWhole) {
            median = par.medianAngle >= 0 ? par.medianAngle : MedianAngle(m);
            if (median >= 0 && par.passAngle > 0) iters = std::max(1, std::min(iters, int(median / par.passAngle)));
        }
        std::unordered_map<const FaceType *, int> id;
        std::vector<const FaceType *> all, front;
        for (const FaceType *f : faces)
            if (id.emplace(f, int(all.size())).second) all.push_back(f), front.push_back(f);
        for (int r = 0; r < iters; ++r) {
            std::vector<const FaceType *> next;
            for (const FaceType *g : front)
                Around(m, g, [&](const FaceType *h) {
                    if (id.emplace(h, int(all.size())).second) all.push_back(h), next.push_back(h);
                });
            front.swap(next);
        }
        const int n = int(all.size());
        std::vector<std::vector<int>> nb(n);
        std::vector<vcg::Point3d> nr(n), tmp(n);
        for (int i = 0; i < n; ++i) {
            Around(m, all[i], [&](const FaceType *h) {
                const auto it = id.find(h);
                if (it != id.end()) nb[i].push_back(it->second);
            });
            std::sort(nb[i].begin(), nb[i].end());
            nb[i].erase(std::unique(nb[i].begin(), nb[i].end()), nb[i].end());
            nr[i] = vcg::Point3d::Construct(vcg::TriangleNormal(*all[i]));
            if (nr[i].Norm() > 0) nr[i].Normalize();
        }
        double t = par.cos;
        if (par.relative > 0) {
            if (!par.relativeWhole) {
                std::vector<double> ang;
                for (int i = 0; i < n; ++i)
                    for (int j : nb[i])
                        if (j > i) ang.push_back(std::acos(std::max(-1.0, std::min(1.0, nr[i] * nr[j]))));
                median = Median(ang);
            }
            if (median >= 0) t = std::cos(std::min(0.5 * M_PI, std::max(par.relativeMin, par.relative * median)));
        }
        for (int it = 0; it < iters; ++it) {
            for (int i = 0; i < n; ++i) {
                vcg::Point3d s(0, 0, 0);
                for (int j : nb[i]) {
                    const double c = std::max(1e-4, std::min(1.0, nr[j] * nr[i]));
                    if (c >= t) s += nr[j] * ((c - t) * (c - t));
                }
                tmp[i] = s.Norm() > 0 ? s / s.Norm() : nr[i];
            }
            nr.swap(tmp);
        }
        for (const FaceType *f : faces) out[f] = nr[id[f]];
        return out;
    }

private:
    /// fn(h) for the faces sharing a vertex with g (g itself among them, once per vertex).
    static void Around(const MeshType &m, const FaceType *g, const std::function<void(const FaceType *)> &fn)
    {
        for (int k = 0; k < 3; ++k)
            PartSalience<MeshType>::ForFaces(m, int(g->cV(k) - &m.vert[0]), [&](const FaceType *h, int) { fn(h); });
    }

    static vcg::Point3d Unit(const FaceType &f)
    {
        vcg::Point3d q = vcg::Point3d::Construct(vcg::TriangleNormal(f));
        return q.Norm() > 0 ? q / q.Norm() : q;
    }

    /// The median (the upper one of an even count), -1 when empty.
    static double Median(std::vector<double> &v)
    {
        if (v.empty()) return -1;
        std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
        return v[v.size() / 2];
    }
};

} // namespace tri
} // namespace vcg

#endif
