// Geometric snake speed (issue 12): one operation and the time to convergence of the paper's
// method (local embeddings, Sec. 4.2 and 5) and of the naive one (3D update + projection), on
// bunny00 (the paper's bunny size) and on its midpoint subdivision to 1.2M faces, for closed
// loops of about 100 and 300 samples and for open snakes from seeds.
//
// BM_Operation/samples/method/mesh/closed   the first 200 operations from the initial curve
//     (Time = mean ms per operation): ms_per_operation (the same mean), embeddings_per_op,
//     ops_per_embedding (segment moves one embedding serves), faces, preprocess_s (adjacency
//     beside the feature energy, as the snake filter does, then the snake surface; once per
//     mesh), first_op_ms (the first operation of the first snake on that mesh: it computes the
//     coarse energy levels around the snake).
// BM_Convergence/samples/method/mesh/closed  from the initial curve to convergence: operations,
//     mean_sample_energy and dist_to_reference (mean distance of the samples to the curve the
//     paper's method reaches with a 10x tighter tolerance, in local edge lengths) beside the time.
// BM_Ratio/samples/closed   both methods to convergence in one iteration: speedup = time of
//     3D update + projection / time of the embedding method, measured in the same run.
//
// BM_StallTest/closed/stall  the stall test's cost (SnakeRunControl::Param::stall, session 29):
//     a 100-sample snake on bunny00 operated (untimed) until it slithers on level 0 and the
//     test's window (2 x convergenceWindow + 1 operations) is full, then `Iterations` level-0
//     operations timed with the test on (1) or off (0); the operations are the same either way
//     (the test only ends a Run). Time = CPU ms per operation (other processes share the
//     cores); ops_before_level0: the untimed operations on the coarse levels.
//
// method 0 = local embedding (the paper), 1 = 3D update + projection; mesh 0 = bunny00, 1 = 1.2M
// faces; closed 1 = loop, 0 = open snake from 5 seeds. Run with --benchmark_repetitions=5 and read
// the medians (scripts/eval.sh does).

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>

#include <snake_bench_util.h>
#include <vcg_ext/energy/energy_source.h>

