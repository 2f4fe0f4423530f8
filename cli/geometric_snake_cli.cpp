// geometric-snake: the plugin's batch operations as one command-line program, over the same
// vcg_ext engine, with the same parameters (vcg_ext/session/param_defs.h) and outputs (JSON
// contract, OBJ `l` records, PLY edges, the mesh with the energy in its quality).
//
//   geometric-snake energy MESH [--type normal|curvature|quadric|crease|part] [--smoothing K] -o OUT.ply
//   geometric-snake snake MESH --seeds "i,j,k" [--closed] [--alpha A] ... -o OUT.json|.obj|.ply
//   geometric-snake path MESH --seeds "i,j,k" [--closed] [--cost length|feature] -o OUT.ply
//   geometric-snake cut MESH --curve CURVE.json [--mode M] [--side S] [--split] -o OUT.ply
//   geometric-snake --batch CASES.jsonl [--jobs N]
//
// Each operation repeats the steps of its MeshLab filter (filter_geometric_snake.cpp) on a mesh
// read the way MeshLab reads it, so both give the same curve; the CLI test checks that.

#include <sys/wait.h>
#include <csignal>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_mesh_io.h"

#include <vcg/complex/algorithms/stat.h>
#include <vcg/complex/algorithms/update/color.h>
#include <vcg_ext/cut/cut_curve_io.h>
#include <vcg_ext/cut/mesh_cut.h>
#include <vcg_ext/energy/feature_energy.h>
#include <vcg_ext/io/seed_list_text.h>
#include <vcg_ext/io/snake_io.h>
#include <vcg_ext/paths/seed_path.h>
#include <vcg_ext/paths/seed_points.h>
#include <vcg_ext/session/controller.h>
#include <vcg_ext/session/param_defs.h>
#include <vcg_ext/session/sidecar.h>
#include <vcg_ext/snake/batch.h>
#include <vcg_ext/surface/mesh_validation.h>
#include <vcg_ext/surface/triangle_soup.h>

using nlohmann::json;
using namespace vcg::tri;

