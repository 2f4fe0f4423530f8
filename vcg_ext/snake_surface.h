#ifndef VCG_EXT_SNAKE_SURFACE_H
#define VCG_EXT_SNAKE_SURFACE_H

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/update/topology.h>
#include <vcg/complex/algorithms/update/normal.h>

#include <vcg_ext/mesh_validation.h>
#include <vcg_ext/snake_error.h>
#include <vcg_ext/surface_point.h>

namespace vcg {
namespace tri {

/// The mesh as the snakes see it, prepared once and shared by every snake on it:
/// FF/VF adjacency (vcglib), the mean edge length h that makes every snake parameter
/// scale-free, the feature energy E in [0,1] (low = feature) read from per-vertex quality,
/// and O(1)-clearable scratch marks so that a snake operation never touches the whole mesh.
template <class MeshType>
class SnakeSurface
{
public:
    typedef typename MeshType::FaceType FaceType;
    typedef typename MeshType::VertexType VertexType;

    /// Checks the mesh and builds adjacency. FF and VF adjacency must be available
    /// (for MeshLab's CMeshO: enabled with updateDataMask before).
    explicit SnakeSurface(MeshType &m, int captureSmoothing = DefaultCaptureSmoothing()) : mesh(m)
    {
        MeshValidation<MeshType>::RequireSurface(m);
        MeshValidation<MeshType>::RequireAdjacencySafe(m);
        if (!tri::HasFFAdjacency(m) || !tri::HasVFAdjacency(m))
            throw SnakeError("Geometric snake: the mesh needs face-face and vertex-face adjacency enabled.");
        tri::UpdateTopology<MeshType>::FaceFace(m);
        tri::UpdateTopology<MeshType>::VertexFace(m);
        tri::UpdateNormal<MeshType>::PerFaceNormalized(m);
        meanEdge = MeshValidation<MeshType>::MeanEdgeLength(m);
        faceCount = int(m.face.size());
        vertCount = int(m.vert.size());
        faceStamp.assign(m.face.size(), 0);
        faceSlot.assign(m.face.size(), -1);
        vertStamp.assign(m.vert.size(), 0);
        vertSlot.assign(m.vert.size(), -1);
        SetEnergyFromQuality();
        SetCaptureSmoothing(captureSmoothing);
    }
    static int DefaultCaptureSmoothing() { return 8; }

    /// Coarse-to-fine capture (beyond the paper): besides the energy E read from quality
    /// (level 0, precise), level 1 is E smoothed `steps` more rounds (Sec. 6.3) and
    /// renormalized. Snakes first slither on level 1, whose wide basins capture features a
    /// few edge lengths away, then settle on level 0, whose narrow wells localize them.
    /// 0 steps: one level only. O(faces * steps), once.
    void SetCaptureSmoothing(int steps)
    {
        if (steps < 0 || steps > 10000) throw SnakeError("Geometric snake: capture smoothing must be in [0, 10000].");
        captureSteps = steps;
        coarse.clear();
        if (steps == 0) return;
        coarse = energy;
        std::vector<double> sum(coarse.size());
        std::vector<int> cnt(coarse.size());
        for (int it = 0; it < steps; ++it) {
            std::fill(sum.begin(), sum.end(), 0.0);
            std::fill(cnt.begin(), cnt.end(), 0);
            for (const auto &f : mesh.face) {
                if (f.IsD()) continue;
                for (int k = 0; k < 3; ++k) { // each edge seen from both faces: symmetric weights
                    int a = Idx(f.cV(k)), b = Idx(f.cV((k + 1) % 3));
                    sum[a] += coarse[b]; ++cnt[a];
                    sum[b] += coarse[a]; ++cnt[b];
                }
            }
            for (size_t v = 0; v < coarse.size(); ++v)
                if (cnt[v] > 0) coarse[v] = float(0.5 * coarse[v] + 0.5 * sum[v] / cnt[v]);
        }
        float lo = 1, hi = 0;
        for (size_t v = 0; v < coarse.size(); ++v)
            if (!mesh.vert[v].IsD()) { lo = std::min(lo, coarse[v]); hi = std::max(hi, coarse[v]); }
        if (hi - lo > 1e-6f)
            for (auto &e : coarse) e = std::min(1.0f, std::max(0.0f, (e - lo) / (hi - lo)));
    }
    int CaptureSmoothing() const { return captureSteps; }
    int Levels() const { return coarse.empty() ? 1 : 2; }
    /// Energy of level `level` (0 precise, 1 coarse) at vertex v.
    float EnergyAt(int level, int v) const { return (level > 0 && !coarse.empty()) ? coarse[v] : energy[v]; }

