#ifndef GS_BENCH_SNAKE_BENCH_UTIL_H
#define GS_BENCH_SNAKE_BENCH_UTIL_H

// Shared by the snake benchmarks: time from the initial curve to convergence, with the
// counters that make two methods comparable (operations, converged, mean sample energy).

#include <benchmark/benchmark.h>

#include <snake_test_util.h>

namespace gs_bench {

inline void MeasureConvergence(benchmark::State &state, CMeshO &mesh,
                               std::shared_ptr<vcg::tri::SnakeSurface<CMeshO>> surf, int samples,
                               vcg::tri::SnakeMethod method, int maxOps)
{
    double ops = 0, energy = 0, converged = 0;
    for (auto _ : state) {
        state.PauseTiming();
        auto s = gs_test::MakeSnakeLoop(mesh, surf, samples, method);
        state.ResumeTiming();
        converged = s->Run(maxOps) ? 1 : 0;
        state.PauseTiming();
        ops = s->Stats().operations;
        energy = 0;
        for (auto &x : s->Samples()) energy += surf->EnergyAt(0, x.p);
        energy /= s->SampleCount();
        state.ResumeTiming();
    }
    state.counters["operations"] = ops;
    state.counters["converged"] = converged;
    state.counters["mean_sample_energy"] = energy;
}

} // namespace gs_bench

#endif
