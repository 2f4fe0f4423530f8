#ifndef GS_BENCH_SNAKE_BENCH_UTIL_H
#define GS_BENCH_SNAKE_BENCH_UTIL_H

// Shared by the snake benchmarks: time from the initial curve to convergence, with the
// counters that make two methods comparable (operations, converged, mean sample energy, and
// the distance to a reference curve).

#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <string>
#include <tuple>

#include <snake_test_util.h>

namespace gs_bench {

/// bunny00 of the shared meshes subdivided to at least `faces` faces (gs_test::Subdivide): the
/// million-face mesh of the speed goals. Loaded once per size, not timed; exits if it is missing.
inline CMeshO &SubdividedBunny(int faces)
{
    static std::map<int, std::unique_ptr<CMeshO>> meshes;
    std::unique_ptr<CMeshO> &m = meshes[faces];
    if (!m) {
        m.reset(new CMeshO);
        const std::string path = std::string(GS_SHARED_MESH_DIR) + "/bunny00.off";
        if (!gs_test::LoadMesh(*m, path)) {
            std::fprintf(stderr, "cannot load %s\n", path.c_str());
            std::exit(1);
        }
        gs_test::Subdivide(*m, faces);
        std::fprintf(stderr, "bunny00 subdivided: %d vertices, %d faces\n", m->vn, m->fn);
    }
    return *m;
}

/// Mean distance (in the snake's length unit) of the samples to a polyline.
inline double MeanDistance(const std::vector<vcg::Point3d> &pts, const std::vector<vcg::Point3d> &line, double unit)
{
    if (pts.empty() || line.size() < 2) return 0;
    double sum = 0;
    for (const auto &p : pts) {
        double best = 1e300;
        for (size_t i = 0; i + 1 < line.size(); ++i) {
            const vcg::Point3d d = line[i + 1] - line[i];
            const double L2 = d.SquaredNorm();
            const double t = L2 > 0 ? std::max(0.0, std::min(1.0, ((p - line[i]) * d) / L2)) : 0.0;
            best = std::min(best, (p - (line[i] + d * t)).Norm());
        }
        sum += best;
    }
    return sum / double(pts.size()) / unit;
}

/// The reference curve of a benchmark snake: the paper's method run to a 10x tighter
/// convergence tolerance (the final curve both methods should reach), computed once.
inline const std::vector<vcg::Point3d> &ReferenceCurve(CMeshO &mesh, std::shared_ptr<vcg::tri::SnakeSurface<CMeshO>> surf,
                                                       int samples, bool closed)
{
    static std::map<std::tuple<const CMeshO *, int, bool>, std::vector<vcg::Point3d>> refs;
    auto &r = refs[std::make_tuple(&mesh, samples, closed)];
    if (r.empty()) {
        auto s = gs_test::MakeSnakeCurve(mesh, surf, samples, vcg::tri::SnakeMethod::LocalEmbedding, closed);
        vcg::tri::SnakeParams p = s->Params();
        p.convergenceTol *= 0.1;
        s->SetParams(p);
        s->Run(5000);
        r = s->PolylinePositions();
        if (closed && !r.empty()) r.push_back(r.front());
    }
    return r;
}

inline void MeasureConvergence(benchmark::State &state, CMeshO &mesh,
                               std::shared_ptr<vcg::tri::SnakeSurface<CMeshO>> surf, int samples,
                               vcg::tri::SnakeMethod method, int maxOps, bool closed = true)
{
    const std::vector<vcg::Point3d> &ref = ReferenceCurve(mesh, surf, samples, closed);
    double ops = 0, energy = 0, converged = 0, dist = 0, n = 0, emb = 0, reuse = 0;
    for (auto _ : state) {
        state.PauseTiming();
        auto s = gs_test::MakeSnakeCurve(mesh, surf, samples, method, closed);
        state.ResumeTiming();
        converged = s->Run(maxOps) ? 1 : 0;
        state.PauseTiming();
        ops = s->Stats().operations;
        emb = s->Stats().embeddings;
        reuse = s->Stats().reuses;
        energy = 0;
        for (auto &x : s->Samples()) energy += surf->EnergyAt(0, x.p);
        energy /= s->SampleCount();
        n = s->SampleCount();
        std::vector<vcg::Point3d> pts;
        for (auto &x : s->Samples()) pts.push_back(x.p.Pd(mesh));
        dist = MeanDistance(pts, ref, s->LengthScale());
        state.ResumeTiming();
    }
    state.counters["samples"] = n;
    state.counters["operations"] = ops;
    state.counters["converged"] = converged;
    state.counters["mean_sample_energy"] = energy;
    state.counters["dist_to_reference"] = dist;
    if (emb > 0) state.counters["ops_per_embedding"] = (emb + reuse) / emb;
}

} // namespace gs_bench

#endif
