// Closed snakes around parts with the part-boundary energy (issue 33): generated surfaces whose
// part boundary is known exactly (a waist, the rim of a bump, the base of a handle), with and
// without noise, and a small version of the evaluation on part boundaries drawn by people
// (bench/eval/gs_parts).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <unordered_map>
#include <random>
#include <string>
#include <tuple>

#include <part_cases.h>
#include <revolved_profile.h>
#include <vcg_ext/session/controller.h>
#include <vcg_ext/snake/loop_bend.h>
#include <vcg_ext/snake/part_boundary_end.h>
#include <snake_test_util.h>
#include <vcg_ext/energy/energy_source.h>
#include <vcg_ext/energy/feature_energy.h>
#include <vcg_ext/energy/part_boundary_energy.h>
#include <vcg_ext/surface/surface_noise.h>
#include <vcg/complex/algorithms/create/marching_cubes.h>
#include <vcg/complex/append.h>
#include <vcg/complex/algorithms/create/mc_trivial_walker.h>
#include <vcg/complex/algorithms/refine.h>
#include <vcg/complex/algorithms/create/platonic.h>

#ifndef GS_SEGMENTATION_DIR
#define GS_SEGMENTATION_DIR GS_DATA_DIR "/../../shared/data/segmentation"
#endif

using namespace vcg::tri;
typedef GeometricSnake<CMeshO> Snake;
typedef SnakeSurface<CMeshO> Surface;
typedef vcg::Point3d P3;

namespace {

/// A unit icosphere (subdivision 4) whose radius along the direction at polar angle phi from
/// +z is R(phi); noise moves every vertex by `noise` (a share of the radius) in a random direction.
template <class Radius>
void MakeRevolved(CMeshO &m, Radius R, double noise)
{
    gs_test::MakeIcosphere(m, 4);
    for (auto &v : m.vert) {
        P3 p = P3::Construct(v.cP()).Normalize();
        const double phi = std::acos(std::max(-1.0, std::min(1.0, p[2])));
        v.P() = Point3m::Construct(p * R(phi));
    }
    if (noise > 0) gs_test::AddVertexNoise(m, noise / gs_test::MedianEdgeLength(m), 7);
    gs_test::EnableSnakeAdjacency(m);
    vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFace(m);
}

std::shared_ptr<Surface> WithEnergy(CMeshO &m, FeatureEnergyType t)
{
    FeatureEnergy<CMeshO>::Compute(m, t, 2);
    return std::make_shared<Surface>(m, SnakeEnergySource<CMeshO>::CaptureSmoothingFor(false, t));
}

/// Seeds on the circle of polar angle phi (8 points), snapped to vertices.
template <class Radius>
std::vector<int> RingSeeds(const CMeshO &m, Radius R, double phi)
{
    std::vector<P3> pts;
    for (int i = 0; i < 8; ++i) {
        const double a = 2 * M_PI * i / 8;
        pts.push_back(P3(std::sin(phi) * std::cos(a), std::sin(phi) * std::sin(a), std::cos(phi)) * R(phi));
    }
    return gs_test::NearestVertices(m, pts);
}

/// How far the points `loop` lie from the parallel at polar angle phiStar of the revolved shape
/// R: |phi - phiStar| times the radius there, in mean edge lengths h (mean and largest).
struct ParallelOffset
{
    double mean = 0, max = 0;
};
template <class Radius>
ParallelOffset OffParallel(const std::vector<P3> &loop, Radius R, double phiStar, double h)
{
    ParallelOffset r;
    for (const P3 &x : loop) {
        const double phi = std::acos(std::max(-1.0, std::min(1.0, x[2] / x.Norm())));
        const double off = std::fabs(phi - phiStar) * R(phiStar) / h;
        r.mean += off / loop.size();
        r.max = std::max(r.max, off);
    }
    return r;
}

struct LoopResult
{
    double meanOff = 0, maxOff = 0; ///< |phi - phi*| times the radius there, in mean edge lengths
    double lengthRatio = 0;         ///< final length / length of the exact loop
    bool stopped = false;
};

/// Runs a closed snake from `seeds` and measures it against the parallel at polar angle phiStar.
template <class Radius>
LoopResult RunLoop(std::shared_ptr<Surface> surf, const std::vector<int> &seeds, Radius R, double phiStar)
{
    Snake s(surf);
    s.InitFromSeeds(seeds, true);
    s.Run(400);
    PartBoundaryEnd<CMeshO>::FinishRun(s, FeatureEnergyType::PartBoundary, false); // as every host does
    const double h = surf->MeanEdge();
    LoopResult r;
    const std::vector<P3> loop = gs_parts::ResampleLoop(s.PolylinePositions(), 0.25 * h);
    const ParallelOffset off = OffParallel(loop, R, phiStar, h);
    r.meanOff = off.mean;
    r.maxOff = off.max;
    r.lengthRatio = gs_parts::LoopLength(loop) / (2 * M_PI * R(phiStar) * std::sin(phiStar));
    r.stopped = s.Stats().stopped;
    return r;
}

// A waist around the equator: a bottle's or a capsule's neck, the valley a loop must find.
double Waist(double phi) { return 1.0 - 0.3 * std::exp(-std::pow((phi - M_PI / 2) / 0.35, 2)); }
// A bump on the north pole of the unit sphere; its rim is a concave valley.
double Bump(double phi) { return 1.0 + 0.5 * std::exp(-std::pow(phi / 0.35, 2)); }

/// Polar angle of a bump's rim: where the meridian's curvature is most negative (the minima
/// rule's line), found on the exact profile (r(phi) = R(phi) in the meridian plane).
template <class Radius>
double RimOf(Radius R)
{
    double best = 0, kBest = 1e300;
    for (double phi = 0.05; phi < 1.5; phi += 1e-4) {
        auto pt = [&](double f) { return P3(R(f) * std::sin(f), 0, R(f) * std::cos(f)); };
        const double d = 1e-4;
        const P3 a = pt(phi - d), b = pt(phi), c = pt(phi + d);
        const P3 t1 = (b - a) / d, t2 = (c - b) / d, acc = (t2 - t1) / d, vel = (c - a) / (2 * d);
        // signed curvature of the profile, > 0 where it bends towards the axis (convex)
        const double k = -(vel[0] * acc[2] - vel[2] * acc[0]) / std::pow(vel.Norm(), 3);
        if (k < kBest) kBest = k, best = phi;
    }
    return best;
}
double BumpRim() { return RimOf(Bump); }

/// A smooth revolved shape R (no noise) with the part-boundary energy, the setup of the tests of
/// a loop's end on a part's rim: the mesh, the rim's polar angle, the snakes' surface, its h.
template <class Radius>
struct RevolvedRim
{
    Radius R;
    double rim;
    CMeshO m;
    std::shared_ptr<Surface> surf;
    double h = 0;
    explicit RevolvedRim(Radius r) : R(r), rim(RimOf(r))
    {
        MakeRevolved(m, R, 0.0);
        surf = WithEnergy(m, FeatureEnergyType::PartBoundary);
        h = surf->MeanEdge();
    }
    RevolvedRim(const RevolvedRim &) = delete;
    /// Seeds on the parallel d mean edge lengths from the rim (d > 0: towards the equator).
    std::vector<int> SeedsOff(double d) const { return RingSeeds(m, R, rim + d * h / R(rim)); }
    /// How far the snake's curve, resampled every h/4, lies from the rim (OffParallel).
    ParallelOffset OffRim(Snake &s) const
    {
        return OffParallel(gs_parts::ResampleLoop(s.PolylinePositions(), 0.25 * h), R, rim, h);
    }
};

// A torus-like handle joined to a body: the upper half of a torus (axis y, centre-line radius
// kHandleR in the xz-plane, tube radius kHandleTube) standing on a slab (|x| <= 3.5, |y| <= 2,
// -1 <= z <= 0), the union of the two solids' signed distances meshed by vcglib's marching
// cubes (voxel 0.1: slivers and uneven edges, as a reconstructed scan has). The
// handle meets the slab's top at right angles along two circles of radius kHandleTube round
// (+-kHandleR, 0, 0) in z = 0: its base loops, concave creases, the exact answer. A loop round one
// foot does not cut the surface in two (the handle is a handle): nothing inside it to shrink into.
const double kHandleR = 2.0, kHandleTube = 0.7;

double HandleDistance(const P3 &p)
{
    const double torus = std::hypot(std::hypot(p[0], p[2]) - kHandleR, p[1]) - kHandleTube;
    const double handle = std::max(torus, -p[2] - 0.5); // its upper half (the rest is in the slab)
    const P3 q(std::fabs(p[0]) - 3.5, std::fabs(p[1]) - 2.0, std::fabs(p[2] + 0.5) - 0.5);
    const P3 qo(std::max(q[0], 0.0), std::max(q[1], 0.0), std::max(q[2], 0.0));
    const double slab = qo.Norm() + std::min(std::max(q[0], std::max(q[1], q[2])), 0.0);
    return std::min(handle, slab);
}

typedef vcg::SimpleVolume<vcg::SimpleVoxel<float>> Volume;

/// vcglib's TrivialWalker never frees its slice buffers (LeakSanitizer): this one does.
struct Walker : vcg::tri::TrivialWalker<CMeshO, Volume>
{
    ~Walker()
    {
        if (_slice_dimension == 0) return;
        delete[] _x_cs;
        delete[] _y_cs;
        delete[] _z_cs;
        delete[] _x_ns;
        delete[] _z_ns;
    }
};

void MakeHandleOnSlab(CMeshO &m, double noise)
{
    typedef vcg::tri::MarchingCubes<CMeshO, Walker> MC;
    const double step = 0.1;
    const vcg::Box3f box(vcg::Point3f(-3.83f, -2.27f, -1.35f), vcg::Point3f(3.77f, 2.33f, 2.95f));
    const vcg::Point3i n(int(std::lround(7.6 / step)) + 1, int(std::lround(4.6 / step)) + 1, int(std::lround(4.3 / step)) + 1);
    Volume vol;
    vol.Init(n, box);
    for (int i = 0; i < n[0]; ++i)
        for (int j = 0; j < n[1]; ++j)
            for (int k = 0; k < n[2]; ++k)
                vol.Val(i, j, k) = float(HandleDistance(P3(box.min[0] + i * step, box.min[1] + j * step, box.min[2] + k * step)));
    Walker walker;
    MC mc(m, walker);
    walker.BuildMesh<MC>(m, vol, mc, 0);
    vcg::tri::Clean<CMeshO>::RemoveDuplicateVertex(m);
    vcg::tri::Clean<CMeshO>::RemoveDegenerateFace(m);
    vcg::tri::Clean<CMeshO>::RemoveZeroAreaFace(m);
    vcg::tri::Clean<CMeshO>::RemoveUnreferencedVertex(m);
    vcg::tri::Allocator<CMeshO>::CompactEveryVector(m);
    if (noise > 0) gs_test::AddVertexNoise(m, noise * kHandleTube / gs_test::MedianEdgeLength(m), 7);
    gs_test::EnableSnakeAdjacency(m);
    vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFace(m);
    vcg::tri::UpdateBounding<CMeshO>::Box(m);
}

/// Distance of x to the handle's base loop round (side * kHandleR, 0, 0).
double OffHandleBase(const P3 &x, int side)
{
    return std::hypot(x[2], std::hypot(x[0] - side * kHandleR, x[1]) - kHandleTube);
}

} // namespace

// The energy marks the concave waist, not the convex ends, whatever the noise.
TEST(PartBoundaryEnergy, LowOnTheWaistOnlyAndScaleFree)
{
    for (double noise : {0.0, 0.03}) {
        CMeshO m;
        MakeRevolved(m, Waist, noise);
        std::vector<double> e = PartBoundaryEnergy<CMeshO>::VertexValues(m, 2);
        double waist = 0, ends = 0;
        int nw = 0, ne = 0;
        for (size_t i = 0; i < m.vert.size(); ++i) {
            const double z = m.vert[i].cP()[2] / vcg::Norm(m.vert[i].cP());
            if (std::fabs(z) < 0.05) waist += e[i], ++nw;
            if (std::fabs(z) > 0.8) ends += e[i], ++ne;
        }
        waist /= nw, ends /= ne;
        std::printf("noise %.2f: mean energy on the waist %.3f, on the convex ends %.3f\n", noise, waist, ends);
        EXPECT_LT(waist, 0.3);
        EXPECT_GT(ends, 0.9);
        // scale-free: the same mesh 1000x larger gives the same energy
        CMeshO big;
        vcg::tri::Append<CMeshO, CMeshO>::MeshCopy(big, m);
        for (auto &v : big.vert) v.P() *= 1000;
        vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFace(big);
        std::vector<double> eb = PartBoundaryEnergy<CMeshO>::VertexValues(big, 2);
        for (size_t i = 0; i < e.size(); i += 37) EXPECT_NEAR(e[i], eb[i], 1e-4);
    }
}

// Inside-out faces (negative volume) do not turn valleys into ridges.
TEST(PartBoundaryEnergy, OrientationIndependent)
{
    CMeshO m;
    MakeRevolved(m, Waist, 0.0);
    std::vector<double> e = PartBoundaryEnergy<CMeshO>::VertexValues(m, 2);
    for (auto &f : m.face) std::swap(f.V(1), f.V(2));
    vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFace(m);
    std::vector<double> f = PartBoundaryEnergy<CMeshO>::VertexValues(m, 2);
    for (size_t i = 0; i < e.size(); i += 11) EXPECT_NEAR(e[i], f[i], 1e-6);
}

namespace {

/// An inner corner: a floor and a wall (each 40 edges across, 40 along y; edge 0.05) joined by
/// a concave fillet of radius rho = 30 edges / (pi / 2), a quarter circle 30 edges long, as a
/// grid along the profile's arc length (two triangles a cell); turned to a generic direction
/// and moved off the origin (so that float rounding of the coordinates tips the planes' fits
/// either way, as on a CAD mesh), faces towards the corner's open side, away from the origin
/// (OutwardSign). `ax[3]`: the corner's axes (floor along x, up z); `c`: the fillet's start.
double MakeFilletedCorner(CMeshO &m, bool split, P3 ax[3], P3 &c)
{
    const int nf = 40, na = 30, ny = 40;
    const double h = 0.05, rho = na * h / (M_PI / 2);
    vcg::Matrix44d rot;
    rot.SetRotateRad(0.7, P3(1, 2, 3).Normalize());
    for (int k = 0; k < 3; ++k) ax[k] = rot * P3(k == 0, k == 1, k == 2);
    c = rot * P3(-0.3 - rho, 0.4, 0.6); // the origin lies on the solid's side
    const int ns = nf + na + nf;
    vcg::tri::Allocator<CMeshO>::AddVertices(m, (ns + 1) * (ny + 1));
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= ns; ++i) {
            double x, z;
            if (i <= nf) x = (i - nf) * h, z = 0; // floor
            else if (i <= nf + na) {
                const double t = (i - nf) * h / rho; // fillet, centre (0, rho)
                x = rho * std::sin(t), z = rho - rho * std::cos(t);
            } else x = rho, z = rho + (i - nf - na) * h; // wall
            const P3 q = ax[0] * x + ax[1] * ((j - ny / 2) * h) + ax[2] * z;
            m.vert[j * (ns + 1) + i].P() = Point3m::Construct(q + c);
        }
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < ns; ++i) {
            const int v00 = j * (ns + 1) + i, v10 = v00 + 1, v01 = v00 + ns + 1, v11 = v01 + 1;
            vcg::tri::Allocator<CMeshO>::AddFace(m, &m.vert[v00], &m.vert[v10], &m.vert[v11]);
            vcg::tri::Allocator<CMeshO>::AddFace(m, &m.vert[v00], &m.vert[v11], &m.vert[v01]);
        }
    if (split) {
        std::vector<std::vector<int>> segs;
        gs_parts::ApplyVariant(m, segs, "refine"); // coplanar children, midpoints rounded to float
    }
    vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFace(m);
    return rho;
}

} // namespace

// The energy's reference does not depend on the mesh's precision (session 32): an inner corner
// with a concave fillet (a valley between two planes, as on a CAD part), meshed and with every
// face split 1-to-4 (gs_parts --variant refine), gives the same reference per edge length (the
// concavity is made dimensionless by the median edge, which halves) and the same energy on the
// fillet. Float rounding of the turned corner's coordinates tips the planes' fits either way:
// without the flat tolerance (0) most plane vertices count as concave at ~1e-6-1e-4 and the
// reference, their median with the fillet's, falls to rounding's level and differs 4x between
// the two (as on the CAD-like benchmark meshes 327, 333, 341, 342).
TEST(PartBoundaryEnergy, SameReferenceOnAFilletedCornerWhenEveryFaceIsSplit1To4)
{
    PartBoundaryEnergy<CMeshO>::Param par, off;
    par.flatTolerance = 16; // as ValleyLoop's (left off by default: see Param)
    off.flatTolerance = 0;
    double ref[2][2], perH[2][2], valley[2][2], flatShare[2][2];
    for (int split : {0, 1}) {
        CMeshO m;
        P3 ax[3], o;
        const double rho = MakeFilletedCorner(m, split != 0, ax, o);
        const double h = gs_parts::MeanEdgeLength(m);
        for (int k : {0, 1}) {
            const PartBoundaryEnergy<CMeshO>::Param &q = k ? off : par;
            const std::vector<double> c = PartBoundaryEnergy<CMeshO>::Concavity(m, q.radius + 2 * q.radiusPerStep, q);
            const std::vector<double> e = PartBoundaryEnergy<CMeshO>::VertexValues(m, 2, q);
            std::vector<double> pos;
            double ev = 0;
            int nv = 0, nf = 0, nfc = 0;
            for (size_t i = 0; i < m.vert.size(); ++i) {
                if (c[i] > 0) pos.push_back(c[i]);
                const P3 d = P3::Construct(m.vert[i].cP()) - o;
                const double x = d * ax[0], z = d * ax[2];
                if (x > 0 && z < rho && std::fabs(std::atan2(x, rho - z) - M_PI / 4) < M_PI / 12) ev += e[i], ++nv; // the fillet's middle third
                if (x < -0.5 || z > rho + 0.5) nfc += c[i] > 0, ++nf; // the planes, off the fillet
            }
            ASSERT_FALSE(pos.empty());
            std::nth_element(pos.begin(), pos.begin() + pos.size() / 2, pos.end());
            ref[split][k] = pos[pos.size() / 2];
            perH[split][k] = ref[split][k] / h;
            valley[split][k] = ev / nv;
            flatShare[split][k] = double(nfc) / nf;
        }
    }
    for (int k : {0, 1})
        std::printf("filleted corner, flatTolerance %s: c_ref %.4g / %.4g (per h %.4g / %.4g), energy on the fillet %.3f / "
                    "%.3f, flat vertices concave %.3f / %.3f (meshed / split 1-to-4)\n",
                    k ? "0" : "16", ref[0][k], ref[1][k], perH[0][k], perH[1][k], valley[0][k], valley[1][k],
                    flatShare[0][k], flatShare[1][k]);
    EXPECT_NEAR(perH[1][0] / perH[0][0], 1.0, 0.1);
    EXPECT_NEAR(valley[1][0] / valley[0][0], 1.0, 0.1);
    EXPECT_LT(valley[0][0], 0.5); // the fillet is a well
    EXPECT_EQ(flatShare[0][0], 0.0);
    EXPECT_EQ(flatShare[1][0], 0.0);
    // the mechanism: without the tolerance rounding's "concave" flat vertices
    EXPECT_GT(flatShare[1][1], 0.1);
}

// Closed snakes seeded 3 edge lengths above or below the waist end on it with the part-boundary
// energy, all around (no point, no stub), with and without noise of 3 % of the radius
// (about half an edge length).
TEST(PartBoundaryLoop, SettlesOnTheWaistFromEitherSide)
{
    for (double noise : {0.0, 0.03}) {
        CMeshO m;
        MakeRevolved(m, Waist, noise);
        auto surf = WithEnergy(m, FeatureEnergyType::PartBoundary);
        const double h = surf->MeanEdge();
        for (int side : {-1, 1}) {
            const double phi0 = M_PI / 2 + side * 3 * h / Waist(M_PI / 2);
            LoopResult r = RunLoop(surf, RingSeeds(m, Waist, phi0), Waist, M_PI / 2);
            std::printf("waist, noise %.2f, seeds %s: off the waist mean %.2f h, max %.2f h, length %.2f of the "
                        "waist's, stopped %d\n", noise, side < 0 ? "above" : "below", r.meanOff, r.maxOff,
                        r.lengthRatio, int(r.stopped));
            EXPECT_FALSE(r.stopped);
            // measured with the valley loop of edges at the end (snake/valley_loop.h): mean 0.15 h,
            // max 0.67 h without noise, 0.26 / 1.06 h with (the icosphere's edges zigzag across
            // the waist; the snake's own loop: 0.00 / 0.04 h, 0.14-0.16 / 0.49-0.51 h)
            EXPECT_LT(r.meanOff, 0.5);
            EXPECT_LT(r.maxOff, noise > 0 ? 1.5 : 1.0);
            EXPECT_GT(r.lengthRatio, 0.9);
        }
    }
}

// Around a bump: seeded on the bump or on the sphere beside it, the loop ends on the bump's
// concave rim; with normal variation it does not (the bump's crest and skirt bend as much).
TEST(PartBoundaryLoop, SettlesOnTheRimOfABump)
{
    const double rim = BumpRim();
    for (double noise : {0.0, 0.03}) {
        CMeshO m;
        MakeRevolved(m, Bump, noise);
        auto surf = WithEnergy(m, FeatureEnergyType::PartBoundary);
        const double h = surf->MeanEdge();
        for (int side : {-1, 1}) {
            const double phi0 = rim + side * 3 * h / Bump(rim);
            LoopResult r = RunLoop(surf, RingSeeds(m, Bump, phi0), Bump, rim);
            std::printf("bump rim at %.3f rad, noise %.2f, seeds %s: off the rim mean %.2f h, max %.2f h, length "
                        "%.2f of the rim's, stopped %d\n", rim, noise, side < 0 ? "on the bump" : "outside",
                        r.meanOff, r.maxOff, r.lengthRatio, int(r.stopped));
            EXPECT_FALSE(r.stopped);
            // measured: mean 0.50-0.67 h, max 0.66-0.74 h without noise (the fit over 3 edge
            // lengths rounds the rim's profile); with noise mean 0.52 / 0.76 h, max 1.0 / 2.7 h
            // (one stretch of the loop seeded outside lies in a noise dent beside the rim) with
            // gcc, and for the loop seeded outside mean 1.25 h, max 4.06 h, 1.36 of the rim's
            // length with clang's ASan build: on noise that loop's excursion depends on rounding
            // (a weakness, issue 33), so its bounds only tell it from a loop off the rim.
            // With the valley loop of edges at the end (snake/valley_loop.h): mean 0.88-0.89 h, max
            // 1.55 h without noise, 0.78-0.79 / 1.65 h with (gcc Release): edges zigzag across the rim.
            EXPECT_LT(r.meanOff, noise > 0 ? 1.5 : 1.0);
            EXPECT_LT(r.maxOff, noise > 0 ? 5.0 : 2.0);
            EXPECT_GT(r.lengthRatio, 0.85);
        }
    }
}

