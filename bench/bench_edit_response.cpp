// What the edit tool does per input on a 1.2M-face mesh (issue 37: a seed click took 0.65-1.04 s
// to show, Build 1.77 s; targets 100 ms and 300 ms). bunny00 midpoint-subdivided twice.
//
// BM_PickGrid      the uniform grid of the faces that picking casts rays on (once per mesh)
// BM_Prepare       the feature energy and the snake surface (once per mesh; the tool starts it
//                  on another thread when it starts, SnakeController::PrepareInBackground,
//                  with the seed paths' SeedPath::MeshIndex)
// BM_Click         one seed click once both are ready: the ray cast and the seed added
// BM_Build         Enter with 4 seeds across the bunny once both are ready: the seed path (A*
//                  between the clicked points), the samples, the session as JSON for autosave
// BM_BuildCold     the same on a controller that has not prepared (what the first Build cost
//                  before; every Build paid the seed path's O(mesh) part)
// BM_ValleyLoop    the end of a converged closed Run on the part-boundary energy (issue 33,
//                  PartBoundaryEnd::FinishRun: the cheapest edge loop within 2 units of the snake
//                  replaces it), what the edit tool does at every such Run end; a loop of 6
//                  clicks round a patch of the bunny's flank, run 60 operations; arg = the
//                  mesh's faces (bunny00 as scanned, and subdivided to 1.2M: the ratio shows
//                  what grows with the mesh rather than with the band). Session 33: with the
//                  mesh's measures the crease filter reads taken once per mesh, as the hosts
//                  do (SnakeSession::RunEndParam), not in the Run's end. arg 1: 1 = read as a mesh
//                  with a handle (ValleyLoop::Param::planar 0 before PartBoundaryEnd::Measured:
//                  the separation test of every loop found, LoopTopology; bunny00 has none)
// BM_RunEndMeasures those measures (PartBoundaryEnd::Measured: SurfaceNoise::Level, the median
//                  face angle), once per mesh and energy; args as BM_ValleyLoop
// BM_ValleyLoopSeeded the same end when the loop converged shorter than half its seeded loop
//                  (PartBoundaryEnd::Param::seededShrink, session 25: a second search round the
//                  seeded loop), on a tall bump on a sphere (icosphere 6, 81920 faces; its rim a
//                  concave valley 70 edges round); arg 0: case (0: a loop 16 h up the bump seeded
//                  8 h outside its rim, the pattern of fourleg 381; 1: a loop that converged on
//                  the rim, seeded on the equator), arg 1: the seeded loop given (1) or not
//                  (0, what FinishRun cost before session 25)
// BM_PartEndTowardBody the same end when no band round the seeded loop holds a ring either
//                  (PartBoundaryEnd::TowardBody, session 27: the seeds' ring moved towards the
//                  body by part salience), on the short part of tests/test_part_boundary.cpp
//                  (984 faces); arg = the mesh's faces at least, the body far below the part
//                  midpoint-subdivided (0: as the test, 100000: 127k, 1200000: 2.0M faces)
// Run: build/bench/bench_edit_response --benchmark_repetitions=5 and read the medians.

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>

#include <snake_bench_util.h>
#include <vcg/complex/algorithms/closest.h>
#include <vcg/complex/algorithms/refine.h>
#include <vcg/space/index/grid_static_ptr.h>
#include <vcg_ext/energy/energy_source.h>
#include <vcg_ext/session/controller.h>
#include <vcg_ext/snake/part_boundary_end.h>
#include <revolved_profile.h>

