#ifndef GS_TESTS_GENERATED_MESHES_H
#define GS_TESTS_GENERATED_MESHES_H

// Synthetic meshes with known features for tests and benchmarks, plus loading/subdivision.
// Header-only. It compiles vcglib's wrap/ply/plylib.cpp into the including translation unit
// (every test/bench is a single .cpp executable); define GS_TEST_NO_PLYLIB before including
// it if your .cpp already includes plylib.cpp.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/create/platonic.h>
#include <vcg/complex/algorithms/refine.h>
#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/complex/algorithms/update/topology.h>
#include <wrap/io_trimesh/import.h>
#include <wrap/io_trimesh/export.h>

#if !defined(GS_TEST_NO_PLYLIB) && !defined(GS_TEST_PLYLIB_INCLUDED)
#define GS_TEST_PLYLIB_INCLUDED
#include <wrap/ply/plylib.cpp>
#endif

namespace gs_test {

namespace detail {

// Ocf containers (CMeshO) need FF adjacency switched on before vcglib's Refine can use it.
template <class C>
auto TryEnableFF(C &c, int) -> decltype(c.EnableFFAdjacency(), bool())
{
    if (!c.IsFFAdjacencyEnabled()) c.EnableFFAdjacency();
    return true;
}
template <class C>
bool TryEnableFF(C &, long)
{
    return false;
}

template <class M>
void Finalize(M &m)
{
    vcg::tri::Allocator<M>::CompactEveryVector(m);
    if (vcg::tri::HasPerFaceNormal(m)) vcg::tri::UpdateNormal<M>::PerFaceNormalized(m);
    if (vcg::tri::HasPerVertexNormal(m)) {
        vcg::tri::UpdateNormal<M>::PerVertexAngleWeighted(m);
        vcg::tri::UpdateNormal<M>::NormalizePerVertex(m);
    }
    vcg::tri::UpdateBounding<M>::Box(m);
}

// Fixed, non axis-aligned rotation (axis (1,2,3), 0.7 rad) so the icosphere's triangles
// straddle the edges of whatever polyhedron it is projected on.
inline vcg::Point3d Rotate(const vcg::Point3d &p)
{
    vcg::Point3d a(1, 2, 3);
    a.Normalize();
    const double th = 0.7, c = std::cos(th), s = std::sin(th);
    return p * c + (a ^ p) * s + a * ((a * p) * (1 - c));
}

template <class M, class Proj>
void MakeProjectedIcosphere(M &m, int subdiv, Proj proj)
{
    m.Clear();
    vcg::tri::Sphere(m, subdiv);
    for (auto &v : m.vert) {
        if (v.IsD()) continue;
        const vcg::Point3d p = proj(Rotate(vcg::Point3d::Construct(v.cP())));
        v.P() = M::CoordType::Construct(p);
    }
    Finalize(m);
}

inline double DistToSegment(const vcg::Point3d &p, const vcg::Point3d &a, const vcg::Point3d &b)
{
    const vcg::Point3d d = b - a;
    double t = ((p - a) * d) / d.SquaredNorm();
    t = std::max(0.0, std::min(1.0, t));
    return vcg::Distance(p, a + d * t);
}

} // namespace detail

/// Unit icosphere (vcg::tri::Sphere), 20*4^subdiv faces.
template <class M>
void MakeIcosphere(M &m, int subdiv)
{
    m.Clear();
    vcg::tri::Sphere(m, subdiv);
    detail::Finalize(m);
}

/// Rotated icosphere projected radially onto the cube [-half,half]^3: its sharp edges cut
/// through triangles, like a scanned CAD part.
template <class M>
void MakeRotatedIcoCube(M &m, int subdiv, double half = 1.0)
{
    detail::MakeProjectedIcosphere(m, subdiv, [half](const vcg::Point3d &p) {
        const double mx = std::max(std::fabs(p[0]), std::max(std::fabs(p[1]), std::fabs(p[2])));
        return p / mx * half;
    });
}

/// Same, projected radially onto the octahedron |x|+|y|+|z| = r.
template <class M>
void MakeRotatedIcoOctahedron(M &m, int subdiv, double r = 1.0)
{
    detail::MakeProjectedIcosphere(m, subdiv, [r](const vcg::Point3d &p) {
        return p / (std::fabs(p[0]) + std::fabs(p[1]) + std::fabs(p[2])) * r;
    });
}

/// Same, projected radially onto the capped cylinder x^2+y^2 <= radius^2, |z| <= halfHeight.
/// The rims at z = +-halfHeight are the features.
template <class M>
void MakeRotatedIcoCylinder(M &m, int subdiv, double radius = 1.0, double halfHeight = 1.0)
{
    detail::MakeProjectedIcosphere(m, subdiv, [radius, halfHeight](const vcg::Point3d &p) {
        const double rho = std::sqrt(p[0] * p[0] + p[1] * p[1]);
        double t = std::numeric_limits<double>::max();
        if (rho > 0) t = radius / rho;
        if (std::fabs(p[2]) > 0) t = std::min(t, halfHeight / std::fabs(p[2]));
        return p * t;
    });
}

/// Flat grid in the z = 0 plane covering [0,size]^2, n x n quads each split in two triangles.
template <class M>
void MakeFlatGrid(M &m, int n, double size = 1.0)
{
    typedef typename M::CoordType C;
    m.Clear();
    auto vi = vcg::tri::Allocator<M>::AddVertices(m, (n + 1) * (n + 1));
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) m.vert[j * (n + 1) + i].P() = C(size * i / n, size * j / n, 0);
    (void)vi;
    vcg::tri::Allocator<M>::AddFaces(m, 2 * n * n);
    int f = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            auto *a = &m.vert[j * (n + 1) + i], *b = &m.vert[j * (n + 1) + i + 1];
            auto *c = &m.vert[(j + 1) * (n + 1) + i + 1], *d = &m.vert[(j + 1) * (n + 1) + i];
            m.face[f].V(0) = a, m.face[f].V(1) = b, m.face[f].V(2) = c, ++f;
            m.face[f].V(0) = a, m.face[f].V(1) = c, m.face[f].V(2) = d, ++f;
        }
    detail::Finalize(m);
}

