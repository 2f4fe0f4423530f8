#ifndef GS_TESTS_CAPTURE_CASES_H
#define GS_TESTS_CAPTURE_CASES_H

// Capture range (issue 9): snakes seeded 1..6 edge lengths to one side of a crease, on the
// projected icospheres (exact creases) and on fandisk (chains of sharp edges). Shared by the
// unit test (tests/test_capture_range.cpp, a sparse set) and the evaluation (bench/eval/gs_eval,
// stage "capture", the full sweep).
//
// Every seed is nearer to the target crease than to any other crease (cases whose seeds cannot
// be placed so are narrowed, or skipped). A case is captured when >= 90 % of the final curve is
// within 0.5 h of the crease (as it lies on the mesh) and >= 90 % of the crease between the
// first and last seed (closed: all of it) has a curve point within 0.5 h.

#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <snake_test_util.h>

namespace gs_capture {

typedef vcg::Point3d P3;

struct Case
{
    std::string shape;
    bool closed = false;
    double offset = 0;         ///< in h
    double h = 1;              ///< the length unit of offsets and tolerances
    std::vector<int> seeds;    ///< vertex seeds
    std::vector<P3> truth;     ///< the crease as it lies on the mesh
    bool truthClosed = false;
    std::vector<P3> span;      ///< the crease between the first and last seed (closed: all)
};

struct Result
{
    double capture = 0, coverage = 0, meanDist = 0;
    int operations = 0;
    int embeddings = 0, reuses = 0; ///< the Run's embeddings built and kept ones reused (Sec. 4.2)
    bool converged = false;
    bool Captured() const { return capture >= 0.9 && coverage >= 0.9; }
};

inline std::vector<P3> Resample(const std::vector<P3> &pl, bool closed, double step)
{
    std::vector<P3> out;
    if (pl.empty()) return out;
    const size_t n = pl.size(), segs = closed ? n : n - 1;
    out.push_back(pl[0]);
    for (size_t i = 0; i < segs; ++i) {
        const P3 &a = pl[i], &b = pl[(i + 1) % n];
        const int k = std::max(1, int(std::ceil((b - a).Norm() / step)));
        for (int j = 1; j <= k; ++j) out.push_back(a + (b - a) * (double(j) / k));
    }
    if (closed) out.pop_back();
    return out;
}

inline std::vector<P3> Segment(const P3 &a, const P3 &b, int n)
{
    std::vector<P3> out;
    for (int i = 0; i < n; ++i) out.push_back(a + (b - a) * (double(i) / (n - 1)));
    return out;
}

inline std::vector<P3> Loop(const std::vector<P3> &corners, int nPerSide)
{
    std::vector<P3> out;
    for (size_t i = 0; i < corners.size(); ++i)
        for (int j = 0; j < nPerSide; ++j)
            out.push_back(corners[i] + (corners[(i + 1) % corners.size()] - corners[i]) * (double(j) / nPerSide));
    return out;
}

/// The generated shapes: "cube", "octahedron", "cylinder" (tests/generated_meshes.h).
inline void BuildShape(CMeshO &m, const std::string &shape, int subdiv, double noise = 0)
{
    if (shape == "cube") gs_test::MakeRotatedIcoCube(m, subdiv);
    else if (shape == "octahedron") gs_test::MakeRotatedIcoOctahedron(m, subdiv);
    else gs_test::MakeRotatedIcoCylinder(m, subdiv);
    if (noise > 0) gs_test::AddVertexNoise(m, noise, 1000u + unsigned(subdiv) * 10u + unsigned(noise * 100));
    gs_test::EnableSnakeAdjacency(m);
}

/// The case of `shape` at `off` edge lengths, or false when no seeds can be placed nearer to
/// the target than to another crease. Open snakes: 4 seeds along the crease, as far apart as
/// that rule allows; closed snakes: seeds all around the crease loop.
inline bool MakeGeneratedCase(CMeshO &m, const std::string &shape, bool closed, double off, Case &c)
{
    c = Case();
    c.shape = shape, c.closed = closed, c.offset = off;
    c.h = vcg::tri::MeshValidation<CMeshO>::MeanEdgeLength(m);
    const double d = off * c.h;
    std::vector<P3> exact, span, picks;
    std::function<double(const P3 &)> others; // distance to every crease of the shape
    std::function<std::vector<P3>(double)> openPicks; // picks over a share w of the crease
    if (shape == "cube") {
        others = [](const P3 &p) { return gs_test::DistToCubeEdges(p); };
        if (!closed) { // the edge x = y = 1; picks on the face x = 1
            exact = Segment(P3(1, 1, -1), P3(1, 1, 1), 800);
            openPicks = [d](double w) {
                std::vector<P3> p;
                for (double t : {-1.0, -1.0 / 3, 1.0 / 3, 1.0}) p.push_back(P3(1, 1 - d, 0.6 * w * t));
                return p;
            };
        } else { // the 4 edges of the face z = 1 (with corners); picks in the middle of the side faces
            // below them (a loop seeded inside the face would have to stretch to reach them and
            // its samples would spread 2-3 spacings apart: see docs/evaluation.md)
            exact = Loop({P3(1, 1, 1), P3(-1, 1, 1), P3(-1, -1, 1), P3(1, -1, 1)}, 300);
            picks = {P3(1, 0, 1 - d), P3(0, 1, 1 - d), P3(-1, 0, 1 - d), P3(0, -1, 1 - d)};
        }
    } else if (shape == "octahedron") {
        others = [](const P3 &p) { return gs_test::DistToOctahedronEdges(p); };
        const P3 up = P3(-0.5, -0.5, 1) / std::sqrt(1.5); // in the face x+y+z=1, away from the edge
        if (!closed) { // the edge (1,0,0)-(0,1,0); picks on the face above it
            const P3 A(1, 0, 0), B(0, 1, 0);
            exact = Segment(A, B, 800);
            openPicks = [=](double w) {
                std::vector<P3> p;
                for (double t : {-1.0, -1.0 / 3, 1.0 / 3, 1.0}) p.push_back(A + (B - A) * (0.5 + 0.3 * w * t) + up * d);
                return p;
            };
        } else { // the equator; picks at the middle of the 4 upper faces
            exact = Loop({P3(1, 0, 0), P3(0, 1, 0), P3(-1, 0, 0), P3(0, -1, 0)}, 300);
            for (int q = 0; q < 4; ++q) {
                const double a = M_PI / 4 + q * M_PI / 2;
                const P3 mid(0.5 * std::sqrt(2.0) * std::cos(a), 0.5 * std::sqrt(2.0) * std::sin(a), 0);
                const P3 u = (P3(0, 0, 1) - mid * 0.5).Normalize(); // up the face, across the equator
                picks.push_back(mid + u * d);
            }
        }
    } else { // cylinder: the top rim; picks on the side below it
        others = [](const P3 &p) { return gs_test::DistToCylinderRims(p); };
        exact = gs_test::CylinderRimLine(1.0, 1.0, 1200);
        if (!closed) {
            openPicks = [d](double w) {
                std::vector<P3> p;
                for (int i = 0; i < 4; ++i) {
                    const double a = 0.75 * M_PI * w * i / 3;
                    p.push_back(P3(std::cos(a), std::sin(a), 1 - d));
                }
                return p;
            };
        } else {
            for (int i = 0; i < 6; ++i) picks.push_back(P3(std::cos(2 * M_PI * i / 6), std::sin(2 * M_PI * i / 6), 1 - d));
        }
    }
    const bool exactClosed = closed || shape == "cylinder";
    auto valid = [&](const std::vector<P3> &p) {
        for (const P3 &x : p)
            if (gs_test::DistToPolyline(x, exact, exactClosed) > others(x) + 1e-9) return false;
        return true;
    };
    if (!closed) {
        double w = 1;
        while (w > 0.3 && !valid(openPicks(w))) w -= 0.02;
        picks = openPicks(w);
        // the crease between the first and last pick
        const P3 a = picks.front(), b = picks.back();
        for (const P3 &x : exact) {
            if (shape == "cylinder") {
                const double ang = std::atan2(x[1], x[0]);
                if (ang >= -1e-9 && ang <= 0.75 * M_PI * w + 1e-9) span.push_back(x);
            } else {
                const P3 dir = (b - a).Normalize();
                const double s = (x - a) * dir;
                if (s >= 0 && s <= (b - a).Norm()) span.push_back(x);
            }
        }
    } else {
        span = exact;
    }
    if (!valid(picks)) return false;
    c.seeds = gs_test::NearestVertices(m, picks);
    c.truth = gs_test::ProjectOntoMesh(m, exact);
    c.truthClosed = exactClosed;
    c.span = gs_test::ProjectOntoMesh(m, span);
    return c.seeds.size() >= 2;
}

// ------------------------------------------------------------------ fandisk
/// Chains of sharp edges (dihedral angle above minAngleDeg), longest first: vertex indices.
inline std::vector<std::vector<int>> SharpChains(CMeshO &m, double minAngleDeg)
{
    vcg::tri::UpdateNormal<CMeshO>::PerFaceNormalized(m);
    const double cosT = std::cos(minAngleDeg * M_PI / 180.0);
    std::map<int, std::set<int>> g;
    for (auto &f : m.face) {
        if (f.IsD()) continue;
        for (int k = 0; k < 3; ++k) {
            CFaceO *o = f.FFp(k);
            if (o == &f || o < &f) continue;
            if (vcg::Point3d::Construct(f.cN()) * vcg::Point3d::Construct(o->cN()) < cosT) {
                int a = int(vcg::tri::Index(m, f.V(k))), b = int(vcg::tri::Index(m, f.V((k + 1) % 3)));
                g[a].insert(b), g[b].insert(a);
            }
        }
    }
    std::set<std::pair<int, int>> used;
    std::vector<std::pair<double, std::vector<int>>> chains;
    for (auto &kv : g) {
        if (kv.second.size() == 2) continue; // chains start at ends and junctions
        for (int nb : kv.second) {
            if (used.count({kv.first, nb})) continue;
            std::vector<int> c = {kv.first};
            double len = 0;
            int prev = kv.first, cur = nb;
            used.insert({prev, cur}), used.insert({cur, prev});
            while (true) {
                c.push_back(cur);
                len += vcg::Distance(m.vert[prev].cP(), m.vert[cur].cP());
                if (g[cur].size() != 2) break;
                int next = -1;
                for (int x : g[cur]) if (x != prev) next = x;
                if (next < 0 || used.count({cur, next})) break;
                used.insert({cur, next}), used.insert({next, cur});
                prev = cur, cur = next;
            }
            chains.push_back({len, c});
        }
    }
    std::sort(chains.begin(), chains.end(), [](const auto &a, const auto &b) { return a.first > b.first; });
    std::vector<std::vector<int>> out;
    for (auto &c : chains) out.push_back(c.second);
    return out;
}

/// Open cases on the `nChains` longest sharp-edge chains of a CAD mesh (fandisk): 4 picks at
/// `off` edge lengths to the left of the chain, each nearer to its chain than to any other sharp
/// edge and about `off` from it (a pick that falls past another crease is rejected; the picks
/// are then drawn closer together along the chain, or the case is skipped).
inline std::vector<Case> MakeChainCases(CMeshO &m, const std::vector<double> &offsets, int nChains)
{
    const double h = vcg::tri::MeshValidation<CMeshO>::MeanEdgeLength(m);
    std::vector<std::vector<int>> chains = SharpChains(m, 30.0);
    std::vector<std::vector<P3>> lines;
    for (auto &ch : chains) {
        std::vector<P3> pl;
        for (int v : ch) pl.push_back(P3::Construct(m.vert[v].cP()));
        lines.push_back(pl);
    }
    std::vector<Case> out;
    int used = 0;
    for (size_t ci = 0; ci < chains.size() && used < nChains; ++ci) {
        const std::vector<P3> &pl = lines[ci];
        std::vector<double> cum(pl.size(), 0.0);
        for (size_t i = 1; i < pl.size(); ++i) cum[i] = cum[i - 1] + (pl[i] - pl[i - 1]).Norm();
        if (cum.back() < 15 * h || pl.size() < 10) continue;
        ++used;
        auto at = [&](double s, size_t &seg) {
            seg = 0;
            while (seg + 2 < pl.size() && cum[seg + 1] < s) ++seg;
            const double t = (s - cum[seg]) / std::max(1e-12, cum[seg + 1] - cum[seg]);
            return pl[seg] + (pl[seg + 1] - pl[seg]) * t;
        };
        auto leftOf = [&](size_t seg) { // in the face on the left of edge seg, perpendicular to it
            const int a = chains[ci][seg], b = chains[ci][seg + 1];
            for (auto &f : m.face) {
                if (f.IsD()) continue;
                for (int k = 0; k < 3; ++k)
                    if (int(vcg::tri::Index(m, f.V(k))) == a && int(vcg::tri::Index(m, f.V((k + 1) % 3))) == b)
                        return (P3::Construct(f.cN()) ^ (pl[seg + 1] - pl[seg])).Normalize();
            }
            return P3(0, 0, 0);
        };
        auto nearestOther = [&](const P3 &x) {
            double best = 1e300;
            for (size_t o = 0; o < lines.size(); ++o)
                if (o != ci) best = std::min(best, gs_test::DistToPolyline(x, lines[o]));
            return best;
        };
        for (double off : offsets) {
            Case c;
            c.shape = "fandisk" + std::to_string(used);
            c.offset = off, c.h = h;
            for (double w = 0.7; w >= 0.2 && c.seeds.empty(); w -= 0.1) {
                std::vector<P3> picks;
                bool ok = true;
                for (double t : {-1.0, -1.0 / 3, 1.0 / 3, 1.0}) {
                    size_t seg;
                    const P3 p = at(cum.back() * (0.5 + 0.5 * w * t), seg);
                    const int v = gs_test::NearestVertex(m, p + leftOf(seg) * (off * h));
                    const P3 q = P3::Construct(m.vert[v].cP());
                    const double dt = gs_test::DistToPolyline(q, pl);
                    ok &= dt > 0.5 * off * h && dt < off * h + h && dt <= nearestOther(q);
                    picks.push_back(q);
                }
                if (!ok) continue;
                c.seeds = gs_test::NearestVertices(m, picks);
                for (int i = 0; i <= 200; ++i) {
                    size_t seg;
                    c.span.push_back(at(cum.back() * (0.5 + 0.5 * w * (2.0 * i / 200 - 1)), seg));
                }
            }
            if (c.seeds.size() < 2) continue;
            c.truth = Resample(pl, false, 0.1 * h);
            out.push_back(c);
        }
    }
    return out;
}

// ------------------------------------------------------------------ running and measuring
inline Result Measure(const std::vector<P3> &curve, bool closed, const Case &c)
{
    Result r;
    const std::vector<P3> pts = Resample(curve, closed, 0.25 * c.h);
    int in = 0;
    for (const P3 &x : pts) {
        const double dd = gs_test::DistToPolyline(x, c.truth, c.truthClosed);
        r.meanDist += dd / c.h;
        in += dd <= 0.5 * c.h;
    }
    if (!pts.empty()) r.capture = double(in) / pts.size(), r.meanDist /= pts.size();
    int cov = 0;
    for (const P3 &x : c.span) cov += gs_test::DistToPolyline(x, pts, closed) <= 0.5 * c.h;
    r.coverage = c.span.empty() ? 0 : double(cov) / c.span.size();
    return r;
}

/// Runs the default snake (with `method`) from the case's seeds until it converges (at most
/// maxOps operations) and measures the final curve.
inline Result Run(std::shared_ptr<vcg::tri::SnakeSurface<CMeshO>> surf, const Case &c, vcg::tri::SnakeMethod method,
                  int maxOps = 300)
{
    vcg::tri::SnakeParams p;
    p.method = method;
    vcg::tri::GeometricSnake<CMeshO> s(surf, p);
    s.InitFromSeeds(c.seeds, c.closed);
    const bool conv = s.Run(maxOps);
    Result r = Measure(s.PolylinePositions(), c.closed, c);
    r.converged = conv;
    r.operations = s.Stats().operations;
    return r;
}

} // namespace gs_capture

#endif
