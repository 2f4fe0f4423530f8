// Picking in the edit tool: the surface point under the cursor, by casting the ray through the
// pixel on a uniform grid of the faces (vcglib's tri::DoRay). The grid is per mesh and built on
// another thread as soon as the tool starts (issue 37: 0.3 s on 1.2M faces, which the first
// click used to wait for), then kept across clicks until the mesh gains or loses faces.

#include "edit_geometric_snake.h"

#include <vcg/complex/algorithms/closest.h>
#include <Eigen/Dense>

using vcg::tri::SurfacePoint;

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
