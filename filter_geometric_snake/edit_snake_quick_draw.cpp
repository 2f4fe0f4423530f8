// Showing an input at once on a large mesh (issue 37). MeshLab redraws the whole scene after
// every mouse event it passes to an edit tool (GLArea::mousePressEvent/mouseMoveEvent/
// mouseReleaseEvent call update()): on bunny00 subdivided twice (1.2M faces) under software
// OpenGL one redraw took 0.42-0.54 s, so a seed click waited for two of them. In seed mode
// the tool takes the mouse events of the 3D view before MeshLab does, and under Mesa's
// software OpenGL draws what changed over the last frame instead of redrawing the mesh: a
// seed, a stroke being painted, a new snake. There a buffer swap copies the back buffer to
// the window and keeps it (and the depth buffer), so the last frame is still in it; nothing
// else in the view changed (the view's matrices are the last frame's). A GPU redraws the mesh
// in milliseconds, and its swaps may not keep the back buffer: there the full redraw, as before.
// (Drawing into the front buffer instead showed a black view under Xvfb: its front buffer
// does not hold the frame on screen.)

#include <GL/glew.h>

#include "edit_geometric_snake.h"
#include "snake_dock.h"

#include <QMouseEvent>

#include <string>

#include <meshlab/glarea.h>

/// Mesa's software OpenGL (llvmpipe, softpipe, swrast): swaps copy and keep the back buffer.
static bool softwareGL()
{
    const char *r = reinterpret_cast<const char *>(glGetString(GL_RENDERER));
    const std::string s = r ? r : "";
    return s.find("llvmpipe") != std::string::npos || s.find("softpipe") != std::string::npos ||
           s.find("Software Rasterizer") != std::string::npos;
}

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

/// Draws the tool's curves and seeds over the last frame (software OpenGL, see above) and
/// swaps, with the view of the last frame; `mustShow` (a new seed) is read back first: if it
/// is not there, a full redraw. Elsewhere a full redraw. Logs the response time of the input
/// being shown (SnakeResponseClock).
void EditGeometricSnakePlugin::showNow(const vcg::Point3d *mustShow)
{
    if (!glArea || !ctl || !model || !viewValid || !glArea->isVisible()) {
        if (glArea) glArea->update();
        return;
    }
    glArea->makeCurrent();
    if (!softwareGL()) {
        glArea->update();
        return;
    }
    glPushAttrib(GL_ALL_ATTRIB_BITS);
    glMatrixMode(GL_PROJECTION);
    glPushMatrix();
    glLoadMatrixd(P);
    glMatrixMode(GL_MODELVIEW);
    glPushMatrix();
    glLoadMatrixd(MV);
    glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
    glDrawBuffer(GL_BACK);
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
            glReadBuffer(GL_BACK);
            glReadPixels(int(s[0]), int(s[1]), 1, 1, GL_RGB, GL_UNSIGNED_BYTE, px);
        }
        ok = px[1] > 150 && px[0] < 100 && px[2] < 100; // the seed's green
    }
    glMatrixMode(GL_PROJECTION);
    glPopMatrix();
    glMatrixMode(GL_MODELVIEW);
    glPopMatrix();
    glPopAttrib();
    if (!ok) {
        glArea->update(); // the response is logged when that redraw shows it
        return;
    }
    glArea->swapBuffers();
    if (response.Pending()) Log(GLLogStream::FILTER, "%s", response.Shown("drawn over the last frame").c_str());
}
