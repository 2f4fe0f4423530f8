#ifndef VCG_EXT_SEED_POINTS_H
#define VCG_EXT_SEED_POINTS_H

// Seeds given as points in space rather than vertex indices (beyond the paper's Sec. 5.5,
// where the user picks vertices): typed coordinates ("x y z; x y z; ...") or a MeshLab Pick
// Points file (.pp), each snapped to the closest point of the surface. On CAD tessellations
// every vertex lies on some crease, so a seed must be able to sit inside a face.
//
// The parsers are pure functions over strings and streams (no Qt, no mesh): the filters, the
// command line program and the fuzz targets all call these same functions.

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <istream>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/closest.h>
#include <vcg/space/distance3.h>
#include <vcg/space/index/grid_static_ptr.h>
#include <vcg/space/triangle3.h>

#include <vcg_ext/io/input_file.h>
#include <vcg_ext/snake/error.h>
#include <vcg_ext/surface/mesh_validation.h>
#include <vcg_ext/surface/surface_point.h>

namespace vcg {
namespace tri {

/// One point of a MeshLab Pick Points file.
struct PickedPoint
{
    std::string name;
    vcg::Point3d p;
    bool active = true; ///< Pick Points writes active="0" for points the user left unplaced
};

class SeedPointsParser
{
public:
    /// Largest input the parsers accept (a seed list is short; this bounds the work on junk).
    static size_t MaxTextSize() { return size_t(16) << 20; }

    /// "x y z; x y z; ..." -> points. Points are separated by ';' or line breaks, the three
    /// coordinates by spaces, tabs or commas. Empty text gives no points. Throws SnakeError
    /// on anything else: letters, a point without exactly three numbers, NaN or infinity.
    static std::vector<vcg::Point3d> Parse(const std::string &text)
    {
        if (text.size() > MaxTextSize()) throw SnakeError("The seed point list is too long.");
        std::vector<vcg::Point3d> out;
        size_t start = 0;
        int index = 0;
        while (start <= text.size()) {
            size_t end = text.find_first_of(";\n\r", start);
            if (end == std::string::npos) end = text.size();
            const std::string item = text.substr(start, end - start);
            start = end + 1;
            std::vector<double> c;
            if (!Numbers(item, c, text)) continue; // blank item (trailing ';', empty line)
            ++index;
            if (c.size() != 3)
                throw Junk(text, "point " + std::to_string(index) + " has " + std::to_string(c.size()) +
                                     " coordinates instead of 3");
            out.push_back(vcg::Point3d(c[0], c[1], c[2]));
            if (end == text.size()) break;
        }
        return out;
    }

