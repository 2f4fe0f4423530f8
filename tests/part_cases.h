#ifndef GS_TESTS_PART_CASES_H
#define GS_TESTS_PART_CASES_H

// Closed-snake cases on part boundaries drawn by people (issue 33): the Princeton Segmentation
// Benchmark subset in ../shared/data/segmentation (off/<id>.off, seg/<id>/<id>_<k>.seg, one label
// per face). Shared by bench/eval/gs_parts (the evaluation) and test_part_boundary (its small
// version).
//
// A *part* is a connected region of one label in one person's segmentation whose boundary with
// the rest of the mesh is a single closed loop of edges, smaller than half the surface, that a
// majority of the people reproduce (a label of theirs overlaps it with intersection over union
// >= 0.75). Nothing is chosen by hand: every mesh of the benchmark gives its parts the same way.
// A case seeds a closed snake `ring` edge rings off the part's boundary, on one side (inside,
// on the part, or outside, on the rest), with seeds at evenly spaced places along it.
//
// Measures (h = the mesh's mean edge length): capture = share of the final loop (resampled at
// h/4) within 1 h of the cut of some person who reproduced the part; coverage = share of that
// person's cut within 1 h of the loop (the best person); length ratio = final / initial length.

#include <algorithm>
#include <cmath>
#include <deque>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <common/ml_mesh_type.h>
#include <part_variants.h>
#include <snake_test_util.h>
#include <wrap/io_trimesh/import_off.h>
#include <vcg/complex/algorithms/update/topology.h>

