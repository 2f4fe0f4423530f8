// Closed snakes around the parts of real scans (issue 33, observations 1 and 2): lion-head's
// eyes and bunny00's ear bases, seeded as a user clicks them, a few edge lengths off the rim or
// base. Before issue 33 both loops shrank to a point or a stub (normal variation marks the whole
// eye socket and the ear's ridge as feature) and the tool's Run never ended. With the
// part-boundary energy a loop must end on the rim or base, or stop saying why, never at a point
// called converged; every Run ends within Max operations and the time limit with its reason, with
// either energy. Figures: docs/evaluation.md "Eyes, an ear base and a handle".

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>

#include <part_cases.h>
#include <snake_test_util.h>
#include <vcg_ext/paths/seed_path.h>
#include <vcg_ext/session/controller.h>
#include <vcg_ext/snake/part_boundary_end.h>

#ifndef GS_SHARED_MESH_DIR
#define GS_SHARED_MESH_DIR GS_DATA_DIR "/../../shared/data/meshes"
#endif

using namespace vcg::tri;
typedef vcg::Point3d P3;

namespace {

struct ScanCase
{
    const char *name, *mesh;
    std::vector<P3> clicks; ///< around the part, in order (see Cases())
    bool hasTip = false;    ///< the part has a tip, at `tip`: a loop round the part cuts it off the body
    P3 tip = P3(0, 0, 0);
};

/// The frame of the clicks: centre, the normal of their polygon (the area vector, turned to
/// face like the surface there) and two axes in its plane.
struct Frame
{
    P3 c, n, u, v;
    Frame(const CMeshO &m, const std::vector<int> &seeds)
    {
        c = P3(0, 0, 0);
        P3 vn(0, 0, 0);
        for (int s : seeds) c += P3::Construct(m.vert[s].cP()), vn += P3::Construct(m.vert[s].cN());
        c /= double(seeds.size());
        n = P3(0, 0, 0);
        for (size_t i = 0; i < seeds.size(); ++i)
            n += (P3::Construct(m.vert[seeds[i]].cP()) - c) ^ (P3::Construct(m.vert[seeds[(i + 1) % seeds.size()]].cP()) - c);
        n.Normalize();
        if (n * vn < 0) n = -n;
        u = (std::fabs(n[0]) < 0.9 ? P3(1, 0, 0) : P3(0, 1, 0)) ^ n;
        u.Normalize();
        v = n ^ u;
    }
    double Angle(const P3 &x) const { return std::atan2((x - c) * v, (x - c) * u); }
    double Radius(const P3 &x) const { const P3 d = x - c; return std::hypot(d * u, d * v); }
    double Height(const P3 &x) const { return (x - c) * n; }
    /// Times the loop winds round the axis through the centre along the normal.
    double Winding(const std::vector<P3> &loop) const
    {
        double w = 0;
        for (size_t i = 0; i < loop.size(); ++i) {
            double d = Angle(loop[(i + 1) % loop.size()]) - Angle(loop[i]);
            while (d > M_PI) d -= 2 * M_PI;
            while (d < -M_PI) d += 2 * M_PI;
            w += d;
        }
        return w / (2 * M_PI);
    }
};

struct ScanOutcome
{
    SnakeStop stop = SnakeStop::Running;
    int operations = 0, samples = 0;
    double seconds = 0, length0 = 0, length = 0, winding = 0, minRadius = 0, meanRadius = 0, radius0 = 0;
    double energy0 = 0, energy = 0; ///< mean part-boundary energy along the start and final loops
    double h = 0;                   ///< mean edge length
    std::string warning;            ///< the run's last warning
    bool startSeparates = false, separates = false; ///< the start's and the final loop cut the tip off (Separates)
};

/// Whether closed polyline `loop` on m cuts the part's tip off the body: a topological test,
/// not the planar winding (an ear's base is oblique to any view). The loop is taken to the edge
/// path through its nearest vertices (SeedPath, as the tool joins clicks), and the vertices
/// flooded over edges without crossing it from the vertex nearest `tip` must not reach the
/// vertex farthest from it (the body).
bool Separates(CMeshO &m, const std::vector<P3> &loop, const P3 &tipPoint)
{
    if (loop.size() < 3) return false;
    std::vector<char> blocked(m.vert.size(), 0);
    for (int v : SeedPath<CMeshO>::Compute(m, gs_test::NearestVertices(m, loop), true).vertices) blocked[v] = 1;
    std::vector<std::vector<int>> adj(m.vert.size());
    for (const auto &f : m.face)
        for (int k = 0; k < 3; ++k) adj[Index(m, f.cV(k))].push_back(int(Index(m, f.cV((k + 1) % 3))));
    const int tip = gs_test::NearestVertex(m, tipPoint);
    int body = -1;
    double far = -1;
    for (size_t i = 0; i < m.vert.size(); ++i) {
        const double d = (P3::Construct(m.vert[i].cP()) - P3::Construct(m.vert[tip].cP())).Norm();
        if (d > far) far = d, body = int(i);
    }
    if (blocked[tip] || blocked[body]) return false;
    std::vector<char> seen(m.vert.size(), 0);
    std::vector<int> q = {tip};
    seen[tip] = 1;
    for (size_t i = 0; i < q.size(); ++i)
        for (int w : adj[q[i]])
            if (!seen[w] && !blocked[w]) seen[w] = 1, q.push_back(w);
    return !seen[body];
}

double MeanEnergy(const CMeshO &m, const std::vector<double> &e, const std::vector<P3> &loop)
{
    double s = 0;
    for (const P3 &x : loop) s += e[gs_test::NearestVertex(m, x)];
    return s / loop.size();
}

ScanOutcome RunCase(CMeshO &m, const std::vector<int> &seeds, FeatureEnergyType t, const std::vector<double> &partEnergy,
                const Frame &fr, const ScanCase &sc, bool end)
{
    SnakeController<CMeshO> ctl(m);
    ctl.SetEnergySettings(t, 2);
    ctl.SetSeeds(seeds);
    ctl.CloseSeeds(true);
    GeometricSnake<CMeshO> &s = ctl.Get(0);
    ScanOutcome o;
    o.samples = s.SampleCount();
    const std::vector<P3> start = s.PolylinePositions();
    o.length0 = gs_parts::LoopLength(start);
    for (const P3 &x : start) o.radius0 += fr.Radius(x) / start.size();
    o.energy0 = MeanEnergy(m, partEnergy, start);
    if (sc.hasTip) o.startSeparates = Separates(m, start, sc.tip);
    const auto seeded = PartBoundaryEnd<CMeshO>::Seeded::Of(s);
    SnakeRunLimits lim; // the tool's defaults: 500 operations, 60 s
    lim.maxOperations = 500;
    lim.seconds = 60;
    const auto t0 = SnakeClock::Now();
    o.stop = s.Run(lim);
    o.seconds = SnakeClock::MsSince(t0) / 1000;
    o.operations = s.Stats().operations;
    // the Run's end every host applies (edit tool, filters, program: PartBoundaryEnd::FinishRun)
    if (end) PartBoundaryEnd<CMeshO>::FinishRun(s, t, false, ctl.RunEndParam(), &seeded);
    const std::vector<P3> loop = s.PolylinePositions();
    if (sc.hasTip) o.separates = Separates(m, loop, sc.tip);
    o.length = gs_parts::LoopLength(loop);
    o.winding = fr.Winding(loop);
    o.minRadius = 1e300;
    for (const P3 &x : loop) o.minRadius = std::min(o.minRadius, fr.Radius(x)), o.meanRadius += fr.Radius(x) / loop.size();
    o.energy = MeanEnergy(m, partEnergy, loop);
    o.h = ctl.MeanEdge();
    if (!s.Stats().warnings.empty()) o.warning = s.Stats().warnings.back();
    return o;
}

/// The clicks mirrored through the plane {x : n.x = d} (n a unit vector).
std::vector<P3> Mirrored(const std::vector<P3> &clicks, const P3 &n, double d)
{
    std::vector<P3> out;
    for (const P3 &x : clicks) out.push_back(x - n * (2 * (n * x - d)));
    return out;
}

struct Loaded
{
    CMeshO m;
    std::vector<double> partEnergy;
};

/// The two meshes, loaded once for all the cases.
Loaded &Mesh(const std::string &name)
{
    static std::map<std::string, std::unique_ptr<Loaded>> cache;
    std::unique_ptr<Loaded> &l = cache[name];
    if (!l) {
        l.reset(new Loaded);
        if (!gs_test::LoadMesh(l->m, std::string(GS_SHARED_MESH_DIR) + "/" + name)) return *l;
        gs_test::EnableSnakeAdjacency(l->m);
        vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFace(l->m);
        l->partEnergy = PartBoundaryEnergy<CMeshO>::VertexValues(l->m, 2);
    }
    return *l;
}

std::vector<P3> RightEyeClicks()
{
    return {P3(0.1352, 0.1436, 0.3102), P3(0.1003, 0.1783, 0.3446), P3(0.0401, 0.1759, 0.3764),
            P3(0.0167, 0.1395, 0.3717), P3(0.0503, 0.1031, 0.3501), P3(0.1116, 0.1054, 0.3256)};
}

std::vector<ScanCase> Cases()
{
    std::vector<ScanCase> c = {
        // the six clicks of the issue's observation 1 round lion-head's right eye (vertices 8111,
        // 1644, 6377, 1581, 8187, 8109 of the file, as in host_edit_gui_run_end), a few edge
        // lengths outside the eye's rim
        {"lion-head right eye", "lion-head.off", RightEyeClicks()},
        // the left eye: the same six clicks mirrored through the head's plane of symmetry,
        // n = (0.9801, 0.0441, 0.1938), d = -0.0075 (fitted as the plane whose mirror image of the
        // mesh lies nearest the mesh: mean distance from a mirrored vertex to the nearest vertex
        // 0.0057, 0.34 h). The mirrored clicks lie within 0.1 h of a vertex, on the part-boundary energy
        // of their right twins (1.0, 0.78, 1.0, 0.24, 0.11, 0.96 right; 0.84, 0.78, 1.0, 0.25,
        // 0.06, 1.0 left), so the case is the right eye's, seen in a mirror.
        {"lion-head left eye", "lion-head.off", Mirrored(RightEyeClicks(), P3(0.98005, 0.04413, 0.19377), -0.0075)},
        // the four clicks of observation 2 round the base of bunny00's back ear (vertices 29600,
        // 2997, 4963, 14816)
        // (the tip: the back ear's, the mesh's highest vertex). Joined by the tool's shortest
        // paths they enclose a patch of the head beside the ear's front face (205 vertices),
        // neither ear: no loop from them goes round the ear without crossing its tip
        {"bunny00 back ear base", "bunny00.off",
         {P3(-0.1745, 0.2886, 0.0555), P3(-0.2261, 0.3379, 0.0352), P3(-0.2957, 0.2810, 0.2102),
          P3(-0.2454, 0.2397, 0.1914)},
         true, P3(-0.0049, 0.4938, -0.1203)},
        // six clicks round each ear's base, over both faces of the ear's blade, as a user goes
        // round it (the back ear: vertices 4223, 14874, 36289, 14756, 21464, 29097; the front
        // one: 13929, 6212, 21292, 4143, 12296, 20932): the vertices nearest six points evenly
        // spaced along the ear's section by the plane normal to its axis (from the middle of
        // its base to its tip), 0.1 (back) and 0.05 (front) of the axis from the base towards
        // the tip, i.e. 2-4 edge lengths beside the valley where the ear leaves the head. The
        // front ear's tip: its vertex farthest along -z.
        {"bunny00 back ear base, round it", "bunny00.off",
         {P3(-0.2564, 0.2721, 0.0015), P3(-0.2232, 0.2330, -0.0008), P3(-0.1860, 0.2284, 0.0335),
          P3(-0.1869, 0.2689, 0.0654), P3(-0.2267, 0.3048, 0.0709), P3(-0.2589, 0.3129, 0.0356)},
         true, P3(-0.0049, 0.4938, -0.1203)},
        {"bunny00 front ear base", "bunny00.off",
         {P3(-0.3666, 0.3047, -0.0204), P3(-0.3182, 0.2876, -0.0118), P3(-0.2899, 0.2393, -0.0219),
          P3(-0.3039, 0.1967, -0.0384), P3(-0.3578, 0.2089, -0.0465), P3(-0.3841, 0.2559, -0.0359)},
         true, P3(-0.2906, 0.3976, -0.3865)},
    };
    return c;
}

/// Runs the case's closed snake as the tool does (its controller, the clicks closed into a loop,
/// Run with the panel's default limits) and prints what it did.
ScanOutcome RunScan(const ScanCase &sc, FeatureEnergyType t, bool end = false)
{
    Loaded &l = Mesh(sc.mesh);
    if (l.m.fn == 0) return ScanOutcome();
    const std::vector<int> seeds = gs_test::NearestVertices(l.m, sc.clicks);
    const Frame fr(l.m, seeds);
    const ScanOutcome o = RunCase(l.m, seeds, t, l.partEnergy, fr, sc, end);
    std::printf("%s, %s: %d samples, %s after %d operations, %.2f s; length %.2f of the start's (%.1f h), winding "
                "%.2f round the clicks' centre, radius min %.1f h mean %.1f h (start %.1f h), part-boundary energy "
                "%.2f (start %.2f)\n",
                sc.name, FeatureEnergyName(t), o.samples, SnakeStopKey(o.stop), o.operations, o.seconds,
                o.length / o.length0, o.length0 / o.h, o.winding, o.minRadius / o.h, o.meanRadius / o.h,
                o.radius0 / o.h, o.energy, o.energy0);
    if (sc.hasTip)
        std::printf("  %s: the start %s the tip off the body, the final loop %s\n", end ? "with the Run's end" : "the snake alone",
                    o.startSeparates ? "cuts" : "does not cut", o.separates ? "cuts it off" : "does not");
    return o;
}

/// Every Run ends by itself within the tool's limits and says why; never a point called converged.
void ExpectEndsWithAReason(const ScanCase &sc, const ScanOutcome &o)
{
    EXPECT_NE(o.stop, SnakeStop::Running) << sc.name;
    EXPECT_LE(o.operations, 500) << sc.name;
    EXPECT_LT(o.seconds, 60) << sc.name;
    if (o.stop == SnakeStop::Converged) {
        EXPECT_GT(o.length, 0.4 * o.length0) << sc.name << ": converged at a point or a stub";
    } else {
        EXPECT_TRUE(o.stop == SnakeStop::Collapsed || o.stop == SnakeStop::LeftPart) << sc.name << ": " << SnakeStopKey(o.stop);
        EXPECT_FALSE(o.warning.empty()) << sc.name << ": a stop without its warning";
    }
}

} // namespace

