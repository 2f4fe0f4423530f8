// Geometric snake speed (paper Table 1, today): ms per embedding, per update and per
// operation (embedding + 5 updates) for the embedding method and the naive 3D-update +
// projection method, on bunny00 (the paper's bunny size) with 100- and 300-sample snakes;
// time to convergence of both; and the same operation on bunny00 subdivided to ~1M faces,
// to show that the cost of an operation does not grow with the mesh.
//
// Figures are printed as counters. Run with --benchmark_repetitions=5 and read the medians.

#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>

#include <snake_bench_util.h>

namespace {

using namespace vcg::tri;
typedef GeometricSnake<CMeshO> Snake;

struct Scene
{
    CMeshO mesh;
    std::shared_ptr<SnakeSurface<CMeshO>> surf;
    double prepSeconds = 0;
};

// bunny00 (level 0) or its midpoint subdivision to >= 1M faces (level 1); loaded once.
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
        if (level > 0) gs_test::Subdivide(s->mesh, 1000000);
        auto t0 = std::chrono::steady_clock::now();
        gs_test::EnableSnakeAdjacency(s->mesh);
        FeatureEnergy<CMeshO>::Compute(s->mesh, FeatureEnergyType::NormalVariation, 2);
        s->surf = std::make_shared<SnakeSurface<CMeshO>>(s->mesh);
        s->prepSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        std::fprintf(stderr, "bunny00 level %d: %d vertices, %d faces, preprocessing %.2f s\n", level, s->mesh.vn,
                     s->mesh.fn, s->prepSeconds);
    }
    return *s;
}

std::unique_ptr<Snake> MakeLoop(Scene &sc, int samples, SnakeMethod method)
{
    return gs_test::MakeSnakeLoop(sc.mesh, sc.surf, samples, method);
}

void Report(benchmark::State &state, Snake &s)
{
    const SnakeStats &st = s.Stats();
    state.counters["samples"] = s.SampleCount();
    state.counters["ms_per_embedding"] = SnakeStats::Median(st.msEmbedding);
    state.counters["ms_per_update"] = SnakeStats::Median(st.msUpdate);
    state.counters["ms_per_operation"] = SnakeStats::Median(st.msOperation);
    state.counters["embeddings_per_op"] = st.operations ? double(st.embeddings) / st.operations : 0;
}

// One snake operation (Sec. 4.3), steady state.
void BM_Operation(benchmark::State &state)
{
    Scene &sc = GetScene(int(state.range(2)));
    auto s = MakeLoop(sc, int(state.range(0)), SnakeMethod(state.range(1)));
    for (auto _ : state) benchmark::DoNotOptimize(s->Step());
    Report(state, *s);
    state.counters["faces"] = sc.mesh.fn;
}

// From the initial curve to convergence; also the final mean energy of the samples, so the
// two methods are compared at equal accuracy.
void BM_Convergence(benchmark::State &state)
{
    Scene &sc = GetScene(int(state.range(2)));
    gs_bench::MeasureConvergence(state, sc.mesh, sc.surf, int(state.range(0)), SnakeMethod(state.range(1)), 2000);
}

} // namespace

// args: samples, method (0 embedding, 1 projection), mesh level (0 bunny00, 1 ~1M faces)
BENCHMARK(BM_Operation)
    ->ArgNames({"samples", "method", "mesh"})
    ->Args({100, 0, 0})->Args({300, 0, 0})->Args({100, 1, 0})->Args({300, 1, 0})
    ->Args({100, 0, 1})->Args({300, 0, 1})
    ->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(0.5);
BENCHMARK(BM_Convergence)
    ->ArgNames({"samples", "method", "mesh"})
    ->Args({100, 0, 0})->Args({100, 1, 0})->Args({300, 0, 0})->Args({300, 1, 0})
    ->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

BENCHMARK_MAIN();
