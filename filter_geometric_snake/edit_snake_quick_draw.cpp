// Showing an input at once on a large mesh (issue 37). MeshLab redraws the whole scene after
// every mouse event it passes to an edit tool (GLArea::mousePressEvent/mouseMoveEvent/
// mouseReleaseEvent call update()): on bunny00 subdivided twice (1.2M faces) under software
// OpenGL one redraw took 0.42-0.54 s, so a seed click waited for two of them. In seed mode
// the tool takes the mouse events of the 3D view before MeshLab does (no redraw of the mesh)
// and draws what changed over the frame on screen: a seed, a stroke being painted, a new
// snake. Nothing else in the view changes then: the view's matrices are those of the last
// frame, and its depth buffer is still there to hide what lies behind the mesh. A seed is
// checked on screen afterwards; where the front buffer is not what the user sees (some
// compositors) the full redraw follows at once, as before.

#include <GL/glew.h>

#include "edit_geometric_snake.h"
#include "snake_dock.h"

#include <QMouseEvent>

#include <meshlab/glarea.h>

bool EditGeometricSnakePlugin::seedModeMouse(QObject *o, QEvent *e)
{
    const QEvent::Type t = e->type();
    if (t != QEvent::MouseButtonPress && t != QEvent::MouseButtonRelease && t != QEvent::MouseMove) return false;
    if (!keysOwned || !glArea || o != glArea || !ctl || !model || !dock || !dock->seedMode->isChecked()) return false;
    if (glArea->suspendedEditor) return false; // Esc gave the mouse back to MeshLab's trackball
    if (doc && doc->mm() != model) return false;
    QMouseEvent *me = static_cast<QMouseEvent *>(e);
    // the left button only (seeds, strokes): the other buttons stay MeshLab's
    const bool left = t == QEvent::MouseMove ? (me->buttons() & ~Qt::LeftButton) == Qt::NoButton
                                             : me->button() == Qt::LeftButton;
    if (!left) return false;
    glArea->makeCurrent();
    if (t == QEvent::MouseButtonPress) {
        if (!glArea->hasFocus()) glArea->setFocus(); // as MeshLab does: the tool's keys come next
        mousePressEvent(me, *model, glArea);
    } else if (t == QEvent::MouseMove)
        mouseMoveEvent(me, *model, glArea);
    else
        mouseReleaseEvent(me, *model, glArea);
    e->accept();
    return true;
}

/// Draws the tool's curves and seeds over the frame on screen (its front buffer), with the
/// view of the last frame; `mustShow` (a new seed) is then read back: if it is not on screen,
/// a full redraw. Logs the response time of the input being shown (SnakeResponseClock).
void EditGeometricSnakePlugin::showNow(const vcg::Point3d *mustShow)
{
    if (!glArea || !ctl || !model || !viewValid || !glArea->isVisible()) {
        if (glArea) glArea->update();
        return;
    }
    glArea->makeCurrent();
    glPushAttrib(GL_ALL_ATTRIB_BITS);
    glMatrixMode(GL_PROJECTION);
    glPushMatrix();
    glLoadMatrixd(P);
    glMatrixMode(GL_MODELVIEW);
    glPushMatrix();
    glLoadMatrixd(MV);
    glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
    glDrawBuffer(GL_FRONT);
    bool ok = true;
    try {
        drawAll(*model);
    } catch (const std::exception &) {
        ok = false;
    }
    glFinish();
    if (ok && mustShow) {
        vcg::Point3d s;
        GLubyte px[3] = {0, 0, 0};
        if (project(*mustShow, s)) {
            glReadBuffer(GL_FRONT);
            glReadPixels(int(s[0]), int(s[1]), 1, 1, GL_RGB, GL_UNSIGNED_BYTE, px);
        }
        ok = px[1] > 150 && px[0] < 100 && px[2] < 100; // the seed's green
    }
    glDrawBuffer(GL_BACK);
    glReadBuffer(GL_BACK);
    glMatrixMode(GL_PROJECTION);
    glPopMatrix();
    glMatrixMode(GL_MODELVIEW);
    glPopMatrix();
    glPopAttrib();
    if (!ok) {
        glArea->update(); // the response is logged when that redraw shows it
        return;
    }
    if (response.Pending()) Log(GLLogStream::FILTER, "%s", response.Shown("drawn over the last frame").c_str());
}