// The evaluation's small version: the teddy bear of the segmentation benchmark (ears, arms,
// legs: 6 parts most people cut off with one loop), closed snakes seeded 3 rings off each
// boundary on both sides. Measured: part boundary 12 of 12, normal variation 0 of 12.
TEST(PartBoundaryBenchmark, TeddyPartsCapturedByThePartBoundaryEnergyOnly)
{
    gs_parts::Model md;
    ASSERT_TRUE(gs_parts::LoadModel(GS_SEGMENTATION_DIR, 161, md)) << GS_SEGMENTATION_DIR;
    ASSERT_GE(md.parts.size(), 5u);
    for (FeatureEnergyType t : {FeatureEnergyType::PartBoundary, FeatureEnergyType::NormalVariation}) {
        auto surf = WithEnergy(md.mesh, t);
        int cases = 0, ok = 0, points = 0;
        for (const gs_parts::Part &p : md.parts)
            for (int side : {1, -1}) {
                const std::vector<int> seeds = gs_parts::Seeds(md.mesh, p, 3, side, 8);
                if (seeds.empty()) continue;
                Snake s(surf);
                s.InitFromSeeds(seeds, true);
                const double L0 = gs_parts::LoopLength(s.PolylinePositions());
                s.Run(400);
                PartBoundaryEnd<CMeshO>::FinishRun(s, t, false); // as every host does (nothing for normal variation)
                const std::vector<P3> loop = s.PolylinePositions();
                const gs_parts::Score sc = gs_parts::Measure(loop, p, md.h, md.h);
                ++cases;
                ok += sc.Success();
                points += s.Stats().stopped || gs_parts::LoopLength(loop) < 0.25 * L0;
            }
        std::printf("%s: %d of %d loops on a person's cut, %d collapsed\n", FeatureEnergyName(t), ok, cases, points);
        ASSERT_GE(cases, 10);
        if (t == FeatureEnergyType::PartBoundary) {
            EXPECT_GE(ok, cases * 9 / 10);
            EXPECT_EQ(points, 0);
        } else {
            EXPECT_LE(ok, cases / 4);
        }
    }
}

// The tessellation variants (part_variants.h, gs_parts --variant, session 29): red-green splits
// leave the mesh closed and consistently oriented (every directed edge once, its twin present:
// no T-junction), keep its area, and the labels' boundary is the same curve (the same length).
namespace {
double LabelBoundaryLength(const CMeshO &m, const std::vector<int> &lab, size_t &edges)
{
    std::map<std::pair<int, int>, int> face; // directed edge -> its face
    for (size_t f = 0; f < m.face.size(); ++f)
        for (int k = 0; k < 3; ++k)
            face[{int(vcg::tri::Index(m, m.face[f].cV(k))), int(vcg::tri::Index(m, m.face[f].cV((k + 1) % 3)))}] = int(f);
    double L = 0;
    edges = 0;
    for (const auto &e : face) {
        if (e.first.first > e.first.second) continue;
        auto twin = face.find({e.first.second, e.first.first});
        if (twin == face.end()) return -1; // open or T-junction
        ++edges;
        if (lab[e.second] != lab[twin->second])
            L += vcg::Distance(m.vert[e.first.first].cP(), m.vert[e.first.second].cP());
    }
    return face.size() == 2 * edges ? L : -1; // -1: an edge twice in one direction
}
} // namespace

TEST(PartVariants, SplitsStayConformingAndKeepTheLabelsBoundary)
{
    CMeshO m;
    vcg::tri::Octahedron(m);
    std::vector<std::vector<int>> segs(1);
    for (const auto &f : m.face) segs[0].push_back(vcg::Barycenter(f)[2] > 0);
    size_t edges = 0;
    const double L0 = LabelBoundaryLength(m, segs[0], edges); // the equator, 4 sqrt(2)
    ASSERT_NEAR(L0, 4 * std::sqrt(2.0), 1e-6);
    gs_parts::SplitFaces(m, std::vector<char>(m.face.size(), 1), segs); // 1-to-4
    ASSERT_EQ(m.face.size(), 32u);
    // then some faces only: their neighbours split in 2 or 3 (both kinds occur)
    std::vector<char> mark(m.face.size(), 0);
    for (size_t f = 0; f < m.face.size(); ++f) mark[f] = vcg::Barycenter(m.face[f])[0] < -0.2;
    const size_t marked = std::count(mark.begin(), mark.end(), 1), before = m.face.size();
    gs_parts::SplitFaces(m, mark, segs);
    EXPECT_GT(m.face.size(), before + 3 * marked); // the green splits added faces too
    ASSERT_EQ(segs[0].size(), m.face.size());
    double area = 0;
    for (const auto &f : m.face) area += vcg::DoubleArea(f) / 2;
    EXPECT_NEAR(area, 4 * std::sqrt(3.0), 1e-5); // the octahedron's, 8 faces of sqrt(3)/2
    EXPECT_NEAR(LabelBoundaryLength(m, segs[0], edges), L0, 1e-5);
    EXPECT_EQ(3 * m.face.size(), 2 * edges);
    // graded, as gs_parts runs it: the same area and boundary, conforming
    ASSERT_TRUE(gs_parts::ApplyVariant(m, segs, "graded"));
    EXPECT_NEAR(LabelBoundaryLength(m, segs[0], edges), L0, 1e-5);
    EXPECT_FALSE(gs_parts::ApplyVariant(m, segs, "unknown"));
}

// On the benchmark (teddy 161): every part and every person's cut is found again on the refined
// and graded meshes, the same curve (the same length); refine halves h; noise moves the cuts by
// at most 0.2 h along the normal, so their length changes little.
TEST(PartVariants, TeddyCutsCarriedOverTheVariants)
{
    gs_parts::Model md;
    ASSERT_TRUE(gs_parts::LoadModel(GS_SEGMENTATION_DIR, 161, md)) << GS_SEGMENTATION_DIR;
    ASSERT_GE(md.parts.size(), 5u);
    EXPECT_EQ(md.h0, md.h);
    for (const char *v : {"refine", "graded", "noise"}) {
        gs_parts::Model mv;
        ASSERT_TRUE(gs_parts::LoadModel(GS_SEGMENTATION_DIR, 161, mv, v)) << v;
        EXPECT_NEAR(mv.h0, md.h, 1e-9 * md.h) << v;
        ASSERT_EQ(mv.parts.size(), md.parts.size()) << v;
        if (std::string(v) == "refine") EXPECT_NEAR(mv.h / md.h, 0.5, 0.01);
        if (std::string(v) == "graded") EXPECT_LT(mv.h / md.h, 0.5);
        const double tol = std::string(v) == "noise" ? 0.05 : 1e-6; // relative
        for (size_t i = 0; i < md.parts.size(); ++i) {
            ASSERT_EQ(mv.parts[i].cuts.size(), md.parts[i].cuts.size()) << v << " part " << i;
            for (size_t c = 0; c < md.parts[i].cuts.size(); ++c) {
                const double L = gs_parts::LoopLength(md.parts[i].cuts[c]);
                EXPECT_NEAR(gs_parts::LoopLength(mv.parts[i].cuts[c]), L, tol * L) << v << " part " << i << " cut " << c;
            }
        }
    }
}

// The snakes read the part-boundary energy on level 0 only (the pyramid let loops collapse), and
// every other energy through the pyramid, also after switching energies on the same surface.
TEST(PartBoundaryEnergy, ReadWithoutThePyramid)
{
    CMeshO m;
    MakeRevolved(m, Waist, 0.0);
    SnakeEnergySource<CMeshO> src(m);
    src.SetSettings(FeatureEnergyType::PartBoundary, 2);
    EXPECT_EQ(src.EnsureSurface()->Levels(), 1);
    src.SetSettings(FeatureEnergyType::NormalVariation, 2);
    EXPECT_GT(src.EnsureSurface()->Levels(), 1);
    src.SetSettings(FeatureEnergyType::PartBoundary, 2);
    EXPECT_EQ(src.EnsureSurface()->Levels(), 1);
    src.UseQuality();
    EXPECT_GT(src.EnsureSurface()->Levels(), 1);
}

// The torus-like handle: closed snakes seeded 3 edge lengths off either base loop, on the handle
// or on the slab, end round the base loop (length 0.99-1.15 of the base's), with and without
// noise of 3 % of the tube's radius. Measured without noise: seeded on the slab, mean 0.33-0.49 h,
// max 0.68-0.89 h off the base; seeded on the handle, mean 1.13-1.17 h, max 1.47-1.50 h: round
// this sharp right-angle crease the energy is 0 over a band 4 h wide (from 2 h out on the slab to
// 2 h up the handle, the quadric fit over 3 h; mean energy by 1 h bands), and a loop stops where
// it enters the band (a limit of the energy, issue 33). With noise (the noise differs between
// gcc and clang, which evaluate its random draws in another order): on the slab mean 0.53-0.57 h,
// max 0.83-1.02 h with gcc, 0.75-0.81 and 1.32-1.33 h with clang's ASan build; on the handle
// mean 0.90-1.20 h, max 1.64-1.77 h with gcc, mean 1.30 and 1.58 h, max 1.85 and 4.54 h (a
// stretch of that loop only) with clang. The bounds tell a loop in that band from
// one left where it was seeded (3 h off).
TEST(PartBoundaryLoop, SettlesOnTheBaseOfAHandle)
{
    for (double noise : {0.0, 0.03}) {
        CMeshO m;
        MakeHandleOnSlab(m, noise);
        ASSERT_GT(m.fn, 5000);
        auto r = vcg::tri::MeshValidation<CMeshO>::Inspect(m);
        EXPECT_EQ(r.nonManifoldEdges, 0);
        EXPECT_EQ(r.borderEdges, 0);
        EXPECT_EQ(r.components, 1);
        auto surf = WithEnergy(m, FeatureEnergyType::PartBoundary);
        const double h = surf->MeanEdge();
        for (int foot : {-1, 1})
            for (int seedSide : {1, -1}) { // on the handle, on the slab
                std::vector<P3> pts;
                for (int i = 0; i < 8; ++i) {
                    const double a = 2 * M_PI * i / 8;
                    if (seedSide > 0) { // the tube's cross-section 3 h up the handle from the foot
                        const double t = 3 * h / kHandleR, rc = kHandleR * std::cos(t);
                        const P3 c(foot * rc, 0, kHandleR * std::sin(t)), er(foot * std::cos(t), 0, std::sin(t));
                        pts.push_back(c + er * (kHandleTube * std::cos(a)) + P3(0, kHandleTube * std::sin(a), 0));
                    } else { // a circle 3 h out from the foot on the slab's top
                        pts.push_back(P3(foot * kHandleR + (kHandleTube + 3 * h) * std::cos(a),
                                         (kHandleTube + 3 * h) * std::sin(a), 0));
                    }
                }
                Snake s(surf);
                s.InitFromSeeds(gs_test::NearestVertices(m, pts), true);
                s.Run(400);
                const std::vector<P3> loop = gs_parts::ResampleLoop(s.PolylinePositions(), 0.25 * h);
                double mean = 0, mx = 0;
                for (const P3 &x : loop) {
                    const double d = OffHandleBase(x, foot) / h;
                    mean += d / loop.size();
                    mx = std::max(mx, d);
                }
                const double ratio = gs_parts::LoopLength(loop) / (2 * M_PI * kHandleTube);
                std::printf("handle (%d faces, h %.3f), noise %.2f, foot %+d, seeds %s: off the base mean %.2f h, max "
                            "%.2f h, length %.2f of the base's, %d operations, stop %s\n", m.fn, h, noise, foot,
                            seedSide > 0 ? "on the handle" : "on the slab", mean, mx, ratio, s.Stats().operations,
                            SnakeStopKey(s.Stats().stop));
                EXPECT_FALSE(s.Stats().stopped);
                EXPECT_LT(mean, noise > 0 ? 2.0 : 1.5);
                EXPECT_LT(mx, noise > 0 ? 5.0 : 2.0);
                EXPECT_GT(ratio, 0.9);
                EXPECT_LT(ratio, 1.25);
            }
    }
}

// The end of a converged part-boundary loop (snake/part_boundary_end.h): the cheapest edge loop
// round it (snake/valley_loop.h) replaces it, on the waist's valley, and the run's end stays
// (converged: a new Run does not move it, one undo step returns the state before the Run); other
// energies, open snakes and runs that did not converge are left as they are.
TEST(ValleyLoop, EndsAConvergedLoopOnTheValleysEdgesAndKeepsTheRun)
{
    CMeshO m;
    MakeRevolved(m, Waist, 0.0);
    auto surf = WithEnergy(m, FeatureEnergyType::PartBoundary);
    const double h = surf->MeanEdge();
    Snake s(surf);
    s.InitFromSeeds(RingSeeds(m, Waist, M_PI / 2 + 3 * h / Waist(M_PI / 2)), true);
    const std::vector<P3> start = s.PolylinePositions();
    s.Run(400);
    ASSERT_EQ(s.Stats().stop, SnakeStop::Converged);
    EXPECT_FALSE(PartBoundaryEnd<CMeshO>::FinishRun(s, FeatureEnergyType::NormalVariation, false));
    EXPECT_FALSE(PartBoundaryEnd<CMeshO>::FinishRun(s, FeatureEnergyType::PartBoundary, true)); // quality as energy
    const int ops = s.Stats().operations;
    ASSERT_TRUE(PartBoundaryEnd<CMeshO>::FinishRun(s, FeatureEnergyType::PartBoundary, false));
    EXPECT_EQ(s.Stats().stop, SnakeStop::Converged);
    const double maxOff = OffParallel(s.PolylinePositions(), Waist, M_PI / 2, h).max;
    std::printf("valley loop on the waist: %zu samples, max %.2f h off the waist\n", s.PolylinePositions().size(), maxOff);
    EXPECT_LT(maxOff, 1.0);
    const std::vector<P3> snapped = s.PolylinePositions();
    s.Run(400);
    EXPECT_EQ(s.Stats().operations, ops); // converged: not moved again
    EXPECT_LT((s.PolylinePositions()[0] - snapped[0]).Norm(), 1e-9 * h);
    // undo: the empty Run's step, then the Run's (the snap is part of it): the state before the Run
    ASSERT_TRUE(s.Undo());
    ASSERT_TRUE(s.Undo());
    ASSERT_EQ(s.PolylinePositions().size(), start.size());
    EXPECT_LT((s.PolylinePositions()[0] - start[0]).Norm(), 1e-9 * h);
    // a run cut short is not replaced
    Snake t(surf);
    t.InitFromSeeds(RingSeeds(m, Waist, M_PI / 2 + 3 * h / Waist(M_PI / 2)), true);
    t.Run(1);
    EXPECT_FALSE(PartBoundaryEnd<CMeshO>::FinishRun(t, FeatureEnergyType::PartBoundary, false));
}

// FinishRun records the loop after each of its stages (ValleyLoop::Param::record, session 31: what
// bench/eval/gs_parts GS_PARTS_CHAIN prints instead of replaying the rule), in its order, the last
// the Run's loop, and its concavity reference (Param::recordReference, session 32); recording
// changes nothing.
TEST(ValleyLoop, RecordsTheLoopAfterEachStageOfTheRunsEnd)
{
    CMeshO m;
    MakeRevolved(m, Waist, 0.0);
    auto surf = WithEnergy(m, FeatureEnergyType::PartBoundary);
    const double h = surf->MeanEdge();
    const std::vector<int> seeds = RingSeeds(m, Waist, M_PI / 2 + 3 * h / Waist(M_PI / 2));
    Snake s(surf), t(surf), u(surf);
    for (Snake *x : {&s, &t, &u}) {
        x->InitFromSeeds(seeds, true);
        x->Run(400);
    }
    ASSERT_EQ(s.Stats().stop, SnakeStop::Converged);
    PartBoundaryEnd<CMeshO>::Param par;
    std::vector<std::pair<std::string, std::vector<int>>> rec;
    par.valley.record = [&](const char *st, const std::vector<int> &l) {
        if (std::string(st).compare(0, 4, "end:") == 0) rec.push_back({st, l});
    };
    // session 32: the concavity reference it priced with, recorded too: FinishFrom's round the
    // snake's loop (what GS_PARTS_CHAIN searched again for before)
    double ref = -1, ref2 = -1, cost2 = 0;
    int refCalls = 0;
    par.recordReference = [&](double r) { ref = r, ++refCalls; };
    const auto own = PartBoundaryEnd<CMeshO>::Seeded::Of(s);
    PartBoundaryEnd<CMeshO>::FinishFrom(m, own.loop, own.faces, surf->Energy(), s.LengthScale(), PartBoundaryEnd<CMeshO>::Param(),
                                        ref2, cost2);
    ASSERT_TRUE(PartBoundaryEnd<CMeshO>::FinishRun(s, FeatureEnergyType::PartBoundary, false, par));
    ASSERT_TRUE(PartBoundaryEnd<CMeshO>::FinishRun(t, FeatureEnergyType::PartBoundary, false));
    EXPECT_EQ(refCalls, 1);
    EXPECT_GT(ref, 0);
    EXPECT_EQ(ref, ref2);
    ASSERT_EQ(rec.size(), 4u);
    const char *order[] = {"end:descent", "end:salience", "end:seeded", "end:bend"};
    for (size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(rec[i].first, order[i]);
        EXPECT_GE(rec[i].second.size(), 3u) << order[i];
    }
    // the last record is the Run's loop, and the Run's loop is the one FinishRun gives unrecorded
    u.SetClosedVertexLoop(rec.back().second);
    const std::vector<P3> a = s.PolylinePositions(), b = t.PolylinePositions(), c = u.PolylinePositions();
    ASSERT_EQ(a.size(), b.size());
    ASSERT_EQ(a.size(), c.size());
    for (size_t i = 0; i < a.size(); ++i) {
        EXPECT_LT((a[i] - b[i]).Norm(), 1e-12 * h);
        EXPECT_LT((a[i] - c[i]).Norm(), 1e-12 * h);
    }
}

namespace {

// A tube with a waist at z = 0 (radius 1 - 0.3 exp(-(z/0.35)^2), z in [-1, 1.2], open ends)
// whose tessellation is graded 20x across the waist: rings (and the edges along them) 0.02
// apart below z = -0.1, 0.4 above z = 0.1, growing geometrically between, one ring exactly on
// the waist. Consecutive rings of different sizes are zipped by angle (triangles of every
// shape). The waist's circle is the exact valley.
const double kFine = 0.02, kCoarse = 20 * kFine;
double TubeRadius(double z) { return 1.0 - 0.3 * std::exp(-std::pow(z / 0.35, 2)); }
double GradedEdge(double z) { return kFine * std::pow(kCoarse / kFine, std::max(0.0, std::min(1.0, (z + 0.1) / 0.2))); }

void MakeGradedWaist(CMeshO &m)
{
    std::vector<double> zs{0.0};
    while (zs.front() > -1.0) zs.insert(zs.begin(), zs.front() - GradedEdge(zs.front() - 0.5 * GradedEdge(zs.front())));
    while (zs.back() < 1.2) zs.push_back(zs.back() + GradedEdge(zs.back() + 0.5 * GradedEdge(zs.back())));
    std::vector<int> first, count;
    for (size_t j = 0; j < zs.size(); ++j) {
        const double r = TubeRadius(zs[j]);
        const int n = std::max(6, int(std::lround(2 * M_PI * r / GradedEdge(zs[j]))));
        first.push_back(int(m.vert.size()));
        count.push_back(n);
        auto vi = vcg::tri::Allocator<CMeshO>::AddVertices(m, n);
        for (int k = 0; k < n; ++k, ++vi) {
            const double a = 2 * M_PI * (k + 0.5 * (j % 2)) / n;
            vi->P() = Point3m(r * std::cos(a), r * std::sin(a), zs[j]);
        }
    }
    for (size_t j = 0; j + 1 < zs.size(); ++j) {
        const int na = count[j], nb = count[j + 1];
        auto A = [&](int i) { return &m.vert[first[j] + i % na]; };
        auto B = [&](int i) { return &m.vert[first[j + 1] + i % nb]; };
        auto angle = [](int i, int n, size_t ring) { return (i + 0.5 * (ring % 2)) / n; };
        for (int i = 0, k = 0; i < na || k < nb;) {
            if (k == nb || (i < na && angle(i + 1, na, j) <= angle(k + 1, nb, j + 1)))
                vcg::tri::Allocator<CMeshO>::AddFace(m, A(i), A(i + 1), B(k)), ++i;
            else
                vcg::tri::Allocator<CMeshO>::AddFace(m, A(i), B(k + 1), B(k)), ++k;
        }
    }
    gs_test::EnableSnakeAdjacency(m);
    vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFace(m);
}

} // namespace

