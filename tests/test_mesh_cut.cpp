// Cutting meshes along curves (vcg_ext/cut/): generated meshes with exact answers (polygons on
// irregular plates, whose inside area is the polygon's; rings on tubes, whose parts' areas are
// the mesh clipped by the plane), refusals that leave the mesh as it was, attributes across
// the cut, and real part boundaries drawn by people.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include <common/ml_mesh_type.h>
#include <generated_meshes.h>
#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/update/topology.h>
#include <vcg_ext/cut/mesh_cut.h>

using namespace vcg::tri;

namespace {

class CutVertex;
class CutFace;
struct CutUsed : public vcg::UsedTypes<vcg::Use<CutVertex>::AsVertexType, vcg::Use<CutFace>::AsFaceType> {};
class CutVertex : public vcg::Vertex<CutUsed, vcg::vertex::Coord3d, vcg::vertex::Normal3d, vcg::vertex::Color4b,
                                   vcg::vertex::Qualityd, vcg::vertex::BitFlags> {};
class CutFace : public vcg::Face<CutUsed, vcg::face::VertexRef, vcg::face::Normal3d, vcg::face::WedgeTexCoord2d,
                               vcg::face::Qualityd, vcg::face::FFAdj, vcg::face::BitFlags> {};
class CutMesh : public vcg::tri::TriMesh<std::vector<CutVertex>, std::vector<CutFace>> {};

typedef MeshCut<CutMesh> Cut;

void Build(CutMesh &m, const std::vector<vcg::Point3d> &pts, const std::vector<std::array<int, 3>> &tris)
{
    m.Clear();
    Allocator<CutMesh>::AddVertices(m, pts.size());
    for (size_t i = 0; i < pts.size(); ++i) m.vert[i].P() = pts[i];
    Allocator<CutMesh>::AddFaces(m, tris.size());
    for (size_t i = 0; i < tris.size(); ++i)
        for (int k = 0; k < 3; ++k) m.face[i].V(k) = &m.vert[tris[i][k]];
    UpdateBounding<CutMesh>::Box(m);
    UpdateNormal<CutMesh>::PerVertexNormalizedPerFace(m);
}

/// An irregular plate [0, n*cell]^2 (jittered vertices, random diagonals; edge lengths vary).
void Plate(CutMesh &m, int n, double cell, double jitter, unsigned seed)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> U(-1, 1);
    std::vector<vcg::Point3d> p;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            const bool border = i == 0 || j == 0 || i == n || j == n;
            p.push_back(vcg::Point3d(cell * (i + (border ? 0 : jitter * U(rng))), cell * (j + (border ? 0 : jitter * U(rng))), 0));
        }
    std::vector<std::array<int, 3>> t;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const int a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
            if (rng() & 1) {
                t.push_back({a, b, c});
                t.push_back({a, c, d});
            } else {
                t.push_back({a, b, d});
                t.push_back({b, c, d});
            }
        }
    Build(m, p, t);
}

/// A point of the plane z = 0 as a surface point of the plate (brute force).
SurfacePoint Locate(const CutMesh &m, const vcg::Point3d &x)
{
    int best = -1;
    vcg::Point3d bb;
    double bm = -1e300;
    for (size_t f = 0; f < m.face.size(); ++f) {
        vcg::Point3d l = CutCommit<CutMesh>::Bary(m.face[f].cP(0), m.face[f].cP(1), m.face[f].cP(2), x);
        const double mn = std::min(l[0], std::min(l[1], l[2]));
        if (mn > bm) { bm = mn; best = int(f); bb = l; }
    }
    SurfacePoint s(best, bb);
    s.Normalize();
    return s;
}

/// A polygon in the plane of a flat mesh as a curve on it: its corners and every crossing of a
/// mesh edge, in order (consecutive points share a face).
CutCurve PolygonCurve(const CutMesh &m, const std::vector<vcg::Point2d> &poly, bool closed = true)
{
    CutCurve c;
    c.closed = closed;
    const int n = int(poly.size()), ns = closed ? n : n - 1;
    for (int i = 0; i < ns; ++i) {
        const vcg::Point2d A = poly[i], B = poly[(i + 1) % n];
        std::vector<std::pair<double, SurfacePoint>> hits;
        hits.push_back({0, Locate(m, vcg::Point3d(A[0], A[1], 0))});
        for (size_t f = 0; f < m.face.size(); ++f)
            for (int k = 0; k < 3; ++k) {
                const vcg::Point2d P(m.face[f].cP(k)[0], m.face[f].cP(k)[1]);
                const vcg::Point2d Q(m.face[f].cP((k + 1) % 3)[0], m.face[f].cP((k + 1) % 3)[1]);
                const vcg::Point2d d = B - A, e = Q - P;
                const double den = d[0] * e[1] - d[1] * e[0];
                if (std::abs(den) < 1e-300) continue;
                const vcg::Point2d w = P - A;
                const double t = (w[0] * e[1] - w[1] * e[0]) / den, s = (w[0] * d[1] - w[1] * d[0]) / den;
                if (t > 0 && t < 1 && s >= 0 && s <= 1) {
                    vcg::Point3d b(0, 0, 0);
                    b[k] = 1 - s;
                    b[(k + 1) % 3] = s;
                    hits.push_back({t, SurfacePoint(int(f), b)});
                }
            }
        std::sort(hits.begin(), hits.end(), [](const auto &a, const auto &b) { return a.first < b.first; });
        for (const auto &h : hits) {
            if (!c.points.empty() && (c.points.back().Pd(m) - h.second.Pd(m)).Norm() < 1e-13) continue;
            c.points.push_back(h.second);
        }
    }
    if (!closed) c.points.push_back(Locate(m, vcg::Point3d(poly.back()[0], poly.back()[1], 0)));
    if (closed && (c.points.back().Pd(m) - c.points.front().Pd(m)).Norm() < 1e-13) c.points.pop_back();
    return c;
}

double PolygonArea(const std::vector<vcg::Point2d> &p)
{
    double a = 0;
    for (size_t i = 0; i < p.size(); ++i) a += p[i][0] * p[(i + 1) % p.size()][1] - p[(i + 1) % p.size()][0] * p[i][1];
    return std::abs(a) / 2;
}

double Area(const CutMesh &m, bool selectedOnly = false)
{
    double a = 0;
    for (const auto &f : m.face)
        if (!f.IsD() && (!selectedOnly || f.IsS())) a += vcg::DoubleArea(f) / 2;
    return a;
}

