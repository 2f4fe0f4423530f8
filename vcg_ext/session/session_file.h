#ifndef VCG_EXT_SNAKE_SESSION_FILE_H
#define VCG_EXT_SNAKE_SESSION_FILE_H

// The edit tool's session file (format "geometric-snake-session", e.g. the sidecar
// <mesh>.snakes.json): energy settings, parameters, the seeds being placed and the snakes with
// their pins. Read is all or nothing: every field is validated against the mesh before anything
// is used, and a SnakeError says what is wrong in the file.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <vcg_ext/energy/crease_energy.h>
#include <vcg_ext/energy/feature_energy.h>
#include <vcg_ext/io/snake_io.h>
#include <vcg_ext/paths/seed_list.h>
#include <vcg_ext/paths/seed_path_cost.h>
#include <vcg_ext/snake/error.h>

namespace vcg {
namespace tri {

template <class MeshType>
struct SnakeSessionFile
{
    typedef SnakeIO<MeshType> IO;
    typedef nlohmann::json json;

    static const char *FormatName() { return "geometric-snake-session"; }
    static int FormatVersion() { return 1; }

    /// A snake as saved: enough to rebuild it with GeometricSnake::InitFromSamples.
    struct SavedSnake
    {
        SnakeParams params;
        std::vector<SnakeSample> samples;
        bool closed = false;
        double lengthScale = 0;
        /// the curve a cut embedded, through mesh vertices ("embedded", SnakeIO::ToJson): kept
        /// by GeometricSnake::KeepPolyline; empty in older files
        std::vector<SurfacePoint> embedded;
    };

    bool energyFromQuality = false; ///< the vertex quality as it is, not a computed energy
    FeatureEnergyType energyType = FeatureEnergyType::NormalVariation;
    int energySmoothing = 2;
    double creaseAngle = CreaseEnergy<MeshType>::DefaultAngle();
    SnakeParams params;
    SeedPathCost seedCost = SeedPathCost::Length;
    int selected = -1;
    SnakeSeedList<MeshType> seeds;
    std::vector<SavedSnake> snakes;

    explicit SnakeSessionFile(const MeshType &m) : seeds(m) {}

    /// The file's header, energy settings, parameters and seeds (the snakes are written by the
    /// caller with SnakeIO::ToJson, into "snakes").
    json HeaderJson(const MeshType &m) const
    {
        json j;
        j["format"] = FormatName();
        j["version"] = FormatVersion();
        j["mesh"] = {{"vertices", int(m.vert.size())}, {"faces", int(m.face.size())}};
        j["energy"] = {{"type", energyFromQuality ? -1 : int(energyType)}, {"smoothing", energySmoothing},
                       {"crease_angle", creaseAngle}};
        j["params"] = IO::ParamsJson(params);
        j["seed_cost"] = int(seedCost);
        j["selected"] = selected;
        j["seeds"] = seeds.Vertices();
        // where each seed was clicked (null: the vertex itself)
        j["seed_points"] = json::array();
        for (int i = 0; i < seeds.size(); ++i) {
            const SurfacePoint &sp = seeds.Point(i);
            j["seed_points"].push_back(sp.face >= 0 ? IO::PointJson(m, sp) : json());
        }
        j["snakes"] = json::array();
        return j;
    }

