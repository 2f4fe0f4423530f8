// Picking in the edit tool: the surface point under the cursor, by casting the ray through the
// pixel on a uniform grid of the faces (vcglib's tri::DoRay). The grid is per mesh and built on
// another thread as soon as the tool starts (issue 37: 0.3 s on 1.2M faces, which the first
// click used to wait for), then kept across clicks until the mesh gains or loses faces. And the
// view's mapping between the screen and the mesh (from the matrices the last decorate cached):
// the samples and seeds nearest to the cursor on screen, the bounded target of a drag.

#include "edit_geometric_snake.h"

#include <vcg/complex/algorithms/closest.h>
#include <Eigen/Dense>
#include <QMouseEvent>
#include <meshlab/glarea.h>
#include <wrap/qt/device_to_logical.h>

using vcg::tri::SurfacePoint;

namespace {

Eigen::Vector4d apply(const double *m, const Eigen::Vector4d &v) { return Eigen::Map<const Eigen::Matrix4d>(m) * v; }

} // namespace

void EditGeometricSnakePlugin::preparePickGrid()
{
    faceGrid.reset();
    if (faceGridReady.valid()) faceGridReady.wait(); // a grid of the previous mesh: dropped
    if (!model) return;
    CMeshO *m = &model->cm;
    pickGridFaces = m->face.size();
    pickGridMesh = m;
    // reads the faces only, as MeshLab's drawing does; the tool's end waits for it (stop())
    faceGridReady = std::async(std::launch::async, [m] {
        std::unique_ptr<FaceGrid> g(new FaceGrid());
        g->Set(m->face.begin(), m->face.end());
        return g;
    });
}

/// The grid of the current mesh's faces (waiting for the one being built), rebuilt if the
/// mesh changed its face count since.
EditGeometricSnakePlugin::FaceGrid *EditGeometricSnakePlugin::pickGrid()
{
    if (!model) return nullptr;
    if (faceGridReady.valid()) faceGrid = faceGridReady.get();
    CMeshO &m = model->cm;
    if (!faceGrid || pickGridFaces != m.face.size() || pickGridMesh != &m) {
        faceGrid.reset(new FaceGrid());
        faceGrid->Set(m.face.begin(), m.face.end());
        pickGridFaces = m.face.size();
        pickGridMesh = &m;
    }
    return faceGrid.get();
}

/// Exact picking: the ray through the pixel against the mesh's triangles, with vcglib's
/// ray casting on a uniform grid (tri::DoRay), so a click costs the same on a 1M-face mesh;
/// the hit gives the face and barycentric coordinates.
bool EditGeometricSnakePlugin::pick(const QPointF &g, SurfacePoint &sp, vcg::Point3d &xyz)
{
    if (!viewValid || !ctl || !model) return false;
    double nx = 2.0 * (g.x() - viewport[0]) / viewport[2] - 1.0, ny = 2.0 * (g.y() - viewport[1]) / viewport[3] - 1.0;
    const Eigen::Map<const Eigen::Matrix4d> inv(Minv);
    Eigen::Vector4d a = inv * Eigen::Vector4d(nx, ny, -1, 1), b = inv * Eigen::Vector4d(nx, ny, 1, 1);
    if (a[3] == 0 || b[3] == 0) return false;
    Eigen::Vector3d o = a.head<3>() / a[3], d = b.head<3>() / b[3] - o;
    if (!o.allFinite() || !d.allFinite() || d.norm() == 0) return false;
    CMeshO &m = model->cm;
    FaceGrid *grid = pickGrid();
    vcg::Ray3<Scalarm> ray(Point3m(o[0], o[1], o[2]), Point3m(d[0], d[1], d[2]));
    Scalarm t = 0;
    CFaceO *f = vcg::tri::DoRay(m, *grid, ray, Scalarm(d.norm() * 2), t);
    if (f == nullptr || f->IsD() || !std::isfinite(t)) return false;
    ray.Normalize();
    const Point3m hit = ray.Origin() + ray.Direction() * t;
    vcg::Triangle3<Scalarm> tri(f->cP(0), f->cP(1), f->cP(2));
    Point3m bary;
    if (!vcg::InterpolationParameters(tri, hit, bary)) return false; // a degenerate face: ignore the click
    sp = SurfacePoint(int(vcg::tri::Index(m, f)), vcg::Point3d::Construct(bary));
    sp.Normalize();
    xyz = sp.Pd(m);
    return true;
}

QPointF EditGeometricSnakePlugin::glPos(QMouseEvent *e, GLArea *gla) const
{
    vcg::Point2f p = QTLogicalToOpenGL(gla, e->pos());
    return QPointF(p[0], p[1]);
}