/// Everything a cut could change, to compare byte for byte.
std::string Snapshot(const CutMesh &m)
{
    std::string s;
    auto put = [&s](const void *p, size_t n) { s.append(static_cast<const char *>(p), n); };
    for (const auto &v : m.vert) {
        const auto P = v.cP();
        const auto C = v.cC();
        put(&P, sizeof P);
        put(&C, sizeof C);
        const double q = v.cQ();
        put(&q, sizeof q);
        const int fl = v.cFlags();
        put(&fl, sizeof fl);
    }
    for (const auto &f : m.face) {
        for (int k = 0; k < 3; ++k) {
            const size_t vi = vcg::tri::Index(m, f.cV(k));
            put(&vi, sizeof vi);
            const double uv[2] = {f.cWT(k).U(), f.cWT(k).V()};
            put(uv, sizeof uv);
        }
        const int fl = f.cFlags();
        put(&fl, sizeof fl);
    }
    return s;
}

/// Edges with more than two faces (vcglib's CountNonManifoldEdgeFF takes a new bit flag per call
/// and runs out of them in a long test).
int NonManifoldEdges(const CutMesh &m)
{
    std::map<std::pair<size_t, size_t>, int> n;
    for (const auto &f : m.face)
        for (int k = 0; k < 3; ++k) {
            const size_t a = Index(m, f.cV(k)), b = Index(m, f.cV((k + 1) % 3));
            ++n[{std::min(a, b), std::max(a, b)}];
        }
    int bad = 0;
    for (const auto &e : n) bad += e.second > 2;
    return bad;
}

/// Validity of a cut mesh: manifold edges, no face below 1e-12 of the mean area, none turned
/// over (normal against +z on a plate), the area preserved to 1e-9 relative.
void ExpectValid(CutMesh &m, double areaBefore, bool flat = true)
{
    EXPECT_EQ(NonManifoldEdges(m), 0);
    const double mean = Area(m) / m.fn;
    double minA = 1e300;
    for (const auto &f : m.face) {
        minA = std::min(minA, vcg::DoubleArea(f) / 2);
        if (flat) EXPECT_GT(vcg::TriangleNormal(f)[2], 0);
    }
    EXPECT_GE(minA, 1e-12 * mean);
    EXPECT_NEAR(Area(m), areaBefore, 1e-9 * areaBefore);
}

/// The faces' selection as a set of centroids' polygon membership (point in polygon).
bool InPolygon(const std::vector<vcg::Point2d> &p, const vcg::Point2d &x)
{
    bool in = false;
    for (size_t i = 0, j = p.size() - 1; i < p.size(); j = i++)
        if ((p[i][1] > x[1]) != (p[j][1] > x[1]) &&
            x[0] < (p[j][0] - p[i][0]) * (x[1] - p[i][1]) / (p[j][1] - p[i][1]) + p[i][0])
            in = !in;
    return in;
}

void ExpectSelectsPolygon(const std::vector<vcg::Point2d> &poly, int n = 12, double jitter = 0.3, unsigned seed = 3)
{
    CutMesh m;
    Plate(m, n, 1.0, jitter, seed);
    const double before = Area(m);
    const CutCurve c = PolygonCurve(m, poly);
    Cut::Param p;
    const Cut::Result r = Cut::Apply(m, {c}, p);
    ExpectValid(m, before);
    EXPECT_NEAR(Area(m, true), PolygonArea(poly), 1e-9 * before);
    EXPECT_NEAR(r.areaInside, PolygonArea(poly), 1e-9 * before);
    for (const auto &f : m.face) {
        const vcg::Point3d g = vcg::Barycenter(f);
        EXPECT_EQ(f.IsS(), InPolygon(poly, vcg::Point2d(g[0], g[1])));
    }
}

} // namespace

TEST(MeshCutTest, PolygonOnIrregularPlateSelectsItsArea)
{
    ExpectSelectsPolygon({{2.3, 2.7}, {8.6, 3.1}, {9.2, 8.4}, {5.5, 6.1}, {3.1, 9.0}});
}

TEST(MeshCutTest, LoopThroughVerticesAndAlongEdges)
{
    // a regular plate: the square runs along mesh edges, the diamond through vertices
    ExpectSelectsPolygon({{2, 2}, {7, 2}, {7, 6}, {2, 6}}, 10, 0.0, 1);
    ExpectSelectsPolygon({{5, 1}, {9, 5}, {5, 9}, {1, 5}}, 10, 0.0, 2);
}

TEST(MeshCutTest, SeveralCrossingsOfOneEdge)
{
    // two triangles; a zigzag loop crosses their shared diagonal six times
    CutMesh m;
    Build(m, {{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0}}, {{0, 1, 2}, {0, 2, 3}});
    std::vector<vcg::Point2d> poly = {{2, 1}, {3.5, 5}, {2.5, 1.2}, {4.2, 6.3}, {4.5, 1}, {8.7, 9.4}, {1, 8.8}};
    const double before = Area(m);
    const CutCurve c = PolygonCurve(m, poly);
    int onDiagonal = 0;
    for (const auto &p : c.points) {
        const vcg::Point3d x = p.Pd(m);
        if (std::abs(x[0] - x[1]) < 1e-12) ++onDiagonal;
    }
    EXPECT_GE(onDiagonal, 6);
    const Cut::Result r = Cut::Apply(m, {c}, Cut::Param());
    ExpectValid(m, before);
    EXPECT_NEAR(Area(m, true), PolygonArea(poly), 1e-9 * before);
    EXPECT_GT(r.addedVertices, 10);
}

TEST(MeshCutTest, CrossingsWithinTinyDistanceOfVertices)
{
    // a regular plate; the polygon passes 1e-9 (and 1e-13) from vertices: snapped, no sliver
    const double e = 1e-9;
    ExpectSelectsPolygon({{2 + e, 2 - e}, {7 - 1e-13, 2 + e}, {7 + e, 6 + 1e-13}, {2.5, 6 - e}}, 10, 0.0, 1);
    ExpectSelectsPolygon({{3 + e, 1.5}, {8.5, 4 - e}, {6 - e, 8.0 + e}, {1.5 + e, 5}}, 10, 0.0, 1);
}

