#ifndef VCG_EXT_SNAKE_SPLINE_H
#define VCG_EXT_SNAKE_SPLINE_H

#include <map>
#include <memory>
#include <tuple>
#include <vector>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

namespace vcg {
namespace tri {

/// The internal spline energy of a sampled snake (Eq. 2) and the semi-implicit update of Eq. 4,
///     x_t = (A + gamma I)^-1 (gamma x_{t-1} - f_x),
/// with A = alpha D1^T D1 + beta D2^T D2 from first/second finite differences over sample
/// indices. Closed snakes use cyclic differences. Open snakes use natural (free) ends: the
/// difference terms that would need samples beyond the ends are dropped, so an end moves
/// under the feature force and the curve's own tension/rigidity only.
/// Fixed samples are Dirichlet constraints: eliminated from the system, so they are held
/// exactly. (A + gamma I) restricted to the free samples is symmetric positive definite; it
/// is factored once (sparse LDL^T, never a dense inverse) per change of length, parameters
/// or fixed set and then reused by every update.
class SnakeSpline
{
public:
    typedef Eigen::SparseMatrix<double> SpMat;

    /// A = alpha D1^T D1 + beta D2^T D2 (n x n).
    static SpMat StiffnessMatrix(int n, bool closed, double alpha, double beta)
    {
        std::vector<Eigen::Triplet<double>> t;
        auto addTerm = [&](const std::vector<int> &idx, const std::vector<double> &c, double w) {
            // w * c c^T on the given indices: the Hessian of w/2 (c . x_idx)^2
            for (size_t a = 0; a < idx.size(); ++a)
                for (size_t b = 0; b < idx.size(); ++b) t.emplace_back(idx[a], idx[b], w * c[a] * c[b]);
        };
        if (n >= 2 && alpha != 0) {
            int edges = closed ? n : n - 1;
            for (int i = 0; i < edges; ++i) addTerm({i, (i + 1) % n}, {-1.0, 1.0}, alpha);
        }
        if (n >= 3 && beta != 0) {
            int first = closed ? 0 : 1, last = closed ? n - 1 : n - 2;
            for (int i = first; i <= last; ++i) addTerm({(i - 1 + n) % n, i, (i + 1) % n}, {1.0, -2.0, 1.0}, beta);
        }
        SpMat A(n, n);
        A.setFromTriplets(t.begin(), t.end());
        return A;
    }

    /// Spline energy (Eq. 2 summed over samples), for tests: sum alpha/2|D1 x|^2 + beta/2|D2 x|^2.
    static double Energy(const Eigen::MatrixXd &X, bool closed, double alpha, double beta)
    {
        int n = int(X.rows());
        double e = 0;
        if (n >= 2) {
            int edges = closed ? n : n - 1;
            for (int i = 0; i < edges; ++i) e += 0.5 * alpha * (X.row((i + 1) % n) - X.row(i)).squaredNorm();
        }
        if (n >= 3) {
            int first = closed ? 0 : 1, last = closed ? n - 1 : n - 2;
            for (int i = first; i <= last; ++i)
                e += 0.5 * beta * (X.row((i - 1 + n) % n) - 2 * X.row(i) + X.row((i + 1) % n)).squaredNorm();
        }
        return e;
    }

    SnakeSpline() = default;

    /// Factors (A + gamma I) for the free samples. Cheap if nothing changed since last time.
    void Setup(int n, bool closed, double alpha, double beta, double gamma, const std::vector<bool> &fixed)
    {
        if (factor && n == n_ && closed == closed_ && alpha == alpha_ && beta == beta_ && gamma == gamma_ &&
            fixed == fixed_)
            return;
        n_ = n; closed_ = closed; alpha_ = alpha; beta_ = beta; gamma_ = gamma; fixed_ = fixed;
        ++factorizations;
        SpMat M = StiffnessMatrix(n, closed, alpha, beta);
        for (int i = 0; i < n; ++i) M.coeffRef(i, i) += gamma;
        freeIdx.clear();
        slot.assign(n, -1);
        for (int i = 0; i < n; ++i)
            if (!fixed[i]) { slot[i] = int(freeIdx.size()); freeIdx.push_back(i); }
        int nf = int(freeIdx.size());
        std::vector<Eigen::Triplet<double>> tf, tc;
        for (int k = 0; k < M.outerSize(); ++k)
            for (SpMat::InnerIterator it(M, k); it; ++it) {
                int r = int(it.row()), c = int(it.col());
                if (slot[r] < 0) continue;
                if (slot[c] >= 0) tf.emplace_back(slot[r], slot[c], it.value());
                else tc.emplace_back(slot[r], c, it.value());
            }
        Mff.resize(nf, nf);
        Mff.setFromTriplets(tf.begin(), tf.end());
        Mfc.resize(nf, n);
        Mfc.setFromTriplets(tc.begin(), tc.end());
        factor = std::make_unique<Eigen::SimplicialLDLT<SpMat>>();
        if (nf > 0) factor->compute(Mff);
    }

    /// One step of Eq. 4 for all columns of X (2 for the plane, 3 for space); F = f_x.
    /// Fixed rows are returned unchanged.
    Eigen::MatrixXd Update(const Eigen::MatrixXd &X, const Eigen::MatrixXd &F) const
    {
        Eigen::MatrixXd out;
        Update(X, F, out);
        return out;
    }
    /// The same into `out`; no allocation once the sizes repeat (the snake's steady state).
    void Update(const Eigen::MatrixXd &X, const Eigen::MatrixXd &F, Eigen::MatrixXd &out) const
    {
        out = X;
        if (freeIdx.empty()) return;
        rhs_.resize(Eigen::Index(freeIdx.size()), X.cols());
        for (size_t k = 0; k < freeIdx.size(); ++k) rhs_.row(k) = gamma_ * X.row(freeIdx[k]) - F.row(freeIdx[k]);
        rhs_.noalias() -= Mfc * X; // fixed samples' coupling moves to the right-hand side
        sol_ = factor->solve(rhs_);
        for (size_t k = 0; k < freeIdx.size(); ++k) out.row(freeIdx[k]) = sol_.row(k);
    }

    bool Ok() const { return factor && (freeIdx.empty() || factor->info() == Eigen::Success); }
    int factorizations = 0;

private:
    int n_ = -1;
    bool closed_ = false;
    double alpha_ = 0, beta_ = 0, gamma_ = 0;
    std::vector<bool> fixed_;
    std::vector<int> freeIdx, slot;
    SpMat Mff, Mfc;
    mutable Eigen::MatrixXd rhs_, sol_; // Update's scratch
    std::unique_ptr<Eigen::SimplicialLDLT<SpMat>> factor;
};

/// The factored spline systems of a snake, by size, closure and pins (the matrix of Eq. 4
/// depends on nothing else): reused across updates and operations.
class SnakeSplineCache
{
public:
    SnakeSpline &For(int k, bool closed, double alpha, double beta, double gamma, const std::vector<bool> &fixed)
    {
        auto key = std::make_tuple(k, closed, fixed);
        if (splines.size() > 64) splines.clear();
        SnakeSpline &s = splines[key];
        s.Setup(k, closed, alpha, beta, gamma, fixed);
        return s;
    }
    void Clear() { splines.clear(); }

private:
    std::map<std::tuple<int, bool, std::vector<bool>>, SnakeSpline> splines;
};

} // namespace tri
} // namespace vcg

#endif