    /// A MeshLab Pick Points file (edit_pickpoints, PickedPoints::save): an XML document whose
    /// root is <PickedPoints> holding <point x=".." y=".." z=".." active="1" name=".."/>
    /// elements (attributes in any order). Every point is returned, in file order, with its
    /// `active` flag; SeedPointsParser::Active() keeps the placed ones as Pick Points itself does.
    /// Throws SnakeError on a file that is not such a document.
    static std::vector<PickedPoint> ParsePickPoints(const std::string &xml)
    {
        if (xml.size() > MaxTextSize()) throw SnakeError("The Pick Points file is too large.");
        // UTF-16/32 (a byte-order mark, or NUL bytes between ASCII characters): say so, not "root element is <"
        if (xml.compare(0, 2, "\xFF\xFE") == 0 || xml.compare(0, 2, "\xFE\xFF") == 0 ||
            xml.find('\0') < std::min<size_t>(xml.size(), 256))
            throw PpJunk("it is UTF-16 or UTF-32 text; MeshLab writes Pick Points files in UTF-8 (save it as UTF-8)");
        std::vector<PickedPoint> out;
        bool sawRoot = false;
        size_t i = 0;
        while (true) {
            const size_t lt = xml.find('<', i);
            if (lt == std::string::npos) break;
            if (xml.compare(lt, 4, "<!--") == 0) { // comment
                const size_t e = xml.find("-->", lt + 4);
                if (e == std::string::npos) throw PpJunk("unterminated comment");
                i = e + 3;
                continue;
            }
            size_t gt = lt + 1;
            char quote = 0;
            for (; gt < xml.size(); ++gt) { // '>' inside a quoted attribute value does not end the tag
                const char ch = xml[gt];
                if (quote) { if (ch == quote) quote = 0; }
                else if (ch == '"' || ch == '\'') quote = ch;
                else if (ch == '>') break;
            }
            if (gt >= xml.size()) throw PpJunk("unterminated tag");
            const std::string tag = xml.substr(lt + 1, gt - lt - 1);
            i = gt + 1;
            if (tag.empty() || tag[0] == '?' || tag[0] == '!' || tag[0] == '/') continue;
            size_t ne = 0;
            while (ne < tag.size() && !std::isspace(static_cast<unsigned char>(tag[ne])) && tag[ne] != '/') ++ne;
            const std::string name = tag.substr(0, ne);
            if (!sawRoot) {
                if (name != "PickedPoints")
                    throw PpJunk("its root element is <" + name + ">, not <PickedPoints>");
                sawRoot = true;
                continue;
            }
            if (name != "point") continue;
            std::vector<std::pair<std::string, std::string>> attrs;
            Attributes(tag.substr(ne), attrs);
            PickedPoint pp;
            bool has[3] = {false, false, false};
            for (const auto &a : attrs) {
                if (a.first == "name") pp.name = a.second;
                else if (a.first == "active") pp.active = (a.second != "0");
                else if (a.first == "x" || a.first == "y" || a.first == "z") {
                    const int k = a.first[0] - 'x';
                    std::vector<double> c;
                    try {
                        Numbers(a.second, c, a.second);
                    } catch (const SnakeError &) {
                        c.clear();
                    }
                    if (c.size() != 1)
                        throw PpJunk("point " + std::to_string(out.size() + 1) + " has a bad " + a.first + " (\"" +
                                     Short(a.second) + "\")");
                    pp.p[k] = c[0];
                    has[k] = true;
                }
            }
            if (!has[0] || !has[1] || !has[2])
                throw PpJunk("point " + std::to_string(out.size() + 1) + " lacks an x, y or z coordinate");
            out.push_back(pp);
        }
        if (!sawRoot) throw PpJunk("it is not an XML document with a <PickedPoints> root");
        return out;
    }

    static std::vector<PickedPoint> ReadPickPoints(std::istream &in)
    {
        std::string s;
        char buf[65536];
        while (in.read(buf, sizeof buf) || in.gcount() > 0) {
            s.append(buf, size_t(in.gcount()));
            if (s.size() > MaxTextSize()) throw SnakeError("The Pick Points file is too large.");
        }
        return ParsePickPoints(s);
    }

    /// Reads a .pp file; a missing or unreadable file throws SnakeError naming it.
    static std::vector<PickedPoint> ReadPickPointsFile(const std::string &path)
    {
        InputFile::Require(path, "the Pick Points file");
        std::ifstream in(path, std::ios::binary);
        if (!in) throw SnakeError("Cannot open the Pick Points file \"" + path + "\".");
        try {
            return ReadPickPoints(in);
        } catch (const SnakeError &e) {
            throw SnakeError(std::string(e.what()) + " (file \"" + path + "\")");
        }
    }

    /// Seeds as the filters and the program take them: the SeedPoints text, else the active
    /// points of the SeedFile (.pp); `source` says which, for the Log. Empty if neither is
    /// given; both given is an error.
    static std::vector<vcg::Point3d> FromTextOrFile(const std::string &text, std::string file, std::string &source)
    {
        while (!file.empty() && std::isspace(static_cast<unsigned char>(file.back()))) file.pop_back();
        while (!file.empty() && std::isspace(static_cast<unsigned char>(file.front()))) file.erase(file.begin());
        std::vector<vcg::Point3d> pts = Parse(text);
        if (!pts.empty()) {
            if (!file.empty()) throw SnakeError("Both SeedPoints and SeedFile are given: use one of them.");
            source = "the SeedPoints coordinates";
            return pts;
        }
        if (file.empty()) return pts;
        pts = Active(ReadPickPointsFile(file));
        source = "the Pick Points file " + file;
        return pts;
    }

