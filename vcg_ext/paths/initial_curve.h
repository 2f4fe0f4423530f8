#ifndef VCG_EXT_SNAKE_INITIAL_CURVE_H
#define VCG_EXT_SNAKE_INITIAL_CURVE_H

// The initial curve of a snake (Sec. 5.5 and 7): samples at uniform spacing along a path on the
// surface -- the seeds' vertex path, or a path of surface points whose consecutive points share
// a face -- with the gaps between them already traced (the path's faces and points), and the
// snake's length unit: the median edge length along the path, so that one set of parameters
// fits meshes whose edge lengths vary by 10-100x.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <vcg_ext/snake/curve.h>
#include <vcg_ext/snake/error.h>
#include <vcg_ext/surface/snake_surface.h>
#include <vcg_ext/surface/surface_point.h>

namespace vcg {
namespace tri {

template <class MeshType>
class SnakeInitialCurve
{
public:
    typedef SnakeSurface<MeshType> Surface;

    /// Most samples a snake may have.
    static long MaxSamples() { return 200000; }

    struct Result
    {
        std::vector<SnakeSample> samples;
        std::vector<SnakeGap> gaps; ///< one per gap, traced
        double unit = 1;            ///< the snake's length unit
    };

    /// Along a vertex path (consecutive vertices share an edge; closed: the first is not
    /// repeated), `spacing` length units apart. `lengthScale`: the length unit (0: the median
    /// edge of the path).
    static Result FromVertexPath(const Surface &surf, const std::vector<int> &pathVerts, bool closed, double spacing,
                                 double lengthScale = 0)
    {
        const MeshType &m = surf.Mesh();
        std::vector<int> pv = pathVerts;
        if (closed && !pv.empty()) pv.push_back(pv.front());
        if (pv.size() < 2) throw SnakeError("Geometric snake: the seed path is too short.");
        for (int v : pv)
            if (v < 0 || v >= int(m.vert.size()) || m.vert[v].IsD())
                throw SnakeError("Geometric snake: the seed path has an invalid vertex.");
        Path path;
        std::vector<double> pathEdges;
        for (size_t i = 0; i < pv.size(); ++i) {
            path.points.push_back(surf.VertexPoint(pv[i]));
            // in double: a float square over- or underflows at 1e30 / 1e-30
            const double len = i == 0 ? 0.0
                                      : vcg::Distance(vcg::Point3d::Construct(m.vert[pv[i - 1]].cP()),
                                                      vcg::Point3d::Construct(m.vert[pv[i]].cP()));
            path.cum.push_back(i == 0 ? 0.0 : path.cum.back() + len);
            if (i == 0) continue;
            pathEdges.push_back(path.cum[i] - path.cum[i - 1]); // as summed (the unit is bit-exact)
            const SurfacePoint e0 = surf.PointOnEdge(pv[i - 1], pv[i], 0.0);
            if (e0.face < 0) throw SnakeError("Geometric snake: the seed path uses a missing edge.");
            path.pieces.push_back({e0, surf.PointOnEdge(pv[i - 1], pv[i], 1.0), surf.EdgeFaces(pv[i - 1], pv[i])});
        }
        return sample(surf, path, closed, spacing, usable(lengthScale) ? lengthScale : medianPositive(surf, pathEdges));
    }

    /// Along a polyline of surface points in which consecutive points share a face (closed: the
    /// first point is not repeated). `lengthScale`: the length unit (0: the median edge of the
    /// faces the path crosses; the pieces themselves can be far longer than any edge on a CAD face).
    static Result FromSurfacePath(const Surface &surf, const std::vector<SurfacePoint> &pathPts, bool closed,
                                  double spacing, double lengthScale = 0)
    {
        const MeshType &m = surf.Mesh();
        Path path;
        std::vector<SurfacePoint> &pv = path.points;
        for (const auto &p : pathPts) {
            CheckPoint(surf, p);
            if (pv.empty() || p.Pd(m) != pv.back().Pd(m)) pv.push_back(p);
        }
        if (closed && pv.size() > 1 && pv.front().Pd(m) == pv.back().Pd(m)) pv.pop_back();
        if (closed && !pv.empty()) pv.push_back(pv.front());
        if (pv.size() < 2) throw SnakeError("Geometric snake: the seed path is too short.");
        // the face each piece lies in, and both ends expressed in it
        std::vector<int> pieceFaces;
        path.cum.assign(1, 0.0);
        for (size_t i = 0; i + 1 < pv.size(); ++i) {
            Piece piece;
            const int f = surf.CommonFace(pv[i], pv[i + 1]);
            if (f < 0) throw SnakeError("Geometric snake: consecutive seed path points share no face.");
            pv[i].InFace(m, f, piece.from);
            pv[i + 1].InFace(m, f, piece.to);
            piece.faces = {f};
            path.pieces.push_back(piece);
            pieceFaces.push_back(f);
            path.cum.push_back(path.cum.back() + (pv[i + 1].Pd(m) - pv[i].Pd(m)).Norm());
        }
        return sample(surf, path, closed, spacing,
                      usable(lengthScale) ? lengthScale : medianPositive(surf, faceEdges(surf, pieceFaces)));
    }

