#ifndef VCG_EXT_SNAKE_MOTION_RULES_H
#define VCG_EXT_SNAKE_MOTION_RULES_H

// What both ways of moving a snake share: SnakeSegmentMotion (the paper's method, in the plane
// of a local embedding, Sec. 5) and SnakeProjectionMotion (the naive one, in space, Sec. 4.2).
// The per-sample step control, the level a sample moves on and its hold at level-0 wells, the
// open ends' conditions, the balloon's pressure, and level 0's slope across the curve measured
// in space.

#include <algorithm>
#include <cmath>
#include <memory>

#include <Eigen/Dense>

#include <vcg_ext/snake/curve.h>
#include <vcg_ext/surface/snake_surface.h>
#include <vcg_ext/surface/surface_point.h>
#include <vcg_ext/surface/surface_projection.h>

namespace vcg {
namespace tri {

template <class MeshType>
class SnakeMotionRules
{
public:
    typedef typename MeshType::FaceType FaceType;
    typedef SnakeSurface<MeshType> Surface;

    explicit SnakeMotionRules(std::shared_ptr<Surface> s) : surf(std::move(s)) {}

    /// Step control (both methods). The energy is piecewise linear, so its force does not
    /// vanish at the bottom of a well and a sample would bounce across it by |f|/gamma: a move
    /// that raised the sample's energy by more than the noise halves its step cap, any other
    /// move grows it back. On level 0 (piecewise linear) any rise is an overshoot. On a smooth
    /// level the noise is a quarter of what the slope predicts for the step (`expected`, slope
    /// times step length; at least 1e-3 of the energy range): smaller rises come from the
    /// spline sliding the sample along the curve or from the curvature of the level, not from
    /// overshooting, and halving on them collapsed the steps on the gentle slopes of the coarse
    /// levels, so that the snake crawled and the coarse-to-fine switch fired far from the feature.
    static void UpdateTrust(double &trust, int level, double eOld, double eNew, double expected)
    {
        const double noise = level == 0 ? 1e-9 : std::max(1e-3, 0.25 * expected);
        trust = eNew > eOld + noise ? std::max(0.01, trust * 0.5) : std::min(1.0, trust * 1.1);
    }

    /// The level a sample moves on: 0 once held at a level-0 well (HoldAtWell), else the snake's.
    static int SampleLevel(const SnakeSample &s, int level) { return s.heldFine ? 0 : level; }

    /// Whether a sample of an open snake that moved from pOld to pNew on a coarse level (by d,
    /// mostly across the curve: nrm is the curve's normal there, tan its tangent) is held on
    /// level 0 from now on. A coarse level merges a feature with a parallel one a few edges away
    /// into one well between them (the chamfer: two creases 3 edges apart); a snake pulled
    /// across the first feature into that well rolls down either side of it at the switch to
    /// level 0 (ends on the second feature, or zigzags between the two). A sample is held where
    /// it crosses, or lands in, a well of level 0 that
    ///  - is feature-like: level-0 energy below kWellEnergy at the lower end of the move;
    ///  - is a well across the curve: kWellProbe length units behind and beyond the move the
    ///    energy is at least kWellDepth higher on both sides;
    ///  - runs along the curve: kWellProbe along the curve from where it lands, the energy stays
    ///    below those rims (a feature crossing the curve rises there);
    ///  - is one the coarse level leads past: its energy still falls beyond the move. Where the
    ///    coarse well and the level-0 well coincide the coarse level does not mislead.
    /// Closed snakes are not held (callers): a loop seeded over an octahedron's corners lies
    /// along its diagonal creases and must slide down them onto the equator on the coarse
    /// levels; holding it there broke capture (0.70-0.88 of the loop captured at offsets 2-6).
    /// A held sample is released when dragged out of the well (level-0 energy above kWellEnergy).
    /// `probe(v, ahead, q)`: the surface point at pNew + v (ahead) or pOld + v; false if unknown.
    template <class Vec, class Probe>
    bool HoldAtWell(bool held, const SurfacePoint &pOld, const SurfacePoint &pNew, const Vec &d, const Vec &nrm,
                    const Vec &tan, int level, const Probe &probe) const
    {
        const double eNew = surf->EnergyAt(0, pNew);
        if (held) return eNew < kWellEnergy;
        const double len = d.norm(), dn = d.dot(nrm);
        if (!(len > 0) || !(std::abs(dn) >= 0.5 * len)) return false;
        const double eMin = std::min(surf->EnergyAt(0, pOld), eNew);
        if (!(eMin < kWellEnergy)) return false;
        const Vec dir = nrm * (dn > 0 ? kWellProbe : -kWellProbe);
        SurfacePoint qBehind, qAhead, qFore, qAft;
        if (!probe(Vec(-dir), false, qBehind) || !probe(dir, true, qAhead)) return false;
        // the coarse level leads beyond the well (it has merged it with another): where it does
        // not, the two agree and the coarse level is not misleading (a loop lying along an
        // octahedron's diagonal crease, sliding down it onto the equator)
        if (!(surf->EnergyAt(level, qAhead) < surf->EnergyAt(level, pNew))) return false;
        const double rim = std::min(surf->EnergyAt(0, qBehind), surf->EnergyAt(0, qAhead));
        if (!(rim > eMin + kWellDepth)) return false;
        // the well runs along the curve: along it, from where the sample lands, the energy
        // stays below the rims across it (a feature crossing the curve rises there)
        const Vec along = tan * kWellProbe;
        if (!probe(along, true, qFore) || !probe(Vec(-along), true, qAft)) return false;
        const double fore = surf->EnergyAt(0, qFore), aft = surf->EnergyAt(0, qAft);
        return std::max(fore, aft) < rim;
    }