TEST(MeshCutTest, TubeRingSplitsIntoTwoPartsWithTheRingAsBoundary)
{
    // an open tube of radius 1 and height 2, irregular rows; cut by the plane z = 0.2 + 0.1 x
    const int nt = 40, nz = 9;
    std::vector<vcg::Point3d> p;
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> U(-0.3, 0.3);
    for (int j = 0; j <= nz; ++j)
        for (int i = 0; i < nt; ++i) {
            const double a = 2 * M_PI * (i + (j % 2) * 0.5) / nt;
            const double z = -1 + 2.0 * j / nz + (j > 0 && j < nz ? U(rng) * 2.0 / nz : 0);
            p.push_back(vcg::Point3d(std::cos(a), std::sin(a), z));
        }
    std::vector<std::array<int, 3>> t;
    for (int j = 0; j < nz; ++j)
        for (int i = 0; i < nt; ++i) {
            const int a = j * nt + i, b = j * nt + (i + 1) % nt, c = (j + 1) * nt + (i + 1) % nt, d = (j + 1) * nt + i;
            t.push_back({a, b, c});
            t.push_back({a, c, d});
        }
    CutMesh m;
    Build(m, p, t);
    const vcg::Point3d nrm(-0.1, 0, 1);
    const double off = 0.2;
    auto side = [&](const vcg::Point3d &x) { return x * nrm - off; };
    // the section: per face the plane's crossings of its edges, chained face to face
    std::map<std::pair<int, int>, SurfacePoint> cross;
    std::map<std::pair<int, int>, std::vector<int>> edgeFaces;
    for (size_t f = 0; f < m.face.size(); ++f)
        for (int k = 0; k < 3; ++k) {
            int a = int(Index(m, m.face[f].V(k))), b = int(Index(m, m.face[f].V((k + 1) % 3)));
            const double sa = side(m.vert[a].P()), sb = side(m.vert[b].P());
            if ((sa < 0) == (sb < 0)) continue;
            vcg::Point3d bary(0, 0, 0);
            bary[k] = sb / (sb - sa);
            bary[(k + 1) % 3] = -sa / (sb - sa);
            std::pair<int, int> key(std::min(a, b), std::max(a, b));
            cross[key] = SurfacePoint(int(f), bary);
            edgeFaces[key].push_back(int(f));
        }
    CutCurve c;
    c.closed = true;
    std::pair<int, int> cur = cross.begin()->first;
    int face = edgeFaces[cur][0];
    for (size_t n = 0; n < cross.size(); ++n) {
        c.points.push_back(cross[cur]);
        for (int k = 0; k < 3; ++k) { // the face's other crossed edge
            int a = int(Index(m, m.face[face].V(k))), b = int(Index(m, m.face[face].V((k + 1) % 3)));
            std::pair<int, int> key(std::min(a, b), std::max(a, b));
            if (key != cur && cross.count(key)) { cur = key; break; }
        }
        const auto &ef = edgeFaces[cur];
        face = ef[0] == face ? ef[1] : ef[0];
    }
    // the parts' exact areas: every face clipped by the plane
    double below = 0, total = Area(m);
    for (const auto &f : m.face) {
        std::vector<vcg::Point3d> poly;
        for (int k = 0; k < 3; ++k) {
            const vcg::Point3d a = f.cP(k), b = f.cP((k + 1) % 3);
            if (side(a) < 0) poly.push_back(a);
            if ((side(a) < 0) != (side(b) < 0)) poly.push_back(a + (b - a) * (side(a) / (side(a) - side(b))));
        }
        for (size_t i = 1; i + 1 < poly.size(); ++i) below += ((poly[i] - poly[0]) ^ (poly[i + 1] - poly[0])).Norm() / 2;
    }
    CutMesh in, out;
    Cut::Param prm;
    const std::string before = Snapshot(m);
    const Cut::Result r = Cut::Split(m, {c}, prm, in, out);
    EXPECT_EQ(Snapshot(m), before); // split leaves the mesh alone
    // the smaller part is above the plane (z from ~0.2 to 1)
    EXPECT_NEAR(Area(out), below, 1e-9 * total);
    EXPECT_NEAR(Area(in), total - below, 1e-9 * total);
    // the analytic areas, to the discretisation (1%): 2 pi r (z + 1) below, with z = 0.2 on average
    EXPECT_NEAR(Area(out), 2 * M_PI * 1.2, 0.01 * 2 * M_PI * 1.2);
    EXPECT_NEAR(Area(in), 2 * M_PI * 0.8, 0.01 * 2 * M_PI * 0.8);
    EXPECT_GT(r.addedVertices, nt);
    // each part: one boundary loop at the cut, the ring's polyline within 1e-6 of the diagonal
    const double diag = m.bbox.Diag();
    for (CutMesh *part : {&in, &out}) {
        UpdateTopology<CutMesh>::FaceFace(*part);
        EXPECT_EQ(NonManifoldEdges(*part), 0);
        std::vector<vcg::Point3d> bnd;
        for (auto &f : part->face)
            for (int k = 0; k < 3; ++k)
                if (vcg::face::IsBorder(f, k) && std::abs(side(f.P(k))) < 1e-9 && std::abs(side(f.P((k + 1) % 3))) < 1e-9)
                    bnd.push_back(f.P(k));
        EXPECT_EQ(int(bnd.size()), r.curveVertices);
        // Hausdorff between the boundary at the cut and the polyline's points, both ways
        double h = 0;
        for (const auto &b : bnd) {
            double d = 1e300;
            for (const auto &q : c.points) d = std::min(d, (q.Pd(m) - b).Norm());
            // boundary vertices are the polyline's points or lie on its segments
            if (d > 1e-6 * diag) {
                for (size_t i = 0; i < c.points.size(); ++i) {
                    vcg::Point3d a = c.points[i].Pd(m), e = c.points[(i + 1) % c.points.size()].Pd(m);
                    double t = std::max(0.0, std::min(1.0, ((b - a) * (e - a)) / (e - a).SquaredNorm()));
                    d = std::min(d, (a + (e - a) * t - b).Norm());
                }
            }
            h = std::max(h, d);
        }
        for (const auto &q : c.points) {
            double d = 1e300;
            for (const auto &b : bnd) d = std::min(d, (q.Pd(m) - b).Norm());
            h = std::max(h, d);
        }
        EXPECT_LE(h, 1e-6 * diag);
        // and the part's boundary edges besides the cut are the tube's rim: 1 + 1 loops
        int borderEdges = 0;
        for (auto &f : part->face)
            for (int k = 0; k < 3; ++k) borderEdges += vcg::face::IsBorder(f, k);
        EXPECT_EQ(borderEdges, r.curveVertices + nt);
    }
}

