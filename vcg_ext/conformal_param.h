#ifndef VCG_EXT_CONFORMAL_PARAM_H
#define VCG_EXT_CONFORMAL_PARAM_H

#include <algorithm>
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

/// Least-squares conformal embedding of a disk (Lévy et al. 2002), the local embedding the
/// snake uses first (beyond the paper, which uses a convex combination with a virtual
/// boundary, VirtualBoundaryParam). It has no boundary condition besides two pinned vertices,
/// so a developable region (a flat plate, a strip folded across a crease) is embedded exactly,
/// up to a similarity: straight lines stay straight in the plane, and the snake's spline has
/// nothing spurious to straighten (observed with the convex combination on anisotropic
/// meshes: S-kinks that made a snake without any force drift by a random walk). It is not
/// injective on every input: the caller checks for flipped triangles and falls back.
///
/// The conformal energy of triangle T with local complex coordinates w_k is
/// |sum_k (w_{k+2} - w_{k+1}) U_k|^2 / (2 A_T) (U_k = u_k + i v_k); its minimum with two pinned
/// vertices solves a symmetric positive definite system, unknowns (u, v) interleaved and
/// numbered by a sweep along the region's major axis (banded: natural-ordering LDL^T).
class ConformalParam
{
public:
    /// pos/tri: the region's vertices and triangles (a disk); boundary: its outer loop.
    /// uv: one 2D point per vertex, scaled so that the embedded edges have, on average, their 3D
    /// length divided by `unit`. False (with error) when the system cannot be solved.
    static bool Embed(const std::vector<vcg::Point3d> &pos, const std::vector<std::array<int, 3>> &tri,
                      const std::vector<int> &boundary, double unit, std::vector<Eigen::Vector2d> &uv,
                      std::string &error)
    {
        const int nv = int(pos.size());
        uv.assign(nv, Eigen::Vector2d::Zero());
        if (boundary.size() < 3 || tri.empty()) { error = "region border too short"; return false; }
        // Pins: the two border vertices farthest apart along the region's major axis.
        Eigen::Vector3d c = Eigen::Vector3d::Zero();
        for (const auto &p : pos) c += Eigen::Vector3d(p[0], p[1], p[2]);
        c /= double(nv);
        Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
        for (const auto &p : pos) {
            Eigen::Vector3d d = Eigen::Vector3d(p[0], p[1], p[2]) - c;
            cov += d * d.transpose();
        }
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
        const Eigen::Vector3d axis = eig.eigenvectors().col(2);
        auto key = [&](int v) { return (Eigen::Vector3d(pos[v][0], pos[v][1], pos[v][2]) - c).dot(axis); };
        int pa = boundary[0], pb = boundary[0];
        for (int v : boundary) {
            if (key(v) < key(pa)) pa = v;
            if (key(v) > key(pb)) pb = v;
        }
        const double dab = (pos[pb] - pos[pa]).Norm();
        if (pa == pb || !(dab > 0)) { error = "degenerate region"; return false; }

        std::vector<int> order(nv), slot(nv, -1);
        for (int i = 0; i < nv; ++i) order[i] = i;
        std::sort(order.begin(), order.end(), [&](int a, int b) { return key(a) < key(b); });
        int nf = 0;
        for (int v : order)
            if (v != pa && v != pb) slot[v] = nf++;
        Eigen::Vector2d pin[2] = {Eigen::Vector2d(0, 0), Eigen::Vector2d(dab, 0)};
        auto pinIndex = [&](int v) { return v == pa ? 0 : v == pb ? 1 : -1; };

        std::vector<Eigen::Triplet<double>> trip;
        trip.reserve(tri.size() * 36);
        Eigen::VectorXd rhs = Eigen::VectorXd::Zero(2 * nf);
        double areaSum = 0;
        for (const auto &t : tri) areaSum += 0.5 * ((pos[t[1]] - pos[t[0]]) ^ (pos[t[2]] - pos[t[0]])).Norm();
        const double minArea = 1e-12 * std::max(areaSum, 1e-300);
        for (const auto &t : tri) {
            // the triangle in its own orthonormal frame
            vcg::Point3d e1 = pos[t[1]] - pos[t[0]], e2 = pos[t[2]] - pos[t[0]];
            vcg::Point3d n = e1 ^ e2;
            double a2 = n.Norm(); // twice the area
            if (!(a2 > 2 * minArea) || !std::isfinite(a2)) continue;
            double l1 = e1.Norm();
            vcg::Point3d x = e1 / l1, y = (n / a2) ^ x;
            double w[3][2] = {{0, 0}, {l1, 0}, {e2 * x, e2 * y}};
            const double s = 1.0 / std::sqrt(a2); // |.|^2 / (2A) = |.|^2 / a2
            // residual (re, im) = sum_k W_k U_k, W_k = w_{k+2} - w_{k+1}
            double coef[2][6]; // rows re/im, columns (u_k, v_k) for k = 0..2
            for (int k = 0; k < 3; ++k) {
                double a = s * (w[(k + 2) % 3][0] - w[(k + 1) % 3][0]), b = s * (w[(k + 2) % 3][1] - w[(k + 1) % 3][1]);
                coef[0][2 * k] = a; coef[0][2 * k + 1] = -b;
                coef[1][2 * k] = b; coef[1][2 * k + 1] = a;
            }
            for (int r = 0; r < 2; ++r)
                for (int i = 0; i < 6; ++i) {
                    int vi = t[i / 2];
                    if (slot[vi] < 0) continue;
                    int row = 2 * slot[vi] + i % 2;
                    for (int j = 0; j < 6; ++j) {
                        int vj = t[j / 2];
                        double val = coef[r][i] * coef[r][j];
                        if (slot[vj] >= 0) {
                            if (2 * slot[vj] + j % 2 <= row) trip.emplace_back(row, 2 * slot[vj] + j % 2, val);
                        } else {
                            rhs[row] -= val * pin[pinIndex(vj)][j % 2];
                        }
                    }
                }
        }
        // A vanishing regularization keeps vertices of degenerate triangles determined.
        for (int i = 0; i < 2 * nf; ++i) trip.emplace_back(i, i, 1e-12);
        Eigen::SparseMatrix<double> A(2 * nf, 2 * nf);
        A.setFromTriplets(trip.begin(), trip.end());
        Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>> solver(A);
        if (solver.info() != Eigen::Success) { error = "conformal embedding: factorization failed"; return false; }
        Eigen::VectorXd sol = solver.solve(rhs);
        if (solver.info() != Eigen::Success || !sol.allFinite()) { error = "conformal embedding: solve failed"; return false; }
        for (int v = 0; v < nv; ++v) {
            int p = pinIndex(v);
            uv[v] = p >= 0 ? pin[p] : Eigen::Vector2d(sol[2 * slot[v]], sol[2 * slot[v] + 1]);
        }
        // Scale to mesh units.
        double l3 = 0, l2 = 0;
        for (const auto &t : tri)
            for (int k = 0; k < 3; ++k) {
                l3 += (pos[t[(k + 1) % 3]] - pos[t[k]]).Norm();
                l2 += (uv[t[(k + 1) % 3]] - uv[t[k]]).norm();
            }
        if (!(l2 > 0) || !(l3 > 0) || !std::isfinite(l2)) { error = "conformal embedding collapsed"; return false; }
        const double sc = (l3 / unit) / l2;
        for (auto &p : uv) p *= sc;
        return true;
    }
};

} // namespace tri
} // namespace vcg

#endif