// Lion-head's eyes with the part-boundary energy: each ends on the eye's rim, a loop round the
// clicks' centre (winding 1; the left eye's clicks, mirrored, wind the other way), no point
// (measured: 0.53 and 0.55 of the start's length, no point nearer the clicks' centre than 1.2 h),
// in the valley (mean energy 0.05 against 0.57 where they started). Before session 37 the left
// eye's clicks were a circle of radius 2.2 h round a centre 1.85 h off the mirrored right one,
// half of them on the socket's floor: that loop collapsed, 43 operations (the case's fault, not
// the energy's: mirrored, the right eye's clicks end on the left rim as on the right one).
TEST(PartScans, LionEyesEndOnTheRim)
{
    const std::vector<ScanCase> cases = Cases();
    for (int i : {0, 1}) {
        const ScanCase &sc = cases[i];
        const Loaded &l = Mesh(sc.mesh);
        ASSERT_GT(l.m.fn, 0) << sc.mesh;
        const ScanOutcome o = RunScan(sc, FeatureEnergyType::PartBoundary);
        for (const P3 &x : sc.clicks) // the mirror keeps the clicks on the surface (measured: < 0.1 h)
            EXPECT_LT((P3::Construct(l.m.vert[gs_test::NearestVertex(l.m, x)].cP()) - x).Norm(), 0.25 * o.h) << sc.name;
        ExpectEndsWithAReason(sc, o);
        EXPECT_EQ(o.stop, SnakeStop::Converged) << sc.name;
        EXPECT_NEAR(std::fabs(o.winding), 1.0, 0.01) << sc.name << ": the loop no longer goes round the eye";
        EXPECT_GT(o.length, 0.4 * o.length0) << sc.name;
        EXPECT_GT(o.minRadius, 0.5 * o.h) << sc.name << ": the loop passes through the eye's centre";
        EXPECT_LT(o.energy, 0.2) << sc.name << ": the loop is not in the rim's valley";
        EXPECT_LT(o.energy, 0.5 * o.energy0) << sc.name;
    }
}