TEST(MeshCutTest, TorusMeridianIsRefusedAndTheMeshUnchanged)
{
    const int nu = 24, nv = 12;
    std::vector<vcg::Point3d> p;
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            const double u = 2 * M_PI * i / nu, v = 2 * M_PI * j / nv;
            p.push_back(vcg::Point3d((2 + 0.6 * std::cos(v)) * std::cos(u), (2 + 0.6 * std::cos(v)) * std::sin(u), 0.6 * std::sin(v)));
        }
    std::vector<std::array<int, 3>> t;
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            const int a = i * nv + j, b = ((i + 1) % nu) * nv + j, c = ((i + 1) % nu) * nv + (j + 1) % nv,
                      d = i * nv + (j + 1) % nv;
            t.push_back({a, b, c});
            t.push_back({a, c, d});
        }
    CutMesh m;
    Build(m, p, t);
    // the meridian u = 0: the vertices i = 0, as corners of their faces
    CutCurve c;
    c.closed = true;
    for (int j = 0; j < nv; ++j) {
        const int face = 2 * (0 * nv + j); // (a, b, c) with a = vertex (0, j)
        c.points.push_back(SurfacePoint::AtCorner(face, 0));
    }
    const std::string before = Snapshot(m);
    for (CutMode mode : {CutMode::Select, CutMode::SelectOnly}) {
        Cut::Param prm;
        prm.mode = mode;
        try {
            Cut::Apply(m, {c}, prm);
            ADD_FAILURE() << "a torus meridian was cut";
        } catch (const SnakeError &e) {
            EXPECT_NE(std::string(e.what()).find("does not separate"), std::string::npos) << e.what();
        }
        EXPECT_EQ(Snapshot(m), before);
    }
    CutMesh in, out;
    EXPECT_THROW(Cut::Split(m, {c}, Cut::Param(), in, out), SnakeError);
    EXPECT_EQ(Snapshot(m), before);
    // cut open, the meridian makes the torus a tube: allowed
    Cut::Param open;
    open.mode = CutMode::CutOpen;
    Cut::Apply(m, {c}, open);
    UpdateTopology<CutMesh>::FaceFace(m);
    int border = 0;
    for (auto &f : m.face)
        for (int k = 0; k < 3; ++k) border += vcg::face::IsBorder(f, k);
    EXPECT_EQ(border, 2 * nv);
}

TEST(MeshCutTest, FigureEightAndForeignCurvesAreRefusedAndTheMeshUnchanged)
{
    CutMesh m;
    Plate(m, 10, 1.0, 0.3, 7);
    const std::string before = Snapshot(m);
    auto refused = [&](const CutCurve &c, const std::string &why) {
        for (CutMode mode : {CutMode::Select, CutMode::SelectOnly, CutMode::CutOpen}) {
            Cut::Param prm;
            prm.mode = mode;
            try {
                Cut::Apply(m, {c}, prm);
                ADD_FAILURE() << "not refused: " << why;
            } catch (const SnakeError &e) {
                EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
            }
            EXPECT_EQ(Snapshot(m), before);
        }
    };
    // a figure eight: crosses itself inside a face
    refused(PolygonCurve(m, {{2, 2}, {8, 8}, {8, 2}, {2, 8}}), "crosses or touches itself");
    // faces out of range (a curve of a larger mesh)
    CutCurve big = PolygonCurve(m, {{2, 2}, {8, 2}, {5, 8}});
    big.points[3].face = int(m.face.size()) + 10;
    refused(big, "not on this mesh");
    // points off their face
    CutCurve off = PolygonCurve(m, {{2, 2}, {8, 2}, {5, 8}});
    off.points[2].bary = vcg::Point3d(1.7, -0.7, 0);
    refused(off, "not on this mesh");
    // consecutive points that share no face (the indices of another mesh)
    CutCurve other = PolygonCurve(m, {{2, 2}, {8, 2}, {5, 8}});
    std::swap(other.points[2], other.points[7]);
    refused(other, "not on this mesh");
}

TEST(MeshCutTest, OpenCurvesBoundaryToBoundarySelectAndEndingInsideOnlySlit)
{
    CutMesh m;
    Plate(m, 10, 1.0, 0.3, 9);
    const double before = Area(m);
    const CutCurve across = PolygonCurve(m, {{0, 3.3}, {4.5, 5.2}, {10, 4.1}}, false);
    Cut::Param prm;
    prm.side = CutSide::Inside; // the left of the curve: above it
    Cut::Apply(m, {across}, prm);
    ExpectValid(m, before);
    const double below = PolygonArea({{0, 0}, {10, 0}, {10, 4.1}, {4.5, 5.2}, {0, 3.3}});
    EXPECT_NEAR(Area(m, true), 100 - below, 1e-9 * before);

    CutMesh s;
    Plate(s, 10, 1.0, 0.3, 9);
    const std::string snap = Snapshot(s);
    const CutCurve slit = PolygonCurve(s, {{2.5, 3.3}, {4.5, 5.2}, {7.2, 4.1}}, false);
    try {
        Cut::Apply(s, {slit}, Cut::Param());
        ADD_FAILURE() << "an open curve ending inside was selected";
    } catch (const SnakeError &e) {
        EXPECT_NE(std::string(e.what()).find("ends inside the mesh"), std::string::npos) << e.what();
    }
    EXPECT_EQ(Snapshot(s), snap);
    prm.mode = CutMode::CutOpen;
    const Cut::Result r = Cut::Apply(s, {slit}, prm);
    ExpectValid(s, before);
    UpdateTopology<CutMesh>::FaceFace(s);
    int border = 0;
    for (auto &f : s.face)
        for (int k = 0; k < 3; ++k) border += vcg::face::IsBorder(f, k);
    const int curveEdges = r.curveVertices - 1;
    EXPECT_EQ(border, 40 + 2 * curveEdges); // the plate's rim and both lips of the slit
}