// The valley loop where edge lengths vary 20x across the valley (the guide's uneven
// tessellations; here 0.02-0.61, 30x with the zipped diagonals). A Run from seeds on the fine
// side, and Runs from seeds on the coarse side (the first coarse ring, 6 waist edges up, and
// 15 waist edges up) converge on the waist and end on its circle of edges or the coarse ring
// beside it; the valley loop alone (a loop taken as converged where it was placed) from a fine
// ring below and from the first coarse ring above (1.95 waist edges up, at the band's edge)
// reaches the waist too, never a point or a stub. The coarse-side Runs need the concavity made
// dimensionless by one length for the mesh (PartBoundaryEnergy::Concavity): by each vertex's
// own fit radius, the coarse side's broad fits read up to 20x deeper than the waist and a Run
// from z = 0.12 slid up to z = 0.8, where the coarse rings meet (10.9 waist edges off).
TEST(ValleyLoop, EndsOnTheValleyWhereEdgeLengthsVary20x)
{
    CMeshO m;
    MakeGradedWaist(m);
    double emin = 1e300, emax = 0;
    for (const auto &f : m.face)
        for (int k = 0; k < 3; ++k) {
            const double e = vcg::Distance(f.cP(k), f.cP((k + 1) % 3));
            emin = std::min(emin, e), emax = std::max(emax, e);
        }
    EXPECT_GT(emax / emin, 20.0);
    auto surf = WithEnergy(m, FeatureEnergyType::PartBoundary);
    const double e0 = GradedEdge(0); // the edge length on the waist
    struct Case
    {
        double zSeed;
        bool run;
        double maxOff; // bound on the farthest point off the waist, in waist edges
    };
    // measured: 0.87, 0.87, 1.95, 1.95 and 0.87 waist edges (1.95: on the coarse ring for part of the way)
    for (const Case c : {Case{-0.08, true, 1.0}, Case{-0.08, false, 1.0}, Case{0.12, false, 2.5}, Case{0.12, true, 2.5},
                         Case{0.3, true, 2.5}}) {
        std::vector<P3> pts;
        for (int i = 0; i < 8; ++i)
            pts.push_back(P3(std::cos(M_PI * i / 4), std::sin(M_PI * i / 4), 0) * TubeRadius(c.zSeed) + P3(0, 0, c.zSeed));
        Snake s(surf);
        s.InitFromSeeds(gs_test::NearestVertices(m, pts), true);
        if (c.run)
            s.Run(400);
        else
            s.EndRun(SnakeStop::Converged);
        ASSERT_EQ(s.Stats().stop, SnakeStop::Converged) << "seeds at z = " << c.zSeed;
        ASSERT_TRUE(PartBoundaryEnd<CMeshO>::FinishRun(s, FeatureEnergyType::PartBoundary, false)) << "seeds at z = " << c.zSeed;
        double maxOff = 0, len = 0;
        const std::vector<P3> l = s.PolylinePositions();
        for (size_t i = 0; i < l.size(); ++i) {
            maxOff = std::max(maxOff, std::fabs(l[i][2]) / e0);
            len += vcg::Distance(l[i], l[(i + 1) % l.size()]);
        }
        const double ratio = len / (2 * M_PI * TubeRadius(0));
        std::printf("graded waist (edges %.3f-%.3f), seeds at z = %.2f, %s: %zu samples, max %.2f waist edges off "
                    "the waist, length %.3f of the waist's\n",
                    emin, emax, c.zSeed, c.run ? "Run" : "valley loop alone", l.size(), maxOff, ratio);
        EXPECT_LT(maxOff, c.maxOff);
        EXPECT_GT(ratio, 0.95); // measured 0.999-1.032: the whole way round, never a point or a stub
        EXPECT_LT(ratio, 1.1);
    }
}

namespace {

// A tube whose wall turns outwards at z = 0 (radius 1 + 0.2 z below, 1 + z above: a concave
// crease ring, the base of a flaring part), rings kKneeStep apart with kKneeStep-long edges
// round them, one ring exactly on the crease, quads split by one diagonal. The shortest loops
// round it lie below the crease.
const double kKneeStep = 0.05;
double KneeRadius(double z, double up = 1.0) { return 1.0 + (z < 0 ? 0.2 : up) * z; }

void MakeKneeTube(CMeshO &m, double up = 1.0)
{
    const int rings = 25, n = int(std::lround(2 * M_PI / kKneeStep));
    for (int j = 0; j < rings; ++j) {
        const double z = (j - rings / 2) * kKneeStep;
        auto vi = vcg::tri::Allocator<CMeshO>::AddVertices(m, n);
        for (int k = 0; k < n; ++k, ++vi)
            vi->P() = Point3m(KneeRadius(z, up) * std::cos(2 * M_PI * k / n), KneeRadius(z, up) * std::sin(2 * M_PI * k / n), z);
    }
    for (int j = 0; j + 1 < rings; ++j)
        for (int k = 0; k < n; ++k) {
            auto V = [&](int jj, int kk) { return &m.vert[jj * n + kk % n]; };
            vcg::tri::Allocator<CMeshO>::AddFace(m, V(j, k), V(j, k + 1), V(j + 1, k)); // outward
            vcg::tri::Allocator<CMeshO>::AddFace(m, V(j, k + 1), V(j + 1, k + 1), V(j + 1, k));
        }
    gs_test::EnableSnakeAdjacency(m);
    vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFace(m);
}

// The knee tube with its part 0.4 as steep (noisy: the benchmark's noise variant, +-0.2 h along
// the normal) and a loop of 32 points round it a ring below the crease, with the faces at its
// points (as a snake's samples' for ValleyLoop::Find); false when the variant fails.
bool MakeKneeTubeLoop(CMeshO &m, bool noisy, std::vector<P3> &loop, std::vector<int> &faces)
{
    MakeKneeTube(m, 0.4);
    if (noisy) {
        std::vector<std::vector<int>> segs;
        if (!gs_parts::ApplyVariant(m, segs, "noise")) return false;
        vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFace(m);
    }
    for (int i = 0; i < 32; ++i)
        loop.push_back(P3(std::cos(M_PI * i / 16), std::sin(M_PI * i / 16), 0) * KneeRadius(-kKneeStep) + P3(0, 0, -kKneeStep));
    for (int v : gs_test::NearestVertices(m, loop)) faces.push_back(int(m.vert[v].cVFp() - &m.face[0]));
    return true;
}

// Edge loop vl's mean distance off the knee tube's crease (z = 0) in rings, its largest in
// maxOff; 1e9 when it is empty.
double RingsOffCrease(const CMeshO &m, const std::vector<int> &vl, double &maxOff)
{
    double sum = 0;
    maxOff = 0;
    for (int v : vl) {
        const double z = std::fabs(m.vert[v].cP()[2]) / kKneeStep;
        sum += z, maxOff = std::max(maxOff, z);
    }
    return vl.empty() ? 1e9 : sum / vl.size();
}

} // namespace

// The valley loop follows the mesh's own concave crease where the energy is a flat-floored
// valley wider than the band (here a constant 0.5: the energy cannot tell where in the valley
// the crease runs). The loop round the tube a ring below the crease ends on the crease's
// ring of edges, every vertex exactly on it; by energy and length alone (concavityWeight 0, as
// before) it ran on a shorter ring of the band, below the crease.
TEST(ValleyLoop, FollowsTheConcaveCreaseInAFlatValley)
{
    CMeshO m;
    MakeKneeTube(m);
    const std::vector<double> flat(m.vert.size(), 0.5);
    std::vector<P3> loop;
    std::vector<P3> near;
    for (int i = 0; i < 32; ++i) {
        const P3 x = P3(std::cos(M_PI * i / 16), std::sin(M_PI * i / 16), 0) * KneeRadius(-kKneeStep) + P3(0, 0, -kKneeStep);
        loop.push_back(x);
        near.push_back(x);
    }
    std::vector<int> faces;
    for (int v : gs_test::NearestVertices(m, near)) faces.push_back(int(m.vert[v].cVFp() - &m.face[0]));
    auto farthest = [&](const std::vector<int> &vl) {
        double z = 0;
        for (int v : vl) z = std::max(z, std::fabs(m.vert[v].cP()[2]) / kKneeStep);
        return z;
    };
    const std::vector<int> crease = ValleyLoop<CMeshO>::Find(m, loop, faces, flat, kKneeStep);
    ValleyLoop<CMeshO>::Param plain;
    plain.concavityWeight = 0;
    const std::vector<int> shortest = ValleyLoop<CMeshO>::Find(m, loop, faces, flat, kKneeStep, plain);
    std::printf("knee tube: with the crease term %zu vertices, max %.2f rings off the crease; without %zu, %.2f\n",
                crease.size(), farthest(crease), shortest.size(), farthest(shortest));
    ASSERT_GE(crease.size(), 100u); // round the whole tube (126 vertices a ring)
    EXPECT_LT(farthest(crease), 1e-6);
    ASSERT_GE(shortest.size(), 100u);
    EXPECT_GT(farthest(shortest), 0.9); // the mechanism: length alone leaves the crease
}

// The crease term with scan noise (session 29): a knee tube with a shallow crease (slope 0.2
// below, 0.4 above: 0.18 rad) and every vertex moved along its normal by +-0.2 of an edge
// (gs_parts --variant noise). Many of the band's edges are now concave at one ring, on the
// flanks as well as on the crease, and the loop priced by one-ring concavity alone
// (concavityRings 0, as before) follows them off the crease: mean 0.51, max 2.0 rings off.
// Counting an edge only where the surface is also concave across it at the scale of a ring
// (concavityRings 1, left off: see its Param) keeps it nearer: mean 0.18, max 1.1. (Measured with the upper slope 0.25,
// 0.3, 0.4, 0.6, 1.0: mean 1.08, 0.75, 0.18, 0.09, 0.07 against 0.87, 0.87, 0.51, 0.25,
// 0.08 one ring: a crease much shallower than the noise is lost either way.)
TEST(ValleyLoop, FollowsTheConcaveCreaseInAFlatValleyWithNoise)
{
    CMeshO m;
    std::vector<P3> loop;
    std::vector<int> faces;
    ASSERT_TRUE(MakeKneeTubeLoop(m, true, loop, faces));
    const std::vector<double> flat(m.vert.size(), 0.5);
    ValleyLoop<CMeshO>::Param oneRing, ringScale;
    oneRing.concavityRings = 0;
    ringScale.concavityRings = 1;
    oneRing.creaseFilter.iterations = ringScale.creaseFilter.iterations = 0; // the raw normals (session 32's filter: off)
    const std::vector<int> scaled = ValleyLoop<CMeshO>::Find(m, loop, faces, flat, kKneeStep, ringScale);
    const std::vector<int> plain = ValleyLoop<CMeshO>::Find(m, loop, faces, flat, kKneeStep, oneRing);
    double maxS, maxP;
    const double meanS = RingsOffCrease(m, scaled, maxS), meanP = RingsOffCrease(m, plain, maxP);
    std::printf("noisy knee tube: concave at a ring's scale %zu vertices, mean %.2f max %.2f rings off the crease; "
                "one ring %zu, mean %.2f max %.2f\n", scaled.size(), meanS, maxS, plain.size(), meanP, maxP);
    ASSERT_GE(scaled.size(), 100u);
    ASSERT_GE(plain.size(), 100u);
    EXPECT_LT(meanS, 0.3);
    EXPECT_LT(maxS, 1.5);
    EXPECT_GT(meanP, 0.4); // the mechanism: one-ring concavity is noise here
    EXPECT_GT(maxP, 1.5);
}

// The same noisy knee tube with the crease term read from feature-preserving filtered normals
// (session 31, ValleyLoop::Param::creaseFilter, crease_normals.h: the thresholded filter of vcglib's
// Smooth::FaceNormalAngleThreshold over the band): the noise on the flanks is smoothed, the
// crease stays where it is, and the loop follows it where the raw one-ring angles lead it off.
// The search and CostParts price the found loop alike (the filter runs on the faces within its
// iterations' rings, whichever set it is given). Measured (3 passes, cos 30 degrees): mean 0.21,
// max 1.04 rings off, against 0.51 and 2.01 raw; 5 passes or cos 45 degrees: 0.03 and 0.07;
// 1-2 passes at 30 degrees or up to 5 at 20: 0.33-0.53 (the crease, 0.18 rad, is shallower than
// the threshold, so here the filter smooths across it as an isotropic one would).
TEST(ValleyLoop, FollowsTheNoisyCreaseWithFilteredNormals)
{
    CMeshO m;
    std::vector<P3> loop;
    std::vector<int> faces;
    ASSERT_TRUE(MakeKneeTubeLoop(m, true, loop, faces));
    const std::vector<double> flat(m.vert.size(), 0.5);
    ValleyLoop<CMeshO>::Param raw, filtered;
    raw.creaseFilter.iterations = 0;
    filtered.creaseFilter.iterations = 3;
    filtered.creaseFilter.cos = 0.866;
    filtered.creaseFilter.relative = 0, filtered.creaseFilter.relativeWhole = false, filtered.creaseFilter.noiseMin = 0; // the fixed threshold
    double ref = -1, cost = 0;
    const std::vector<int> f = ValleyLoop<CMeshO>::FindAt(m, loop, faces, flat, kKneeStep, filtered, ref, cost);
    const std::vector<int> p = ValleyLoop<CMeshO>::Find(m, loop, faces, flat, kKneeStep, raw);
    double maxF, maxP;
    const double meanF = RingsOffCrease(m, f, maxF), meanP = RingsOffCrease(m, p, maxP);
    std::printf("noisy knee tube: filtered normals %zu vertices, mean %.2f max %.2f rings off the crease; "
                "raw %zu, mean %.2f max %.2f\n", f.size(), meanF, maxF, p.size(), meanP, maxP);
    ASSERT_GE(f.size(), 100u);
    ASSERT_GE(p.size(), 100u);
    EXPECT_LT(meanF, 0.3);
    EXPECT_LT(maxF, 1.5);
    EXPECT_GT(meanP, 0.4); // the mechanism: the raw one-ring angles are noise here
    double len = 0;
    EXPECT_NEAR(ValleyLoop<CMeshO>::Cost(m, f, flat, ref, filtered, len), cost, 1e-9 * cost);
}

// The filter of FollowsTheNoisyCreaseWithFilteredNormals with a threshold relative to the
// surface's own angles (session 31, creaseFilter.relative: k times the median angle between
// vertex-adjacent faces). Over the whole mesh (creaseFilter.relativeWhole) the band and the
// loop's own faces get the same threshold, so CostParts prices the found loop as the search did;
// over the filtered set alone they do not (the loop's faces sit on the crease; measured 0.999).
TEST(ValleyLoop, FollowsTheNoisyCreaseWithARelativeFilterThreshold)
{
    CMeshO m;
    std::vector<P3> loop;
    std::vector<int> faces;
    ASSERT_TRUE(MakeKneeTubeLoop(m, true, loop, faces));
    const std::vector<double> flat(m.vert.size(), 0.5);
    ValleyLoop<CMeshO>::Param whole, band;
    whole.creaseFilter.iterations = band.creaseFilter.iterations = 3;
    whole.creaseFilter.relative = band.creaseFilter.relative = 2;
    whole.creaseFilter.relativeWhole = true;
    band.creaseFilter.relativeWhole = false;
    whole.creaseFilter.noiseMin = band.creaseFilter.noiseMin = 0; // no gate (session 32)
    double refW = -1, costW = 0, refB = -1, costB = 0, len = 0;
    const std::vector<int> w = ValleyLoop<CMeshO>::FindAt(m, loop, faces, flat, kKneeStep, whole, refW, costW);
    const std::vector<int> b = ValleyLoop<CMeshO>::FindAt(m, loop, faces, flat, kKneeStep, band, refB, costB);
    double maxOff = 0;
    const double meanW = RingsOffCrease(m, w, maxOff);
    const double costB2 = ValleyLoop<CMeshO>::Cost(m, b, flat, refB, band, len);
    std::printf("noisy knee tube, relative threshold: %zu vertices, mean %.2f max %.2f rings off; "
                "CostParts / search: whole %.9f, band %.6f\n", w.size(), meanW, maxOff,
                ValleyLoop<CMeshO>::Cost(m, w, flat, refW, whole, len) / costW, costB2 / costB);
    ASSERT_GE(w.size(), 100u);
    EXPECT_LT(meanW, 0.15); // measured 0.03 (k 2, 3 passes); the fixed 30 degrees: 0.21
    EXPECT_NEAR(ValleyLoop<CMeshO>::Cost(m, w, flat, refW, whole, len), costW, 1e-9 * costW);
    EXPECT_GT(std::fabs(costB2 - costB), 1e-6 * costB); // the mechanism: the set's own median differs
}

// The crease filter gated by the surface's noise (sessions 32-33, the defaults: creaseFilter.noiseMin
// 0.06 over SurfaceNoise::Level, 8 passes, the threshold twice the mesh's median
// face-to-face angle). The noisy knee tube measures above the gate, and the default loop
// follows the crease where the raw normals lead it off; the clean knee tube measures below it,
// and its reference and loop are exactly those without the filter (with the gate at 0 the
// filter runs there too and changes the reference).
TEST(ValleyLoop, FiltersTheCreaseTermOnlyOnANoisySurface)
{
    ValleyLoop<CMeshO>::Param def, off, ungated;
    off.creaseFilter.iterations = 0;
    ungated.creaseFilter.noiseMin = 0;
    EXPECT_GT(def.creaseFilter.iterations, 0);
    EXPECT_GT(def.creaseFilter.noiseMin, 0);
    // noisy: the filter runs and keeps the loop on the crease
    CMeshO n;
    std::vector<P3> loopN;
    std::vector<int> facesN;
    ASSERT_TRUE(MakeKneeTubeLoop(n, true, loopN, facesN));
    const std::vector<double> flatN(n.vert.size(), 0.5);
    const double levelN = SurfaceNoise<CMeshO>::Level(n);
    double refD = -1, costD = 0, refO = -1, costO = 0;
    const std::vector<int> d = ValleyLoop<CMeshO>::FindAt(n, loopN, facesN, flatN, kKneeStep, def, refD, costD);
    const std::vector<int> o = ValleyLoop<CMeshO>::FindAt(n, loopN, facesN, flatN, kKneeStep, off, refO, costO);
    double maxD, maxO;
    const double offD = RingsOffCrease(n, d, maxD), offO = RingsOffCrease(n, o, maxO);
    // clean: below the gate, the same reference and loop as without the filter
    CMeshO c;
    std::vector<P3> loopC;
    std::vector<int> facesC;
    ASSERT_TRUE(MakeKneeTubeLoop(c, false, loopC, facesC));
    const std::vector<double> flatC(c.vert.size(), 0.5);
    const double levelC = SurfaceNoise<CMeshO>::Level(c);
    double refCD = -1, costCD = 0, refCO = -1, costCO = 0, refCU = -1, costCU = 0;
    const std::vector<int> cd = ValleyLoop<CMeshO>::FindAt(c, loopC, facesC, flatC, kKneeStep, def, refCD, costCD);
    const std::vector<int> co = ValleyLoop<CMeshO>::FindAt(c, loopC, facesC, flatC, kKneeStep, off, refCO, costCO);
    const std::vector<int> cu = ValleyLoop<CMeshO>::FindAt(c, loopC, facesC, flatC, kKneeStep, ungated, refCU, costCU);
    std::printf("knee tube noise level: noisy %.4f h, clean %.4f h (gate %.3f); noisy loop mean %.2f rings off with the "
                "default, %.2f without the filter; clean reference %.6f default, %.6f off, %.6f ungated\n",
                levelN, levelC, def.creaseFilter.noiseMin, offD, offO, refCD, refCO, refCU);
    EXPECT_GT(levelN, def.creaseFilter.noiseMin);
    EXPECT_LT(levelC, def.creaseFilter.noiseMin);
    ASSERT_GE(d.size(), 100u);
    ASSERT_GE(o.size(), 100u);
    EXPECT_LT(offD, 0.15);
    EXPECT_GT(offO, 0.4); // the mechanism: the raw one-ring angles are noise here
    EXPECT_EQ(cd, co);
    EXPECT_EQ(refCD, refCO);
    EXPECT_EQ(costCD, costCO);
    EXPECT_GT(std::fabs(refCU - refCO), 1e-6 * refCO); // ungated, the filter would change the clean reference
    // the mesh's measures taken once (CreaseNormals::Measured, as PartBoundaryEnd::FinishRun
    // does) price as those taken at each call: the noisy tube's level and median angle, the
    // clean one's level alone (gated: no median)
    ValleyLoop<CMeshO>::Param mn = def, mc = def;
    mn.creaseFilter = CreaseNormals<CMeshO>::Measured(n, def.creaseFilter);
    mc.creaseFilter = CreaseNormals<CMeshO>::Measured(c, def.creaseFilter);
    EXPECT_EQ(mn.creaseFilter.noiseLevel, levelN);
    EXPECT_EQ(mn.creaseFilter.medianAngle, CreaseNormals<CMeshO>::MedianAngle(n));
    EXPECT_GT(mn.creaseFilter.medianAngle, 0);
    EXPECT_EQ(mc.creaseFilter.noiseLevel, levelC);
    EXPECT_LT(mc.creaseFilter.medianAngle, 0);
    double refMN = -1, costMN = 0, refMC = -1, costMC = 0;
    EXPECT_EQ(ValleyLoop<CMeshO>::FindAt(n, loopN, facesN, flatN, kKneeStep, mn, refMN, costMN), d);
    EXPECT_EQ(refMN, refD);
    EXPECT_EQ(costMN, costD);
    EXPECT_EQ(ValleyLoop<CMeshO>::FindAt(c, loopC, facesC, flatC, kKneeStep, mc, refMC, costMC), cd);
    EXPECT_EQ(refMC, refCD);
    EXPECT_EQ(costMC, costCD);
}

// SurfaceNoise::Level reads the noise's rms, not the shape (session 33): uniform noise +-A h
// along the normal (tests/part_variants.h's noiseA) reads about its rms A/sqrt(3) whatever the
// mesh's shape, a clean mesh reads near 0 even where session 32's two-ring fit residual
// (FitResidual) is high: the bearing's sharp creases (0.094 h, above session 32's gate 0.085)
// and the armadillo scan's detail.
TEST(SurfaceNoise, ReadsTheNoiseRmsNotTheShape)
{
    for (int id : {161, 381}) {
        gs_parts::Model clean;
        ASSERT_TRUE(gs_parts::LoadModel(GS_SEGMENTATION_DIR, id, clean)) << GS_SEGMENTATION_DIR;
        const double l0 = SurfaceNoise<CMeshO>::Level(clean.mesh);
        std::printf("model %d: clean %.4f h (fit residual %.4f h)", id, l0, SurfaceNoise<CMeshO>::FitResidual(clean.mesh));
        EXPECT_LT(l0, 0.02) << id; // measured 0.006 teddy, 0 fourleg
        for (double a : {0.1, 0.2, 0.3}) {
            gs_parts::Model md;
            ASSERT_TRUE(gs_parts::LoadModel(GS_SEGMENTATION_DIR, id, md, "noise" + std::to_string(a).substr(0, 3)));
            const double l = SurfaceNoise<CMeshO>::Level(md.mesh), rms = a / std::sqrt(3.0);
            std::printf(", +-%.1f h %.4f (rms %.4f)", a, l, rms);
            EXPECT_NEAR(l, rms, 0.15 * rms) << id << " +-" << a;
        }
        std::printf("\n");
    }
    gs_parts::Model bearing;
    ASSERT_TRUE(gs_parts::LoadModel(GS_SEGMENTATION_DIR, 341, bearing)) << GS_SEGMENTATION_DIR;
    const double lb = SurfaceNoise<CMeshO>::Level(bearing.mesh), rb = SurfaceNoise<CMeshO>::FitResidual(bearing.mesh);
    std::printf("bearing 341: %.4f h (fit residual %.4f h)\n", lb, rb);
    EXPECT_GT(rb, 0.085); // the mechanism: a quadric does not fit the creases
    EXPECT_LT(lb, 0.01);  // measured 0.002
    EXPECT_LT(lb, ValleyLoop<CMeshO>::Param().creaseFilter.noiseMin);
}

