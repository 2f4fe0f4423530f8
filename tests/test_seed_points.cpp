// Seeds as points in space: the "x y z; ..." parser, MeshLab Pick Points (.pp) files and
// snapping onto the surface (vcg_ext/paths/seed_points.h).

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>

#include <common/ml_mesh_type.h>

#include "generated_meshes.h"
#include "vcg_ext/paths/seed_points.h"

namespace {

using vcg::tri::SeedPointsParser;
using vcg::tri::SnakeError;
typedef vcg::tri::SeedPointSnap<CMeshO> PointSnap;

// A .pp file exactly as MeshLab's Pick Points tool writes it (QDomDocument::save, indent 1;
// Qt orders the attributes by hash, so they come in no fixed order).
std::string PickPointsXml(const std::vector<vcg::Point3d> &pts, const std::vector<bool> &active = {})
{
    std::ostringstream s;
    s.precision(9);
    s << "<!DOCTYPE PickedPoints>\n<PickedPoints>\n <DocumentData>\n"
         "  <DateTime time=\"05:01:02\" date=\"2026-11-24\"/>\n  <User name=\"root\"/>\n"
         "  <DataFileName name=\"cad_box.ply\"/>\n  <templateName name=\"\"/>\n </DocumentData>\n";
    for (size_t i = 0; i < pts.size(); ++i) {
        const bool a = active.empty() || active[i];
        if (i % 2 == 0)
            s << " <point y=\"" << pts[i][1] << "\" x=\"" << pts[i][0] << "\" active=\"" << (a ? 1 : 0) << "\" z=\""
              << pts[i][2] << "\" name=\"" << i + 1 << "\"/>\n";
        else
            s << " <point name=\"p &amp; " << i + 1 << "\" active=\"" << (a ? 1 : 0) << "\" z=\"" << pts[i][2]
              << "\" x=\"" << pts[i][0] << "\" y=\"" << pts[i][1] << "\"/>\n";
    }
    s << "</PickedPoints>\n";
    return s.str();
}

TEST(SeedPointsParser, ReadsTriples)
{
    auto p = SeedPointsParser::Parse("0 0 1; 2.5, -3e-1 ,4\n  1e2\t2 3 ;");
    ASSERT_EQ(p.size(), 3u);
    EXPECT_EQ(p[0], vcg::Point3d(0, 0, 1));
    EXPECT_EQ(p[1], vcg::Point3d(2.5, -0.3, 4));
    EXPECT_EQ(p[2], vcg::Point3d(100, 2, 3));
    EXPECT_TRUE(SeedPointsParser::Parse("").empty());
    EXPECT_TRUE(SeedPointsParser::Parse("  ; \n ").empty());
}

TEST(SeedPointsParser, RefusesGarbage)
{
    for (const char *bad : {"1 2", "1 2 3 4", "1 2 x", "1 2 3; a b c", "nan 0 0", "0 inf 0", "0 0 -nan", "1e999 0 0",
                            "0x10 0 0", "1..2 0 0", "1 2 3 # comment", "--1 2 3"}) {
        SCOPED_TRACE(bad);
        EXPECT_THROW(SeedPointsParser::Parse(bad), SnakeError);
    }
    try {
        SeedPointsParser::Parse("1 2 3; 4 nan 6");
        FAIL();
    } catch (const SnakeError &e) {
        EXPECT_NE(std::string(e.what()).find("finite"), std::string::npos) << e.what();
    }
}

TEST(SeedPointsParser, ReadsPickPointsFile)
{
    std::vector<vcg::Point3d> pts{{1.5, 2, 3}, {-4, 5.25, 6}, {7, 8, 9}};
    auto pp = SeedPointsParser::ParsePickPoints(PickPointsXml(pts, {true, false, true}));
    ASSERT_EQ(pp.size(), 3u);
    EXPECT_EQ(pp[0].p, pts[0]);
    EXPECT_EQ(pp[1].p, pts[1]);
    EXPECT_EQ(pp[1].name, "p & 2");
    EXPECT_FALSE(pp[1].active);
    auto act = SeedPointsParser::Active(pp);
    ASSERT_EQ(act.size(), 2u);
    EXPECT_EQ(act[1], pts[2]);

    const std::string path = testing::TempDir() + "/gs_seed_points_test.pp";
    {
        std::ofstream f(path);
        f << PickPointsXml(pts);
    }
    EXPECT_EQ(SeedPointsParser::ReadPickPointsFile(path).size(), 3u);
    std::remove(path.c_str());
    EXPECT_THROW(SeedPointsParser::ReadPickPointsFile(path), SnakeError); // missing
}

TEST(SeedPointsParser, RefusesMalformedPickPoints)
{
    for (const char *bad :
         {"", "hello", "<mesh><point x=\"1\" y=\"2\" z=\"3\"/></mesh>", "<PickedPoints><point x=\"1\" y=\"2\"/></PickedPoints>",
          "<PickedPoints><point x=\"1\" y=\"b\" z=\"3\"/></PickedPoints>", "<PickedPoints><point x=1 y=\"2\" z=\"3\"/>",
          "<PickedPoints><point x=\"nan\" y=\"2\" z=\"3\"/></PickedPoints>", "<PickedPoints><point x=\"1", "<!-- x"}) {
        SCOPED_TRACE(bad);
        try {
            SeedPointsParser::ParsePickPoints(bad);
            ADD_FAILURE() << "accepted";
        } catch (const SnakeError &e) {
            EXPECT_NE(std::string(e.what()).find("Pick Points"), std::string::npos) << e.what();
        }
    }
    // A document without points is well formed; the caller complains about too few seeds.
    EXPECT_TRUE(SeedPointsParser::ParsePickPoints("<?xml version=\"1.0\"?><PickedPoints/>").empty());
}

TEST(SeedPointSnap, SnapsToClosestSurfacePoint)
{
    CMeshO m;
    gs_test::MakeFlatGrid(m, 10, 1.0); // [0,1]^2 at z = 0 (or the generator's frame)
    vcg::Box3d box;
    for (auto &v : m.vert) box.Add(vcg::Point3d::Construct(v.cP()));
    const vcg::Point3d c = box.Center();
    const double diag = box.Diag();
    std::vector<vcg::Point3d> q{c + vcg::Point3d(0.013, 0.021, 0.05 * diag), c + vcg::Point3d(-0.2, 0.1, -0.01 * diag)};
    auto r = PointSnap::Snap(m, q, 2);
    ASSERT_EQ(r.points.size(), 2u);
    for (int i = 0; i < 2; ++i) {
        vcg::Point3d p = r.points[i].Pd(m);
        EXPECT_NEAR(p[0], q[i][0], 1e-5);
        EXPECT_NEAR(p[1], q[i][1], 1e-5);
        EXPECT_NEAR(p[2], box.min[2], 1e-6);
        EXPECT_GE(r.points[i].bary[0], 0);
        EXPECT_NEAR(r.points[i].bary[0] + r.points[i].bary[1] + r.points[i].bary[2], 1, 1e-12);
    }
    EXPECT_NEAR(r.distances[0], 0.05 * diag, 1e-5);
}

TEST(SeedPointSnap, RefusesFarTooFewAndRepeated)
{
    CMeshO m;
    gs_test::MakeFlatGrid(m, 10, 1.0);
    vcg::Box3d box;
    for (auto &v : m.vert) box.Add(vcg::Point3d::Construct(v.cP()));
    const vcg::Point3d c = box.Center();
    const double diag = box.Diag();
    try {
        PointSnap::Snap(m, {c, c + vcg::Point3d(0, 0, 0.15 * diag)}, 2);
        FAIL();
    } catch (const SnakeError &e) {
        EXPECT_NE(std::string(e.what()).find("Seed point 2"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("10%"), std::string::npos) << e.what();
    }
    EXPECT_THROW(PointSnap::Snap(m, {c, c + vcg::Point3d(0, 0, 1e6 * diag)}, 2), SnakeError);
    EXPECT_THROW(PointSnap::Snap(m, {c}, 2), SnakeError);
    EXPECT_THROW(PointSnap::Snap(m, {c, c + vcg::Point3d(0.1, 0, 0)}, 3, true), SnakeError);
    EXPECT_THROW(PointSnap::Snap(m, {c, c + vcg::Point3d(0, 0, 0.01 * diag)}, 2), SnakeError); // same surface point
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(PointSnap::Snap(m, {c, vcg::Point3d(nan, 0, 0)}, 2), SnakeError);
}

} // namespace