// bunny00's ear bases with the part-boundary energy, ended as every host ends a Run
// (PartBoundaryEnd::FinishRun). Seeded round an ear (six clicks over both faces of its blade,
// Cases()), the loop ends on the ear's base: it still cuts the ear off the body (a topological
// test: the planar winding cannot tell on an oblique base), keeps its length and lies in the
// valley (measured, s37-h2: back ear 25 operations, length 1.03 of the start's, mean energy
// 0.63 -> 0.14; front ear 56 operations, 1.07, 0.30 -> 0.14). The issue's four clicks enclose
// a patch of the head beside the back ear, not the ear (the start cuts nothing off): the loop
// cannot reach the base without crossing the ear's tip; it must still end with a reason, no
// point (measured: converged beside the base, length 1.01; the Run's end keeps 0.53 of it).
TEST(PartScans, BunnyEarBaseKeepsItsLengthAndEnds)
{
    const std::vector<ScanCase> cases = Cases();
    ASSERT_GT(Mesh(cases[2].mesh).m.fn, 0) << cases[2].mesh;
    const ScanOutcome issue = RunScan(cases[2], FeatureEnergyType::PartBoundary, true);
    ExpectEndsWithAReason(cases[2], issue);
    EXPECT_FALSE(issue.startSeparates) << "the issue's clicks now go round the ear: assert that the loop ends round it";
    for (int i : {3, 4}) {
        const ScanCase &sc = cases[i];
        const ScanOutcome o = RunScan(sc, FeatureEnergyType::PartBoundary, true);
        ExpectEndsWithAReason(sc, o);
        EXPECT_EQ(o.stop, SnakeStop::Converged) << sc.name;
        EXPECT_TRUE(o.startSeparates) << sc.name << ": the clicks do not go round the ear";
        EXPECT_TRUE(o.separates) << sc.name << ": the loop no longer goes round the ear";
        EXPECT_GT(o.length, 0.6 * o.length0) << sc.name;
        EXPECT_LT(o.energy, 0.2) << sc.name << ": the loop is not in the base's valley";
        EXPECT_LT(o.energy, 0.6 * o.energy0) << sc.name;
    }
}

// The documented behaviour of normal variation round a part (README "Snaking around a part"): it
// marks the whole socket or ridge as feature, the loop shrinks into it and the Run stops as
// collapsing (measured: the eyes after 4 and 7 operations, the ear base after 350), with its
// warning; before issue 33 the tool's Run went on for 237,068 operations.
TEST(PartScans, NormalVariationStopsInsteadOfEndingAtAPoint)
{
    const std::vector<ScanCase> cases = Cases();
    for (int i : {0, 1, 2}) {
        const ScanCase &sc = cases[i];
        ASSERT_GT(Mesh(sc.mesh).m.fn, 0) << sc.mesh;
        const ScanOutcome o = RunScan(sc, FeatureEnergyType::NormalVariation);
        ExpectEndsWithAReason(sc, o);
        EXPECT_NE(o.stop, SnakeStop::Converged) << sc.name << ": the loop settled round the part with normal variation?";
    }
}