TEST(MeshCutTest, SelectOnlyKeepsTheMeshAndSelectsByCentroid)
{
    CutMesh m;
    Plate(m, 12, 1.0, 0.3, 11);
    const std::vector<vcg::Point2d> poly = {{2.3, 2.7}, {8.6, 3.1}, {9.2, 8.4}, {3.1, 9.0}};
    const CutCurve c = PolygonCurve(m, poly);
    const size_t vn = m.vert.size(), fn = m.face.size();
    Cut::Param prm;
    prm.mode = CutMode::SelectOnly;
    Cut::Apply(m, {c}, prm);
    EXPECT_EQ(m.vert.size(), vn);
    EXPECT_EQ(m.face.size(), fn);
    for (const auto &f : m.face) {
        const vcg::Point3d g = vcg::Barycenter(f);
        EXPECT_EQ(f.IsS(), InPolygon(poly, vcg::Point2d(g[0], g[1])));
    }
}

TEST(MeshCutTest, TextureAndColourSurviveASplit)
{
    CutMesh m;
    Plate(m, 8, 1.0, 0.3, 13);
    // per-wedge uv = a linear map of xy with a seam (faces with x < 4 in a second chart);
    // colour and quality linear in x and y
    auto uv = [](const vcg::Point3d &x, bool chart) {
        return vcg::Point2d(0.1 * x[0] + 0.02 * x[1] + (chart ? 0.5 : 0), 0.03 * x[0] + 0.09 * x[1]);
    };
    for (auto &v : m.vert) {
        v.C() = vcg::Color4b((unsigned char)(25 * v.P()[0]), (unsigned char)(30 * v.P()[1]), 100, 255);
        v.Q() = 3 * v.P()[0] - v.P()[1];
    }
    for (auto &f : m.face) {
        const bool chart = vcg::Barycenter(f)[0] < 4;
        for (int k = 0; k < 3; ++k) {
            const vcg::Point2d t = uv(f.P(k), chart);
            f.WT(k).U() = t[0];
            f.WT(k).V() = t[1];
        }
    }
    CutMesh orig;
    Append<CutMesh, CutMesh>::MeshCopy(orig, m);
    const CutCurve c = PolygonCurve(m, {{1.3, 1.7}, {6.6, 2.1}, {5.2, 6.4}, {1.1, 5.0}});
    CutMesh in, out;
    Cut::Split(m, {c}, Cut::Param(), in, out);
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> U(0.05, 0.9);
    int compared = 0;
    for (CutMesh *part : {&in, &out})
        for (const auto &f : part->face) {
            double a = U(rng), b = U(rng) * (1 - a);
            const vcg::Point3d l(a, b, 1 - a - b);
            const vcg::Point3d x = f.cP(0) * l[0] + f.cP(1) * l[1] + f.cP(2) * l[2];
            vcg::Point2d t(0, 0);
            double q = 0, red = 0;
            for (int k = 0; k < 3; ++k) {
                t += vcg::Point2d(f.cWT(k).U(), f.cWT(k).V()) * l[k];
                q += f.cV(k)->cQ() * l[k];
                red += f.cV(k)->cC()[0] * l[k];
            }
            const SurfacePoint o = Locate(orig, x);
            const auto &g = orig.face[o.face];
            vcg::Point2d to(0, 0);
            double qo = 0, redo = 0;
            for (int k = 0; k < 3; ++k) {
                to += vcg::Point2d(g.cWT(k).U(), g.cWT(k).V()) * o.bary[k];
                qo += g.cV(k)->cQ() * o.bary[k];
                redo += g.cV(k)->cC()[0] * o.bary[k];
            }
            EXPECT_NEAR(t[0], to[0], 1e-12);
            EXPECT_NEAR(t[1], to[1], 1e-12);
            EXPECT_NEAR(q, qo, 1e-9);
            EXPECT_NEAR(red, redo, 1.0); // colours are bytes
            ++compared;
        }
    EXPECT_GT(compared, int(orig.face.size()));
}

// ---------------------------------------------------------------- real part boundaries
namespace {

/// The boundary of label `lab` of a segmentation as curves of vertices (one per loop).
std::vector<CutCurve> PartBoundary(const CutMesh &m, const std::vector<int> &label, int lab)
{
    std::map<std::pair<int, int>, std::vector<std::pair<int, int>>> edges; // edge -> (face, corner)
    for (size_t f = 0; f < m.face.size(); ++f)
        for (int k = 0; k < 3; ++k) {
            int a = int(Index(m, m.face[f].cV(k))), b = int(Index(m, m.face[f].cV((k + 1) % 3)));
            edges[{std::min(a, b), std::max(a, b)}].push_back({int(f), k});
        }
    std::map<int, std::pair<int, int>> next; // directed along the part's faces: a -> b, with a face holding a
    for (const auto &e : edges) {
        if (e.second.size() != 2) continue;
        const auto x = e.second[0], y = e.second[1];
        if ((label[x.first] == lab) == (label[y.first] == lab)) continue;
        const auto in = label[x.first] == lab ? x : y;
        const int a = int(Index(m, m.face[in.first].cV(in.second)));
        next[a] = {int(Index(m, m.face[in.first].cV((in.second + 1) % 3))), in.first};
    }
    std::vector<CutCurve> out;
    std::set<int> used;
    for (const auto &s : next) {
        if (used.count(s.first)) continue;
        CutCurve c;
        c.closed = true;
        int v = s.first;
        while (!used.count(v) && next.count(v)) {
            used.insert(v);
            const int f = next[v].second;
            int k = 0;
            while (int(Index(m, m.face[f].cV(k))) != v) ++k;
            c.points.push_back(SurfacePoint::AtCorner(f, k));
            v = next[v].first;
        }
        out.push_back(c);
    }
    return out;
}

} // namespace