// The sides of a loop are flooded only as far as the part it cuts off: a cap of 3.5 % of a
// sphere (z > 0.93, a band of loop vertices 0.90 < z <= 0.93 round it) is measured exactly,
// and the flood stops once the rest has been seen to be the body (maxPart 1/3: twice the cap's
// area), far short of the sphere's 40962 vertices. Flooding every side to its end (the cost of
// the whole mesh, what part salience did before) would visit them all.
TEST(PartSalience, SidesFloodOnlyAsFarAsThePart)
{
    CMeshO m;
    gs_test::MakeIcosphere(m, 6);
    m.vert.EnableVFAdjacency();
    m.face.EnableVFAdjacency();
    UpdateTopology<CMeshO>::VertexFace(m);
    std::vector<int> loop;
    auto z = [&](int v) { return double(m.vert[v].cP()[2]); };
    for (int v = 0; v < int(m.vert.size()); ++v)
        if (z(v) > 0.90 && z(v) <= 0.93) loop.push_back(v);
    double cap = 0; // faces with a vertex above the loop
    size_t capVerts = 0;
    for (int v = 0; v < int(m.vert.size()); ++v) capVerts += z(v) > 0.93;
    for (const auto &f : m.face) {
        bool above = false;
        for (int k = 0; k < 3; ++k) above = above || z(int(f.cV(k) - &m.vert[0])) > 0.93;
        if (above) cap += vcg::DoubleArea(f) / 2;
    }
    PartSalience<CMeshO>::Sides s(m, loop);
    // as Choose stops: one side left growing, at least twice the ended one's area
    auto bodyKnown = [&] {
        return s.growing == 1 && s.ended.size() == 1 && s.area[s.GrowingSide()] > 2 * s.area[s.ended[0]];
    };
    while (!bodyKnown() && s.Step()) {}
    ASSERT_TRUE(bodyKnown());
    std::printf("cap: %zu vertices, loop %zu, flooded %zu of %zu\n", capVerts, loop.size(), s.visited, m.vert.size());
    EXPECT_NEAR(s.area[s.ended[0]], cap, 1e-9 * cap);
    EXPECT_NEAR(cap / (4 * M_PI), 0.035, 0.003);
    EXPECT_LT(s.visited, 6 * capVerts);
    EXPECT_LT(s.visited, m.vert.size() / 4);
    while (s.Step()) {}
    EXPECT_EQ(s.visited, m.vert.size() - loop.size());
    EXPECT_EQ(s.ended.size(), 2u);
}

// A candidate loop that leaves the first loop's part on its larger side (part salience's 1/3
// test, PartSalience::PartArea): a loop round the far end of a sphere (a band, -0.93 < z <=
// -0.90) with the first loop's part (the cap z > 0.93, rep its pole) beyond it. That side is no
// part; once the far cap has ended and the side left growing is past half of the rest (maxPart
// 1/3), nothing it still adds can make it one (session 29): it is not flooded to the pole, the
// whole sphere, and the answer is the full flood's. The first loop itself: its cap, true. A
// loop that cuts nothing off (an arc) is known as such once the floods round it meet
// (Sides::OneSide), not after flooding the sphere.
TEST(PartSalience, PartAreaStopsWhereTheLargerSideIsNoPart)
{
    CMeshO m;
    gs_test::MakeIcosphere(m, 6);
    m.vert.EnableVFAdjacency();
    m.face.EnableVFAdjacency();
    vcg::tri::UpdateTopology<CMeshO>::VertexFace(m);
    typedef vcg::tri::PartSalience<CMeshO> PS;
    auto z = [&](int v) { return double(m.vert[v].cP()[2]); };
    auto band = [&](double lo, double hi) {
        std::vector<int> l;
        for (int v = 0; v < int(m.vert.size()); ++v)
            if (z(v) > lo && z(v) <= hi) l.push_back(v);
        return l;
    };
    const std::vector<int> top = band(0.90, 0.93), bottom = band(-0.93, -0.90);
    int rep = 0;
    for (int v = 0; v < int(m.vert.size()); ++v)
        if (z(v) > z(rep)) rep = v;
    const double mp = 1.0 / 3;
    PS::Sides s0(m, top), sc(m, bottom);
    double A = -1;
    EXPECT_FALSE(PS::PartArea(sc, rep, s0, mp, A));
    std::printf("far loop: flooded %zu of %zu vertices\n", sc.visited, m.vert.size());
    EXPECT_LT(sc.visited, m.vert.size() / 4);
    // every side flooded to its end: the same answer
    PS::Sides full(m, bottom), s0Full(m, top);
    while (full.Step()) {}
    while (s0Full.Step()) {}
    ASSERT_TRUE(full.Ended(full.Side(rep)));
    EXPECT_FALSE(full.area[full.Side(rep)] < mp * s0Full.known);
    PS::Sides own(m, top);
    EXPECT_TRUE(PS::PartArea(own, rep, s0, mp, A));
    EXPECT_NEAR(A / (4 * M_PI), 0.035, 0.003);
    // half the band (x > 0), an arc: it cuts nothing off, known once the floods round it meet
    std::vector<int> arc;
    for (int v : top)
        if (m.vert[v].cP()[0] > 0) arc.push_back(v);
    PS::Sides a(m, arc);
    while (!a.OneSide() && a.Step()) {}
    EXPECT_TRUE(a.OneSide());
    EXPECT_LT(a.visited, m.vert.size() / 4);
    while (a.Step()) {}
    EXPECT_EQ(a.ended.size(), 1u);
}

namespace {

/// PartSalience::Choose on `loop` (its cost its length, no band, the score's own factors alone:
/// no width), the loop chosen sorted by vertex index.
template <class Find>
std::vector<int> ChosenBySalience(CMeshO &m, const std::vector<int> &loop, double h,
                                  typename vcg::tri::PartSalience<CMeshO>::Param par, Find find)
{
    typedef vcg::tri::PartSalience<CMeshO> PS;
    par.widthExponent = 0;
    auto inBand = [](const vcg::Point3d &) { return false; };
    std::vector<int> got = PS::Choose(m, loop, PS::Length(m, loop), h, par, find, inBand);
    std::sort(got.begin(), got.end());
    return got;
}

} // namespace

// Part salience's dominance (PartSalience::Param::dominantPrice, session 36): a bulb (radius 0.5)
// on a neck (radius 0.45, z 1.5-1.7) on a wide body, the loop round the bulb at z = 1.9, 1 per
// length; a guide into the body reaches a ring of the neck, 10 % shorter round a part 30-60 %
// larger, at 1.10 per length (every other ring 2). Its score, 1.10 x (0.9 / sqrt(1.3))^0.5 = 0.97
// of the loop's, is not below the margin (0.95): salience alone keeps the loop, the dominance takes
// a ring of the neck, and not when it costs more than dominantPrice x the loop's per length.
TEST(PartSalience, TakesAShorterCutRoundALargerPart)
{
    CMeshO m;
    const double step = 0.1, h = 0.1;
    gs_test::MakeRevolvedProfile(m,
                                 {{0.0, 3.0, 0},
                                  {0.5, 2.0, 0},  // the bulb's tip
                                  {0.5, 1.8, 0},  // the bulb
                                  {0.45, 1.7, 1}, // into the neck
                                  {0.45, 1.5, 0}, // the neck
                                  {2.0, 1.5, 0},  // the body's top
                                  {2.0, 0.0, 0},
                                  {0.0, 0.0, 0}},
                                 48, step, 0.45, 0);
    typedef vcg::tri::PartSalience<CMeshO> PS;
    auto rho = [&](int v) { return std::hypot(double(m.vert[v].cP()[0]), double(m.vert[v].cP()[1])); };
    auto ringAt = [&](double r, double z) { // the ring of radius r at height z, sorted
        std::vector<int> l;
        for (int v = 0; v < int(m.vert.size()); ++v)
            if (std::fabs(rho(v) - r) < 1e-4 && std::fabs(m.vert[v].cP()[2] - z) < 1e-4) l.push_back(v);
        return l;
    };
    const std::vector<int> loop = ringAt(0.5, 1.9);
    const std::vector<std::vector<int>> neck = {ringAt(0.45, 1.7), ringAt(0.45, 1.6), ringAt(0.45, 1.5)};
    ASSERT_EQ(loop.size(), 48u);
    for (const auto &r : neck) ASSERT_EQ(r.size(), 48u);
    auto onNeck = [&](const std::vector<int> &l) { return std::find(neck.begin(), neck.end(), l) != neck.end(); };
    // a candidate: the ring nearest the guide's mean (rho, z), the neck's at 1.10 per length
    auto find = [&](const std::vector<vcg::Point3d> &guide, const std::vector<int> &, double &c, bool, std::vector<int> *,
                    double *) {
        double r = 0, z = 0;
        for (const auto &p : guide) r += std::hypot(p[0], p[1]) / guide.size(), z += p[2] / guide.size();
        int best = -1;
        double d = 1e30;
        for (int v = 0; v < int(m.vert.size()); ++v)
            if (rho(v) > 1e-9 && std::hypot(rho(v) - r, m.vert[v].cP()[2] - z) < d) d = std::hypot(rho(v) - r, m.vert[v].cP()[2] - z), best = v;
        const std::vector<int> ring = ringAt(rho(best), m.vert[best].cP()[2]);
        c = (onNeck(ring) ? 1.10 : 2.0) * PS::Length(m, ring);
        return ring;
    };
    PS::Param par;
    auto chosen = [&]() { return ChosenBySalience(m, loop, h, par, find); };
    EXPECT_TRUE(onNeck(chosen()));
    par.dominantPrice = 0; // off: salience's score keeps the loop
    EXPECT_EQ(chosen(), loop);
    par.dominantPrice = 1.05; // dearer per length than that
    EXPECT_EQ(chosen(), loop);
}

// Part salience scores the descent's refused step (PartSalience::Param::refusedSteps, session 37):
// the bulb on a neck of TakesAShorterCutRoundALargerPart, the loop round the bulb at z = 1.9, 1 per
// length. Every guide into the body finds (descended) a ring on the body's top, radius ~0.9, 1 per
// length: twice as long round a part not twice as large, it scores worse than the loop. The
// descent's last step, to the neck's ring at z = 1.6, was refused at 1.05 per length (cheaper in
// total, dearer per length); scored, it is the most salient (1.05 x (0.9 / sqrt(1.3))^0.5 of the
// loop's). Without the refused step the loop stays.
TEST(PartSalience, ScoresTheDescentsRefusedStep)
{
    CMeshO m;
    const double step = 0.1, h = 0.1;
    gs_test::MakeRevolvedProfile(m,
                                 {{0.0, 3.0, 0},
                                  {0.5, 2.0, 0},
                                  {0.5, 1.8, 0},
                                  {0.45, 1.7, 1},
                                  {0.45, 1.5, 0},
                                  {2.0, 1.5, 0},
                                  {2.0, 0.0, 0},
                                  {0.0, 0.0, 0}},
                                 48, step, 0.45, 0);
    typedef vcg::tri::PartSalience<CMeshO> PS;
    auto rho = [&](int v) { return std::hypot(double(m.vert[v].cP()[0]), double(m.vert[v].cP()[1])); };
    auto ringNear = [&](double r, double z) { // the ring of the vertex nearest (r, z), sorted
        int best = -1;
        double d = 1e30;
        for (int v = 0; v < int(m.vert.size()); ++v)
            if (rho(v) > 1e-9 && std::hypot(rho(v) - r, m.vert[v].cP()[2] - z) < d)
                d = std::hypot(rho(v) - r, m.vert[v].cP()[2] - z), best = v;
        std::vector<int> l;
        for (int v = 0; v < int(m.vert.size()); ++v)
            if (std::fabs(rho(v) - rho(best)) < 1e-4 && std::fabs(m.vert[v].cP()[2] - m.vert[best].cP()[2]) < 1e-4)
                l.push_back(v);
        return l;
    };
    const std::vector<int> loop = ringNear(0.5, 1.9), wide = ringNear(0.9, 1.5), neck = ringNear(0.45, 1.6);
    ASSERT_EQ(loop.size(), 48u);
    ASSERT_EQ(neck.size(), 48u);
    ASSERT_GT(PS::Length(m, wide), 1.6 * PS::Length(m, loop));
    auto find = [&](const std::vector<vcg::Point3d> &, const std::vector<int> &, double &c, bool narrow,
                    std::vector<int> *refused, double *refusedCost) {
        if (narrow) return std::vector<int>(); // no width profile here
        c = PS::Length(m, wide);
        if (refused) *refused = neck, *refusedCost = 1.05 * PS::Length(m, neck);
        return wide;
    };
    PS::Param par;
    auto chosen = [&]() { return ChosenBySalience(m, loop, h, par, find); };
    EXPECT_EQ(chosen(), neck);
    par.refusedSteps = false; // the descended candidate alone
    EXPECT_EQ(chosen(), loop);
}

// A short part whose top lies within the valley loop's band (2.5 length units) of its base: a low
// bump 14 edges round (a fourleg's stubby leg, an ant's foot). The band round a loop on its rim
// covers the top and is no ring: its cheapest "loop" circles the top's middle (6.4 edges long
// round a 17-edge snake), and the snake's own loop was kept. The band is narrowed until it is a
// ring (PartBoundaryEnd::FinishRun, session 24): the edge loop then lies on the rim.
// Measured: FinishRun true, mean 0.34 h, max 0.48 h off the rim, from both seedings.
TEST(ValleyLoop, NarrowsABandThatCoversAShortPartsTop)
{
    const RevolvedRim low([](double phi) { return 1.0 + 0.1 * std::exp(-std::pow(phi / 0.12, 2)); });
    const CMeshO &m = low.m;
    const auto &surf = low.surf;
    const double h = low.h;
    EXPECT_LT(2 * M_PI * low.R(low.rim) * std::sin(low.rim) / h, 16.0); // a short rim, as the fourleg's legs
    for (double off : {0.0, 1.5}) { // on the rim, outside it
        Snake s(surf);
        s.InitFromSeeds(low.SeedsOff(off), true);
        s.Run(400);
        ASSERT_TRUE(s.Stats().converged);
        std::vector<int> faces;
        for (const auto &x : s.Samples()) faces.push_back(x.p.face);
        const double len = gs_parts::LoopLength(s.PolylinePositions());
        // the default band is no ring here: the premise of the test
        const std::vector<int> wide = ValleyLoop<CMeshO>::Find(m, s.PolylinePositions(), faces, surf->Energy(), s.LengthScale());
        EXPECT_LT(wide.size() < 3 ? 0.0 : ValleyLoop<CMeshO>::LengthOf(m, wide), 0.5 * len);
        EXPECT_TRUE(PartBoundaryEnd<CMeshO>::FinishRun(s, FeatureEnergyType::PartBoundary, false));
        const ParallelOffset o = low.OffRim(s);
        std::printf("low bump, seeds %.1f h off the rim: the edge loop mean %.2f h, max %.2f h off the rim\n", off, o.mean, o.max);
        EXPECT_LT(o.mean, 0.6);
        EXPECT_LT(o.max, 1.0);
    }
}

// ValleyLoop::CostParts (the diagnostics of bench/eval/gs_parts, GS_PARTS_COST) prices a loop
// as FindAt does: on the knee tube with the concavity reference below the crease's dihedral
// angle, the crease ring costs its length (energy 0.5 x length, no concavity cost), the ring
// below it its full length in concavity cost (convex edges), and the cost FindAt reports for
// the loop it finds is the sum of the parts with the Param's weights (ValleyLoop::Cost).
TEST(ValleyLoop, CostPartsPriceALoopAsTheSearchDoes)
{
    CMeshO m;
    MakeKneeTube(m);
    const int n = int(std::lround(2 * M_PI / kKneeStep)), crease = 12; // ring 12: z = 0
    const std::vector<double> flat(m.vert.size(), 0.5);
    std::vector<int> ring0, ring1;
    for (int k = 0; k < n; ++k) ring0.push_back(crease * n + k), ring1.push_back((crease - 1) * n + k);
    const double ref = 0.5; // below the crease's angle, atan(1) - atan(0.2) = 0.588: c = 1 on it
    double e, l, c;
    ValleyLoop<CMeshO>::CostParts(m, ring0, flat, ref, e, l, c);
    const double per0 = n * 2 * std::sin(M_PI / n);
    EXPECT_NEAR(l, per0, 1e-6);
    EXPECT_NEAR(e, 0.5 * per0, 1e-6);
    EXPECT_NEAR(c, 0.0, 1e-9);
    ValleyLoop<CMeshO>::CostParts(m, ring1, flat, ref, e, l, c);
    EXPECT_NEAR(l, KneeRadius(-kKneeStep) * per0, 1e-6);
    EXPECT_NEAR(c, l, 1e-5 * l); // every edge of a ring below the crease is convex round the tube (flat
                                 // across it, up to the float positions' rounding)
    std::vector<P3> loop;
    for (int v : ring1) loop.push_back(P3::Construct(m.vert[v].cP()));
    std::vector<int> faces;
    for (int v : ring1) faces.push_back(int(m.vert[v].cVFp() - &m.face[0]));
    ValleyLoop<CMeshO>::Param par;
    double r = ref, cost = 0;
    const std::vector<int> found = ValleyLoop<CMeshO>::FindAt(m, loop, faces, flat, kKneeStep, par, r, cost);
    ASSERT_GE(found.size(), 100u);
    ValleyLoop<CMeshO>::CostParts(m, found, flat, ref, e, l, c);
    EXPECT_NEAR(cost, e + par.lambda * l + par.concavityWeight * c, 1e-9 * cost);
    double len = 0; // Cost: the same sum, as the Run's end compares loops with (PerLength)
    EXPECT_NEAR(ValleyLoop<CMeshO>::Cost(m, found, flat, ref, par, len), cost, 1e-9 * cost);
    EXPECT_EQ(len, l);
}

// The filtered crease term gives an edge next to a zero-area face no crease, as the unfiltered
// one does (session 32's last fix, EdgeConcavity::Angle with CreaseNormals::Filtered's
// normals): the zero-area face keeps a zero filtered normal, and before the fix the edge was
// priced acos(0) = 90 degrees concave whenever the sign test ((n1 - n0) . (b1 - b0) < 0) tipped
// with the neighbour's filtered normal. A flat grid whose cell (a, b, c) is flattened to zero
// area (b moved to the midpoint of its diagonal a-c) beside the face (a, c, d); the grid rises
// beyond d (z = 0.5 (y - x - h) where y - x > h), so the filter tilts (a, c, d)'s normal
// towards the zero-area face and the sign test tips. The edge a-c, walked both ways
// (CostParts' loop {a, c}), costs its full length in concavity (c = 0 on it).
TEST(ValleyLoop, AZeroAreaFaceGivesItsEdgeNoCreaseWithFilteredNormals)
{
    CMeshO m;
    const int n = 8, i = 3, j = 3;
    const double h = 1.0 / n;
    gs_test::MakeFlatGrid(m, n);
    const auto idx = [&](int x, int y) { return y * (n + 1) + x; };
    for (auto &v : m.vert) {
        const double t = double(v.cP()[1]) - double(v.cP()[0]) - h;
        if (t > 1e-9) v.P()[2] = Scalarm(0.5 * t);
    }
    const int a = idx(i, j), b = idx(i + 1, j), c = idx(i + 1, j + 1);
    m.vert[b].P() = (m.vert[a].cP() + m.vert[c].cP()) * Scalarm(0.5); // (a, b, c): zero area
    gs_test::EnableSnakeAdjacency(m);
    vcg::tri::UpdateTopology<CMeshO>::VertexFace(m);
    const CFaceO *zero = nullptr, *beside = nullptr; // (a, b, c) and (a, c, d), d = (i, j + 1)
    for (const CFaceO &f : m.face) {
        auto has = [&](int v) { return f.cV(0) == &m.vert[v] || f.cV(1) == &m.vert[v] || f.cV(2) == &m.vert[v]; };
        if (has(a) && has(c)) (has(b) ? zero : beside) = &f;
    }
    ASSERT_TRUE(zero && beside);
    ASSERT_EQ(vcg::DoubleArea(*zero), 0);
    ValleyLoop<CMeshO>::Param par;
    par.creaseFilter.iterations = 1;
    par.creaseFilter.relative = 0, par.creaseFilter.cos = 0.5; // a fixed 60-degree threshold
    par.creaseFilter.noiseMin = 0;                              // no gate by the surface's noise
    par.concavityRings = 1;
    // the mechanism: the zero-area face's filtered normal stays zero, its neighbour's turns
    // towards it (the sign test's side: n . (b_zero - b_beside) > 0)
    const auto fn = CreaseNormals<CMeshO>::Filtered(m, {zero, beside}, par.creaseFilter);
    ASSERT_EQ(fn.count(zero), 1u);
    ASSERT_EQ(fn.count(beside), 1u);
    EXPECT_EQ(fn.at(zero).Norm(), 0);
    const P3 b0 = P3::Construct(vcg::Barycenter(*zero)), b1 = P3::Construct(vcg::Barycenter(*beside));
    EXPECT_GT(fn.at(beside) * (b0 - b1), 1e-3 * h);
    const std::vector<double> flat(m.vert.size(), 0.5);
    double e, l, cs;
    ValleyLoop<CMeshO>::CostParts(m, {a, c}, flat, 1.0, e, l, cs, par);
    EXPECT_NEAR(l, 2 * std::sqrt(2.0) * h, 1e-6);
    EXPECT_NEAR(cs, l, 1e-12 * l); // no concavity on the edge (before the fix: c = 1, cs = 0)
}