    MeshType &Mesh() { return mesh; }
    const MeshType &Mesh() const { return mesh; }
    double MeanEdge() const { return meanEdge; }
    const std::vector<float> &Energy() const { return energy; }
    float EnergyAt(int v) const { return energy[v]; }
    /// Warnings about the energy (constant field, NaN values), for the Log.
    const std::vector<std::string> &Warnings() const { return warnings; }

    /// True while the mesh still has the element counts the snakes were built on.
    bool MatchesMesh() const { return int(mesh.face.size()) == faceCount && int(mesh.vert.size()) == vertCount; }

    /// Copies per-vertex quality into the snake energy. Any quality field can drive a snake:
    /// it is mapped robustly (0.1 / 99.9 percentiles) to [0,1] with low values = feature.
    /// Non-finite values count as flat (1). A constant field gives no force (warned).
    void SetEnergyFromQuality()
    {
        warnings.clear();
        energy.assign(mesh.vert.size(), 1.0f);
        std::vector<float> finite;
        finite.reserve(mesh.vert.size());
        int bad = 0;
        for (size_t i = 0; i < mesh.vert.size(); ++i) {
            if (mesh.vert[i].IsD()) continue;
            float q = mesh.vert[i].cQ();
            if (std::isfinite(q)) finite.push_back(q);
            else ++bad;
        }
        if (bad > 0)
            warnings.push_back(std::to_string(bad) + " vertices have a non-finite quality; treated as flat.");
        if (finite.empty()) {
            warnings.push_back("No usable vertex quality: the snake feels no feature force.");
            return;
        }
        auto pct = [&](double p) {
            size_t k = std::min(finite.size() - 1, size_t(p * double(finite.size() - 1) + 0.5));
            std::nth_element(finite.begin(), finite.begin() + k, finite.end());
            return double(finite[k]);
        };
        double lo = pct(0.001), hi = pct(0.999);
        if (!(hi - lo > 1e-12 * std::max(1.0, std::abs(hi)))) {
            warnings.push_back("Vertex quality is constant: the snake feels no feature force.");
            return;
        }
        for (size_t i = 0; i < mesh.vert.size(); ++i) {
            float q = mesh.vert[i].cQ();
            if (!std::isfinite(q)) continue;
            energy[i] = float(std::min(1.0, std::max(0.0, (double(q) - lo) / (hi - lo))));
        }
        if (captureSteps > 0) SetCaptureSmoothing(captureSteps);
    }

    /// Energy at a surface point: linear inside the face (Sec. 6.1).
    double EnergyAt(int level, const SurfacePoint &p) const
    {
        const FaceType &f = mesh.face[p.face];
        return p.bary[0] * EnergyAt(level, Idx(f.cV(0))) + p.bary[1] * EnergyAt(level, Idx(f.cV(1))) +
               p.bary[2] * EnergyAt(level, Idx(f.cV(2)));
    }

    int Idx(const VertexType *v) const { return int(v - &mesh.vert[0]); }
    int Idx(const FaceType *f) const { return int(f - &mesh.face[0]); }
    bool FaceUsable(int f) const { return f >= 0 && f < int(mesh.face.size()) && !mesh.face[f].IsD(); }

    /// Scratch marks (one generation counter, so clearing is O(1)): used by local region
    /// building so that the cost of an operation never grows with the mesh.
    int NewGeneration()
    {
        if (++generation == 0x7fffffff) {
            std::fill(faceStamp.begin(), faceStamp.end(), 0);
            std::fill(vertStamp.begin(), vertStamp.end(), 0);
            generation = 1;
        }
        return generation;
    }
    std::vector<int> faceStamp, faceSlot, vertStamp, vertSlot;

private:
    MeshType &mesh;
    double meanEdge = 1;
    int faceCount = 0, vertCount = 0;
    int generation = 0;
    int captureSteps = 0;
    std::vector<float> energy, coarse;
    std::vector<std::string> warnings;
};

} // namespace tri
} // namespace vcg

#endif
