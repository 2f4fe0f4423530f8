#ifndef GS_CLI_OBJ_FACES_H
#define GS_CLI_OBJ_FACES_H

// The faces of an OBJ file, read and checked by the program itself. vcglib's ImporterOBJ (MeshLab
// 2020.09) reads vertices, texture coordinates, normals and materials well, but its face pass
// drops every triangle that uses the file's first vertex (or first texture coordinate or normal)
// and reads m.vert[i] for an out-of-range index before checking it (a crash on `f 1 2 100000`).
// So every index is checked here first (a bad one refuses the file, with its line), and when the
// importer's face count differs from the file's, the faces are rebuilt from this list: a mesh
// loads whole or is refused.

#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <vcg/complex/complex.h>
#include <wrap/io_trimesh/io_mask.h>

#include <vcg_ext/snake/error.h>

namespace gs_cli {

class ObjFaces
{
public:
    /// One polygon corner: 0-based indices into the file's v, vt and vn lists (-1: none).
    struct Corner
    {
        int v = -1, t = -1, n = -1;
    };
    std::vector<std::vector<Corner>> polygons;
    std::vector<vcg::Point2f> texCoords;
    std::vector<vcg::Point3f> normals;
    long long vertices = 0;

    /// Triangles of the fan triangulation (what the importer makes of the polygons).
    long long Triangles() const
    {
        long long t = 0;
        for (const auto &p : polygons) t += static_cast<long long>(p.size()) - 2;
        return t;
    }

    /// Reads and checks every face (`f`) and line (`l`) record of the OBJ file `path`.
    /// Throws SnakeError naming the line of the first bad record.
    void Read(const std::string &path)
    {
        std::ifstream in(path, std::ios::binary);
        if (!in) throw vcg::tri::SnakeError("Cannot read the mesh \"" + path + "\".");
        long long nt = 0, nn = 0;
        std::string line;
        for (long long ln = 1; std::getline(in, line); ++ln) {
            std::istringstream ls(line);
            std::string head;
            if (!(ls >> head)) continue;
            auto bad = [&](const std::string &why) {
                return vcg::tri::SnakeError("Cannot read the mesh \"" + path + "\": line " + std::to_string(ln) +
                                            " (\"" + Shorten(line) + "\") " + why + ".");
            };
            if (head == "v") ++vertices;
            else if (head == "vt") {
                float u = 0, w = 0;
                ls >> u >> w;
                texCoords.emplace_back(u, w);
                ++nt;
            } else if (head == "vn") {
                float x = 0, y = 0, z = 0;
                ls >> x >> y >> z;
                normals.emplace_back(x, y, z);
                ++nn;
            } else if (head == "f" || head == "l") {
                std::vector<Corner> poly;
                for (std::string tok; ls >> tok;) {
                    if (tok[0] == '#') break;
                    Corner c;
                    std::string part[3];
                    int k = 0;
                    for (char ch : tok) {
                        if (ch == '/') {
                            if (++k > 2) throw bad("has a corner \"" + Shorten(tok) + "\" with more than three parts");
                        } else part[k] += ch;
                    }
                    c.v = Resolve(part[0], vertices, "vertex", bad);
                    if (!part[1].empty()) c.t = Resolve(part[1], nt, "texture coordinate", bad);
                    if (k == 2 && !part[2].empty()) c.n = Resolve(part[2], nn, "normal", bad);
                    poly.push_back(c);
                }
                if (head == "l") {
                    if (poly.size() < 2) throw bad("is a line with fewer than 2 vertices");
                    continue;
                }
                if (poly.size() < 3) throw bad("is a face with fewer than 3 vertices");
                polygons.push_back(poly);
            }
        }
    }

    /// Replaces m's faces by the fan triangulation of the polygons, with their texture
    /// coordinates (per wedge and, when `mask` has them, per vertex) and normals as the file gives
    /// them. m's vertices must be the file's, in file order.
    template <class MeshType>
    void Rebuild(MeshType &m, int mask) const
    {
        namespace io = vcg::tri::io;
        for (auto &f : m.face)
            if (!f.IsD()) vcg::tri::Allocator<MeshType>::DeleteFace(m, f);
        vcg::tri::Allocator<MeshType>::CompactFaceVector(m);
        auto fi = vcg::tri::Allocator<MeshType>::AddFaces(m, size_t(Triangles()));
        for (const auto &p : polygons) {
            for (size_t i = 1; i + 1 < p.size(); ++i, ++fi) {
                const Corner c[3] = {p[0], p[i], p[i + 1]};
                for (int j = 0; j < 3; ++j) {
                    fi->V(j) = &m.vert[size_t(c[j].v)];
                    if (c[j].t >= 0) {
                        const vcg::Point2f &t = texCoords[size_t(c[j].t)];
                        if ((mask & io::Mask::IOM_WEDGTEXCOORD) && m.face.IsWedgeTexCoordEnabled()) {
                            fi->WT(j).u() = t[0];
                            fi->WT(j).v() = t[1];
                            fi->WT(j).n() = 0;
                        }
                        if ((mask & io::Mask::IOM_VERTTEXCOORD) && m.vert.IsTexCoordEnabled()) {
                            fi->V(j)->T().u() = t[0];
                            fi->V(j)->T().v() = t[1];
                        }
                    }
                    if (c[j].n >= 0 && (mask & io::Mask::IOM_VERTNORMAL))
                        fi->V(j)->N().Import(normals[size_t(c[j].n)]);
                }
                // the polygon's inner edges are faux (MeshLab draws the polygon, not the fan)
                if (i > 1) fi->SetF(2);
                if (i + 2 < p.size()) fi->SetF(1);
            }
        }
    }

private:
    static std::string Shorten(const std::string &s) { return s.size() > 60 ? s.substr(0, 57) + "..." : s; }

    /// An OBJ index (1-based, or negative: counted back from the last one read) as a 0-based one.
    template <class Bad>
    static int Resolve(const std::string &s, long long count, const char *what, const Bad &bad)
    {
        char *end = nullptr;
        errno = 0;
        const long long i = std::strtoll(s.c_str(), &end, 10);
        if (s.empty() || *end || errno == ERANGE) throw bad(std::string("has a bad ") + what + " index \"" + Shorten(s) + "\"");
        const long long r = i > 0 ? i - 1 : count + i;
        if (i == 0 || r < 0 || r >= count)
            throw bad("refers to " + std::string(what) + " " + Shorten(s) + ", but only " + std::to_string(count) + " " +
                      (count == 1 ? what : std::string(what) == "vertex" ? "vertices" : what + std::string("s")) +
                      (count == 1 ? " is" : " are") + " defined before it (OBJ indices start at 1)");
        return int(r);
    }
};

} // namespace gs_cli

#endif
