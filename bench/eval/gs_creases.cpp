// Creases on CAD meshes (issue 38): open and closed snakes seeded a few local edge lengths to
// one side of a sharp-edge chain, nearer it than any other sharp edge (tests/crease_cases.h),
// with normal variation and the crease energy, on three sets:
//   dense   stepped shafts whose shoulder is 2, 3, 4 h wide and blocks whose bore comes 2, 3, 4 h
//           from the top edge, remeshed isotropically to h; seeds 2-4 h off
//   tess    the stepped shaft as a tessellator exports it (50:1 side slivers, shoulder 3 chain
//           edges wide), caps as fans, ear clipping, strips; seeds 2-4 chain-edge lengths off
//   shared  ../shared/data: mechanical parts 327, 333, bearings 341, 342 (seeds 2-4 h off) and
//           fandisk (5-7 h off); ground truth: edges above 30 degrees
// One CSV row per run; a summary per set and energy on stderr.
//
//   gs_creases [--sets dense,tess,shared] [--meshes NAME,...] [--energy normal,crease] [--chains N]
//              [--max-ops N] [--out FILE.csv]
// (--meshes: only the meshes of those names, e.g. shaft-strip,fandisk). The log and the CSV give the
// embeddings each run built and the kept ones it reused (Sec. 4.2).

#include <chrono>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include <crease_cases.h>

using namespace vcg::tri;

namespace {

std::vector<std::string> List(const std::string &s)
{
    std::vector<std::string> out;
    std::stringstream ss(s);
    std::string t;
    while (std::getline(ss, t, ',')) out.push_back(t);
    return out;
}

struct Mesh
{
    std::string set, name;
    std::vector<double> offsets;
    std::function<bool(CMeshO &)> make;
};

} // namespace