// The hosts take the Run's end's measures of their mesh once (session 33,
// SnakeSession::RunEndParam: the noise level and the median face angle the crease filter reads,
// PartBoundaryEnd::Measured), not at every Run's end, and again when the energy is recomputed
// (the mesh may have changed); other energies leave them unmeasured (FinishRun does nothing
// there). On the noisy knee tube (above the gate: both measures taken), its z then halved.
TEST(PartBoundaryEnd, TheSessionTakesTheMeshsMeasuresOnceAndAgainWithTheEnergy)
{
    CMeshO m;
    std::vector<P3> loop;
    std::vector<int> faces;
    ASSERT_TRUE(MakeKneeTubeLoop(m, true, loop, faces));
    SnakeController<CMeshO> ctl(m);
    ctl.ComputeEnergy(FeatureEnergyType::NormalVariation, 2);
    EXPECT_LT(ctl.RunEndParam().valley.creaseFilter.noiseLevel, 0);
    EXPECT_LT(ctl.RunEndParam().valley.creaseFilter.medianAngle, 0);
    ctl.ComputeEnergy(FeatureEnergyType::PartBoundary, 2);
    const auto &cf = ctl.RunEndParam().valley.creaseFilter;
    const auto want = PartBoundaryEnd<CMeshO>::Measured(m, PartBoundaryEnd<CMeshO>::Param()).valley.creaseFilter;
    EXPECT_EQ(cf.noiseLevel, SurfaceNoise<CMeshO>::Level(m));
    EXPECT_GT(cf.noiseLevel, cf.noiseMin);
    EXPECT_EQ(cf.medianAngle, want.medianAngle);
    EXPECT_GT(cf.medianAngle, 0);
    const double median0 = cf.medianAngle;
    for (auto &v : m.vert) v.P()[2] *= Scalarm(0.5); // the mesh changes: its faces' angles
    EXPECT_EQ(ctl.RunEndParam().valley.creaseFilter.medianAngle, median0); // kept until the energy changes
    ctl.ComputeEnergy(FeatureEnergyType::PartBoundary, 2);
    const auto again = PartBoundaryEnd<CMeshO>::Measured(m, PartBoundaryEnd<CMeshO>::Param()).valley.creaseFilter;
    EXPECT_NE(again.medianAngle, median0);
    EXPECT_EQ(ctl.RunEndParam().valley.creaseFilter.medianAngle, again.medianAngle);
    EXPECT_EQ(ctl.RunEndParam().valley.creaseFilter.noiseLevel, again.noiseLevel);
}

// A loop that converged at less than half the length it was seeded with (PartBoundaryEnd::Param::
// seededShrink, session 25): on the benchmark, outside loops that slid through a leg's narrowing
// onto the leg (fourleg 381 part 3). On a tall bump (its rim a concave valley 35 edges round):
// a loop that ended 4 h up the bump (a Run that converged there, set by EndRun as the edit tool
// does) is brought to the rim when the loop it was seeded with lay 2 h outside the rim, and is
// left up the bump without it; a loop that converged on the rim stays there although it was
// seeded on the featureless equator, more than twice as long (the seeded search is taken only
// when cheaper per length). Measured: up the bump 3.93 h off the rim without the seeded loop
// (FinishRun finds no ring there), 0.31 h with it; on the rim 0.31 h with an equator seed
// (16.6 h, on the equator's band, when the seeded search is taken without the price test).
TEST(ValleyLoop, SearchesRoundTheSeededLoopWhenTheSnakeShrankFar)
{
    const RevolvedRim leg([](double phi) { return 1.0 + 0.8 * std::exp(-std::pow(phi / 0.25, 2)); });
    const auto &surf = leg.surf;
    Snake outside(surf);
    outside.InitFromSeeds(leg.SeedsOff(2), true);
    const auto seeded = PartBoundaryEnd<CMeshO>::Seeded::Of(outside);
    const PartBoundaryEnd<CMeshO>::Param par;
    double off[2] = {0, 0};
    for (int with : {0, 1}) {
        Snake up(surf);
        up.InitFromSeeds(leg.SeedsOff(-4), true);
        up.EndRun(SnakeStop::Converged);
        ASSERT_LT(gs_parts::LoopLength(up.PolylinePositions()), par.seededShrink * gs_parts::LoopLength(seeded.loop)); // the premise
        const bool done = PartBoundaryEnd<CMeshO>::FinishRun(up, FeatureEnergyType::PartBoundary, false, par, with ? &seeded : nullptr);
        if (with) EXPECT_TRUE(done); // without it the bands round the loop cover the bump's top: no ring, the loop stays
        EXPECT_EQ(up.Stats().stop, SnakeStop::Converged);
        off[with] = leg.OffRim(up).mean;
    }
    std::printf("loop up the bump: %.2f h off the rim without the seeded loop, %.2f h with it\n", off[0], off[1]);
    EXPECT_GT(off[0], 2.0);
    EXPECT_LT(off[1], 0.6);
    // a loop that shrank onto the rim from the equator stays on the rim
    Snake wide(surf);
    wide.InitFromSeeds(RingSeeds(leg.m, leg.R, M_PI / 2), true);
    const auto equator = PartBoundaryEnd<CMeshO>::Seeded::Of(wide);
    Snake s(surf);
    s.InitFromSeeds(leg.SeedsOff(2), true);
    s.Run(400);
    ASSERT_EQ(s.Stats().stop, SnakeStop::Converged);
    ASSERT_LT(gs_parts::LoopLength(s.PolylinePositions()), par.seededShrink * gs_parts::LoopLength(equator.loop));
    ASSERT_TRUE(PartBoundaryEnd<CMeshO>::FinishRun(s, FeatureEnergyType::PartBoundary, false, par, &equator));
    std::printf("loop on the rim, seeded on the equator: %.2f h off the rim\n", leg.OffRim(s).mean);
    EXPECT_LT(leg.OffRim(s).mean, 0.6);
}

// The crease term does not depend on the tessellation (session 31): a bump's rim (a concave
// valley, constant energy so that the crease term alone places the loop) meshed as it is and
// with every face split 1-to-4 (gs_parts --variant refine: coplanar children, h halves) gives
// the same concavity reference and the same loop. The split makes edges of dihedral angle 0
// inside the old faces that float rounding tips either way: without flatTolerance (0) about
// half of them count as concave at ~1e-5 rad and the band's median concave angle, the
// reference, falls 40x (0.0911 -> 0.0023 rad; 0.0995 with it): every slightly concave edge is
// then priced as the crease (on the refined benchmark meshes the loop left the people's cut for
// a stretch; on this smooth bump it happens to end on the same loop, mean 0.55 / 0.46 h0 off
// the rim, either way).
TEST(ValleyLoop, SameReferenceAndLoopWhenEveryFaceIsSplit1To4)
{
    auto R = [](double phi) { return 1.0 + 0.5 * std::exp(-std::pow(phi / 0.35, 2)); };
    const double rim = RimOf(R);
    ValleyLoop<CMeshO>::Param par, off;
    off.flatTolerance = 0;
    EXPECT_GT(par.flatTolerance, 0); // the default
    struct Out
    {
        double ref[2] = {0, 0}, mean[2] = {0, 0}, maxOff[2] = {0, 0};
        size_t n[2] = {0, 0};
    } out[2];
    double h0 = 0;
    for (int refine : {0, 1}) {
        CMeshO m;
        MakeRevolved(m, R, 0.0);
        if (refine) {
            std::vector<std::vector<int>> segs;
            ASSERT_TRUE(gs_parts::ApplyVariant(m, segs, "refine"));
            gs_test::EnableSnakeAdjacency(m);
            vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFace(m);
        }
        const double h = gs_parts::MeanEdgeLength(m);
        if (!refine) h0 = h;
        const std::vector<double> flat(m.vert.size(), 0.5);
        std::vector<P3> loop, near;
        const double phi = rim + 1.0 * h0 / R(rim); // an edge of the original mesh off the rim
        for (int i = 0; i < 64; ++i) {
            const double a = 2 * M_PI * i / 64;
            loop.push_back(P3(std::sin(phi) * std::cos(a), std::sin(phi) * std::sin(a), std::cos(phi)) * R(phi));
        }
        std::vector<int> faces;
        for (int v : gs_test::NearestVertices(m, loop)) faces.push_back(int(m.vert[v].cVFp() - &m.face[0]));
        for (int k : {0, 1}) {
            double ref = -1, cost = 0;
            const std::vector<int> vl = ValleyLoop<CMeshO>::FindAt(m, loop, faces, flat, h, k ? off : par, ref, cost);
            std::vector<P3> pts;
            for (int v : vl) pts.push_back(P3::Construct(m.vert[v].cP()));
            const ParallelOffset o = OffParallel(pts, R, rim, h0); // in the original mesh's h
            out[refine].ref[k] = ref, out[refine].mean[k] = o.mean, out[refine].maxOff[k] = o.max, out[refine].n[k] = vl.size();
        }
    }
    for (int k : {0, 1})
        std::printf("bump rim, flatTolerance %s: reference %.4f / %.4f rad, loop %zu / %zu vertices, mean %.2f / %.2f h0, "
                    "max %.2f / %.2f h0 off the rim (original / split 1-to-4)\n",
                    k ? "0" : "default", out[0].ref[k], out[1].ref[k], out[0].n[k], out[1].n[k], out[0].mean[k], out[1].mean[k],
                    out[0].maxOff[k], out[1].maxOff[k]);
    ASSERT_GE(out[0].n[0], 20u);
    ASSERT_GE(out[1].n[0], 40u);
    EXPECT_NEAR(out[1].ref[0] / out[0].ref[0], 1.0, 0.1);
    EXPECT_LT(std::fabs(out[1].mean[0] - out[0].mean[0]), 0.25);
    EXPECT_LT(out[1].ref[1] / out[0].ref[1], 0.5); // the mechanism: rounding's "concave" flat edges
}

namespace {

// A limb of even width on a body, revolved round z with kLimbN vertices a ring, rings kLimbStep
// apart along the profile (quads split by one diagonal), closed: a wide flat head (the part's
// far end, so that the part's area barely changes along the limb) on a tube of radius 1 from
// z = 1.2 down to z = 0, where the body opens at 45 degrees (a cone to radius 4) and closes
// with a flat bottom. Returns the index of each tube ring's first vertex by its height in
// steps (ring[j]: z = j kLimbStep).
const double kLimbStep = 0.1;
const int kLimbN = 63;

std::vector<int> MakeLimbOnBody(CMeshO &m)
{
    return gs_test::MakeRevolvedProfile(m,
                                        {{0.0, 1.7, 0},
                                         {2.5, 1.7, 0},   // the head's top
                                         {2.5, 1.2, 0},   // its side
                                         {1.0, 1.2, 0},   // its underside
                                         {1.0, 0.0, 0},   // the limb
                                         {4.0, -3.0, 0},  // the body opens at 45 degrees
                                         {0.0, -3.0, 0}}, // the bottom
                                        kLimbN, kLimbStep, 1.0, 13);
}

} // namespace

// Where a limb of even width meets the body (issue 33, session 26: the width profile,
// part_profile.h). The energy is 0.5 everywhere but on a dimple ring 3 rings up the limb (0.2,
// where the snake settled) and on the limb's last ring before the body opens (0.18): that ring
// is a little cheaper per length (1.18 against 1.2 with lambda 1, the concavity term off), no
// longer, and cuts off a part only 4 % larger, so part salience's score (cost per length x
// (L / sqrt(A))^0.5) does not pass its margin of 0.95, and it lies beyond the band the descent
// searches (2.5 rings). The perimeter of the level sets into the body is constant for 3 units
// (the tube) and grows by 2 pi sin 45 = 4.4 per unit beyond: the profile's jump lies exactly on
// the limb's last ring, and the loop found there ends the Run; without it the dimple stays.
TEST(PartProfile, BringsALoopDownALimbToWhereTheBodyOpens)
{
    CMeshO m;
    const std::vector<int> ring = MakeLimbOnBody(m);
    ASSERT_GE(ring[0], 0);
    ASSERT_GE(ring[3], 0);
    std::vector<double> energy(m.vert.size(), 0.5);
    for (int k = 0; k < kLimbN; ++k) energy[ring[3] + k] = 0.2, energy[ring[0] + k] = 0.18;
    std::vector<P3> loop;
    std::vector<int> faces;
    for (int k = 0; k < kLimbN; ++k) {
        loop.push_back(P3::Construct(m.vert[ring[3] + k].cP()));
        faces.push_back(int(m.vert[ring[3] + k].cVFp() - &m.face[0]));
    }
    PartBoundaryEnd<CMeshO>::Param par;
    par.valley.concavityWeight = 0; // the crease at the limb's base would decide alone
    par.salience.widthExponent = 0; // the shape diameter's width term finds this ring too
    auto meanZ = [&](const std::vector<int> &vl) {
        double z = 0;
        for (int v : vl) z += m.vert[v].cP()[2] / (kLimbStep * vl.size());
        return z;
    };
    auto maxOff = [&](const std::vector<int> &vl, double z0) {
        double o = 0;
        for (int v : vl) o = std::max(o, std::fabs(m.vert[v].cP()[2] / kLimbStep - z0));
        return o;
    };
    double ref = -1, cost = 0;
    const std::vector<int> with = PartBoundaryEnd<CMeshO>::FinishFrom(m, loop, faces, energy, kLimbStep, par, ref, cost);
    PartBoundaryEnd<CMeshO>::Param off = par;
    off.salience.profile.slope = 0;
    ref = -1;
    const std::vector<int> without = PartBoundaryEnd<CMeshO>::FinishFrom(m, loop, faces, energy, kLimbStep, off, ref, cost);
    std::printf("limb on a body: with the profile %zu vertices at mean z %.3f rings, without %zu at %.3f\n", with.size(),
                meanZ(with), without.size(), meanZ(without));
    ASSERT_EQ(with.size(), size_t(kLimbN));
    EXPECT_LT(maxOff(with, 0.0), 1e-6); // every vertex on the limb's last ring
    ASSERT_EQ(without.size(), size_t(kLimbN));
    EXPECT_LT(maxOff(without, 3.0), 1e-6); // the mechanism: salience and the descent keep the dimple
}

// A loop one ring pair up a limb where people cut at its base (issue 33, session 28; hand 181
// part 0 and octopus 121 part 2 seeded inside): the energy is 0.5 everywhere but on the limb's
// ring 2 steps up (0.45, where the loop settled) and on its last ring before the body opens at
// 45 degrees (0.47). With the concavity and width terms off, the ring up the limb is the cheapest
// by every price of the Run's end (in total and per length, 1.45 against 1.47: the descent, part
// salience and the width profile keep it). Across that ring the limb is straight (bend 0); across
// the base ring the surface bends inwards (the minima rule's direction: about 0.76 h, measured 2
// units to each side), so the loop round the level loop 3 units towards the body replaces it
// (PartBoundaryEnd::Param::crossBend). Without the rule the loop stays 2 rings up.
TEST(PartBoundaryEnd, EndsWhereTheSurfaceBendsInwardsAcrossTheLoopNotUpAStraightLimb)
{
    CMeshO m;
    const std::vector<int> ring = MakeLimbOnBody(m);
    ASSERT_GE(ring[0], 0);
    ASSERT_GE(ring[2], 0);
    for (auto &v : m.vert) v.Q() = v.cP()[2] > 1.7 - 1e-6 ? 1.0 : (v.cP()[2] < -3 + 1e-6 ? 0.0 : 0.5); // the far ends fix the range
    for (int k = 0; k < kLimbN; ++k) m.vert[ring[2] + k].Q() = 0.45, m.vert[ring[0] + k].Q() = 0.47;
    auto surf = std::make_shared<Surface>(m, 0); // the energy: the vertices' quality, mapped to [0, 1]
    ASSERT_NEAR(surf->Energy()[ring[2]], 0.45, 1e-3);
    ASSERT_NEAR(surf->Energy()[ring[0]], 0.47, 1e-3);
    std::vector<int> seeds;
    for (int k = 0; k < kLimbN; k += 3) seeds.push_back(ring[2] + k);
    PartBoundaryEnd<CMeshO>::Param par;
    par.valley.concavityWeight = 0;        // the crease at the limb's base would decide alone
    par.salience.widthExponent = 0; // as would the width across it
    // on this grid (rings 1.003 units apart) the level loop 2 units down is ring 1, whose band
    // still holds the loop: steps of 1.5 units put the second level loop on the base ring
    par.crossStep = 1.5;
    auto endAt = [&](const PartBoundaryEnd<CMeshO>::Param &p, double &zMin, double &zMax) {
        Snake s(surf);
        s.InitFromSeeds(seeds, true);
        s.EndRun(SnakeStop::Converged); // a Run that converged on the seeded ring
        EXPECT_TRUE(PartBoundaryEnd<CMeshO>::FinishRun(s, FeatureEnergyType::PartBoundary, false, p));
        zMin = 1e9, zMax = -1e9;
        for (const P3 &x : s.PolylinePositions()) zMin = std::min(zMin, x[2]), zMax = std::max(zMax, x[2]);
    };
    double zMin, zMax;
    endAt(par, zMin, zMax);
    std::printf("limb on a body, seeded 2 rings up: the Run ends at z %.3f..%.3f\n", zMin, zMax);
    EXPECT_LT(std::max(std::fabs(zMin), std::fabs(zMax)), 1e-4); // the limb's base ring
    // the mechanism: without the bend across, every price keeps the ring up the limb
    PartBoundaryEnd<CMeshO>::Param off = par;
    off.crossBend = 0;
    endAt(off, zMin, zMax);
    std::printf("  without the bend across: z %.3f..%.3f\n", zMin, zMax);
    EXPECT_NEAR(zMin, 2 * kLimbStep, 1e-4);
    EXPECT_NEAR(zMax, 2 * kLimbStep, 1e-4);
    // the bend itself: 0 across the straight limb, inwards across its base
    std::vector<int> r0, r2;
    for (int k = 0; k < kLimbN; ++k) r0.push_back(ring[0] + k), r2.push_back(ring[2] + k);
    const double h = kLimbStep;
    EXPECT_NEAR(LoopBend<CMeshO>::Bend(m, r2, h, 2.0), 0.0, 1e-3);
    EXPECT_GT(LoopBend<CMeshO>::Bend(m, r0, h, 2.0), 0.5);
}

// The same limb where its base ring is as cheap per length as the ring 2 steps up (0.45 both,
// session 29): the bend across gained (about 0.76 h) falls short of a crossGain of 1 h, so the
// bend rule keeps the ring up the limb; a loop that bends more and costs no more per length is
// better by both of the Run's end's counts and needs no gain (Param::crossDominant).
TEST(PartBoundaryEnd, TakesALoopThatBendsMoreAndCostsNoMorePerLength)
{
    CMeshO m;
    const std::vector<int> ring = MakeLimbOnBody(m);
    ASSERT_GE(ring[0], 0);
    ASSERT_GE(ring[2], 0);
    for (auto &v : m.vert) v.Q() = v.cP()[2] > 1.7 - 1e-6 ? 1.0 : (v.cP()[2] < -3 + 1e-6 ? 0.0 : 0.5);
    for (int k = 0; k < kLimbN; ++k) m.vert[ring[2] + k].Q() = 0.45, m.vert[ring[0] + k].Q() = 0.45;
    auto surf = std::make_shared<Surface>(m, 0);
    std::vector<int> seeds;
    for (int k = 0; k < kLimbN; k += 3) seeds.push_back(ring[2] + k);
    PartBoundaryEnd<CMeshO>::Param par;
    par.valley.concavityWeight = 0;
    par.salience.widthExponent = 0;
    par.crossStep = 1.5;
    par.crossGain = 1.0; // more than the bend gained: the bend rule alone keeps the ring up the limb
    auto endAt = [&](const PartBoundaryEnd<CMeshO>::Param &p, double &zMin, double &zMax) {
        Snake s(surf);
        s.InitFromSeeds(seeds, true);
        s.EndRun(SnakeStop::Converged);
        EXPECT_TRUE(PartBoundaryEnd<CMeshO>::FinishRun(s, FeatureEnergyType::PartBoundary, false, p));
        zMin = 1e9, zMax = -1e9;
        for (const P3 &x : s.PolylinePositions()) zMin = std::min(zMin, x[2]), zMax = std::max(zMax, x[2]);
    };
    double zMin, zMax;
    par.crossDominant = true;
    endAt(par, zMin, zMax);
    std::printf("limb on a body, base as cheap as the ring up: the Run ends at z %.3f..%.3f\n", zMin, zMax);
    EXPECT_LT(std::max(std::fabs(zMin), std::fabs(zMax)), 1e-4); // the limb's base ring
    par.crossDominant = false; // the mechanism: without it the ring 2 steps up stays
    endAt(par, zMin, zMax);
    std::printf("  without crossDominant: z %.3f..%.3f\n", zMin, zMax);
    EXPECT_NEAR(zMin, 2 * kLimbStep, 1e-4);
    EXPECT_NEAR(zMax, 2 * kLimbStep, 1e-4);
}

// A loop on convex ground (issue 33, session 35; human 3 part 1 seeded inside 2 rings off): a
// roof meets a cylinder through two convex turns of its profile, a gentle one (13 degrees, ring
// A, where the loop settled) and 2 rings below a sharp one (55 degrees, ring B). The energy is
// 0.5 but on A (0.3) and B (0.28): A is the cheapest ring in total (it is shorter), B per length.
// The surface bends outwards across both, across B more: the bend rules (a loop that bends more)
// keep A. Nothing bends inwards across A, so the bend does not hold it there: the neighbour
// cheapest per length, B, replaces it (PartBoundaryEnd::Param::crossConvex).
TEST(PartBoundaryEnd, TakesTheCheapestNeighbourPerLengthOfALoopConvexAcross)
{
    CMeshO m;
    const int n = 126;
    const double step = 0.1, t = 35 * M_PI / 180;
    const double rA = 2.0, zA = 2.2, rB = rA + 2 * step * std::cos(t), zB = zA - 2 * step * std::sin(t);
    gs_test::MakeRevolvedProfile(m,
                                 {{0.0, 3.0, 0},
                                  {rA, zA, 0},  // the roof, 21.8 degrees below horizontal
                                  {rB, zB, 2},  // 35 degrees down, 2 rings
                                  {rB, -1.0, 0}, // the cylinder
                                  {0.0, -1.0, 0}},
                                 n, step, -1, 0);
    auto firstAt = [&](double r, double z) {
        for (int v = 0; v < int(m.vert.size()); ++v) {
            const auto &p = m.vert[v].cP();
            if (std::fabs(std::hypot(p[0], p[1]) - r) < 1e-4 && std::fabs(p[2] - z) < 1e-4) return v;
        }
        return -1;
    };
    const int a = firstAt(rA, zA), b = firstAt(rB, zB);
    ASSERT_GE(a, 0);
    ASSERT_GE(b, 0);
    for (auto &v : m.vert) v.Q() = v.cP()[2] > 3.0 - 1e-6 ? 1.0 : (v.cP()[2] < -1.0 + 1e-6 ? 0.0 : 0.5); // the range
    for (int k = 0; k < n; ++k) m.vert[a + k].Q() = 0.3, m.vert[b + k].Q() = 0.28;
    auto surf = std::make_shared<Surface>(m, 0);
    std::vector<int> seeds;
    for (int k = 0; k < n; k += 6) seeds.push_back(a + k);
    PartBoundaryEnd<CMeshO>::Param par;
    par.valley.concavityWeight = 0; // the convex turns would decide alone
    par.salience.exponent = 0;      // salience's candidates towards the body would too
    // rings 0.1 apart on the profile: the level loops of steps of 1 unit lie within 1.5 units of
    // A, whose band still holds A; steps of 1.5 units put the second level loop below B
    par.crossStep = 1.5;
    auto endAt = [&](const PartBoundaryEnd<CMeshO>::Param &p, double &zMin, double &zMax) {
        Snake s(surf);
        s.InitFromSeeds(seeds, true);
        s.EndRun(SnakeStop::Converged); // a Run that converged on ring A
        EXPECT_TRUE(PartBoundaryEnd<CMeshO>::FinishRun(s, FeatureEnergyType::PartBoundary, false, p));
        zMin = 1e9, zMax = -1e9;
        for (const P3 &x : s.PolylinePositions()) zMin = std::min(zMin, x[2]), zMax = std::max(zMax, x[2]);
    };
    std::vector<int> ra, rb;
    for (int k = 0; k < n; ++k) ra.push_back(a + k), rb.push_back(b + k);
    Snake s0(surf);
    s0.InitFromSeeds(seeds, true);
    const double h = s0.LengthScale(), bA = LoopBend<CMeshO>::Bend(m, ra, h, 2.0), bB = LoopBend<CMeshO>::Bend(m, rb, h, 2.0);
    std::printf("roof on a cylinder: h %.4f, bend across A %.3f, across B %.3f\n", h, bA, bB);
    EXPECT_LT(bA, 0.0); // convex across both, more across B
    EXPECT_LT(bB, bA);
    double zMin, zMax;
    endAt(par, zMin, zMax);
    std::printf("  the Run ends at z %.3f..%.3f (A %.3f, B %.3f)\n", zMin, zMax, zA, zB);
    EXPECT_NEAR(zMin, zB, 1e-4);
    EXPECT_NEAR(zMax, zB, 1e-4);
    par.crossConvex = false; // the mechanism: without it ring A stays
    endAt(par, zMin, zMax);
    std::printf("  without crossConvex: z %.3f..%.3f\n", zMin, zMax);
    EXPECT_NEAR(zMin, zA, 1e-4);
    EXPECT_NEAR(zMax, zA, 1e-4);
}

