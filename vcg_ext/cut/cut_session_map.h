#ifndef VCG_EXT_CUT_CUT_SESSION_MAP_H
#define VCG_EXT_CUT_CUT_SESSION_MAP_H

// The edit tool's session (SnakeController::ToJson: snakes, their initial curves and
// polylines, seed points) saved on the mesh before a cut, rewritten for the mesh after it:
// every surface point ({"face", "bary", "position"}) goes through the cut's CutPointMap, its
// position is recomputed on the new faces, and the session's mesh counts are the new mesh's.
// Seeds are vertex indices: a cut adds vertices after the user's, so they stay valid.

#include <nlohmann/json.hpp>

#include <vcg_ext/cut/cut_point_map.h>
#include <vcg_ext/surface/surface_point.h>

namespace vcg {
namespace tri {

template <class MeshType>
class CutSessionMap
{
public:
    typedef nlohmann::json json;

    /// `session` of the mesh before the cut, for m, the mesh after it.
    static json Map(json session, const CutPointMap &map, const MeshType &m)
    {
        walk(session, map, m);
        if (session.is_object() && session.contains("mesh") && session["mesh"].is_object()) {
            session["mesh"]["vertices"] = int(m.vert.size());
            session["mesh"]["faces"] = int(m.face.size());
        }
        return session;
    }

private:
    static bool isPoint(const json &j)
    {
        return j.contains("face") && j["face"].is_number_integer() && j.contains("bary") && j["bary"].is_array() &&
               j["bary"].size() == 3 && j["bary"][0].is_number() && j["bary"][1].is_number() && j["bary"][2].is_number();
    }
    static void walk(json &j, const CutPointMap &map, const MeshType &m)
    {
        if (j.is_array()) {
            for (json &e : j) walk(e, map, m);
            return;
        }
        if (!j.is_object()) return;
        if (isPoint(j)) {
            SurfacePoint p(j["face"].get<int>(), vcg::Point3d(j["bary"][0].get<double>(), j["bary"][1].get<double>(),
                                                             j["bary"][2].get<double>()));
            p = map.Map(p);
            // element by element: the arrays stay the ones the session holds
            j["face"] = p.face;
            for (int k = 0; k < 3; ++k) j["bary"][k] = p.bary[k];
            if (j.contains("position") && j["position"].is_array() && j["position"].size() == 3 && p.OnMesh(m)) {
                const vcg::Point3d x = p.Pd(m);
                for (int k = 0; k < 3; ++k) j["position"][k] = x[k];
            }
            return;
        }
        for (auto it = j.begin(); it != j.end(); ++it) walk(it.value(), map, m);
    }
};

} // namespace tri
} // namespace vcg

#endif