/// Flat plate in the z = 0 plane: nx x ny cells of cellX x cellY (anisotropic when they
/// differ), each split in two triangles. With jitter > 0 every vertex moves randomly by up to
/// jitter * min(cellX, cellY) in x and y (in x only on row `straightRow`, which stays a
/// straight mesh line) and each cell takes a random diagonal: an irregular triangulation.
template <class M>
void MakeGridPlate(M &m, int nx, int ny, double cellX, double cellY, double jitter = 0, unsigned seed = 1,
                   int straightRow = -1)
{
    typedef typename M::CoordType C;
    m.Clear();
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> U(-1, 1);
    const double amp = jitter * std::min(cellX, cellY);
    vcg::tri::Allocator<M>::AddVertices(m, (nx + 1) * (ny + 1));
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) {
            double x = cellX * i, y = cellY * j;
            if (amp > 0) {
                if (i > 0 && i < nx) x += amp * U(rng);
                if (j > 0 && j < ny && j != straightRow) y += amp * U(rng);
            }
            m.vert[j * (nx + 1) + i].P() = C(x, y, 0);
        }
    vcg::tri::Allocator<M>::AddFaces(m, 2 * nx * ny);
    int f = 0;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            auto *a = &m.vert[j * (nx + 1) + i], *b = &m.vert[j * (nx + 1) + i + 1];
            auto *c = &m.vert[(j + 1) * (nx + 1) + i + 1], *d = &m.vert[(j + 1) * (nx + 1) + i];
            if (amp > 0 && U(rng) < 0) { // the other diagonal
                m.face[f].V(0) = a, m.face[f].V(1) = b, m.face[f].V(2) = d, ++f;
                m.face[f].V(0) = b, m.face[f].V(1) = c, m.face[f].V(2) = d, ++f;
            } else {
                m.face[f].V(0) = a, m.face[f].V(1) = b, m.face[f].V(2) = c, ++f;
                m.face[f].V(0) = a, m.face[f].V(1) = c, m.face[f].V(2) = d, ++f;
            }
        }
    detail::Finalize(m);
}