bool EditGeometricSnakePlugin::unproject(const vcg::Point3d &s, vcg::Point3d &p) const
{
    Eigen::Vector4d c = apply(Minv, Eigen::Vector4d(2.0 * (s[0] - viewport[0]) / viewport[2] - 1.0,
                                                    2.0 * (s[1] - viewport[1]) / viewport[3] - 1.0, 2.0 * s[2] - 1.0, 1.0));
    if (c[3] == 0 || !c.allFinite()) return false;
    p = vcg::Point3d(c[0] / c[3], c[1] / c[3], c[2] / c[3]);
    return true;
}

/// The dragged sample follows the surface point under the cursor, but moves at most twice
/// the surface distance the cursor covers on a view facing the surface: on a grazing view a
/// few pixels span many edge lengths, and an unbounded jump would make the next Run tangle.
/// A bounded step is taken in space, then brought back to the nearest point of the mesh.
bool EditGeometricSnakePlugin::boundedDragTarget(const QPointF &g, const SurfacePoint &hit, SurfacePoint &target)
{
    CMeshO &m = model->cm;
    const vcg::Point3d from = dragTarget.Pd(m), to = hit.Pd(m);
    vcg::Point3d sf, a, b;
    if (!project(from, sf) || !unproject(sf, a) || !unproject(sf + vcg::Point3d(1, 0, 0), b)) {
        target = hit;
        return true;
    }
    const double pixelSize = (b - a).Norm(); // the size of a pixel at the sample's depth
    const double pixels = std::hypot(g.x() - dragLastPos.x(), g.y() - dragLastPos.y()) + 2.0;
    const double maxStep = 2.0 * pixels * pixelSize, d = (to - from).Norm();
    FaceGrid *grid = pickGrid();
    if (!(d > maxStep) || !grid) {
        target = hit;
        return true;
    }
    const vcg::Point3d q = from + (to - from) * (maxStep / d);
    Scalarm dist = 0;
    Point3m closest;
    CFaceO *f = vcg::tri::GetClosestFaceBase(m, *grid, Point3m::Construct(q), Scalarm(2 * maxStep), dist, closest);
    if (!f || f->IsD()) return false;
    Point3m bary;
    if (!vcg::InterpolationParameters(vcg::Triangle3<Scalarm>(f->cP(0), f->cP(1), f->cP(2)), closest, bary)) return false;
    target = SurfacePoint(int(vcg::tri::Index(m, f)), vcg::Point3d::Construct(bary));
    target.Normalize();
    return true;
}

bool EditGeometricSnakePlugin::project(const vcg::Point3d &p, vcg::Point3d &s) const
{
    Eigen::Vector4d c = apply(M, Eigen::Vector4d(p[0], p[1], p[2], 1.0));
    if (!(c[3] > 0)) return false;
    s = vcg::Point3d(viewport[0] + (c[0] / c[3] + 1) * 0.5 * viewport[2], viewport[1] + (c[1] / c[3] + 1) * 0.5 * viewport[3],
                     (c[2] / c[3] + 1) * 0.5);
    return std::isfinite(s[0]) && std::isfinite(s[1]);
}

int EditGeometricSnakePlugin::nearestSampleOnScreen(const QPointF &g, int &snake, double radius)
{
    snake = -1;
    if (!ctl || !viewValid) return -1;
    int best = -1;
    double bd = radius * radius;
    // the selected snake first, then the others
    for (int k = 0; k < ctl->SnakeCount(); ++k) {
        int si = ctl->Selected() >= 0 ? (k + ctl->Selected()) % ctl->SnakeCount() : k;
        const auto &smp = ctl->Get(si).Samples();
        for (int i = 0; i < int(smp.size()); ++i) {
            vcg::Point3d s;
            if (!project(smp[i].p.Pd(model->cm), s)) continue;
            double dd = (s[0] - g.x()) * (s[0] - g.x()) + (s[1] - g.y()) * (s[1] - g.y());
            if (dd < bd) { bd = dd; best = i; snake = si; }
        }
        if (best >= 0) break;
    }
    return best;
}

int EditGeometricSnakePlugin::nearestSeedOnScreen(const QPointF &g, double radius)
{
    if (!ctl || !viewValid) return -1;
    int best = -1;
    double bd = radius * radius;
    for (int i = 0; i < int(ctl->Seeds().size()); ++i) {
        vcg::Point3d s;
        if (!project(ctl->SeedPosition(i), s)) continue;
        double dd = (s[0] - g.x()) * (s[0] - g.x()) + (s[1] - g.y()) * (s[1] - g.y());
        if (dd < bd) { bd = dd; best = i; }
    }
    return best;
}