// The profile's level-set lengths for all levels in one pass (session 27) are ContourLength's at
// each level, bit for bit (the same terms added in the same order), and on the tube of the limb
// above the perimeter of its ring polygon: the depth below z = 0.3 as the distance, the levels
// between rings (3 in the tube, 9 down the body's cone).
TEST(PartProfile, ContourLengthsInOnePassMatchEachLevel)
{
    CMeshO m;
    MakeLimbOnBody(m);
    std::unordered_map<int, double> dist;
    for (int v = 0; v < int(m.vert.size()); ++v)
        if (m.vert[v].cP()[2] <= 0.3 + 1e-6) dist[v] = 0.3 - m.vert[v].cP()[2];
    auto isBody = [](int) { return true; };
    std::vector<double> levels;
    for (int j = 0; j < 12; ++j) levels.push_back((j + 0.5) * kLimbStep);
    const std::vector<double> all = PartProfile<CMeshO>::ContourLengths(m, isBody, dist, levels);
    ASSERT_EQ(all.size(), levels.size());
    for (size_t i = 0; i < levels.size(); ++i) {
        EXPECT_EQ(all[i], PartProfile<CMeshO>::ContourLength(m, isBody, dist, levels[i])) << "level " << levels[i];
        if (i < 3) EXPECT_NEAR(all[i], 2 * kLimbN * std::sin(M_PI / kLimbN), 1e-5) << "level " << levels[i];
        if (i >= 3) EXPECT_GT(all[i], all[i - 1]); // the cone opens
    }
}

namespace {

// A short thin part on a body (gs_test::MakeStubOnBody): a tube of radius 0.2 from z = 0 to 0.3,
// kStubN vertices a ring, rings kStubStep apart.
const double kStubStep = 0.1;
const int kStubN = 12;

std::vector<int> MakeStubOnBody(CMeshO &m) { return gs_test::MakeStubOnBody(m, kStubN, kStubStep); }

} // namespace

// A closed loop seeded round a short part, 2 rings up from its base, that shrank onto its tip
// (fourleg 381's ears: 3.6 h from 10.5 h seeded, people's cut 13 h). The energy is flat (0.5), so
// the valley loop's concavity term and part salience decide. The Run is repeated from the
// snake's end (converged) with a length unit 1.5 x the seeds' (faces at the tip a little
// coarser): every band round the seeded loop (2.5 and 1.5 units) then covers the tip, and its
// cheapest loop winds round the tip, shorter than half the seeded loop, so that before session
// 27 FinishRun found no ring round the seeded loop and kept the loop round the tip (0.17 long, at
// z 0.33-0.35). Now the edge ring along the seeded loop and part salience's candidates from it
// into the body (PartBoundaryEnd::TowardBody) give the part's base ring, z = 0, 1.24 long.
TEST(ValleyLoop, SearchesFromTheSeedsTowardsTheBodyWhenTheLoopShrankOntoAShortPartsTip)
{
    CMeshO m;
    const std::vector<int> ring = MakeStubOnBody(m);
    ASSERT_GE(ring[2], 0);
    for (auto &v : m.vert) v.Q() = 0.5;
    auto surf = std::make_shared<Surface>(m, 0); // the energy: the vertices' quality
    std::vector<int> seeds;
    for (int k = 0; k < kStubN; k += 2) seeds.push_back(ring[2] + k);
    Snake t(surf);
    t.InitFromSeeds(seeds, true);
    const auto seeded = PartBoundaryEnd<CMeshO>::Seeded::Of(t);
    const double L0 = gs_parts::LoopLength(seeded.loop);
    t.Run(400);
    Snake s(surf);
    s.InitFromSamples(t.Samples(), true, 1.5 * t.LengthScale());
    s.EndRun(SnakeStop::Converged);
    const double L1 = gs_parts::LoopLength(s.PolylinePositions());
    const PartBoundaryEnd<CMeshO>::Param par;
    ASSERT_LT(L1, par.seededShrink * L0); // the premise: the loop shrank onto the tip
    // no band round the seeded loop holds a ring (the premise of the search towards the body)
    double ref = -1, cost = 0;
    EXPECT_TRUE(PartBoundaryEnd<CMeshO>::FinishFrom(m, seeded.loop, seeded.faces, surf->Energy(), s.LengthScale(), par, ref, cost).empty());
    ASSERT_TRUE(PartBoundaryEnd<CMeshO>::FinishRun(s, FeatureEnergyType::PartBoundary, false, par, &seeded));
    double zMin = 1e9, zMax = -1e9;
    for (const P3 &x : s.PolylinePositions()) zMin = std::min(zMin, x[2]), zMax = std::max(zMax, x[2]);
    const double L = gs_parts::LoopLength(s.PolylinePositions());
    std::printf("short part: seeded %.2f long, shrank to %.2f; the Run ends at z %.3f..%.3f, %.2f long\n", L0, L1, zMin, zMax, L);
    EXPECT_LT(std::max(std::fabs(zMin), std::fabs(zMax)), 1e-4); // the part's base ring
    EXPECT_NEAR(L, kStubN * 2 * 0.2 * std::sin(M_PI / kStubN), 1e-3); // the 12-gon of radius 0.2
    EXPECT_EQ(s.Stats().stop, SnakeStop::Converged);
    // with part salience off there are no candidates: the loop round the tip stays
    PartBoundaryEnd<CMeshO>::Param off = par;
    off.salience.exponent = 0;
    Snake u(surf);
    u.InitFromSamples(t.Samples(), true, 1.5 * t.LengthScale());
    u.EndRun(SnakeStop::Converged);
    PartBoundaryEnd<CMeshO>::FinishRun(u, FeatureEnergyType::PartBoundary, false, off, &seeded);
    double zu = 1e9;
    for (const P3 &x : u.PolylinePositions()) zu = std::min(zu, x[2]);
    EXPECT_GT(zu, 0.25);
}

// ValleyLoop::Param::record (bench/eval/gs_parts GS_PARTS_ORACLE, session 28): every edge loop
// the Run's end finds is passed to it with its stage, the searches from the seeded loop and
// TowardBody behind their markers, and recording changes nothing. The case above goes through
// every stage: the bands round the shrunk loop, the seeded search, TowardBody's ring, salience.
TEST(PartBoundaryEnd, RecordsEveryLoopItFindsWithoutChangingTheChoice)
{
    CMeshO m;
    const std::vector<int> ring = MakeStubOnBody(m);
    ASSERT_GE(ring[2], 0);
    for (auto &v : m.vert) v.Q() = 0.5;
    auto surf = std::make_shared<Surface>(m, 0);
    std::vector<int> seeds;
    for (int k = 0; k < kStubN; k += 2) seeds.push_back(ring[2] + k);
    Snake t(surf);
    t.InitFromSeeds(seeds, true);
    const auto seeded = PartBoundaryEnd<CMeshO>::Seeded::Of(t);
    t.Run(400);
    auto finish = [&](const PartBoundaryEnd<CMeshO>::Param &par) {
        Snake s(surf);
        s.InitFromSamples(t.Samples(), true, 1.5 * t.LengthScale());
        s.EndRun(SnakeStop::Converged);
        EXPECT_TRUE(PartBoundaryEnd<CMeshO>::FinishRun(s, FeatureEnergyType::PartBoundary, false, par, &seeded));
        return s.PolylinePositions();
    };
    const std::vector<P3> plain = finish(PartBoundaryEnd<CMeshO>::Param());
    PartBoundaryEnd<CMeshO>::Param par;
    std::vector<std::pair<std::string, std::vector<int>>> rec;
    par.valley.record = [&](const char *stage, const std::vector<int> &l) { rec.push_back({stage, l}); };
    const std::vector<P3> recorded = finish(par);
    ASSERT_EQ(recorded.size(), plain.size());
    for (size_t i = 0; i < plain.size(); ++i) EXPECT_EQ(recorded[i], plain[i]);
    std::vector<std::string> stages;
    for (const auto &r : rec) stages.push_back(r.first);
    auto at = [&](const char *x) { return std::find(stages.begin(), stages.end(), x) - stages.begin(); };
    ASSERT_FALSE(rec.empty());
    EXPECT_EQ(stages.front(), "band"); // the band round the snake's loop comes first
    EXPECT_LT(at("seeded"), at("toward")); // then the seeded search, then TowardBody
    EXPECT_LT(at("toward"), int(stages.size()));
    EXPECT_TRUE(rec[at("seeded")].second.empty() && rec[at("toward")].second.empty()); // markers
    EXPECT_LT(at("salience"), int(stages.size()));
    // the loop the Run ended on is one of the loops recorded
    bool found = false;
    for (const auto &r : rec) {
        if (r.second.size() < 3) continue;
        std::vector<P3> pl;
        for (int v : r.second) pl.push_back(P3::Construct(m.vert[v].cP()));
        bool same = true;
        for (const P3 &x : pl) same = same && gs_parts::DistToLoop(x, recorded) < 1e-9;
        for (const P3 &x : recorded) same = same && gs_parts::DistToLoop(x, pl) < 1e-9;
        found = found || same;
    }
    EXPECT_TRUE(found);
}

namespace {

// The generated cases re-tessellated as users' meshes are (the guide's 20x edge-length
// variation, slivers, noise), each with its exact part boundary: a revolved surface (the waist,
// the bump) with its boundary at polar angle phiStar, or the handle on its slab.

/// A midpoint (vcglib's RefineE) moved onto the exact surface.
struct RoughMidPoint : vcg::tri::MidPoint<CMeshO>
{
    std::function<P3(const P3 &)> proj;
    RoughMidPoint(CMeshO *m, std::function<P3(const P3 &)> p) : vcg::tri::MidPoint<CMeshO>(m), proj(p) {}
    void operator()(CVertexO &nv, vcg::face::Pos<CFaceO> ep)
    {
        vcg::tri::MidPoint<CMeshO>::operator()(nv, ep);
        nv.P() = Point3m::Construct(proj(P3::Construct(nv.cP())));
    }
};

/// Splits every edge longer than target(its midpoint) until none is (edges end between half
/// the target and the target), the new vertices on the exact surface.
struct RoughEdgePred
{
    std::function<double(const P3 &)> target;
    bool operator()(vcg::face::Pos<CFaceO> ep) const
    {
        const P3 a = P3::Construct(ep.V()->cP()), b = P3::Construct(ep.VFlip()->cP());
        return vcg::Distance(a, b) > target((a + b) * 0.5);
    }
};

void RoughRefine(CMeshO &m, std::function<double(const P3 &)> target, std::function<P3(const P3 &)> proj)
{
    gs_test::EnableSnakeAdjacency(m);
    RoughMidPoint mid(&m, proj);
    RoughEdgePred pred{target};
    for (int pass = 0; pass < 12; ++pass) {
        vcg::tri::UpdateTopology<CMeshO>::FaceFace(m);
        if (!vcg::tri::RefineE(m, mid, pred)) break;
    }
    vcg::tri::Allocator<CMeshO>::CompactEveryVector(m);
}

/// Edge lengths graded `ratio` x across the boundary: `fine` within `w` of it on the fine side
/// (d < 0, d the signed distance to the boundary), growing geometrically to fine * ratio across
/// it (d from -w to w) and back to it beyond the fine band (d < -3w), so that the fine band stays small.
double RoughTarget(double d, double fine, double ratio, double w)
{
    double t = d >= -w ? (d + w) / (2 * w) : std::min(1.0, (-d - w) / (4 * w));
    return fine * std::pow(ratio, std::max(0.0, std::min(1.0, t)));
}

/// Slivers: every vertex slid towards a random neighbour by up to 45 % of the edge (needles
/// where two slide towards each other, caps where one nears the opposite edge), back on the
/// exact surface; and a share of the faces split at a point 2 % off one of their edges (a cap
/// and two needles each).
void RoughSlivers(CMeshO &m, std::function<P3(const P3 &)> proj, double splitShare, unsigned seed)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    gs_test::EnableSnakeAdjacency(m);
    for (auto &f : m.face) {
        for (int k = 0; k < 3; ++k) {
            CVertexO *v = f.V(k);
            if (v->IsV()) continue;
            v->SetV();
            const P3 a = P3::Construct(v->cP()), b = P3::Construct(f.cV((k + 1 + int(u(rng) * 2)) % 3)->cP());
            v->P() = Point3m::Construct(proj(a + (b - a) * (0.45 * u(rng))));
        }
    }
    vcg::tri::UpdateFlags<CMeshO>::VertexClearV(m);
    std::vector<std::pair<int, int>> split; // face, its edge next to the new vertex
    for (size_t i = 0; i < m.face.size(); ++i)
        if (u(rng) < splitShare) split.push_back({int(i), int(u(rng) * 3) % 3});
    auto vi = vcg::tri::Allocator<CMeshO>::AddVertices(m, split.size());
    const int v0 = int(vi - m.vert.begin());
    auto fi = vcg::tri::Allocator<CMeshO>::AddFaces(m, 2 * split.size());
    const int f0 = int(fi - m.face.begin());
    for (size_t j = 0; j < split.size(); ++j) {
        CFaceO &f = m.face[split[j].first];
        const int k = split[j].second;
        CVertexO *a = f.V(k), *b = f.V((k + 1) % 3), *c = f.V((k + 2) % 3), *x = &m.vert[v0 + j];
        x->P() = a->cP() * 0.49f + b->cP() * 0.49f + c->cP() * 0.02f;
        f.V((k + 2) % 3) = x; // a b x
        CFaceO &g = m.face[f0 + 2 * j], &e = m.face[f0 + 2 * j + 1];
        g.V(0) = b, g.V(1) = c, g.V(2) = x;
        e.V(0) = c, e.V(1) = a, e.V(2) = x;
    }
    gs_test::EnableSnakeAdjacency(m);
}

struct RoughMeasure
{
    double mean = 0, max = 0, ratio = 0;
    bool finite = true;
    std::string stop;
    bool finished = false;
    int ops = 0;        ///< the Run's operations
    double runMean = 0; ///< the snake's own loop at the Run's end (before FinishRun): mean off, in h
};

} // namespace

namespace {

/// Every vertex moved in a random direction by `share` of its mean edge length, at most `cap`
/// (0.4 and 3 % of the radius: the noise of the uniform spheres above, MakeRevolved's 3 %,
/// where the mesh is that coarse or coarser, and no more than 0.4 edges where it is finer:
/// noise as large as the fine side's edges folds it, no scan of that sampling has).
void RoughNoise(CMeshO &m, double share, double cap, unsigned seed)
{
    std::vector<double> sum(m.vert.size(), 0);
    std::vector<int> cnt(m.vert.size(), 0);
    for (const auto &f : m.face)
        for (int k = 0; k < 3; ++k) {
            const int a = int(f.cV(k) - &m.vert[0]);
            sum[a] += vcg::Distance(f.cP(k), f.cP((k + 1) % 3)) + vcg::Distance(f.cP(k), f.cP((k + 2) % 3));
            cnt[a] += 2;
        }
    std::mt19937 rng(seed);
    std::normal_distribution<double> g(0.0, 1.0);
    for (size_t i = 0; i < m.vert.size(); ++i) {
        P3 d(g(rng), g(rng), g(rng));
        if (!(d.Norm() > 1e-9) || !cnt[i]) continue;
        m.vert[i].P() = Point3m::Construct(P3::Construct(m.vert[i].cP()) + d.Normalize() * std::min(cap, share * sum[i] / cnt[i]));
    }
}

struct RoughStyle
{
    bool graded;   ///< edges graded 20x across the boundary (fine on the side fineSide)
    int fineSide;  ///< +1: fine inside the part (phi < phiStar, on the handle), -1 outside
    bool slivers;
    double noise;  ///< RoughNoise's share
    std::string Name() const
    {
        std::string n = graded ? (fineSide > 0 ? "graded (fine inside)" : "graded (fine outside)") : "uniform";
        if (slivers) n += " + slivers";
        if (noise > 0) n += " + noise";
        return n;
    }
};

/// A revolved surface (MakeRevolved's) re-tessellated in `st`'s style.
template <class Radius>
void MakeRoughRevolved(CMeshO &m, Radius R, double phiStar, const RoughStyle &st, unsigned seed)
{
    auto phiOf = [](const P3 &p) { return std::acos(std::max(-1.0, std::min(1.0, p[2] / p.Norm()))); };
    auto proj = [&](const P3 &p) { P3 q = p; q.Normalize(); return q * R(phiOf(p)); };
    gs_test::MakeIcosphere(m, st.graded ? 2 : 4);
    for (auto &v : m.vert) v.P() = Point3m::Construct(proj(P3::Construct(v.cP())));
    if (st.graded)
        RoughRefine(m, [&](const P3 &p) { return RoughTarget(-st.fineSide * (phiOf(p) - phiStar) * R(phiStar), 0.02, 20, 0.1); },
                    proj);
    if (st.slivers) RoughSlivers(m, proj, 0.3, seed);
    if (st.noise > 0) RoughNoise(m, st.noise, 0.03, seed + 1);
    gs_test::EnableSnakeAdjacency(m);
    vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFace(m);
    vcg::tri::UpdateBounding<CMeshO>::Box(m);
}

/// The shortest and longest edge.
std::pair<double, double> RoughEdgeRange(const CMeshO &m)
{
    double lo = 1e300, hi = 0;
    for (const auto &f : m.face)
        for (int k = 0; k < 3; ++k) {
            const double e = vcg::Distance(f.cP(k), f.cP((k + 1) % 3));
            lo = std::min(lo, e), hi = std::max(hi, e);
        }
    return {lo, hi};
}

/// A Run from `seeds` as every host does it (the seeded loop kept for FinishRun), measured by
/// `off` (distance to the exact boundary) against its length `exactLen`.
RoughMeasure RoughRun(std::shared_ptr<Surface> surf, const std::vector<int> &seeds, std::function<double(const P3 &)> off,
                      double exactLen, double unit, bool stall = true)
{
    RoughMeasure r;
    Snake s(surf);
    s.InitFromSeeds(seeds, true);
    s.RunParam().stall = stall;
    const auto seeded = PartBoundaryEnd<CMeshO>::Seeded::Of(s);
    s.Run(400);
    r.ops = s.Stats().operations;
    {
        const std::vector<P3> own = gs_parts::ResampleLoop(s.PolylinePositions(), 0.25 * unit);
        for (const P3 &x : own) r.runMean += off(x) / unit / own.size();
    }
    r.finished = PartBoundaryEnd<CMeshO>::FinishRun(s, FeatureEnergyType::PartBoundary, false, PartBoundaryEnd<CMeshO>::Param(), &seeded);
    r.stop = SnakeStopKey(s.Stats().stop);
    const std::vector<P3> pl = s.PolylinePositions();
    for (const P3 &x : pl) r.finite = r.finite && std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]);
    if (!r.finite || pl.size() < 2) return r;
    const std::vector<P3> loop = gs_parts::ResampleLoop(pl, 0.25 * unit);
    for (const P3 &x : loop) {
        const double d = off(x) / unit;
        r.mean += d / loop.size(), r.max = std::max(r.max, d);
    }
    r.ratio = gs_parts::LoopLength(loop) / exactLen;
    return r;
}

} // namespace