/// Flat square plate [0,size]^2 (n x n cells) with a smooth Gaussian bump of the given height
/// and width (standard deviation) at its centre: a smooth feature with no rim.
template <class M>
void MakeBumpPlate(M &m, int n, double size, double height, double sigma)
{
    MakeGridPlate(m, n, n, size / n, size / n);
    for (auto &v : m.vert) {
        if (v.IsD()) continue;
        const double x = v.cP()[0] - size / 2, y = v.cP()[1] - size / 2;
        v.P()[2] = typename M::ScalarType(height * std::exp(-(x * x + y * y) / (2 * sigma * sigma)));
    }
    detail::Finalize(m);
}

/// Grid plate (MakeGridPlate) lifted to the height field z = height(x, y): creases where the
/// field's slope jumps, e.g. a chamfered step or a circular plateau. Its triangles straddle
/// any crease that is not a mesh line.
template <class M, class HeightFn>
void MakeHeightPlate(M &m, int nx, int ny, double cellX, double cellY, double jitter, unsigned seed, HeightFn height)
{
    MakeGridPlate(m, nx, ny, cellX, cellY, jitter, seed);
    for (auto &v : m.vert)
        if (!v.IsD()) v.P()[2] = typename M::ScalarType(height(double(v.cP()[0]), double(v.cP()[1])));
    detail::Finalize(m);
}

/// The rotated icosphere of MakeRotatedIcoCube with its vertices graded before the projection:
/// a conformal (Moebius) map of the sphere crowds them towards one pole, so edge lengths vary
/// `ratio` times between the finest and the coarsest part of the cube (like an adaptive remesh).
template <class M>
void MakeGradedIcoCube(M &m, int subdiv, double ratio, double half = 1.0)
{
    // stereographic projection from the south pole, scaling by k, back: lengths at the north
    // pole shrink by k and at the south pole grow by k, k^2 = ratio in all
    const double k = std::sqrt(ratio);
    detail::MakeProjectedIcosphere(m, subdiv, [half, k](const vcg::Point3d &q) {
        vcg::Point3d p = q / q.Norm();
        const double den = 1 + p[2];
        vcg::Point3d g = p;
        if (den > 1e-12) {
            const double X = p[0] / den / k, Y = p[1] / den / k, r2 = X * X + Y * Y;
            g = vcg::Point3d(2 * X, 2 * Y, 1 - r2) / (1 + r2);
        }
        g = detail::Rotate(g); // the fine pole away from any symmetry of the cube
        const double mx = std::max(std::fabs(g[0]), std::max(std::fabs(g[1]), std::fabs(g[2])));
        return g / mx * half;
    });
}

/// Median length of the mesh's edges (each counted from every face that has it).
template <class M>
double MedianEdgeLength(const M &m)
{
    std::vector<double> l;
    for (const auto &f : m.face)
        if (!f.IsD())
            for (int k = 0; k < 3; ++k)
                l.push_back(vcg::Distance(vcg::Point3d::Construct(f.cP(k)), vcg::Point3d::Construct(f.cP((k + 1) % 3))));
    if (l.empty()) return 0;
    std::nth_element(l.begin(), l.begin() + l.size() / 2, l.end());
    return l[l.size() / 2];
}

