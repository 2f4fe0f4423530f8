// Feature energy (Sec. 6) timing on bunny00 subdivided to ~1M faces. Goal: normal-variation
// energy (no smoothing) <= 0.5 s at 1M faces.

#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <memory>

#include <common/ml_mesh_type.h>

#include "generated_meshes.h"
#include "snake_bench_util.h"
#include "vcg_ext/energy/feature_energy.h"
#include "vcg_ext/paths/seed_path.h"

namespace {

using vcg::tri::FeatureEnergyType;
typedef vcg::tri::FeatureEnergy<CMeshO> FE;

// As a plain MeshLab layer: no optional component needed.
CMeshO &BigBunny()
{
    static CMeshO &m = [] () -> CMeshO & {
        CMeshO &b = gs_bench::SubdividedBunny(1000000);
        b.face.DisableFFAdjacency();
        return b;
    }();
    return m;
}

void BM_Energy(benchmark::State &state, FeatureEnergyType type, int steps)
{
    CMeshO &m = BigBunny();
    for (auto _ : state) {
        FE::Stats st = FE::Compute(m, type, steps);
        benchmark::DoNotOptimize(st);
    }
    state.counters["faces"] = m.fn;
}

void BM_FaceGradients(benchmark::State &state)
{
    CMeshO &m = BigBunny();
    FE::Compute(m, FeatureEnergyType::NormalVariation, 0);
    for (auto _ : state) {
        auto g = FE::FaceGradients(m);
        benchmark::DoNotOptimize(g.data());
    }
}

void BM_Inspect(benchmark::State &state)
{
    CMeshO &m = BigBunny();
    for (auto _ : state) {
        auto r = vcg::tri::MeshValidation<CMeshO>::Inspect(m);
        benchmark::DoNotOptimize(r);
    }
}

void BM_SeedPathShort(benchmark::State &state)
{
    // Two vertices ~30 edge lengths apart: A* should stay local, cost dominated by the O(F) adjacency table.
    CMeshO &m = BigBunny();
    const double L = vcg::tri::MeshValidation<CMeshO>::MeanEdgeLength(m);
    int b = -1;
    for (size_t i = 1; i < m.vert.size() && b < 0; ++i) {
        const double d = vcg::Distance(m.vert[i].cP(), m.vert[0].cP());
        if (d > 30 * L && d < 35 * L) b = int(i);
    }
    if (b < 0) {
        state.SkipWithError("no vertex at the wanted distance");
        return;
    }
    for (auto _ : state) {
        auto r = vcg::tri::SeedPath<CMeshO>::Compute(m, {0, b}, false);
        benchmark::DoNotOptimize(r.length);
    }
}

#define GS_ENERGY_BENCH(name, type, steps)                                                                            \
    BENCHMARK_CAPTURE(BM_Energy, name, type, steps)                                                                   \
        ->Unit(benchmark::kMillisecond)                                                                              \
        ->Iterations(3)                                                                                              \
        ->Repetitions(3)                                                                                             \
        ->ReportAggregatesOnly(true)

GS_ENERGY_BENCH(NormalVariation_0, FeatureEnergyType::NormalVariation, 0);
GS_ENERGY_BENCH(NormalVariation_10, FeatureEnergyType::NormalVariation, 10);
GS_ENERGY_BENCH(CurvatureNorm_0, FeatureEnergyType::CurvatureNorm, 0);
GS_ENERGY_BENCH(QuadricError_0, FeatureEnergyType::QuadricError, 0);
// The crease energy (dihedral angles, then each face's nearest creases through vcglib's grid).
GS_ENERGY_BENCH(Crease_2, FeatureEnergyType::Crease, 2);
// The part-boundary energy (issue 33): a quadric fitted over 3 local edge lengths per vertex.
GS_ENERGY_BENCH(PartBoundary_2, FeatureEnergyType::PartBoundary, 2);
BENCHMARK(BM_FaceGradients)->Unit(benchmark::kMillisecond)->Iterations(3)->Repetitions(3)->ReportAggregatesOnly(true);
BENCHMARK(BM_Inspect)->Unit(benchmark::kMillisecond)->Iterations(3)->Repetitions(3)->ReportAggregatesOnly(true);
BENCHMARK(BM_SeedPathShort)->Unit(benchmark::kMillisecond)->Iterations(3)->Repetitions(3)->ReportAggregatesOnly(true);

} // namespace

BENCHMARK_MAIN();