    /// The placed (active) points, in order: what Pick Points' own "get points" returns.
    static std::vector<vcg::Point3d> Active(const std::vector<PickedPoint> &pts)
    {
        std::vector<vcg::Point3d> out;
        for (const auto &p : pts)
            if (p.active) out.push_back(p.p);
        return out;
    }

private:
    static SnakeError Junk(const std::string &text, const std::string &why)
    {
        return SnakeError("Cannot read the seed points \"" + Short(text) + "\": " + why +
                          ". Write x y z triples separated by ';', e.g. \"0 0 1; 2.5 0 1\".");
    }
    static SnakeError PpJunk(const std::string &why)
    {
        return SnakeError("Not a MeshLab Pick Points (.pp) file: " + why + ".");
    }
    static std::string Short(const std::string &s) { return s.size() > 80 ? s.substr(0, 77) + "..." : s; }

    /// Finite decimal numbers separated by whitespace or commas; false for a blank item.
    static bool Numbers(const std::string &item, std::vector<double> &c, const std::string &whole)
    {
        c.clear();
        size_t i = 0;
        const size_t n = item.size();
        bool any = false;
        while (i < n) {
            const char ch = item[i];
            if (std::isspace(static_cast<unsigned char>(ch)) || ch == ',') { ++i; continue; }
            // strtod also reads "nan", "inf" and hex floats: only plain decimals are allowed.
            size_t j = i;
            while (j < n && (std::isdigit(static_cast<unsigned char>(item[j])) || item[j] == '.' || item[j] == '-' ||
                             item[j] == '+' || item[j] == 'e' || item[j] == 'E'))
                ++j;
            const std::string tok = item.substr(i, j - i);
            if (tok.empty()) {
                if (std::isalpha(static_cast<unsigned char>(ch)) &&
                    (item.compare(i, 3, "nan") == 0 || item.compare(i, 3, "NaN") == 0 || item.compare(i, 3, "inf") == 0 ||
                     item.compare(i, 3, "Inf") == 0))
                    throw Junk(whole, "coordinates must be finite numbers (found \"" + Short(item.substr(i, 8)) + "\")");
                throw Junk(whole, std::string("unexpected character '") + ch + "'");
            }
            errno = 0;
            char *end = nullptr;
            const double v = std::strtod(tok.c_str(), &end);
            if (end != tok.c_str() + tok.size()) throw Junk(whole, "\"" + Short(tok) + "\" is not a number");
            if (!std::isfinite(v)) throw Junk(whole, "coordinates must be finite numbers (\"" + Short(tok) + "\")");
            c.push_back(v);
            any = true;
            i = j;
            if (c.size() > 16) throw Junk(whole, "too many numbers in one point");
        }
        return any;
    }

    /// name="value" pairs of a tag (single or double quotes; XML's five entities decoded).
    static void Attributes(const std::string &s, std::vector<std::pair<std::string, std::string>> &out)
    {
        size_t i = 0;
        while (i < s.size()) {
            while (i < s.size() && (std::isspace(static_cast<unsigned char>(s[i])) || s[i] == '/')) ++i;
            if (i >= s.size()) break;
            size_t e = i;
            while (e < s.size() && s[e] != '=' && !std::isspace(static_cast<unsigned char>(s[e]))) ++e;
            const std::string key = s.substr(i, e - i);
            while (e < s.size() && std::isspace(static_cast<unsigned char>(s[e]))) ++e;
            if (e >= s.size() || s[e] != '=') throw PpJunk("attribute \"" + Short(key) + "\" has no value");
            ++e;
            while (e < s.size() && std::isspace(static_cast<unsigned char>(s[e]))) ++e;
            if (e >= s.size() || (s[e] != '"' && s[e] != '\'')) throw PpJunk("unquoted attribute \"" + Short(key) + "\"");
            const char q = s[e];
            const size_t close = s.find(q, e + 1);
            if (close == std::string::npos) throw PpJunk("unterminated attribute \"" + Short(key) + "\"");
            out.push_back({key, Unescape(s.substr(e + 1, close - e - 1))});
            i = close + 1;
        }
    }

