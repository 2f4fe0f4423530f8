#ifndef VCG_EXT_PART_BOUNDARY_ENERGY_H
#define VCG_EXT_PART_BOUNDARY_ENERGY_H

// Part-boundary energy (issue 33): the minima rule (Hoffman & Richards; used for snakes by
// Lee, Lee, Shamir, Cohen-Or & Seidel, "Intelligent Mesh Scissoring Using 3D Snakes", PG 2004,
// and "Mesh Scissoring with Minima Rule and Part Salience", CAGD 2005): people cut a surface
// into parts along lines of negative minimum principal curvature. The energy is low on concave
// valleys and 1 on flat, convex and ridge-like ground, so a loop around a finger, an ear or an
// eye has a well to settle in at the part's base, and none in the socket or on the ridge that
// the normal-variation energy also marks (it sees any bend, convex or concave).
//
// Curvature is measured at a scale, not on one ring, so that scan noise does not make wells:
// at each vertex a quadric height field z = a x^2 + b xy + c y^2 + d x + e y + f is fitted by
// least squares to the vertices within a distance r, connected to it along edges (a geodesic
// neighbourhood, so a neighbouring finger is not mixed in), in the frame of the mean normal of
// that neighbourhood. r is a number of local edge lengths (the snake's length unit is the
// median edge along its seed path), so the fit follows meshes whose edge lengths vary. The
// signed minimum curvature k_min (outward normals: convex > 0) is made dimensionless by one
// length for the whole mesh, R = the same number of median edge lengths (not by r: see
// Concavity), so the energy is scale-free; the concavity c = max(0, -k_min R) maps to E = exp(-c / c_ref), with
// c_ref the median concavity of the concave vertices: strong valleys go to 0, flat ground
// stays at 1, whatever the mesh's size.
//
// vcglib's UpdateCurvatureFitting::updateCurvatureLocal fits the same kind of quadric in a
// sphere, but walks VF adjacency (Nring) and writes the optional curvature components: the
// feature energies read no adjacency, so that they run beside MeshLab's adjacency build on a
// second core (SnakeEnergySource::ComputeBeside), and its radius is one length for the whole
// mesh where this one follows the local edge length. The vertex graph is built here instead.

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/Dense>

#include <vcg/complex/complex.h>

namespace vcg {
namespace tri {

template <class MeshType>
class PartBoundaryEnergy
{
public:
    typedef typename MeshType::FaceType FaceType;
    typedef typename MeshType::VertexType VertexType;

    struct Param
    {
        /// Radius of the fit, in local edge lengths; each smoothing step adds `radiusPerStep`.
        /// Default smoothing (2) gives 3 edge lengths: on the benchmark's parts (bench/eval/gs_parts)
        /// 1.5, 2, 3, 4 and 6 edges captured 42, 45, 43, 22 and 11 % of the loops, 1 edge 6 % (noise
        /// wells); 3 leaves room for noisier scans.
        double radius = 1.0;
        double radiusPerStep = 1.0;
        /// At most this many vertices in a neighbourhood (the nearest along edges first).
        int maxNeighbours = 400;
        /// A vertex is flat, not concave, where its concavity is within flatTolerance times the
        /// curvature that the rounding of the coordinates alone can give its fit (the mesh
        /// scalar's epsilon times the coordinates' magnitude, through the least-squares fit: see
        /// RoundingCurvature). On planar regions (CAD faces, faces split into coplanar children)
        /// rounding tips k_min either way: on mesh 327 58 % of the vertices were "concave" at
        /// ~1e-6-1e-4 and c_ref (their median) 1e-4, so every slightly concave vertex got energy
        /// ~0; with 16, 27 % and 0.032 (session 32; the valley loop's flatTolerance is the same
        /// test on its edges). Left off (0, the sign of k_min alone): 16 changes no CAD-like nor
        /// refined row but moves rows that flip with any change of the energy at 1e-3 (the 9
        /// meshes 167 / 168, graded 165 / 167, noise 101 / 102; docs/method.md, session 32).
        double flatTolerance = 0;
    };

