#ifndef VCG_EXT_SNAKE_IO_H
#define VCG_EXT_SNAKE_IO_H

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <vcg_ext/io/input_file.h>
#include <vcg_ext/io/safe_file_write.h>
#include <vcg_ext/snake/geometric_snake.h>

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
    /// j[key] as a number (def when absent); a message instead of a conversion of the wrong type.
    static double RealFrom(const json &j, const char *key, double def)
    {
        if (!j.is_object()) throw SnakeError(std::string("Snake JSON: expected an object holding \"") + key + "\".");
        if (!j.contains(key)) return def;
        const json &v = j[key];
        if (!v.is_number()) throw SnakeError(std::string("Snake JSON: \"") + key + "\" must be a number, not " + v.type_name() + ".");
        return v.get<double>();
    }
    /// j[key] as an int, range-checked before the conversion (1e20 does not fit).
    static int IntFrom(const json &j, const char *key, int def)
    {
        const double x = RealFrom(j, key, def);
        if (!(x >= double(std::numeric_limits<int>::min()) && x <= double(std::numeric_limits<int>::max())) ||
            x != std::floor(x))
            throw SnakeError(std::string("Snake JSON: \"") + key + "\" must be a whole number, not " + j[key].dump() + ".");
        return int(x);
    }

    static SnakeParams ParamsFromJson(const json &j, SnakeParams p = SnakeParams())
    {
        if (!j.is_object()) throw SnakeError("Snake JSON: \"params\" must be an object.");
        p.alpha = RealFrom(j, "alpha", p.alpha);
        p.beta = RealFrom(j, "beta", p.beta);
        p.gamma = RealFrom(j, "gamma", p.gamma);
        p.externalWeight = RealFrom(j, "external_weight", p.externalWeight);
        p.spacing = RealFrom(j, "spacing", p.spacing);
        p.updatesPerOperation = IntFrom(j, "updates_per_operation", p.updatesPerOperation);
        p.segmentSamples = IntFrom(j, "segment_samples", p.segmentSamples);
        p.virtualLayers = IntFrom(j, "virtual_layers", p.virtualLayers);
        p.maxStep = RealFrom(j, "max_step", p.maxStep);
        p.convergenceTol = RealFrom(j, "convergence_tol", p.convergenceTol);
        p.convergenceWindow = IntFrom(j, "convergence_window", p.convergenceWindow);
        p.balloon = RealFrom(j, "balloon", p.balloon);
        const int method = IntFrom(j, "method", int(p.method));
        if (method < 0 || method > 1) throw SnakeError("Snake JSON: \"method\" must be 0 or 1.");
        p.method = SnakeMethod(method);
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
        j["length_scale"] = s.LengthScale(); // the unit of spacing, steps and tolerances
        j["seeds"] = s.SeedVertices();
        j["seed_points"] = json::array();
        for (const auto &p : s.SeedPoints()) j["seed_points"].push_back(PointJson(m, p));
        j["initial"] = {{"samples", SamplesJson(m, s.InitialSamples())}, {"polyline", PolylineJson(m, s.InitialPolyline())}};
        j["samples"] = SamplesJson(m, s.Samples());
        j["polyline"] = PolylineJson(m, polyline);
        // a curve running through mesh vertices only (the curve a cut embedded, kept by
        // GeometricSnake::KeepPolyline): its points, so a restored snake keeps it instead of a
        // new trace that would leave the embedded edges (older files lack it: traced anew)
        if (OnVertices(polyline)) {
            j["embedded"] = json::array();
            for (const auto &p : polyline) j["embedded"].push_back(PointJson(m, p));
        }
        j["params"] = ParamsJson(s.Params());
        j["stats"] = {{"operations", st.operations},
                      {"updates", st.updates},
                      {"embeddings", st.embeddings},
                      {"converged", st.converged},
                      {"stop", SnakeStopKey(st.stop)},
                      {"stop_message", st.stopMessage},
                      {"seconds_total", st.secondsTotal},
                      {"ms_per_embedding", SnakeStats::Median(st.msEmbedding)},
                      {"ms_per_update", SnakeStats::Median(st.msUpdate)},
                      {"ms_per_operation", SnakeStats::Median(st.msOperation)},
                      {"region_failures", st.regionFailures},
                      {"warnings", st.warnings}};
        return j;
    }

    /// A whole number in [0, INT_MAX] from JSON, checked before any conversion (a float such as
    /// 1e20 would overflow the int).
    static int IndexFromJson(const json &v, const char *what)
    {
        if (v.is_number_unsigned() || v.is_number_integer()) {
            const long long x = v.get<long long>();
            if (x >= 0 && x <= std::numeric_limits<int>::max()) return int(x);
        } else if (v.is_number_float()) {
            const double x = v.get<double>();
            if (std::isfinite(x) && x >= 0 && x <= double(std::numeric_limits<int>::max()) && x == std::floor(x))
                return int(x);
        } else {
            throw SnakeError(std::string("Snake JSON: \"") + what + "\" must be a number, not " + v.type_name() + ".");
        }
        throw SnakeError(std::string("Snake JSON: \"") + what + "\" is " + v.dump() +
                         ", which is not a valid index (a whole number from 0).");
    }

    /// Every point at a vertex of its face (one barycentric coordinate 1).
    static bool OnVertices(const std::vector<SurfacePoint> &pl)
    {
        for (const auto &p : pl)
            if (std::max(p.bary[0], std::max(p.bary[1], p.bary[2])) < 1 - 1e-12) return false;
        return !pl.empty();
    }

    static std::vector<SurfacePoint> PointsOf(const std::vector<SnakeSample> &s)
    {
        std::vector<SurfacePoint> out;
        for (const auto &x : s) out.push_back(x.p);
        return out;
    }

    static std::vector<SnakeSample> SamplesFromJson(const MeshType &m, const json &a)
    {
        std::vector<SnakeSample> out;
        if (!a.is_array()) throw SnakeError("Snake JSON: \"samples\" must be an array.");
        out.reserve(a.size());
        for (const auto &j : a) {
            if (!j.is_object()) throw SnakeError("Snake JSON: each sample must be an object with \"face\" and \"bary\".");
            SnakeSample s;
            if (!j.contains("face")) throw SnakeError("Snake JSON: a sample has no \"face\".");
            s.p.face = IndexFromJson(j["face"], "face");
            if (!j.contains("bary")) throw SnakeError("Snake JSON: a sample has no \"bary\".");
            const auto &b = j["bary"];
            if (!b.is_array() || b.size() != 3 || !b[0].is_number() || !b[1].is_number() || !b[2].is_number())
                throw SnakeError("Snake JSON: \"bary\" must have 3 numbers.");
            s.p.bary = vcg::Point3d(b[0].get<double>(), b[1].get<double>(), b[2].get<double>());
            if (j.contains("fixed") && !j["fixed"].is_boolean())
                throw SnakeError("Snake JSON: \"fixed\" must be true or false.");
            s.fixed = j.value("fixed", false);
            if (s.p.face >= int(m.face.size()) || m.face[s.p.face].IsD())
                throw SnakeError("Snake JSON: sample on face " + std::to_string(s.p.face) + ", which this mesh does not have.");
            if (!s.p.IsValid())
                throw SnakeError("Snake JSON: a sample on face " + std::to_string(s.p.face) +
                                 " has invalid barycentric coordinates.");
            s.p.Normalize();
            out.push_back(s);
        }
        return out;
    }

    /// "[json.exception.type_error.302] type must be number, but is string" -> what a user can act on.
    static std::string JsonErrorText(const json::exception &e)
    {
        std::string w = e.what();
        const size_t close = w.find("] ");
        if (w.rfind("[json.exception.", 0) == 0 && close != std::string::npos) w = w.substr(close + 2);
        if (dynamic_cast<const json::parse_error *>(&e)) return "it is not valid JSON (" + w + ")";
        if (dynamic_cast<const json::type_error *>(&e)) return "a value has the wrong type (" + w + ")";
        if (dynamic_cast<const json::out_of_range *>(&e)) return "an entry is missing or out of range (" + w + ")";
        return w;
    }

    /// A snake's saved length unit; 0 (derive it from the samples' faces) when absent or not positive.
    static double LengthScaleFrom(const json &j)
    {
        const double u = RealFrom(j, "length_scale", 0);
        return std::isfinite(u) && u > 0 ? u : 0;
    }

    /// Restores a snake saved by ToJson onto the same mesh.
    static void FromJson(Snake &s, const json &j)
    {
        try {
            if (!j.is_object()) throw SnakeError("Snake JSON: a snake must be an object with \"samples\".");
            if (!j.contains("samples")) throw SnakeError("Snake JSON: the snake has no \"samples\".");
            if (j.contains("closed") && !j["closed"].is_boolean())
                throw SnakeError("Snake JSON: \"closed\" must be true or false.");
            const MeshType &m = s.GetSurface().Mesh();
            if (j.contains("params")) s.SetParams(ParamsFromJson(j["params"], s.Params()));
            s.InitFromSamples(SamplesFromJson(m, j["samples"]), j.value("closed", false), LengthScaleFrom(j));
            if (j.contains("embedded")) s.KeepPolyline(PointsOf(SamplesFromJson(m, j["embedded"])));
        } catch (const json::exception &e) {
            throw SnakeError("Snake JSON: " + JsonErrorText(e) + ".");
        }
    }

    /// The most samples a snake may have (as many as a seed path may give, InitFromPath).
    static constexpr int MaxSnakeSamples() { return 200000; }
    /// The largest snake or session file read (a session of many long snakes is far smaller).
    static constexpr long long MaxFileBytes() { return 256LL << 20; }

    /// Parses a snake or session file keeping only what a restore reads: derived data (the
    /// curve "polyline", each sample's "position", "initial", "stats") is dropped while it is
    /// read, so memory stays about the file's size; a snake of more than MaxSnakeSamples()
    /// samples is refused while reading. `name` is the file, for messages. A SAX handler: the
    /// callback parser of nlohmann::json rescans the parent of every finished object, which
    /// is quadratic in the number of samples.
    static json ParseLean(std::istream &in, const std::string &name)
    {
        LeanSax sax(name, size_t(MaxSnakeSamples()));
        try {
            json::sax_parse(in, &sax);
        } catch (const json::exception &e) {
            throw SnakeError("\"" + name + "\" cannot be read: " + JsonErrorText(e) + ".");
        }
        return std::move(sax.root);
    }

    /// ParseLean on a file; refuses files over MaxFileBytes() before reading them.
    static json ParseFileLean(const std::string &path)
    {
        InputFile::Require(path, "the curve file");
        std::error_code ec;
        const auto size = std::filesystem::file_size(path, ec);
        if (!ec && (long long)size > MaxFileBytes())
            throw SnakeError("\"" + path + "\" is too large (" + std::to_string(size >> 20) + " MB; at most " +
                             std::to_string(MaxFileBytes() >> 20) + " MB are read). It was not loaded.");
        std::ifstream in(path, std::ios::binary);
        if (!in) throw SnakeError("Cannot read \"" + path + "\".");
        return ParseLean(in, path);
    }

    enum class CurveFormat { Json, Obj, Ply };

    /// The format chosen by the file's extension; a message naming the file otherwise.
    static CurveFormat FormatOf(const std::string &path)
    {
        const std::string ext = SafeFileWrite::Extension(path);
        if (ext == "json") return CurveFormat::Json;
        if (ext == "obj") return CurveFormat::Obj;
        if (ext == "ply") return CurveFormat::Ply;
        if (ext.empty())
            throw SnakeError("\"" + path + "\" has no extension: name the file .json, .obj or .ply to choose the format.");
        throw SnakeError("Unknown curve format \"." + ext + "\" of \"" + path + "\" (use .json, .obj or .ply).");
    }

    /// The file's content: .json (all snakes), .obj (`l` records), .ply (edges).
    static std::string CurvesText(CurveFormat format, const std::vector<Snake *> &snakes)
    {
        std::ostringstream out;
        out.precision(9);
        if (format == CurveFormat::Json) {
            json j;
            if (snakes.size() == 1) j = ToJson(*snakes[0]);
            else {
                j["snakes"] = json::array();
                for (auto *s : snakes) j["snakes"].push_back(ToJson(*s));
            }
            out << j.dump(1) << "\n";
        } else if (format == CurveFormat::Obj) {
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
        } else {
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
        }
        if (!out) throw SnakeError("Formatting the curves failed.");
        return out.str();
    }

    /// Writes curves by extension: .json (all snakes), .obj (`l` records), .ply (edges). The
    /// name and format are checked before anything is written, and the file is replaced only by
    /// a complete new one (SafeFileWrite); `keep` lists files never to overwrite (the mesh, its sidecar).
    static void WriteCurves(const std::string &path, const std::vector<Snake *> &snakes,
                            const std::vector<ProtectedFile> &keep = {})
    {
        const CurveFormat format = FormatOf(path);
        SafeFileWrite::CheckTarget(path, keep);
        SafeFileWrite::Write(path, CurvesText(format, snakes), keep);
    }

