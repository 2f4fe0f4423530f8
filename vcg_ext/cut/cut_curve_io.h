#ifndef VCG_EXT_CUT_CUT_CURVE_IO_H
#define VCG_EXT_CUT_CUT_CURVE_IO_H

// The curve to cut along, from a snake JSON file (io/snake_io.h's contract: one snake, or
// {"snakes": [...]}): its samples on this mesh and, between them, the polyline the snake shows
// once restored (snake/polyline.h). A file made on another mesh is refused: faces out of range
// (SnakeIO), or samples whose saved "position" is not where their face and barycentric
// coordinates put them on this mesh.

#include <fstream>
#include <sstream>
#include <string>

#include <vcg/complex/algorithms/update/bounding.h>

#include <vcg_ext/cut/curve_embedding.h>
#include <vcg_ext/io/snake_io.h>
#include <vcg_ext/snake/polyline.h>

namespace vcg {
namespace tri {

template <class MeshType>
class CutCurveIO
{
public:
    typedef nlohmann::json json;

    /// Snake `index` (0-based; -1: the session's selected snake, or the file's only one) of a
    /// snake file; m needs FF and VF adjacency (SnakeSurface).
    static CutCurve FromSnakeFile(MeshType &m, const std::string &path, int index = -1)
    {
        std::error_code ec;
        const auto size = std::filesystem::file_size(path, ec);
        if (ec) throw SnakeError("Cannot read the curve file \"" + path + "\".");
        if ((long long)size > SnakeIO<MeshType>::MaxFileBytes()) throw SnakeError("\"" + path + "\" is too large.");
        std::ifstream in(path, std::ios::binary);
        json j;
        try {
            j = json::parse(in);
        } catch (const json::exception &e) {
            throw SnakeError("\"" + path + "\" cannot be read: " + SnakeIO<MeshType>::JsonErrorText(e) + ".");
        }
        return FromJson(m, j, index, "\"" + path + "\"");
    }

    /// The same from parsed JSON: one snake, or a session ({"mesh": {...}, "snakes": [...],
    /// "selected": k}, the edit tool's sidecar or the snakes kept on the mesh). `name` is for messages.
    static CutCurve FromJson(MeshType &m, json j, int index, const std::string &name)
    {
        if (j.is_object() && j.contains("snakes")) {
            if (j.contains("mesh") && j["mesh"].is_object()) {
                const json &jm = j["mesh"];
                if (SnakeIO<MeshType>::IntFrom(jm, "vertices", int(m.vert.size())) != int(m.vert.size()) ||
                    SnakeIO<MeshType>::IntFrom(jm, "faces", int(m.face.size())) != int(m.face.size()))
                    throw SnakeError("Cut: the snakes of " + name + " were made on another version of this mesh "
                                     "(its vertex or face count differs). The mesh was not changed.");
            }
            if (index < 0) index = SnakeIO<MeshType>::IntFrom(j, "selected", 0);
            if (!j["snakes"].is_array() || index < 0 || index >= int(j["snakes"].size()))
                throw SnakeError(name + " has no snake " + std::to_string(index) + " (snakes are counted from 0).");
            j = json(j["snakes"][index]);
        } else if (index > 0) {
            throw SnakeError(name + " holds one snake only.");
        }
        if (!j.is_object() || !j.contains("samples"))
            throw SnakeError(name + " is not a snake curve file (no \"samples\").");
        CutCurve c;
        SnakeCurve sc;
        try {
            sc.samples = SnakeIO<MeshType>::SamplesFromJson(m, j["samples"]);
            sc.closed = j.value("closed", false);
        } catch (const json::exception &e) {
            throw SnakeError(name + ": " + SnakeIO<MeshType>::JsonErrorText(e) + ".");
        }
        vcg::tri::UpdateBounding<MeshType>::Box(m);
        const double tol = 1e-5 * m.bbox.Diag();
        for (size_t i = 0; i < sc.samples.size(); ++i) {
            const json &s = j["samples"][i];
            if (!sc.samples[i].p.OnMesh(m))
                throw SnakeError("Cut: the curve of " + name + " is not on this mesh (sample " + std::to_string(i) +
                                 " lies outside its face). The mesh was not changed.");
            if (s.contains("position") && s["position"].is_array() && s["position"].size() == 3) {
                const auto &p = s["position"];
                if (!p[0].is_number() || !p[1].is_number() || !p[2].is_number()) continue;
                const vcg::Point3d x(p[0].get<double>(), p[1].get<double>(), p[2].get<double>());
                if (!((x - sc.samples[i].p.Pd(m)).Norm() <= tol))
                    throw SnakeError("Cut: the curve of " + name + " was made on another mesh (sample " +
                                     std::to_string(i) + " is not where its face puts it on this mesh). The mesh "
                                     "was not changed.");
            }
        }
        sc.gaps.assign(sc.NumGaps(), SnakeGap());
        SnakeSurface<MeshType> surf(m);
        c.points = SnakePolyline<MeshType>::Points(surf, sc);
        c.closed = sc.closed;
        return c;
    }
};

} // namespace tri
} // namespace vcg

#endif
