#ifndef VCG_EXT_SNAKE_ENERGY_SOURCE_H
#define VCG_EXT_SNAKE_ENERGY_SOURCE_H

// What the snakes of one mesh slither on: a feature energy computed into the vertex quality
// (FeatureEnergy: type, smoothing, crease angle), or the vertex quality as it is (any field
// MeshLab computes), and the SnakeSurface built over it once, on demand. Each setter returns
// whether the energy changed: the snakes on it must then start afresh (EnergyChanged).

#include <cmath>
#include <functional>
#include <future>
#include <memory>
#include <string>
#include <vector>

#include <vcg_ext/energy/crease_energy.h>
#include <vcg_ext/energy/crease_energy_field.h>
#include <vcg_ext/energy/feature_energy.h>
#include <vcg_ext/snake/error.h>
#include <vcg_ext/surface/mesh_validation.h>
#include <vcg_ext/surface/snake_surface.h>

namespace vcg {
namespace tri {

template <class MeshType>
class SnakeEnergySource
{
public:
    typedef SnakeSurface<MeshType> Surface;

    explicit SnakeEnergySource(MeshType &m) : mesh(m) {}
    // the preparation thread refers to the members (it ends with the object: see `preparing`)
    SnakeEnergySource(const SnakeEnergySource &) = delete;
    SnakeEnergySource &operator=(const SnakeEnergySource &) = delete;

    /// Computes the energy with the current settings (if it is not computed yet) and builds the
    /// surface on another thread, so that the first snake does not wait for them (issue 37: on
    /// 1.2M faces about a second, while the user is still placing seeds). Every other member
    /// but the const ones waits for it first; until then SurfacePtr() is empty. Meanwhile
    /// the thread writes the vertex quality and reads the rest of the mesh: the caller changes
    /// neither (the edit tool: MeshLab ends the tool before a filter, and the end waits).
    void PrepareInBackground()
    {
        if (preparing.valid() || (computed && surface)) return;
        preparing = std::async(std::launch::async, [this] {
            if (!computed) FeatureEnergy<MeshType>::Compute(mesh, type, smooth, angle);
            auto s = std::make_shared<Surface>(mesh);
            applyField(*s);
            return s;
        });
    }

    /// Computes the feature energy into the vertex quality (low = feature). Throws on a bad
    /// type or smoothing, or an unusable mesh.
    void Compute(FeatureEnergyType t, int smoothing)
    {
        join();
        checkSettings(t, smoothing);
        FeatureEnergy<MeshType>::Compute(mesh, t, smoothing, angle);
        fromQuality = false;
        type = t;
        smooth = smoothing;
        computed = true;
        if (surface) {
            surface->SetEnergyFromQuality();
            applyField();
        }
    }
    /// Computes the energy with the current settings, if it is not computed yet, while
    /// `adjacency` (the caller's FF/VF build, e.g. MeshLab's updateDataMask: a sort of every
    /// edge) runs: on a large mesh the energy goes to the second core. No energy type reads
    /// the adjacency (they sweep the faces; the crease energy sorts its own edges) and the
    /// adjacency build reads only the faces, so neither writes what the other reads.
    /// Throws what either throws, after both have ended.
    void ComputeBeside(const std::function<void()> &adjacency)
    {
        join();
        if (computed || mesh.fn <= MeshValidation<MeshType>::ConcurrentFaces()) {
            adjacency();
            if (!computed) Compute(type, smooth);
            return;
        }
        std::future<void> energy = std::async(std::launch::async, [this] { Compute(type, smooth); });
        adjacency(); // should it throw, the future's destructor still waits for the energy
        energy.get();
    }
    /// The current vertex quality is the energy (low = feature).
    void UseQuality()
    {
        join();
        fromQuality = true;
        computed = true;
        if (surface) surface->SetEnergyFromQuality();
        applyField();
    }
    /// Dihedral angle (degrees) above which an edge is a crease; recomputes a crease energy.
    bool SetCreaseAngle(double deg)
    {
        join();
        if (!std::isfinite(deg) || deg <= 0 || deg >= 180)
            throw SnakeError("Geometric snake: the crease angle must be between 0 and 180 degrees.");
        const bool changed = deg != angle;
        angle = deg;
        if (!changed || !computed || fromQuality || type != FeatureEnergyType::Crease) return false;
        Compute(type, smooth);
        return true;
    }
    /// The settings used when the energy is computed on demand; recomputes it if it was computed.
    bool SetSettings(FeatureEnergyType t, int smoothing)
    {
        join();
        checkSettings(t, smoothing);
        const bool recompute = computed && (t != type || smoothing != smooth);
        if (recompute) Compute(t, smoothing);
        type = t;
        smooth = smoothing;
        return recompute;
    }
    /// Settings read from a session file: the energy is recomputed only if they differ from
    /// what the quality holds now.
    bool Apply(bool quality, FeatureEnergyType t, int smoothing, double crease)
    {
        join();
        bool changed = false;
        if (quality) {
            if (!fromQuality) UseQuality(), changed = true;
        } else if (!computed || fromQuality || t != type || smoothing != smooth ||
                   (t == FeatureEnergyType::Crease && crease != angle)) {
            angle = crease;
            Compute(t, smoothing);
            changed = true;
        }
        angle = crease;
        return changed;
    }

