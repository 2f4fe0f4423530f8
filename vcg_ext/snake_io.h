#ifndef VCG_EXT_SNAKE_IO_H
#define VCG_EXT_SNAKE_IO_H

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <vcg_ext/geometric_snake.h>

namespace vcg {
namespace tri {

/// Snakes to and from JSON (the stable contract of the batch filter and the edit tool's
/// sidecar file), and curve export to OBJ (`l` records) and PLY (vertex + edge elements).
template <class MeshType>
class SnakeIO
{
public:
    typedef GeometricSnake<MeshType> Snake;
    typedef nlohmann::json json;

    static json PointJson(const MeshType &m, const SurfacePoint &p)
    {
        vcg::Point3d x = p.Pd(m);
        return json{{"face", p.face}, {"bary", {p.bary[0], p.bary[1], p.bary[2]}}, {"position", {x[0], x[1], x[2]}}};
    }
    static json SamplesJson(const MeshType &m, const std::vector<SnakeSample> &s)
    {
        json a = json::array();
        for (const auto &x : s) {
            json j = PointJson(m, x.p);
            j["fixed"] = x.fixed;
            a.push_back(j);
        }
        return a;
    }
    static json PolylineJson(const MeshType &m, const std::vector<SurfacePoint> &pl)
    {
        json a = json::array();
        for (const auto &p : pl) {
            vcg::Point3d x = p.Pd(m);
            a.push_back({x[0], x[1], x[2]});
        }
        return a;
    }
    static json ParamsJson(const SnakeParams &p)
    {
        return json{{"alpha", p.alpha}, {"beta", p.beta}, {"gamma", p.gamma}, {"external_weight", p.externalWeight},
                    {"spacing", p.spacing}, {"updates_per_operation", p.updatesPerOperation},
                    {"segment_samples", p.segmentSamples}, {"virtual_layers", p.virtualLayers},
                    {"max_step", p.maxStep}, {"convergence_tol", p.convergenceTol},
                    {"convergence_window", p.convergenceWindow}, {"balloon", p.balloon},
                    {"method", int(p.method)}};
    }
    static SnakeParams ParamsFromJson(const json &j, SnakeParams p = SnakeParams())
    {
        p.alpha = j.value("alpha", p.alpha);
        p.beta = j.value("beta", p.beta);
        p.gamma = j.value("gamma", p.gamma);
        p.externalWeight = j.value("external_weight", p.externalWeight);
        p.spacing = j.value("spacing", p.spacing);
        p.updatesPerOperation = j.value("updates_per_operation", p.updatesPerOperation);
        p.segmentSamples = j.value("segment_samples", p.segmentSamples);
        p.virtualLayers = j.value("virtual_layers", p.virtualLayers);
        p.maxStep = j.value("max_step", p.maxStep);
        p.convergenceTol = j.value("convergence_tol", p.convergenceTol);
        p.convergenceWindow = j.value("convergence_window", p.convergenceWindow);
        p.balloon = j.value("balloon", p.balloon);
        p.method = SnakeMethod(j.value("method", int(p.method)));
        p.Validate();
        return p;
    }

    /// One snake: closed, initial {samples, polyline}, samples, polyline, params, stats.
    static json ToJson(Snake &s)
    {
        const MeshType &m = s.GetSurface().Mesh();
        const SnakeStats &st = s.Stats();
        // the polyline first: tracing untraced gaps may re-express the samples' barycentric
        // coordinates, and the samples written must be those of the curve written
        const std::vector<SurfacePoint> polyline = s.Polyline();
        json j;
        j["closed"] = s.Closed();
        j["seeds"] = s.SeedVertices();
        j["seed_points"] = json::array();
        for (const auto &p : s.SeedPoints()) j["seed_points"].push_back(PointJson(m, p));
        j["initial"] = {{"samples", SamplesJson(m, s.InitialSamples())}, {"polyline", PolylineJson(m, s.InitialPolyline())}};
        j["samples"] = SamplesJson(m, s.Samples());
        j["polyline"] = PolylineJson(m, polyline);
        j["params"] = ParamsJson(s.Params());
        j["stats"] = {{"operations", st.operations},
                      {"updates", st.updates},
                      {"embeddings", st.embeddings},
                      {"converged", st.converged},
                      {"seconds_total", st.secondsTotal},
                      {"ms_per_embedding", SnakeStats::Median(st.msEmbedding)},
                      {"ms_per_update", SnakeStats::Median(st.msUpdate)},
                      {"ms_per_operation", SnakeStats::Median(st.msOperation)},
                      {"region_failures", st.regionFailures},
                      {"warnings", st.warnings}};
        return j;
    }

