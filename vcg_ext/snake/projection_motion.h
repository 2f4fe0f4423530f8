#ifndef VCG_EXT_SNAKE_PROJECTION_MOTION_H
#define VCG_EXT_SNAKE_PROJECTION_MOTION_H

// The naive method of Sec. 4.2, kept for comparison (SnakeMethod::Projection3D): Eq. 4 on the
// whole curve in space, then every sample projected back onto the surface. It follows the same
// rules as the paper's method (SnakeMotionRules): step control, levels, open ends, balloon.

#include <chrono>
#include <cmath>
#include <memory>
#include <vector>

#include <Eigen/Dense>

#include <vcg_ext/snake/curve.h>
#include <vcg_ext/snake/motion_rules.h>
#include <vcg_ext/snake/spline.h>
#include <vcg_ext/surface/snake_surface.h>
#include <vcg_ext/surface/surface_projection.h>

namespace vcg {
namespace tri {

template <class MeshType>
class SnakeProjectionMotion : public SnakeMotionRules<MeshType>
{
    typedef SnakeMotionRules<MeshType> Rules;

public:
    typedef SnakeSurface<MeshType> Surface;

    explicit SnakeProjectionMotion(std::shared_ptr<Surface> s) : Rules(std::move(s)) {}

    /// Forget the factored spline systems (parameters or samples changed).
    void ClearCache() { splines.Clear(); }