/// Moves every vertex by fractionOfMeanEdge * (mean edge length) along a random direction
/// (deterministic for a given seed).
template <class M>
void AddVertexNoise(M &m, double fractionOfMeanEdge, unsigned seed)
{
    double sum = 0;
    size_t cnt = 0;
    for (const auto &f : m.face)
        if (!f.IsD())
            for (int k = 0; k < 3; ++k, ++cnt)
                sum += vcg::Distance(vcg::Point3d::Construct(f.cV(k)->cP()),
                                     vcg::Point3d::Construct(f.cV((k + 1) % 3)->cP()));
    const double amp = cnt ? fractionOfMeanEdge * sum / double(cnt) : 0.0;
    std::mt19937 rng(seed);
    std::normal_distribution<double> g(0.0, 1.0);
    for (auto &v : m.vert) {
        if (v.IsD()) continue;
        vcg::Point3d d;
        do {
            d = vcg::Point3d(g(rng), g(rng), g(rng));
        } while (d.Norm() < 1e-9);
        d.Normalize();
        v.P() = M::CoordType::Construct(vcg::Point3d::Construct(v.cP()) + d * amp);
    }
    detail::Finalize(m);
}

/// Exact distance from p to the 12 edges of the cube [-half,half]^3.
inline double DistToCubeEdges(const vcg::Point3d &p, double half = 1.0)
{
    double best = std::numeric_limits<double>::max();
    for (int axis = 0; axis < 3; ++axis)
        for (int s1 = -1; s1 <= 1; s1 += 2)
            for (int s2 = -1; s2 <= 1; s2 += 2) {
                vcg::Point3d a, b;
                const int u = (axis + 1) % 3, w = (axis + 2) % 3;
                a[axis] = -half, b[axis] = half;
                a[u] = b[u] = s1 * half;
                a[w] = b[w] = s2 * half;
                best = std::min(best, detail::DistToSegment(p, a, b));
            }
    return best;
}

/// Exact distance from p to the 12 edges of the octahedron |x|+|y|+|z| = r.
inline double DistToOctahedronEdges(const vcg::Point3d &p, double r = 1.0)
{
    std::vector<vcg::Point3d> tips;
    for (int axis = 0; axis < 3; ++axis)
        for (int s = -1; s <= 1; s += 2) {
            vcg::Point3d t(0, 0, 0);
            t[axis] = s * r;
            tips.push_back(t);
        }
    double best = std::numeric_limits<double>::max();
    for (size_t i = 0; i < tips.size(); ++i)
        for (size_t j = i + 1; j < tips.size(); ++j)
            if (std::fabs(tips[i] * tips[j]) < 1e-12) best = std::min(best, detail::DistToSegment(p, tips[i], tips[j]));
    return best;
}

/// Exact distance from p to the two rim circles (radius, z = +-halfHeight) of the capped cylinder.
inline double DistToCylinderRims(const vcg::Point3d &p, double radius = 1.0, double halfHeight = 1.0)
{
    const double rho = std::sqrt(p[0] * p[0] + p[1] * p[1]);
    const double dr = rho - radius;
    return std::min(std::sqrt(dr * dr + (p[2] - halfHeight) * (p[2] - halfHeight)),
                    std::sqrt(dr * dr + (p[2] + halfHeight) * (p[2] + halfHeight)));
}

/// vcglib importer (ply/off/obj, by extension), then duplicate/unreferenced vertex removal,
/// normals and bbox. Returns false if the file cannot be read.
template <class M>
bool LoadMesh(M &m, const std::string &path)
{
    m.Clear();
    int mask = 0;
    const int err = vcg::tri::io::Importer<M>::Open(m, path.c_str(), mask);
    if (err != 0 && vcg::tri::io::Importer<M>::ErrorCritical(err)) return false;
    vcg::tri::Clean<M>::RemoveDuplicateVertex(m);
    vcg::tri::Clean<M>::RemoveDegenerateFace(m); // welding can make faces repeat a vertex
    vcg::tri::Clean<M>::RemoveUnreferencedVertex(m);
    detail::Finalize(m);
    return m.fn > 0;
}

