#ifndef VCG_EXT_CREASE_ENERGY_FIELD_H
#define VCG_EXT_CREASE_ENERGY_FIELD_H

// How the snakes read the crease energy (energy/crease_energy.h): a SnakeEnergyField of two
// levels, a wide basin to capture the curve and the crease's own narrow one to settle it, and
// the length unit of a snake seeded near creases.

#include <algorithm>
#include <cmath>
#include <vector>

#include <vcg_ext/energy/crease_energy.h>
#include <vcg_ext/energy/energy_field.h>
#include <vcg_ext/snake/error.h>
#include <vcg_ext/surface/surface_point.h>

namespace vcg {
namespace tri {

/// The crease energy as the snakes read it (SnakeEnergyField): evaluated at each sample, not
/// interpolated from vertices. Level 1 (capture) has the local basin width 3 f s, s the feature
/// size of the nearest crease on the sample's side (f = CreaseEnergy::WidthFraction(smoothing)):
/// it reaches across the face the snake was seeded on. Level 0 has the width f s', s' the
/// crease's own scale (its narrower side): on a tessellation's long side slivers beside a
/// narrow shoulder the side's own width made a valley so flat at its bottom that the curve
/// stopped short of the rim (bench/eval/gs_creases). The snakes first slither on the wide
/// basins, then settle in the narrow ones.
template <class MeshType>
class CreaseEnergyField : public SnakeEnergyField<MeshType>
{
public:
    typedef CreaseEnergy<MeshType> Crease;
    /// Width fractions of the levels for `steps` smoothing steps.
    static std::vector<double> Fractions(int steps)
    {
        const double f = Crease::WidthFraction(steps);
        return {f, CaptureFactor() * f};
    }
    static double CaptureFactor() { return 3.0; }

    CreaseEnergyField(const MeshType &m, double angleDeg, const std::vector<double> &levelFractions) : fractions(levelFractions)
    {
        if (fractions.empty()) throw SnakeError("The crease energy needs at least one basin width.");
        for (double f : fractions)
            if (!std::isfinite(f) || f <= 0) throw SnakeError("The crease energy needs a positive basin width.");
        crease.Build(m, angleDeg);
        crease.Collect(Crease::ReachInWidths() * *std::max_element(fractions.begin(), fractions.end()) * crease.MaxFeatureSize());
    }
    int Levels() const override { return int(fractions.size()); }
    double Value(int level, const SurfacePoint &p) const override { return crease.LocalValue(p, fraction(level), scale(level)); }
    vcg::Point3d Gradient(int level, const SurfacePoint &p) const override
    {
        return crease.LocalGradient(p, fraction(level), scale(level));
    }
    bool AcrossFeature(int /*level*/, const SurfacePoint &p, vcg::Point3d &dir) const override
    {
        return crease.AcrossDirection(p, dir);
    }
    const Crease &Creases() const { return crease; }

    /// The length unit of a snake seeded at `pts` (spacing, step caps): the basin width without
    /// smoothing of the nearest creases' own scale (CreaseSize), the median over the points; of
    /// the whole part's creases without points. Smoothing widens the basins, never the sampling.
    double LengthUnit(const std::vector<SurfacePoint> &pts = {}) const
    {
        std::vector<double> u;
        for (const SurfacePoint &p : pts) u.push_back(crease.CreaseSizeAt(p));
        if (u.empty()) return Crease::WidthFraction(0) * crease.MedianCreaseSize();
        std::nth_element(u.begin(), u.begin() + u.size() / 2, u.end());
        return Crease::WidthFraction(0) * u[u.size() / 2];
    }

private:
    Crease crease;
    std::vector<double> fractions;
    double fraction(int level) const { return fractions[std::max(0, std::min(level, int(fractions.size()) - 1))]; }
    typename Crease::Scale scale(int level) const { return level <= 0 ? Crease::Scale::Crease : Crease::Scale::Side; }
};

} // namespace tri
} // namespace vcg

#endif
