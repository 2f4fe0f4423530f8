// The paper's Table 1 today, and the scaling with mesh size (issue 5).
//
// BM_Table1/mesh:M/samples:N/method:K   one snake operation (embedding + 5 updates) of a
//     closed N-sample snake on the mesh standing in for the paper's model M:
//       0 man (skull, 100 samples)  1 mannequin-devil (Buddha, 91)  2 bunny00 (bunny, 117)
//       3 lion-head (mask, 288); method 0 = local embedding (the paper), 1 = 3D update + projection.
//     The first 200 operations from the initial curve. Counters: vertices, faces, samples,
//     ms_per_embedding (one segment region, median), embeddings_per_op, ops_per_embedding (segment
//     moves one embedding serves: embeddings are kept while the samples stay inside, Sec. 4.2),
//     ms_embedding_per_op (embedding time per operation, mean), ms_per_update (median),
//     ms_per_operation (mean: embeddings amortized over the operations they serve).
// BM_Convergence/mesh/samples/method   from the initial curve to convergence (Run(300)):
//     operations, converged, mean energy of the samples (lower = closer to a feature).
// BM_Scaling/level:L                   man.off midpoint-subdivided L times (35k, 140k, 560k,
//     2.24M faces): load_s (binary PLY), prep_s (adjacency + normal-variation energy with 2
//     smoothing steps + snake surface with capture smoothing 8), ms_per_operation (mean of the first
//     100 operations) of the same 100-sample snake.
//
// Run with --benchmark_repetitions=3 (or more) and read the medians; scripts/eval.sh does.

#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>

#include <snake_bench_util.h>