private:
    /// Builds the DOM of a snake file without the keys a restore does not read (see ParseLean).
    class LeanSax : public nlohmann::json_sax<json>
    {
    public:
        json root;
        LeanSax(const std::string &file, size_t maxSamples) : name(file), cap(maxSamples) {}

        bool null() override { return add(json()); }
        bool boolean(bool v) override { return add(json(v)); }
        bool number_integer(number_integer_t v) override { return add(json(v)); }
        bool number_unsigned(number_unsigned_t v) override { return add(json(v)); }
        bool number_float(number_float_t v, const string_t &) override { return add(json(v)); }
        bool string(string_t &v) override { return add(json(v)); }
        bool binary(binary_t &) override { return add(json()); }
        bool start_object(std::size_t) override { return open(json::object()); }
        bool start_array(std::size_t) override { return open(json::array()); }
        bool end_object() override { return close(); }
        bool end_array() override { return close(); }
        bool key(string_t &k) override
        {
            if (skip > 0) return true;
            if (k == "polyline" || k == "position" || k == "initial" || k == "stats") skipNext = true;
            else if (k == "samples") samples = 0; // counted per snake
            else if (k == "face" && ++samples > cap)
                throw SnakeError("\"" + name + "\" holds a snake of more than " + std::to_string(cap) +
                                 " samples, the most a snake may have. It was not loaded.");
            key_ = k;
            return true;
        }
        bool parse_error(std::size_t, const std::string &, const nlohmann::detail::exception &e) override
        {
            std::string w = e.what();
            const size_t close = w.find("] ");
            if (close != std::string::npos) w = w.substr(close + 2);
            throw SnakeError("\"" + name + "\" cannot be read: it is not valid JSON (" + w + ").");
        }

    private:
        std::string name;
        size_t cap, samples = 0;
        std::vector<json *> stack; // the open containers, innermost last
        std::string key_;
        int skip = 0;              // depth inside a dropped value
        bool skipNext = false;     // the next value is dropped

        json *put(json &&v)
        {
            if (stack.empty()) {
                root = std::move(v);
                return &root;
            }
            json &top = *stack.back();
            if (top.is_array()) {
                top.push_back(std::move(v));
                return &top.back();
            }
            json &slot = top[key_];
            slot = std::move(v);
            return &slot;
        }
        bool add(json &&v)
        {
            if (skip > 0) return true;
            if (skipNext) { skipNext = false; return true; }
            put(std::move(v));
            return true;
        }
        bool open(json &&v)
        {
            if (skip > 0 || skipNext) {
                skipNext = false;
                ++skip;
                return true;
            }
            stack.push_back(put(std::move(v)));
            return true;
        }
        bool close()
        {
            if (skip > 0) --skip;
            else stack.pop_back();
            return true;
        }
    };
};

} // namespace tri
} // namespace vcg

#endif