TEST(MeshCutTest, PersonsPartBoundarySelectsExactlyThatPart)
{
    const std::string dir = std::string(GS_DATA_DIR) + "/../../shared/data/segmentation/";
    struct Case { const char *id; int person; };
    int tested = 0;
    for (const Case cs : {Case{"181", 0}, Case{"3", 0}}) {
        CutMesh m;
        int mask = 0;
        if (vcg::tri::io::ImporterOFF<CutMesh>::Open(m, (dir + "off/" + cs.id + ".off").c_str(), mask) != 0) {
            ADD_FAILURE() << "cannot read " << cs.id;
            continue;
        }
        std::ifstream seg(dir + "seg/" + cs.id + "/" + cs.id + "_" + std::to_string(cs.person) + ".seg");
        std::vector<int> label;
        for (int l; seg >> l;) label.push_back(l);
        ASSERT_EQ(label.size(), m.face.size());
        UpdateBounding<CutMesh>::Box(m);
        const double total = Area(m);
        // every label whose part is bounded by one loop
        std::set<int> labels(label.begin(), label.end());
        for (int lab : labels) {
            const std::vector<CutCurve> b = PartBoundary(m, label, lab);
            if (b.size() != 1 || b[0].points.size() < 3) continue;
            double partArea = 0;
            for (size_t f = 0; f < m.face.size(); ++f)
                if (label[f] == lab) partArea += vcg::DoubleArea(m.face[f]) / 2;
            CutMesh c;
            Append<CutMesh, CutMesh>::MeshCopy(c, m);
            Cut::Param prm;
            prm.side = partArea < total / 2 ? CutSide::Smaller : CutSide::Larger;
            const Cut::Result r = Cut::Apply(c, b, prm);
            EXPECT_EQ(r.addedVertices, 0);
            int wrong = 0;
            for (size_t f = 0; f < c.face.size(); ++f) wrong += c.face[f].IsS() != (label[f] == lab);
            EXPECT_EQ(wrong, 0) << "mesh " << cs.id << " label " << lab;
            ++tested;
        }
    }
    EXPECT_GE(tested, 4);
}

TEST(MeshCutTest, InsideIsTheEnclosedSideWhateverTheDirection)
{
    // a loop enclosing 70% of the plate: "smaller" is outside it, "inside" is the enclosed side,
    // whichever way the loop runs (as the Balloon decides its outside)
    std::vector<vcg::Point2d> poly = {{0.7, 0.6}, {9.4, 0.8}, {9.2, 9.3}, {0.5, 9.1}};
    const double enclosed = PolygonArea(poly);
    for (int dir = 0; dir < 2; ++dir) {
        CutMesh m;
        Plate(m, 10, 1.0, 0.3, 21);
        if (dir) std::reverse(poly.begin(), poly.end());
        const CutCurve c = PolygonCurve(m, poly);
        Cut::Param prm;
        prm.side = CutSide::Inside;
        Cut::Apply(m, {c}, prm);
        EXPECT_NEAR(Area(m, true), enclosed, 1e-9 * 100) << "direction " << dir;
        prm.side = CutSide::Smaller;
        CutMesh s;
        Plate(s, 10, 1.0, 0.3, 21);
        Cut::Apply(s, {PolygonCurve(s, poly)}, prm);
        EXPECT_NEAR(Area(s, true), 100 - enclosed, 1e-9 * 100);
    }
}

TEST(MeshCutTest, NonManifoldEdgeAlongTheCutIsRefused)
{
    CutMesh m;
    Plate(m, 6, 1.0, 0.0, 1);
    // a fin on the interior edge between vertices (2,3) and (3,3): three faces on that edge
    std::vector<vcg::Point3d> p;
    std::vector<std::array<int, 3>> t;
    for (const auto &v : m.vert) p.push_back(v.cP());
    for (const auto &f : m.face) t.push_back({int(Index(m, f.cV(0))), int(Index(m, f.cV(1))), int(Index(m, f.cV(2)))});
    const int a = 3 * 7 + 2, b = 3 * 7 + 3;
    p.push_back(vcg::Point3d(2.5, 3.0, 1.0));
    t.push_back({a, b, int(p.size()) - 1});
    Build(m, p, t);
    const std::string before = Snapshot(m);
    // an open curve crossing that edge
    const CutCurve across = PolygonCurve(m, {{2.5, 2.5}, {2.7, 3.5}, {1.5, 3.6}});
    try {
        Cut::Apply(m, {across}, Cut::Param());
        ADD_FAILURE() << "a cut across a non-manifold edge";
    } catch (const SnakeError &e) {
        EXPECT_NE(std::string(e.what()).find("not manifold"), std::string::npos) << e.what();
    }
    EXPECT_EQ(Snapshot(m), before);
}

TEST(MeshCutTest, MeshLabMeshSplitKeepsItsOptionalTextureCoordinates)
{
    // CMeshO keeps wedge texture coordinates and face quality optional: the parts have them too
    CutMesh d;
    Plate(d, 6, 1.0, 0.2, 5);
    CMeshO m;
    Allocator<CMeshO>::AddVertices(m, d.vert.size());
    for (size_t i = 0; i < d.vert.size(); ++i) m.vert[i].P() = CMeshO::CoordType::Construct(d.vert[i].P());
    Allocator<CMeshO>::AddFaces(m, d.face.size());
    m.face.EnableWedgeTexCoord();
    m.face.EnableQuality();
    for (size_t f = 0; f < d.face.size(); ++f)
        for (int k = 0; k < 3; ++k) {
            m.face[f].V(k) = &m.vert[Index(d, d.face[f].V(k))];
            m.face[f].WT(k).U() = 0.1f * m.face[f].V(k)->P()[0];
            m.face[f].WT(k).V() = 0.1f * m.face[f].V(k)->P()[1];
        }
    CutCurve c = PolygonCurve(d, {{1.3, 1.7}, {4.6, 2.1}, {3.2, 4.4}});
    CMeshO in, out;
    MeshCut<CMeshO>::Split(m, {c}, MeshCut<CMeshO>::Param(), in, out);
    for (CMeshO *part : {&in, &out}) {
        ASSERT_TRUE(part->face.IsWedgeTexCoordEnabled());
        EXPECT_TRUE(part->face.IsQualityEnabled());
        for (const auto &f : part->face)
            for (int k = 0; k < 3; ++k) {
                EXPECT_NEAR(f.cWT(k).U(), 0.1 * f.cV(k)->cP()[0], 1e-6);
                EXPECT_NEAR(f.cWT(k).V(), 0.1 * f.cV(k)->cP()[1], 1e-6);
            }
    }
}