    /// One operation: `updatesPerOperation` updates of Eq. 4 in space, each followed by the
    /// projection of every sample onto the surface; the gaps are traced lazily afterwards.
    void Step(SnakeCurve &st, SnakeStats &stats, const SnakeMotionFrame &fr)
    {
        const int level = fr.level;
        const double unit = fr.unit;
        const bool faceLinear = surf->EnergyField().FaceLinear();
        const MeshType &m = surf->Mesh();
        const int n = int(st.samples.size());
        const double h = unit;
        std::vector<bool> fixed(n);
        for (int i = 0; i < n; ++i) fixed[i] = st.samples[i].fixed;
        SnakeSpline &spline = splines.For(n, st.closed, st.params.alpha, st.params.beta, st.params.gamma, fixed);
        Eigen::MatrixXd X(n, 3), F(n, 3);
        std::vector<double> slope(n, 0.0);
        std::vector<Eigen::Vector3d> across(n, Eigen::Vector3d::Zero()), tangent(n, Eigen::Vector3d::Zero()); // the curve's frame
        std::vector<Eigen::Vector3d> pull(n, Eigen::Vector3d::Zero()); // the coarse gradient (alongPullBlend)
        for (int u = 0; u < st.params.updatesPerOperation; ++u) {
            auto tu = SnakeClock::Now();
            for (int i = 0; i < n; ++i) {
                vcg::Point3d p = st.samples[i].p.Pd(m) / h;
                X.row(i) << p[0], p[1], p[2];
                const int lev = SampleLevel(st.samples[i], level);
                vcg::Point3d g = surf->EnergyGradient(lev, st.samples[i].p) * h; // per edge length
                slope[i] = g.Norm();
                if (lev > 0 && faceLinear) pull[i] = Eigen::Vector3d(g[0], g[1], g[2]); // alongPullBlend
                g *= st.params.externalWeight * (lev == level ? fr.gain : 1.0);
                F.row(i) << g[0], g[1], g[2];
            }
            for (int i = 0; i < n; ++i) { // the feature force across the curve only (see moveSegment)
                int a = st.closed ? (i - 1 + n) % n : std::max(i - 1, 0), b = st.closed ? (i + 1) % n : std::min(i + 1, n - 1);
                Eigen::Vector3d t = (X.row(b) - X.row(a)).transpose();
                if (t.norm() > 0) {
                    t.normalize();
                    F.row(i) -= F.row(i).dot(t.transpose()) * t.transpose();
                    const int lev = SampleLevel(st.samples[i], level);
                    const vcg::Point3d fn = surf->FaceNormal(st.samples[i].p.face);
                    Eigen::Vector3d nrm = t.cross(Eigen::Vector3d(fn[0], fn[1], fn[2]));
                    if (nrm.norm() > 0) across[i] = nrm.normalized(), tangent[i] = t;
                    if (lev == 0 && faceLinear) { // the across slope, averaged (acrossSlope)
                        double a;
                        if (nrm.norm() > 0 && acrossSlope(st.samples[i].p, nrm.normalized(), h, a))
                            F.row(i) = st.params.externalWeight * (lev == level ? fr.gain : 1.0) * a * h *
                                       nrm.normalized().transpose();
                    }
                    if (fr.outside != 0) { // balloon: outward = tangent x face normal for a counter-clockwise curve
                        const vcg::Point3d n = surf->FaceNormal(st.samples[i].p.face);
                        Eigen::Vector3d o = t.cross(Eigen::Vector3d(n[0], n[1], n[2]));
                        if (o.norm() > 0) F.row(i) -= balloonPressure(st.params, fr, st.samples[i].p) * o.normalized().transpose();
                    }
                }
            }
            Eigen::MatrixXd Xn = spline.Update(X, F);
            for (int i = 0; i < n; ++i) {
                if (fixed[i]) continue;
                Eigen::Vector3d d = (Xn.row(i) - X.row(i)).transpose();
                if (!d.allFinite()) continue;
                const bool pulled = st.IsOpenEnd(i) && pull[i].norm() > 0;
                if (st.IsOpenEnd(i)) {
                    // in space "across the end tangent" is a plane: keep only the direction across
                    // it in the sample's tangent plane (the rest slides the end along a crease)
                    const vcg::Point3d fn = surf->FaceNormal(st.samples[i].p.face);
                    Eigen::Vector3d a = Rules::template endTangent<Eigen::Vector3d>(X, i).cross(Eigen::Vector3d(fn[0], fn[1], fn[2]));
                    const Eigen::Vector3d dAcross = a.norm() > 0 ? Eigen::Vector3d(d.dot(a.normalized()) * a.normalized())
                                                                 : Rules::template acrossEnd<Eigen::Vector3d>(X, i, d);
                    vcg::Point3d u;
                    d = pulled ? alongPullBlend(d, pull[i], dAcross)
                        : surf->EnergyField().AcrossFeature(SampleLevel(st.samples[i], level), st.samples[i].p, u)
                            ? acrossFeatureEnd(d, Eigen::Vector3d(u[0], u[1], u[2]))
                            : dAcross;
                }
                double len = d.norm();
                double cap = len > 0 ? st.params.maxStep * st.samples[i].trust * faceWidth(st.samples[i].p.face, d / len) / h : 0;
                if (len > cap) d *= cap / len;
                Eigen::Vector3d q = X.row(i).transpose() + d;
                vcg::Point3d target(q[0] * h, q[1] * h, q[2] * h);
                SurfacePoint np = SurfaceProjection<MeshType>::Closest(*surf, st.samples[i].p.face, target,
                                                                       d.norm() * h + 1.5 * h);
                if (st.IsOpenEnd(i)) { // the projection, too, can slide an end along a crease: undo that
                    // (only its own slide: the blended move may go along the tangent, alongPullBlend)
                    Eigen::Vector3d t = Rules::template endTangent<Eigen::Vector3d>(X, i);
                    const vcg::Point3d y = np.Pd(m) / h;
                    const double along = t.norm() > 0 ? (Eigen::Vector3d(y[0], y[1], y[2]) - q).dot(t.normalized()) : 0;
                    if (along != 0) {
                        const Eigen::Vector3d q2 = q - along * t.normalized();
                        np = SurfaceProjection<MeshType>::Closest(*surf, np.face, vcg::Point3d(q2[0] * h, q2[1] * h, q2[2] * h),
                                                                  d.norm() * h + 1.5 * h + std::abs(along) * h);
                    }
                }
                const int lev = SampleLevel(st.samples[i], level);
                UpdateTrust(st.samples[i].trust, lev, surf->EnergyAt(lev, st.samples[i].p), surf->EnergyAt(lev, np),
                            slope[i] * std::min(len, cap));
                if (level > 0 && !st.closed) { // open snakes only (HoldAtWell)
                    const SurfacePoint pOld = st.samples[i].p;
                    st.samples[i].heldFine =
                        HoldAtWell(st.samples[i].heldFine, pOld, np, d, across[i], tangent[i], level,
                                   [&](const Eigen::Vector3d &v, bool ahead, SurfacePoint &q) {
                            const SurfacePoint &base = ahead ? np : pOld;
                            const vcg::Point3d x = base.Pd(m) + vcg::Point3d(v[0], v[1], v[2]) * h;
                            q = SurfaceProjection<MeshType>::Closest(*surf, base.face, x, 2 * v.norm() * h);
                            return true;
                        });
                }
                st.samples[i].p = np;
            }
            stats.updates++;
            stats.msUpdate.push_back(SnakeClock::MsSince(tu));
        }
        for (auto &g : st.gaps) g = SnakeGap(); // traced lazily by Polyline()
    }

private:
    using Rules::surf;
    using Rules::UpdateTrust;
    using Rules::SampleLevel;
    using Rules::HoldAtWell;
    using Rules::alongPullBlend;
    using Rules::acrossFeatureEnd;
    using Rules::acrossSlope;
    using Rules::faceWidth;
    using Rules::balloonPressure;
    SnakeSplineCache splines;

};

} // namespace tri
} // namespace vcg

#endif
