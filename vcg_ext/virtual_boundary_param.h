#ifndef VCG_EXT_VIRTUAL_BOUNDARY_PARAM_H
#define VCG_EXT_VIRTUAL_BOUNDARY_PARAM_H

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <vcg/space/point3.h>

namespace vcg {
namespace tri {

/// Convex-combination parameterization of a disk with a virtual boundary (Sec. 5.3; the
/// paper's reference 18, Lee, Kim & Lee 2002).
///
/// Plain convex combination (Tutte/Floater) pins the real boundary onto a convex polygon,
/// which distorts the faces near it. Here `layers` rings of virtual vertices are attached
/// outside the real boundary, each offset outwards in the tangent plane, with offsets
/// growing geometrically (1, 3, 7, ... local edge lengths) so the virtual band is wide
/// enough to absorb the mismatch between the region's shape and the pinned outline. Only the
/// outermost virtual ring is pinned, onto a convex curve: an ellipse with the region's
/// principal extents (a snake's region is an elongated strip, which a circle would bend),
/// arc-length spaced. The real boundary becomes interior, so it is free, and the
/// distortion stays low where the snake lives.
///
/// Weights are mean-value weights (Floater 2003) computed on the 3D triangles, symmetrized:
/// W_ij = (w_ij + w_ji) / 2. Every weight is positive, so by Tutte/Floater the result is an
/// injective embedding whatever the geometry (degenerate triangles included), and the
/// symmetric system is solved with one sparse Cholesky (LDL^T) for both coordinates.
/// The embedding is finally scaled so that its edges have, on average, their 3D length
/// divided by `unit` (the mesh's mean edge length): snake parameters are then scale-free.
class VirtualBoundaryParam
{
public:
    struct Result
    {
        std::vector<Eigen::Vector2d> uv;            // every local vertex, then the virtual ones
        std::vector<std::array<int, 3>> virtualTri; // the strip triangles between the rings
        int virtualVertices = 0;
        std::string error;
    };