    /// Reads a session saved on mesh m; throws SnakeError (another mesh, a broken file).
    static SnakeSessionFile Read(const MeshType &m, const json &j)
    {
        SnakeSessionFile f(m);
        try {
            if (!j.is_object() || j.value("format", std::string()) != FormatName())
                throw SnakeError("Geometric snake: not a snake session file.");
            if (IO::IntFrom(j, "version", 0) > FormatVersion())
                throw SnakeError("Geometric snake: the session file is from a newer version.");
            if (!j.contains("mesh")) throw SnakeError("Geometric snake: the session file does not say which mesh it belongs to.");
            const json &jm = j["mesh"];
            const int nv = IO::IntFrom(jm, "vertices", -1), nf = IO::IntFrom(jm, "faces", -1);
            if (nv != int(m.vert.size()) || nf != int(m.face.size()))
                throw SnakeError("Geometric snake: the session was saved on another mesh (" + std::to_string(nv) +
                                 " vertices, " + std::to_string(nf) + " faces; this mesh has " +
                                 std::to_string(m.vert.size()) + " and " + std::to_string(m.face.size()) + ").");
            f.params = j.contains("params") ? IO::ParamsFromJson(j["params"]) : SnakeParams();
            const json &je = j.contains("energy") ? j["energy"] : json::object();
            const int etype = IO::IntFrom(je, "type", 0); // -1: the vertex quality as it is
            f.energySmoothing = IO::IntFrom(je, "smoothing", 2);
            if (etype < -1 || etype >= FeatureEnergyTypeCount() || f.energySmoothing < 0 || f.energySmoothing > 1000)
                throw SnakeError("Geometric snake: bad energy settings in the session file.");
            f.energyFromQuality = etype == -1;
            f.energyType = FeatureEnergyType(std::max(0, etype));
            f.creaseAngle = IO::RealFrom(je, "crease_angle", CreaseEnergy<MeshType>::DefaultAngle());
            if (!std::isfinite(f.creaseAngle) || f.creaseAngle <= 0 || f.creaseAngle >= 180)
                throw SnakeError("Geometric snake: bad crease angle in the session file.");
            const int sc = IO::IntFrom(j, "seed_cost", 0);
            if (sc < 0 || sc > 1) throw SnakeError("Geometric snake: bad seed cost in the session file.");
            f.seedCost = SeedPathCost(sc);

            std::vector<int> sv;
            if (j.contains("seeds")) {
                if (!j["seeds"].is_array()) throw SnakeError("Geometric snake: \"seeds\" must be a list of vertex indices.");
                for (const json &v : j["seeds"]) sv.push_back(IO::IndexFromJson(v, "seeds"));
            }
            // "seeds" is what counts: "seed_points" (where each was clicked) only when it lists one
            // point (or null) per seed, so a hand-edited seed list is not refused
            std::vector<SurfacePoint> at(sv.size());
            if (j.contains("seed_points") && j["seed_points"].is_array() && j["seed_points"].size() == sv.size()) {
                const json &jp = j["seed_points"];
                for (size_t i = 0; i < sv.size(); ++i)
                    if (!jp[i].is_null()) at[i] = IO::SamplesFromJson(m, json::array({jp[i]}))[0].p;
            }
            f.seeds.Set(sv, at);

            if (!j.contains("snakes") || !j["snakes"].is_array())
                throw SnakeError("Geometric snake: the session file has no list of \"snakes\".");
            for (const json &js : j["snakes"]) {
                if (!js.is_object() || !js.contains("samples"))
                    throw SnakeError("Geometric snake: a snake in the session file has no \"samples\".");
                if (js.contains("closed") && !js["closed"].is_boolean())
                    throw SnakeError("Geometric snake: \"closed\" must be true or false.");
                SavedSnake s;
                s.params = js.contains("params") ? IO::ParamsFromJson(js["params"], f.params) : f.params;
                s.samples = IO::SamplesFromJson(m, js["samples"]);
                s.closed = js.value("closed", false);
                s.lengthScale = IO::LengthScaleFrom(js);
                if (js.contains("embedded")) s.embedded = IO::PointsOf(IO::SamplesFromJson(m, js["embedded"]));
                f.snakes.push_back(std::move(s));
            }
            const int n = int(f.snakes.size());
            f.selected = IO::IntFrom(j, "selected", n == 0 ? -1 : 0);
            if (f.selected < 0 || f.selected >= n) f.selected = n == 0 ? -1 : 0;
        } catch (const json::exception &e) {
            throw SnakeError("Geometric snake: broken session file: " + IO::JsonErrorText(e) + ".");
        }
        return f;
    }
};

} // namespace tri
} // namespace vcg

#endif
