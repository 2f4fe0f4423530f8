// Replays the committed fuzz corpus (fuzz/corpus/<target>/) through the fuzz harnesses
// (fuzz/gs_fuzz.h): the seeds, and every input a fuzzer once found crashing (saved there as
// a regression test). A harness aborts on a bug, which fails this test with the file named
// on stderr.
#include <gtest/gtest.h>

#include <algorithm>
#include <dirent.h>
#include <fstream>
#include <iterator>

#include <gs_fuzz.h>
#include <gs_fuzz_mesh.h>

namespace {

std::vector<std::string> CorpusFiles(const std::string &target)
{
    std::vector<std::string> out;
    const std::string dir = std::string(GS_FUZZ_CORPUS_DIR) + "/" + target;
    if (DIR *d = opendir(dir.c_str())) {
        while (dirent *e = readdir(d))
            if (e->d_name[0] != '.') out.push_back(dir + "/" + e->d_name);
        closedir(d);
    }
    std::sort(out.begin(), out.end());
    return out;
}

std::string Read(const std::string &path)
{
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

template <class Harness>
void Replay(const std::string &target, Harness h, size_t minFiles)
{
    const auto files = CorpusFiles(target);
    ASSERT_GE(files.size(), minFiles) << "fuzz/corpus/" << target << " lost its seeds";
    for (const auto &f : files) {
        std::fprintf(stderr, "replaying %s\n", f.c_str());
        const std::string d = Read(f);
        EXPECT_EQ(h(reinterpret_cast<const uint8_t *>(d.data()), d.size()), 0) << f;
    }
}

} // namespace

TEST(FuzzCorpus, SnakeJson) { Replay("snake_json", gs_fuzz::SnakeJson, 4); }

// The fuzzer starts deep only if its seed session still loads: keep session.json current
// with the session format (regenerate it if the format changes).
TEST(FuzzCorpus, SeedSessionLoads)
{
    CMeshO m;
    gs_fuzz::MakeMesh(m);
    vcg::tri::SnakeController<CMeshO> c(m);
    c.FromJson(nlohmann::json::parse(Read(std::string(GS_FUZZ_CORPUS_DIR) + "/snake_json/session.json")));
    EXPECT_EQ(c.SnakeCount(), 2);
}

TEST(FuzzCorpus, SeedString) { Replay("seed_string", gs_fuzz::SeedString, 4); }

TEST(FuzzCorpus, SeedPoints) { Replay("seed_points", gs_fuzz::SeedPoints, 4); }

TEST(FuzzCorpus, PickPoints) { Replay("pick_points", gs_fuzz::PickPoints, 3); }

// The program's mesh loading (issue 36: vcglib's OBJ importer crashed on a far index and dropped
// the faces at vertex 1; negative PLY/OFF counts reached std::vector).
TEST(FuzzCorpus, MeshObj)
{
#ifndef NDEBUG
    // Builds with asserts (the sanitizer builds): vcglib's OBJ importer asserts on its own face
    // count for every file whose faces use vertex 1 (import_obj.h), files the program, built
    // without asserts, reads whole; and its per-face attribute leaks. Replayed in Release.
    GTEST_SKIP() << "vcglib's OBJ importer asserts on valid files in builds with asserts";
#endif
    Replay("mesh_obj", gs_fuzz::MeshObj, 3);
}
TEST(FuzzCorpus, MeshPly) { Replay("mesh_ply", gs_fuzz::MeshPly, 3); }
TEST(FuzzCorpus, MeshOff) { Replay("mesh_off", gs_fuzz::MeshOff, 3); }
TEST(FuzzCorpus, MeshStl) { Replay("mesh_stl", gs_fuzz::MeshStl, 2); }

// Found by fuzz_seed_points: a seed point 8.9e12 away went into vcglib's grid, whose
// float-to-int cell index is undefined there (UBSan: grid_util.h PToIP). It must be refused
// with the distance message before the grid sees it.
TEST(FuzzRegressions, FarSeedPointIsRefusedBeforeTheGrid)
{
    CMeshO m;
    gs_fuzz::MakeMesh(m);
    try {
        vcg::tri::SeedPointSnap<CMeshO>::Snap(m, {vcg::Point3d(1, 8888888888880.9, -0.6), vcg::Point3d(1, 0.9, 0)}, 2);
        FAIL() << "a point 8.9e12 away was snapped";
    } catch (const vcg::tri::SnakeError &e) {
        EXPECT_NE(std::string(e.what()).find("Seed point 1"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("away from the surface"), std::string::npos) << e.what();
    }
}