TEST(MeshCutTest, NonManifoldVertexAlongTheCutIsRefused)
{
    // a regular plate and a fin of one face touching it only at the inner vertex (3,3): two
    // sheets of faces meet there; the square loop (1,1)-(3,1)-(3,3)-(1,3) runs through it
    CutMesh m;
    Plate(m, 6, 1.0, 0.0, 1);
    const CutCurve loop = PolygonCurve(m, {{1, 1}, {3, 1}, {3, 3}, {1, 3}});
    std::vector<vcg::Point3d> p;
    std::vector<std::array<int, 3>> t;
    for (const auto &v : m.vert) p.push_back(v.cP());
    for (const auto &f : m.face) t.push_back({int(Index(m, f.cV(0))), int(Index(m, f.cV(1))), int(Index(m, f.cV(2)))});
    const int centre = 3 * 7 + 3;
    p.push_back(vcg::Point3d(3.5, 3.5, 1.0));
    p.push_back(vcg::Point3d(3.2, 3.8, 1.0));
    t.push_back({centre, int(p.size()) - 2, int(p.size()) - 1});
    Build(m, p, t); // the plate's faces keep their indices: the loop is still on them
    const std::string before = Snapshot(m);
    for (CutMode mode : {CutMode::Select, CutMode::SelectOnly, CutMode::CutOpen}) {
        Cut::Param prm;
        prm.mode = mode;
        try {
            Cut::Apply(m, {loop}, prm);
            ADD_FAILURE() << "a cut through a non-manifold vertex, mode " << Cut::ModeName(mode);
        } catch (const SnakeError &e) {
            EXPECT_NE(std::string(e.what()).find("separate sheets of faces meet"), std::string::npos) << e.what();
        }
        EXPECT_EQ(Snapshot(m), before);
    }
    CutMesh in, out;
    EXPECT_THROW(Cut::Split(m, {loop}, Cut::Param(), in, out), SnakeError);
    EXPECT_EQ(Snapshot(m), before);
    EXPECT_EQ(in.fn + out.fn, 0);
    // the same loop moved off that vertex is cut
    const CutCurve away = PolygonCurve(m, {{1, 1}, {2.5, 1}, {2.5, 2.5}, {1, 2.5}});
    Cut::Apply(m, {away}, Cut::Param());
    EXPECT_NEAR(Area(m, true), 2.25, 1e-12);
}

TEST(MeshCutTest, NewVerticesInterpolateNormalsColourAndQuality)
{
    // per-vertex attributes linear in x and y: normal (x, y, 10) (not unit), colour (10x, 10y,
    // 7, 255), quality x - 2y. Linear interpolation in the face a new vertex lies in gives the
    // same functions at it exactly (up to round-off); the normal is then normalised.
    CutMesh m;
    Plate(m, 10, 1.0, 0.3, 4);
    for (auto &v : m.vert) {
        const double x = v.P()[0], y = v.P()[1];
        v.N() = vcg::Point3d(x, y, 10);
        v.C() = vcg::Color4b((unsigned char)std::lround(10 * x), (unsigned char)std::lround(10 * y), 7, 255);
        v.Q() = x - 2 * y;
    }
    const size_t vn = m.vert.size();
    const CutCurve c = PolygonCurve(m, {{2.3, 2.7}, {8.6, 3.1}, {9.2, 8.4}, {3.1, 9.0}});
    const Cut::Result r = Cut::Apply(m, {c}, Cut::Param());
    ASSERT_GT(r.addedVertices, 20);
    for (size_t i = vn; i < m.vert.size(); ++i) {
        const auto &v = m.vert[i];
        const double x = v.cP()[0], y = v.cP()[1];
        const vcg::Point3d n = vcg::Point3d(x, y, 10).Normalize();
        EXPECT_NEAR((v.cN() - n).Norm(), 0, 1e-12) << "vertex " << i;
        EXPECT_NEAR(v.cQ(), x - 2 * y, 1e-12) << "vertex " << i;
        EXPECT_EQ(v.cC()[2], 7);
        EXPECT_EQ(v.cC()[3], 255);
        EXPECT_NEAR(v.cC()[0], 10 * x, 1.0) << "vertex " << i; // bytes: inputs and output rounded
        EXPECT_NEAR(v.cC()[1], 10 * y, 1.0) << "vertex " << i;
    }
}

TEST(MeshCutTest, SurfacePointsOfTheMeshBeforeTheCutMapOntoItAfter)
{
    // points of the user's snakes are face + barycentric of the mesh before the cut: the map
    // gives the same points in space on the faces after it, inside their faces; the curve's own
    // points land on the embedded curve's vertices
    for (CutMode mode : {CutMode::Select, CutMode::CutOpen}) {
        CutMesh m;
        Plate(m, 12, 1.0, 0.3, 21);
        const CutCurve c = PolygonCurve(m, {{2.3, 2.7}, {8.6, 3.1}, {9.2, 8.4}, {5.5, 6.1}, {3.1, 9.0}});
        std::mt19937 rng(5);
        std::uniform_real_distribution<double> U(0, 1);
        std::vector<SurfacePoint> pts = c.points;
        for (int i = 0; i < 3000; ++i) {
            double a = U(rng), b = U(rng);
            if (a + b > 1) { a = 1 - a; b = 1 - b; }
            pts.push_back(SurfacePoint(int(rng() % m.face.size()), vcg::Point3d(a, b, 1 - a - b)));
        }
        std::vector<vcg::Point3d> xyz;
        for (const auto &p : pts) xyz.push_back(p.Pd(m));
        Cut::Param prm;
        prm.mode = mode;
        const Cut::Result r = Cut::Apply(m, {c}, prm);
        ASSERT_GT(r.points.SplitFaces(), 20u);
        std::vector<SurfacePoint> mapped = pts;
        r.points.MapAll(mapped);
        int moved = 0;
        for (size_t i = 0; i < pts.size(); ++i) {
            const SurfacePoint &q = mapped[i];
            ASSERT_TRUE(q.OnMesh(m)) << i;
            for (int k = 0; k < 3; ++k) EXPECT_GE(q.bary[k], 0.0);
            EXPECT_NEAR(q.bary[0] + q.bary[1] + q.bary[2], 1.0, 1e-15);
            EXPECT_LT((q.Pd(m) - xyz[i]).Norm(), 1e-12) << "point " << i << " mode " << Cut::ModeName(mode);
            moved += q.face != pts[i].face;
            if (i < c.points.size()) // on the curve: at a vertex of the mesh after the cut
                EXPECT_NEAR(std::max(q.bary[0], std::max(q.bary[1], q.bary[2])), 1.0, 1e-9) << "curve point " << i;
        }
        EXPECT_GT(moved, 100); // many points were in split faces and went to added sub-faces
    }
    // the select-only mode does not change the mesh: its map is the identity
    CutMesh m;
    Plate(m, 8, 1.0, 0.3, 2);
    Cut::Param only;
    only.mode = CutMode::SelectOnly;
    const Cut::Result r = Cut::Apply(m, {PolygonCurve(m, {{2.3, 2.7}, {6.6, 3.1}, {3.1, 6.0}})}, only);
    EXPECT_EQ(r.points.SplitFaces(), 0u);
    const SurfacePoint p(17, vcg::Point3d(0.2, 0.3, 0.5));
    EXPECT_EQ(r.points.Map(p).face, 17);
}