namespace {

using namespace vcg::tri;
typedef GeometricSnake<CMeshO> Snake;

struct Scene
{
    CMeshO mesh;
    std::shared_ptr<SnakeSurface<CMeshO>> surf;
    double prepSeconds = 0;
    double firstOpMs = 0; // the first operation of a snake there, coarse energy levels computed on the way
};

// bunny00 (level 0) or its midpoint subdivision to >= 1.2M faces (level 1); loaded once.
Scene &GetScene(int level)
{
    static std::map<int, std::unique_ptr<Scene>> scenes;
    auto &s = scenes[level];
    if (!s) {
        s.reset(new Scene);
        const std::string path = std::string(GS_SHARED_MESH_DIR) + "/bunny00.off";
        if (!gs_test::LoadMesh(s->mesh, path)) {
            std::fprintf(stderr, "cannot load %s\n", path.c_str());
            std::exit(1);
        }
        if (level > 0) gs_test::Subdivide(s->mesh, 1200000);
        typedef std::chrono::steady_clock clk;
        auto sec = [](clk::time_point a, clk::time_point b) { return std::chrono::duration<double>(b - a).count(); };
        const auto t0 = clk::now();
        // As the snake filter and the CLI do: the adjacency is built while the energy is computed.
        SnakeEnergySource<CMeshO> energy(s->mesh);
        energy.SetSettings(FeatureEnergyType::NormalVariation, 2);
        double adjacency = 0;
        energy.ComputeBeside([&] {
            const auto a = clk::now();
            gs_test::EnableSnakeAdjacency(s->mesh);
            adjacency = sec(a, clk::now());
        });
        const auto t2 = clk::now();
        s->surf = energy.EnsureSurface();
        const auto t3 = clk::now();
        s->prepSeconds = sec(t0, t3);
        // the coarse energy levels are computed where snakes first read them: the first
        // operation of a snake pays for its neighbourhood (later snakes there do not)
        auto first = gs_test::MakeSnakeCurve(s->mesh, s->surf, 100, SnakeMethod::LocalEmbedding, true);
        const auto t4 = clk::now();
        first->Step();
        s->firstOpMs = 1000 * sec(t4, clk::now());
        std::fprintf(stderr,
                     "bunny00 level %d: %d vertices, %d faces, preprocessing %.3f s (adjacency %.3f beside the energy, "
                     "both %.3f; surface %.3f); first operation of the first snake %.1f ms\n",
                     level, s->mesh.vn, s->mesh.fn, s->prepSeconds, adjacency, sec(t0, t2), sec(t2, t3), s->firstOpMs);
    }
    return *s;
}

// One snake operation (Sec. 4.3): the first 200 operations from the initial curve.
void BM_Operation(benchmark::State &state)
{
    Scene &sc = GetScene(int(state.range(2)));
    auto s = gs_test::MakeSnakeCurve(sc.mesh, sc.surf, int(state.range(0)), SnakeMethod(state.range(1)), state.range(3) != 0);
    for (auto _ : state) benchmark::DoNotOptimize(s->Step());
    const SnakeStats &st = s->Stats();
    double total = 0;
    for (double ms : st.msOperation) total += ms;
    state.counters["samples"] = s->SampleCount();
    state.counters["ms_per_operation"] = st.operations ? total / st.operations : 0;
    state.counters["embeddings_per_op"] = st.operations ? double(st.embeddings) / st.operations : 0;
    state.counters["ops_per_embedding"] = st.embeddings ? double(st.embeddings + st.reuses) / st.embeddings : 0;
    state.counters["faces"] = sc.mesh.fn;
    state.counters["preprocess_s"] = sc.prepSeconds;
    state.counters["first_op_ms"] = sc.firstOpMs;
}

// From the initial curve to convergence, with the final accuracy beside the time.
void BM_Convergence(benchmark::State &state)
{
    Scene &sc = GetScene(int(state.range(2)));
    gs_bench::MeasureConvergence(state, sc.mesh, sc.surf, int(state.range(0)), SnakeMethod(state.range(1)), 3000,
                                 state.range(3) != 0);
}

// Both methods to convergence back to back, so that their ratio comes from one time window.
void BM_Ratio(benchmark::State &state)
{
    Scene &sc = GetScene(0);
    const int samples = int(state.range(0));
    const bool closed = state.range(1) != 0;
    double tEmb = 0, tProj = 0;
    for (auto _ : state) {
        for (int method = 0; method < 2; ++method) {
            auto s = gs_test::MakeSnakeCurve(sc.mesh, sc.surf, samples, SnakeMethod(method), closed);
            auto t0 = std::chrono::steady_clock::now();
            s->Run(3000);
            const double t = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
            (method == 0 ? tEmb : tProj) += t;
        }
    }
    state.counters["ms_embedding"] = tEmb / state.iterations();
    state.counters["ms_projection"] = tProj / state.iterations();
    state.counters["speedup"] = tEmb > 0 ? tProj / tEmb : 0;
}

// BM_StallTest's timed operation, a function of its own so that callgrind counts it alone:
// valgrind --tool=callgrind --collect-atstart=no --toggle-collect='*StallTimedStep*'
#if defined(__GNUC__)
__attribute__((noinline))
#endif
double StallTimedStep(Snake &s)
{
    return s.Step();
}

// The stall test on or off over the same level-0 operations (see the top of the file).
void BM_StallTest(benchmark::State &state)
{
    Scene &sc = GetScene(0);
    auto s = gs_test::MakeSnakeCurve(sc.mesh, sc.surf, 100, SnakeMethod::LocalEmbedding, state.range(0) != 0);
    s->RunParam().stall = state.range(1) != 0;
    int before = 0;
    while (s->EnergyStage() > 0 && before < 3000) s->Step(), ++before;
    for (int k = 0; k < 2 * s->Params().convergenceWindow + 1; ++k) s->Step();
    if (s->EnergyStage() != 0) state.SkipWithError("the snake did not reach level 0");
    for (auto _ : state) benchmark::DoNotOptimize(StallTimedStep(*s));
    state.counters["samples"] = s->SampleCount();
    state.counters["ops_before_level0"] = before;
}

} // namespace

// args: samples, method (0 embedding, 1 projection), mesh (0 bunny00, 1 1.2M faces), closed
BENCHMARK(BM_Operation)
    ->ArgNames({"samples", "method", "mesh", "closed"})
    ->Args({100, 0, 0, 1})->Args({300, 0, 0, 1})->Args({100, 0, 0, 0})
    ->Args({100, 1, 0, 1})->Args({300, 1, 0, 1})
    ->Args({100, 0, 1, 1})->Args({300, 0, 1, 1})->Args({100, 0, 1, 0})
    ->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(200);
BENCHMARK(BM_Convergence)
    ->ArgNames({"samples", "method", "mesh", "closed"})
    ->Args({100, 0, 0, 1})->Args({100, 1, 0, 1})->Args({300, 0, 0, 1})->Args({300, 1, 0, 1})
    ->Args({100, 0, 0, 0})->Args({100, 1, 0, 0})
    ->Args({100, 0, 1, 1})->Args({300, 0, 1, 1})
    ->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(BM_StallTest)
    ->ArgNames({"closed", "stall"})
    ->Args({0, 0})->Args({0, 1})->Args({1, 0})->Args({1, 1})
    ->Unit(benchmark::kMillisecond)->Iterations(100)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(BM_Ratio)
    ->ArgNames({"samples", "closed"})
    ->Args({100, 1})->Args({300, 1})->Args({100, 0})
    ->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

BENCHMARK_MAIN();