namespace gs_cli {

const char *const kProgram = "geometric-snake";
typedef std::chrono::steady_clock Clock;

/// Bad command line (exit status 2); SnakeError is bad input or a failed run (exit status 1).
struct UsageError : std::runtime_error
{
    explicit UsageError(const std::string &m) : std::runtime_error(m) {}
};

double Since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// ============================================================================ subcommands
struct Command
{
    std::string name;
    const std::vector<ParamDef> *defs;
    std::vector<std::string> outputs; ///< formats of -o
    bool outputRequired;
    std::string summary;
};

const std::vector<Command> &Commands()
{
    static const std::vector<Command> c = {
        {"energy", &SnakeParamDefs::FeatureEnergy(), {"ply"}, true,
         "Computes the feature energy (0 on features, 1 on flat regions) into the vertex quality and writes the "
         "mesh with it (filter \"Compute Geometric Snake Feature Energy\")."},
        {"snake", &SnakeParamDefs::Snake(), {"json", "obj", "ply"}, false,
         "Runs a geometric snake from seeds (vertex indices, 3D points or a MeshLab Pick Points file) onto the "
         "nearby feature and writes the curve: .json (the JSON contract: samples, initial and final curve, "
         "stats), .obj (l records) or .ply (edges) (filter \"Geometric Snake from Seed Vertices\")."},
        {"path", &SnakeParamDefs::SeedPath(), {"ply", "obj", "json"}, true,
         "Joins the seeds (vertex indices, 3D points or a Pick Points file) by shortest paths along mesh edges "
         "(the snake's initial curve) and writes the path as vertices and edges (filter \"Geometric Snake Seed "
         "Path\")."},
        {"cut", &SnakeParamDefs::Cut(), {"ply"}, true,
         "Cuts the mesh along a snake (a curve JSON file made on this mesh): embeds the curve exactly and writes "
         "the mesh with each face's side in its quality (1 inside, 0 outside), selected; --split writes "
         "OUT_inside.ply and OUT_outside.ply instead; --mode cut-open makes the curve's edges boundary edges "
         "(filter \"Cut Mesh along Geometric Snake\")."},
    };
    return c;
}

const Command *FindCommand(const std::string &name)
{
    for (const auto &c : Commands())
        if (c.name == name) return &c;
    return nullptr;
}

// ============================================================================ help
std::string StripHtml(const std::string &s)
{
    std::string out;
    bool tag = false;
    for (size_t i = 0; i < s.size(); ++i) {
        if (s[i] == '<') tag = true;
        else if (s[i] == '>' && tag) tag = false;
        else if (!tag) out += s[i];
    }
    const std::pair<const char *, const char *> ents[] = {{"&lt;", "<"}, {"&gt;", ">"}, {"&amp;", "&"}};
    for (const auto &e : ents)
        for (size_t p; (p = out.find(e.first)) != std::string::npos;) out.replace(p, std::strlen(e.first), e.second);
    return out;
}

/// Word-wraps `text` at 78 columns, every line indented by `indent` spaces.
std::string Wrap(const std::string &text, size_t indent)
{
    std::istringstream in(text);
    std::string word, line, out;
    const std::string pad(indent, ' ');
    while (in >> word) {
        if (!line.empty() && pad.size() + line.size() + 1 + word.size() > 78) {
            out += pad + line + "\n";
            line.clear();
        }
        line += (line.empty() ? "" : " ") + word;
    }
    if (!line.empty()) out += pad + line + "\n";
    std::replace(out.begin(), out.end(), '\1', ' ');
    return out;
}

std::string OptionHelp(const std::string &head, const std::string &text)
{
    std::string s = "  " + head + "\n";
    return s + Wrap(text, 6);
}

/// "snake MESH [--seeds TEXT] [--closed] [--alpha X] ... -o OUT.json|.obj|.ply", from the definitions.
std::string Synopsis(const Command &c)
{
    std::string s = c.name + " MESH";
    for (const ParamDef &d : *c.defs) {
        if (d.option.empty()) continue;
        static const char *const arg[] = {"", "\1N", "\1X", "", "\1TEXT"}; // \1: a space Wrap keeps
        s += " [--" + d.option + (d.kind == ParamDef::Enum ? "\1" + d.RangeText() : arg[d.kind]) + "]";
    }
    std::string outs;
    for (const auto &o : c.outputs) outs += (outs.empty() ? "OUT." : "|.") + o;
    s += c.outputRequired ? " -o\1" + outs : " [-o\1" + outs + "]";
    if (c.name == "snake") s += " [--mesh-out\1MESH.ply]";
    return s + " [--timeout\1S] [--json-log] [-q]";
}

std::string CommandHelp(const Command &c)
{
    std::string s = "usage:\n" + Wrap(std::string(kProgram) + " " + Synopsis(c), 2) + "\n" + Wrap(c.summary, 0) +
                    "\noptions:\n";
    for (const ParamDef &d : *c.defs) {
        if (d.option.empty()) continue;
        std::string head = "--" + d.option;
        std::string tail = " Default: " + (d.kind == ParamDef::Text && d.text.empty() ? "none" : d.DefaultText()) + ".";
        switch (d.kind) {
        case ParamDef::Bool: head += ", --no-" + d.option; break;
        case ParamDef::Int: head += " N"; tail = " Range " + d.RangeText() + "." + tail; break;
        case ParamDef::Real: head += " X"; tail = " Range " + d.RangeText() + "." + tail; break;
        case ParamDef::Enum: head += " " + d.RangeText(); break;
        case ParamDef::Text: head += " TEXT"; break;
        }
        if (d.kind == ParamDef::Enum) {
            tail += " Values:";
            for (const auto &ch : d.choices) tail += " " + ch.key + " (" + ch.label + ")";
            tail += ".";
        }
        s += OptionHelp(head, StripHtml(d.help) + tail + " [MeshLab parameter " + d.name + "]");
    }
    std::string outs;
    for (const auto &o : c.outputs) outs += (outs.empty() ? "." : ", .") + o;
    s += OptionHelp("-o, --output FILE", std::string("Output file, format by extension: ") + outs + "." +
                                             (c.outputRequired ? "" : " Optional with --mesh-out or --json-log."));
    if (c.name == "snake")
        s += OptionHelp("--mesh-out FILE.ply", "Also write the mesh with the feature energy in its vertex quality.");
    s += OptionHelp("--timeout S", "Stop the run after S seconds (wall clock): its temporary files are removed, "
                                   "the reason goes to stderr (and with --json-log to stdout), exit status 1. "
                                   "Default: no limit.");
    s += OptionHelp("--json-log", "Print the run's statistics as one JSON line on stdout.");
    s += OptionHelp("-q, --quiet", "No messages on stderr except errors; no progress bar.");
    return s;
}

std::string MainHelp()
{
    std::string s = std::string("usage: ") + kProgram + " COMMAND MESH [options]\n       " + kProgram +
                    " --batch CASES.jsonl [--jobs N] [--timeout S] [--json-log]\n\n" +
                    Wrap("Geometric snakes (Lee & Lee, Eurographics 2002) on triangle meshes, without MeshLab: "
                         "the same engine, parameters and outputs as the MeshLab filters. MESH is a .ply, .off, "
                         ".obj or .stl file; vertex indices are 0-based, in file order.", 0) +
                    "\ncommands:\n";
    for (const auto &c : Commands()) s += OptionHelp(c.name, c.summary);
    s += "\n";
    for (const auto &c : Commands()) s += CommandHelp(c) + "\n";
    s += "batch:\n" +
         OptionHelp("--batch FILE", "Runs the cases of FILE, one JSON object per line (blank lines and lines "
                                    "starting with # are skipped), in parallel, each in its own process: a bad "
                                    "case reports its error and the others finish. Keys are the command-line "
                                    "option names plus \"command\", \"mesh\", \"output\" (and \"mesh-out\"); "
                                    "relative paths are relative to FILE's folder. Example: {\"command\": "
                                    "\"snake\", \"mesh\": \"part.ply\", \"seeds\": \"12, 40, 77\", \"closed\": true, "
                                    "\"output\": \"part.json\"}. Prints one JSON line per case on stdout as it "
                                    "finishes ({\"case\": N, \"line\": L, \"ok\": true, ...statistics} or {\"case\": "
                                    "N, \"line\": L, \"ok\": false, \"error\": \"...\"}), then with --json-log a "
                                    "summary line.") +
         OptionHelp("-j, --jobs N", "Cases run at once (default: the number of cores).") +
         OptionHelp("--timeout S", "Stop a case that runs longer than S seconds and report it as an error "
                                   "(default: no limit).") +
         "\nexit status: 0 success; 1 the run failed (bad mesh, seeds, parameters or files; in a batch: any "
         "case failed); 2 bad command line.\n"
         "Outputs are written to a temporary file (.NAME.gs-tmp-PID-...) and renamed into place: a failed,\n"
         "interrupted (SIGINT, SIGTERM, SIGHUP), size-limited (ulimit -f) or timed-out run leaves no partial\n"
         "file, and a later write to the same output removes what a killed run left. The program never\n"
         "overwrites the input mesh, its Pick Points file, nor the edit tool's session files\n"
         "(MESH.snakes.json, its backup and recovered sessions).\n";
    return s;
}

// ============================================================================ jobs
/// One run: a command, its mesh, its outputs and its parameter values.
struct Job
{
    const Command *cmd = nullptr;
    std::string mesh, output, meshOut;
    std::unique_ptr<ParamValues> values;
    bool jsonLog = false, quiet = false, progress = false;
};

/// Builds a job from (key, value) pairs: command-line options or the keys of a batch case.
void SetOption(Job &job, const std::string &key, const std::string &value, bool hasValue)
{
    if (key == "o" || key == "output") job.output = value;
    else if (key == "mesh-out" && job.cmd->name == "snake") job.meshOut = value;
    else if (const ParamDef *d = job.values->FindOption(key)) {
        if (!hasValue && d->kind != ParamDef::Bool) throw UsageError("--" + key + " needs a value.");
        job.values->Parse(*d, hasValue ? value : "on", "--" + key);
    } else if (key.compare(0, 3, "no-") == 0 && job.values->FindOption(key.substr(3)) &&
               job.values->FindOption(key.substr(3))->kind == ParamDef::Bool && !hasValue) {
        job.values->SetNumber(job.values->FindOption(key.substr(3))->name, 0);
    } else {
        throw UsageError("\"" + job.cmd->name + "\" has no option --" + key + " (see " + kProgram + " " +
                         job.cmd->name + " --help).");
    }
}

/// The files a job must never overwrite: its input mesh with the edit tool's session files
/// (the filters' rule), and its Pick Points file.
std::vector<ProtectedFile> Keep(const Job &job)
{
    std::vector<ProtectedFile> keep = SnakeSidecar::ProtectedFiles(job.mesh);
    if (const ParamDef *d = job.values->FindOption("pp"))
        if (!job.values->Text(d->name).empty()) keep.push_back({job.values->Text(d->name), "the seed file"});
    if (const ParamDef *d = job.values->FindOption("curve"))
        if (!job.values->Text(d->name).empty()) keep.push_back({job.values->Text(d->name), "the curve file"});
    return keep;
}

/// Validates a job before any work: parameters, outputs (format, folder, not the input).
void CheckJob(Job &job)
{
    if (job.mesh.empty())
        throw UsageError("No mesh given. Usage:\n" + Wrap(std::string(kProgram) + " " + Synopsis(*job.cmd), 2));
    job.values->Check(true);
    if (job.output.empty() && job.cmd->outputRequired)
        throw UsageError("No output file: give -o FILE (" + job.cmd->name + " writes " + job.cmd->outputs[0] + ").");
    if (job.output.empty() && job.meshOut.empty() && !job.jsonLog)
        throw UsageError("Nothing to write: give -o FILE, --mesh-out FILE.ply or --json-log.");
    if (!job.output.empty()) CheckWritable(job.output, job.cmd->outputs, "the output", Keep(job));
    if (!job.meshOut.empty()) {
        CheckWritable(job.meshOut, {"ply"}, "the mesh", Keep(job));
        if (SafeFileWrite::SameFile(job.meshOut, job.output)) throw UsageError("-o and --mesh-out name the same file.");
    }
}

/// The progress bar: on stderr, only when it is a terminal.
class Progress
{
public:
    explicit Progress(bool on) : on_(on) {}
    ~Progress() { Done(); }
    void Show(double fraction, const std::string &what)
    {
        if (!on_) return;
        const int width = 30, fill = int(std::min(1.0, std::max(0.0, fraction)) * width + 0.5);
        const int pct = int(fraction * 100 + 0.5);
        if (pct == last_) return;
        last_ = pct;
        std::fprintf(stderr, "\r%s [%s%s] %3d%%", what.c_str(), std::string(fill, '#').c_str(),
                     std::string(width - fill, ' ').c_str(), pct);
        std::fflush(stderr);
        shown_ = true;
    }
    void Done()
    {
        if (shown_) std::fprintf(stderr, "\r%*s\r", 60, "");
        shown_ = false;
    }

private:
    bool on_, shown_ = false;
    int last_ = -1;
};

void Info(const Job &job, const std::string &msg)
{
    if (!job.quiet) std::fprintf(stderr, "%s\n", msg.c_str());
}

std::string Fmt(const char *f, ...) __attribute__((format(printf, 1, 2)));
std::string Fmt(const char *f, ...)
{
    char buf[1024];
    va_list ap;
    va_start(ap, f);
    std::vsnprintf(buf, sizeof buf, f, ap);
    va_end(ap);
    return buf;
}

/// The seed checks of the filters (after compaction, which a freshly read mesh never needs).
void CheckSeeds(const std::vector<int> &seeds, const CMeshO &m)
{
    for (int s : seeds)
        if (s < 0 || s >= m.vn)
            throw SnakeError("Seed vertex " + std::to_string(s) + " does not exist: the mesh has " +
                             std::to_string(m.vn) + " vertices (valid indices 0.." + std::to_string(m.vn - 1) + ").");
}

/// Seeds as points (--seed-points, else the --pp file) when there are no seed vertices, as the
/// filters' seedPointsWanted. `source` names where they came from.
std::vector<vcg::Point3d> SeedPointsWanted(const Job &job, const std::vector<int> &seeds, std::string &source)
{
    const ParamValues &v = *job.values;
    if (!seeds.empty()) {
        if (v.Text("SeedPoints").find_first_not_of(" \t\r\n") != std::string::npos ||
            v.Text("SeedFile").find_first_not_of(" \t\r\n") != std::string::npos)
            Info(job, "warning: seed vertices are given (--seeds), so --seed-points and --pp are ignored.");
        return {};
    }
    std::vector<vcg::Point3d> pts = SeedPointsParser::FromTextOrFile(v.Text("SeedPoints"), v.Text("SeedFile"), source);
    if (pts.empty())
        throw SnakeError("No seeds given: give --seeds \"i, j, ...\" (0-based vertex indices), --seed-points "
                         "\"x y z; x y z; ...\" or --pp FILE.pp (a MeshLab Pick Points file).");
    return pts;
}

/// Seed points moved onto the surface, said as the filters' Log says it.
SeedPointSnap<CMeshO>::Result Snap(const Job &job, CMeshO &m, const std::vector<vcg::Point3d> &pts, bool closed,
                                   const std::string &source)
{
    const auto snap = SeedPointSnap<CMeshO>::Snap(m, pts, closed ? 3 : 2, closed);
    double worst = 0;
    for (double d : snap.distances) worst = std::max(worst, d);
    Info(job, Fmt("%d seed points from %s, moved onto the surface by at most %g (%.2g%% of the bounding box "
                  "diagonal).", int(snap.points.size()), source.c_str(), worst,
                  100.0 * worst / std::max(snap.bboxDiagonal, 1e-300)));
    return snap;
}

/// A triangle soup is refused, or merged with --merge-duplicates (the filters' handleSoup).
void HandleSoup(const Job &job, CMeshO &m)
{
    const int vn = m.vn;
    const int merged = TriangleSoup<CMeshO>::Handle(m, job.values->Bool("MergeDuplicateVertices"));
    if (merged < 0) return;
    UpdateBounding<CMeshO>::Box(m);
    Info(job, Fmt("The mesh was a triangle soup: merged %d duplicate vertices (%d -> %d vertices, %d faces); vertex "
                  "indices now refer to the merged mesh.", merged, vn, m.vn, m.fn));
}

/// What an output mesh keeps of the input's attributes (`mask`: what the file held), plus the
/// vertex quality (the energy): every output mesh keeps everything the input had.
int KeptAttributes(int mask)
{
    namespace io = vcg::tri::io;
    const int keep = io::Mask::IOM_VERTCOLOR | io::Mask::IOM_FACECOLOR | io::Mask::IOM_VERTTEXCOORD |
                     io::Mask::IOM_WEDGTEXCOORD | io::Mask::IOM_VERTRADIUS | io::Mask::IOM_FACEQUALITY |
                     io::Mask::IOM_VERTNORMAL;
    return (mask & keep) | io::Mask::IOM_VERTQUALITY;
}

json RunEnergy(Job &job, CMeshO &m, int mask, json r)
{
    const ParamValues &v = *job.values;
    const int type = v.Enum("EnergyType"), steps = v.Int("SmoothingSteps");
    const bool colorize = v.Bool("Colorize");
    const double creaseAngle = v.Real("CreaseAngle");
    MeshValidation<CMeshO>::RequireSurface(m);
    HandleSoup(job, m);
    const auto st = FeatureEnergy<CMeshO>::Compute(m, FeatureEnergyType(type), steps, creaseAngle);
    if (colorize) UpdateColor<CMeshO>::PerVertexQualityRamp(m, 0.0f, 1.0f);
    SaveMeshPly(m, job.output, KeptAttributes(mask) | (colorize ? vcg::tri::io::Mask::IOM_VERTCOLOR : 0));
    r["energy_type"] = SnakeParamDefs::EnergyChoices()[type].key;
    r["smoothing"] = steps;
    r["raw_min"] = st.rawMin;
    r["raw_max"] = st.rawMax;
    r["seconds_energy"] = st.seconds;
    r["non_manifold_vertices"] = st.nonManifoldVertices;
    r["degenerate_faces"] = st.degenerateFaces;
    if (type == int(FeatureEnergyType::Crease)) r["creases"] = st.creases;
    json warnings = json::array();
    if (st.constant) warnings.push_back(FeatureEnergy<CMeshO>::ConstantWarning(FeatureEnergyType(type)));
    r["warnings"] = warnings;
    Info(job, Fmt("Feature energy (%s, %d smoothing steps) on %d vertices: raw range [%g, %g], %.2f ms. Wrote %s.",
                  SnakeParamDefs::EnergyChoices()[type].label.c_str(), steps, m.vn, double(st.rawMin),
                  double(st.rawMax), st.seconds * 1e3, job.output.c_str()));
    if (type == int(FeatureEnergyType::Crease))
        Info(job, Fmt("Crease energy: %d sharp edges (dihedral angle above %g degrees).", st.creases, creaseAngle));
    if (st.nonManifoldVertices > 0 || st.degenerateFaces > 0)
        Info(job, Fmt("warning: %d non-manifold vertices, %d degenerate faces (handled, but the energy may be "
                      "unreliable there).", st.nonManifoldVertices, st.degenerateFaces));
    for (const auto &w : warnings) Info(job, "warning: " + w.get<std::string>());
    return r;
}

json RunPath(Job &job, CMeshO &m, int mask, json r)
{
    const ParamValues &v = *job.values;
    const bool closed = v.Bool("Closed");
    const int cost = v.Enum("Cost");
    const std::vector<int> seeds = SeedListText::Parse(v.Text("Seeds"));
    std::string source;
    const std::vector<vcg::Point3d> seedPts = SeedPointsWanted(job, seeds, source);
    MeshValidation<CMeshO>::RequireSurface(m);
    HandleSoup(job, m);
    CheckSeeds(seeds, m);
    if (cost == int(SeedPathCost::Feature) && !(mask & vcg::tri::io::Mask::IOM_VERTQUALITY)) {
        FeatureEnergy<CMeshO>::Compute(m, FeatureEnergyType::NormalVariation, SnakeParamDefs::DefaultSmoothingSteps());
        Info(job, "The mesh has no vertex quality: computed the normal-variation feature energy for the feature cost.");
    }
    // Through seed vertices, or from surface point to surface point (starting and ending at the seeds).
    typename SeedPath<CMeshO>::PointResult path;
    if (seedPts.empty()) {
        const auto vp = SeedPath<CMeshO>::Compute(m, seeds, closed, SeedPathCost(cost));
        path.vertices = vp.vertices;
        path.closed = vp.closed;
        path.length = vp.length;
    } else {
        path = SeedPath<CMeshO>::ComputeFromPoints(m, Snap(job, m, seedPts, closed, source).points, closed,
                                                   SeedPathCost(cost));
    }
    std::vector<vcg::Point3d> pts;
    if (seedPts.empty())
        for (int vi : path.vertices) pts.push_back(vcg::Point3d::Construct(m.vert[vi].cP()));
    else
        for (const auto &sp : path.points) pts.push_back(sp.Pd(m));
    if (pts.empty()) throw SnakeError("No path was found between the seeds.");
    const size_t nSeeds = seedPts.empty() ? seeds.size() : seedPts.size();
    if (Extension(job.output) == "json") {
        json j = {{"closed", path.closed}, {"seeds", seeds}, {"vertices", path.vertices}, {"length", path.length}};
        json pl = json::array();
        for (const auto &p : pts) pl.push_back({p[0], p[1], p[2]});
        j["polyline"] = pl;
        SafeFileWrite::Write(job.output, j.dump(1) + "\n", Keep(job));
    } else {
        SavePolylines({pts}, {closed}, job.output);
    }
    r["closed"] = path.closed;
    r["cost"] = v.Def("Cost").choices[cost].key;
    r["path_vertices"] = path.vertices.size();
    r["length"] = path.length;
    r["path_points"] = pts.size();
    Info(job, Fmt("Seed path (%s, %s cost) through %d seeds: %d points, %d vertices, length %g. Wrote %s.",
                  closed ? "closed" : "open", cost == 0 ? "length" : "feature", int(nSeeds), int(pts.size()),
                  int(path.vertices.size()), path.length, job.output.c_str()));
    return r;
}

json RunSnake(Job &job, CMeshO &m, int mask, json r)
{
    typedef SnakeController<CMeshO> Controller;
    const ParamValues &v = *job.values;
    const std::vector<int> seeds = SeedListText::Parse(v.Text("Seeds")); // as the filter: first
    SnakeBatch<CMeshO>::Settings b = SnakeBatch<CMeshO>::FromValues(v, seeds);
    const bool closed = b.closed, useQuality = b.useQuality;
    const int maxOps = b.maxOperations;
    const SnakeParams &p = b.params;
    std::string source;
    const std::vector<vcg::Point3d> seedPts = SeedPointsWanted(job, seeds, source);

    MeshValidation<CMeshO>::RequireSurface(m);
    HandleSoup(job, m);
    CheckSeeds(seeds, m);
    if (useQuality && !(mask & vcg::tri::io::Mask::IOM_VERTQUALITY))
        throw SnakeError("--use-quality is on, but the mesh has no vertex quality. Compute one first (e.g. "
                         "geometric-snake energy), or leave --use-quality off.");
    MeshValidation<CMeshO>::RequireAdjacencySafe(m);

    const auto t0 = Clock::now();
    Controller ctl(m);
    // What MeshLab's updateDataMask(MM_FACEFACETOPO | MM_VERTFACETOPO) does for the filter,
    // run as there while the energy is computed.
    b.adjacency = [&m] {
        m.face.EnableFFAdjacency();
        m.vert.EnableVFAdjacency();
        m.face.EnableVFAdjacency();
        UpdateTopology<CMeshO>::FaceFace(m);
        UpdateTopology<CMeshO>::VertexFace(m);
    };
    if (!seedPts.empty()) b.seedPoints = Snap(job, m, seedPts, closed, source).points;
    SnakeBatch<CMeshO>::Result res;
    {
        Progress bar(job.progress);
        res = SnakeBatch<CMeshO>::Run(ctl, b, [&](int op) {
            bar.Show(maxOps > 0 ? double(op + 1) / maxOps : 1.0, "snake");
            return true;
        });
    }
    GeometricSnake<CMeshO> &snake = ctl.Get(0);
    const SnakeStats &st = snake.Stats();
    json warnings = json::array(); // as the filter's Log
    for (const auto &w : res.energyWarnings) warnings.push_back(w);
    for (const auto &w : res.runWarnings)
        warnings.push_back(w.second > 1 ? Fmt("%s (%d times in this run)", w.first.c_str(), w.second) : w.first);
    if (!job.output.empty()) {
        std::vector<GeometricSnake<CMeshO> *> list{&snake};
        SnakeIO<CMeshO>::WriteCurves(job.output, list, Keep(job));
    }
    if (!job.meshOut.empty()) SaveMeshPly(m, job.meshOut, KeptAttributes(mask));

    r["closed"] = snake.Closed();
    r["method"] = v.Def("Method").choices[int(p.method)].key;
    r["energy"] = useQuality ? std::string("quality") : SnakeParamDefs::EnergyChoices()[size_t(b.energy)].key;
    r["samples"] = snake.SampleCount();
    r["operations"] = st.operations;
    r["updates"] = st.updates;
    r["embeddings"] = st.embeddings;
    r["converged"] = res.stop == SnakeStop::Converged;
    r["stop"] = SnakeStopKey(res.stop); // why the run ended (snake/stop.h); a problem is also in warnings
    r["stop_message"] = res.stopMessage;
    r["seconds_snake"] = Since(t0);
    r["ms_per_operation"] = SnakeStats::Median(st.msOperation);
    r["ms_per_embedding"] = SnakeStats::Median(st.msEmbedding);
    r["ms_per_update"] = SnakeStats::Median(st.msUpdate);
    r["region_failures"] = st.regionFailures;
    r["curve_points"] = res.curve.size();
    r["length"] = res.length;
    r["warnings"] = warnings;
    Info(job, Fmt("Geometric snake (%s, %s): %d samples, %d operations, %s, curve of %d points and length %g, "
                  "%.1f ms.", snake.Closed() ? "closed" : "open", p.method == SnakeMethod::LocalEmbedding ? "local embedding"
                  : "3D update + projection", snake.SampleCount(), st.operations,
                  SnakeStopSummary(res.stop),
                  int(res.curve.size()), res.length,
                  Since(t0) * 1e3));
    for (const auto &w : warnings) Info(job, "warning: " + w.get<std::string>());
    if (!job.output.empty()) Info(job, "Wrote " + job.output + ".");
    if (!job.meshOut.empty()) Info(job, "Wrote " + job.meshOut + ".");
    return r;
}

/// OUT.ply -> OUT_inside.ply (the parts of `cut --split`).
std::string PartName(const std::string &out, const std::string &part)
{
    const size_t dot = out.find_last_of('.'), slash = out.find_last_of('/');
    const std::string stem = dot == std::string::npos || (slash != std::string::npos && dot < slash) ? out : out.substr(0, dot);
    return stem + "_" + part + ".ply";
}

json RunCut(Job &job, CMeshO &m, int mask, json r)
{
    const ParamValues &v = *job.values;
    const std::string curveFile = v.Text("CurveFile");
    if (curveFile.find_first_not_of(" \t") == std::string::npos)
        throw SnakeError("No curve given: give --curve CURVE.json (a snake file made on this mesh).");
    const int mode = v.Enum("Mode");
    const bool split = v.Bool("Split") || mode == int(CutMode::Split);
    const std::string in = PartName(job.output, "inside"), out = PartName(job.output, "outside");
    if (split) {
        CheckWritable(in, {"ply"}, "the inside part", Keep(job));
        CheckWritable(out, {"ply"}, "the outside part", Keep(job));
    }
    MeshValidation<CMeshO>::RequireSurface(m);
    MeshValidation<CMeshO>::RequireAdjacencySafe(m);
    m.face.EnableFFAdjacency();
    m.vert.EnableVFAdjacency();
    m.face.EnableVFAdjacency();
    UpdateTopology<CMeshO>::FaceFace(m);
    UpdateTopology<CMeshO>::VertexFace(m);
    const auto t0 = Clock::now();
    const CutCurve curve = CutCurveIO<CMeshO>::FromSnakeFile(m, curveFile, v.Int("SnakeIndex"));
    MeshCut<CMeshO>::Param p;
    p.side = CutSide(v.Enum("Side"));
    p.mode = split ? CutMode::Split : CutMode(mode);
    m.face.DisableFFAdjacency(); // the cut adds faces; adjacency is not written
    m.vert.DisableVFAdjacency();
    m.face.DisableVFAdjacency();
    namespace io = vcg::tri::io;
    const int keep = io::Mask::IOM_VERTCOLOR | io::Mask::IOM_FACECOLOR | io::Mask::IOM_VERTTEXCOORD |
                     io::Mask::IOM_WEDGTEXCOORD | io::Mask::IOM_VERTQUALITY | io::Mask::IOM_VERTNORMAL;
    MeshCut<CMeshO>::Result res;
    if (split) {
        CMeshO inside, outside;
        res = MeshCut<CMeshO>::Split(m, {curve}, p, inside, outside);
        SaveMeshPly(inside, in, mask & keep);
        SaveMeshPly(outside, out, mask & keep);
        r["inside"] = in;
        r["outside"] = out;
        r["inside_faces"] = inside.fn;
        r["outside_faces"] = outside.fn;
    } else {
        res = MeshCut<CMeshO>::Apply(m, {curve}, p);
        m.face.EnableQuality();
        for (size_t f = 0; f < m.face.size(); ++f) m.face[f].Q() = res.faceSide[f];
        // the side in the face quality and the selection in the flags (MeshLab shows it on load)
        SaveMeshPly(m, job.output, (mask & keep) | io::Mask::IOM_FACEQUALITY | io::Mask::IOM_FACEFLAGS |
                                       io::Mask::IOM_VERTFLAGS);
    }
    r["mode"] = v.Def("Mode").choices[size_t(split ? int(CutMode::Split) : mode)].key;
    r["side"] = v.Def("Side").choices[size_t(v.Enum("Side"))].key;
    r["curve_points"] = curve.points.size();
    r["closed"] = curve.closed;
    r["added_vertices"] = res.addedVertices;
    r["added_faces"] = res.addedFaces;
    r["curve_vertices"] = res.curveVertices;
    r["faces_inside"] = res.facesInside;
    r["area_inside"] = res.areaInside;
    r["area_outside"] = res.areaOutside;
    r["seconds_cut"] = Since(t0);
    Info(job, Fmt("Cut (%s) along a %s curve of %d points: %d vertices and %d faces added, %d curve vertices; "
                  "inside %d faces, area %g (outside %g). Wrote %s.",
                  MeshCut<CMeshO>::ModeName(p.mode).c_str(), curve.closed ? "closed" : "open", int(curve.points.size()),
                  res.addedVertices, res.addedFaces, res.curveVertices, res.facesInside, res.areaInside,
                  res.areaOutside, split ? (in + " and " + out).c_str() : job.output.c_str()));
    return r;
}

/// Runs a checked job; returns its statistics. Throws SnakeError.
json Run(Job &job)
{
    const auto t0 = Clock::now();
    json r = {{"command", job.cmd->name}, {"mesh", job.mesh}};
    if (!job.output.empty()) r["output"] = job.output;
    if (!job.meshOut.empty()) r["mesh_out"] = job.meshOut;
    json par = json::object(); // the values used, by option name: a batch's results say what they ran
    for (const ParamDef &d : *job.cmd->defs) {
        if (d.option.empty()) continue;
        const ParamValues &v = *job.values;
        switch (d.kind) {
        case ParamDef::Bool: par[d.option] = v.Bool(d.name); break;
        case ParamDef::Int: par[d.option] = v.Int(d.name); break;
        case ParamDef::Real: par[d.option] = v.Real(d.name); break;
        case ParamDef::Enum: par[d.option] = d.choices[size_t(v.Enum(d.name))].key; break;
        case ParamDef::Text: par[d.option] = v.Text(d.name); break;
        }
    }
    r["parameters"] = par;
    CMeshO m;
    int mask = 0;
    try {
        LoadMesh(job.mesh, m, mask);
    } catch (const std::bad_alloc &) {
        throw SnakeError("Out of memory while reading \"" + job.mesh + "\".");
    }
    r["vertices"] = m.vn;
    r["faces"] = m.fn;
    r["seconds_load"] = Since(t0);
    if (job.cmd->name == "energy") r = RunEnergy(job, m, mask, r);
    else if (job.cmd->name == "path") r = RunPath(job, m, mask, r);
    else if (job.cmd->name == "cut") r = RunCut(job, m, mask, r);
    else r = RunSnake(job, m, mask, r);
    r["seconds_total"] = Since(t0);
    return r;
}

/// Runs a job, turning every failure into a message: never an exception out of here.
bool RunCaught(Job &job, json &result, std::string &error)
{
    try {
        result = Run(job);
        return true;
    } catch (const SnakeError &e) {
        error = e.what();
    } catch (const std::bad_alloc &) {
        error = "Out of memory.";
    } catch (const std::exception &e) {
        error = std::string("Internal error: ") + e.what();
    } catch (...) {
        error = "Internal error (unknown exception).";
    }
    return false;
}

// ============================================================================ signals
// A run stopped by SIGINT, SIGTERM, SIGHUP or its --timeout (SIGALRM) removes its temporary
// files (TempFiles) and says why, on stderr and with --json-log on stdout; the messages are made
// before the run, so that the handler only calls write() and unlink(). SIGXFSZ (ulimit -f) is
// ignored: the write then fails with EFBIG ("File too large") and is reported as a write error.
namespace stop {
char errText[2][1024], jsonText[2][2048];
volatile sig_atomic_t silent = 0; // a batch case: its parent reports it

void Write(int fd, const char *s)
{
    for (size_t n = std::strlen(s); n > 0;) {
        const ssize_t w = ::write(fd, s, n);
        if (w <= 0) return;
        s += w;
        n -= size_t(w);
    }
}

void Handler(int sig)
{
    TempFiles::RemoveAll();
    const int k = sig == SIGALRM ? 0 : 1;
    if (!silent) {
        Write(STDERR_FILENO, errText[k]);
        Write(STDOUT_FILENO, jsonText[k]);
    }
    if (k == 1 || silent) { // as killed by the signal, for the caller (a batch's parent)
        ::signal(sig, SIG_DFL);
        sigset_t one;
        sigemptyset(&one);
        sigaddset(&one, sig);
        ::sigprocmask(SIG_UNBLOCK, &one, nullptr); // blocked while its handler runs
        ::raise(sig);
    }
    ::_exit(1);
}

/// Installs the handler; `command`, `mesh` and `timeout` go into the messages.
void Install(const std::string &command, const std::string &mesh, int timeout, bool jsonLog)
{
    const std::string why[2] = {"stopped after --timeout " + std::to_string(timeout) + " s",
                                "stopped by a signal (interrupt, terminate or hang-up)"};
    for (int k = 0; k < 2; ++k) {
        const std::string e = why[k] + "; its temporary files are removed and no output is partly written.";
        std::snprintf(errText[k], sizeof errText[k], "%s: error: %s\n", kProgram, e.c_str());
        std::snprintf(jsonText[k], sizeof jsonText[k], "%s",
                      jsonLog ? (json({{"command", command}, {"mesh", mesh}, {"ok", false}, {"error", e}}).dump() + "\n")
                                    .c_str()
                              : "");
    }
    struct sigaction sa;
    std::memset(&sa, 0, sizeof sa);
    sa.sa_handler = Handler;
    sigemptyset(&sa.sa_mask);
    for (int s : {SIGINT, SIGTERM, SIGHUP, SIGALRM}) sigaddset(&sa.sa_mask, s);
    for (int s : {SIGINT, SIGTERM, SIGHUP, SIGALRM}) ::sigaction(s, &sa, nullptr);
    ::signal(SIGXFSZ, SIG_IGN);
}
} // namespace stop

// ============================================================================ batch
std::string JsonToText(const json &v)
{
    if (v.is_string()) return v.get<std::string>();
    if (v.is_boolean()) return v.get<bool>() ? "on" : "off";
    if (v.is_number_integer()) return std::to_string(v.get<long long>());
    if (v.is_number()) {
        std::ostringstream o;
        o.precision(17);
        o << v.get<double>();
        return o.str();
    }
    if (v.is_array()) { // "seeds": [12, 40, 77]
        std::string s;
        for (const auto &x : v) s += (s.empty() ? "" : ", ") + JsonToText(x);
        return s;
    }
    throw UsageError("unsupported value " + v.dump());
}

std::string Resolve(const std::string &dir, const std::string &path)
{
    return path.empty() || path[0] == '/' || dir.empty() ? path : dir + "/" + path;
}

/// One case of a batch file into a job (UsageError/SnakeError on a bad case).
void CaseToJob(const std::string &line, const std::string &dir, Job &job)
{
    json c;
    try {
        c = json::parse(line);
    } catch (const json::exception &e) {
        throw UsageError(std::string("not a JSON object: ") + e.what());
    }
    if (!c.is_object()) throw UsageError("not a JSON object");
    if (!c.contains("command") || !c["command"].is_string())
        throw UsageError("no \"command\" (energy, snake or path)");
    job.cmd = FindCommand(c["command"].get<std::string>());
    if (!job.cmd) throw UsageError("unknown command \"" + c["command"].get<std::string>() + "\"");
    job.values.reset(new ParamValues(*job.cmd->defs));
    for (auto it = c.begin(); it != c.end(); ++it) {
        const std::string key = it.key();
        if (key == "command") continue;
        const std::string val = JsonToText(it.value());
        if (key == "mesh") job.mesh = Resolve(dir, val);
        else if (key == "output" || key == "o" || key == "mesh-out" || key == "pp")
            SetOption(job, key, Resolve(dir, val), true);
        else SetOption(job, key, val, true);
    }
    CheckJob(job);
}

int RunBatch(const std::string &file, int jobs, int timeout, bool jsonLog, bool quiet)
{
    InputFile::Require(file, "the batch file");
    std::ifstream in(file);
    if (!in) throw SnakeError("Cannot read the batch file \"" + file + "\".");
    const size_t slash = file.find_last_of('/');
    const std::string dir = slash == std::string::npos ? "" : file.substr(0, slash);
    struct Case
    {
        int line;
        std::string text;
    };
    std::vector<Case> cases;
    std::string line;
    for (int ln = 1; std::getline(in, line); ++ln) {
        const size_t b = line.find_first_not_of(" \t\r");
        if (b == std::string::npos || line[b] == '#') continue;
        cases.push_back({ln, line});
    }
    if (cases.empty()) throw SnakeError("The batch file \"" + file + "\" holds no cases.");
    if (jobs <= 0) jobs = std::max(1, int(std::thread::hardware_concurrency()));

    char tmpl[] = "/tmp/geometric-snake-batch-XXXXXX";
    if (!::mkdtemp(tmpl)) throw SnakeError("Cannot create a temporary folder for the batch.");
    const std::string work = tmpl;
    const auto t0 = Clock::now();
    int ok = 0, failed = 0, done = 0;
    std::map<pid_t, size_t> running;
    size_t next = 0;
    std::fflush(stdout);
    std::fflush(stderr);
    auto report = [&](size_t i, json r) {
        json out = {{"case", i + 1}, {"line", cases[i].line}};
        for (auto it = r.begin(); it != r.end(); ++it) out[it.key()] = it.value();
        const bool good = out.value("ok", false);
        (good ? ok : failed) += 1;
        ++done;
        std::printf("%s\n", out.dump().c_str());
        std::fflush(stdout);
        if (!quiet) {
            if (good) std::fprintf(stderr, "[%d/%zu] case %zu (line %d): ok\n", done, cases.size(), i + 1, cases[i].line);
            else
                std::fprintf(stderr, "[%d/%zu] case %zu (line %d): error: %s\n", done, cases.size(), i + 1,
                             cases[i].line, out.value("error", std::string("?")).c_str());
        }
    };
    while (next < cases.size() || !running.empty()) {
        while (next < cases.size() && int(running.size()) < jobs) {
            const size_t i = next++;
            const pid_t pid = ::fork();
            if (pid < 0) {
                report(i, {{"ok", false}, {"error", "cannot start a process for this case"}});
                continue;
            }
            if (pid == 0) { // the case, isolated in its own process
                stop::silent = 1; // a stopped case: its temporary files go, the parent reports it
                if (timeout > 0) ::alarm(unsigned(timeout)); // SIGALRM ends a case that hangs
                json r;
                std::string err;
                Job job;
                job.quiet = true;
                try {
                    CaseToJob(cases[i].text, dir, job);
                    if (RunCaught(job, r, err)) r["ok"] = true;
                } catch (const std::exception &e) {
                    err = e.what();
                }
                if (!err.empty()) r = {{"ok", false}, {"error", err}};
                std::ofstream(work + "/" + std::to_string(i) + ".json") << r.dump() << "\n";
                std::fflush(nullptr);
                ::_exit(0);
            }
            running[pid] = i;
        }
        int status = 0;
        const pid_t pid = ::waitpid(-1, &status, 0);
        if (pid < 0) break;
        auto it = running.find(pid);
        if (it == running.end()) continue;
        const size_t i = it->second;
        running.erase(it);
        const std::string rf = work + "/" + std::to_string(i) + ".json";
        json r;
        std::ifstream rin(rf);
        try {
            rin >> r;
        } catch (const std::exception &) {
            r = json();
        }
        std::remove(rf.c_str());
        if (!r.is_object()) {
            Job killed; // its outputs, to remove the temporary files it was writing
            try {
                CaseToJob(cases[i].text, dir, killed);
                for (const auto &o : {killed.output, killed.meshOut})
                    if (!o.empty()) SafeFileWrite::RemoveLeftovers(o);
            } catch (const std::exception &) {
            }
            std::string why = "the case stopped without a result";
            if (WIFSIGNALED(status) && WTERMSIG(status) == SIGALRM)
                why = "the case ran longer than --timeout " + std::to_string(timeout) + " s and was stopped";
            else if (WIFSIGNALED(status))
                why = "the case crashed (signal " + std::to_string(WTERMSIG(status)) + ")";
            r = {{"ok", false}, {"error", why}};
        }
        report(i, r);
    }
    ::rmdir(work.c_str());
    const double secs = Since(t0);
    if (!quiet)
        std::fprintf(stderr, "batch: %zu cases, %d ok, %d errors, %.2f s with %d jobs\n", cases.size(), ok, failed,
                     secs, jobs);
    if (jsonLog)
        std::printf("%s\n", json({{"batch", file}, {"cases", cases.size()}, {"ok", ok}, {"errors", failed},
                                  {"jobs", jobs}, {"seconds_total", secs}}).dump().c_str());
    return failed == 0 ? 0 : 1;
}

// ============================================================================ main
int Main(int argc, char **argv)
{
    std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty()) {
        std::fprintf(stderr, "%s", MainHelp().c_str());
        return 2;
    }
    Job job;
    std::string batch;
    int jobs = 0, timeout = 0;
    bool help = false;
    std::vector<std::pair<std::string, std::pair<std::string, bool>>> opts;
    std::vector<std::string> positional;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string &a = args[i];
        if (a == "-h" || a == "--help") { help = true; continue; }
        if (a == "--version") {
            std::printf("%s (Geometric Snakes for MeshLab)\n", kProgram);
            return 0;
        }
        if (a == "--json-log") { job.jsonLog = true; continue; }
        if (a == "-q" || a == "--quiet") { job.quiet = true; continue; }
        std::string key, value;
        bool hasValue = false;
        if (a.size() > 2 && a.compare(0, 2, "--") == 0) {
            key = a.substr(2);
            const size_t eq = key.find('=');
            if (eq != std::string::npos) {
                value = key.substr(eq + 1);
                key = key.substr(0, eq);
                hasValue = true;
            }
        } else if (a == "-o" || a == "-j") {
            key = a == "-o" ? "output" : "jobs";
        } else if (a.size() > 1 && a[0] == '-' && !std::isdigit(static_cast<unsigned char>(a[1]))) {
            throw UsageError("unknown option " + a + " (see " + kProgram + " --help).");
        } else {
            positional.push_back(a);
            continue;
        }
        // Options that take a value take the next argument, unless they are on/off switches.
        const Command *c = positional.empty() ? nullptr : FindCommand(positional[0]);
        bool isSwitch = false;
        if (c) {
            ParamValues probe(*c->defs);
            const ParamDef *d = probe.FindOption(key);
            isSwitch = (d && d->kind == ParamDef::Bool) ||
                       (key.compare(0, 3, "no-") == 0 && probe.FindOption(key.substr(3)));
        }
        if (!hasValue && !isSwitch) {
            if (i + 1 >= args.size()) throw UsageError(a + " needs a value.");
            value = args[++i];
            hasValue = true;
        }
        if (key == "batch") batch = value;
        else if (key == "jobs") {
            char *e = nullptr;
            jobs = int(std::strtol(value.c_str(), &e, 10));
            if (value.empty() || *e || jobs < 1 || jobs > 1024) throw UsageError("--jobs expects a number in [1, 1024].");
        } else if (key == "timeout") {
            char *e = nullptr;
            timeout = int(std::strtol(value.c_str(), &e, 10));
            if (value.empty() || *e || timeout < 1 || timeout > 1000000)
                throw UsageError("--timeout expects seconds in [1, 1000000].");
        } else opts.push_back({key, {value, hasValue}});
    }

    if (!batch.empty()) {
        if (!positional.empty() || !opts.empty())
            throw UsageError("--batch takes the cases from its file: no command, mesh or other options beside it "
                             "(only --jobs, --timeout, --json-log, --quiet).");
        stop::Install("batch", batch, timeout, job.jsonLog);
        return RunBatch(batch, jobs, timeout, job.jsonLog, job.quiet);
    }
    if (positional.empty() || positional[0] == "help") {
        const Command *c = positional.size() > 1 ? FindCommand(positional[1]) : nullptr;
        std::printf("%s", c ? CommandHelp(*c).c_str() : MainHelp().c_str());
        if (help || !positional.empty()) return 0;
        throw UsageError("no command given");
    }
    job.cmd = FindCommand(positional[0]);
    if (!job.cmd) throw UsageError("unknown command \"" + positional[0] + "\" (energy, snake, path or cut).");
    if (help) {
        std::printf("%s", CommandHelp(*job.cmd).c_str());
        return 0;
    }
    if (positional.size() > 2) throw UsageError("unexpected argument \"" + positional[2] + "\".");
    if (positional.size() == 2) job.mesh = positional[1];
    if (jobs) throw UsageError("--jobs only applies to --batch.");
    job.values.reset(new ParamValues(*job.cmd->defs));
    for (const auto &o : opts) SetOption(job, o.first, o.second.first, o.second.second);
    CheckJob(job);
    job.progress = !job.quiet && ::isatty(STDERR_FILENO);
    stop::Install(job.cmd->name, job.mesh, timeout, job.jsonLog);
    if (timeout > 0) ::alarm(unsigned(timeout));

    json r;
    std::string err;
    if (!RunCaught(job, r, err)) {
        if (job.jsonLog) std::printf("%s\n", json({{"command", job.cmd->name}, {"mesh", job.mesh}, {"ok", false},
                                                   {"error", err}}).dump().c_str());
        std::fprintf(stderr, "%s: error: %s\n", kProgram, err.c_str());
        return 1;
    }
    if (job.jsonLog) {
        r["ok"] = true;
        std::printf("%s\n", r.dump().c_str());
    }
    return 0;
}

} // namespace gs_cli

int main(int argc, char **argv)
{
    try {
        return gs_cli::Main(argc, argv);
    } catch (const gs_cli::UsageError &e) {
        std::fprintf(stderr, "%s: %s\nTry '%s --help'.\n", gs_cli::kProgram, e.what(), gs_cli::kProgram);
        return 2;
    } catch (const vcg::tri::SnakeError &e) {
        std::fprintf(stderr, "%s: error: %s\n", gs_cli::kProgram, e.what());
        return 1;
    } catch (const std::exception &e) {
        std::fprintf(stderr, "%s: internal error: %s\n", gs_cli::kProgram, e.what());
        return 1;
    }
}
