#ifndef GS_TESTS_CREASE_CASES_H
#define GS_TESTS_CREASE_CASES_H

// Creases on CAD meshes (issue 38): snakes seeded a few local edge lengths to one side of a
// sharp-edge chain, nearer it than any other sharp edge, on
//  - dense features: a stepped shaft whose shoulder is 2, 3 or 4 edge lengths wide and a block
//    whose bore comes 2, 3 or 4 edge lengths from its top edge, remeshed isotropically
//    (vcglib's IsotropicRemeshing, creases kept) to that edge length;
//  - CAD tessellations: the stepped shaft as a B-rep tessellator exports it (every vertex on a
//    rim, 50:1 side slivers), its caps in three styles (fan from one corner, ear clipping,
//    strip);
//  - any mesh (the shared CAD-like meshes): the ground truth is the chains of edges whose
//    dihedral angle is above 30 degrees.
// Shared by the unit test (tests/test_cad_creases.cpp, a sparse set) and the evaluation
// (bench/eval/gs_creases, scripts/eval.sh --creases).
//
// Captured (the criterion): >= 90 % of the curve within half a local edge length h of
// the crease and >= 90 % of the crease between the first and last seed (closed: all of it)
// within h / 2 of the curve; h = the mean length of the chain's own edges (on a tessellation the
// chain-edge length; the faces' edges are slivers as long as the part).

#include <algorithm>
#include <array>
#include <map>
#include <string>
#include <vector>

#include <vcg/complex/algorithms/isotropic_remeshing.h>

#include <capture_cases.h>
#include <cad_meshes.h>
#include <vcg_ext/paths/seed_points.h>
#include <vcg_ext/session/controller.h>

