#ifndef VCG_EXT_CONFORMAL_PARAM_H
#define VCG_EXT_CONFORMAL_PARAM_H

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/OrderingMethods>
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
/// vertices solves a Hermitian positive definite system in the complex unknowns U (one per
/// vertex: the real system in (u, v) has 2x2 blocks that are multiplications by complex
/// numbers, and its LDL^T did four times the index work), the vertices in a minimum-degree
/// order of their graph (ties along the snake's arc length, or a sweep along the region's major
/// axis), so that the LDL^T needs no analysis of its own.
class ConformalParam
{
public:
    /// Scratch reused across embeddings (no allocation once warm), and the symbolic
    /// factorization of the last system, reused when the next one has the same pattern.
    struct Workspace
    {
        std::vector<int> order, slot, first, fill, byOld;
        struct Block
        {
            int v;       // neighbour
            double c, d; // the 2x2 block [c d; -d c] coupling (u, v) of both vertices
        };
        std::vector<Block> adj; // per vertex, at first[v] .. first[v] + fill[v]
        std::vector<double> diag;
        std::vector<double> keys;
        Eigen::SparseMatrix<std::complex<double>> A;
        Eigen::SparseMatrix<double> graph;
        Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> perm;
        Eigen::VectorXcd rhs, sol;
        Eigen::SimplicialLDLT<Eigen::SparseMatrix<std::complex<double>>, Eigen::Lower, Eigen::NaturalOrdering<int>> solver;
        std::vector<int> lastOuter, lastInner; // the pattern the solver was analysed for
        int analyses = 0, factorizations = 0;
    };

    /// pos/tri: the region's vertices and triangles (a disk); boundary: its outer loop.
    /// uv: one 2D point per vertex, scaled so that the embedded edges have, on average, their 3D
    /// length divided by `unit`. False (with error) when the system cannot be solved.
    static bool Embed(const std::vector<vcg::Point3d> &pos, const std::vector<std::array<int, 3>> &tri,
                      const std::vector<int> &boundary, double unit, std::vector<Eigen::Vector2d> &uv,
                      std::string &error)
    {
        Workspace w;
        return Embed(pos, tri, boundary, unit, uv, error, w, nullptr);
    }

    /// The same with a reusable workspace. `arc` (optional, one value per vertex): the first
    /// numbering of the unknowns (the minimum-degree order's ties), e.g. the arc length of the
    /// nearest point of the snake (the default is a sweep along the major axis).
    static bool Embed(const std::vector<vcg::Point3d> &pos, const std::vector<std::array<int, 3>> &tri,
                      const std::vector<int> &boundary, double unit, std::vector<Eigen::Vector2d> &uv,
                      std::string &error, Workspace &w, const std::vector<double> *arc)
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
        std::vector<double> &key = w.keys;
        key.resize(nv);
        for (int v = 0; v < nv; ++v) key[v] = (Eigen::Vector3d(pos[v][0], pos[v][1], pos[v][2]) - c).dot(axis);
        int pa = boundary[0], pb = boundary[0];
        for (int v : boundary) {
            if (key[v] < key[pa]) pa = v;
            if (key[v] > key[pb]) pb = v;
        }
        const double dab = (pos[pb] - pos[pa]).Norm();
        if (pa == pb || !(dab > 0)) { error = "degenerate region"; return false; }
        if (arc && int(arc->size()) == nv) key = *arc;

        std::vector<int> &order = w.order, &slot = w.slot;
        order.resize(nv);
        slot.assign(nv, -1);
        for (int i = 0; i < nv; ++i) order[i] = i;
        std::sort(order.begin(), order.end(), [&](int a, int b) { return key[a] < key[b] || (key[a] == key[b] && a < b); });
        int nf = 0;
        for (int v : order)
            if (v != pa && v != pb) slot[v] = nf++;
        const Eigen::Vector2d pin[2] = {Eigen::Vector2d(0, 0), Eigen::Vector2d(dab, 0)};
        auto pinIndex = [&](int v) { return v == pa ? 0 : v == pb ? 1 : -1; };

