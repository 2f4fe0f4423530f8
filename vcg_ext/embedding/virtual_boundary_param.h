#ifndef VCG_EXT_VIRTUAL_BOUNDARY_PARAM_H
#define VCG_EXT_VIRTUAL_BOUNDARY_PARAM_H

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

        // Outward tangent direction and local edge length at each border vertex.
        std::vector<vcg::Point3d> outDir(nb);
        std::vector<double> outLen(nb);
        for (int i = 0; i < nb; ++i) {
            const vcg::Point3d &p = pos[boundary[i]];
            vcg::Point3d dPrev = p - pos[boundary[(i - 1 + nb) % nb]];
            vcg::Point3d dNext = pos[boundary[(i + 1) % nb]] - p;
            double len = 0.5 * (dPrev.Norm() + dNext.Norm());
            vcg::Point3d out3 = (dPrev + dNext) ^ normal[boundary[i]]; // right of the border = outside
            if (!(out3.Norm() > 1e-300)) out3 = p - centroid;
            if (!(out3.Norm() > 1e-300)) out3 = vcg::Point3d(1, 0, 0);
            outDir[i] = out3.Normalize();
            outLen[i] = len > 0 ? len : unit;
        }
        // Virtual rings: ring 1 has a vertex per border vertex, each further ring half as
        // many (they are farther out, so coarser is enough), offsets 1, 3, 7, ... edges.
        std::vector<vcg::Point3d> all = pos;
        std::vector<int> prev = boundary, cur;
        std::vector<std::array<int, 3>> strip;
        int firstFixed = nv;
        for (int r = 1; r <= layers; ++r) {
            int n1 = int(prev.size());
            int n2 = (r == 1) ? nb : std::max(std::min(8, n1), (n1 + 1) / 2);
            firstFixed = int(all.size());
            cur.resize(n2);
            for (int j = 0; j < n2; ++j) {
                int b = int((long(j) * nb) / n2);
                cur[j] = int(all.size());
                all.push_back(pos[boundary[b]] + outDir[b] * (outLen[b] * double((1 << r) - 1)));
            }
            // zip the two rings; the strip lies right of the border, so counter-clockwise
            // triangles run against the border's direction
            for (int i = 0, j = 0; i < n1 || j < n2;) {
                if (j == n2 || (i < n1 && double(i + 1) / n1 <= double(j + 1) / n2)) {
                    strip.push_back({prev[(i + 1) % n1], prev[i], cur[j % n2]});
                    ++i;
                } else {
                    strip.push_back({prev[i % n1], cur[j], cur[(j + 1) % n2]});
                    ++j;
                }
            }
            prev = cur;
        }
        const int total = int(all.size());
        const int nl = total - firstFixed; // pinned (outermost) ring

        // Symmetrized mean-value weights, accumulated per edge from each triangle corner:
        // W_ab += tan(theta_a / 2) / (2 |ab|). Adjacency lists (a vertex has few neighbours)
        // instead of triplets: no sort, and the matrix is assembled directly below.
        // Flat adjacency: a vertex has at most two neighbours per incident triangle.
        std::vector<int> first(total + 1, 0);
        for (const auto &t : tri)
            for (int k = 0; k < 3; ++k) first[t[k] + 1] += 2;
        for (const auto &t : strip)
            for (int k = 0; k < 3; ++k) first[t[k] + 1] += 2;
        for (int i = 0; i < total; ++i) first[i + 1] += first[i];
        std::vector<int> fill(total, 0);
        std::vector<std::pair<int, double>> adjW(first[total]);
        std::vector<double> diag(total, 0.0);
        const double lmin = 1e-9 * unit;
        auto addHalf = [&](int a, int b, double w) {
            std::pair<int, double> *p = &adjW[first[a]], *e = p + fill[a];
            for (; p != e; ++p)
                if (p->first == b) { p->second += w; return; }
            *p = std::make_pair(b, w);
            ++fill[a];
        };
        auto addW = [&](int a, int b, double w) {
            diag[a] += w;
            diag[b] += w;
            addHalf(a, b, w);
            addHalf(b, a, w);
        };
        auto addTri = [&](const std::array<int, 3> &t) {
            vcg::Point3d e[3] = {all[t[1]] - all[t[0]], all[t[2]] - all[t[1]], all[t[0]] - all[t[2]]};
            double l[3] = {e[0].Norm(), e[1].Norm(), e[2].Norm()};
            double twiceArea = (e[0] ^ e[2]).Norm();
            for (int k = 0; k < 3; ++k) {
                // corner at t[k] between edges to t[k+1] (e[k]) and t[k+2] (-e[k+2])
                const vcg::Point3d &u = e[k];
                vcg::Point3d v = -e[(k + 2) % 3];
                double den = l[k] * l[(k + 2) % 3] + u * v; // tan(theta/2) = |u x v| / (|u||v| + u.v)
                double th = den > 0 ? twiceArea / den : 1e3;
                th = std::max(1e-6, std::min(th, 1e3));
                addW(t[k], t[(k + 1) % 3], 0.5 * th / std::max(l[k], lmin));
                addW(t[k], t[(k + 2) % 3], 0.5 * th / std::max(l[(k + 2) % 3], lmin));
            }
        };
        for (const auto &t : tri) addTri(t);
        for (const auto &t : strip) addTri(t);

        // Pin the outermost ring onto an ellipse with the ring's principal extents,
        // counter-clockwise, arc-length spaced, starting at the ring's extreme point along
        // the major axis.
        Eigen::Vector3d c3 = Eigen::Vector3d::Zero();
        for (int i = 0; i < nl; ++i) c3 += toE(all[firstFixed + i]);
        c3 /= nl;
        Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
        for (int i = 0; i < nl; ++i) {
            Eigen::Vector3d d = toE(all[firstFixed + i]) - c3;
            cov += d * d.transpose();
        }
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov / nl);
        Eigen::Vector3d axis = eig.eigenvectors().col(2);
        double s1 = std::sqrt(std::max(0.0, eig.eigenvalues()[2])), s2 = std::sqrt(std::max(0.0, eig.eigenvalues()[1]));
        double aspect = (s1 > 0 && s2 > 0) ? std::min(8.0, s1 / s2) : 1.0;
        if (!std::isfinite(aspect) || aspect < 1) aspect = 1;
        int start = 0;
        double best = -1e300;
        for (int i = 0; i < nl; ++i) {
            double pr = (toE(all[firstFixed + i]) - c3).dot(axis);
            if (pr > best) { best = pr; start = i; }
        }
        std::vector<double> cum(nl + 1, 0.0);
        for (int k = 0; k < nl; ++k) {
            int i = (start + k) % nl, j = (start + k + 1) % nl;
            cum[k + 1] = cum[k] + std::max(1e-12 * unit, (all[firstFixed + j] - all[firstFixed + i]).Norm());
        }
        const int ns = 128; // ellipse (aspect, 1) by arc length
        std::vector<double> ecum(ns + 1, 0.0);
        auto ell = [&](double t) { return Eigen::Vector2d(aspect * std::cos(t), std::sin(t)); };
        for (int k = 0; k < ns; ++k) ecum[k + 1] = ecum[k] + (ell(2 * M_PI * (k + 1) / ns) - ell(2 * M_PI * k / ns)).norm();
        out.uv.assign(total, Eigen::Vector2d::Zero());
        for (int k = 0, seg = 0; k < nl; ++k) {
            double target = cum[k] / cum[nl] * ecum[ns];
            while (seg + 1 < ns && ecum[seg + 1] < target) ++seg;
            double f = (ecum[seg + 1] > ecum[seg]) ? (target - ecum[seg]) / (ecum[seg + 1] - ecum[seg]) : 0.0;
            out.uv[firstFixed + (start + k) % nl] = ell(2 * M_PI * (seg + f) / ns);
        }

        // Solve L_ff u_f = -L_fc u_c. The unknowns are numbered by a sweep along the
        // region's major axis: a snake's region is a strip, so the matrix is then banded
        // with a bandwidth of one cross-section, and a natural-ordering LDL^T beats a
        // general fill-reducing ordering (whose analysis would cost more than the solve).
        const int nf = firstFixed;
        std::vector<int> order(nf), slot(nf);
        std::vector<double> key(nf);
        for (int i = 0; i < nf; ++i) { order[i] = i; key[i] = (toE(all[i]) - c3).dot(axis); }
        std::sort(order.begin(), order.end(), [&](int a, int b) { return key[a] < key[b]; });
        for (int k = 0; k < nf; ++k) slot[order[k]] = k;
        // Lower triangle, column by column in sweep order.
        Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(nf, 2);
        Eigen::SparseMatrix<double> A(nf, nf);
        Eigen::VectorXi count(nf);
        for (int k = 0; k < nf; ++k) count[k] = fill[order[k]] + 1;
        A.reserve(count);
        std::vector<std::pair<int, double>> col;
        for (int k = 0; k < nf; ++k) {
            const int v = order[k];
            col.clear();
            col.emplace_back(k, diag[v]);
            for (int q = first[v]; q < first[v] + fill[v]; ++q) {
                const auto &e = adjW[q];
                if (e.first >= nf) rhs.row(k) += e.second * out.uv[e.first].transpose(); // pinned neighbour
                else if (slot[e.first] > k) col.emplace_back(slot[e.first], -e.second);
            }
            std::sort(col.begin(), col.end());
            for (const auto &x : col) A.insert(x.first, k) = x.second;
        }
        A.makeCompressed();
        Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>> solver(A);
        if (solver.info() != Eigen::Success) { out.error = "embedding: factorization failed"; return false; }
        Eigen::MatrixXd sol = solver.solve(rhs);
        if (solver.info() != Eigen::Success || !sol.allFinite()) { out.error = "embedding: solve failed"; return false; }
        for (int i = 0; i < nf; ++i) out.uv[i] = sol.row(slot[i]).transpose();

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
        out.virtualVertices = total - nv;
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