// The waist graded 20x across it (edges 0.02 on one side, 0.4 on the other) with slivers (each
// vertex slid up to 45 % along an edge, 30 % of the faces split next to an edge): the snake's
// unit, the median edge of its samples' faces, is there a fraction of the faces it crosses
// (0.015 for a Run from 3 h outside, where the boundary's faces are 0.09 across), and the band
// of 2.5 units held no ring of edges at any width: FinishRun kept the snake's loop. The band
// now holds the snake's own faces (ValleyLoop::FindAt, session 26). Measured (gcc Release):
// before, no band round the loop from 3 h outside held a ring (Find empty at 2.5, 1.5 and 1
// units) and FinishRun kept the snake's loop; now the valley loop from both seedings, mean
// 0.83 and 1.10 h, max 1.84 and 2.17 h off the waist, 1.07-1.12 of its length (h the mean edge).
TEST(ValleyLoop, FindsARingWhereTheSnakesFacesAreWiderThanItsBand)
{
    CMeshO m;
    MakeRoughRevolved(m, Waist, M_PI / 2, RoughStyle{true, 1, true, 0}, 11);
    const auto er = RoughEdgeRange(m);
    EXPECT_GT(er.second / er.first, 100.0);
    auto surf = WithEnergy(m, FeatureEnergyType::PartBoundary);
    const double h = surf->MeanEdge();
    for (double k : {-3.0, 2.0}) { // outside (below the waist, coarse there), inside
        Snake s(surf);
        s.InitFromSeeds(RingSeeds(m, Waist, M_PI / 2 - k * h / Waist(M_PI / 2)), true);
        s.Run(400);
        ASSERT_EQ(s.Stats().stop, SnakeStop::Converged);
        std::vector<int> faces;
        for (const auto &x : s.Samples()) faces.push_back(x.p.face);
        const double len = gs_parts::LoopLength(s.PolylinePositions());
        const std::vector<int> ring = ValleyLoop<CMeshO>::Find(m, s.PolylinePositions(), faces, surf->Energy(), s.LengthScale());
        ASSERT_GE(ring.size(), 3u);
        EXPECT_GT(ValleyLoop<CMeshO>::LengthOf(m, ring), 0.5 * len);
        const double unit = s.LengthScale();
        ASSERT_TRUE(PartBoundaryEnd<CMeshO>::FinishRun(s, FeatureEnergyType::PartBoundary, false));
        double mean = 0, mx = 0;
        const std::vector<P3> loop = gs_parts::ResampleLoop(s.PolylinePositions(), 0.25 * h);
        for (const P3 &x : loop) {
            const double o = std::fabs(std::acos(std::max(-1.0, std::min(1.0, x[2] / x.Norm()))) - M_PI / 2) * Waist(M_PI / 2) / h;
            mean += o / loop.size(), mx = std::max(mx, o);
        }
        const double ratio = gs_parts::LoopLength(loop) / (2 * M_PI * Waist(M_PI / 2));
        std::printf("graded waist with slivers (%d faces, edges %.4f-%.4f), seeds %.0f h %s, unit %.4f: the valley loop "
                    "mean %.2f h, max %.2f h off the waist, length %.3f of it\n", m.fn, er.first, er.second, std::fabs(k),
                    k < 0 ? "outside" : "inside", unit, mean, mx, ratio);
        EXPECT_LT(mean, 1.5);
        EXPECT_LT(mx, 3.0);
        EXPECT_GT(ratio, 0.95);
        EXPECT_LT(ratio, 1.25);
    }
}

// The waist and the bump re-tessellated as users' meshes are: the waist with slivers and noise
// (3 % of the radius), the bump with edge lengths graded 20x across its rim and slivers (edges
// 0.0013-0.59). Runs from 2 h inside and 3 h outside (h the mean edge) end by themselves,
// converged, finite, on the valley loop near the exact boundary. Measured (gcc Release): waist
// mean 0.33 h, max 1.04 h off, 1.27 of its length (the edge loop zigzags through the noise);
// bump mean 0.85 and 1.40 h, max 1.82 and 2.36 h, 1.00-1.04. (The bump graded with slivers and
// noise of 0.4 local edges, at most 3 % of the radius, measured 1.24 h / 2.99 h from inside; the
// Run from outside ends at 400 operations, 2.67 h / 4.99 h off: the exploration test of commit
// c323a14, not kept.)
// One test per mesh (each under 2 s).
namespace {

struct RoughCase
{
    const char *name;
    double (*R)(double);
    double phiStar;
    RoughStyle st;
    double mean, max; // bounds, in h
};

void RoughSettles(const RoughCase &c)
{
    CMeshO m;
    MakeRoughRevolved(m, c.R, c.phiStar, c.st, 11);
    auto surf = WithEnergy(m, FeatureEnergyType::PartBoundary);
    const double h = surf->MeanEdge();
    const auto er = RoughEdgeRange(m);
    const double exactLen = 2 * M_PI * c.R(c.phiStar) * std::sin(c.phiStar);
    auto off = [&](const P3 &x) {
        return std::fabs(std::acos(std::max(-1.0, std::min(1.0, x[2] / x.Norm()))) - c.phiStar) * c.R(c.phiStar);
    };
    for (double k : {2.0, -3.0}) {
        RoughMeasure r;
        EXPECT_NO_THROW(r = RoughRun(surf, RingSeeds(m, c.R, c.phiStar - k * h / c.R(c.phiStar)), off, exactLen, h));
        std::printf("%s %s (%d faces, edges %.4f-%.4f, h %.4f), seeds %.0f h %s: %s, valley loop %d, off mean %.2f h, "
                    "max %.2f h, length %.3f\n", c.name, c.st.Name().c_str(), m.fn, er.first, er.second, h, std::fabs(k),
                    k > 0 ? "inside" : "outside", r.stop.c_str(), int(r.finished), r.mean, r.max, r.ratio);
        EXPECT_TRUE(r.finite);
        EXPECT_EQ(r.stop, "converged");
        EXPECT_TRUE(r.finished);
        EXPECT_LT(r.mean, c.mean);
        EXPECT_LT(r.max, c.max);
        EXPECT_GT(r.ratio, 0.95);
        EXPECT_LT(r.ratio, 1.4);
    }
}

} // namespace

TEST(PartBoundaryLoop, SettlesOnTheWaistWithSliversAndNoise)
{
    RoughSettles({"waist", Waist, M_PI / 2, {false, 1, true, 0.4}, 0.6, 1.6});
}

TEST(PartBoundaryLoop, SettlesOnTheBumpGraded20xWithSlivers)
{
    RoughSettles({"bump", Bump, BumpRim(), {true, -1, true, 0}, 2.0, 3.5});
}

// The bump graded 20x across its rim with slivers and noise (0.4 local edges, at most 3 % of the
// radius; session 28's trace): on the noisy fine side every operation a different handful of
// samples hops between neighbouring noise dips, so the worst-sample tests never fire and the
// Runs from 2 h inside and 3 h outside reach the limit (400 operations, not converged, so no
// valley loop). The stall test on the curve as a whole (SnakeRunControl::Param, session 29)
// ends them as converged, and stopping early loses nothing: the Run's own loop is as far from
// the rim as after 400 operations without the test. Measured (gcc Release): with the test
// converged after 124 (inside) and 323 (outside) operations, the Run's loop 2.70 and 1.53 h off
// the rim (without: 400 operations, 2.70 and 1.59 h); the valley loop 2.73 and 3.20 h, max 3.54
// and 4.56 h (from outside it is farther off than the snake's loop: FinishRun on the noisy side,
// left open; the noise-free bump's bounds are 2.0 and 3.5 h). From inside the loop never reaches
// the rim (2.65 h off from its first operations on, session 28). The noisy Runs are chaotic: the
// ASan + UBSan build (other optimisation) converged after 341 and 168 operations, the Run's loop
// 2.46 and 1.30 h off, the valley loop 2.77 and 3.84 h; without the test from outside it ended
// by the worst-sample test after 168 operations too. So the bounds hold in both builds, and the
// premise is that at least one of the two Runs reaches its limit without the test.
TEST(PartBoundaryLoop, StallTestEndsRunsOnTheBumpGraded20xWithSliversAndNoise)
{
    CMeshO m;
    const double rim = BumpRim();
    MakeRoughRevolved(m, Bump, rim, RoughStyle{true, -1, true, 0.4}, 11);
    auto surf = WithEnergy(m, FeatureEnergyType::PartBoundary);
    const double h = surf->MeanEdge();
    const double exactLen = 2 * M_PI * Bump(rim) * std::sin(rim);
    auto off = [&](const P3 &x) { return std::fabs(std::acos(std::max(-1.0, std::min(1.0, x[2] / x.Norm()))) - rim) * Bump(rim); };
    int limited = 0;
    for (double k : {2.0, -3.0}) {
        const std::vector<int> seeds = RingSeeds(m, Bump, rim - k * h / Bump(rim));
        const RoughMeasure with = RoughRun(surf, seeds, off, exactLen, h, true);
        const RoughMeasure without = RoughRun(surf, seeds, off, exactLen, h, false);
        std::printf("noisy graded bump, seeds %.0f h %s: with the stall test %s after %d operations, valley loop %d, off "
                    "mean %.2f h, max %.2f h, length %.3f (the Run's loop %.2f h); without %s after %d operations (off mean %.2f h, "
                    "max %.2f h)\n", std::fabs(k), k > 0 ? "inside" : "outside", with.stop.c_str(), with.ops,
                    int(with.finished), with.mean, with.max, with.ratio, with.runMean, without.stop.c_str(), without.ops,
                    without.mean, without.max);
        // where the Run without the stall test reaches its limit, the rule's case, ending early
        // loses nothing: the Run's loop is no farther off than 400 operations leave it
        const bool limit = without.stop == "max_operations";
        limited += limit;
        if (limit) EXPECT_LT(with.runMean, without.mean + 0.25);
        EXPECT_TRUE(with.finite);
        EXPECT_EQ(with.stop, "converged");
        EXPECT_LT(with.ops, 400);
        EXPECT_TRUE(with.finished);
        EXPECT_LT(with.runMean, 3.0);
        EXPECT_LT(with.mean, 4.5); // the valley loop near the rim (FinishRun on the noisy side: left open)
        EXPECT_GT(with.ratio, 0.95);
        EXPECT_LT(with.ratio, 1.4);
    }
    // the premise: without the stall test a Run on this mesh runs to its limit (both in the
    // Release build; the noisy Runs are chaotic, and under ASan the one from outside ends by
    // the worst-sample test after 168 operations)
    EXPECT_GE(limited, 1);
}

namespace {

/// The short part (MakeStubOnBody) re-tessellated as users' meshes are, each vertex added or
/// moved kept on the exact surface of revolution (the profile's nearest point, same angle).
struct StubRough
{
    const char *name;
    bool graded, slivers;
    double depth; ///< graded: the depth below the part's base over which the body's edges grow back
    double noise; ///< every vertex moved this far in a random direction
};

/// The exact stub: the nearest point of its profile (r, z) at p's angle round z.
P3 StubProject(const P3 &p)
{
    static const double prof[][2] = {{0.0, 0.35}, {0.2, 0.3}, {0.2, 0.0}, {1.2, -1.0}, {1.2, -2.0}, {0.0, -2.0}};
    const double r = std::hypot(p[0], p[1]);
    double best = 1e300, br = r, bz = p[2];
    for (int i = 0; i + 1 < 6; ++i) {
        const double ar = prof[i][0], az = prof[i][1], dr = prof[i + 1][0] - ar, dz = prof[i + 1][1] - az;
        const double t = std::max(0.0, std::min(1.0, ((r - ar) * dr + (p[2] - az) * dz) / (dr * dr + dz * dz)));
        const double qr = ar + t * dr, qz = az + t * dz, d = std::hypot(r - qr, p[2] - qz);
        if (d < best) best = d, br = qr, bz = qz;
    }
    const double s = r > 1e-12 ? br / r : 0;
    return P3(p[0] * s, p[1] * s, bz);
}

struct StubEnd
{
    std::string runStop, endStop;
    std::vector<P3> loop;
    bool finite = true, towardBody = false, finished = false;
    double zMax = 0, len = 0, ownZMin = 0, h = 0, lo = 0, hi = 0;
    int faces = 0;
};

/// The Run's end of SearchesFromTheSeedsTowardsTheBodyWhenTheLoopShrankOntoAShortPartsTip on
/// the stub re-tessellated in `st`'s style: a Run from 6 seeds on the tube 0.2 up (it ends by
/// itself), repeated from its end with a length unit 1.5 x its own and ended converged, then
/// FinishRun with the seeded loop (`par`). towardBody: the seeded loop's search found no ring
/// after the loop shrank, the path of PartBoundaryEnd::TowardBody.
StubEnd StubRunEnd(const StubRough &st, const PartBoundaryEnd<CMeshO>::Param &par)
{
    CMeshO m;
    MakeStubOnBody(m);
    if (st.graded) // edges up to 0.12 on the part, 20x finer (0.006) on the body at its base, back to 0.12 by `depth` below
        RoughRefine(m, [&](const P3 &p) { return p[2] >= 0 ? 0.12 : 0.006 * std::pow(20.0, std::min(1.0, -p[2] / st.depth)); },
                    StubProject);
    if (st.slivers) RoughSlivers(m, StubProject, 0.3, 5);
    if (st.noise > 0) {
        double sum = 0; // AddVertexNoise moves by a share of the mean edge
        for (const auto &f : m.face)
            for (int k = 0; k < 3; ++k) sum += vcg::Distance(P3::Construct(f.cP(k)), P3::Construct(f.cP((k + 1) % 3)));
        gs_test::AddVertexNoise(m, st.noise / (sum / (3.0 * m.fn)), 9);
    }
    gs_test::EnableSnakeAdjacency(m);
    vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFace(m);
    StubEnd r;
    r.faces = m.fn;
    std::tie(r.lo, r.hi) = RoughEdgeRange(m);
    for (auto &v : m.vert) v.Q() = 0.5;
    auto surf = std::make_shared<Surface>(m, 0); // the energy: the vertices' quality
    r.h = surf->MeanEdge();
    std::vector<P3> pts;
    for (int k = 0; k < 6; ++k) pts.push_back(P3(0.2 * std::cos(M_PI * k / 3), 0.2 * std::sin(M_PI * k / 3), 0.2));
    Snake t(surf);
    t.InitFromSeeds(gs_test::NearestVertices(m, pts), true);
    const auto seeded = PartBoundaryEnd<CMeshO>::Seeded::Of(t);
    t.Run(400);
    r.runStop = SnakeStopKey(t.Stats().stop);
    Snake s(surf);
    s.InitFromSamples(t.Samples(), true, 1.5 * t.LengthScale());
    s.EndRun(SnakeStop::Converged);
    r.ownZMin = 1e9;
    for (const P3 &x : s.PolylinePositions()) r.ownZMin = std::min(r.ownZMin, x[2]);
    double ref = -1, cost = 0;
    const bool shrank = gs_parts::LoopLength(s.PolylinePositions()) < par.seededShrink * gs_parts::LoopLength(seeded.loop);
    r.towardBody = shrank && PartBoundaryEnd<CMeshO>::FinishFrom(m, seeded.loop, seeded.faces, surf->Energy(),
                                                                 s.LengthScale(), par, ref, cost).empty();
    r.finished = PartBoundaryEnd<CMeshO>::FinishRun(s, FeatureEnergyType::PartBoundary, false, par, &seeded);
    r.endStop = SnakeStopKey(s.Stats().stop);
    for (const P3 &x : s.PolylinePositions()) {
        r.finite = r.finite && std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]);
        r.zMax = std::max(r.zMax, std::fabs(x[2]));
    }
    r.len = gs_parts::LoopLength(s.PolylinePositions());
    r.loop = s.PolylinePositions();
    std::printf("stub %s (%d faces, edges %.4f-%.4f, h %.4f): Run %s; own loop from z %.3f; towards the body %d; "
                "FinishRun %d (%s): |z| <= %.4f, %.3f long\n", st.name, r.faces, r.lo, r.hi, r.h, r.runStop.c_str(),
                r.ownZMin, int(r.towardBody), int(r.finished), r.endStop.c_str(), r.zMax, r.len);
    return r;
}

/// The Run ends by itself (collapsed onto the tip, as on the clean stub, or converged), the
/// loop that shrank onto the tip reaches TowardBody's path (no ring round the seeded loop), and
/// FinishRun keeps the Run's stop reason and gives finite positions. tol >= 0: the loop is the
/// part's base ring, z = 0 (the 12-gon of radius 0.2, 1.242 long) within tol; tol < 0: the
/// documented outcome where no candidate is found: the loop is the one FinishRun gives without
/// the path (salience off), round the tip.
void StubEndsOnItsBase(const StubRough &st, double tol, double lenTol)
{
    const PartBoundaryEnd<CMeshO>::Param par;
    const StubEnd r = StubRunEnd(st, par);
    EXPECT_TRUE(r.runStop == "collapsed" || r.runStop == "converged") << r.runStop;
    EXPECT_TRUE(r.towardBody); // the premise: the path under test is taken
    EXPECT_EQ(r.endStop, "converged");
    EXPECT_TRUE(r.finite);
    EXPECT_TRUE(r.finished);
    if (tol >= 0) {
        EXPECT_LT(r.zMax, tol);
        EXPECT_NEAR(r.len, kStubN * 2 * 0.2 * std::sin(M_PI / kStubN), lenTol);
        return;
    }
    PartBoundaryEnd<CMeshO>::Param off = par;
    off.salience.exponent = 0;
    const StubEnd u = StubRunEnd(st, off);
    ASSERT_EQ(r.loop.size(), u.loop.size());
    for (size_t i = 0; i < r.loop.size(); ++i) EXPECT_EQ(vcg::Distance(r.loop[i], u.loop[i]), 0.0);
    EXPECT_GT(r.zMax, 0.25); // round the tip
}

} // namespace

// The short part's loop (SearchesFromTheSeedsTowardsTheBodyWhenTheLoopShrankOntoAShortPartsTip)
// on the stub re-tessellated as users' meshes are (issue 33, session 28): in every case the Run
// collapses onto the tip by itself and no band round the seeded loop holds a ring. Measured (gcc
// Release), the largest |z| of the Run's end (0 on the part's base ring) and its length (1.242
// exact); without the path (salience off) the loop stays round the tip, |z| 0.34-0.36, 0.12-0.34
// long. Clean 0.0000, 1.242; graded 20x (edges 0.006 on the body at the part's base, up to 0.12
// on the part, growing back over 0.4 below it; 47k faces) 0.0000, 1.242; slivers (30 % of the
// faces split, each vertex slid up to 45 % of an edge) 0.042, 1.267: within the slide, 0.45 x
// the part's 0.1 edges; every vertex moved 3 % of the part's radius (0.006) 0.0053, 1.236:
// within that; 3 % of the body's radius (0.036: 18 % of the part's radius, a third of its
// edges) 0.102, 1.467: the edge loop zigzags through the noise, within one of the part's edges
// plus the noise. Graded 20x growing back over 0.15 instead (27k faces): the candidates from
// the seeds' ring find none cheaper per length than the loop round the tip, which stays as
// FinishRun gives it without the path (|z| 0.350, 0.172 long), the documented outcome.
TEST(PartBoundaryEnd, MovesAShortPartsLoopTowardsTheBodyGraded20x)
{
    StubEndsOnItsBase({"graded 20x (0.4 deep)", true, false, 0.4, 0}, 1e-4, 1e-3);
    StubEndsOnItsBase({"graded 20x (0.15 deep)", true, false, 0.15, 0}, -1, 0);
}

TEST(PartBoundaryEnd, MovesAShortPartsLoopTowardsTheBodyWithSlivers)
{
    StubEndsOnItsBase({"slivers", false, true, 0, 0}, 0.45 * kStubStep, 0.03 * 1.242);
}

TEST(PartBoundaryEnd, MovesAShortPartsLoopTowardsTheBodyWithNoise)
{
    StubEndsOnItsBase({"noise 3 % of the part", false, false, 0, 0.03 * 0.2}, 0.03 * 0.2 + 1e-6, 0.03 * 1.242);
    StubEndsOnItsBase({"noise 3 % of the body", false, false, 0, 0.03 * 1.2}, kStubStep + 0.03 * 1.2, 0.25 * 1.242);
}

// Session 34: CAD-like parts. A flat-bottomed recess in a block (revolved, 24 vertices a ring):
// the floor, rings 0.25 apart out to radius 1 at z = 0, meets the wall (one step, 0.25 up) in a
// right-angle concave crease, the answer; the wall meets the top face (out to radius 2) in a
// convex edge. The band's concave edges are the crease's 24 and the faceted wall's 24 vertical
// edges (0.26 rad), so their median is the crease's own angle and twice it gave the crease half a
// crease's credit: with the energy the same everywhere the floor's ring at radius 0.5 (half as
// long, flat) was cheaper. Returns the index of the crease ring's first vertex.
static int MakeRecessInABlock(CMeshO &m, int n)
{
    const double step = 0.25;
    gs_test::MakeRevolvedProfile(m, {{0.0, 0.0, 0}, {1.0, 0.0, 4}, {1.0, step, 1}, {2.0, step, 4}, {2.0, -1.0, 0}, {0.0, -1.0, 0}},
                                 n, step, 1.0, 1);
    for (size_t v = 0; v < m.vert.size(); ++v) // the first vertex of the ring at radius 1 on the floor
        if (std::fabs(m.vert[v].cP()[2]) < 1e-9 && std::fabs(std::hypot(m.vert[v].cP()[0], m.vert[v].cP()[1]) - 1.0) < 1e-9)
            return int(v);
    return -1;
}

static void RingRadii(const CMeshO &m, const std::vector<int> &l, double &rMin, double &rMax, double &zAbs)
{
    rMin = 1e9, rMax = -1e9, zAbs = 0;
    for (int v : l) {
        const double r = std::hypot(m.vert[v].cP()[0], m.vert[v].cP()[1]);
        rMin = std::min(rMin, r), rMax = std::max(rMax, r), zAbs = std::max(zAbs, std::fabs(double(m.vert[v].cP()[2])));
    }
}

// ValleyLoop::Param::creaseAngle: the concavity reference is at most a right angle, so an edge
// that turns a right angle inwards is a full crease (c = 1) whatever the band's median. The
// band round the crease ring holds the floor's rings at 0.75 and 0.5 and the top face's at 1.25
// and 1.5; the loop is the crease ring exactly (the 24-gon of radius 1). Without the bound the
// reference is pi and the floor's ring at 0.5 is taken (checked: the second half asserts it).
TEST(ValleyLoop, TakesARightAngleConcaveCreaseAsAFullCreaseWhateverTheBandsMedian)
{
    CMeshO m;
    const int n = 24;
    const int c0 = MakeRecessInABlock(m, n);
    ASSERT_GE(c0, 0);
    std::vector<P3> guide;
    std::vector<int> faces;
    for (int k = 0; k < n; ++k) {
        guide.push_back(P3::Construct(m.vert[c0 + k].cP()));
        PartSalience<CMeshO>::ForFaces(m, c0 + k, [&](const CFaceO *f, int) { faces.push_back(int(f - &m.face[0])); });
    }
    const std::vector<double> energy(m.vert.size(), 0.5);
    const double h = 0.25;
    const PartBoundaryEnd<CMeshO>::Param par = PartBoundaryEnd<CMeshO>::Measured(m, PartBoundaryEnd<CMeshO>::Param());
    for (bool bound : {true, false}) {
        ValleyLoop<CMeshO>::Param vp = par.valley;
        if (!bound) vp.creaseAngle = 0; // the default bounds it (a right angle)
        double ref = -1, cost = 0;
        const std::vector<int> l = ValleyLoop<CMeshO>::FindAt(m, guide, faces, energy, h, vp, ref, cost);
        double rMin, rMax, zAbs;
        RingRadii(m, l, rMin, rMax, zAbs);
        std::printf("recess, crease bound %d: reference %.3f rad, loop of %zu vertices at r %.3f..%.3f, |z| <= %.3f, %.3f long\n",
                    int(bound), ref, l.size(), rMin, rMax, zAbs, ValleyLoop<CMeshO>::LengthOf(m, l));
        ASSERT_EQ(int(l.size()), n);
        if (bound) {
            EXPECT_NEAR(ref, 0.5 * M_PI, 1e-6);
            EXPECT_NEAR(rMin, 1.0, 1e-6);
            EXPECT_NEAR(rMax, 1.0, 1e-6);
            EXPECT_LT(zAbs, 1e-6);
            EXPECT_NEAR(ValleyLoop<CMeshO>::LengthOf(m, l), n * 2 * std::sin(M_PI / n), 1e-4);
        } else { // the premise: without the bound the crease loses to the floor's shorter ring
            EXPECT_NEAR(ref, M_PI, 1e-3);
            EXPECT_NEAR(rMax, 0.5, 1e-6);
        }
    }
}