    /// On a coarse level an open end moves along the feature force only, not across its
    /// tangent: by symmetry the smoothed energy's gradient is across the feature, while the
    /// tangent, on a seed path that is a staircase of mesh edges, is up to 28 degrees off it
    /// until the curve straightens, and a move of 3 cells across it slid the end 2 cells along
    /// the feature (the chamfer seeded 3 cells off: 0.943 of the span covered). Only on the
    /// smoothed vertex energy (FaceLinear fields): the CAD crease distance's gradient points at
    /// the nearest crease point, which near a rim's end lies along the rim (an open snake on a
    /// pocket rim then covered 85.8 % of its span instead of 96.8 %).
    /// Hence: along g where the coarse gradient g is steep, the move across the end's tangent
    /// (`across`) where it is flat, blended smoothly: g g^T / (|g|^2 + s^2) is smooth in g, the
    /// direction of g alone is not, and near a coarse well's bottom it turns with the rounding of
    /// the mesh (the open snake on icocube at 1e30 ended 2.05e-6 of the size from scale 1, limit
    /// 1e-6; blended with s = kPullSlope, 7.7e-8). Both methods: g is per length unit (the
    /// embedding's plane is in length units; the projection method scales it by the unit). The
    /// projection method moved along g alone until then: at 1e+-30 its open snake on icocube ended
    /// 7.3e-3 / 5.5e-3 of the size from scale 1; blended, 9.5e-4 / 3.3e-4.
    template <class Vec>
    static Vec alongPullBlend(const Vec &d, const Vec &g, const Vec &across)
    {
        const double g2 = g.squaredNorm(), s2 = kPullSlope * kPullSlope;
        return (g.dot(d) / (g2 + s2)) * g + (s2 / (g2 + s2)) * across;
    }
    /// alongPullBlend: the coarse slope (energy per length unit) at which the two directions weigh
    /// the same. 0.01 still flipped a decision at 1e30 (5.5e-3 of the size), 0.05 gave 1.8e-4.
    static constexpr double kPullSlope = 0.2;
    /// The end condition of an open snake: its end samples move only across the curve, so the
    /// span the user seeded stays covered (under tension an end free to slide creeps inwards).
    /// "Across" is measured against the direction over several samples (endTangent), not the
    /// chord to the next one: while the snake still follows its seed path, a staircase of mesh
    /// edges, the first chord can be 45 degrees off the feature, and moving across it slides the
    /// end along the feature.
    template <class Vec>
    static Vec acrossEnd(const Eigen::MatrixXd &X, int j, Vec d)
    {
        Vec t = endTangent<Vec>(X, j);
        if (t.norm() > 0) {
            t.normalize();
            d -= d.dot(t) * t;
        }
        return d;
    }
    /// An open end where the field knows the way straight across its nearest feature (`u`, unit:
    /// SnakeEnergyField::AcrossFeature, the crease energy's perpendicular to the crease) moves
    /// along that way only, so it lands on the feature point nearest to where it was seeded.
    /// Across the curve's own tangent is that way only once the curve follows the feature: a snake
    /// seeded as a chord inside a rim (seeds 3 edges inside a tessellated shaft's top rim) slid its
    /// ends 24 degrees along the rim while the chord bulged out to it (83 % of the span covered).
    template <class Vec>
    static Vec acrossFeatureEnd(const Vec &d, const Vec &u)
    {
        return d.dot(u) * u;
    }
    /// The curve's direction at end sample j: the one-sided second-order difference over the
    /// samples q and 2q in (q = 2), exact on a circle's arc. A chord alone is a secant: on a
    /// curved feature "across" it has a part along the feature, and an end that bounces across
    /// the feature while the samples settle walks along it (the arc shortens or grows).
    template <class Vec>
    static Vec endTangent(const Eigen::MatrixXd &X, int j)
    {
        const int k = int(X.rows());
        if (k < 2) return Vec::Zero();
        const int s = j == 0 ? 1 : -1;
        if (k < 5) return (X.row(j + s) - X.row(j)).transpose(); // too short for more: the neighbour
        const Vec c2 = (X.row(j + 2 * s) - X.row(j)).transpose(), c4 = (X.row(j + 4 * s) - X.row(j)).transpose();
        return 4 * c2 - c4;
    }