    /// The length unit of samples restored without one: the median edge of their faces.
    static double UnitOf(const Surface &surf, const std::vector<SnakeSample> &samples)
    {
        std::vector<int> faces;
        for (const auto &s : samples) faces.push_back(s.p.face);
        return medianPositive(surf, faceEdges(surf, faces));
    }

    static void CheckPoint(const Surface &surf, const SurfacePoint &p)
    {
        if (!p.IsValid() || !surf.FaceUsable(p.face))
            throw SnakeError("Geometric snake: the point is not on the mesh (face " + std::to_string(p.face) + ").");
    }

private:
    // A path to take samples along: its points (closed: the first repeated at the end), their
    // arc lengths, and per piece between two points its ends expressed in one face and the faces
    // a gap over it holds.
    struct Piece
    {
        SurfacePoint from, to; // in the same face
        std::vector<int> faces;
    };
    struct Path
    {
        std::vector<SurfacePoint> points;
        std::vector<double> cum;
        std::vector<Piece> pieces;
    };

    static bool usable(double lengthScale) { return lengthScale > 0 && std::isfinite(lengthScale); }

    // Sec. 7: samples at uniform spacing along the path, the ends of an open one exactly at its
    // ends; the gaps between them are the path's pieces they span (their faces) with the path
    // points strictly inside as crossings.
    static Result sample(const Surface &surf, const Path &path, bool closed, double spacing, double unit)
    {
        const std::vector<double> &cum = path.cum;
        const double L = cum.back();
        const double d = spacing * unit;
        if (!(L > 1e-9 * surf.MeanEdge())) throw SnakeError("Geometric snake: the seed path has zero length.");
        long n = closed ? std::lround(L / d) : std::lround(L / d) + 1;
        n = std::max<long>(n, closed ? 3 : 2);
        if (n > MaxSamples()) throw SnakeError(tooManySamples(n, L, unit, spacing, path.points.size() - (closed ? 1 : 0)));
        const double step = closed ? L / double(n) : L / double(n - 1);

        Result r;
        r.unit = unit;
        std::vector<double> sampleArc;
        size_t e = 0;
        for (long k = 0; k < n; ++k) {
            const double s = (!closed && k == n - 1) ? L : std::min(L, k * step);
            while (e + 2 < path.points.size() && cum[e + 1] < s) ++e;
            const double len = cum[e + 1] - cum[e];
            const double t = std::min(1.0, std::max(0.0, len > 0 ? (s - cum[e]) / len : 0.0));
            const Piece &piece = path.pieces[e];
            SnakeSample smp;
            smp.p = SurfacePoint(piece.from.face, piece.from.bary * (1 - t) + piece.to.bary * t);
            smp.p.Normalize();
            r.samples.push_back(smp);
            sampleArc.push_back(s);
        }
        const long gapsN = closed ? n : n - 1;
        r.gaps.assign(gapsN, SnakeGap());
        const double eps = 1e-12 * L; // relative: any scale
        for (long g = 0; g < gapsN; ++g) {
            const double s0 = sampleArc[g], s1 = (g + 1 < n) ? sampleArc[g + 1] : L;
            SnakeGap &gap = r.gaps[g];
            for (size_t i = 0; i < path.pieces.size(); ++i) {
                if (cum[i + 1] < s0 - eps || cum[i] > s1 + eps) continue;
                gap.faces.insert(gap.faces.end(), path.pieces[i].faces.begin(), path.pieces[i].faces.end());
                if (cum[i] > s0 + eps && cum[i] < s1 - eps) gap.crossings.push_back(path.points[i]);
            }
            gap.traced = true;
        }
        return r;
    }

    // the "too many samples" message, blaming the spacing or the length of the path
    static std::string tooManySamples(long n, double L, double unit, double spacing, size_t pathPoints)
    {
        const double edges = L / unit;
        char buf[320];
        if (spacing < 1.0 && edges <= MaxSamples())
            std::snprintf(buf, sizeof buf, "Geometric snake: the sample spacing (%g edge lengths) is too small for "
                          "this path: it would need %ld samples (at most %ld). Raise the spacing.",
                          spacing, n, MaxSamples());
        else
            std::snprintf(buf, sizeof buf, "Geometric snake: the seed path is too long for one snake: %zu points, "
                          "%.0f local edge lengths, %ld samples at spacing %g (at most %ld). Use fewer or "
                          "closer seeds, or a larger spacing.", pathPoints, edges, n, spacing, MaxSamples());
        return buf;
    }
    // the edge lengths of the given faces, in double
    static std::vector<double> faceEdges(const Surface &surf, const std::vector<int> &faces)
    {
        const MeshType &m = surf.Mesh();
        std::vector<double> l;
        for (int f : faces)
            for (int k = 0; k < 3; ++k)
                l.push_back(vcg::Distance(vcg::Point3d::Construct(m.face[f].cP(k)),
                                          vcg::Point3d::Construct(m.face[f].cP((k + 1) % 3))));
        return l;
    }
    // median of the positive values (the mesh's mean edge length if there is none)
    static double medianPositive(const Surface &surf, std::vector<double> v)
    {
        v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !(x > 0) || !std::isfinite(x); }), v.end());
        if (v.empty()) return surf.MeanEdge();
        std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
        return v[v.size() / 2];
    }
};

} // namespace tri
} // namespace vcg

#endif