    static std::string Unescape(const std::string &v)
    {
        static const char *const ent[][2] = {{"&amp;", "&"}, {"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&apos;", "'"}};
        std::string r;
        for (size_t i = 0; i < v.size();) {
            bool done = false;
            if (v[i] == '&')
                for (const auto &e : ent) {
                    const size_t l = std::char_traits<char>::length(e[0]);
                    if (v.compare(i, l, e[0]) == 0) { r += e[1]; i += l; done = true; break; }
                }
            if (!done) r += v[i++];
        }
        return r;
    }
};

/// Seed points snapped onto a mesh: each to its closest surface point (vcglib's uniform grid
/// and closest-point search), as a (face, barycentric) SurfacePoint.
template <class MeshType>
class SeedPointSnap
{
public:
    typedef typename MeshType::FaceType FaceType;
    typedef typename MeshType::ScalarType ScalarType;
    typedef typename MeshType::CoordType CoordType;
    typedef MeshValidation<MeshType> MV;

    /// Points farther from the surface than this fraction of the bounding box diagonal are refused.
    static double MaxDistanceFraction() { return 0.1; }

    struct Result
    {
        std::vector<SurfacePoint> points;
        std::vector<double> distances; ///< from each given point to the surface
        double bboxDiagonal = 0;
    };

    /// Snaps `pts` (at least `minCount`) onto the surface. Throws SnakeError with a message
    /// naming the seed for: too few points, a point farther than MaxDistanceFraction() of the
    /// bounding box diagonal, two consecutive seeds snapping to the same surface point.
    static Result Snap(const MeshType &m, const std::vector<vcg::Point3d> &pts, size_t minCount, bool closed = false)
    {
        MV::RequireSurface(m);
        if (pts.size() < minCount)
            throw SnakeError("A" + std::string(closed ? " closed" : "n open") + " snake needs at least " +
                             std::to_string(minCount) + " seed points (got " + std::to_string(pts.size()) + ").");
        vcg::Box3d box;
        for (const auto &v : m.vert)
            if (!v.IsD()) box.Add(vcg::Point3d::Construct(v.cP()));
        Result r;
        r.bboxDiagonal = box.Diag();
        const double maxD = MaxDistanceFraction() * r.bboxDiagonal;
        for (size_t i = 0; i < pts.size(); ++i)
            if (!std::isfinite(pts[i][0]) || !std::isfinite(pts[i][1]) || !std::isfinite(pts[i][2]))
                throw SnakeError("Seed point " + std::to_string(i + 1) + " has a NaN or infinite coordinate.");

        // vcglib's grid over the faces; the distance functor works in double on the triangle
        // (vcglib's PointDistanceBase would need normalized per-face normals).
        vcg::GridStaticPtr<FaceType, ScalarType> grid;
        MeshType &mm = const_cast<MeshType &>(m); // the grid stores non-const pointers; it only reads
        grid.Set(mm.face.begin(), mm.face.end());
        vcg::tri::EmptyTMark<MeshType> marker;
        for (size_t i = 0; i < pts.size(); ++i) {
            const CoordType q = CoordType::Construct(pts[i]);
            // Search a little farther than the limit so the message can say how far the point is.
            const ScalarType searchMax = ScalarType(std::max(maxD, 1e-30) * 4);
            ScalarType dist = searchMax;
            CoordType closest(0, 0, 0);
            DistanceFunctor fn;
            // A point beyond the limit from the bounding box never reaches the grid: vcglib's
            // grid turns coordinates into int cell indices, undefined far outside (fuzz_seed_points).
            const double boxDist = BoxDistance(box, pts[i]);
            FaceType *f = boxDist <= maxD ? grid.GetClosest(fn, marker, q, searchMax, dist, closest) : nullptr;
            const std::string who = "Seed point " + std::to_string(i + 1) + " (" + Fmt(pts[i][0]) + " " +
                                    Fmt(pts[i][1]) + " " + Fmt(pts[i][2]) + ")";
            if (f == nullptr && !std::isfinite(boxDist))
                throw SnakeError(who + " is too far from the surface to measure (its distance overflows); the mesh's "
                                 "bounding box diagonal is " + Fmt(r.bboxDiagonal) + ". Give points on or near the "
                                 "mesh, in the mesh's own coordinates.");
            if (f == nullptr || !(double(dist) <= maxD))
                throw SnakeError(who + " is " +
                                 (f == nullptr ? "more than " + Fmt(std::max(boxDist, 4 * maxD)) : Fmt(double(dist))) +
                                 " away from the surface, farther than 10% of the bounding box diagonal (" +
                                 Fmt(maxD) + "). Give points on or near the mesh, in the mesh's own coordinates.");
            const int fi = int(f - &*m.face.begin());
            SurfacePoint sp(fi, Bary(*f, vcg::Point3d::Construct(closest)));
            sp.Normalize();
            r.points.push_back(sp);
            r.distances.push_back(double(dist));
        }
        const double same = 1e-9 * std::max(r.bboxDiagonal, 1e-300);
        for (size_t i = 0; i + 1 < r.points.size(); ++i)
            if ((r.points[i].Pd(m) - r.points[i + 1].Pd(m)).Norm() <= same)
                throw SnakeError("Seed points " + std::to_string(i + 1) + " and " + std::to_string(i + 2) +
                                 " land on the same surface point; remove the repetition.");
        if (closed && r.points.size() > 1 && (r.points.front().Pd(m) - r.points.back().Pd(m)).Norm() <= same)
            throw SnakeError("The last seed point repeats the first; a closed snake is closed automatically.");
        return r;
    }