namespace gs_crease {

typedef vcg::Point3d P3;
typedef std::array<int, 3> Tri;

// ------------------------------------------------------------------ tessellations
enum class CapStyle { Fan, EarClip, Strip };
inline const char *StyleName(CapStyle s) { return s == CapStyle::Fan ? "fan" : (s == CapStyle::EarClip ? "earclip" : "strip"); }

/// Triangulates a convex polygon (vertex indices in order, facing the side it is to be seen
/// from): a fan from its first corner; ear clipping that always cuts the ear with the largest
/// smallest angle (as polygon tessellators do); or a strip zigzagging between the two sides.
inline void Polygon(const std::vector<P3> &p, std::vector<int> poly, CapStyle style, std::vector<Tri> &t)
{
    const int n = int(poly.size());
    if (style == CapStyle::Fan) {
        for (int i = 1; i + 1 < n; ++i) t.push_back({poly[0], poly[i], poly[i + 1]});
    } else if (style == CapStyle::Strip) {
        int a = 0, b = n - 1;
        bool left = true;
        while (b - a >= 2) {
            if (left) t.push_back({poly[a], poly[a + 1], poly[b]}), ++a;
            else t.push_back({poly[a], poly[b - 1], poly[b]}), --b;
            left = !left;
        }
    } else {
        auto minAngle = [&](int a, int b, int c) {
            const P3 A = p[a], B = p[b], C = p[c];
            auto ang = [](P3 u, P3 v) { return std::acos(std::max(-1.0, std::min(1.0, u.Normalize() * v.Normalize()))); };
            return std::min({ang(B - A, C - A), ang(A - B, C - B), ang(A - C, B - C)});
        };
        while (poly.size() > 3) {
            const int m = int(poly.size());
            int best = 0;
            double bestA = -1;
            for (int i = 0; i < m; ++i) {
                const double a = minAngle(poly[(i + m - 1) % m], poly[i], poly[(i + 1) % m]);
                if (a > bestA) bestA = a, best = i;
            }
            t.push_back({poly[(best + m - 1) % m], poly[best], poly[(best + 1) % m]});
            poly.erase(poly.begin() + best);
        }
        t.push_back({poly[0], poly[1], poly[2]});
    }
}

/// A stepped shaft as a tessellator exports it: a cylinder of radius r1 and height h1 (axis z,
/// base at z = 0) with a coaxial one of radius r2 < r1 and height h2 on top; `n` segments. The
/// sides are long strips (slivers of height / (2 pi r / n)), the shoulder ring a zip between
/// its two circles, the two caps polygons in `style`. Every vertex is on a rim.
template <class M>
void MakeSteppedShaft(M &m, int n, double r1, double h1, double r2, double h2, CapStyle style)
{
    std::vector<P3> p;
    auto ring = [&](double r, double z) {
        std::vector<int> idx;
        for (int i = 0; i < n; ++i) {
            const double a = 2 * M_PI * i / n;
            idx.push_back(int(p.size()));
            p.push_back(P3(r * std::cos(a), r * std::sin(a), z));
        }
        return idx;
    };
    const std::vector<int> b1 = ring(r1, 0), t1 = ring(r1, h1), b2 = ring(r2, h1), t2 = ring(r2, h1 + h2);
    std::vector<Tri> t;
    for (int i = 0; i < n; ++i) {
        const int j = (i + 1) % n;
        gs_test::detail::Quad(t, b1[i], b1[j], t1[j], t1[i]); // outward
        gs_test::detail::Quad(t, b2[i], b2[j], t2[j], t2[i]);
    }
    gs_test::detail::ZipRing(p, t1, b2, P3(0, 0, 1), false, t); // the shoulder, facing +z
    std::vector<int> top = t2, bottom(b1.rbegin(), b1.rend());   // counter-clockwise seen from outside
    Polygon(p, top, style, t);
    Polygon(p, bottom, style, t);
    gs_test::MakeFromArrays(m, p, t);
}

/// A block [0,X] x [0,Y] x [0,Z] with a through-bore (axis z) of radius r at (bx, by), `n`
/// segments; the top and bottom faces zip the bore's circles to their outlines, which are split
/// into pieces about as long as the bore's segments (so the zip does not fold when the bore
/// comes close to an edge), the sides are strips between those pieces.
template <class M>
void MakeBoredBlock(M &m, double X, double Y, double Z, double bx, double by, double r, int n)
{
    std::vector<P3> p;
    auto add = [&](double x, double y, double z) {
        p.push_back(P3(x, y, z));
        return int(p.size()) - 1;
    };
    const double piece = 2 * M_PI * r / n;
    const std::vector<P3> corners{P3(0, 0, 0), P3(X, 0, 0), P3(X, Y, 0), P3(0, Y, 0)};
    std::vector<int> outTop, outBot; // counter-clockwise seen from +z
    for (int c = 0; c < 4; ++c) {
        const P3 a = corners[c], b = corners[(c + 1) % 4];
        const int k = std::max(1, int(std::ceil((b - a).Norm() / piece)));
        for (int i = 0; i < k; ++i) {
            const P3 q = a + (b - a) * (double(i) / k);
            outBot.push_back(add(q[0], q[1], 0));
            outTop.push_back(add(q[0], q[1], Z));
        }
    }
    std::vector<int> top, bot;
    for (int i = 0; i < n; ++i) {
        const double a = 2 * M_PI * i / n;
        top.push_back(add(bx + r * std::cos(a), by + r * std::sin(a), Z));
        bot.push_back(add(bx + r * std::cos(a), by + r * std::sin(a), 0));
    }
    std::vector<Tri> t;
    const P3 up(0, 0, 1);
    gs_test::detail::ZipRing(p, outTop, top, up, false, t);
    gs_test::detail::ZipRing(p, outBot, bot, up, true, t);
    const int no = int(outTop.size());
    for (int i = 0; i < no; ++i) {
        const int j = (i + 1) % no;
        gs_test::detail::Quad(t, outBot[i], outBot[j], outTop[j], outTop[i]); // outward
    }
    for (int i = 0; i < n; ++i) {
        const int j = (i + 1) % n;
        gs_test::detail::Quad(t, bot[i], top[i], top[j], bot[j]);
    }
    gs_test::MakeFromArrays(m, p, t);
}

/// Remeshes m isotropically to edge length h, keeping its creases (vcglib's
/// IsotropicRemeshing, feature angle 30 degrees): a dense CAD mesh.
inline void Remesh(CMeshO &m, double h, int iterations = 8)
{
    gs_test::EnableSnakeAdjacency(m);
    vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFaceNormalized(m);
    vcg::tri::IsotropicRemeshing<CMeshO>::Params par;
    par.SetTargetLen(float(h));
    par.SetFeatureAngleDeg(30);
    par.iter = iterations;
    par.surfDistCheck = false;
    // vcglib leaves it unset, and ProjectToSurface searches within 1.5x it: a value off the stack
    // made the remeshed mesh differ from run to run (valgrind: uninitialised, the closest-face
    // query's distance). The vertices move far less than an edge between projections.
    par.maxSurfDist = float(h);
    CMeshO target; // what the vertices are projected back onto (with the marks its grid needs)
    vcg::tri::Append<CMeshO, CMeshO>::MeshCopy(target, m);
    gs_test::EnableSnakeAdjacency(target);
    vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFaceNormalized(target);
    vcg::tri::IsotropicRemeshing<CMeshO>::Do(m, target, par);
    vcg::tri::Allocator<CMeshO>::CompactEveryVector(m);
    vcg::tri::UpdateTopology<CMeshO>::FaceFace(m);
    vcg::tri::UpdateTopology<CMeshO>::VertexFace(m);
    vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFaceNormalized(m);
    vcg::tri::UpdateBounding<CMeshO>::Box(m);
}

// ------------------------------------------------------------------ ground truth
/// A chain of sharp edges: its vertices, closed or not, and the mean length of its edges.
struct Chain
{
    std::vector<int> verts;
    std::vector<P3> pts;
    bool closed = false;
    double h = 0, length = 0;
};

/// The chains of edges whose dihedral angle is above `angleDeg` (ends and junctions split
/// them; loops are closed chains), longest first. Needs FF adjacency.
inline std::vector<Chain> SharpChains(CMeshO &m, double angleDeg = 30)
{
    vcg::tri::UpdateNormal<CMeshO>::PerFaceNormalized(m);
    const double cosT = std::cos(angleDeg * M_PI / 180.0);
    std::map<int, std::vector<int>> g;
    for (auto &f : m.face) {
        if (f.IsD()) continue;
        for (int k = 0; k < 3; ++k) {
            CFaceO *o = f.FFp(k);
            if (o == &f || o < &f) continue;
            if (P3::Construct(f.cN()) * P3::Construct(o->cN()) < cosT) {
                const int a = int(vcg::tri::Index(m, f.V(k))), b = int(vcg::tri::Index(m, f.V((k + 1) % 3)));
                g[a].push_back(b), g[b].push_back(a);
            }
        }
    }
    std::map<std::pair<int, int>, bool> used;
    std::vector<Chain> out;
    auto walk = [&](int from, int nb) {
        Chain c;
        c.verts = {from};
        int prev = from, cur = nb;
        used[{prev, cur}] = used[{cur, prev}] = true;
        while (true) {
            c.verts.push_back(cur);
            if (g[cur].size() != 2) break;
            const int next = g[cur][0] == prev ? g[cur][1] : g[cur][0];
            if (used.count({cur, next})) break;
            used[{cur, next}] = used[{next, cur}] = true;
            prev = cur, cur = next;
        }
        if (c.verts.size() > 2 && c.verts.back() == c.verts.front()) c.verts.pop_back(), c.closed = true;
        for (int v : c.verts) c.pts.push_back(P3::Construct(m.vert[v].cP()));
        const size_t segs = c.closed ? c.pts.size() : c.pts.size() - 1;
        for (size_t i = 0; i < segs; ++i) c.length += (c.pts[(i + 1) % c.pts.size()] - c.pts[i]).Norm();
        c.h = c.length / std::max<size_t>(1, segs);
        out.push_back(c);
    };
    for (auto &kv : g) // chains from their ends and junctions
        if (kv.second.size() != 2)
            for (int nb : kv.second)
                if (!used.count({kv.first, nb})) walk(kv.first, nb);
    for (auto &kv : g) // what is left are loops
        for (int nb : kv.second)
            if (!used.count({kv.first, nb})) walk(kv.first, nb);
    std::sort(out.begin(), out.end(), [](const Chain &a, const Chain &b) { return a.length > b.length; });
    return out;
}

// ------------------------------------------------------------------ cases
struct Case
{
    std::string set, mesh;
    int chain = 0;
    bool closed = false;
    double offset = 0;     ///< in h
    gs_capture::Case c;    ///< truth, span, h
    std::vector<P3> seeds; ///< seed points (snapped onto the surface when run)
};

/// Seeds `off` h to one side of chain `ci` (left or right of its direction; the first side
/// where it works), each within (0.5 off h, off h + h/2] of the chain, nearest to it within
/// off h + h (along the chain) of the point it was offset from, and 1.5x nearer to it than
/// to any other sharp edge. Open: 4 seeds over a share of the chain (drawn closer together
/// until the rule holds; chains shorter than 12 h are skipped); closed (loops only): 6 seeds
/// all around. False if no side works.
inline bool MakeCase(CMeshO &m, const std::vector<Chain> &chains, int ci, double off, bool closed, Case &out)
{
    const Chain &ch = chains[ci];
    const double h = ch.h;
    if (closed && !ch.closed) return false;
    if (!closed && ch.length < 12 * h) return false;
    const size_t n = ch.pts.size(), segs = ch.closed ? n : n - 1;
    std::vector<double> cum(segs + 1, 0.0);
    for (size_t i = 0; i < segs; ++i) cum[i + 1] = cum[i] + (ch.pts[(i + 1) % n] - ch.pts[i]).Norm();
    std::map<std::pair<int, int>, int> faceOf; // directed edge -> face
    for (size_t f = 0; f < m.face.size(); ++f)
        if (!m.face[f].IsD())
            for (int k = 0; k < 3; ++k)
                faceOf[{int(vcg::tri::Index(m, m.face[f].V(k))), int(vcg::tri::Index(m, m.face[f].V((k + 1) % 3)))}] = int(f);
    vcg::GridStaticPtr<CFaceO, float> grid;
    grid.Set(m.face.begin(), m.face.end());
    auto project = [&](const P3 &q) {
        float dist = 1e30f;
        Point3m closest;
        vcg::tri::GetClosestFaceBase(m, grid, Point3m::Construct(q), 1e30f, dist, closest);
        return P3::Construct(closest);
    };
    auto nearestOther = [&](const P3 &x) {
        double best = 1e300;
        for (size_t o = 0; o < chains.size(); ++o)
            if (int(o) != ci) best = std::min(best, gs_test::DistToPolyline(x, chains[o].pts, chains[o].closed));
        return best;
    };
    auto pick = [&](double s, bool left, P3 &q) { // a seed beside arclength s
        s = std::max(0.0, std::min(s, cum.back()));
        size_t seg = 0;
        while (seg + 1 < segs && cum[seg + 1] < s) ++seg;
        const P3 a = ch.pts[seg], b = ch.pts[(seg + 1) % n];
        const double t = (s - cum[seg]) / std::max(1e-12, cum[seg + 1] - cum[seg]);
        const int va = ch.verts[seg], vb = ch.verts[(seg + 1) % n];
        auto it = left ? faceOf.find({va, vb}) : faceOf.find({vb, va});
        if (it == faceOf.end()) return false;
        const P3 nrm = P3::Construct(m.face[it->second].cN());
        const P3 dir = (nrm ^ (left ? b - a : a - b)).Normalize(); // into that face
        q = project(a + (b - a) * t + dir * (off * h));
        // the chain's point nearest the seed (its arclength sq): the seed must be beside s, not
        // across a loop narrower than 2 off (inside a small rim, off h inwards passes its centre)
        double dt = 1e300, sq = 0;
        for (size_t i = 0; i < segs; ++i) {
            const P3 u = ch.pts[i], d = ch.pts[(i + 1) % n] - u;
            const double L2 = d.SquaredNorm(), ti = L2 > 0 ? std::max(0.0, std::min(1.0, ((q - u) * d) / L2)) : 0.0;
            const double di = (q - (u + d * ti)).Norm();
            if (di < dt) dt = di, sq = cum[i] + ti * (cum[i + 1] - cum[i]);
        }
        double along = std::abs(sq - s);
        if (ch.closed) along = std::min(along, cum.back() - along);
        return dt > 0.5 * off * h && dt <= off * h + 0.5 * h && along <= off * h + h && 1.5 * dt <= nearestOther(q);
    };
    for (bool left : {true, false}) {
        std::vector<P3> picks;
        double w = 0.7;
        for (; w >= 0.2 && picks.empty(); w -= 0.1) {
            std::vector<P3> p;
            bool ok = true;
            if (closed)
                for (int i = 0; i < 6 && ok; ++i) {
                    P3 q;
                    ok = pick(cum.back() * (i + 0.5) / 6, left, q);
                    p.push_back(q);
                }
            else
                for (double t : {-1.0, -1.0 / 3, 1.0 / 3, 1.0}) {
                    P3 q;
                    ok = ok && pick(cum.back() * (0.5 + 0.5 * w * t), left, q);
                    p.push_back(q);
                }
            if (ok) picks = p;
            if (closed) break;
        }
        if (picks.empty()) continue;
        w += 0.1; // the share that worked
        out = Case();
        out.chain = ci, out.closed = closed, out.offset = off, out.seeds = picks;
        out.c.h = h, out.c.closed = closed, out.c.offset = off;
        out.c.truth = gs_capture::Resample(ch.pts, ch.closed, 0.1 * h);
        out.c.truthClosed = ch.closed;
        if (closed) out.c.span = out.c.truth;
        else
            for (int i = 0; i <= 200; ++i) {
                const double s = cum.back() * (0.5 + 0.5 * w * (2.0 * i / 200 - 1));
                size_t seg = 0;
                while (seg + 1 < segs && cum[seg + 1] < s) ++seg;
                const double t = (s - cum[seg]) / std::max(1e-12, cum[seg + 1] - cum[seg]);
                out.c.span.push_back(ch.pts[seg] + (ch.pts[(seg + 1) % n] - ch.pts[seg]) * t);
            }
        return true;
    }
    return false;
}

/// Runs the tool's snake (SnakeController: the energy's own length unit, default parameters,
/// 2 smoothing steps) from the case's seed points and measures it.
inline gs_capture::Result Run(CMeshO &m, const Case &k, vcg::tri::FeatureEnergyType type, int maxOps = 400)
{
    vcg::tri::SnakeController<CMeshO> ctl(m);
    ctl.SetEnergySettings(type, 2);
    auto snap = vcg::tri::SeedPointSnap<CMeshO>::Snap(m, k.seeds, k.closed ? 3 : 2, k.closed);
    ctl.CreateSnakeFromSeedPoints(snap.points, k.closed);
    auto &s = ctl.Get(0);
    const bool conv = s.Run(maxOps);
    gs_capture::Result r = gs_capture::Measure(s.PolylinePositions(), k.closed, k.c);
    r.converged = conv;
    r.operations = s.Stats().operations;
    r.embeddings = s.Stats().embeddings;
    r.reuses = s.Stats().reuses;
    return r;
}

} // namespace gs_crease

#endif
