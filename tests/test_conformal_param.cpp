// The local embedding's solver (ConformalParam, least-squares conformal map): it solves the
// Hermitian system in one complex unknown per vertex. Checked against an independent dense
// least-squares solve of the same energy in real unknowns (u, v), on curved regions, where the
// map is not a similarity and every term of the system (the border's area term included)
// shows in the result.
#include <gtest/gtest.h>

#include <complex>

#include <Eigen/Dense>

#include <generated_meshes.h>
#include <snake_test_util.h>

using namespace vcg::tri;

namespace {

/// argmin sum_T |sum_k W_k U_k|^2 / (2 A_T) with U = u + i v, the pinned vertices held at
/// their given positions: dense least squares, one complex residual (two real rows) per triangle.
std::vector<Eigen::Vector2d> DenseConformal(const std::vector<vcg::Point3d> &pos, const std::vector<std::array<int, 3>> &tri,
                                            const std::vector<std::pair<int, Eigen::Vector2d>> &pins)
{
    const int nv = int(pos.size());
    std::vector<int> col(nv, -1);
    int n = 0;
    for (int v = 0; v < nv; ++v)
        if (std::none_of(pins.begin(), pins.end(), [&](const auto &p) { return p.first == v; })) col[v] = n++;
    Eigen::MatrixXd M = Eigen::MatrixXd::Zero(2 * tri.size(), 2 * n);
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(2 * tri.size());
    for (size_t t = 0; t < tri.size(); ++t) {
        const auto &T = tri[t];
        const vcg::Point3d e1 = pos[T[1]] - pos[T[0]], e2 = pos[T[2]] - pos[T[0]];
        const double a2 = (e1 ^ e2).Norm();
        const vcg::Point3d x = e1 / e1.Norm(), y = ((e1 ^ e2) / a2) ^ x;
        const std::complex<double> w[3] = {{0, 0}, {e1.Norm(), 0}, {e2 * x, e2 * y}};
        for (int k = 0; k < 3; ++k) {
            const std::complex<double> W = (w[(k + 2) % 3] - w[(k + 1) % 3]) / std::sqrt(a2);
            // W (u + i v) = (Re W u - Im W v) + i (Im W u + Re W v)
            const int v = T[k];
            if (col[v] >= 0) {
                M(2 * t, 2 * col[v]) += W.real(), M(2 * t, 2 * col[v] + 1) -= W.imag();
                M(2 * t + 1, 2 * col[v]) += W.imag(), M(2 * t + 1, 2 * col[v] + 1) += W.real();
            } else {
                const Eigen::Vector2d p = std::find_if(pins.begin(), pins.end(), [&](const auto &q) { return q.first == v; })->second;
                const std::complex<double> r = W * std::complex<double>(p.x(), p.y());
                rhs[2 * t] -= r.real(), rhs[2 * t + 1] -= r.imag();
            }
        }
    }
    const Eigen::VectorXd s = M.colPivHouseholderQr().solve(rhs);
    std::vector<Eigen::Vector2d> uv(nv);
    for (int v = 0; v < nv; ++v)
        uv[v] = col[v] >= 0 ? Eigen::Vector2d(s[2 * col[v]], s[2 * col[v] + 1])
                            : std::find_if(pins.begin(), pins.end(), [&](const auto &q) { return q.first == v; })->second;
    return uv;
}

struct Region
{
    CMeshO m;
    LocalRegion<CMeshO> r;
};

/// A band of faces of the unit icosphere around a circle of latitude `z0` (strongly curved,
/// so the conformal map distorts), as a LocalRegion with a margin of `margin` edge lengths.
void SphereBand(Region &g, int subdiv, double z0, double margin)
{
    gs_test::MakeIcosphere(g.m, subdiv);
    gs_test::EnableSnakeAdjacency(g.m);
    for (auto &v : g.m.vert) v.Q() = 1;
    SnakeSurface<CMeshO> surf(g.m);
    std::vector<int> core;
    for (size_t i = 0; i < g.m.face.size(); ++i) {
        const vcg::Point3d b = vcg::Point3d::Construct(vcg::Barycenter(g.m.face[i]));
        if (std::abs(b[2] - z0) < 0.05 && b[0] > 0 && b[1] > -0.2) core.push_back(int(i));
    }
    ASSERT_FALSE(core.empty());
    ASSERT_TRUE(g.r.Build(surf, core, 60000, margin * surf.MeanEdge())) << g.r.error;
}

} // namespace

TEST(ConformalParam, MatchesADenseSolveOfTheSameEnergyOnCurvedRegions)
{
    for (const auto &c : {std::make_tuple(3, 0.0, 0.0), std::make_tuple(3, 0.6, 2.0), std::make_tuple(4, -0.3, 3.0)}) {
        Region g;
        SphereBand(g, std::get<0>(c), std::get<1>(c), std::get<2>(c));
        if (HasFatalFailure()) return;
        const LocalRegion<CMeshO> &r = g.r;
        const int realFaces = r.RealFaces();
        std::vector<Eigen::Vector2d> uv;
        std::string err;
        ConformalParam::Workspace w;
        const double unit = 0.1;
        ASSERT_TRUE(ConformalParam::Embed(r.pos, r.tri, r.boundary, unit, uv, err, w, nullptr)) << err;
        EXPECT_EQ(VirtualBoundaryParam::CountFlipped(uv, r.tri), 0);
        // the pins: the vertex at the origin and the one on the positive x axis
        int p0 = -1, p1 = -1;
        double size = 0;
        for (int v = 0; v < int(uv.size()); ++v) {
            if (uv[v] == Eigen::Vector2d(0, 0)) p0 = v;
            else if (uv[v].y() == 0 && uv[v].x() > 0) p1 = v;
            size = std::max(size, uv[v].norm());
        }
        ASSERT_GE(p0, 0);
        ASSERT_GE(p1, 0);
        const std::vector<Eigen::Vector2d> ref = DenseConformal(r.pos, r.tri, {{p0, uv[p0]}, {p1, uv[p1]}});
        double worst = 0, bend = 0;
        for (size_t v = 0; v < uv.size(); ++v) worst = std::max(worst, (uv[v] - ref[v]).norm());
        // the map is far from a similarity here: a face's embedded edge ratio differs from 3D
        for (int t = 0; t < realFaces; ++t) {
            const auto &T = r.tri[t];
            const double l3 = (r.pos[T[1]] - r.pos[T[0]]).Norm() / (r.pos[T[2]] - r.pos[T[0]]).Norm();
            const double l2 = (uv[T[1]] - uv[T[0]]).norm() / (uv[T[2]] - uv[T[0]]).norm();
            bend = std::max(bend, std::abs(std::log(l2 / l3)));
        }
        std::printf("subdiv %d z0 %.1f: %zu vertices, %d faces, largest difference %.3g of the size, edge ratios off by up to %.3f\n",
                    std::get<0>(c), std::get<1>(c), uv.size(), realFaces, worst / size, bend);
        // the solver's vanishing regularization (1e-12 on the diagonal) and the system's
        // conditioning leave about 1e-8; an assembly error (a sign, a conjugate) gives O(1)
        EXPECT_LT(worst, 1e-6 * size);
        EXPECT_GT(bend, 1e-3);
    }
}