    /// Distance from p to the box (0 inside).
    static double BoxDistance(const vcg::Box3d &b, const vcg::Point3d &p)
    {
        double d2 = 0;
        for (int k = 0; k < 3; ++k) {
            const double e = std::max(0.0, std::max(b.min[k] - p[k], p[k] - b.max[k]));
            d2 += e * e;
        }
        return std::sqrt(d2);
    }

    /// Barycentric coordinates of a point of face f (clamped into the triangle).
    static vcg::Point3d Bary(const FaceType &f, const vcg::Point3d &p)
    {
        vcg::Triangle3<double> t(vcg::Point3d::Construct(f.cV(0)->cP()), vcg::Point3d::Construct(f.cV(1)->cP()),
                                 vcg::Point3d::Construct(f.cV(2)->cP()));
        vcg::Point3d b;
        // (vcglib's "false" also means "a hair outside", which a closest point on an edge can be)
        vcg::InterpolationParameters(t, p, b);
        if (!std::isfinite(b[0]) || !std::isfinite(b[1]) || !std::isfinite(b[2]) ||
            !((t.cP(0) * b[0] + t.cP(1) * b[1] + t.cP(2) * b[2] - p).Norm() <= 1e-6 * std::max(1.0, p.Norm())) ||
            MeshValidation<MeshType>::IsDegenerate(f)) { // degenerate face: the nearest corner
            int best = 0;
            for (int k = 1; k < 3; ++k)
                if ((t.cP(k) - p).SquaredNorm() < (t.cP(best) - p).SquaredNorm()) best = k;
            b = vcg::Point3d(0, 0, 0);
            b[best] = 1;
        }
        return b;
    }

private:
    struct DistanceFunctor
    {
        typedef CoordType QueryType;
        static const CoordType &Pos(const CoordType &q) { return q; }
        bool operator()(const FaceType &f, const CoordType &p, ScalarType &minDist, CoordType &q) const
        {
            vcg::Triangle3<double> t(vcg::Point3d::Construct(f.cV(0)->cP()), vcg::Point3d::Construct(f.cV(1)->cP()),
                                     vcg::Point3d::Construct(f.cV(2)->cP()));
            double d;
            vcg::Point3d c;
            vcg::TrianglePointDistance<double>(t, vcg::Point3d::Construct(p), d, c);
            if (!(d <= double(minDist))) return false;
            minDist = ScalarType(d);
            q = CoordType::Construct(c);
            return true;
        }
    };
    static std::string Fmt(double v)
    {
        std::ostringstream s;
        s.precision(6);
        s << v;
        return s.str();
    }
};

} // namespace tri
} // namespace vcg

#endif
