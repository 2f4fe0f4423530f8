#ifndef VCG_EXT_CUT_CUT_SESSION_MAP_H
#define VCG_EXT_CUT_CUT_SESSION_MAP_H

// The edit tool's session (SnakeController::ToJson: snakes, their initial curves and
// polylines, seed points) saved on the mesh before a cut, rewritten for the mesh after it:
// every surface point ({"face", "bary", "position"}) goes through the cut's CutPointMap, its
// position is recomputed on the new faces, and the session's mesh counts are the new mesh's.
// Seeds are vertex indices: a cut adds vertices after the user's, so they stay valid.
// The snake cut along keeps the embedded curve as its polyline (KeepCurve): traced anew on
// the split faces it would move by a few percent of an edge, and cutting along it again would
// split the mesh again.

#include <unordered_map>
#include <vector>

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

    /// After the controller restored the mapped session (Map) on the cut mesh m: snake `snake`,
    /// the one cut along, takes the embedded curve (MeshCut::Result::chains[k]) as its polyline:
    /// its samples are vertices of that chain, the chain's vertices between them its crossings.
    /// Returns false, the snake keeping its trace, when its samples are not on the chain in order.
    template <class Controller>
    static bool KeepCurve(Controller &c, int snake, const std::vector<SurfacePoint> &chain, const MeshType &m)
    {
        if (snake < 0 || snake >= c.SnakeCount() || chain.empty()) return false;
        auto &s = c.Get(snake);
        auto vertexOf = [&](const SurfacePoint &p) {
            int k = 0;
            for (int h = 1; h < 3; ++h)
                if (p.bary[h] > p.bary[k]) k = h;
            return p.OnMesh(m) ? int(vcg::tri::Index(m, m.face[p.face].cV(k))) : -1;
        };
        std::unordered_map<int, int> at; // chain vertex -> its place in the chain
        for (size_t i = 0; i < chain.size(); ++i) at.emplace(vertexOf(chain[i]), int(i));
        const auto &samples = s.Samples();
        const int n = int(samples.size()), len = int(chain.size());
        std::vector<int> place(n);
        for (int i = 0; i < n; ++i) {
            auto it = at.find(vertexOf(samples[i].p));
            if (it == at.end()) return false;
            place[i] = it->second;
        }
        std::vector<SurfacePoint> line;
        int walked = 0; // along the chain, which the samples follow once in order
        for (int i = 0; i < n; ++i) {
            line.push_back(samples[i].p);
            if (i + 1 == n && !s.Closed()) break;
            const int a = place[i], b = place[(i + 1) % n];
            int steps = s.Closed() ? (b - a + len) % len : b - a;
            if (steps < 0) return false;
            walked += steps;
            for (int j = 1; j < steps; ++j) line.push_back(chain[(a + j) % len]);
        }
        if (s.Closed() ? walked != len : (place[0] != 0 || walked != len - 1)) return false;
        return s.KeepPolyline(line);
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
