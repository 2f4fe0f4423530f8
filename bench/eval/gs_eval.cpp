// Accuracy sweep of the geometric snake (issue 5). Drives vcg_ext directly and writes one CSV
// row per (case, method). Post-processing (tables, plots, headline numbers) is done by
// bench/eval/report.py; scripts/eval.sh runs both.
//
//   gs_eval [--quick] [--stages main,energy,params,fandisk,capture] [--out FILE.csv]
//
// Cases with exact answers: rotated icospheres projected onto a cube, an octahedron and a
// capped cylinder (tests/generated_meshes.h), with vertex noise, picks placed on one side of
// a feature at 1..6 edge lengths, open and closed snakes; and sharp-edge chains of fandisk
// (dihedral angle above a threshold) taken as ground truth.
//
// Metrics per case (all in mean edge lengths h):
//   mean/p95 distance from the final curve (resampled every h/4) to the feature projected onto
//   the mesh (closest points; what a surface curve can reach) and to the exact feature;
//   capture  = share of the curve within 0.5 h of the projected feature;
//   coverage = share of the projected feature between the first and last pick (closed: all of
//              it) that has a curve point within 0.5 h;
//   operations and milliseconds to convergence (Run(300)).

#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

#include <capture_cases.h>
#include <snake_test_util.h>

using namespace vcg::tri;
typedef GeometricSnake<CMeshO> Snake;
typedef SnakeSurface<CMeshO> Surface;
typedef vcg::Point3d P3;

