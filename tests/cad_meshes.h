#ifndef GS_TESTS_CAD_MESHES_H
#define GS_TESTS_CAD_MESHES_H

// CAD-like tessellations with exact answers, as a B-rep tessellator exports them (STL, OBJ,
// PLY): every vertex lies on a crease, each flat face is triangulated from its boundary
// vertices only (fans and strips of slivers, no interior vertex), cylinders are long strips.
//  - MakeCadBlock: a 60 x 40 x 20 block with a cylindrical through-bore and a rectangular
//    pocket in its top face.
//  - MakeCadCylinder: a cylinder whose side is long strips and whose caps are fans of slivers
//    from one rim vertex.
// Both are closed, manifold, consistently oriented (outward normals).

#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <vcg/space/point3.h>

#include "generated_meshes.h"

namespace gs_test {

struct CadBlock
{
    static constexpr double X = 60, Y = 40, Z = 20;                // block [0,X] x [0,Y] x [0,Z]
    static constexpr double BoreX = 15, BoreY = 20, BoreR = 6;      // through-bore along z
    static constexpr double PX0 = 36, PX1 = 52, PY0 = 12, PY1 = 28; // pocket in the top face ...
    static constexpr double PocketFloor = 12;                       // ... down to this height
    static constexpr double SplitX = 30;                            // top and bottom faces are cut here
};

namespace detail {

/// Triangulates the planar ring between an outer loop and an inner loop (both counter-
/// clockwise seen from the side the face looks to) using only their vertices: the classic
/// zip, always taking the shorter new diagonal. Appends triangles facing that side; `flip`
/// reverses them. Throws if a triangle would fold over (normal against `up`).
inline void ZipRing(const std::vector<vcg::Point3d> &pts, const std::vector<int> &outer, const std::vector<int> &inner,
                    const vcg::Point3d &up, bool flip, std::vector<std::array<int, 3>> &tris)
{
    const size_t no = outer.size(), ni = inner.size();
    // start the inner loop at its vertex nearest to outer[0]
    size_t i0 = 0;
    for (size_t i = 1; i < ni; ++i)
        if ((pts[inner[i]] - pts[outer[0]]).Norm() < (pts[inner[i0]] - pts[outer[0]]).Norm()) i0 = i;
    size_t a = 0, b = 0; // steps taken on each loop
    while (a < no || b < ni) {
        const int o = outer[a % no], o1 = outer[(a + 1) % no];
        const int in = inner[(i0 + b) % ni], in1 = inner[(i0 + b + 1) % ni];
        bool advanceOuter;
        if (a == no) advanceOuter = false;
        else if (b == ni) advanceOuter = true;
        else advanceOuter = (pts[o1] - pts[in]).Norm() <= (pts[in1] - pts[o]).Norm();
        std::array<int, 3> t = advanceOuter ? std::array<int, 3>{in, o, o1} : std::array<int, 3>{in, o, in1};
        const vcg::Point3d n = (pts[t[1]] - pts[t[0]]) ^ (pts[t[2]] - pts[t[0]]);
        if (!(n * up > 0)) throw std::runtime_error("ZipRing: a triangle folds over");
        if (flip) std::swap(t[1], t[2]);
        tris.push_back(t);
        if (advanceOuter) ++a;
        else ++b;
    }
}

/// Two triangles for a planar quad a,b,c,d (counter-clockwise seen from outside).
inline void Quad(std::vector<std::array<int, 3>> &tris, int a, int b, int c, int d)
{
    tris.push_back({a, b, c});
    tris.push_back({a, c, d});
}

} // namespace detail

/// The block of CadBlock with `boreSegments` segments on the bore's circles.
template <class M>
void MakeCadBlock(M &m, int boreSegments = 64)
{
    typedef CadBlock B;
    std::vector<vcg::Point3d> p;
    auto add = [&](double x, double y, double z) {
        p.push_back(vcg::Point3d(x, y, z));
        return int(p.size()) - 1;
    };
    // block corners (bottom z=0: b.., top z=Z: t..) and the split points at x = SplitX
    const int b00 = add(0, 0, 0), bS0 = add(B::SplitX, 0, 0), bX0 = add(B::X, 0, 0), bXY = add(B::X, B::Y, 0),
              bSY = add(B::SplitX, B::Y, 0), b0Y = add(0, B::Y, 0);
    const int t00 = add(0, 0, B::Z), tS0 = add(B::SplitX, 0, B::Z), tX0 = add(B::X, 0, B::Z), tXY = add(B::X, B::Y, B::Z),
              tSY = add(B::SplitX, B::Y, B::Z), t0Y = add(0, B::Y, B::Z);
    std::vector<int> boreTop, boreBot;
    for (int i = 0; i < boreSegments; ++i) {
        const double a = 2 * M_PI * i / boreSegments;
        boreTop.push_back(add(B::BoreX + B::BoreR * std::cos(a), B::BoreY + B::BoreR * std::sin(a), B::Z));
        boreBot.push_back(add(B::BoreX + B::BoreR * std::cos(a), B::BoreY + B::BoreR * std::sin(a), 0));
    }
    const std::vector<int> pocketTop{add(B::PX0, B::PY0, B::Z), add(B::PX1, B::PY0, B::Z), add(B::PX1, B::PY1, B::Z),
                                     add(B::PX0, B::PY1, B::Z)};
    const std::vector<int> pocketBot{add(B::PX0, B::PY0, B::PocketFloor), add(B::PX1, B::PY0, B::PocketFloor),
                                     add(B::PX1, B::PY1, B::PocketFloor), add(B::PX0, B::PY1, B::PocketFloor)};
    std::vector<std::array<int, 3>> t;
    const vcg::Point3d up(0, 0, 1);
    // top face: left half around the bore, right half around the pocket (seen from +z)
    detail::ZipRing(p, {t00, tS0, tSY, t0Y}, boreTop, up, false, t);
    detail::ZipRing(p, {tS0, tX0, tXY, tSY}, pocketTop, up, false, t);
    // bottom face (seen from -z): the same rings, reversed; the right half is a plain quad
    detail::ZipRing(p, {b00, bS0, bSY, b0Y}, boreBot, up, true, t);
    detail::Quad(t, bS0, bSY, bXY, bX0);
    // sides
    detail::Quad(t, b00, bS0, tS0, t00);
    detail::Quad(t, bS0, bX0, tX0, tS0); // front, y = 0
    detail::Quad(t, bXY, bSY, tSY, tXY);
    detail::Quad(t, bSY, b0Y, t0Y, tSY); // back, y = Y
    detail::Quad(t, b0Y, b00, t00, t0Y); // left, x = 0
    detail::Quad(t, bX0, bXY, tXY, tX0); // right, x = X
    // bore wall (facing the axis): long strips
    for (int i = 0; i < boreSegments; ++i) {
        const int j = (i + 1) % boreSegments;
        detail::Quad(t, boreBot[i], boreTop[i], boreTop[j], boreBot[j]);
    }
    // pocket walls (facing the pocket) and floor
    for (int i = 0; i < 4; ++i) {
        const int j = (i + 1) % 4;
        detail::Quad(t, pocketBot[i], pocketTop[i], pocketTop[j], pocketBot[j]);
    }
    detail::Quad(t, pocketBot[0], pocketBot[1], pocketBot[2], pocketBot[3]);
    MakeFromArrays(m, p, t);
}

/// Exact answers on the block: distance to its top front edge (y = 0, z = Z), to the bore's
/// top rim as tessellated (a polygon of `boreSegments` sides) and to the pocket's rim.
inline double DistToBlockTopFrontEdge(const vcg::Point3d &q)
{
    return detail::DistToSegment(q, vcg::Point3d(0, 0, CadBlock::Z), vcg::Point3d(CadBlock::X, 0, CadBlock::Z));
}
inline std::vector<vcg::Point3d> CirclePolygon(double cx, double cy, double r, double z, int n)
{
    std::vector<vcg::Point3d> out;
    for (int i = 0; i < n; ++i) {
        const double a = 2 * M_PI * i / n;
        out.push_back(vcg::Point3d(cx + r * std::cos(a), cy + r * std::sin(a), z));
    }
    return out;
}
inline double DistToClosedPolygon(const vcg::Point3d &q, const std::vector<vcg::Point3d> &poly)
{
    double best = 1e300;
    for (size_t i = 0; i < poly.size(); ++i) best = std::min(best, detail::DistToSegment(q, poly[i], poly[(i + 1) % poly.size()]));
    return best;
}
inline std::vector<vcg::Point3d> PocketRim()
{
    typedef CadBlock B;
    return {vcg::Point3d(B::PX0, B::PY0, B::Z), vcg::Point3d(B::PX1, B::PY0, B::Z), vcg::Point3d(B::PX1, B::PY1, B::Z),
            vcg::Point3d(B::PX0, B::PY1, B::Z)};
}

/// A cylinder of radius r and height h (axis z, base at z=0) whose side is `segments` long
/// strips of two triangles, and whose caps are fans of slivers from one rim vertex.
template <class M>
void MakeCadCylinder(M &m, int segments = 48, double r = 10, double h = 40)
{
    std::vector<vcg::Point3d> p;
    std::vector<int> bot, top;
    for (int i = 0; i < segments; ++i) {
        const double a = 2 * M_PI * i / segments;
        bot.push_back(int(p.size()));
        p.push_back(vcg::Point3d(r * std::cos(a), r * std::sin(a), 0));
        top.push_back(int(p.size()));
        p.push_back(vcg::Point3d(r * std::cos(a), r * std::sin(a), h));
    }
    std::vector<std::array<int, 3>> t;
    for (int i = 0; i < segments; ++i) {
        const int j = (i + 1) % segments;
        detail::Quad(t, bot[i], bot[j], top[j], top[i]); // outward
    }
    for (int i = 1; i + 1 < segments; ++i) {
        t.push_back({top[0], top[i], top[i + 1]}); // +z
        t.push_back({bot[0], bot[i + 1], bot[i]}); // -z
    }
    MakeFromArrays(m, p, t);
}

} // namespace gs_test

#endif
