// The edit tool's drawing: the view cached for picking (projection * modelview * mesh
// transform) and the snakes, samples, pins, seeds, stroke and drag line over the mesh.
#include <GL/glew.h>

#include "edit_geometric_snake.h"

#include <cmath>

#include <Eigen/Dense>
#include <meshlab/glarea.h>

using namespace vcg;
using vcg::tri::SurfacePoint;

namespace {

// Colours: bright over a dark outline, readable on any background; magenta does not occur
// in MeshLab's quality ramp (red-yellow-green-cyan-blue).
const GLubyte kSelected[3] = {255, 0, 255};
const GLubyte kOther[3] = {255, 150, 0}; // orange: stands out on MeshLab's blue-grey background and grey meshes
const GLubyte kOutline[3] = {20, 20, 20};
const GLubyte kSample[3] = {255, 255, 255};
const GLubyte kPinned[3] = {255, 40, 40};
const GLubyte kSeed[3] = {0, 230, 0};
const GLubyte kCurrent[3] = {255, 200, 0};

void mul4(const double *a, const double *b, double *r) // column-major r = a*b
{
    for (int c = 0; c < 4; ++c)
        for (int rr = 0; rr < 4; ++rr) {
            double s = 0;
            for (int k = 0; k < 4; ++k) s += a[k * 4 + rr] * b[c * 4 + k];
            r[c * 4 + rr] = s;
        }
}

bool invert4(const double *m, double *inv)
{
    Eigen::Matrix4d a = Eigen::Map<const Eigen::Matrix4d>(m); // column-major, like GL
    bool ok = false;
    Eigen::Matrix4d b;
    double det = a.determinant();
    if (std::isfinite(det) && std::abs(det) > 1e-300) {
        b = a.inverse();
        ok = b.allFinite();
    }
    if (ok) {
        Eigen::Map<Eigen::Matrix4d> out(inv);
        out = b;
    }
    return ok;
}

} // namespace

// ====================================================================== drawing
void EditGeometricSnakePlugin::decorate(MeshModel &m, GLArea *gla, QPainter *)
{
    if (gla != glArea) return;
    checkSuspended(gla);
    if (&m != model) {
        // the current layer changed under us (MeshLab normally restarts the tool)
        if (ctl && !modelAlive()) { ctl.reset(); model = nullptr; setRunning(false); }
        return;
    }
    if (!ctl) return;
    if (!ctl->MeshMatches()) {
        setRunning(false);
        report("Geometric snake: the mesh changed (elements added or removed); restart the tool.", true);
        return;
    }
    // cache the view for picking: projection * modelview * mesh transform
    double T[16], PMV[16];
    glGetDoublev(GL_PROJECTION_MATRIX, P);
    glGetDoublev(GL_MODELVIEW_MATRIX, MV);
    glGetIntegerv(GL_VIEWPORT, viewport);
    Matrix44m tr = m.cm.Tr;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) T[c * 4 + r] = tr[r][c];
    mul4(P, MV, PMV);
    mul4(PMV, T, M);
    viewValid = viewport[2] > 0 && viewport[3] > 0 && invert4(M, Minv);
    try {
        drawAll(m);
    } catch (const std::exception &e) {
        report(QString("Geometric snake: drawing failed: %1").arg(e.what()), true);
    }
    if (response.Pending()) {
        glFinish(); // software OpenGL draws at the flush: the mesh's redraw counts too
        Log(GLLogStream::FILTER, "%s", response.Shown("redraw").c_str());
    }
}