namespace {

const char *EnergyName(FeatureEnergyType t)
{
    switch (t) {
    case FeatureEnergyType::NormalVariation: return "normal_variation";
    case FeatureEnergyType::CurvatureNorm: return "curvature_norm";
    default: return "quadric_error";
    }
}

// ------------------------------------------------------------------ geometry helpers
std::vector<P3> Resample(const std::vector<P3> &pl, bool closed, double step)
{
    std::vector<P3> out;
    if (pl.empty()) return out;
    size_t n = pl.size();
    size_t segs = closed ? n : n - 1;
    out.push_back(pl[0]);
    for (size_t i = 0; i < segs; ++i) {
        const P3 &a = pl[i], &b = pl[(i + 1) % n];
        double L = (b - a).Norm();
        int k = std::max(1, int(std::ceil(L / step)));
        for (int j = 1; j <= k; ++j) out.push_back(a + (b - a) * (double(j) / k));
    }
    if (closed && !out.empty()) out.pop_back();
    return out;
}

double PolylineLength(const std::vector<P3> &pl, bool closed)
{
    double L = 0;
    for (size_t i = 0; i + 1 < pl.size(); ++i) L += (pl[i + 1] - pl[i]).Norm();
    if (closed && pl.size() > 2) L += (pl.front() - pl.back()).Norm();
    return L;
}

// Exact feature curves.
std::vector<P3> Segment(const P3 &a, const P3 &b, int n)
{
    std::vector<P3> out;
    for (int i = 0; i < n; ++i) out.push_back(a + (b - a) * (double(i) / (n - 1)));
    return out;
}
std::vector<P3> Loop(const std::vector<P3> &corners, int nPerSide)
{
    std::vector<P3> out;
    for (size_t i = 0; i < corners.size(); ++i) {
        const P3 &a = corners[i], &b = corners[(i + 1) % corners.size()];
        for (int j = 0; j < nPerSide; ++j) out.push_back(a + (b - a) * (double(j) / nPerSide));
    }
    return out;
}

// ------------------------------------------------------------------ cases
struct Case
{
    std::string shape; // cube, octahedron, cylinder, fandisk
    bool closed = false;
    double offset = 0;            // edge lengths
    std::vector<P3> picks;        // 3D pick positions (snapped to nearest vertices)
    std::vector<P3> feature;      // exact feature, dense
    bool featureClosed = false;
    std::vector<P3> span;         // exact feature between first and last pick (closed: all), dense
};

// Builds the open or closed case of `shape` with picks `off` edge lengths on one side of the feature.
Case MakeCase(const std::string &shape, bool closed, double off, double h)
{
    Case c;
    c.shape = shape;
    c.closed = closed;
    c.offset = off;
    const double d = off * h;
    if (shape == "cube") {
        if (!closed) { // the edge x = y = 1; picks on the face x = 1
            c.feature = Segment(P3(1, 1, -1), P3(1, 1, 1), 800);
            c.span = Segment(P3(1, 1, -0.6), P3(1, 1, 0.6), 500);
            for (double z : {-0.6, -0.2, 0.2, 0.6}) c.picks.push_back(P3(1, 1 - d, z));
        } else { // the 4 edges of the face z = 1 (has corners); picks inset on that face
            c.feature = Loop({P3(1, 1, 1), P3(-1, 1, 1), P3(-1, -1, 1), P3(1, -1, 1)}, 300);
            c.featureClosed = true;
            c.span = c.feature;
            const double s = 1 - d;
            c.picks = {P3(s, s, 1), P3(0, s, 1), P3(-s, s, 1), P3(-s, 0, 1),
                       P3(-s, -s, 1), P3(0, -s, 1), P3(s, -s, 1), P3(s, 0, 1)};
        }
    } else if (shape == "octahedron") {
        const P3 up = P3(-0.5, -0.5, 1) / std::sqrt(1.5); // in the face x+y+z=1, perpendicular to the edge
        if (!closed) { // the edge (1,0,0)-(0,1,0)
            P3 A(1, 0, 0), B(0, 1, 0);
            c.feature = Segment(A, B, 800);
            c.span = Segment(A + (B - A) * 0.2, A + (B - A) * 0.8, 500);
            for (double t : {0.2, 0.4, 0.6, 0.8}) c.picks.push_back(A + (B - A) * t + up * d);
        } else { // the equator |x|+|y| = 1, z = 0; picks on the upper faces
            c.feature = Loop({P3(1, 0, 0), P3(0, 1, 0), P3(-1, 0, 0), P3(0, -1, 0)}, 300);
            c.featureClosed = true;
            c.span = c.feature;
            const double z = d / std::sqrt(1.5), r = 1 - z;
            c.picks = {P3(r, 0, z), P3(r / 2, r / 2, z), P3(0, r, z), P3(-r / 2, r / 2, z),
                       P3(-r, 0, z), P3(-r / 2, -r / 2, z), P3(0, -r, z), P3(r / 2, -r / 2, z)};
        }
    } else { // cylinder: the top rim; picks on the side below it
        c.feature = gs_test::CylinderRimLine(1.0, 1.0, 1200);
        c.featureClosed = true;
        if (!closed) {
            for (int i = 0; i < 4; ++i) {
                double a = 0.75 * M_PI * i / 3;
                c.picks.push_back(P3(std::cos(a), std::sin(a), 1 - d));
            }
            for (int i = 0; i <= 500; ++i) {
                double a = 0.75 * M_PI * i / 500;
                c.span.push_back(P3(std::cos(a), std::sin(a), 1));
            }
        } else {
            for (int i = 0; i < 6; ++i) {
                double a = 2 * M_PI * i / 6;
                c.picks.push_back(P3(std::cos(a), std::sin(a), 1 - d));
            }
            c.span = c.feature;
        }
    }
    return c;
}

// ------------------------------------------------------------------ metrics
struct Metrics
{
    double meanProj = 0, p95Proj = 0, meanExact = 0, p95Exact = 0, capture = 0, coverage = 0;
    int samples = 0;
};

struct Truth
{
    std::vector<P3> proj, exact, spanProj;
    bool closed = false;
};

Metrics Measure(const std::vector<P3> &curve, bool curveClosed, const Truth &t, double h)
{
    Metrics m;
    std::vector<P3> pts = Resample(curve, curveClosed, 0.25 * h);
    auto ep = gs_test::MeasureCurve(pts, h, [&](const P3 &x) { return gs_test::DistToPolyline(x, t.proj, t.closed); });
    auto ee = gs_test::MeasureCurve(pts, h, [&](const P3 &x) { return gs_test::DistToPolyline(x, t.exact, t.closed); });
    m.meanProj = ep.mean, m.p95Proj = ep.p95, m.meanExact = ee.mean, m.p95Exact = ee.p95;
    int in = 0;
    for (auto &x : pts) in += gs_test::DistToPolyline(x, t.proj, t.closed) <= 0.5 * h;
    m.capture = pts.empty() ? 0 : double(in) / pts.size();
    int cov = 0;
    for (auto &x : t.spanProj) cov += gs_test::DistToPolyline(x, pts, curveClosed) <= 0.5 * h;
    m.coverage = t.spanProj.empty() ? 0 : double(cov) / t.spanProj.size();
    return m;
}

// ------------------------------------------------------------------ output
struct Row
{
    std::string stage, shape, variant, method, energy, snakeMethod;
    int subdiv = 0, faces = 0, esmooth = 0, csmooth = 0;
    double noise = 0, offset = 0, h = 0;
    bool closed = false;
    double alpha = 0, beta = 0, gamma = 0, ext = 0;
    Metrics met;
    int ops = 0;
    double ms = 0, msPerOp = 0;
    int converged = 0;
};

std::ofstream csv;
int rowsWritten = 0;

void WriteHeader()
{
    csv << "stage,shape,subdiv,faces,noise,offset,closed,method,variant,energy,esmooth,csmooth,snake_method,alpha,beta,"
           "gamma,ext,samples,mean_proj,p95_proj,mean_exact,p95_exact,capture,coverage,ops,ms,ms_per_op,converged\n";
}

void Write(const Row &r)
{
    char buf[1024];
    std::snprintf(buf, sizeof buf,
                  "%s,%s,%d,%d,%.3f,%.1f,%d,%s,%s,%s,%d,%d,%s,%.3g,%.3g,%.3g,%.3g,%d,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%d,%.2f,%.3f,%d\n",
                  r.stage.c_str(), r.shape.c_str(), r.subdiv, r.faces, r.noise, r.offset, int(r.closed), r.method.c_str(),
                  r.variant.c_str(), r.energy.c_str(), r.esmooth, r.csmooth, r.snakeMethod.c_str(), r.alpha, r.beta,
                  r.gamma, r.ext, r.met.samples, r.met.meanProj, r.met.p95Proj, r.met.meanExact, r.met.p95Exact,
                  r.met.capture, r.met.coverage, r.ops, r.ms, r.msPerOp, r.converged);
    csv << buf;
    csv.flush();
    ++rowsWritten;
}

// ------------------------------------------------------------------ snake configurations
struct Config
{
    std::string method = "snake"; // initial, scissors, snake
    std::string variant = "default";
    FeatureEnergyType et = FeatureEnergyType::NormalVariation;
    int esmooth = 2, csmooth = 8;
    SnakeParams p;
};

struct PreparedCase
{
    Case c;
    std::vector<int> seeds;
    Truth truth;
};

// Runs every configuration on every case of one mesh. Energies and surfaces are computed once
// per (energy, smoothing) and capture smoothing.
void RunMesh(CMeshO &m, const std::string &stage, int subdiv, double noise, const std::vector<PreparedCase> &cases,
             const std::vector<Config> &cfgs)
{
    const double h = vcg::tri::MeshValidation<CMeshO>::MeanEdgeLength(m);
    std::map<std::pair<int, int>, std::map<int, std::vector<const Config *>>> groups;
    for (auto &c : cfgs) groups[{int(c.et), c.esmooth}][c.method == "snake" ? c.csmooth : -1].push_back(&c);
    for (auto &eg : groups) {
        FeatureEnergy<CMeshO>::Compute(m, FeatureEnergyType(eg.first.first), eg.first.second);
        for (auto &sg : eg.second) {
            std::shared_ptr<Surface> surf;
            if (sg.first >= 0) surf = std::make_shared<Surface>(m, sg.first);
            for (const Config *cfg : sg.second) {
                for (const PreparedCase &pc : cases) {
                    Row r;
                    r.stage = stage, r.shape = pc.c.shape, r.subdiv = subdiv, r.faces = m.fn, r.noise = noise;
                    r.offset = pc.c.offset, r.closed = pc.c.closed, r.method = cfg->method, r.variant = cfg->variant;
                    r.energy = EnergyName(cfg->et), r.esmooth = cfg->esmooth, r.csmooth = cfg->csmooth;
                    r.snakeMethod = cfg->p.method == SnakeMethod::LocalEmbedding ? "embedding" : "projection";
                    r.alpha = cfg->p.alpha, r.beta = cfg->p.beta, r.gamma = cfg->p.gamma, r.ext = cfg->p.externalWeight;
                    r.h = h;
                    try {
                        std::vector<P3> curve;
                        auto t0 = std::chrono::steady_clock::now();
                        if (cfg->method == "initial" || cfg->method == "scissors") {
                            auto path = SeedPath<CMeshO>::Compute(
                                m, pc.seeds, pc.c.closed, cfg->method == "initial" ? SeedPathCost::Length : SeedPathCost::Feature);
                            r.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
                            for (int v : path.vertices) curve.push_back(P3::Construct(m.vert[v].cP()));
                            r.snakeMethod = "-";
                            if (cfg->method == "initial") r.energy = "-", r.esmooth = 0;
                            r.csmooth = 0;
                        } else {
                            Snake s(surf, cfg->p);
                            s.InitFromSeeds(pc.seeds, pc.c.closed);
                            r.converged = s.Run(300) ? 1 : 0;
                            r.ms = s.Stats().secondsTotal * 1000.0;
                            r.ops = s.Stats().operations;
                            r.msPerOp = SnakeStats::Median(s.Stats().msOperation);
                            curve = s.PolylinePositions();
                        }
                        r.met = Measure(curve, pc.c.closed, pc.truth, h);
                        r.met.samples = int(curve.size());
                    } catch (const std::exception &e) {
                        std::fprintf(stderr, "  failed %s %s: %s\n", pc.c.shape.c_str(), cfg->variant.c_str(), e.what());
                        r.met.capture = r.met.coverage = 0, r.met.meanProj = r.met.p95Proj = -1;
                        r.met.meanExact = r.met.p95Exact = -1;
                    }
                    Write(r);
                }
            }
        }
    }
}

void BuildShape(CMeshO &m, const std::string &shape, int subdiv, double noise)
{
    if (shape == "cube") gs_test::MakeRotatedIcoCube(m, subdiv);
    else if (shape == "octahedron") gs_test::MakeRotatedIcoOctahedron(m, subdiv);
    else gs_test::MakeRotatedIcoCylinder(m, subdiv);
    if (noise > 0) gs_test::AddVertexNoise(m, noise, 1000u + unsigned(subdiv) * 10u + unsigned(noise * 100));
    gs_test::EnableSnakeAdjacency(m);
}

std::vector<PreparedCase> PrepareCases(CMeshO &m, const std::string &shape, const std::vector<double> &offsets,
                                       const std::vector<bool> &closedList)
{
    const double h = vcg::tri::MeshValidation<CMeshO>::MeanEdgeLength(m);
    std::vector<PreparedCase> out;
    for (bool closed : closedList) {
        Case proto = MakeCase(shape, closed, 1.0, h);
        Truth t;
        t.exact = proto.feature;
        t.closed = proto.featureClosed;
        t.proj = gs_test::ProjectOntoMesh(m, proto.feature);
        t.spanProj = gs_test::ProjectOntoMesh(m, proto.span);
        for (double off : offsets) {
            PreparedCase pc;
            pc.c = MakeCase(shape, closed, off, h);
            pc.seeds = gs_test::NearestVertices(m, pc.c.picks);
            pc.truth = t;
            out.push_back(pc);
        }
    }
    return out;
}

// ------------------------------------------------------------------ fandisk: sharp-edge chains
struct Chain
{
    std::vector<int> verts;
    double length = 0;
};

/// The sharp-edge chains of tests/capture_cases.h, longest first, with their lengths.
std::vector<Chain> SharpChains(CMeshO &m, double minAngleDeg)
{
    std::vector<Chain> chains;
    for (auto &v : gs_capture::SharpChains(m, minAngleDeg)) {
        Chain c;
        c.verts = v;
        for (size_t i = 1; i < v.size(); ++i) c.length += vcg::Distance(m.vert[v[i - 1]].cP(), m.vert[v[i]].cP());
        chains.push_back(c);
    }
    return chains;
}

void RunFandisk(const std::vector<double> &offsets, const std::vector<Config> &cfgs, int nChains)
{
    CMeshO m;
    std::string path = std::string(GS_DATA_DIR) + "/fandisk.ply";
    if (!gs_test::LoadMesh(m, path)) {
        path = std::string(GS_SHARED_MESH_DIR) + "/fandisk.off";
        if (!gs_test::LoadMesh(m, path)) { std::fprintf(stderr, "no fandisk\n"); return; }
    }
    gs_test::EnableSnakeAdjacency(m);
    const double h = vcg::tri::MeshValidation<CMeshO>::MeanEdgeLength(m);
    std::vector<Chain> chains = SharpChains(m, 30.0);
    std::vector<PreparedCase> cases;
    int used = 0;
    for (const Chain &ch : chains) {
        if (used >= nChains) break;
        if (ch.length < 15 * h || ch.verts.size() < 10) continue;
        std::vector<P3> pl;
        for (int v : ch.verts) pl.push_back(P3::Construct(m.vert[v].cP()));
        std::vector<double> cum(pl.size(), 0.0);
        for (size_t i = 1; i < pl.size(); ++i) cum[i] = cum[i - 1] + (pl[i] - pl[i - 1]).Norm();
        auto at = [&](double s, P3 &p, size_t &seg) {
            seg = 0;
            while (seg + 2 < pl.size() && cum[seg + 1] < s) ++seg;
            double t = (s - cum[seg]) / std::max(1e-12, cum[seg + 1] - cum[seg]);
            p = pl[seg] + (pl[seg + 1] - pl[seg]) * t;
        };
        // the side: the face on one side of the chain's middle edge (same side for every pick)
        Truth t;
        t.exact = Resample(pl, false, 0.1 * h);
        t.proj = t.exact; // mesh edges: the feature is on the mesh
        std::vector<P3> spanPts;
        for (int i = 0; i <= 200; ++i) {
            P3 p; size_t seg;
            at(ch.length * (0.15 + 0.7 * i / 200.0), p, seg);
            spanPts.push_back(p);
        }
        t.spanProj = spanPts;
        ++used;
        for (double off : offsets) {
            PreparedCase pc;
            pc.c.shape = "fandisk" + std::to_string(used);
            pc.c.closed = false;
            pc.c.offset = off;
            for (double frac : {0.15, 0.38, 0.62, 0.85}) {
                P3 p; size_t seg;
                at(ch.length * frac, p, seg);
                // offset direction: within the face on the left of the edge (a -> b), perpendicular to it
                int a = ch.verts[seg], b = ch.verts[seg + 1];
                P3 dir(0, 0, 0);
                for (auto &f : m.face) {
                    if (f.IsD()) continue;
                    for (int k = 0; k < 3; ++k)
                        if (int(vcg::tri::Index(m, f.V(k))) == a && int(vcg::tri::Index(m, f.V((k + 1) % 3))) == b) {
                            P3 e = pl[seg + 1] - pl[seg];
                            dir = P3::Construct(f.cN()) ^ e; // points into f (counter-clockwise face)
                            dir.Normalize();
                        }
                }
                pc.c.picks.push_back(p + dir * (off * h));
            }
            pc.seeds = gs_test::NearestVertices(m, pc.c.picks);
            pc.truth = t;
            if (pc.seeds.size() >= 2) cases.push_back(pc);
        }
    }
    std::fprintf(stderr, "fandisk: %d faces, h %.4f, %zu sharp chains, %zu cases\n", m.fn, h, chains.size(), cases.size());
    RunMesh(m, "fandisk", 0, 0.0, cases, cfgs);
}

// ------------------------------------------------------------------ capture range (issue 9)
// tests/capture_cases.h: offsets 1..6 h, every seed nearer to the target crease than to any
// other; the generated shapes at subdiv 4 and 5 with noise 0 and 5 %, and fandisk's chains.
void RunCaptureCases(CMeshO &m, int subdiv, double noise, const std::vector<gs_capture::Case> &cases)
{
    FeatureEnergy<CMeshO>::Compute(m, FeatureEnergyType::NormalVariation, 2);
    auto surf = std::make_shared<Surface>(m);
    for (SnakeMethod method : {SnakeMethod::LocalEmbedding, SnakeMethod::Projection3D})
        for (const gs_capture::Case &c : cases) {
            Row r;
            r.stage = "capture", r.shape = c.shape, r.subdiv = subdiv, r.faces = m.fn, r.noise = noise;
            r.offset = c.offset, r.closed = c.closed, r.method = "snake";
            r.variant = method == SnakeMethod::LocalEmbedding ? "default" : "projection";
            r.energy = "normal_variation", r.esmooth = 2, r.csmooth = Surface::DefaultCaptureSmoothing();
            r.snakeMethod = method == SnakeMethod::LocalEmbedding ? "embedding" : "projection";
            SnakeParams p;
            r.alpha = p.alpha, r.beta = p.beta, r.gamma = p.gamma, r.ext = p.externalWeight, r.h = c.h;
            try {
                p.method = method;
                Snake s(surf, p);
                s.InitFromSeeds(c.seeds, c.closed);
                r.converged = s.Run(300) ? 1 : 0;
                r.ms = s.Stats().secondsTotal * 1000.0;
                r.ops = s.Stats().operations;
                r.msPerOp = SnakeStats::Median(s.Stats().msOperation);
                const std::vector<P3> curve = s.PolylinePositions();
                const gs_capture::Result res = gs_capture::Measure(curve, c.closed, c);
                r.met.capture = res.capture, r.met.coverage = res.coverage, r.met.meanProj = res.meanDist;
                r.met.samples = int(curve.size());
            } catch (const std::exception &e) {
                std::fprintf(stderr, "  failed %s: %s\n", c.shape.c_str(), e.what());
                r.met.capture = r.met.coverage = 0, r.met.meanProj = -1;
            }
            Write(r);
        }
}

} // namespace