namespace {

using namespace vcg::tri;
typedef SnakeController<CMeshO> Controller;
typedef vcg::GridStaticPtr<CFaceO, Scalarm> Grid;

CMeshO &Mesh()
{
    static CMeshO &m = [] () -> CMeshO & {
        CMeshO &b = gs_bench::SubdividedBunny(1200000);
        gs_test::EnableSnakeAdjacency(b);
        return b;
    }();
    return m;
}

Grid &PickGrid()
{
    static std::unique_ptr<Grid> g;
    if (!g) {
        g.reset(new Grid);
        g->Set(Mesh().face.begin(), Mesh().face.end());
    }
    return *g;
}

/// A ray towards the back of the bunny (-z) through (x, y) of its bounding box, as a click
/// (a little higher where the scan has a hole).
CFaceO *Click(CMeshO &m, Grid &grid, double fx, double fy, SurfacePoint &sp)
{
    const auto &b = m.bbox;
    Point3m o;
    vcg::Ray3<Scalarm> ray;
    Scalarm t = 0;
    CFaceO *f = nullptr;
    for (int k = 0; k < 20 && !f; ++k) {
        o = Point3m(b.min[0] + fx * b.DimX(), b.min[1] + (fy + 0.02 * k) * b.DimY(), b.max[2] + b.DimZ());
        ray = vcg::Ray3<Scalarm>(o, Point3m(0, 0, -1));
        f = vcg::tri::DoRay(m, grid, ray, Scalarm(3 * b.DimZ()), t);
    }
    if (!f) return nullptr;
    Point3m bary;
    vcg::InterpolationParameters(vcg::Triangle3<Scalarm>(f->cP(0), f->cP(1), f->cP(2)), o + ray.Direction() * t, bary);
    sp = SurfacePoint(int(vcg::tri::Index(m, f)), vcg::Point3d::Construct(bary));
    sp.Normalize();
    return f;
}
CFaceO *Click(double fx, double fy, SurfacePoint &sp) { return Click(Mesh(), PickGrid(), fx, fy, sp); }

const double kX[4] = {0.43, 0.45, 0.47, 0.49}; // across the body (~100 samples, as the 92), at 40 % of its height
const double kY = 0.4;

double BuildOnce(Controller &c, benchmark::State *state = nullptr);

/// A controller as the edit tool has it some seconds after it started: prepared, one Build done.
Controller &Ready()
{
    static std::unique_ptr<Controller> c;
    if (!c) {
        c.reset(new Controller(Mesh()));
        c->PrepareInBackground();
        c->EnsureSurface();
        BuildOnce(*c);
    }
    return *c;
}

double BuildOnce(Controller &c, benchmark::State *state)
{
    for (double x : kX) {
        SurfacePoint sp;
        if (!Click(x, kY, sp)) std::exit(2);
        c.AddSeedFromPick(sp.face, sp.bary);
    }
    if (state) state->ResumeTiming();
    c.CloseSeeds(false);
    benchmark::DoNotOptimize(c.ToJson().dump());
    if (state) state->PauseTiming();
    const double n = c.SelectedSnake()->SampleCount();
    c.DeleteSnake(c.Selected());
    return n;
}

void BM_PickGrid(benchmark::State &state)
{
    for (auto _ : state) {
        Grid g;
        g.Set(Mesh().face.begin(), Mesh().face.end());
    }
    state.counters["faces"] = Mesh().fn;
}

void BM_Prepare(benchmark::State &state)
{
    for (auto _ : state) {
        Controller c(Mesh());
        c.EnsureSurface();
    }
}

void BM_Click(benchmark::State &state)
{
    Controller &c = Ready();
    int i = 0;
    for (auto _ : state) {
        SurfacePoint sp;
        if (!Click(kX[i % 4], kY + 0.01 * (i / 4 % 10), sp)) std::exit(2);
        c.AddSeedFromPick(sp.face, sp.bary);
        benchmark::DoNotOptimize(c.ToJson().dump());
        ++i;
    }
    c.ClearSeeds();
}

void BM_Build(benchmark::State &state)
{
    Controller &c = Ready();
    double n = 0;
    for (auto _ : state) {
        state.PauseTiming();
        n = BuildOnce(c, &state);
        state.ResumeTiming();
    }
    state.counters["samples"] = n;
}

void BM_BuildCold(benchmark::State &state)
{
    double n = 0;
    for (auto _ : state) {
        state.PauseTiming();
        Controller c(Mesh());
        n = BuildOnce(c, &state);
        state.ResumeTiming();
    }
    state.counters["samples"] = n;
}

/// A closed snake on the part-boundary energy after its Run, on bunny00 subdivided to `faces`.
struct ValleyCase
{
    std::unique_ptr<Controller> c;
    std::vector<SnakeSample> samples;
    double unit = 0;
};

ValleyCase &Valley(int faces)
{
    static std::map<int, ValleyCase> cases;
    ValleyCase &k = cases[faces];
    if (k.c) return k;
    CMeshO &m = faces == 1200000 ? Mesh() : gs_bench::SubdividedBunny(faces);
    gs_test::EnableSnakeAdjacency(m);
    Grid grid;
    grid.Set(m.face.begin(), m.face.end());
    k.c.reset(new Controller(m));
    k.c->SetEnergySettings(FeatureEnergyType::PartBoundary, k.c->EnergySmoothing());
    for (int i = 0; i < 6; ++i) {
        SurfacePoint sp;
        const double a = 2 * M_PI * i / 6;
        if (!Click(m, grid, 0.45 + 0.08 * std::cos(a), 0.45 + 0.08 * std::sin(a), sp)) std::exit(2);
        k.c->AddSeedFromPick(sp.face, sp.bary);
    }
    k.c->CloseSeeds(true);
    auto *s = k.c->SelectedSnake();
    s->Run(60);
    std::fprintf(stderr, "valley case on %d faces: %zu samples, unit %g (%.2f mean edges), run: %s\n", m.fn,
                 s->Samples().size(), s->LengthScale(), s->LengthScale() / k.c->MeanEdge(), SnakeStopKey(s->Stats().stop));
    k.samples = s->Samples();
    k.unit = s->LengthScale();
    k.c->RunEndParam(); // the mesh's measures for the Run's end, taken once (BM_RunEndMeasures)
    return k;
}

/// The Run's end's parameters before the mesh's measures: with `handle`, as on a mesh with a
/// handle (ValleyLoop::Param::planar 0, so that Measured does not read it as planar).
PartBoundaryEnd<CMeshO>::Param HandleIn(bool handle)
{
    PartBoundaryEnd<CMeshO>::Param p;
    if (handle) p.valley.planar = 0;
    return p;
}

/// The Run's end's parameters on case k's mesh read as one with a handle, measured once.
const PartBoundaryEnd<CMeshO>::Param &HandleParam(ValleyCase &k)
{
    static std::map<const ValleyCase *, PartBoundaryEnd<CMeshO>::Param> measured;
    auto it = measured.find(&k);
    if (it == measured.end()) it = measured.emplace(&k, PartBoundaryEnd<CMeshO>::Measured(k.c->Mesh(), HandleIn(true))).first;
    return it->second;
}

void BM_ValleyLoop(benchmark::State &state)
{
    ValleyCase &k = Valley(int(state.range(0)));
    const PartBoundaryEnd<CMeshO>::Param par = state.range(1) ? HandleParam(k) : k.c->RunEndParam();
    auto *s = k.c->SelectedSnake();
    int replaced = 0;
    for (auto _ : state) {
        state.PauseTiming();
        s->InitFromSamples(k.samples, true, k.unit);
        s->EndRun(SnakeStop::Converged); // as a Run that converged there
        state.ResumeTiming();
        replaced += PartBoundaryEnd<CMeshO>::FinishRun(*s, FeatureEnergyType::PartBoundary, false, par);
    }
    state.counters["faces"] = k.c->Mesh().fn;
    state.counters["samples"] = double(k.samples.size());
    state.counters["replaced"] = double(replaced) / state.iterations();
}

/// What a host pays once per mesh for the Run's end (SnakeSession::RunEndParam, session 33).
void BM_RunEndMeasures(benchmark::State &state)
{
    ValleyCase &k = Valley(int(state.range(0)));
    double noise = 0;
    for (auto _ : state) {
        const PartBoundaryEnd<CMeshO>::Param p = PartBoundaryEnd<CMeshO>::Measured(k.c->Mesh(), HandleIn(state.range(1)));
        noise = p.valley.creaseFilter.noiseLevel;
        benchmark::DoNotOptimize(noise);
    }
    state.counters["faces"] = k.c->Mesh().fn;
    state.counters["noise"] = noise;
}

/// The tall bump of tests/test_part_boundary.cpp (ValleyLoop.SearchesRoundTheSeededLoopWhenTheSnakeShrankFar)
/// on a finer sphere, and its loops: where FinishRun starts from, and the loop seeded.
struct SeededCase
{
    CMeshO m;
    std::shared_ptr<SnakeSurface<CMeshO>> surf;
    std::vector<SnakeSample> samples[2];
    double unit[2] = {0, 0};
    PartBoundaryEnd<CMeshO>::Seeded seeded[2];
    PartBoundaryEnd<CMeshO>::Param par; // with the mesh's measures (PartBoundaryEnd::Measured), as a host's
};

double Leg(double phi) { return 1.0 + 0.8 * std::exp(-std::pow(phi / 0.25, 2)); }

SeededCase &Seeded()
{
    static std::unique_ptr<SeededCase> k;
    if (k) return *k;
    k.reset(new SeededCase);
    CMeshO &m = k->m;
    gs_test::MakeIcosphere(m, 6);
    for (auto &v : m.vert) {
        const vcg::Point3d p = vcg::Point3d::Construct(v.cP()).Normalize();
        v.P() = Point3m::Construct(p * Leg(std::acos(std::max(-1.0, std::min(1.0, p[2])))));
    }
    gs_test::EnableSnakeAdjacency(m);
    vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFace(m);
    FeatureEnergy<CMeshO>::Compute(m, FeatureEnergyType::PartBoundary, 2);
    k->surf = std::make_shared<SnakeSurface<CMeshO>>(m, SnakeEnergySource<CMeshO>::CaptureSmoothingFor(false, FeatureEnergyType::PartBoundary));
    k->par = PartBoundaryEnd<CMeshO>::Measured(m, PartBoundaryEnd<CMeshO>::Param());
    // the rim: where the meridian bends most inwards (as the test's RimOf)
    double rim = 0, kBest = 1e300;
    for (double phi = 0.05; phi < 1.5; phi += 1e-4) {
        auto pt = [](double f) { return vcg::Point3d(Leg(f) * std::sin(f), 0, Leg(f) * std::cos(f)); };
        const double d = 1e-4;
        const vcg::Point3d a = pt(phi - d), b = pt(phi), c = pt(phi + d);
        const vcg::Point3d acc = ((c - b) - (b - a)) / (d * d), vel = (c - a) / (2 * d);
        const double kk = -(vel[0] * acc[2] - vel[2] * acc[0]) / std::pow(vel.Norm(), 3);
        if (kk < kBest) kBest = kk, rim = phi;
    }
    const auto ring = [&](double phi) {
        std::vector<vcg::Point3d> pts;
        for (int i = 0; i < 8; ++i) {
            const double a = 2 * M_PI * i / 8;
            pts.push_back(vcg::Point3d(std::sin(phi) * std::cos(a), std::sin(phi) * std::sin(a), std::cos(phi)) * Leg(phi));
        }
        return gs_test::NearestVertices(m, pts);
    };
    // offsets in the test's units (its icosphere 4 has 4x longer edges): the same loops
    const double u = 4 * k->surf->MeanEdge();
    GeometricSnake<CMeshO> s(k->surf);
    // case 0: seeded 2 units outside the rim, ended 4 units up the bump
    s.InitFromSeeds(ring(rim + 2 * u / Leg(rim)), true);
    k->seeded[0] = PartBoundaryEnd<CMeshO>::Seeded::Of(s);
    s.InitFromSeeds(ring(rim - 4 * u / Leg(rim)), true);
    k->samples[0] = s.Samples(), k->unit[0] = s.LengthScale();
    // case 1: seeded on the equator, converged on the rim (a Run from 2 units outside it)
    s.InitFromSeeds(ring(M_PI / 2), true);
    k->seeded[1] = PartBoundaryEnd<CMeshO>::Seeded::Of(s);
    s.InitFromSeeds(ring(rim + 2 * u / Leg(rim)), true);
    s.Run(400);
    k->samples[1] = s.Samples(), k->unit[1] = s.LengthScale();
    std::fprintf(stderr, "seeded case on %d faces (h %.4f): run from outside the rim: %s, %zu samples\n", m.fn,
                 k->surf->MeanEdge(), SnakeStopKey(s.Stats().stop), k->samples[1].size());
    return *k;
}

void BM_ValleyLoopSeeded(benchmark::State &state)
{
    SeededCase &k = Seeded();
    const int c = int(state.range(0));
    const bool with = state.range(1) != 0;
    GeometricSnake<CMeshO> s(k.surf);
    int replaced = 0, shrank = 0;
    for (auto _ : state) {
        state.PauseTiming();
        s.InitFromSamples(k.samples[c], true, k.unit[c]);
        s.EndRun(SnakeStop::Converged); // as a Run that converged there
        shrank += ValleyLoop<CMeshO>::PolyLength(s.PolylinePositions()) <
                  PartBoundaryEnd<CMeshO>::Param().seededShrink * ValleyLoop<CMeshO>::PolyLength(k.seeded[c].loop);
        state.ResumeTiming();
        replaced += PartBoundaryEnd<CMeshO>::FinishRun(s, FeatureEnergyType::PartBoundary, false, k.par, with ? &k.seeded[c] : nullptr);
    }
    state.counters["faces"] = k.m.fn;
    state.counters["samples"] = double(k.samples[c].size());
    state.counters["shrank"] = double(shrank) / state.iterations(); // 1: the seeded search runs when given
    state.counters["replaced"] = double(replaced) / state.iterations();
}

/// The short part of tests/test_part_boundary.cpp
/// (ValleyLoop.SearchesFromTheSeedsTowardsTheBodyWhenTheLoopShrankOntoAShortPartsTip), its loop
/// seeded 2 tube rings up (0.2 units of the part's 0.3) and the loop that shrank onto its tip,
/// repeated with a length unit 1.5 x the Run's: no band round the seeded loop holds a ring, so
/// the Run's end searches from the seeds' ring towards the body. The body below z = -1 (half
/// the mesh, far from the part) is midpoint-subdivided until the mesh has `faces` faces: what
/// grows with the mesh rather than with the part.
struct StubCase
{
    CMeshO m;
    std::shared_ptr<SnakeSurface<CMeshO>> surf;
    std::vector<SnakeSample> samples;
    double unit = 0;
    PartBoundaryEnd<CMeshO>::Seeded seeded;
    bool towardBody = false; // the seeded loop's search empty after the loop shrank: TowardBody's path
    PartBoundaryEnd<CMeshO>::Param par; // with the mesh's measures (PartBoundaryEnd::Measured), as a host's
};

/// Splits the edges with both ends below z = -1.
struct LowerBodyEdge
{
    bool operator()(vcg::face::Pos<CFaceO> ep) const { return ep.V()->cP()[2] < -1 && ep.VFlip()->cP()[2] < -1; }
};

StubCase &Stub(int faces)
{
    static std::map<int, std::unique_ptr<StubCase>> cases;
    std::unique_ptr<StubCase> &k = cases[faces];
    if (k) return *k;
    k.reset(new StubCase);
    CMeshO &m = k->m;
    const int n = 12;
    const std::vector<int> ring = gs_test::MakeStubOnBody(m, n, 0.1);
    while (m.fn < faces) {
        vcg::tri::UpdateTopology<CMeshO>::FaceFace(m);
        vcg::tri::MidPoint<CMeshO> mid(&m);
        LowerBodyEdge lower;
        if (!vcg::tri::RefineE(m, mid, lower)) break;
    }
    gs_test::EnableSnakeAdjacency(m);
    vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFace(m);
    for (auto &v : m.vert) v.Q() = 0.5;
    k->surf = std::make_shared<SnakeSurface<CMeshO>>(m, 0); // the energy: the vertices' quality
    k->par = PartBoundaryEnd<CMeshO>::Measured(m, PartBoundaryEnd<CMeshO>::Param());
    std::vector<int> seeds;
    for (int i = 0; i < n; i += 2) seeds.push_back(ring[2] + i);
    GeometricSnake<CMeshO> t(k->surf);
    t.InitFromSeeds(seeds, true);
    k->seeded = PartBoundaryEnd<CMeshO>::Seeded::Of(t);
    t.Run(400);
    k->samples = t.Samples(), k->unit = 1.5 * t.LengthScale();
    GeometricSnake<CMeshO> s(k->surf);
    s.InitFromSamples(k->samples, true, k->unit);
    const auto own = PartBoundaryEnd<CMeshO>::Seeded::Of(s);
    const PartBoundaryEnd<CMeshO>::Param par;
    double r1 = -1, c1 = 0, r2 = -1, c2 = 0;
    const auto &e = k->surf->Energy();
    const bool ownEmpty = PartBoundaryEnd<CMeshO>::FinishFrom(m, own.loop, own.faces, e, k->unit, par, r1, c1).empty();
    const bool seededEmpty = PartBoundaryEnd<CMeshO>::FinishFrom(m, k->seeded.loop, k->seeded.faces, e, k->unit, par, r2, c2).empty();
    const double L0 = ValleyLoop<CMeshO>::PolyLength(k->seeded.loop), L1 = ValleyLoop<CMeshO>::PolyLength(own.loop);
    k->towardBody = seededEmpty && (L1 < par.seededShrink * L0 || ownEmpty);
    std::fprintf(stderr, "stub case on %d faces: seeded %.3f long, shrank to %.3f; valley loop round it %s, round the "
                         "seeded loop %s\n", m.fn, L0, L1, ownEmpty ? "none" : "found", seededEmpty ? "none" : "found");
    return *k;
}

/// The Run's end down TowardBody's path (PartBoundaryEnd::FinishRun, session 27); arg: the
/// mesh's faces at least (0: the test's mesh, 984 faces).
void BM_PartEndTowardBody(benchmark::State &state)
{
    StubCase &k = Stub(int(state.range(0)));
    GeometricSnake<CMeshO> s(k.surf);
    int replaced = 0;
    double zMax = 0;
    for (auto _ : state) {
        state.PauseTiming();
        s.InitFromSamples(k.samples, true, k.unit);
        s.EndRun(SnakeStop::Converged); // as a Run that converged there
        state.ResumeTiming();
        replaced += PartBoundaryEnd<CMeshO>::FinishRun(s, FeatureEnergyType::PartBoundary, false, k.par, &k.seeded);
        state.PauseTiming();
        for (const auto &x : s.PolylinePositions()) zMax = std::max(zMax, std::fabs(x[2]));
        state.ResumeTiming();
    }
    state.counters["faces"] = k.m.fn;
    state.counters["towardBody"] = k.towardBody; // 1: the path measured is TowardBody's
    state.counters["replaced"] = double(replaced) / state.iterations();
    state.counters["zMax"] = zMax; // 0: the loop ends on the part's base ring
}

} // namespace

BENCHMARK(BM_PickGrid)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK(BM_Prepare)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(BM_Click)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(40);
BENCHMARK(BM_Build)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(5);
BENCHMARK(BM_BuildCold)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(BM_ValleyLoop)->Args({0, 0})->Args({1200000, 0})->Args({0, 1})->Args({1200000, 1})->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(10);
BENCHMARK(BM_RunEndMeasures)->Args({0, 0})->Args({1200000, 0})->Args({0, 1})->Args({1200000, 1})->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(10);
BENCHMARK(BM_ValleyLoopSeeded)->Args({0, 0})->Args({0, 1})->Args({1, 0})->Args({1, 1})->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(10);
BENCHMARK(BM_PartEndTowardBody)->Arg(0)->Arg(100000)->Arg(1200000)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(10);

BENCHMARK_MAIN();