    /// The shared surface; computes the energy first if that was not done yet.
    const std::shared_ptr<Surface> &EnsureSurface()
    {
        join();
        if (!computed) Compute(type, smooth);
        if (!surface) {
            surface = std::make_shared<Surface>(mesh);
            applyField();
        }
        return surface;
    }
    const std::shared_ptr<Surface> &SurfacePtr() const { return surface; }

    /// Warnings about the energy the snakes read, for the Log: those of the vertex energy,
    /// or, for the crease energy (read at the samples), that it found no crease at all.
    std::vector<std::string> Warnings()
    {
        join();
        Surface &s = *EnsureSurface();
        if (fromQuality || type != FeatureEnergyType::Crease) return s.Warnings();
        const auto *f = dynamic_cast<const CreaseEnergyField<MeshType> *>(&s.EnergyField());
        if (f && f->Creases().CreaseCount() == 0)
            return {"no edge has a dihedral angle above " + std::to_string(int(std::lround(angle))) +
                    " degrees: the crease energy is flat and the snake will not move (lower the crease angle, "
                    "or choose another energy type)."};
        return {};
    }

    /// The length unit of new snakes seeded at `seeds` (spacing, step caps, tolerances), 0 =
    /// the engine's own (from the edges along the seed path). With the crease energy: its basin
    /// width without smoothing at the creases nearest to the seeds (CreaseEnergyField::
    /// LengthUnit; of the whole part without seeds), since on a CAD tessellation the edges are
    /// slivers as long as the part and say nothing about the features; smoothing widens the
    /// basin, never the sampling (the corners of a pocket's rim are cut by about one sample
    /// spacing). Builds the surface if needed.
    double LengthScale(const std::vector<SurfacePoint> &seeds = {})
    {
        if (fromQuality || type != FeatureEnergyType::Crease) return 0;
        const auto *f = dynamic_cast<const CreaseEnergyField<MeshType> *>(&EnsureSurface()->EnergyField());
        return f ? f->LengthUnit(seeds) : 0;
    }
    /// The mean edge length, without building the surface for it.
    double MeanEdge() const
    {
        if (surface) return surface->MeanEdge();
        const double h = MeshValidation<MeshType>::MeanEdgeLength(mesh);
        return (h > 0 && std::isfinite(h)) ? h : 1.0;
    }

    /// The coarse-to-fine pyramid the snakes slither on (SnakeSurface::SetCaptureSmoothing).
    /// None for the part-boundary energy (issue 33): its curvature fit over a few edge lengths
    /// is its capture range already, and the pyramid's smoothing of it lets a loop shrink past
    /// the valley (bench/eval/gs_parts, 220 loops: 20 collapsed with the pyramid, 2 without;
    /// 43 % captured either way).
    static int CaptureSmoothingFor(bool quality, FeatureEnergyType t)
    {
        return !quality && t == FeatureEnergyType::PartBoundary ? 0 : Surface::DefaultCaptureSmoothing();
    }

    bool FromQuality() const { return fromQuality; }
    bool Computed() const { return computed; }
    FeatureEnergyType Type() const { return type; }
    int Smoothing() const { return smooth; }
    double CreaseAngle() const { return angle; }

private:
    MeshType &mesh;
    std::shared_ptr<Surface> surface;
    FeatureEnergyType type = FeatureEnergyType::NormalVariation;
    int smooth = 2;
    double angle = CreaseEnergy<MeshType>::DefaultAngle();
    bool computed = false;
    bool fromQuality = false;
    // PrepareInBackground's thread; last, so that it ends before the members it uses go
    std::future<std::shared_ptr<Surface>> preparing;

    /// Takes the surface PrepareInBackground made (waiting for it); rethrows its error.
    void join()
    {
        if (!preparing.valid()) return;
        std::shared_ptr<Surface> s = preparing.get();
        if (!computed) {
            computed = true;
            fromQuality = false;
        }
        if (!surface) surface = std::move(s);
    }

    static void checkSettings(FeatureEnergyType t, int smoothing)
    {
        if (int(t) < 0 || int(t) >= FeatureEnergyTypeCount()) throw SnakeError("Geometric snake: unknown energy type.");
        if (smoothing < 0 || smoothing > 1000) throw SnakeError("Geometric snake: energy smoothing must be in [0, 1000].");
    }
    /// The crease energy is read by the snakes at each sample (CreaseEnergyField), not
    /// interpolated from the vertex values the quality holds (those are for display).
    void applyField()
    {
        if (surface) applyField(*surface);
    }
    void applyField(Surface &s) const
    {
        const int capture = CaptureSmoothingFor(fromQuality, type);
        if (s.CaptureSmoothing() != capture) s.SetCaptureSmoothing(capture);
        if (fromQuality || type != FeatureEnergyType::Crease) return;
        s.SetEnergyField(std::make_shared<CreaseEnergyField<MeshType>>(mesh, angle, CreaseEnergyField<MeshType>::Fractions(smooth)));
    }
};

} // namespace tri
} // namespace vcg

#endif