// PartBoundaryEnd::Param::endAtMaxOperations (off by default): a Run that ran out of operations
// ends on its valley loop as a converged one does (on CAD meshes a snake between the two vertex rings of a strip of
// long faces, whose energy is linear across each face, hops and never converges: bearing 341
// part 1 outside 2). Seeded on the recess's top face at radius 1.25 and stopped after 3
// operations, it ends on the crease ring; without the rule FinishRun leaves it where it stopped.
TEST(PartBoundaryEnd, EndsARunThatRanOutOfOperationsOnItsValleyLoop)
{
    CMeshO m;
    const int n = 24;
    ASSERT_GE(MakeRecessInABlock(m, n), 0);
    for (auto &v : m.vert) v.Q() = 0.5;
    auto surf = std::make_shared<Surface>(m, 0); // the energy: the vertices' quality
    std::vector<int> seeds;
    for (size_t v = 0; v < m.vert.size(); ++v)
        if (std::fabs(m.vert[v].cP()[2] - 0.25) < 1e-9 && std::fabs(std::hypot(m.vert[v].cP()[0], m.vert[v].cP()[1]) - 1.25) < 1e-9 &&
            (v % 3) == 0)
            seeds.push_back(int(v));
    ASSERT_GE(seeds.size(), 6u);
    PartBoundaryEnd<CMeshO>::Param par; // off by default: a Run cut short is left as it is
    for (bool rule : {true, false}) {
        par.endAtMaxOperations = rule;
        Snake s(surf);
        s.InitFromSeeds(seeds, true);
        s.Run(3);
        ASSERT_EQ(s.Stats().stop, SnakeStop::MaxOperations);
        const std::vector<P3> before = s.PolylinePositions();
        const bool replaced = PartBoundaryEnd<CMeshO>::FinishRun(s, FeatureEnergyType::PartBoundary, false, par);
        const std::vector<P3> after = s.PolylinePositions();
        double rMin = 1e9, rMax = -1e9, zAbs = 0;
        for (const P3 &x : after)
            rMin = std::min(rMin, std::hypot(x[0], x[1])), rMax = std::max(rMax, std::hypot(x[0], x[1])), zAbs = std::max(zAbs, std::fabs(x[2]));
        std::printf("recess, ran out of operations, rule %d: replaced %d, loop at r %.3f..%.3f, |z| <= %.3f\n", int(rule), int(replaced),
                    rMin, rMax, zAbs);
        if (rule) {
            EXPECT_TRUE(replaced);
            EXPECT_NEAR(rMin, 1.0 * std::cos(M_PI / n), 1e-4); // on the 24-gon's edges
            EXPECT_NEAR(rMax, 1.0, 1e-6);
            EXPECT_LT(zAbs, 1e-6);
        } else {
            EXPECT_FALSE(replaced);
            EXPECT_EQ(before, after);
        }
    }
}

// A loop round a part is a simple cycle that separates the surface (session 34, loop_topology.h,
// ValleyLoop::Param::separating). On a torus a loop round the tube (a meridian) is simple but
// separates nothing: the band round it holds only such loops, and the cheapest of them, which
// the valley loop returned before, is no part's boundary (the benchmark's octopus, genus 1: the
// snake round a tentacle ran through a handle beside its base and every stage of the Run's end
// kept a loop through it). A vertex's one-ring on the torus separates; a loop with a vertex
// twice is no simple cycle.
TEST(ValleyLoop, KeepsNoLoopThatSeparatesNothing)
{
    CMeshO m;
    vcg::tri::Torus(m, 1.0f, 0.3f, 48, 16);
    gs_test::EnableSnakeAdjacency(m);
    // the meridian in the plane y = 0, x > 0: its vertices in order round the tube
    std::vector<std::pair<double, int>> mer;
    for (size_t v = 0; v < m.vert.size(); ++v) {
        const P3 p = P3::Construct(m.vert[v].cP());
        if (std::abs(p[1]) < 1e-4 && p[0] > 0) mer.push_back({std::atan2(p[2], p[0] - 1.0), int(v)});
    }
    ASSERT_EQ(mer.size(), 16u);
    std::sort(mer.begin(), mer.end());
    std::vector<int> vl;
    std::vector<P3> loop;
    std::vector<int> faces;
    for (const auto &x : mer) {
        vl.push_back(x.second);
        loop.push_back(P3::Construct(m.vert[x.second].cP()));
        faces.push_back(int(vcg::tri::Index(m, m.vert[x.second].cVFp())));
    }
    typedef LoopTopology<CMeshO> LT;
    EXPECT_FALSE(LT::SimpleSeparating(m, vl)); // simple, separates nothing
    // a vertex's one-ring (the faces round it in order) separates it
    std::vector<int> ring;
    {
        CVertexO *c = &m.vert[vl[0]];
        vcg::face::Pos<CFaceO> p(c->VFp(), c);
        const CVertexO *first = p.VFlip();
        do {
            ring.push_back(int(vcg::tri::Index(m, p.VFlip())));
            p.FlipE(), p.FlipF();
        } while (p.VFlip() != first);
    }
    ASSERT_GE(ring.size(), 3u);
    EXPECT_TRUE(LT::SimpleSeparating(m, ring));
    std::vector<int> twice = ring;
    twice.insert(twice.end(), ring.begin(), ring.end()); // round it twice: a vertex twice
    EXPECT_FALSE(LT::SimpleSeparating(m, twice));
    // the valley loop round the meridian: none when it must separate, a meridian before
    const std::vector<double> flat(m.vert.size(), 0.5);
    const double h = gs_test::MedianEdgeLength(m);
    ValleyLoop<CMeshO>::Param sep, any;
    any.separating = false;
    const std::vector<int> before = ValleyLoop<CMeshO>::Find(m, loop, faces, flat, h, any);
    ASSERT_GE(before.size(), 3u);
    EXPECT_FALSE(LT::SimpleSeparating(m, before));
    EXPECT_TRUE(ValleyLoop<CMeshO>::Find(m, loop, faces, flat, h, sep).empty());
    // a loop round a bump on the tube (a contractible ring of the band) is still found
    std::vector<P3> small;
    std::vector<int> smallFaces;
    for (int v : ring) small.push_back(P3::Construct(m.vert[v].cP())), smallFaces.push_back(int(vcg::tri::Index(m, m.vert[v].cVFp())));
    const std::vector<int> round = ValleyLoop<CMeshO>::Find(m, small, smallFaces, flat, 0.5 * h, sep);
    EXPECT_GE(round.size(), 3u);
    if (round.size() >= 3) EXPECT_TRUE(LT::SimpleSeparating(m, round));
}

// Whether a surface has a handle, from its Euler characteristic (LoopTopology::Planar): where it
// has none every simple cycle separates, and the valley loop skips the flood (the measure is
// taken once per mesh, PartBoundaryEnd::Measured). A sphere, a sphere with holes and two spheres
// are planar; a torus, and a sphere joined to a torus, are not.
TEST(LoopTopology, PlanarOnlyWithoutAHandle)
{
    typedef LoopTopology<CMeshO> LT;
    CMeshO sphere, holes, two, torus, both;
    vcg::tri::Sphere(sphere, 3);
    gs_test::EnableSnakeAdjacency(sphere);
    EXPECT_TRUE(LT::Planar(sphere));
    vcg::tri::Sphere(holes, 3);
    for (size_t i = 0; i < holes.face.size(); i += 97) vcg::tri::Allocator<CMeshO>::DeleteFace(holes, holes.face[i]);
    vcg::tri::Allocator<CMeshO>::CompactEveryVector(holes);
    gs_test::EnableSnakeAdjacency(holes);
    EXPECT_TRUE(LT::Planar(holes));
    vcg::tri::Sphere(two, 2);
    CMeshO other;
    vcg::tri::Sphere(other, 2);
    for (auto &v : other.vert) v.P() += vcg::Point3f(3, 0, 0);
    vcg::tri::Append<CMeshO, CMeshO>::Mesh(two, other);
    gs_test::EnableSnakeAdjacency(two);
    EXPECT_TRUE(LT::Planar(two));
    vcg::tri::Torus(torus, 1.0f, 0.3f, 48, 16);
    gs_test::EnableSnakeAdjacency(torus);
    EXPECT_FALSE(LT::Planar(torus));
    vcg::tri::Sphere(both, 2);
    for (auto &v : torus.vert) v.P() += vcg::Point3f(4, 0, 0);
    vcg::tri::Append<CMeshO, CMeshO>::Mesh(both, torus);
    gs_test::EnableSnakeAdjacency(both);
    EXPECT_FALSE(LT::Planar(both));
    // the Run's end's measure of the mesh
    EXPECT_EQ(PartBoundaryEnd<CMeshO>::Measured(sphere, PartBoundaryEnd<CMeshO>::Param()).valley.planar, 1);
    EXPECT_EQ(PartBoundaryEnd<CMeshO>::Measured(torus, PartBoundaryEnd<CMeshO>::Param()).valley.planar, 0);
}

// The loops round the border of a set of faces, each as its vertices in order (a vertex where
// the border meets itself is passed twice: no simple cycle).
std::vector<std::vector<int>> BorderLoops(const CMeshO &m, const std::vector<char> &in)
{
    std::multimap<int, int> next; // a -> b along each edge with `in` on its left
    for (size_t i = 0; i < m.face.size(); ++i) {
        const CFaceO &f = m.face[i];
        if (f.IsD() || !in[i]) continue;
        for (int k = 0; k < 3; ++k) {
            const CFaceO *g = f.cFFp(k);
            if (g != &f && !in[vcg::tri::Index(m, g)])
                next.insert({int(vcg::tri::Index(m, f.cV(k))), int(vcg::tri::Index(m, f.cV((k + 1) % 3)))});
        }
    }
    std::vector<std::vector<int>> loops;
    while (!next.empty()) {
        std::vector<int> l(1, next.begin()->first);
        for (auto it = next.begin(); it != next.end(); it = next.find(l.back())) {
            const int b = it->second;
            next.erase(it);
            if (b == l[0]) break;
            l.push_back(b);
        }
        loops.push_back(l);
    }
    return loops;
}

// LoopTopology's test by homology (made once per mesh on a surface with a handle, session 35)
// answers as the flood (LoopTopology::SimpleSeparating) on every loop, the closed path across a
// non-separating loop too: the borders of balls of faces growing on a torus (contractible
// rings, then the two meridians round the tube once the ball wraps round it, then rings round
// the hole), the torus with holes (loops through a border vertex: the flood answers), a torus
// joined to a sphere, a sphere and the benchmark's octopus. The generators: 2 g + b - 1 (g the
// genus, b the boundary loops).
TEST(LoopTopology, HomologyAnswersAsTheFlood)
{
    typedef LoopTopology<CMeshO> LT;
    CMeshO torus, holes, sphere, both;
    vcg::tri::Torus(torus, 1.0f, 0.3f, 48, 16);
    vcg::tri::Torus(holes, 1.0f, 0.3f, 48, 16);
    for (size_t i = 5; i < holes.face.size(); i += 211) vcg::tri::Allocator<CMeshO>::DeleteFace(holes, holes.face[i]);
    vcg::tri::Allocator<CMeshO>::CompactEveryVector(holes);
    vcg::tri::Sphere(sphere, 3);
    vcg::tri::Sphere(both, 2);
    CMeshO ring;
    vcg::tri::Torus(ring, 1.0f, 0.3f, 24, 12);
    for (auto &v : ring.vert) v.P() += vcg::Point3f(4, 0, 0);
    vcg::tri::Append<CMeshO, CMeshO>::Mesh(both, ring);
    gs_parts::Model octopus; // the benchmark's (genus 1)
    ASSERT_TRUE(gs_parts::LoadModel(GS_SEGMENTATION_DIR, 121, octopus)) << GS_SEGMENTATION_DIR;
    int separating = 0, not_ = 0, tested = 0;
    for (CMeshO *m : {&torus, &holes, &sphere, &both, &octopus.mesh}) {
        gs_test::EnableSnakeAdjacency(*m);
        const LT topo(*m);
        ASSERT_GE(topo.Generators(), 0);
        const int nf = int(m->face.size());
        for (int seed = 0; seed < nf; seed += nf / 7) {
            // a ball of faces round face `seed`, one ring of faces more at every step
            std::vector<char> in(nf, 0);
            std::vector<int> front(1, seed);
            in[seed] = 1;
            for (int step = 0; step < 60 && !front.empty(); ++step) {
                for (const auto &l : BorderLoops(*m, in)) {
                    std::vector<std::pair<int, int>> a, b;
                    const bool flood = LT::SimpleSeparating(*m, l, &a);
                    EXPECT_EQ(topo.Separating(*m, l, &b), flood);
                    std::sort(a.begin(), a.end()), std::sort(b.begin(), b.end());
                    EXPECT_EQ(a, b);
                    if (LT::Simple(l)) (flood ? separating : not_)++;
                    ++tested;
                }
                std::vector<int> next;
                for (int f : front)
                    for (int k = 0; k < 3; ++k) {
                        const int g = int(vcg::tri::Index(*m, m->face[f].cFFp(k)));
                        if (!in[g]) in[g] = 1, next.push_back(g);
                    }
                front.swap(next);
            }
        }
    }
    std::printf("%d loops, simple: %d separating, %d not\n", tested, separating, not_);
    EXPECT_GT(separating, 100);
    EXPECT_GT(not_, 20);
    EXPECT_EQ(LT(torus).Generators(), 2);
    EXPECT_EQ(LT(sphere).Generators(), 0);
    EXPECT_EQ(LT(both).Generators(), 2);
    EXPECT_EQ(LT(octopus.mesh).Generators(), 2);
    // every hole apart from one a generator more (the torus's deleted faces are apart)
    EXPECT_EQ(LT(holes).Generators(), 2 + int((torus.face.size() - 5 + 210) / 211) - 1);
}

// The benchmark's octopus (segmentation id 121, genus 1: a tunnel of a few faces beside tentacle
// 1's base, two of its edge triangles separate nothing). The loop the Run's end kept round that
// tentacle before session 34 (gs_parts GS_PARTS_TOPO_DUMP, part 1 seeded 2 rings inside) is simple
// and separates nothing: the band round it holds it as its cheapest loop. ValleyLoop::Param::
// separating takes the cheapest loop that meets the closed path across it (through the tunnel)
// evenly, round the tunnel's other side: a separating loop on the people's cut (1.00/0.94 in the
// benchmark, against 1.00/0.70).
TEST(ValleyLoop, GoesRoundAHandleBesideThePartOnTheOctopus)
{
    gs_parts::Model md;
    ASSERT_TRUE(gs_parts::LoadModel(GS_SEGMENTATION_DIR, 121, md)) << GS_SEGMENTATION_DIR;
    ASSERT_GE(md.parts.size(), 2u);
    CMeshO &m = md.mesh;
    const std::vector<int> old = {3746, 3194, 1841, 2375, 3734, 4037, 4054, 4191, 4201, 4296, 4295, 4305, 4304, 4210, 4209, 4071};
    ASSERT_EQ(m.vert.size(), 5944u);
    typedef LoopTopology<CMeshO> LT;
    EXPECT_FALSE(LT::SimpleSeparating(m, old));
    auto surf = WithEnergy(m, FeatureEnergyType::PartBoundary);
    std::vector<P3> loop;
    std::vector<int> faces;
    for (int v : old) loop.push_back(P3::Construct(m.vert[v].cP())), faces.push_back(int(vcg::tri::Index(m, m.vert[v].cVFp())));
    ValleyLoop<CMeshO>::Param sep, any;
    any.separating = false;
    const std::vector<int> a = ValleyLoop<CMeshO>::Find(m, loop, faces, surf->Energy(), md.h, any);
    const std::vector<int> b = ValleyLoop<CMeshO>::Find(m, loop, faces, surf->Energy(), md.h, sep);
    const gs_parts::Score sa = gs_parts::Measure(gs_parts::Positions(m, a), md.parts[1], md.h, md.h);
    const gs_parts::Score sb = gs_parts::Measure(gs_parts::Positions(m, b), md.parts[1], md.h, md.h);
    std::printf("octopus tentacle 1 beside the handle: the cheapest loop %zu vertices %.2f/%.2f, separating %d; "
                "the cheapest separating %zu vertices %.2f/%.2f\n", a.size(), sa.capture, sa.coverage, int(LT::SimpleSeparating(m, a)),
                b.size(), sb.capture, sb.coverage);
    ASSERT_GE(a.size(), 3u);
    EXPECT_FALSE(LT::SimpleSeparating(m, a)); // the mechanism: the band's cheapest loop runs through the handle
    ASSERT_GE(b.size(), 3u);
    EXPECT_TRUE(LT::SimpleSeparating(m, b));
    EXPECT_GT(sb.coverage, sa.coverage);
}

namespace {
/// A row of bench/eval/gs_parts: part `index` of benchmark model `id` and its 8 seeds `ring`
/// rings off it on `side` (+1 on the part, -1 outside). False when the data or the part is
/// missing or fewer than 3 seeds are found.
bool BenchmarkRow(int id, int index, int ring, int side, gs_parts::Model &md, const gs_parts::Part *&part,
                  std::vector<int> &seeds)
{
    part = nullptr;
    if (!gs_parts::LoadModel(GS_SEGMENTATION_DIR, id, md)) return false;
    for (const auto &p : md.parts)
        if (p.index == index) part = &p;
    if (!part) return false;
    seeds = gs_parts::Seeds(md.mesh, *part, ring, side, 8);
    return seeds.size() >= 3;
}
} // namespace

// The benchmark's octopus again (genus 1, the tunnel beside tentacle 1's base): seeded 2 rings
// outside tentacle 1 (gs_parts part 1 outside 2), the snake converges beside the tunnel, and no
// band round its loop nor round the seeded one holds a separating ring (their loops all run through
// the tunnel); FinishRun kept the snake's own loop (1.00/0.84). PartBoundaryEnd::Param::
// handleWiden (session 35) searches round it again in a band 1.5 times as wide, which reaches round
// the tunnel's other side: a separating loop on the people's cut (1.00/0.95).
TEST(PartBoundaryEnd, WidensTheBandBesideAHandleWhenNoRingSeparates)
{
    gs_parts::Model md;
    const gs_parts::Part *part = nullptr;
    std::vector<int> seeds;
    ASSERT_TRUE(BenchmarkRow(121, 1, 2, -1, md, part, seeds)) << GS_SEGMENTATION_DIR;
    CMeshO &m = md.mesh;
    ASSERT_EQ(m.vert.size(), 5944u);
    auto surf = WithEnergy(m, FeatureEnergyType::PartBoundary);
    typedef PartBoundaryEnd<CMeshO> End;
    const End::Param measured = End::Measured(m, End::Param());
    EXPECT_EQ(measured.valley.planar, 0); // the octopus has a handle
    gs_parts::Score score[2];
    bool replaced[2];
    for (int widen : {0, 1}) {
        End::Param par = measured;
        if (!widen) par.handleWiden = 1;
        Snake s(surf);
        s.InitFromSeeds(seeds, true);
        const auto seeded = End::Seeded::Of(s);
        s.Run(400);
        ASSERT_EQ(s.Stats().stop, SnakeStop::Converged);
        replaced[widen] = End::FinishRun(s, FeatureEnergyType::PartBoundary, false, par, &seeded);
        score[widen] = gs_parts::Measure(s.PolylinePositions(), *part, md.h, md.h);
        std::printf("octopus tentacle 1 seeded outside beside the handle, widen %d: replaced %d, %.2f/%.2f\n", widen,
                    int(replaced[widen]), score[widen].capture, score[widen].coverage);
    }
    EXPECT_FALSE(replaced[0]); // the mechanism: no band held a separating ring
    EXPECT_FALSE(score[0].Success());
    EXPECT_TRUE(replaced[1]);
    EXPECT_TRUE(score[1].Success());
}

// The benchmark's hand (issue 33, session 36): finger 1 seeded 2 rings outside (gs_parts part 1
// outside 2). The descent ends on the people's ring round the finger's base (28.1 h, 1.00/0.99,
// bend across 0.60); the bend rule then takes the loop round the level loop towards the body
// (31.8 h, 0.87/0.88): it bends more (0.79) and is 1 % cheaper per length, but only because it is
// longer, 12 % dearer in all. PartBoundaryEnd::Param::crossTotal (1.1) keeps a loop across no
// dearer in all than 1.1 times the loop's: the ring at the base stays.
TEST(PartBoundaryEnd, KeepsTheLoopWhenTheOneAcrossCostsMoreInAll)
{
    gs_parts::Model md;
    const gs_parts::Part *part = nullptr;
    std::vector<int> seeds;
    ASSERT_TRUE(BenchmarkRow(181, 1, 2, -1, md, part, seeds)) << GS_SEGMENTATION_DIR;
    CMeshO &m = md.mesh;
    auto surf = WithEnergy(m, FeatureEnergyType::PartBoundary);
    typedef PartBoundaryEnd<CMeshO> End;
    const End::Param measured = End::Measured(m, End::Param());
    gs_parts::Score score[2];
    double len[2];
    for (int total : {0, 1}) {
        End::Param par = measured;
        if (!total) par.crossTotal = 0;
        SnakeParams sp;
        sp.balloon = 0; // as bench/eval/gs_parts
        Snake s(surf, sp);
        s.InitFromSeeds(seeds, true);
        const auto seeded = End::Seeded::Of(s);
        s.Run(400);
        ASSERT_EQ(s.Stats().stop, SnakeStop::Converged);
        EXPECT_TRUE(End::FinishRun(s, FeatureEnergyType::PartBoundary, false, par, &seeded));
        score[total] = gs_parts::Measure(s.PolylinePositions(), *part, md.h, md.h);
        len[total] = gs_parts::LoopLength(s.PolylinePositions()) / md.h;
        std::printf("hand finger 1 seeded outside, crossTotal %d: %.1f h, %.2f/%.2f\n", total, len[total], score[total].capture,
                    score[total].coverage);
    }
    EXPECT_FALSE(score[0].Success()); // the mechanism: the longer loop towards the body
    EXPECT_GT(len[0], len[1]);
    EXPECT_TRUE(score[1].Success());
}