int main(int argc, char **argv)
{
    bool quick = false;
    std::string out = "sweep.csv", stages = "main,energy,params,fandisk";
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--quick")) quick = true;
        else if (!std::strcmp(argv[i], "--out") && i + 1 < argc) out = argv[++i];
        else if (!std::strcmp(argv[i], "--stages") && i + 1 < argc) stages = argv[++i];
        else { std::fprintf(stderr, "usage: gs_eval [--quick] [--stages main,energy,params,fandisk,capture] [--out F.csv]\n"); return 2; }
    }
    auto has = [&](const char *s) { return ("," + stages + ",").find(std::string(",") + s + ",") != std::string::npos; };
    csv.open(out);
    if (!csv) { std::fprintf(stderr, "cannot write %s\n", out.c_str()); return 1; }
    WriteHeader();
    auto T0 = std::chrono::steady_clock::now();
    const std::vector<std::string> shapes = {"cube", "octahedron", "cylinder"};
    const std::vector<double> allOffsets = {1, 2, 3, 4, 6};

    // ---- main: every generated case; initial curve, scissors, default snake, 3D+projection
    if (has("main")) {
        std::vector<Config> cfgs(4);
        cfgs[0].method = "initial", cfgs[0].variant = "initial";
        cfgs[1].method = "scissors", cfgs[1].variant = "scissors";
        cfgs[2].variant = "default";
        cfgs[3].variant = "projection", cfgs[3].p.method = SnakeMethod::Projection3D;
        std::vector<int> subdivs = quick ? std::vector<int>{4} : std::vector<int>{3, 4, 5};
        std::vector<double> noises = quick ? std::vector<double>{0, 0.05} : std::vector<double>{0, 0.02, 0.05, 0.10};
        std::vector<double> offsets = quick ? std::vector<double>{1, 3, 6} : allOffsets;
        for (auto &shape : shapes)
            for (int sd : subdivs)
                for (double nz : noises) {
                    CMeshO m;
                    BuildShape(m, shape, sd, nz);
                    auto cases = PrepareCases(m, shape, offsets, {false, true});
                    auto t0 = std::chrono::steady_clock::now();
                    RunMesh(m, "main", sd, nz, cases, cfgs);
                    std::fprintf(stderr, "main %s subdiv %d noise %.2f: %d faces, %.1f s\n", shape.c_str(), sd, nz, m.fn,
                                 std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
                }
    }

    // ---- energy: energy type x energy smoothing x capture smoothing, on subdiv 4
    if (has("energy")) {
        std::vector<Config> cfgs;
        for (auto et : {FeatureEnergyType::NormalVariation, FeatureEnergyType::CurvatureNorm, FeatureEnergyType::QuadricError})
            for (int es : {0, 2, 5}) {
                Config sc;
                sc.method = "scissors", sc.variant = "scissors", sc.et = et, sc.esmooth = es;
                cfgs.push_back(sc);
                for (int cs : {0, 4, 8, 16}) {
                    Config c;
                    c.et = et, c.esmooth = es, c.csmooth = cs;
                    c.variant = std::string(EnergyName(et)) + "/e" + std::to_string(es) + "/c" + std::to_string(cs);
                    cfgs.push_back(c);
                }
            }
        std::vector<double> noises = quick ? std::vector<double>{0.05} : std::vector<double>{0, 0.05, 0.10};
        std::vector<double> offsets = quick ? std::vector<double>{2} : std::vector<double>{1, 3, 6};
        for (auto &shape : shapes)
            for (double nz : noises) {
                CMeshO m;
                BuildShape(m, shape, 4, nz);
                auto cases = PrepareCases(m, shape, offsets, {false, true});
                auto t0 = std::chrono::steady_clock::now();
                RunMesh(m, "energy", 4, nz, cases, cfgs);
                std::fprintf(stderr, "energy %s noise %.2f: %.1f s\n", shape.c_str(), nz,
                             std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
            }
    }

    // ---- params: one factor at a time around the defaults (alpha, beta, gamma, external weight)
    if (has("params") && !quick) {
        std::vector<Config> cfgs;
        auto add = [&](const std::string &name, double SnakeParams::*field, std::vector<double> vals) {
            for (double v : vals) {
                Config c;
                c.p.*field = v;
                char b[64];
                std::snprintf(b, sizeof b, "%s=%g", name.c_str(), v);
                c.variant = b;
                cfgs.push_back(c);
            }
        };
        add("alpha", &SnakeParams::alpha, {0.01, 0.05, 0.2});
        add("beta", &SnakeParams::beta, {0.1, 2.0});
        add("gamma", &SnakeParams::gamma, {0.5, 2.0});
        add("ext", &SnakeParams::externalWeight, {0.5, 2.0});
        for (auto &shape : shapes)
            for (double nz : {0.0, 0.05}) {
                CMeshO m;
                BuildShape(m, shape, 4, nz);
                auto cases = PrepareCases(m, shape, {1, 3, 6}, {false, true});
                auto t0 = std::chrono::steady_clock::now();
                RunMesh(m, "params", 4, nz, cases, cfgs);
                std::fprintf(stderr, "params %s noise %.2f: %.1f s\n", shape.c_str(), nz,
                             std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
            }
    }

    // ---- fandisk: sharp-edge chains (dihedral > 30 deg) as ground truth
    if (has("fandisk")) {
        std::vector<Config> cfgs(4);
        cfgs[0].method = "initial", cfgs[0].variant = "initial";
        cfgs[1].method = "scissors", cfgs[1].variant = "scissors";
        cfgs[2].variant = "default";
        cfgs[3].variant = "projection", cfgs[3].p.method = SnakeMethod::Projection3D;
        RunFandisk(quick ? std::vector<double>{1, 3} : allOffsets, cfgs, quick ? 2 : 4);
    }
    // ---- capture: the capture range, offsets 1..6 h (issue 9)
    if (has("capture")) {
        const std::vector<double> offsets = quick ? std::vector<double>{2, 4, 6} : std::vector<double>{1, 2, 3, 4, 5, 6};
        for (auto &shape : shapes)
            for (int sd : quick ? std::vector<int>{4} : std::vector<int>{4, 5})
                for (double nz : quick ? std::vector<double>{0} : std::vector<double>{0, 0.05}) {
                    CMeshO m;
                    gs_capture::BuildShape(m, shape, sd, nz);
                    std::vector<gs_capture::Case> cases;
                    for (bool closed : {false, true})
                        for (double off : offsets) {
                            gs_capture::Case c;
                            if (gs_capture::MakeGeneratedCase(m, shape, closed, off, c)) cases.push_back(c);
                        }
                    auto t0 = std::chrono::steady_clock::now();
                    RunCaptureCases(m, sd, nz, cases);
                    std::fprintf(stderr, "capture %s subdiv %d noise %.2f: %zu cases, %.1f s\n", shape.c_str(), sd, nz,
                                 cases.size(), std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
                }
        CMeshO m;
        if (gs_test::LoadMesh(m, std::string(GS_DATA_DIR) + "/fandisk.ply")) {
            gs_test::EnableSnakeAdjacency(m);
            auto cases = gs_capture::MakeChainCases(m, offsets, quick ? 2 : 4);
            RunCaptureCases(m, 0, 0.0, cases);
            std::fprintf(stderr, "capture fandisk: %zu cases\n", cases.size());
        }
    }
    std::fprintf(stderr, "gs_eval: %d rows in %.1f s -> %s\n", rowsWritten,
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - T0).count(), out.c_str());
    return 0;
}