    /// pos/tri: the region (real + fan faces); boundary: outer loop with the region on its
    /// left. Returns false (with error) only on an unusable input or a failed solve.
    static bool Embed(const std::vector<vcg::Point3d> &pos, const std::vector<std::array<int, 3>> &tri,
                      const std::vector<int> &boundary, double unit, int layers, Result &out)
    {
        out = Result();
        const int nv = int(pos.size()), nb = int(boundary.size());
        if (nb < 3 || tri.empty()) { out.error = "region border too short"; return false; }
        layers = std::max(1, layers);

        // Vertex normals (area weighted) to find the outward tangent direction on the border.
        std::vector<vcg::Point3d> normal(nv, vcg::Point3d(0, 0, 0));
        for (const auto &t : tri) {
            vcg::Point3d n = (pos[t[1]] - pos[t[0]]) ^ (pos[t[2]] - pos[t[0]]);
            for (int k = 0; k < 3; ++k) normal[t[k]] += n;
        }
        vcg::Point3d centroid(0, 0, 0);
        for (int b : boundary) centroid += pos[b];
        centroid /= double(nb);

        // Virtual rings: ring r holds vertices nv + (r-1)*nb + i, i along the border.
        std::vector<vcg::Point3d> all = pos;
        all.resize(nv + layers * nb);
        std::vector<int> ring(nb);
        for (int i = 0; i < nb; ++i) ring[i] = boundary[i];
        for (int r = 1; r <= layers; ++r) {
            for (int i = 0; i < nb; ++i) {
                const vcg::Point3d &p = pos[boundary[i]];
                vcg::Point3d dPrev = p - pos[boundary[(i - 1 + nb) % nb]];
                vcg::Point3d dNext = pos[boundary[(i + 1) % nb]] - p;
                double len = 0.5 * (dPrev.Norm() + dNext.Norm());
                vcg::Point3d n = normal[boundary[i]];
                vcg::Point3d out3 = (dPrev + dNext) ^ n; // right of the border = outside
                if (!(out3.Norm() > 1e-300)) out3 = p - centroid;
                if (!(out3.Norm() > 1e-300)) out3 = vcg::Point3d(1, 0, 0);
                out3.Normalize();
                if (!(len > 0)) len = unit;
                all[nv + (r - 1) * nb + i] = p + out3 * (len * double((1 << r) - 1));
            }
        }
        std::vector<std::array<int, 3>> strip;
        for (int r = 1; r <= layers; ++r) {
            for (int i = 0; i < nb; ++i) {
                int j = (i + 1) % nb;
                int ui = (r == 1) ? boundary[i] : nv + (r - 2) * nb + i;
                int uj = (r == 1) ? boundary[j] : nv + (r - 2) * nb + j;
                int wi = nv + (r - 1) * nb + i, wj = nv + (r - 1) * nb + j;
                // the strip lies right of ui->uj: counter-clockwise it runs uj->ui
                strip.push_back({uj, ui, wi});
                strip.push_back({uj, wi, wj});
            }
        }
        const int total = nv + layers * nb;
        const int firstFixed = nv + (layers - 1) * nb;

        // Symmetrized mean-value weights, accumulated per triangle corner.
        std::vector<Eigen::Triplet<double>> trip;
        std::vector<double> diag(total, 0.0);
        auto corner = [&](int a, int b, int c) {
            vcg::Point3d e1 = all[b] - all[a], e2 = all[c] - all[a];
            double l1 = e1.Norm(), l2 = e2.Norm();
            double cosang = (l1 > 0 && l2 > 0) ? (e1 * e2) / (l1 * l2) : 1.0;
            cosang = std::max(-1.0, std::min(1.0, cosang));
            double theta = std::acos(cosang);
            double th = std::tan(0.5 * std::max(1e-6, std::min(M_PI - 1e-6, theta)));
            th = std::min(th, 1e3);
            double lmin = 1e-9 * unit;
            double wb = 0.5 * th / std::max(l1, lmin), wc = 0.5 * th / std::max(l2, lmin);
            trip.emplace_back(a, b, -wb); trip.emplace_back(b, a, -wb);
            trip.emplace_back(a, c, -wc); trip.emplace_back(c, a, -wc);
            diag[a] += wb; diag[b] += wb; diag[a] += wc; diag[c] += wc;
        };
        auto addTri = [&](const std::array<int, 3> &t) {
            corner(t[0], t[1], t[2]);
            corner(t[1], t[2], t[0]);
            corner(t[2], t[0], t[1]);
        };
        for (const auto &t : tri) addTri(t);
        for (const auto &t : strip) addTri(t);

        // Pin the outermost ring onto an ellipse with the ring's principal extents,
        // counter-clockwise, arc-length spaced, starting at the ring's extreme point along
        // the major axis.
        Eigen::Vector3d c3 = Eigen::Vector3d::Zero();
        for (int i = 0; i < nb; ++i) c3 += toE(all[firstFixed + i]);
        c3 /= nb;
        Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
        for (int i = 0; i < nb; ++i) {
            Eigen::Vector3d d = toE(all[firstFixed + i]) - c3;
            cov += d * d.transpose();
        }
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov / nb);
        Eigen::Vector3d axis = eig.eigenvectors().col(2);
        double s1 = std::sqrt(std::max(0.0, eig.eigenvalues()[2])), s2 = std::sqrt(std::max(0.0, eig.eigenvalues()[1]));
        double aspect = (s1 > 0 && s2 > 0) ? std::min(8.0, s1 / s2) : 1.0;
        if (!std::isfinite(aspect) || aspect < 1) aspect = 1;
        int start = 0;
        double best = -1e300;
        for (int i = 0; i < nb; ++i) {
            double pr = (toE(all[firstFixed + i]) - c3).dot(axis);
            if (pr > best) { best = pr; start = i; }
        }
        std::vector<double> cum(nb + 1, 0.0);
        for (int k = 0; k < nb; ++k) {
            int i = (start + k) % nb, j = (start + k + 1) % nb;
            cum[k + 1] = cum[k] + std::max(1e-12 * unit, (all[firstFixed + j] - all[firstFixed + i]).Norm());
        }
        const int ns = 512; // ellipse (aspect, 1) by arc length
        std::vector<double> ecum(ns + 1, 0.0);
        auto ell = [&](double t) { return Eigen::Vector2d(aspect * std::cos(t), std::sin(t)); };
        for (int k = 0; k < ns; ++k) ecum[k + 1] = ecum[k] + (ell(2 * M_PI * (k + 1) / ns) - ell(2 * M_PI * k / ns)).norm();
        out.uv.assign(total, Eigen::Vector2d::Zero());
        for (int k = 0, seg = 0; k < nb; ++k) {
            double target = cum[k] / cum[nb] * ecum[ns];
            while (seg + 1 < ns && ecum[seg + 1] < target) ++seg;
            double f = (ecum[seg + 1] > ecum[seg]) ? (target - ecum[seg]) / (ecum[seg + 1] - ecum[seg]) : 0.0;
            out.uv[firstFixed + (start + k) % nb] = ell(2 * M_PI * (seg + f) / ns);
        }