    /// Per-vertex energy in [0,1] (low = concave valley), indexed like m.vert (deleted: 1).
    /// Needs up-to-date vertex normals; reads no adjacency (the vertex graph is built here).
    static std::vector<double> VertexValues(const MeshType &m, int smoothingSteps, const Param &par = Param())
    {
        const std::vector<double> c = Concavity(m, par.radius + par.radiusPerStep * std::max(0, smoothingSteps), par);
        std::vector<double> pos;
        for (double x : c)
            if (x > 0) pos.push_back(x);
        double ref = 0;
        if (!pos.empty()) {
            std::nth_element(pos.begin(), pos.begin() + pos.size() / 2, pos.end());
            ref = pos[pos.size() / 2];
        }
        std::vector<double> e(c.size(), 1.0);
        if (!(ref > 0)) return e; // no concave vertex: flat energy
        for (size_t i = 0; i < c.size(); ++i) e[i] = std::exp(-c[i] / ref);
        return e;
    }

    /// max(0, -k_min * R) per vertex: the concavity fitted at the scale r (radiusInEdges local
    /// edge lengths), made dimensionless by R (radiusInEdges median edge lengths of the mesh).
    static std::vector<double> Concavity(const MeshType &m, double radiusInEdges, const Param &par = Param())
    {
        const int nv = int(m.vert.size());
        std::vector<int> start, nbr;
        Graph(m, start, nbr);
        // local edge length: mean of the incident edges
        std::vector<double> le(nv, 0.0);
        for (int v = 0; v < nv; ++v) {
            double s = 0;
            for (int k = start[v]; k < start[v + 1]; ++k) s += vcg::Distance(pos(m, v), pos(m, nbr[k]));
            le[v] = start[v + 1] > start[v] ? s / (start[v + 1] - start[v]) : 0;
        }
        const double sign = OutwardSign(m);
        // One length for the whole mesh makes the curvature dimensionless: the same valley then
        // has the same depth wherever it is measured from. Each vertex's own fit radius would
        // multiply it by the local edge length, so that beside a valley whose tessellation is
        // graded 20x the coarse side's broad fits read 20x deeper than the valley itself, and a
        // loop slid there (test ValleyLoop.EndsOnTheValleyWhereEdgeLengthsVary20x).
        std::vector<double> ls;
        for (int v = 0; v < nv; ++v)
            if (!m.vert[v].IsD() && le[v] > 0) ls.push_back(le[v]);
        double hg = 0;
        if (!ls.empty()) {
            std::nth_element(ls.begin(), ls.begin() + ls.size() / 2, ls.end());
            hg = ls[ls.size() / 2];
        }
        const double R = radiusInEdges * hg; // the fit radius on a median edge
        std::vector<double> out(nv, 0.0);
        std::vector<int> mark(nv, -1), ring;
        for (int v = 0; v < nv; ++v) {
            if (m.vert[v].IsD() || !(le[v] > 0)) continue;
            // the neighbourhood's own edge scale (one ring's mean): the radius follows the mesh
            double h = le[v];
            for (int k = start[v]; k < start[v + 1]; ++k) h += le[nbr[k]];
            h /= 1 + start[v + 1] - start[v];
            const double r = radiusInEdges * h;
            const vcg::Point3d o = pos(m, v);
            ring.clear();
            ring.push_back(v);
            mark[v] = v;
            for (size_t q = 0; q < ring.size() && int(ring.size()) < par.maxNeighbours; ++q)
                for (int k = start[ring[q]]; k < start[ring[q] + 1]; ++k) {
                    const int w = nbr[k];
                    if (mark[w] == v || vcg::Distance(pos(m, w), o) > r) continue;
                    mark[w] = v;
                    ring.push_back(w);
                }
            if (ring.size() < 7) continue;
            vcg::Point3d n(0, 0, 0);
            for (int w : ring) n += vcg::Point3d::Construct(m.vert[w].cN());
            if (!(n.Norm() > 0)) continue;
            n.Normalize();
            vcg::Point3d t1 = (std::fabs(n[0]) < 0.9 ? vcg::Point3d(1, 0, 0) : vcg::Point3d(0, 1, 0)) ^ n;
            t1.Normalize();
            const vcg::Point3d t2 = n ^ t1;
            Eigen::Matrix<double, 6, 6> A = Eigen::Matrix<double, 6, 6>::Zero();
            Eigen::Matrix<double, 6, 1> b = Eigen::Matrix<double, 6, 1>::Zero();
            for (int w : ring) {
                const vcg::Point3d d = (pos(m, w) - o) / r; // unit-free coordinates
                const double x = d * t1, y = d * t2, z = d * n;
                Eigen::Matrix<double, 6, 1> row;
                row << x * x, x * y, y * y, x, y, 1;
                A += row * row.transpose();
                b += row * z;
            }
            A.diagonal().array() += 1e-9;
            const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> ldlt(A);
            const Eigen::Matrix<double, 6, 1> s = ldlt.solve(b);
            if (!s.allFinite()) continue;
            // shape operator of the height field at the origin (first-order terms small in
            // the mean-normal frame); convex (z falling away along the outward normal) > 0
            Eigen::Matrix2d H;
            H << -2 * s[0], -s[1], -s[1], -2 * s[2];
            H *= sign;
            const double kmin = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(H, Eigen::EigenvaluesOnly).eigenvalues()[0];
            if (par.flatTolerance > 0 && -kmin > 0 && -kmin <= par.flatTolerance * RoundingCurvature(m, ring, o, r, t1, t2, ldlt))
                continue; // flat: concavity within the coordinates' rounding
            // kmin is in units of 1/r (the coordinates were divided by r): times R / r
            out[v] = std::max(0.0, -kmin) * (R / r);
        }
        return out;
    }