namespace gs_parts {

typedef vcg::Point3d P3;

/// The benchmark's category of a model id (from the data's README).
inline std::string Category(int id)
{
    static const std::map<int, std::string> c = {{3, "human"},    {84, "ant"},     {121, "octopus"},
                                                 {161, "teddy"},   {181, "hand"},   {221, "fish"},
                                                 {241, "bird"},    {281, "armadillo"}, {381, "fourleg"},
                                                 {327, "mech"},    {333, "mech"},   {341, "bearing"},
                                                 {342, "bearing"}};
    auto it = c.find(id);
    return it == c.end() ? "other" : it->second;
}

struct Part
{
    int id = 0;                       ///< model id
    int index = 0;                    ///< part number within the model
    std::vector<char> inside;         ///< per face: 1 = on the part
    std::vector<int> loop;            ///< the boundary loop's vertices, in order (representative person)
    std::vector<std::vector<P3>> cuts; ///< each agreeing person's cut, as closed polylines
    int agree = 0, people = 0;
    double area = 0;                  ///< share of the surface
};

struct Model
{
    int id = 0;
    std::string category;
    CMeshO mesh;
    double h = 1; ///< mean edge length
    double h0 = 1; ///< the mean edge length before the tessellation variant (LoadModel; = h without one)
    std::vector<std::vector<int>> segs;
    std::vector<Part> parts;
};

inline bool ReadSeg(const std::string &path, size_t faces, std::vector<int> &lab)
{
    std::ifstream in(path);
    lab.clear();
    int x;
    while (in >> x) lab.push_back(x);
    return lab.size() == faces;
}

/// Ordered boundary loop of a face set, or empty if its boundary is not exactly one loop.
inline std::vector<int> BoundaryLoop(CMeshO &m, const std::vector<char> &in)
{
    std::map<int, std::vector<int>> nb; // vertex -> boundary neighbours
    for (size_t f = 0; f < m.face.size(); ++f) {
        if (!in[f]) continue;
        for (int k = 0; k < 3; ++k) {
            const int g = int(vcg::tri::Index(m, m.face[f].FFp(k)));
            if (g == int(f) || in[g]) continue;
            const int a = int(vcg::tri::Index(m, m.face[f].V0(k))), b = int(vcg::tri::Index(m, m.face[f].V1(k)));
            nb[a].push_back(b);
            nb[b].push_back(a);
        }
    }
    if (nb.empty()) return {};
    for (auto &kv : nb)
        if (kv.second.size() != 2) return {};
    std::vector<int> loop;
    int prev = -1, cur = nb.begin()->first;
    do {
        loop.push_back(cur);
        const std::vector<int> &n = nb[cur];
        const int next = n[0] != prev ? n[0] : n[1];
        prev = cur;
        cur = next;
        if (loop.size() > nb.size()) return {};
    } while (cur != loop.front());
    return loop.size() == nb.size() ? loop : std::vector<int>();
}

inline std::vector<P3> Positions(const CMeshO &m, const std::vector<int> &vs)
{
    std::vector<P3> out;
    for (int v : vs) out.push_back(P3::Construct(m.vert[v].cP()));
    return out;
}

/// Connected components (through FF) of the faces carrying each label.
inline std::vector<std::vector<char>> LabelRegions(CMeshO &m, const std::vector<int> &lab)
{
    std::vector<int> comp(m.face.size(), -1);
    std::vector<std::vector<char>> out;
    for (size_t s = 0; s < m.face.size(); ++s) {
        if (comp[s] >= 0) continue;
        std::vector<char> r(m.face.size(), 0);
        std::deque<int> q{int(s)};
        comp[s] = int(out.size());
        while (!q.empty()) {
            const int f = q.front();
            q.pop_front();
            r[f] = 1;
            for (int k = 0; k < 3; ++k) {
                const int g = int(vcg::tri::Index(m, m.face[f].FFp(k)));
                if (comp[g] < 0 && lab[g] == lab[f]) comp[g] = int(out.size()), q.push_back(g);
            }
        }
        out.push_back(std::move(r));
    }
    return out;
}

inline double IoU(const std::vector<char> &a, const std::vector<char> &b, const std::vector<double> &area)
{
    double i = 0, u = 0;
    for (size_t f = 0; f < a.size(); ++f) {
        if (a[f] && b[f]) i += area[f];
        if (a[f] || b[f]) u += area[f];
    }
    return u > 0 ? i / u : 0;
}

/// Loads model `id` and derives its parts. False if the files are missing or disagree, or the
/// variant is unknown. `variant`: a tessellation variant of the mesh, its labels carried over
/// (part_variants.h; "" = the mesh as it is).
inline bool LoadModel(const std::string &dir, int id, Model &md, const std::string &variant = "")
{
    md.id = id;
    md.category = Category(id);
    CMeshO &m = md.mesh;
    int mask = 0;
    if (vcg::tri::io::ImporterOFF<CMeshO>::Open(m, (dir + "/off/" + std::to_string(id) + ".off").c_str(), mask) != 0)
        return false;
    for (int k = 0;; ++k) {
        std::vector<int> lab;
        const std::string p = dir + "/seg/" + std::to_string(id) + "/" + std::to_string(id) + "_" + std::to_string(k) + ".seg";
        if (!ReadSeg(p, m.face.size(), lab)) {
            if (k > 0 && !std::ifstream(p)) break;
            if (k == 0) return false;
            continue;
        }
        md.segs.push_back(lab);
    }
    if (md.segs.empty()) return false;
    const double h0 = MeanEdgeLength(m);
    if (!ApplyVariant(m, md.segs, variant)) return false;
    m.vert.EnableVFAdjacency();
    m.face.EnableVFAdjacency();
    m.face.EnableFFAdjacency();
    m.vert.EnableCurvature();
    m.vert.EnableCurvatureDir();
    m.vert.EnableMark();
    m.face.EnableMark();
    vcg::tri::UpdateTopology<CMeshO>::FaceFace(m);
    vcg::tri::UpdateTopology<CMeshO>::VertexFace(m);
    vcg::tri::UpdateBounding<CMeshO>::Box(m);
    vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFace(m);

    double el = 0;
    std::vector<double> area(m.face.size());
    double total = 0;
    for (size_t f = 0; f < m.face.size(); ++f) {
        const auto &F = m.face[f];
        for (int k = 0; k < 3; ++k) el += vcg::Distance(F.cP(k), F.cP((k + 1) % 3));
        area[f] = vcg::DoubleArea(F) / 2;
        total += area[f];
    }
    md.h = el / (3.0 * m.face.size());
    md.h0 = variant.empty() || variant == "none" ? md.h : h0;

    // every person's label regions (once)
    std::vector<std::vector<std::vector<char>>> regions;
    for (const auto &lab : md.segs) regions.push_back(LabelRegions(m, lab));
    for (size_t k = 0; k < regions.size(); ++k)
        for (const auto &r : regions[k]) {
            double a = 0;
            for (size_t f = 0; f < r.size(); ++f)
                if (r[f]) a += area[f];
            if (a / total > 0.5 || a / total < 1e-3) continue;
            bool seen = false;
            for (const Part &p : md.parts) seen = seen || IoU(p.inside, r, area) > 0.5;
            if (seen) continue;
            const std::vector<int> loop = BoundaryLoop(m, r);
            if (loop.size() < 8) continue;
            Part p;
            p.id = id;
            p.inside = r;
            p.loop = loop;
            p.area = a / total;
            p.people = int(regions.size());
            for (size_t j = 0; j < regions.size(); ++j) {
                const std::vector<char> *best = nullptr;
                double bi = 0;
                for (const auto &s : regions[j]) {
                    const double x = IoU(r, s, area);
                    if (x > bi) bi = x, best = &s;
                }
                if (bi < 0.75) continue;
                ++p.agree;
                const std::vector<int> l = BoundaryLoop(m, *best);
                if (!l.empty()) p.cuts.push_back(Positions(m, l));
            }
            if (2 * p.agree <= p.people) continue;
            p.index = int(md.parts.size());
            md.parts.push_back(std::move(p));
        }
    return true;
}

/// Hop distance (edges) of every vertex from the part's boundary loop, and its side
/// (+1 inside: all its faces on the part; -1 outside; 0 on the loop).
inline void Rings(CMeshO &m, const Part &p, std::vector<int> &dist, std::vector<int> &side)
{
    const size_t nv = m.vert.size();
    dist.assign(nv, -1);
    side.assign(nv, 0);
    std::vector<int> inCount(nv, 0), count(nv, 0);
    for (size_t f = 0; f < m.face.size(); ++f)
        for (int k = 0; k < 3; ++k) {
            const int v = int(vcg::tri::Index(m, m.face[f].V(k)));
            ++count[v];
            inCount[v] += p.inside[f];
        }
    for (size_t v = 0; v < nv; ++v) side[v] = inCount[v] == count[v] ? 1 : (inCount[v] == 0 ? -1 : 0);
    std::deque<int> q;
    for (int v : p.loop) dist[v] = 0, q.push_back(v);
    while (!q.empty()) {
        const int v = q.front();
        q.pop_front();
        vcg::face::VFIterator<CFaceO> vfi(&m.vert[v]);
        for (; !vfi.End(); ++vfi)
            for (int k = 0; k < 3; ++k) {
                const int w = int(vcg::tri::Index(m, vfi.F()->V(k)));
                if (dist[w] < 0) dist[w] = dist[v] + 1, q.push_back(w);
            }
    }
}

/// Seeds `ring` rings off the boundary on `sideWanted` (+1 inside, -1 outside): for evenly
/// spaced loop vertices, the vertex of that ring nearest along edges (ties: nearest in space).
/// Empty if the side has no such ring or fewer than 3 distinct seeds. Ring 0: vertices of the
/// cut itself, for side +1 only.
inline std::vector<int> Seeds(CMeshO &m, const Part &p, int ring, int sideWanted, int count)
{
    std::vector<int> dist, side;
    Rings(m, p, dist, side);
    std::vector<int> seeds;
    const int n = int(p.loop.size());
    if (ring == 0) {
        // on the cut itself (once per part, as "inside"): does the energy hold a loop put there?
        if (sideWanted < 0) return seeds;
        for (int i = 0; i < count; ++i) {
            const int v = p.loop[(long(i) * n) / count];
            if (seeds.empty() || seeds.back() != v) seeds.push_back(v);
        }
        if (seeds.size() > 1 && seeds.back() == seeds.front()) seeds.pop_back();
        if (seeds.size() < 3) seeds.clear();
        return seeds;
    }
    for (int i = 0; i < count; ++i) {
        const int b = p.loop[(long(i) * n) / count];
        // breadth-first from b over vertices of the wanted side (and the loop)
        std::map<int, int> hop{{b, 0}};
        std::deque<int> q{b};
        int best = -1;
        double bd = 1e300;
        int bestHop = 1 << 30;
        while (!q.empty()) {
            const int v = q.front();
            q.pop_front();
            if (hop[v] > bestHop || hop[v] > 2 * ring + 2) break;
            if (dist[v] == ring && side[v] == sideWanted) {
                const double d = vcg::Distance(m.vert[v].cP(), m.vert[b].cP());
                if (d < bd) bd = d, best = v, bestHop = hop[v];
            }
            vcg::face::VFIterator<CFaceO> vfi(&m.vert[v]);
            for (; !vfi.End(); ++vfi)
                for (int k = 0; k < 3; ++k) {
                    const int w = int(vcg::tri::Index(m, vfi.F()->V(k)));
                    if (hop.count(w) || (side[w] != sideWanted && dist[w] != 0)) continue;
                    hop[w] = hop[v] + 1;
                    q.push_back(w);
                }
        }
        if (best >= 0 && (seeds.empty() || (seeds.back() != best && seeds.front() != best))) seeds.push_back(best);
    }
    if (seeds.size() < 3) seeds.clear();
    return seeds;
}

inline double DistToLoop(const P3 &p, const std::vector<P3> &l) { return gs_test::DistToPolyline(p, l, true); }
inline std::vector<P3> ResampleLoop(const std::vector<P3> &pl, double step)
{
    std::vector<P3> out;
    for (size_t i = 0; i < pl.size(); ++i) {
        const P3 &a = pl[i], &b = pl[(i + 1) % pl.size()];
        const int k = std::max(1, int(std::ceil((b - a).Norm() / step)));
        for (int j = 0; j < k; ++j) out.push_back(a + (b - a) * (double(j) / k));
    }
    return out;
}
inline double LoopLength(const std::vector<P3> &pl)
{
    double L = 0;
    for (size_t i = 0; i < pl.size(); ++i) L += (pl[(i + 1) % pl.size()] - pl[i]).Norm();
    return L;
}

struct Score
{
    double capture = 0, coverage = 0, meanDist = 0; // meanDist in h
    bool Success() const { return capture >= 0.9 && coverage >= 0.9; }
};

/// capture / coverage of a closed loop against the part's human cuts (tolerance tol, e.g. 1 h).
inline Score Measure(const std::vector<P3> &loop, const Part &p, double h, double tol)
{
    Score s;
    if (loop.size() < 2 || p.cuts.empty()) return s;
    const std::vector<P3> pts = ResampleLoop(loop, 0.25 * h);
    int in = 0;
    for (const P3 &x : pts) {
        double d = 1e300;
        for (const auto &c : p.cuts) d = std::min(d, DistToLoop(x, c));
        in += d <= tol;
        s.meanDist += d / h;
    }
    s.capture = double(in) / pts.size();
    s.meanDist /= pts.size();
    for (const auto &c : p.cuts) {
        const std::vector<P3> cp = ResampleLoop(c, 0.25 * h);
        int cov = 0;
        for (const P3 &x : cp) cov += DistToLoop(x, pts) <= tol;
        s.coverage = std::max(s.coverage, double(cov) / cp.size());
    }
    return s;
}

} // namespace gs_parts

#endif