        // Per-vertex 2x2 blocks, accumulated per edge: no triplets, no sort.
        std::vector<int> &first = w.first, &fill = w.fill;
        first.assign(nv + 1, 0);
        for (const auto &t : tri)
            for (int k = 0; k < 3; ++k) first[t[k] + 1] += 2;
        for (int i = 0; i < nv; ++i) first[i + 1] += first[i];
        fill.assign(nv, 0);
        w.adj.resize(first[nv]);
        w.diag.assign(nv, 0.0);
        auto addBlock = [&](int a, int b, double cc, double dd) {
            Workspace::Block *p = &w.adj[first[a]], *e = p + fill[a];
            for (; p != e; ++p)
                if (p->v == b) { p->c += cc; p->d += dd; return; }
            *p = {b, cc, dd};
            ++fill[a];
        };
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
            double q[3][2] = {{0, 0}, {l1, 0}, {e2 * x, e2 * y}};
            const double s = 1.0 / std::sqrt(a2); // |.|^2 / (2A) = |.|^2 / a2
            // residual sum_k W_k U_k, W_k = (w_{k+2} - w_{k+1}) s = a_k + i b_k; its square's
            // Hessian block for (k, l) is [c d; -d c], c + i d = W_k conj(W_l) conjugated in d
            double ra[3], rb[3];
            for (int k = 0; k < 3; ++k) {
                ra[k] = s * (q[(k + 2) % 3][0] - q[(k + 1) % 3][0]);
                rb[k] = s * (q[(k + 2) % 3][1] - q[(k + 1) % 3][1]);
            }
            for (int k = 0; k < 3; ++k) {
                w.diag[t[k]] += ra[k] * ra[k] + rb[k] * rb[k];
                for (int l = 0; l < 3; ++l) {
                    if (l == k) continue;
                    addBlock(t[k], t[l], ra[k] * ra[l] + rb[k] * rb[l], rb[k] * ra[l] - ra[k] * rb[l]);
                }
            }
        }
        // A fill-reducing order of the free vertices: minimum degree (AMD) on the vertex graph,
        // numbered along the arc first (its ties). A strip numbered along its arc is banded, but
        // its factor fills the band (the numeric LDL^T was two thirds of an embedding).
        {
            Eigen::SparseMatrix<double> &G = w.graph;
            G.resize(nf, nf);
            G.resizeNonZeros(nf + first[nv]);
            int *go = G.outerIndexPtr(), *gi = G.innerIndexPtr();
            int gz = 0;
            for (int v : order) {
                const int sv = slot[v];
                if (sv < 0) continue;
                go[sv] = gz;
                gi[gz++] = sv;
                for (int q = first[v]; q < first[v] + fill[v]; ++q)
                    if (slot[w.adj[q].v] >= 0) gi[gz++] = slot[w.adj[q].v];
                std::sort(gi + go[sv], gi + gz);
            }
            go[nf] = gz;
            G.resizeNonZeros(gz);
            std::fill(G.valuePtr(), G.valuePtr() + gz, 1.0);
            // G is symmetric already: Eigen's AMD routine itself, without AMDOrdering's copy of
            // G^T + G (two sparse passes and allocations per embedding; the same order)
            Eigen::internal::minimum_degree_ordering(G, w.perm); // perm: new number -> old number
            std::vector<int> &byOld = w.byOld;
            byOld.resize(nf);
            for (int v : order)
                if (slot[v] >= 0) byOld[slot[v]] = v;
            order.resize(nf); // the pins drop out: columns are the free vertices only
            for (int s = 0; s < nf; ++s) slot[order[s] = byOld[w.perm.indices()[s]]] = s;
        }
        // The lower triangle of the system, column by column, straight into compressed storage;
        // pinned neighbours go to the right-hand side. The 2x2 blocks [c d; -d c] of (u, v) are
        // multiplications by the complex number c - i d: the system is Hermitian in U = u + i v,
        // half the unknowns and a quarter of the entries of the interleaved real one.
        typedef std::complex<double> C;
        Eigen::SparseMatrix<C> &A = w.A;
        w.rhs.setZero(nf);
        int nnz = 0;
        for (int v = 0; v < nv; ++v)
            if (slot[v] >= 0) {
                nnz += 1;
                for (int q = first[v]; q < first[v] + fill[v]; ++q)
                    if (slot[w.adj[q].v] > slot[v]) nnz += 1;
            }
        A.resize(nf, nf);
        A.resizeNonZeros(nnz);
        int *outer = A.outerIndexPtr(), *inner = A.innerIndexPtr();
        C *val = A.valuePtr();
        int z = 0;
        // columns in slot order: walk `order` (the pins dropped out)
        for (int v : order) {
            const int sv = slot[v];
            // neighbours after v, sorted by slot
            const int b = first[v], e = first[v] + fill[v];
            std::sort(w.adj.begin() + b, w.adj.begin() + e,
                      [&](const Workspace::Block &x, const Workspace::Block &y) { return slot[x.v] < slot[y.v]; });
            outer[sv] = z;
            // a vanishing regularization keeps degenerate triangles' vertices determined
            inner[z] = sv; val[z++] = C(w.diag[v] + 1e-12, 0);
            for (int q = b; q < e; ++q) {
                const int t = w.adj[q].v;
                const int p = pinIndex(t);
                const C h(w.adj[q].c, w.adj[q].d); // row t of column v: H(t, v) = conj(H(v, t)), H(v, t) = c - i d
                if (p >= 0) {
                    w.rhs[sv] -= std::conj(h) * C(pin[p][0], pin[p][1]);
                    continue;
                }
                if (slot[t] < sv) continue;
                inner[z] = slot[t]; val[z++] = h;
            }
        }
        outer[nf] = z;
        A.resizeNonZeros(z);
        // Symbolic analysis only when the pattern changed (the same region embedded again).
        const bool same = int(w.lastOuter.size()) == nf + 1 && std::equal(outer, outer + nf + 1, w.lastOuter.begin()) &&
                          int(w.lastInner.size()) == z && std::equal(inner, inner + z, w.lastInner.begin());
        if (!same) {
            w.solver.analyzePattern(A);
            w.lastOuter.assign(outer, outer + nf + 1);
            w.lastInner.assign(inner, inner + z);
            ++w.analyses;
        }
        w.solver.factorize(A);
        ++w.factorizations;
        if (w.solver.info() != Eigen::Success) { w.lastOuter.clear(); error = "conformal embedding: factorization failed"; return false; }
        w.sol = w.solver.solve(w.rhs);
        if (w.solver.info() != Eigen::Success || !w.sol.allFinite()) { error = "conformal embedding: solve failed"; return false; }
        for (int v = 0; v < nv; ++v) {
            int p = pinIndex(v);
            uv[v] = p >= 0 ? pin[p] : Eigen::Vector2d(w.sol[slot[v]].real(), w.sol[slot[v]].imag());
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
