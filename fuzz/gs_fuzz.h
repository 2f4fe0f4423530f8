#ifndef GS_FUZZ_GS_FUZZ_H
#define GS_FUZZ_GS_FUZZ_H

// Fuzz harnesses: what the plugin does with bytes a user (or a damaged disk) hands it.
// Each harness takes one input and must return normally: bad input may only end in a
// vcg::tri::SnakeError (the message the filter or the edit tool shows). Any other exception,
// a NaN in a restored curve, a sanitizer report or a crash is a bug and aborts.
//
// Used by the libFuzzer entry points (fuzz_*.cpp, clang, build-asan/) and replayed over the
// committed corpus by tests/test_fuzz_corpus.cpp in every build, so an input that once
// crashed stays a regression test once it is saved in fuzz/corpus/<target>/.

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <common/ml_mesh_type.h>
#include <snake_test_util.h>
#include <vcg_ext/io/seed_list_text.h>
#include <vcg_ext/io/snake_io.h>
#include <vcg_ext/paths/seed_path.h>
#include <vcg_ext/paths/seed_points.h>
#include <vcg_ext/session/controller.h>
#include <vcg_ext/snake/error.h>

namespace gs_fuzz {

[[noreturn]] inline void Fail(const char *what, const std::string &detail)
{
    std::fprintf(stderr, "gs_fuzz: %s: %s\n", what, detail.c_str());
    std::fflush(stderr);
    std::abort();
}

/// The mesh every harness works on: a rotated icosphere projected onto a cube (sharp edges
/// through triangles), 320 faces, rebuilt per input so that no input sees another's state.
inline void MakeMesh(CMeshO &m)
{
    gs_test::MakeRotatedIcoCube(m, 2);
    gs_test::EnableSnakeAdjacency(m);
}

inline void RequireFinite(const std::vector<vcg::Point3d> &pts, const char *what)
{
    for (const auto &p : pts)
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
            Fail(what, "a restored curve has a non-finite point");
}

/// Runs f; SnakeError is the expected way to refuse bad input, anything else is a bug.
template <class F>
bool Guard(const char *what, F f)
{
    try {
        f();
        return true;
    } catch (const vcg::tri::SnakeError &) {
        return false;
    } catch (const std::exception &e) {
        Fail(what, std::string("escaped exception: ") + e.what());
    }
}

/// The JSON / sidecar loader, on the three paths that read it:
///  - the edit tool's restore (SnakeController::FromJson, the sidecar <mesh>.snakes.json);
///  - the export filter (SnakeIO::FromJson on each element of "snakes");
///  - a single snake (the snake filter's .json output).
/// What loads must be finite, must save, and must load again from what it saved; a restored
/// session must also survive one snake operation.
inline int SnakeJson(const uint8_t *data, size_t size)
{
    using namespace vcg::tri;
    typedef SnakeController<CMeshO> Controller;
    typedef SnakeIO<CMeshO> IO;
    const nlohmann::json j = nlohmann::json::parse(data, data + size, nullptr, /*allow_exceptions=*/false);
    if (j.is_discarded()) return 0;

    {
        CMeshO m;
        MakeMesh(m);
        Controller c(m);
        if (Guard("SnakeController::FromJson", [&] { c.FromJson(j); })) {
            nlohmann::json saved;
            for (int i = 0; i < c.SnakeCount(); ++i) RequireFinite(c.Get(i).PolylinePositions(), "session");
            Guard("SnakeController::ToJson", [&] { saved = c.ToJson(); });
            // One operation of the restored snake: partitioning and motion on fuzzed samples,
            // pins and parameters (where the partition overflow once was).
            if (c.SnakeCount() > 0 && c.Get(c.Selected()).SampleCount() <= 200) {
                Guard("SnakeController::Step", [&] { c.Step(); });
                RequireFinite(c.Get(c.Selected()).PolylinePositions(), "step");
            }
            CMeshO m2;
            MakeMesh(m2);
            Controller c2(m2);
            if (!Guard("SnakeController::FromJson (saved)", [&] { c2.FromJson(nlohmann::json::parse(saved.dump())); }))
                Fail("session", "a session that loaded does not load again after saving");
        }
    }

    std::vector<const nlohmann::json *> snakes;
    if (j.is_object() && j.contains("snakes") && j["snakes"].is_array()) {
        for (const auto &js : j["snakes"]) snakes.push_back(&js);
    } else {
        snakes.push_back(&j);
    }
    CMeshO m;
    MakeMesh(m);
    auto surf = std::make_shared<SnakeSurface<CMeshO>>(m, 0);
    for (const nlohmann::json *js : snakes) {
        GeometricSnake<CMeshO> s(surf);
        if (!Guard("SnakeIO::FromJson", [&] { IO::FromJson(s, *js); })) continue;
        RequireFinite(s.PolylinePositions(), "snake");
        nlohmann::json saved;
        Guard("SnakeIO::ToJson", [&] { saved = IO::ToJson(s); });
        GeometricSnake<CMeshO> s2(surf);
        if (!Guard("SnakeIO::FromJson (saved)", [&] { IO::FromJson(s2, nlohmann::json::parse(saved.dump())); }))
            Fail("snake", "a snake that loaded does not load again after saving");
    }
    return 0;
}

/// The "Seeds" parameter of the seed path and snake filters: SeedListText::Parse, then the
/// seed path itself (first byte: closed / cost) on the fuzz mesh, as the filters run it.
inline int SeedString(const uint8_t *data, size_t size)
{
    using namespace vcg::tri;
    if (size == 0) return 0;
    const uint8_t mode = data[0];
    const std::string text(reinterpret_cast<const char *>(data + 1), size - 1);
    std::vector<int> seeds;
    if (!Guard("SeedListText::Parse", [&] { seeds = SeedListText::Parse(text); })) return 0;
    for (int v : seeds)
        if (v < 0) Fail("SeedListText::Parse", "a negative index came through");
    if (seeds.size() > 64) return 0; // the parser is what is fuzzed; long paths only cost time
    CMeshO m;
    MakeMesh(m);
    const bool closed = mode & 1;
    if (mode & 2) FeatureEnergy<CMeshO>::Compute(m, FeatureEnergyType::NormalVariation, 1);
    const SeedPathCost cost = (mode & 2) ? SeedPathCost::Feature : SeedPathCost::Length;
    SeedPath<CMeshO>::Result r;
    if (!Guard("SeedPath::Compute", [&] { r = SeedPath<CMeshO>::Compute(m, seeds, closed, cost); })) return 0;
    if (!std::isfinite(r.length) || r.length <= 0) Fail("SeedPath::Compute", "path length not finite and positive");
    for (int v : r.vertices)
        if (v < 0 || v >= int(m.vert.size())) Fail("SeedPath::Compute", "path vertex out of range");
    return 0;
}

/// Snaps parsed seed points onto the fuzz mesh (as the snake filter does): what comes back
/// must be on the mesh, finite, one surface point per seed.
inline void SnapPoints(const std::vector<vcg::Point3d> &pts, bool closed)
{
    using namespace vcg::tri;
    if (pts.size() > 64) return; // the parsers are what is fuzzed; many points only cost time
    CMeshO m;
    MakeMesh(m);
    SeedPointSnap<CMeshO>::Result r;
    if (!Guard("SeedPointSnap::Snap", [&] { r = SeedPointSnap<CMeshO>::Snap(m, pts, closed ? 3 : 2, closed); }))
        return;
    if (r.points.size() != pts.size()) Fail("SeedPointSnap::Snap", "not one surface point per seed");
    for (const auto &sp : r.points) {
        if (!sp.IsValid() || sp.face >= int(m.face.size())) Fail("SeedPointSnap::Snap", "invalid surface point");
        RequireFinite({sp.Pd(m)}, "SeedPointSnap::Snap");
    }
}

/// The "SeedPoints" parameter ("x y z; x y z; ..."): SeedPointsParser::Parse, then snapping.
/// First byte: closed or open.
inline int SeedPoints(const uint8_t *data, size_t size)
{
    using namespace vcg::tri;
    if (size == 0) return 0;
    const std::string text(reinterpret_cast<const char *>(data + 1), size - 1);
    std::vector<vcg::Point3d> pts;
    if (!Guard("SeedPointsParser::Parse", [&] { pts = SeedPointsParser::Parse(text); })) return 0;
    RequireFinite(pts, "SeedPointsParser::Parse"); // NaN and infinity must be refused
    SnapPoints(pts, data[0] & 1);
    return 0;
}

/// A MeshLab Pick Points file (.pp, the "SeedFile" parameter): ParsePickPoints, the placed
/// points, then snapping.
inline int PickPoints(const uint8_t *data, size_t size)
{
    using namespace vcg::tri;
    const std::string xml(reinterpret_cast<const char *>(data), size);
    std::vector<PickedPoint> pp;
    if (!Guard("SeedPointsParser::ParsePickPoints", [&] { pp = SeedPointsParser::ParsePickPoints(xml); })) return 0;
    std::vector<vcg::Point3d> pts = SeedPointsParser::Active(pp);
    SnapPoints(pts, size > 0 && (data[size - 1] & 1));
    return 0;
}

} // namespace gs_fuzz

#endif