    /// +1 when the faces are oriented outwards (positive enclosed volume), else -1.
    static double OutwardSign(const MeshType &m)
    {
        double vol = 0;
        for (const FaceType &f : m.face) {
            if (f.IsD()) continue;
            const vcg::Point3d a = vcg::Point3d::Construct(f.cP(0)), b = vcg::Point3d::Construct(f.cP(1)),
                               c = vcg::Point3d::Construct(f.cP(2));
            vol += a * (b ^ c);
        }
        return vol < 0 ? -1.0 : 1.0;
    }

    /// The largest k_min (units of 1/r, like the fit's) that the rounding of the coordinates
    /// alone can give the fit of `ring` (Param::flatTolerance): each height in the unit-free
    /// frame is off by up to sigma = epsilon x magnitude / r (the mesh's scalar, the largest
    /// coordinate of the neighbourhood); the quadric's coefficients are linear in the heights,
    /// s = A^-1 sum(row_w z_w), so each is off by up to sigma sum_w |(A^-1 row_w)_j|, and the
    /// eigenvalues of H = -[2a b; b 2c] by up to 2 max(|da|, |dc|) + |db|.
    static double RoundingCurvature(const MeshType &m, const std::vector<int> &ring, const vcg::Point3d &o, double r,
                                    const vcg::Point3d &t1, const vcg::Point3d &t2,
                                    const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> &ldlt)
    {
        typedef typename MeshType::ScalarType S;
        double mag = 0;
        for (int w : ring)
            for (int d = 0; d < 3; ++d) mag = std::max(mag, std::abs(double(m.vert[w].cP()[d])));
        const double sigma = double(std::numeric_limits<S>::epsilon()) * mag / r;
        const Eigen::Matrix<double, 6, 6> Ai = ldlt.solve(Eigen::Matrix<double, 6, 6>::Identity());
        Eigen::Matrix<double, 3, 1> ds = Eigen::Matrix<double, 3, 1>::Zero(); // |d a|, |d b|, |d c| per unit sigma
        for (int w : ring) {
            const vcg::Point3d d = (pos(m, w) - o) / r;
            const double x = d * t1, y = d * t2;
            Eigen::Matrix<double, 6, 1> row;
            row << x * x, x * y, y * y, x, y, 1;
            ds += (Ai.template topRows<3>() * row).cwiseAbs();
        }
        return sigma * (2 * std::max(ds[0], ds[2]) + ds[1]);
    }

private:
    static vcg::Point3d pos(const MeshType &m, int v) { return vcg::Point3d::Construct(m.vert[v].cP()); }

    /// Vertex neighbours from the faces (compressed rows, each neighbour once).
    static void Graph(const MeshType &m, std::vector<int> &start, std::vector<int> &nbr)
    {
        const int nv = int(m.vert.size());
        std::vector<std::pair<int, int>> e;
        e.reserve(m.face.size() * 6);
        for (const FaceType &f : m.face) {
            if (f.IsD()) continue;
            for (int k = 0; k < 3; ++k) {
                const int a = int(f.cV(k) - &m.vert[0]), b = int(f.cV((k + 1) % 3) - &m.vert[0]);
                if (a == b) continue;
                e.push_back({a, b});
                e.push_back({b, a});
            }
        }
        std::sort(e.begin(), e.end());
        e.erase(std::unique(e.begin(), e.end()), e.end());
        start.assign(nv + 1, 0);
        for (const auto &x : e) ++start[x.first + 1];
        for (int v = 0; v < nv; ++v) start[v + 1] += start[v];
        nbr.resize(e.size());
        for (size_t i = 0; i < e.size(); ++i) nbr[i] = e[i].second;
    }
};

} // namespace tri
} // namespace vcg

#endif