    static std::vector<SnakeSample> SamplesFromJson(const MeshType &m, const json &a)
    {
        std::vector<SnakeSample> out;
        if (!a.is_array()) throw SnakeError("Snake JSON: \"samples\" must be an array.");
        for (const auto &j : a) {
            SnakeSample s;
            s.p.face = j.at("face").get<int>();
            const auto &b = j.at("bary");
            if (!b.is_array() || b.size() != 3) throw SnakeError("Snake JSON: \"bary\" must have 3 numbers.");
            s.p.bary = vcg::Point3d(b[0].get<double>(), b[1].get<double>(), b[2].get<double>());
            s.fixed = j.value("fixed", false);
            if (s.p.face < 0 || s.p.face >= int(m.face.size()) || m.face[s.p.face].IsD() || !s.p.IsValid())
                throw SnakeError("Snake JSON: sample on face " + std::to_string(s.p.face) + ", which this mesh does not have.");
            s.p.Normalize();
            out.push_back(s);
        }
        return out;
    }

    /// Restores a snake saved by ToJson onto the same mesh.
    static void FromJson(Snake &s, const json &j)
    {
        try {
            const MeshType &m = s.GetSurface().Mesh();
            if (j.contains("params")) s.SetParams(ParamsFromJson(j["params"], s.Params()));
            s.InitFromSamples(SamplesFromJson(m, j.at("samples")), j.value("closed", false));
        } catch (const json::exception &e) {
            throw SnakeError(std::string("Snake JSON: ") + e.what());
        }
    }

    /// Writes curves by extension: .json (all snakes), .obj (`l` records), .ply (edges).
    static void WriteCurves(const std::string &path, const std::vector<Snake *> &snakes)
    {
        std::string ext = path.size() >= 4 ? path.substr(path.find_last_of('.') + 1) : "";
        for (auto &c : ext) c = char(std::tolower(c));
        std::ofstream out(path);
        if (!out) throw SnakeError("Cannot write \"" + path + "\".");
        out.precision(9);
        if (ext == "json") {
            json j;
            if (snakes.size() == 1) j = ToJson(*snakes[0]);
            else {
                j["snakes"] = json::array();
                for (auto *s : snakes) j["snakes"].push_back(ToJson(*s));
            }
            out << j.dump(1) << "\n";
        } else if (ext == "obj") {
            out << "# geometric snake curves\n";
            size_t base = 1;
            for (auto *s : snakes) {
                std::vector<vcg::Point3d> pl = s->PolylinePositions();
                for (auto &p : pl) out << "v " << p[0] << " " << p[1] << " " << p[2] << "\n";
                out << "l";
                for (size_t i = 0; i < pl.size(); ++i) out << " " << base + i;
                if (s->Closed() && !pl.empty()) out << " " << base;
                out << "\n";
                base += pl.size();
            }
        } else if (ext == "ply") {
            std::vector<vcg::Point3d> v;
            std::vector<std::pair<size_t, size_t>> e;
            for (auto *s : snakes) {
                std::vector<vcg::Point3d> pl = s->PolylinePositions();
                size_t b = v.size();
                v.insert(v.end(), pl.begin(), pl.end());
                for (size_t i = 0; i + 1 < pl.size(); ++i) e.push_back({b + i, b + i + 1});
                if (s->Closed() && pl.size() > 2) e.push_back({b + pl.size() - 1, b});
            }
            out << "ply\nformat ascii 1.0\ncomment geometric snake curves\nelement vertex " << v.size()
                << "\nproperty float x\nproperty float y\nproperty float z\nelement edge " << e.size()
                << "\nproperty int vertex1\nproperty int vertex2\nend_header\n";
            for (auto &p : v) out << p[0] << " " << p[1] << " " << p[2] << "\n";
            for (auto &x : e) out << x.first << " " << x.second << "\n";
        } else {
            throw SnakeError("Unknown curve format \"" + ext + "\" (use .json, .obj or .ply).");
        }
        if (!out) throw SnakeError("Writing \"" + path + "\" failed.");
    }
};

} // namespace tri
} // namespace vcg

#endif
