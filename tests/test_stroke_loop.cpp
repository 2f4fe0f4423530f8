// One stroke across a part gives a loop round it (issue 33; contour completion, Lee et al. 2004):
// an open stroke across a cylinder limb standing on a body, drawn on the side facing +x, is
// completed by the way back round the limb's hidden side. Exact checks: the loop goes round the
// limb (it separates the limb's tip from the body); the stroke is kept as drawn; the way back
// stays on the hidden side; then the closed snake started from it settles on the limb's base
// (the concave crease where the limb meets the body).
#include <gtest/gtest.h>

#include <cstdio>
#include <queue>

#include <snake_test_util.h>
#include <vcg_ext/energy/feature_energy.h>
#include <vcg_ext/paths/stroke_loop.h>
#include <vcg_ext/session/controller.h>

using namespace vcg::tri;
using gs_test::EnableSnakeAdjacency;

namespace {

const int kAround = 48;
const double kRadius = 1, kLimbHeight = 4;

/// A body (a flat annulus round the limb, radii 1 to 3.5 in z = 0) with a limb (a tube of
/// radius 1 from z = 0 to 4, flat cap). Returns the tip vertex (centre of the cap); the annulus'
/// outer ring is the vertices [0, kAround).
int MakeLimbOnBody(CMeshO &m)
{
    m.Clear();
    const double h = 2 * M_PI * kRadius / kAround; // edge length round the limb
    std::vector<vcg::Point3f> pts;
    const int ringsBody = int(std::lround(2.5 / h)), ringsLimb = int(std::lround(kLimbHeight / h));
    for (int j = 0; j <= ringsBody; ++j) { // outer ring first, the base circle last
        const double r = 3.5 - 2.5 * j / ringsBody;
        for (int i = 0; i < kAround; ++i) {
            const double a = 2 * M_PI * (i + 0.5 * (j % 2)) / kAround;
            pts.emplace_back(float(r * std::cos(a)), float(r * std::sin(a)), 0.f);
        }
    }
    for (int j = 1; j <= ringsLimb; ++j) {
        const double z = kLimbHeight * j / ringsLimb;
        for (int i = 0; i < kAround; ++i) {
            const double a = 2 * M_PI * (i + 0.5 * ((ringsBody + j) % 2)) / kAround;
            pts.emplace_back(float(kRadius * std::cos(a)), float(kRadius * std::sin(a)), float(z));
        }
    }
    pts.emplace_back(0.f, 0.f, float(kLimbHeight));
    const int rings = ringsBody + ringsLimb + 1, tip = int(pts.size()) - 1;
    auto vi = vcg::tri::Allocator<CMeshO>::AddVertices(m, pts.size());
    for (size_t k = 0; k < pts.size(); ++k) m.vert[k].P() = pts[k];
    (void)vi;
    std::vector<std::array<int, 3>> tris;
    for (int j = 0; j + 1 < rings; ++j)
        for (int i = 0; i < kAround; ++i) {
            const int a = j * kAround + i, b = j * kAround + (i + 1) % kAround;
            const int c = (j + 1) * kAround + (i + 1) % kAround, d = (j + 1) * kAround + i;
            // rings are offset by half a step every other ring: split so triangles stay fat
            if (j % 2 == 0) {
                tris.push_back({a, b, d});
                tris.push_back({b, c, d});
            } else {
                tris.push_back({a, b, c});
                tris.push_back({a, c, d});
            }
        }
    for (int i = 0; i < kAround; ++i) tris.push_back({(rings - 1) * kAround + i, (rings - 1) * kAround + (i + 1) % kAround, tip});
    vcg::tri::Allocator<CMeshO>::AddFaces(m, tris.size());
    for (size_t f = 0; f < tris.size(); ++f)
        for (int k = 0; k < 3; ++k) m.face[f].V(k) = &m.vert[tris[f][k]];
    // the body's normals face +z, the limb's outwards: orient every face so
    vcg::tri::UpdateBounding<CMeshO>::Box(m);
    for (auto &f : m.face) {
        const vcg::Point3d c = (vcg::Point3d::Construct(f.V(0)->P()) + vcg::Point3d::Construct(f.V(1)->P()) +
                                vcg::Point3d::Construct(f.V(2)->P())) / 3.0;
        const vcg::Point3d n = (vcg::Point3d::Construct(f.V(1)->P()) - vcg::Point3d::Construct(f.V(0)->P())) ^
                               (vcg::Point3d::Construct(f.V(2)->P()) - vcg::Point3d::Construct(f.V(0)->P()));
        vcg::Point3d out = c[2] < 1e-6 ? vcg::Point3d(0, 0, 1) : c[2] > kLimbHeight - 1e-6 ? vcg::Point3d(0, 0, 1)
                                                                                       : vcg::Point3d(c[0], c[1], 0);
        if (n * out < 0) std::swap(f.V(1), f.V(2));
    }
    EnableSnakeAdjacency(m);
    vcg::tri::UpdateNormal<CMeshO>::PerFaceNormalized(m);
    vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalized(m);
    return tip;
}

/// The stroke: points on the limb at height z, from angle -80 to +80 degrees round +x.
std::vector<SurfacePoint> Stroke(CMeshO &m, double z)
{
    std::vector<vcg::Point3d> pts;
    for (int k = 0; k <= 4; ++k) {
        const double a = (-80 + 40 * k) * M_PI / 180;
        pts.push_back(vcg::Point3d(kRadius * std::cos(a), kRadius * std::sin(a), z));
    }
    return SeedPointSnap<CMeshO>::Snap(m, pts, 2).points;
}

/// Removing the vertices of the faces under the loop separates the tip from the body's rim.
bool Separates(const CMeshO &m, const std::vector<SurfacePoint> &loop, int tip)
{
    std::vector<char> cut(m.vert.size(), 0);
    for (const auto &s : loop)
        for (int k = 0; k < 3; ++k) cut[vcg::tri::Index(m, m.face[s.face].cV(k))] = 1;
    std::vector<std::vector<int>> adj(m.vert.size());
    for (const auto &f : m.face)
        for (int k = 0; k < 3; ++k)
            adj[vcg::tri::Index(m, f.cV(k))].push_back(int(vcg::tri::Index(m, f.cV((k + 1) % 3)))),
                adj[vcg::tri::Index(m, f.cV((k + 1) % 3))].push_back(int(vcg::tri::Index(m, f.cV(k))));
    std::vector<char> seen(m.vert.size(), 0);
    std::queue<int> q;
    q.push(tip);
    seen[tip] = 1;
    while (!q.empty()) {
        const int v = q.front();
        q.pop();
        if (v < kAround) return false; // reached the body's rim
        for (int w : adj[v])
            if (!seen[w] && !cut[w]) seen[w] = 1, q.push(w);
    }
    return !cut[tip];
}

} // namespace

