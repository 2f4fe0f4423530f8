// Cutting along a snake (issue 34): embedding a 1,000-sample loop into a 1.2M-face mesh and
// selecting one side, goal <= 0.5 s; the flood fill and the split, printed with the part's
// size for loops of growing radius, to show they grow with the part, not with the mesh.
//
//   build/bench/bench_mesh_cut --benchmark_repetitions=3 --benchmark_report_aggregates_only=true

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include <common/ml_mesh_type.h>

#include "generated_meshes.h"
#include "vcg_ext/cut/mesh_cut.h"
#include "vcg_ext/session/mesh_undo.h"

namespace {

using namespace vcg::tri;
const int kCells = 775; // 2 x 775^2 = 1,201,250 faces

CMeshO &Plate()
{
    static std::unique_ptr<CMeshO> m;
    if (!m) {
        m.reset(new CMeshO);
        gs_test::MakeFlatGrid(*m, kCells, 1.0);
        m->face.DisableFFAdjacency(); // a plain MeshLab layer
        std::fprintf(stderr, "plate: %d vertices, %d faces\n", m->vn, m->fn);
    }
    return *m;
}

/// The circle of `samples` points, radius r, centred on the plate, as a curve on it: the
/// samples and every edge crossing between them (MakeFlatGrid's faces: cell (i, j) holds
/// faces 2 (j n + i) = (a, b, c) and + 1 = (a, c, d)).
CutCurve Circle(const CMeshO &m, int samples, double r)
{
    const int n = kCells;
    const double h = 1.0 / n;
    CutCurve c;
    c.closed = true;
    auto faceHits = [&](int f, const vcg::Point2d &A, const vcg::Point2d &B, std::vector<std::pair<double, SurfacePoint>> &hits) {
        for (int k = 0; k < 3; ++k) {
            const vcg::Point2d P(m.face[f].cP(k)[0], m.face[f].cP(k)[1]), Q(m.face[f].cP((k + 1) % 3)[0], m.face[f].cP((k + 1) % 3)[1]);
            const vcg::Point2d d = B - A, e = Q - P, w = P - A;
            const double den = d[0] * e[1] - d[1] * e[0];
            if (std::abs(den) < 1e-300) continue;
            const double t = (w[0] * e[1] - w[1] * e[0]) / den, s = (w[0] * d[1] - w[1] * d[0]) / den;
            if (t > 0 && t < 1 && s >= 0 && s <= 1) {
                vcg::Point3d b(0, 0, 0);
                b[k] = 1 - s;
                b[(k + 1) % 3] = s;
                hits.push_back({t, SurfacePoint(f, b)});
            }
        }
    };
    auto locate = [&](const vcg::Point2d &x) {
        const int i = std::min(n - 1, int(x[0] / h)), j = std::min(n - 1, int(x[1] / h));
        const double fx = x[0] / h - i, fy = x[1] / h - j;
        if (fx >= fy) return SurfacePoint(2 * (j * n + i), vcg::Point3d(1 - fx, fx - fy, fy));
        return SurfacePoint(2 * (j * n + i) + 1, vcg::Point3d(1 - fy, fx, fy - fx));
    };
    std::vector<vcg::Point2d> pts;
    for (int s = 0; s < samples; ++s) {
        const double a = 2 * M_PI * (s + 0.37) / samples;
        pts.push_back(vcg::Point2d(0.5 + r * std::cos(a), 0.5 + r * std::sin(a)));
    }
    for (int s = 0; s < samples; ++s) {
        const vcg::Point2d A = pts[s], B = pts[(s + 1) % samples];
        std::vector<std::pair<double, SurfacePoint>> hits{{0, locate(A)}};
        const int i0 = int(std::min(A[0], B[0]) / h) - 1, i1 = int(std::max(A[0], B[0]) / h) + 1;
        const int j0 = int(std::min(A[1], B[1]) / h) - 1, j1 = int(std::max(A[1], B[1]) / h) + 1;
        for (int j = std::max(0, j0); j <= std::min(n - 1, j1); ++j)
            for (int i = std::max(0, i0); i <= std::min(n - 1, i1); ++i)
                for (int f : {2 * (j * n + i), 2 * (j * n + i) + 1}) faceHits(f, A, B, hits);
        std::sort(hits.begin(), hits.end(), [](const auto &x, const auto &y) { return x.first < y.first; });
        for (const auto &p : hits)
            if (c.points.empty() || (c.points.back().Pd(m) - p.second.Pd(m)).Norm() > 1e-12) c.points.push_back(p.second);
    }
    return c;
}

/// Radius (in plate widths) of a 1,000-sample loop whose samples are about `cells` cells apart.
double Radius(double cells) { return 1000 * cells / kCells / (2 * M_PI); }

void BM_EmbedAndSelect(benchmark::State &state)
{
    CMeshO &plate = Plate();
    const CutCurve c = Circle(plate, 1000, Radius(state.range(0) / 10.0));
    MeshCut<CMeshO>::Result r;
    std::vector<double> flood, embed;
    for (auto _ : state) {
        state.PauseTiming();
        CMeshO m;
        Append<CMeshO, CMeshO>::MeshCopy(m, plate);
        state.ResumeTiming();
        r = MeshCut<CMeshO>::Apply(m, {c}, MeshCut<CMeshO>::Param());
        state.PauseTiming();
        flood.push_back(r.msSides);
        embed.push_back(r.msEmbed);
        m.Clear(); // freeing the copy is not timed
        state.ResumeTiming();
    }
    std::sort(flood.begin(), flood.end());
    std::sort(embed.begin(), embed.end());
    state.counters["faces"] = plate.fn;
    state.counters["curve_points"] = double(c.points.size());
    state.counters["part_faces"] = r.facesInside;
    state.counters["ms_embed"] = embed[embed.size() / 2];
    state.counters["ms_flood"] = flood[flood.size() / 2];
    state.counters["ms_check"] = r.msCheck;
    state.counters["ms_commit"] = r.msCommit;
}

void BM_Split(benchmark::State &state)
{
    CMeshO &plate = Plate();
    const CutCurve c = Circle(plate, 1000, Radius(state.range(0) / 10.0));
    MeshCut<CMeshO>::Result r;
    std::vector<double> split, flood, part[2];
    for (auto _ : state) {
        CMeshO in, out;
        r = MeshCut<CMeshO>::Split(plate, {c}, MeshCut<CMeshO>::Param(), in, out);
        state.PauseTiming();
        split.push_back(r.msSplit);
        flood.push_back(r.msSides);
        for (int k = 0; k < 2; ++k) part[k].push_back(r.msPart[k]);
        in.Clear();
        out.Clear();
        state.ResumeTiming();
    }
    auto median = [](std::vector<double> v) {
        std::sort(v.begin(), v.end());
        return v[v.size() / 2];
    };
    state.counters["faces"] = plate.fn;
    state.counters["part_faces"] = r.facesInside;
    state.counters["out_faces"] = r.facesOutside;
    state.counters["ms_flood"] = median(flood);
    state.counters["ms_split"] = median(split); // writing both parts (medians of the iterations)
    state.counters["ms_part_in"] = median(part[0]); // each part alone: grows with its faces
    state.counters["ms_part_out"] = median(part[1]);
    // per face of the part: about constant when the part's time is linear in its size
    state.counters["ns_per_face_in"] = median(part[0]) * 1e6 / std::max(1, r.facesInside);
    state.counters["ns_per_face_out"] = median(part[1]) * 1e6 / std::max(1, r.facesOutside);
}

/// The edit tool's second exact Select along a snake that keeps its embedded curve: the mesh
/// does not change. Arg 0: as before the plan, a copy of the mesh for the undo
/// (SnakeMeshUndo::Snapshot) then the cut; arg 1: the cut planned, copied only if it changes
/// the mesh (it does not), then applied.
void BM_SecondSelect(benchmark::State &state)
{
    static std::unique_ptr<CMeshO> cut;
    static CutCurve chain;
    if (!cut) {
        cut.reset(new CMeshO);
        Append<CMeshO, CMeshO>::MeshCopy(*cut, Plate());
        const auto r = MeshCut<CMeshO>::Apply(*cut, {Circle(*cut, 1000, Radius(1.0))}, MeshCut<CMeshO>::Param());
        chain.points = r.chains[0];
        chain.closed = true;
    }
    const bool plan = state.range(0) == 1;
    SnakeMeshUndo<CMeshO, int> undo;
    int copies = 0, added = 0;
    for (auto _ : state) {
        std::string why;
        std::unique_ptr<CMeshO> before;
        MeshCut<CMeshO>::Result r;
        if (plan) {
            MeshCut<CMeshO>::Planned p = MeshCut<CMeshO>::Plan(*cut, {chain}, MeshCut<CMeshO>::Param());
            if (p.ChangesMesh()) before = undo.Snapshot(*cut, why);
            r = MeshCut<CMeshO>::Apply(*cut, std::move(p));
        } else {
            before = undo.Snapshot(*cut, why);
            r = MeshCut<CMeshO>::Apply(*cut, {chain}, MeshCut<CMeshO>::Param());
        }
        copies += before != nullptr;
        added += r.addedVertices + r.addedFaces;
        state.PauseTiming();
        before.reset(); // freeing the copy is not timed
        state.ResumeTiming();
    }
    state.counters["faces"] = cut->fn;
    state.counters["copies"] = copies;
    state.counters["added"] = added;
}

} // namespace

// samples 0.5, 1 and 2 cells apart: loops of radius 80, 160 and 320 cells (parts of 40K to 640K faces);
// the split also 0.2 cells apart (radius 32 cells, a part of 6K faces)
BENCHMARK(BM_EmbedAndSelect)->Arg(5)->Arg(10)->Arg(20)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Split)->Arg(2)->Arg(5)->Arg(10)->Arg(20)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SecondSelect)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