TEST(MeshCutTest, ACurveCutAgainRunsAlongTheEdgesOfItsFirstCut)
{
    // the edit tool: Select inside embeds the snake; the curve traced again on the cut mesh runs
    // along its edges: selecting again adds nothing, cutting open adds a copy of each curve vertex
    CutMesh m;
    Plate(m, 10, 1.0, 0.0, 1);
    const double before = Area(m);
    const std::vector<vcg::Point2d> square = {{2.5, 2.5}, {7.5, 2.5}, {7.5, 7.5}, {2.5, 7.5}};
    Cut::Apply(m, {PolygonCurve(m, square)}, Cut::Param());
    const CutCurve c = PolygonCurve(m, square);
    const size_t vn = m.vert.size();
    const Cut::Result again = Cut::Apply(m, {c}, Cut::Param());
    EXPECT_EQ(m.vert.size(), vn);
    EXPECT_EQ(again.addedVertices, 0);
    EXPECT_NEAR(again.areaInside, 25, 1e-9);
    Cut::Param open;
    open.mode = CutMode::CutOpen;
    const Cut::Result o = Cut::Apply(m, {c}, open);
    EXPECT_EQ(o.addedVertices, o.curveVertices); // one copy of each curve vertex, nothing else
    ExpectValid(m, before);
    UpdateTopology<CutMesh>::FaceFace(m);
    int border = 0;
    for (auto &f : m.face)
        for (int k = 0; k < 3; ++k) border += vcg::face::IsBorder(f, k);
    EXPECT_EQ(border, 40 + 2 * o.curveVertices); // the plate's rim and both lips of the square
}

TEST(MeshCutTest, APlanSaysWhetherTheMeshWillChangeAndChangesNothing)
{
    // the edit tool copies the mesh for its undo only when the cut will change it (Plan first)
    CutMesh m;
    Plate(m, 10, 1.0, 0.3, 5);
    const std::vector<vcg::Point2d> poly = {{2.3, 2.7}, {7.4, 3.1}, {6.2, 7.3}, {2.9, 6.6}};
    const std::string before = Snapshot(m);
    Cut::Planned first = Cut::Plan(m, {PolygonCurve(m, poly)}, Cut::Param());
    EXPECT_TRUE(first.ChangesMesh());
    EXPECT_GT(first.AddedVertices(), 0);
    EXPECT_EQ(Snapshot(m), before); // planning wrote nothing
    const size_t vn = m.vert.size();
    const Cut::Result r = Cut::Apply(m, std::move(first));
    EXPECT_EQ(int(m.vert.size() - vn), r.addedVertices);
    EXPECT_GT(r.addedVertices, 0);
    // the embedded chain (as the edit tool's snake keeps it): nothing left to embed
    const CutCurve chain{r.chains[0], true};
    Cut::Planned again = Cut::Plan(m, {chain}, Cut::Param());
    EXPECT_FALSE(again.ChangesMesh());
    EXPECT_EQ(again.AddedVertices(), 0);
    EXPECT_EQ(again.AddedFaces(), 0);
    const Cut::Result r2 = Cut::Apply(m, std::move(again));
    EXPECT_EQ(m.vert.size(), vn + size_t(r.addedVertices));
    EXPECT_EQ(r2.addedVertices + r2.addedFaces, 0);
    EXPECT_EQ(r2.facesInside, r.facesInside);
    // the same curve cut open changes the mesh; selecting by centroids never does
    Cut::Param open;
    open.mode = CutMode::CutOpen;
    EXPECT_TRUE(Cut::Plan(m, {chain}, open).ChangesMesh());
    Cut::Param only;
    only.mode = CutMode::SelectOnly;
    CutMesh fresh;
    Plate(fresh, 10, 1.0, 0.3, 5);
    EXPECT_FALSE(Cut::Plan(fresh, {PolygonCurve(fresh, poly)}, only).ChangesMesh());
    // a plan of a mesh changed since is refused, the mesh as it was
    Cut::Planned stale = Cut::Plan(fresh, {PolygonCurve(fresh, poly)}, Cut::Param());
    Cut::Apply(fresh, {PolygonCurve(fresh, poly)}, Cut::Param());
    const std::string cutFresh = Snapshot(fresh);
    EXPECT_THROW(Cut::Apply(fresh, std::move(stale)), SnakeError);
    EXPECT_EQ(Snapshot(fresh), cutFresh);
}

TEST(MeshCutTest, ASmallPartOfASplitIsWholeAndItsOwnSize)
{
    // a part under an eighth of the mesh: the vertex table both parts share is reset between them
    CutMesh m, in, out;
    Plate(m, 24, 1.0, 0.3, 7);
    const std::vector<vcg::Point2d> poly = {{3.3, 3.6}, {7.7, 4.1}, {5.2, 7.9}};
    const Cut::Result r = Cut::Split(m, {PolygonCurve(m, poly)}, Cut::Param(), in, out);
    ASSERT_LT(8 * r.facesInside, r.facesInside + r.facesOutside);
    EXPECT_EQ(in.fn, r.facesInside);
    EXPECT_EQ(out.fn, r.facesOutside);
    EXPECT_NEAR(Area(in), PolygonArea(poly), 1e-9);
    EXPECT_NEAR(Area(in) + Area(out), 24.0 * 24.0, 1e-9);
    // each part's vertices are the ones its faces use, none twice: inside, a disk (V - E + F = 1)
    UpdateTopology<CutMesh>::FaceFace(in);
    int border = 0;
    for (auto &f : in.face)
        for (int k = 0; k < 3; ++k) border += vcg::face::IsBorder(f, k);
    const int edges = (3 * in.fn + border) / 2;
    EXPECT_EQ(in.vn - edges + in.fn, 1);
}