        // Solve L_ff u_f = -L_fc u_c.
        const int nf = firstFixed;
        std::vector<Eigen::Triplet<double>> tf;
        tf.reserve(trip.size() + nf);
        Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(nf, 2);
        for (const auto &t : trip) {
            int r = t.row(), c = t.col();
            if (r >= nf) continue;
            if (c < nf) tf.push_back(t);
            else rhs.row(r) -= t.value() * out.uv[c].transpose();
        }
        for (int i = 0; i < nf; ++i) tf.emplace_back(i, i, diag[i]);
        Eigen::SparseMatrix<double> A(nf, nf);
        A.setFromTriplets(tf.begin(), tf.end());
        Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(A);
        if (solver.info() != Eigen::Success) { out.error = "embedding: factorization failed"; return false; }
        Eigen::MatrixXd sol = solver.solve(rhs);
        if (solver.info() != Eigen::Success || !sol.allFinite()) { out.error = "embedding: solve failed"; return false; }
        for (int i = 0; i < nf; ++i) out.uv[i] = sol.row(i).transpose();

        // Scale to mesh units (mean edge length = 1 where 3D edges are 1 unit long).
        double l3 = 0, l2 = 0;
        for (const auto &t : tri)
            for (int k = 0; k < 3; ++k) {
                l3 += (pos[t[(k + 1) % 3]] - pos[t[k]]).Norm();
                l2 += (out.uv[t[(k + 1) % 3]] - out.uv[t[k]]).norm();
            }
        if (!(l2 > 0) || !(l3 > 0)) { out.error = "embedding collapsed"; return false; }
        double s = (l3 / unit) / l2;
        for (auto &p : out.uv) p *= s;
        out.virtualTri = strip;
        out.virtualVertices = layers * nb;
        return true;
    }

    static Eigen::Vector3d toE(const vcg::Point3d &p) { return Eigen::Vector3d(p[0], p[1], p[2]); }

    /// Signed area of a 2D triangle (positive = counter-clockwise).
    static double SignedArea(const Eigen::Vector2d &a, const Eigen::Vector2d &b, const Eigen::Vector2d &c)
    {
        return 0.5 * ((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
    }

    /// Number of triangles that are not strictly counter-clockwise (0 = injective embedding).
    static int CountFlipped(const std::vector<Eigen::Vector2d> &uv, const std::vector<std::array<int, 3>> &tri)
    {
        int bad = 0;
        for (const auto &t : tri)
            if (!(SignedArea(uv[t[0]], uv[t[1]], uv[t[2]]) > 0)) ++bad;
        return bad;
    }
};

} // namespace tri
} // namespace vcg

#endif