TEST(StrokeLoop, StrokeAcrossALimbGivesALoopRoundIt)
{
    CMeshO m;
    const int tip = MakeLimbOnBody(m);
    const auto stroke = Stroke(m, 1.0);
    const StrokeLoop<CMeshO>::Result r = StrokeLoop<CMeshO>::Complete(m, stroke);
    std::printf("stroke %.3f, way back %.3f (half round the limb: %.3f), %zu points\n", r.strokeLength, r.backLength,
                M_PI * kRadius, r.loop.size());
    EXPECT_TRUE(Separates(m, r.loop, tip)) << "the loop goes round the limb";
    // the way back is on the hidden side (x < cos 80 deg, with a cap at the stroke's ends), on
    // the limb near the stroke's height, and about as long as the hidden arc (200 degrees)
    for (size_t i = r.strokePoints; i < r.loop.size(); ++i) {
        const vcg::Point3d x = r.loop[i].Pd(m);
        EXPECT_LT(x[0], 0.3) << "point " << i;
        EXPECT_NEAR(x[2], 1.0, 0.5) << "point " << i;
    }
    EXPECT_LT(r.backLength, 1.3 * (200.0 / 180.0) * M_PI * kRadius);
    // the stroke's own path comes first, through its points
    EXPECT_LT((r.loop.front().Pd(m) - stroke.front().Pd(m)).Norm(), 1e-9);
    EXPECT_LT((r.loop[r.strokePoints - 1].Pd(m) - stroke.back().Pd(m)).Norm(), 1e-9);
}

TEST(StrokeLoop, TheSnakeFromTheLoopSettlesOnTheLimbsBase)
{
    CMeshO m;
    MakeLimbOnBody(m);
    const auto stroke = Stroke(m, 0.6);
    SnakeController<CMeshO> c(m);
    c.SetEnergySettings(FeatureEnergyType::NormalVariation, 2);
    c.CreateLoopFromStroke(stroke);
    ASSERT_TRUE(c.SelectedSnake()->Closed());
    const int ops = c.Run(1000);
    const auto &s = *c.SelectedSnake();
    double worst = 0;
    for (const auto &x : s.positions()) worst = std::max(worst, std::hypot(std::hypot(x[0], x[1]) - kRadius, x[2]));
    std::printf("snake: %d samples, %d operations, %s, farthest sample %.3f from the base circle (edge %.3f)\n",
                s.SampleCount(), ops, SnakeStopKey(s.Stats().stop), worst, 2 * M_PI * kRadius / kAround);
    EXPECT_EQ(s.Stats().stop, SnakeStop::Converged) << s.Stats().stopMessage;
    EXPECT_LT(worst, 2 * M_PI * kRadius / kAround) << "every sample within one edge length of the base";
}

TEST(StrokeLoop, AStrokeThatCrossesNothingIsRefused)
{
    CMeshO m;
    MakeLimbOnBody(m);
    // two points on the flat body, side by side: no hidden side to come back round
    std::vector<vcg::Point3d> pts = {vcg::Point3d(2.0, -1.8, 0), vcg::Point3d(2.0, 1.8, 0)};
    const auto stroke = SeedPointSnap<CMeshO>::Snap(m, pts, 2).points;
    EXPECT_THROW(StrokeLoop<CMeshO>::Complete(m, stroke), SnakeError);
    EXPECT_THROW(StrokeLoop<CMeshO>::Complete(m, {stroke[0]}), SnakeError);
}