namespace {

using namespace vcg::tri;
typedef GeometricSnake<CMeshO> Snake;
typedef std::chrono::steady_clock Clock;

double SecondsSince(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

struct PaperRow
{
    const char *file, *paperModel;
    int samples;
};
const PaperRow kRows[] = {{"man", "skull", 100}, {"mannequin-devil", "Buddha", 91}, {"bunny00", "bunny", 117},
                          {"lion-head", "mask", 288}};

struct Scene
{
    CMeshO mesh;
    std::shared_ptr<SnakeSurface<CMeshO>> surf;
};

void Prepare(Scene &s)
{
    gs_test::EnableSnakeAdjacency(s.mesh);
    FeatureEnergy<CMeshO>::Compute(s.mesh, FeatureEnergyType::NormalVariation, 2);
    s.surf = std::make_shared<SnakeSurface<CMeshO>>(s.mesh);
}

Scene &GetScene(int idx)
{
    static std::map<int, std::unique_ptr<Scene>> scenes;
    auto &s = scenes[idx];
    if (!s) {
        s.reset(new Scene);
        const std::string path = std::string(GS_SHARED_MESH_DIR) + "/" + kRows[idx].file + ".off";
        if (!gs_test::LoadMesh(s->mesh, path)) {
            std::fprintf(stderr, "cannot load %s\n", path.c_str());
            std::exit(1);
        }
        Prepare(*s);
    }
    return *s;
}

std::unique_ptr<Snake> MakeLoop(Scene &sc, int samples, SnakeMethod method)
{
    return gs_test::MakeSnakeLoop(sc.mesh, sc.surf, samples, method);
}

void Report(benchmark::State &state, Snake &s, const CMeshO &m)
{
    const SnakeStats &st = s.Stats();
    const double ops = std::max(1, st.operations);
    auto sum = [](const std::vector<double> &v) { double t = 0; for (double x : v) t += x; return t; };
    state.counters["vertices"] = m.vn;
    state.counters["faces"] = m.fn;
    state.counters["samples"] = s.SampleCount();
    state.counters["ms_per_embedding"] = SnakeStats::Median(st.msEmbedding);
    state.counters["embeddings_per_op"] = st.embeddings / ops;
    state.counters["ops_per_embedding"] = st.embeddings ? double(st.embeddings + st.reuses) / st.embeddings : 0;
    state.counters["ms_embedding_per_op"] = sum(st.msEmbedding) / ops;
    state.counters["ms_per_update"] = SnakeStats::Median(st.msUpdate);
    state.counters["updates_per_op"] = st.updates / ops;
    state.counters["ms_per_operation"] = sum(st.msOperation) / ops;
}

void BM_Table1(benchmark::State &state)
{
    const int idx = int(state.range(0));
    Scene &sc = GetScene(idx);
    auto s = MakeLoop(sc, int(state.range(1)), SnakeMethod(state.range(2)));
    for (auto _ : state) benchmark::DoNotOptimize(s->Step());
    Report(state, *s, sc.mesh);
    state.SetLabel(std::string(kRows[idx].file) + " (" + kRows[idx].paperModel + ")");
}

void BM_Convergence(benchmark::State &state)
{
    const int idx = int(state.range(0));
    Scene &sc = GetScene(idx);
    gs_bench::MeasureConvergence(state, sc.mesh, sc.surf, int(state.range(1)), SnakeMethod(state.range(2)), 300);
    state.SetLabel(std::string(kRows[idx].file) + " (" + kRows[idx].paperModel + ")");
}

// The subdivided meshes are written once as binary PLY to the temp dir, so that "load" is the
// time to read a mesh of that size from disk.
std::string ScalingFile(int level)
{
    const char *tmp = std::getenv("TMPDIR");
    std::string path = std::string(tmp && *tmp ? tmp : "/tmp") + "/gs_scaling_man_" + std::to_string(level) + ".ply";
    if (FILE *f = std::fopen(path.c_str(), "rb")) {
        std::fclose(f);
        return path;
    }
    CMeshO m;
    gs_test::LoadMesh(m, std::string(GS_SHARED_MESH_DIR) + "/man.off");
    int target = m.fn;
    for (int i = 0; i < level; ++i) target *= 4;
    if (level > 0) gs_test::Subdivide(m, target);
    if (!gs_test::SaveMesh(m, path)) {
        std::fprintf(stderr, "cannot write %s\n", path.c_str());
        std::exit(1);
    }
    return path;
}

void BM_Scaling(benchmark::State &state)
{
    const std::string path = ScalingFile(int(state.range(0)));
    double load = 0, prep = 0, msOp = 0, faces = 0, samples = 0;
    for (auto _ : state) {
        Scene sc;
        auto t0 = Clock::now();
        if (!gs_test::LoadMesh(sc.mesh, path)) {
            state.SkipWithError("cannot load the subdivided mesh");
            return;
        }
        load = SecondsSince(t0);
        t0 = Clock::now();
        Prepare(sc);
        prep = SecondsSince(t0);
        auto s = MakeLoop(sc, 100, SnakeMethod::LocalEmbedding);
        for (int i = 0; i < 100; ++i) s->Step();
        msOp = 0;
        for (double ms : s->Stats().msOperation) msOp += ms;
        msOp /= s->Stats().operations;
        faces = sc.mesh.fn;
        samples = s->SampleCount();
    }
    state.counters["faces"] = faces;
    state.counters["samples"] = samples;
    state.counters["load_s"] = load;
    state.counters["prep_s"] = prep;
    state.counters["ms_per_operation"] = msOp;
}

} // namespace

// args: mesh (0 man, 1 mannequin-devil, 2 bunny00, 3 lion-head), samples, method
BENCHMARK(BM_Table1)
    ->ArgNames({"mesh", "samples", "method"})
    ->Args({0, 100, 0})->Args({1, 91, 0})->Args({2, 117, 0})->Args({3, 288, 0})
    ->Args({0, 100, 1})->Args({1, 91, 1})->Args({2, 117, 1})->Args({3, 288, 1})
    ->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(200);
BENCHMARK(BM_Convergence)
    ->ArgNames({"mesh", "samples", "method"})
    ->Args({0, 100, 0})->Args({1, 91, 0})->Args({2, 117, 0})->Args({3, 288, 0})
    ->Args({0, 100, 1})->Args({1, 91, 1})->Args({2, 117, 1})->Args({3, 288, 1})
    ->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(BM_Scaling)
    ->ArgNames({"level"})->DenseRange(0, 3)
    ->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

BENCHMARK_MAIN();