    /// The balloon's pressure at p (signed: > 0 outwards), weighted by the precise (level 0)
    /// energy there, as the edge-stopping term of geodesic active contours: full on flat ground
    /// (energy 1), none on a feature (energy 0), so a rim holds a gently inflated snake (a
    /// constant pressure of 0.4 pushed it past the rim). Level 0, not the coarse level the snake
    /// may be on: a coarse level is low over a wide band and the pressure would fade early.
    double balloonPressure(const SnakeParams &params, const SnakeMotionFrame &fr, const SurfacePoint &p) const
    {
        return params.balloon * fr.outside * surf->EnergyAt(0, p);
    }

    /// Level-0 energy at p -/+ r nrm (in space, projected onto the surface).
    bool acrossEnergies(const SurfacePoint &p, const Eigen::Vector3d &nrm, double r, double &lo, double &hi) const
    {
        if (!(r > 0)) return false;
        const vcg::Point3d x = p.Pd(surf->Mesh()), n(nrm[0], nrm[1], nrm[2]);
        lo = surf->EnergyAt(0, SurfaceProjection<MeshType>::Closest(*surf, p.face, x - n * r, 2 * r));
        hi = surf->EnergyAt(0, SurfaceProjection<MeshType>::Closest(*surf, p.face, x + n * r, 2 * r));
        return true;
    }
    /// acrossSlope for the projection method (`unit`: the snake's length unit).
    bool acrossSlope(const SurfacePoint &p, const Eigen::Vector3d &nrm, double unit, double &slope) const
    {
        const double r = kAcrossReach * std::min(faceWidth(p.face, nrm), unit);
        double lo, hi;
        if (!acrossEnergies(p, nrm, r, lo, hi)) return false;
        slope = (hi - lo) / (2 * r);
        return true;
    }

    /// Width of mesh face f in direction d (unit vector, in space): the step cap's size.
    double faceWidth(int f, const Eigen::Vector3d &d) const
    {
        const FaceType &ff = surf->Mesh().face[f];
        double a[3];
        for (int k = 0; k < 3; ++k) a[k] = d[0] * ff.cP(k)[0] + d[1] * ff.cP(k)[1] + d[2] * ff.cP(k)[2];
        return std::max({a[0], a[1], a[2]}) - std::min({a[0], a[1], a[2]});
    }

    /// Half the span, in triangle widths, over which level 0's slope across the curve is
    /// averaged (acrossSlope). On the chamfer test (level 0 alone) 0.5 left turns of 10.5
    /// degrees with the projection method; 0.75 gives 6-8 degrees; 1.0 5-9 degrees, with the
    /// samples farther from the crease (the wider the span, the flatter the well's bottom).
    static constexpr double kAcrossReach = 0.75;
    /// HoldAtWell: a feature-like level-0 well (its energy below this), probed this many length
    /// units across the curve beyond either end of the move, where it must be this much higher.
    static constexpr double kWellEnergy = 0.5, kWellProbe = 1.0, kWellDepth = 0.1;

protected:
    std::shared_ptr<Surface> surf;
};

} // namespace tri
} // namespace vcg

#endif