void EditGeometricSnakePlugin::drawAll(MeshModel &m)
{
    CMeshO &cm = m.cm;
    double h = ctl->HasSurface() ? ctl->EnsureSurface().MeanEdge() : 0.01 * cm.bbox.Diag();
    const double lift = 0.05 * h; // off the surface along the face normal, against z-fighting
    float dpr = glArea ? float(glArea->devicePixelRatio()) : 1.f;
    auto lifted = [&](const SurfacePoint &sp) {
        vcg::Point3d p = sp.Pd(cm);
        vcg::Point3d n = vcg::Point3d::Construct(cm.face[sp.face].cN());
        double l = n.Norm();
        if (l > 0 && std::isfinite(l)) p += n * (lift / l);
        return p;
    };

    glPushAttrib(GL_ALL_ATTRIB_BITS);
    glPushMatrix();
    glMultMatrix(cm.Tr);
    glDisable(GL_LIGHTING);
    glDisable(GL_TEXTURE_2D);
    glDisable(GL_BLEND);
    glDisable(GL_LINE_SMOOTH);
    glDisable(GL_POINT_SMOOTH);
    glDisable(GL_CULL_FACE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_TRUE);
    // drawn a little in front of the surface in depth too (depth range trick), so the
    // curve is never hidden by the faces it lies on but still by the mesh in front of it
    glDepthRange(0.0, 0.99985);

    auto vertex = [](const vcg::Point3d &p) { glVertex3d(p[0], p[1], p[2]); };
    auto points = [&](const std::vector<vcg::Point3d> &pts, float size, const GLubyte *fill) {
        if (pts.empty()) return;
        glPointSize((size + 3) * dpr);
        glColor3ubv(kOutline);
        glBegin(GL_POINTS);
        for (auto &p : pts) vertex(p);
        glEnd();
        glPointSize(size * dpr);
        glColor3ubv(fill);
        glBegin(GL_POINTS);
        for (auto &p : pts) vertex(p);
        glEnd();
    };

    for (int k = 0; k < ctl->SnakeCount(); ++k) {
        auto &s = ctl->Get(k);
        bool sel = k == ctl->Selected();
        std::vector<SurfacePoint> pl = s.Polyline();
        std::vector<vcg::Point3d> xyz;
        xyz.reserve(pl.size());
        for (auto &sp : pl) xyz.push_back(lifted(sp));
        GLenum mode = s.Closed() ? GL_LINE_LOOP : GL_LINE_STRIP;
        glLineWidth((sel ? 7.f : 5.f) * dpr);
        glColor3ubv(kOutline);
        glBegin(mode);
        for (auto &p : xyz) vertex(p);
        glEnd();
        glLineWidth((sel ? 3.5f : 2.5f) * dpr);
        glColor3ubv(sel ? kSelected : kOther);
        glBegin(mode);
        for (auto &p : xyz) vertex(p);
        glEnd();
        if (s.Closed()) drawInsideMarks(s, lift, dpr, sel ? kSelected : kOther);
        if (sel) {
            std::vector<vcg::Point3d> free, pinned, cur;
            const auto &smp = s.Samples();
            double screenLength = 0;
            vcg::Point3d prev;
            bool hasPrev = false;
            for (int i = 0; i < int(smp.size()); ++i) {
                vcg::Point3d p = lifted(smp[i].p), sp;
                (smp[i].fixed ? pinned : free).push_back(p);
                if (i == currentSample) cur.push_back(p);
                if (project(p, sp)) {
                    if (hasPrev) screenLength += std::hypot(sp[0] - prev[0], sp[1] - prev[1]);
                    prev = sp;
                    hasPrev = true;
                }
            }
            // the current sample is a yellow ring around its own colour (red if pinned);
            // free samples closer than ~8 px on screen would hide the curve: not drawn then
            points(cur, 13.f, kCurrent);
            if (smp.size() < 2 || screenLength / double(smp.size() - 1) > 8.0 * dpr) points(free, 4.f, kSample);
            points(pinned, 8.f, kPinned);
            if (!cur.empty() && !smp[currentSample].fixed) points(cur, 4.f, kSample);
        }
    }
    // seeds
    {
        std::vector<vcg::Point3d> sp;
        for (int i = 0; i < int(ctl->Seeds().size()); ++i) {
            vcg::Point3d p = ctl->SeedPosition(i);
            const auto &v = cm.vert[ctl->Seeds()[i]];
            vcg::Point3d n = vcg::Point3d::Construct(v.cN());
            if (n.Norm() > 0 && std::isfinite(n.Norm())) p += n * (lift / n.Norm());
            sp.push_back(p);
        }
        points(sp, 9.f, kSeed);
    }
    // stroke being painted, sample being dragged
    {
        std::vector<vcg::Point3d> st;
        for (auto &s : stroke) st.push_back(lifted(s));
        points(st, 3.f, kSeed);
        Controller::Snake *s = ctl->SelectedSnake();
        if (dragSample >= 0 && dragMoved && s && dragSample < s->SampleCount()) {
            vcg::Point3d a = lifted(s->Samples()[dragSample].p), b = lifted(dragTarget);
            glLineWidth(2.f * dpr);
            glColor3ubv(kCurrent);
            glBegin(GL_LINES);
            vertex(a);
            vertex(b);
            glEnd();
            points({b}, 8.f, kCurrent);
        }
    }
    glDepthRange(0.0, 1.0);
    glPopMatrix();
    glPopAttrib();
}
