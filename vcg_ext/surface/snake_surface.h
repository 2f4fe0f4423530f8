#ifndef VCG_EXT_SNAKE_SURFACE_H
#define VCG_EXT_SNAKE_SURFACE_H

#include <algorithm>
#include <cmath>
#include <future>
#include <memory>
#include <string>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/update/topology.h>
#include <vcg/complex/algorithms/update/normal.h>

#include <vcg_ext/energy/energy_field.h>
#include <vcg_ext/energy/energy_range.h>
#include <vcg_ext/snake/error.h>
#include <vcg_ext/surface/mesh_validation.h>
#include <vcg_ext/surface/surface_point.h>

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
        // The caller (MeshLab, the CLI) has usually just built the adjacency: FF is checked in
        // one linear pass instead of rebuilt (a sort of every edge), on the second core of a
        // large mesh, as it only reads the faces. VF is rebuilt meanwhile: that is a linear pass
        // too, and quicker than following its lists to check them (0.1 s against 0.25 s on 1.2M
        // faces). The face normals are written in the same time; FF is rebuilt after, if need be.
        std::future<bool> ffCurrent =
            std::async(m.fn > MeshValidation<MeshType>::ConcurrentFaces() ? std::launch::async : std::launch::deferred,
                       [&m] { return FaceFaceCurrent(m); });
        tri::UpdateTopology<MeshType>::VertexFace(m);
        tri::UpdateNormal<MeshType>::PerFaceNormalized(m);
        meanEdge = MeshValidation<MeshType>::MeanEdgeLength(m);
        if (!ffCurrent.get()) tri::UpdateTopology<MeshType>::FaceFace(m);
        faceCount = int(m.face.size());
        vertCount = int(m.vert.size());
        faceStamp.assign(m.face.size(), 0);
        faceSlot.assign(m.face.size(), -1);
        vertStamp.assign(m.vert.size(), 0);
        vertSlot.assign(m.vert.size(), -1);
        vertMark.assign(m.vert.size(), 0);
        vertDist.assign(m.vert.size(), 0.0);
        vertSrc.assign(m.vert.size(), 0);
        floodStamp.assign(m.face.size(), 0);
        if (captureSmoothing < 0 || captureSmoothing > 10000)
            throw SnakeError("Geometric snake: capture smoothing must be in [0, 10000].");
        captureSteps = captureSmoothing;
        SetEnergyFromQuality();
    }
    static int DefaultCaptureSmoothing() { return 8; }

    /// True when every live face's FF adjacency is what UpdateTopology::FaceFace would build
    /// on a mesh whose edges are manifold: each neighbour is live, shares the edge and points back
    /// (a border edge points to the face itself). Anything else (stale, missing, non-manifold) is false.
    static bool FaceFaceCurrent(const MeshType &m)
    {
        for (const FaceType &f : m.face) {
            if (f.IsD()) continue;
            for (int k = 0; k < 3; ++k) {
                const FaceType *g = f.cFFp(k);
                if (g == nullptr) return false;
                const int j = f.cFFi(k);
                if (j < 0 || j > 2) return false;
                if (g == &f) {
                    if (j != k) return false;
                    continue;
                }
                if (g < &m.face[0] || g > &m.face.back() || g->IsD() || g->cFFp(j) != &f) return false;
                const bool same = g->cV(j) == f.cV(k) && g->cV((j + 1) % 3) == f.cV((k + 1) % 3);
                const bool flip = g->cV(j) == f.cV((k + 1) % 3) && g->cV((j + 1) % 3) == f.cV(k);
                if (!same && !flip) return false;
            }
        }
        return true;
    }
    /// Coarse-to-fine capture (beyond the paper): besides the energy E read from quality
    /// (level 0, precise), a pyramid of smoothings of E (Sec. 6.3, by distance: see
    /// VertexEnergyField) whose wells reach `steps` mean edge lengths on the coarsest level,
    /// half that on the next, ... down to about 2 (at most 4 coarse levels). Snakes first
    /// slither on the coarsest level, whose wide basins capture features several edge lengths
    /// away, and step down a level each time they sit in its wells, ending on level 0, whose
    /// narrow wells localize the feature. 0: one level only. Replaces a field set by SetEnergyField.
    void SetCaptureSmoothing(int steps)
    {
        if (steps < 0 || steps > 10000) throw SnakeError("Geometric snake: capture smoothing must be in [0, 10000].");
        captureSteps = steps;
        std::vector<double> reach;
        for (double r = steps; r >= 1.5 && reach.size() < 4; r /= 2) reach.insert(reach.begin(), r * meanEdge);
        field = std::make_shared<VertexEnergyField<MeshType>>(mesh, energy, reach);
    }
    int CaptureSmoothing() const { return captureSteps; }

    /// The energy the snakes read (value and gradient at a surface point, per level). Any
    /// SnakeEnergyField can replace the vertex energy; call the snakes' EnergyChanged() after.
    void SetEnergyField(std::shared_ptr<const SnakeEnergyField<MeshType>> f)
    {
        if (!f || f->Levels() < 1) throw SnakeError("Geometric snake: an energy field needs at least one level.");
        field = std::move(f);
    }
    const SnakeEnergyField<MeshType> &EnergyField() const { return *field; }
    int Levels() const { return field->Levels(); }
    /// Energy on `level` (0 precise, higher = smoother) at a surface point.
    double EnergyAt(int level, const SurfacePoint &p) const { return field->Value(level, p); }
    /// Its gradient: a vector in space, tangent to p's face, energy per unit length.
    vcg::Point3d EnergyGradient(int level, const SurfacePoint &p) const { return field->Gradient(level, p); }

    MeshType &Mesh() { return mesh; }
    const MeshType &Mesh() const { return mesh; }
    double MeanEdge() const { return meanEdge; }
    /// Face f's normal (not normalized), in double: in float the cross product of a tiny mesh's
    /// edges underflows (about 1e-62 at 1e-30) and a huge one's overflows (2^200 at 2^100).
    vcg::Point3d FaceNormal(int f) const
    {
        const FaceType &ff = Mesh().face[f];
        const vcg::Point3d a = vcg::Point3d::Construct(ff.cP(0));
        return (vcg::Point3d::Construct(ff.cP(1)) - a) ^ (vcg::Point3d::Construct(ff.cP(2)) - a);
    }
    /// The vertex energy read from quality, in [0,1] (level 0 of the default field).
    const std::vector<float> &Energy() const { return energy; }
    /// Warnings about the energy (constant field, NaN values), for the Log.
    const std::vector<std::string> &Warnings() const { return warnings; }

    /// True while the mesh still has the element counts the snakes were built on.
    bool MatchesMesh() const { return int(mesh.face.size()) == faceCount && int(mesh.vert.size()) == vertCount; }

    /// Copies per-vertex quality into the snake energy. Any quality field can drive a snake:
    /// it is mapped robustly (EnergyRange, 0.1 % tails) to [0,1] with low values = feature.
    /// Non-finite values count as flat (1). A constant field gives no force (warned).
    void SetEnergyFromQuality()
    {
        readQuality();
        SetCaptureSmoothing(captureSteps);
    }

    int Idx(const VertexType *v) const { return int(v - &mesh.vert[0]); }
    int Idx(const FaceType *f) const { return int(f - &mesh.face[0]); }
    bool FaceUsable(int f) const { return f >= 0 && f < int(mesh.face.size()) && !mesh.face[f].IsD(); }

    // ----- points at mesh vertices and on mesh edges (VF adjacency)
    /// Vertex v as a surface point: a corner of one of its faces.
    SurfacePoint VertexPoint(int v) const
    {
        vcg::face::VFIterator<FaceType> vfi(const_cast<VertexType *>(&mesh.vert[v]));
        if (vfi.End()) throw SnakeError("Geometric snake: seed vertex " + std::to_string(v) + " belongs to no face.");
        return SurfacePoint::AtCorner(Idx(vfi.F()), vfi.I());
    }
    /// The faces holding mesh edge ab (two inside, one on a border).
    std::vector<int> EdgeFaces(int a, int b) const
    {
        std::vector<int> out;
        for (vcg::face::VFIterator<FaceType> vfi(const_cast<VertexType *>(&mesh.vert[a])); !vfi.End(); ++vfi)
            for (int k = 0; k < 3; ++k)
                if (vfi.F()->V(k) == &mesh.vert[b]) out.push_back(Idx(vfi.F()));
        return out;
    }
    /// The point (1-t) a + t b on mesh edge ab, in the first face holding that edge; face -1
    /// if there is no such edge.
    SurfacePoint PointOnEdge(int a, int b, double t) const
    {
        for (vcg::face::VFIterator<FaceType> vfi(const_cast<VertexType *>(&mesh.vert[a])); !vfi.End(); ++vfi)
            for (int k = 0; k < 3; ++k)
                if (vfi.F()->V(k) == &mesh.vert[b]) {
                    vcg::Point3d bary(0, 0, 0);
                    bary[vfi.I()] = 1 - t;
                    bary[k] = t;
                    return SurfacePoint(Idx(vfi.F()), bary);
                }
        return SurfacePoint();
    }
    /// A face holding both surface points (each may lie on an edge or at a vertex), or -1.
    int CommonFace(const SurfacePoint &a, const SurfacePoint &b) const
    {
        SurfacePoint tmp;
        for (int f : {a.face, b.face})
            if (a.InFace(mesh, f, tmp) && b.InFace(mesh, f, tmp)) return f;
        for (int k = 0; k < 3; ++k) {
            if (!(a.bary[k] > 1e-12)) continue;
            for (vcg::face::VFIterator<FaceType> vfi(const_cast<FaceType *>(&mesh.face[a.face])->V(k)); !vfi.End(); ++vfi) {
                const int f = Idx(vfi.F());
                if (!vfi.F()->IsD() && a.InFace(mesh, f, tmp) && b.InFace(mesh, f, tmp)) return f;
            }
        }
        return -1;
    }

    /// Scratch marks (one generation counter, so clearing is O(1)): used by local region
    /// building so that the cost of an operation never grows with the mesh.
    int NewGeneration()
    {
        if (++generation == 0x7fffffff) {
            std::fill(faceStamp.begin(), faceStamp.end(), 0);
            std::fill(vertStamp.begin(), vertStamp.end(), 0);
            std::fill(vertMark.begin(), vertMark.end(), 0);
            generation = 1;
        }
        return generation;
    }
    std::vector<int> faceStamp, faceSlot, vertStamp, vertSlot;
    /// Distances from a region's core (LocalRegion's metric margin), valid where vertMark is
    /// the current generation; the heap is reused so that growing a region does not allocate.
    std::vector<int> vertMark, vertSrc;
    std::vector<double> vertDist;
    std::vector<std::pair<double, int>> heapScratch;
    /// Marks and queue of SurfaceProjection's flood, apart from the region's marks (a kept
    /// region's LocalFace reads faceStamp while projections run). Scratch, hence mutable.
    int NewFloodGeneration() const
    {
        if (++floodGeneration == 0x7fffffff) {
            std::fill(floodStamp.begin(), floodStamp.end(), 0);
            floodGeneration = 1;
        }
        return floodGeneration;
    }
    mutable std::vector<int> floodStamp, floodTodo;

private:
    MeshType &mesh;
    double meanEdge = 1;
    int faceCount = 0, vertCount = 0;
    int generation = 0;
    mutable int floodGeneration = 0;
    int captureSteps = 0;
    std::vector<float> energy;
    std::shared_ptr<const SnakeEnergyField<MeshType>> field;
    std::vector<std::string> warnings;

    /// Quality -> energy in [0,1] and warnings (see SetEnergyFromQuality).
    void readQuality()
    {
        warnings.clear();
        energy.assign(mesh.vert.size(), 1.0f);
        std::vector<double> finite;
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
        const EnergyRange range = EnergyRange::Of(finite, 0.001);
        if (range.constant) {
            warnings.push_back("Vertex quality is constant: the snake feels no feature force.");
            return;
        }
        for (size_t i = 0; i < mesh.vert.size(); ++i)
            if (!mesh.vert[i].IsD()) energy[i] = float(range.Map(double(mesh.vert[i].cQ())));
    }
};

} // namespace tri
} // namespace vcg

#endif
