// Never lose the user's data (issue 8): safe writes (SafeFileWrite, SnakeIO::WriteCurves),
// sidecars that survive (SnakeController::OpenSidecar, SnakeSidecar), lean loading of large sidecars, and
// readable messages for broken snake files.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <snake_test_util.h>
#include <vcg_ext/io/safe_file_write.h>
#include <vcg_ext/io/snake_io.h>
#include <vcg_ext/paths/seed_points.h>
#include <vcg_ext/session/controller.h>

using namespace vcg::tri;
namespace fs = std::filesystem;
using Snake = GeometricSnake<CMeshO>;
using IO = SnakeIO<CMeshO>;
using Controller = SnakeController<CMeshO>;

namespace {

std::string ReadAll(const std::string &p)
{
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}
void WriteAll(const std::string &p, const std::string &s) { std::ofstream(p, std::ios::binary) << s; }

/// A fresh folder per test.
struct TempDir
{
    fs::path dir;
    TempDir()
    {
        const auto *info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir = fs::temp_directory_path() / ("gs_safety_" + std::to_string(::getpid()) + "_" + info->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    ~TempDir() { fs::remove_all(dir); }
    std::string operator/(const std::string &name) const { return (dir / name).string(); }
    int Files() const { return int(std::distance(fs::directory_iterator(dir), fs::directory_iterator())); }
};

void PrepareGrid(CMeshO &m, int n)
{
    gs_test::MakeFlatGrid(m, n);
    gs_test::EnableSnakeAdjacency(m);
    FeatureEnergy<CMeshO>::Compute(m, FeatureEnergyType::NormalVariation, 2);
}

std::string ErrorOf(const std::function<void()> &f)
{
    try {
        f();
    } catch (const SnakeError &e) {
        return e.what();
    }
    return "";
}

} // namespace

// ------------------------------------------------------------------ safe writes
TEST(SafeFileWrite, ReplacesOnlyWithTheCompleteNewFileAndKeepsPermissions)
{
    TempDir t;
    const std::string p = t / "out.json";
    SafeFileWrite::Write(p, "first\n");
    EXPECT_EQ(ReadAll(p), "first\n");
    ::chmod(p.c_str(), 0640);
    SafeFileWrite::Write(p, "second\n");
    EXPECT_EQ(ReadAll(p), "second\n");
    struct stat st;
    ASSERT_EQ(::stat(p.c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 0777, 0640u);
    EXPECT_EQ(t.Files(), 1) << "a temporary file was left behind";
    // through a symbolic link: the link stays, its target gets the content
    const std::string link = t / "link.json";
    fs::create_symlink(p, link);
    SafeFileWrite::Write(link, "third\n");
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_EQ(ReadAll(p), "third\n");
}

TEST(SafeFileWrite, RefusesProtectedFilesFoldersAndMissingFolders)
{
    TempDir t;
    const std::string mesh = t / "part.ply";
    WriteAll(mesh, "ply mesh bytes");
    const std::vector<ProtectedFile> keep{{mesh, "the mesh being worked on"}};
    const std::string spelled = (t.dir / "." / "part.ply").string(); // same file, other spelling
    const std::string hard = t / "hardlink.ply";
    fs::create_hard_link(mesh, hard);
    for (const std::string &target : {mesh, spelled, hard}) {
        const std::string e = ErrorOf([&] { SafeFileWrite::Write(target, "curve", keep); });
        EXPECT_NE(e.find("the mesh being worked on"), std::string::npos) << target << ": " << e;
        EXPECT_EQ(ReadAll(mesh), "ply mesh bytes");
    }
    EXPECT_NE(ErrorOf([&] { SafeFileWrite::Write(t.dir.string(), "x"); }).find("folder"), std::string::npos);
    EXPECT_NE(ErrorOf([&] { SafeFileWrite::Write(t / "no/such/dir/x.json", "x"); }).find("does not exist"),
              std::string::npos);
    EXPECT_EQ(t.Files(), 2);
}

TEST(SnakeIO, WriteCurvesChecksFormatAndTargetBeforeTouchingAnything)
{
    TempDir t;
    CMeshO m;
    PrepareGrid(m, 20);
    auto surf = std::make_shared<SnakeSurface<CMeshO>>(m);
    Snake s(surf);
    s.InitFromSeeds({5 * 21 + 3, 5 * 21 + 15}, false);
    std::vector<Snake *> list{&s};
    // issue 8: an existing file with an unknown or missing extension was left at 0 bytes
    for (const std::string name : {"notes.txt", "README", "curve.JSONX"}) {
        const std::string p = t / name;
        WriteAll(p, "precious " + name);
        const std::string e = ErrorOf([&] { IO::WriteCurves(p, list); });
        EXPECT_FALSE(e.empty());
        EXPECT_EQ(ReadAll(p), "precious " + name) << e;
    }
    // the missing extension is reported as such, not with the whole lower-cased path as the "format"
    const std::string noext = t / "Dir.With.Dots" + "/Curve";
    fs::create_directories(t / "Dir.With.Dots");
    const std::string e = ErrorOf([&] { IO::WriteCurves(noext, list); });
    EXPECT_NE(e.find("has no extension"), std::string::npos) << e;
    EXPECT_EQ(e.find("dir.with.dots"), std::string::npos) << e;
    // the input mesh, even as .ply (it was silently replaced by the curve)
    for (const std::string name : {"mesh.ply", "mesh.obj", "mesh.json"}) {
        const std::string p = t / name;
        WriteAll(p, "the user's mesh");
        EXPECT_FALSE(ErrorOf([&] { IO::WriteCurves(p, list, SnakeSidecar::ProtectedFiles(p)); }).empty());
        EXPECT_EQ(ReadAll(p), "the user's mesh");
        // and its sidecar
        const std::string side = SnakeSidecar::Path(p);
        WriteAll(side, "{}");
        EXPECT_NE(ErrorOf([&] { IO::WriteCurves(side, list, SnakeSidecar::ProtectedFiles(p)); }).find("sidecar"),
                  std::string::npos);
        EXPECT_EQ(ReadAll(side), "{}");
    }
    // a good target is written, by extension
    for (const std::string name : {"c.json", "c.OBJ", "c.ply"}) {
        IO::WriteCurves(t / name, list);
        EXPECT_GT(fs::file_size(t / name), 50u) << name;
    }
    EXPECT_EQ(ReadAll(t / "c.ply").rfind("ply\n", 0), 0u);
    EXPECT_TRUE(nlohmann::json::accept(ReadAll(t / "c.json")));
}

// ------------------------------------------------------------------ readable JSON errors
TEST(SnakeIO, BrokenSnakeFilesGiveReadableMessages)
{
    CMeshO m;
    PrepareGrid(m, 10);
    auto surf = std::make_shared<SnakeSurface<CMeshO>>(m);
    auto load = [&](const std::string &text) {
        Snake s(surf);
        return ErrorOf([&] { IO::FromJson(s, nlohmann::json::parse(text)); });
    };
    const std::string bary = "\"bary\":[0.2,0.3,0.5]";
    // face 1e20 went through an undefined float-to-int conversion
    std::string e = load("{\"samples\":[{\"face\":1e20," + bary + "},{\"face\":2," + bary + "}]}");
    EXPECT_NE(e.find("\"face\""), std::string::npos) << e;
    for (const std::string bad : std::vector<std::string>{"{\"samples\":[{\"face\":\"x\"," + bary + "},{\"face\":2," + bary + "}]}",
                                  "{\"samples\":[{\"face\":-1," + bary + "},{\"face\":2," + bary + "}]}",
                                  "{\"samples\":[{\"face\":1.5," + bary + "},{\"face\":2," + bary + "}]}",
                                  "{\"samples\":[{\"face\":1},{\"face\":2," + bary + "}]}",
                                  "{\"samples\":5}", "[1,2]", "{\"closed\":3,\"samples\":[]}",
                                  "{\"params\":{\"segment_samples\":1e20},\"samples\":[]}",
                                  "{\"params\":{\"alpha\":\"high\"},\"samples\":[]}"}) {
        e = load(bad);
        EXPECT_FALSE(e.empty()) << bad;
        EXPECT_EQ(e.find("json.exception"), std::string::npos) << e;
    }
    // a session file: the same
    Controller c(m);
    const std::string fmt = std::string("{\"format\":\"") + Controller::SessionFile::FormatName();
    for (const std::string bad : std::vector<std::string>{fmt + "\",\"mesh\":{\"vertices\":1e20}}",
                                  fmt + "\",\"mesh\":5}", fmt + "\",\"version\":\"new\"}"}) {
        e = ErrorOf([&] { c.FromJson(nlohmann::json::parse(bad)); });
        EXPECT_FALSE(e.empty()) << bad;
        EXPECT_EQ(e.find("json.exception"), std::string::npos) << e;
    }
    TempDir t;
    WriteAll(t / "cut.json", "{\"format\":\"geometric");
    e = ErrorOf([&] { IO::ParseFileLean(t / "cut.json"); });
    EXPECT_NE(e.find("not valid JSON"), std::string::npos) << e;
    EXPECT_EQ(e.find("json.exception"), std::string::npos) << e;
}

// ------------------------------------------------------------------ sidecars that survive
namespace {

/// The session file of the edit tool with one open snake of `samples` samples, made by the
/// engine along a path that sweeps the grid (n x n quads) row by row.
std::string SessionText(CMeshO &m, int samples)
{
    const int n = int(std::lround(std::sqrt(m.vert.size()))) - 1;
    std::vector<int> seeds;
    for (int r = 1; r + 1 < n; r += 4) {
        const bool right = (r / 4) % 2 == 0;
        seeds.push_back(r * (n + 1) + (right ? 1 : n - 1));
        seeds.push_back(r * (n + 1) + (right ? n - 1 : 1));
    }
    Controller c(m);
    const auto path = SeedPath<CMeshO>::Compute(m, seeds, false);
    // spacing is in the snake's length unit: the median edge of its seed path (all grid edges)
    const double unit = vcg::Distance(m.vert[path.vertices[0]].cP(), m.vert[path.vertices[1]].cP());
    SnakeParams p;
    p.spacing = path.length / (samples - 1) / unit;
    c.SetParams(p);
    c.SetSeeds(seeds);
    c.CloseSeeds(false);
    EXPECT_NEAR(c.Get(0).SampleCount(), samples, samples / 100 + 1);
    return c.ToJson().dump(1) + "\n";
}

} // namespace

TEST(Sidecar, UnreadableSidecarIsKeptAndTheSessionGoesToARecoveryFile)
{
    TempDir t;
    CMeshO m;
    PrepareGrid(m, 20);
    const std::string mesh = t / "part.ply";
    WriteAll(mesh, "mesh");
    const std::string side = SnakeSidecar::Path(mesh);
    const std::string good = SessionText(m, 40);
    const std::string cut = good.substr(0, good.size() / 2); // a truncated sidecar
    WriteAll(side, cut);
    WriteAll(side + ".bak", "an old backup");
    Controller c(m);
    const std::time_t when = 1764000000;
    Controller::SidecarStatus st = c.OpenSidecar(mesh, true, when);
    EXPECT_TRUE(st.unreadable);
    EXPECT_FALSE(st.restored);
    const std::string rec = SnakeSidecar::RecoveryPath(mesh, when);
    EXPECT_NE(rec.find("part.ply.snakes.recovered-"), std::string::npos);
    EXPECT_NE(st.message.find(rec), std::string::npos) << st.message;
    EXPECT_NE(st.message.find("kept unchanged"), std::string::npos) << st.message;
    EXPECT_EQ(c.AutosavePath(), rec);
    // the user works, the tool autosaves and ends
    c.SetSeeds({5 * 21 + 3, 5 * 21 + 15});
    c.CloseSeeds(false);
    EXPECT_TRUE(c.Autosave(true));
    EXPECT_EQ(ReadAll(side), cut) << "the unreadable sidecar was changed";
    EXPECT_EQ(ReadAll(side + ".bak"), "an old backup");
    ASSERT_TRUE(fs::exists(rec));
    Controller back(m);
    EXPECT_TRUE(back.Load(rec));
    EXPECT_EQ(back.SnakeCount(), 1);
    // a second failure in the same second gets its own recovery file
    WriteAll(rec + ".keep", "");
    Controller again(m);
    EXPECT_NE(again.OpenSidecar(mesh, true, when).message.find("recovered-"), std::string::npos);
    EXPECT_NE(again.AutosavePath(), rec);
    // a sidecar of another mesh is just as unusable, and just as safe
    CMeshO other;
    PrepareGrid(other, 7);
    Controller o(other);
    WriteAll(side, good);
    EXPECT_TRUE(o.OpenSidecar(mesh, true, when + 5).unreadable);
    EXPECT_EQ(ReadAll(side), good);
    // a readable sidecar is restored and stays the autosave target
    Controller r(m);
    st = r.OpenSidecar(mesh, true, when);
    EXPECT_TRUE(st.restored) << st.message;
    EXPECT_EQ(r.SnakeCount(), 1);
    EXPECT_EQ(r.AutosavePath(), side);
}

namespace {

/// Peak memory (kB) of running f in a child process, above that of a child doing nothing, and
/// the child's CPU time in seconds (`cpu`; the machine is shared, so not wall time).
long ChildPeakKb(const std::function<void()> &f, bool &ok, double &cpu)
{
    auto run = [&](bool work) -> long {
        pid_t pid = ::fork();
        if (pid == 0) {
            int code = 0;
            try {
                if (work) f();
            } catch (...) {
                code = 3;
            }
            ::_exit(code);
        }
        int status = 0;
        struct rusage ru;
        ::wait4(pid, &status, 0, &ru);
        if (work) {
            ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
            cpu = ru.ru_utime.tv_sec + ru.ru_stime.tv_sec + 1e-6 * (ru.ru_utime.tv_usec + ru.ru_stime.tv_usec);
        }
        return ru.ru_maxrss;
    };
    const long base = run(false);
    return run(true) - base;
}

// AddressSanitizer's shadow memory and quarantine inflate the peak several times: the memory
// bounds hold for the real (uninstrumented) build only.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kMemoryMeasured = false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kMemoryMeasured = false;
#else
constexpr bool kMemoryMeasured = true;
#endif
#else
constexpr bool kMemoryMeasured = true;
#endif

} // namespace

TEST(Sidecar, LargeSidecarsLoadInBoundedTimeAndMemoryOrAreRefused)
{
    TempDir t;
    CMeshO m;
    PrepareGrid(m, 100);
    // 10,000 samples: loaded (and traced) well within 2 s and 10x the file size
    const std::string p10k = t / "m10k.ply.snakes.json";
    WriteAll(p10k, SessionText(m, 10000));
    const double mb10k = fs::file_size(p10k) / 1048576.0;
    bool ok = false;
    double cpu = 0;
    auto t0 = std::chrono::steady_clock::now();
    const long kb = ChildPeakKb([&] {
        Controller c(m);
        if (!c.Load(p10k) || c.SnakeCount() != 1 || std::abs(c.Get(0).SampleCount() - 10000) > 101) throw 1;
        c.Get(0).Polyline();
    }, ok, cpu);
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    ASSERT_TRUE(ok);
    printf("10,000-sample sidecar: %.1f MB, loaded in %.2f s (%.2f s CPU), peak +%.1f MB\n", mb10k, secs, cpu,
           kb / 1024.0);
    EXPECT_LT(cpu, 2.0);
    EXPECT_LT(secs, 30.0); // a hang, on a busy machine
    if (kMemoryMeasured) EXPECT_LT(kb / 1024.0, 10 * mb10k);

    // 1,000,000 samples: refused with a message, while reading, in bounded time and memory
    const std::string p1m = t / "m1m.ply.snakes.json";
    {
        std::ofstream out(p1m);
        out << "{\"format\":\"" << Controller::SessionFile::FormatName() << "\",\"version\":" << Controller::SessionFile::FormatVersion()
            << ",\"mesh\":{\"vertices\":" << m.vert.size() << ",\"faces\":" << m.face.size()
            << "},\"snakes\":[{\"closed\":false,\"samples\":[";
        for (int i = 0; i < 1000000; ++i)
            out << (i ? "," : "") << "{\"face\":" << (2 * i) % int(m.face.size())
                << ",\"bary\":[0.2,0.3,0.5],\"position\":[1.5,2.5,0.0],\"fixed\":false}";
        out << "]}]}\n";
    }
    const double mb1m = fs::file_size(p1m) / 1048576.0;
    std::string msg;
    t0 = std::chrono::steady_clock::now();
    const long kb1m = ChildPeakKb([&] {
        Controller c(m);
        try {
            c.Load(p1m);
        } catch (const SnakeError &e) {
            if (std::string(e.what()).find("samples") != std::string::npos) return;
        }
        throw 1;
    }, ok, cpu);
    const double secs1m = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_TRUE(ok) << "a 1,000,000-sample sidecar was not refused with a message";
    printf("1,000,000-sample sidecar: %.1f MB, refused in %.2f s (%.2f s CPU), peak +%.1f MB\n", mb1m, secs1m, cpu,
           kb1m / 1024.0);
    EXPECT_LT(cpu, 4.0);
    EXPECT_LT(secs1m, 60.0);
    if (kMemoryMeasured) EXPECT_LT(kb1m / 1024.0, 10 * mb1m);
    msg = ErrorOf([&] { Controller c(m); c.Load(p1m); });
    EXPECT_NE(msg.find("was not loaded"), std::string::npos) << msg;
}

// ------------------------------------------------------------------ the smaller ones
TEST(SmallerOnes, ClosedSeedListRepeatingTheFirstSeedIsTheSameLoopEverywhere)
{
    CMeshO m;
    PrepareGrid(m, 20);
    const std::vector<int> loop{3 * 21 + 3, 3 * 21 + 15, 15 * 21 + 9}, repeated{3 * 21 + 3, 3 * 21 + 15, 15 * 21 + 9, 3 * 21 + 3};
    // the seed path filter
    EXPECT_EQ(SeedPath<CMeshO>::Compute(m, repeated, true).vertices, SeedPath<CMeshO>::Compute(m, loop, true).vertices);
    // the snake filter (through the controller)
    Controller a(m), b(m);
    a.SetSeeds(loop);
    a.CloseSeeds(true);
    b.SetSeeds(repeated);
    b.CloseSeeds(true);
    EXPECT_EQ(a.Get(0).SampleCount(), b.Get(0).SampleCount());
    EXPECT_EQ(a.Get(0).Samples()[1].p.face, b.Get(0).Samples()[1].p.face);
}

TEST(SmallerOnes, TooManySamplesBlamesTheRightCause)
{
    CMeshO m;
    PrepareGrid(m, 100);
    auto surf = std::make_shared<SnakeSurface<CMeshO>>(m);
    // thousands of seeds back and forth: too many seeds (issue 36: refused before any search)
    std::vector<int> seeds;
    for (int i = 0; i < 3000; ++i) seeds.push_back(50 * 101 + (i % 2) * 100);
    Snake s(surf);
    std::string e = ErrorOf([&] { s.InitFromSeeds(seeds, false); });
    EXPECT_NE(e.find("3000 seed vertices are given: one path or snake joins at most 1000"), std::string::npos) << e;
    // a short path at a tiny spacing: the spacing
    SnakeParams p;
    p.spacing = 0.05;
    Snake t(surf, p);
    seeds.resize(200);
    e = ErrorOf([&] { t.InitFromSeeds(seeds, false); });
    EXPECT_NE(e.find("spacing"), std::string::npos) << e;
    EXPECT_EQ(e.find("too long"), std::string::npos) << e;
}

TEST(SmallerOnes, AnOpenSnake)
{
    CMeshO m;
    PrepareGrid(m, 5);
    const std::string e = ErrorOf([&] { SeedPath<CMeshO>::Compute(m, {3}, false); });
    EXPECT_NE(e.find("An open snake"), std::string::npos) << e;
}

// Issue 36: a FIFO (or a folder, a device) given as a Pick Points or curve/session file blocked
// the reader forever; InputFile::Require refuses it at once, for the filters, the tool and the program.
TEST(DataSafety, NonRegularInputsAreRefusedAtOnce)
{
    TempDir t;
    const std::string fifo = t / "points.pp";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    const auto t0 = std::chrono::steady_clock::now();
    for (const std::string &p : {fifo, t.dir.string(), std::string("/dev/zero")}) {
        try {
            SeedPointsParser::ReadPickPointsFile(p);
            ADD_FAILURE() << p << " was read";
        } catch (const SnakeError &e) {
            EXPECT_NE(std::string(e.what()).find("Cannot read the Pick Points file"), std::string::npos) << e.what();
        }
        EXPECT_THROW(SnakeIO<CMeshO>::ParseFileLean(p), SnakeError) << p;
    }
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 5.0);
}

// Issue 36: temporary files are named for their target and process, listed while they exist
// (a signal handler removes them), and a later write removes what a dead process left.
TEST(DataSafety, TemporaryFilesOfDeadProcessesAreRemoved)
{
    TempDir t;
    const std::string target = t / "curve.json";
    const std::string prefix = SafeFileWrite::TempPrefix(target, 4194305); // beyond Linux's pid_max
    EXPECT_NE(prefix.find("/.curve.json.gs-tmp-4194305-"), std::string::npos) << prefix;
    std::ofstream(prefix + "abc") << "partial";
    std::ofstream(SafeFileWrite::TempPrefix(target, long(::getpid())) + "live") << "ours";
    SafeFileWrite::Write(target, "{}\n");
    EXPECT_FALSE(fs::exists(prefix + "abc"));
    EXPECT_TRUE(fs::exists(SafeFileWrite::TempPrefix(target, long(::getpid())) + "live")) << "a live process's";
    std::ofstream(t / "listed") << "x";
    TempFiles::Add(t / "listed");
    TempFiles::RemoveAll();
    EXPECT_FALSE(fs::exists(t / "listed"));
}