int main(int argc, char **argv)
{
    std::vector<std::string> sets = {"dense", "tess", "shared"}, energies = {"normal", "crease"}, only;
    std::string out = "creases.csv";
    int chains = 6, maxOps = 400;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&]() -> std::string { return i + 1 < argc ? argv[++i] : ""; };
        if (a == "--sets") sets = List(next());
        else if (a == "--meshes") only = List(next());
        else if (a == "--energy") energies = List(next());
        else if (a == "--chains") chains = std::stoi(next());
        else if (a == "--max-ops") maxOps = std::stoi(next());
        else if (a == "--out") out = next();
        else {
            std::fprintf(stderr, "usage: gs_creases [--sets dense,tess,shared] [--meshes NAME,...] [--energy normal,crease] "
                                 "[--chains N] [--max-ops N] [--out FILE.csv]\n");
            return 2;
        }
    }
    std::vector<Mesh> meshes;
    auto want = [&](const std::string &s) { return std::find(sets.begin(), sets.end(), s) != sets.end(); };
    if (want("dense"))
        for (int k : {2, 3, 4}) {
            meshes.push_back({"dense", "shaft-shoulder" + std::to_string(k) + "h", {2, 3, 4}, [k](CMeshO &m) {
                                  gs_crease::MakeSteppedShaft(m, 64, 10, 10, 10 - k, 8, gs_crease::CapStyle::Fan);
                                  gs_crease::Remesh(m, 1.0);
                                  return true;
                              }});
            meshes.push_back({"dense", "block-bore" + std::to_string(k) + "h", {2, 3, 4}, [k](CMeshO &m) {
                                  gs_crease::MakeBoredBlock(m, 40, 24, 8, 20, 5 + k, 5, 64);
                                  gs_crease::Remesh(m, 1.0);
                                  return true;
                              }});
        }
    if (want("tess"))
        for (auto st : {gs_crease::CapStyle::Fan, gs_crease::CapStyle::EarClip, gs_crease::CapStyle::Strip})
            meshes.push_back({"tess", std::string("shaft-") + gs_crease::StyleName(st), {2, 3, 4}, [st](CMeshO &m) {
                                  const int n = 64;
                                  const double e = 2 * M_PI * 10 / n; // the outer rim's chain edge
                                  gs_crease::MakeSteppedShaft(m, n, 10, 50 * e, 10 - 3 * e, 50 * e * 0.7, st);
                                  return true;
                              }});
    if (want("shared")) {
        for (int id : {327, 333, 341, 342})
            meshes.push_back({"shared", std::to_string(id), {2, 3, 4}, [id](CMeshO &m) {
                                  return gs_test::LoadMesh(m, std::string(GS_SEGMENTATION_DIR) + "/off/" + std::to_string(id) + ".off");
                              }});
        meshes.push_back({"shared", "fandisk", {5, 6, 7}, [](CMeshO &m) {
                              return gs_test::LoadMesh(m, std::string(GS_SHARED_MESH_DIR) + "/fandisk.off");
                          }});
    }

    if (!only.empty())
        meshes.erase(std::remove_if(meshes.begin(), meshes.end(),
                                    [&](const Mesh &mm) { return std::find(only.begin(), only.end(), mm.name) == only.end(); }),
                     meshes.end());
    std::ofstream csv(out);
    csv << "set,mesh,chain,closed,offset,h,energy,capture,coverage,mean_dist_h,operations,embeddings,reuses,converged,captured,ms\n";
    struct Tally { int n = 0, ok = 0; };
    std::map<std::pair<std::string, std::string>, Tally> tally;
    const auto t0 = std::chrono::steady_clock::now();
    for (Mesh &mm : meshes) {
        CMeshO m;
        bool made = false;
        try {
            made = mm.make(m);
        } catch (const std::exception &x) {
            std::fprintf(stderr, "%s: %s\n", mm.name.c_str(), x.what());
        }
        if (!made) {
            std::fprintf(stderr, "%s: not made, skipped\n", mm.name.c_str());
            continue;
        }
        gs_test::EnableSnakeAdjacency(m);
        const std::vector<gs_crease::Chain> ch = gs_crease::SharpChains(m);
        std::fprintf(stderr, "%s %s: %d faces, %zu sharp chains\n", mm.set.c_str(), mm.name.c_str(), m.fn, ch.size());
        int used = 0;
        for (int ci = 0; ci < int(ch.size()) && used < chains; ++ci) {
            bool any = false;
            for (bool closed : {false, true})
                for (double off : mm.offsets) {
                    gs_crease::Case k;
                    if (!gs_crease::MakeCase(m, ch, ci, off, closed, k)) continue;
                    any = true;
                    for (const std::string &e : energies) {
                        const FeatureEnergyType type = e == "crease" ? FeatureEnergyType::Crease : FeatureEnergyType::NormalVariation;
                        const auto a = std::chrono::steady_clock::now();
                        gs_capture::Result r;
                        try {
                            r = gs_crease::Run(m, k, type, maxOps);
                        } catch (const std::exception &x) {
                            std::fprintf(stderr, "  %s chain %d: %s\n", e.c_str(), ci, x.what());
                        }
                        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - a).count();
                        csv << mm.set << ',' << mm.name << ',' << ci << ',' << closed << ',' << off << ',' << k.c.h << ',' << e << ','
                            << r.capture << ',' << r.coverage << ',' << r.meanDist << ',' << r.operations << ',' << r.embeddings << ',' << r.reuses << ',' << r.converged
                            << ',' << r.Captured() << ',' << ms << '\n';
                        Tally &t = tally[{mm.set, e}];
                        ++t.n, t.ok += r.Captured();
                        std::fprintf(stderr,
                                     "  %-7s chain %2d %s off %.0f: capture %5.1f%% coverage %5.1f%% mean %.2f h"
                                     " (%d ops, %d embeddings, %d reuses)%s\n",
                                     e.c_str(), ci, closed ? "closed" : "open  ", off, 100 * r.capture, 100 * r.coverage,
                                     r.meanDist, r.operations, r.embeddings, r.reuses, r.Captured() ? "" : "  MISSED");
                    }
                }
            used += any;
        }
    }
    for (auto &kv : tally)
        std::fprintf(stderr, "%-7s %-7s captured %d of %d (%.0f %%)\n", kv.first.first.c_str(), kv.first.second.c_str(),
                     kv.second.ok, kv.second.n, 100.0 * kv.second.ok / std::max(1, kv.second.n));
    std::fprintf(stderr, "done in %.0f s\n", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    return 0;
}