/// Midpoint subdivision (each triangle -> 4, vcglib Refine with MidPoint and threshold 0)
/// until the mesh has at least targetFaces faces.
template <class M>
void Subdivide(M &m, int targetFaces)
{
    detail::TryEnableFF(m.face, 0);
    while (m.fn < targetFaces && m.fn > 0) {
        const int before = m.fn;
        if (vcg::tri::HasFFAdjacency(m)) {
            vcg::tri::UpdateTopology<M>::FaceFace(m);
            vcg::tri::Refine<M>(m, vcg::tri::MidPoint<M>(&m), 0);
        } else {
            // No FF adjacency in this mesh type: split every face, then weld the midpoints.
            M out;
            for (const auto &f : m.face) {
                if (f.IsD()) continue;
                const auto p0 = f.cP(0), p1 = f.cP(1), p2 = f.cP(2);
                const auto m01 = (p0 + p1) / 2, m12 = (p1 + p2) / 2, m20 = (p2 + p0) / 2;
                vcg::tri::Allocator<M>::AddFace(out, m01, m12, m20);
                vcg::tri::Allocator<M>::AddFace(out, p0, m01, m20);
                vcg::tri::Allocator<M>::AddFace(out, p1, m12, m01);
                vcg::tri::Allocator<M>::AddFace(out, p2, m20, m12);
            }
            vcg::tri::Clean<M>::RemoveDuplicateVertex(out);
            vcg::tri::Allocator<M>::CompactEveryVector(out);
            vcg::tri::Append<M, M>::MeshCopy(m, out);
        }
        vcg::tri::Allocator<M>::CompactEveryVector(m);
        if (m.fn <= before) break;
    }
    detail::Finalize(m);
}

/// Writes m with vcglib's exporter (format by extension). Returns true on success.
template <class M>
bool SaveMesh(M &m, const std::string &path)
{
    return vcg::tri::io::Exporter<M>::Save(m, path.c_str(), int(vcg::tri::io::Mask::IOM_VERTCOORD)) == 0;
}

/// Builds a mesh from explicit coordinates and triangles (vertex indices), e.g. for
/// hand-made non-manifold or degenerate configurations.
template <class M>
void MakeFromArrays(M &m, const std::vector<vcg::Point3d> &pts, const std::vector<std::array<int, 3>> &tris)
{
    m.Clear();
    vcg::tri::Allocator<M>::AddVertices(m, pts.size());
    for (size_t i = 0; i < pts.size(); ++i) m.vert[i].P() = M::CoordType::Construct(pts[i]);
    vcg::tri::Allocator<M>::AddFaces(m, tris.size());
    for (size_t i = 0; i < tris.size(); ++i)
        for (int k = 0; k < 3; ++k) m.face[i].V(k) = &m.vert[tris[i][k]];
    detail::Finalize(m);
}

/// Two open cones (n segments each) whose apexes are the same vertex (index 0): one
/// non-manifold vertex, 2n border edges, one (vertex-connected) component.
template <class M>
void MakeTouchingCones(M &m, int n = 8)
{
    std::vector<vcg::Point3d> pts{vcg::Point3d(0, 0, 0)};
    std::vector<std::array<int, 3>> tris;
    for (int c = 0; c < 2; ++c) {
        const double z = c == 0 ? 1.0 : -1.0;
        const int base = int(pts.size());
        for (int i = 0; i < n; ++i)
            pts.emplace_back(std::cos(2 * M_PI * i / n), std::sin(2 * M_PI * i / n), z);
        for (int i = 0; i < n; ++i) {
            const int a = base + i, b = base + (i + 1) % n;
            if (c == 0) tris.push_back({0, b, a});
            else tris.push_back({0, a, b});
        }
    }
    MakeFromArrays(m, pts, tris);
}

/// Three triangles sharing the edge (0,1): one non-manifold edge, six border edges.
template <class M>
void MakeNonManifoldFin(M &m)
{
    MakeFromArrays(m,
                   {vcg::Point3d(0, 0, 0), vcg::Point3d(1, 0, 0), vcg::Point3d(0.5, 1, 0), vcg::Point3d(0.5, -1, 0),
                    vcg::Point3d(0.5, 0, 1)},
                   {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
}

/// Appends b to a (vcg Append); used for multi-component meshes.
template <class M>
void AppendMesh(M &a, M &b)
{
    vcg::tri::Append<M, M>::Mesh(a, b);
    detail::Finalize(a);
}

} // namespace gs_test

#endif
