// The 3D view while the edit tool is active (issue 37). MeshLab gives an active edit tool every
// mouse and wheel event of its view (GLArea::wheelEvent calls the tool instead of zooming), and
// navigates only while the tool is suspended ("Not editing", Esc). The tool uses the left
// button; the wheel (zoom; with Shift the field of view, Ctrl the near plane, Alt the point
// size) and middle-button drags (pan) go back to MeshLab's own handling, as if the tool were
// suspended for that one event. The same code serves MeshLab 2020.09 to 2025.07: GLArea's
// public suspendedEditor and its event handlers are the same in all of them.

#include "edit_geometric_snake.h"
#include "snake_dock.h"

#include <QCoreApplication>
#include <QDockWidget>
#include <QMainWindow>
#include <QMouseEvent>
#include <QWheelEvent>

#include <meshlab/glarea.h>

void EditGeometricSnakePlugin::passToView(QEvent *e, GLArea *gla)
{
    if (!gla) return;
    const bool was = gla->suspendedEditor;
    gla->suspendedEditor = true; // GLArea's handlers then drive its trackball, not the tool
    QCoreApplication::sendEvent(gla, e);
    gla->suspendedEditor = was;
}

void EditGeometricSnakePlugin::wheelEvent(QWheelEvent *e, MeshModel &, GLArea *gla)
{
    passToView(e, gla); // the picking matrices follow at the next redraw (decorate)
}

/// A middle-button press, move or release: MeshLab's pan. True if the view took the event.
bool EditGeometricSnakePlugin::viewButton(QMouseEvent *e, GLArea *gla)
{
    const bool middle = e->button() == Qt::MiddleButton || (e->type() == QEvent::MouseMove && viewDrag);
    if (!middle) return false;
    if (e->type() == QEvent::MouseButtonPress) viewDrag = true;
    if (e->type() == QEvent::MouseButtonRelease) viewDrag = false;
    passToView(e, gla);
    return true;
}

/// MeshLab draws a suspended tool (decorate is still called) but sends it no events: the
/// panel says so, and the Log, on every change of that state.
void EditGeometricSnakePlugin::checkSuspended(GLArea *gla)
{
    if (!gla || gla->suspendedEditor == shownSuspended) return;
    shownSuspended = gla->suspendedEditor;
    Log(GLLogStream::SYSTEM, "Geometric snake: %s", shownSuspended
        ? "suspended (Esc): the mouse turns the view; the panel and the keys still act on the snakes; Esc resumes."
        : "resumed: the mouse places seeds and edits samples again.");
    QTimer::singleShot(0, this, [this] { showSuspended(); }); // not while MeshLab paints
}

void EditGeometricSnakePlugin::showSuspended()
{
    if (!dock) return;
    dock->suspended->setVisible(shownSuspended);
    dock->setWindowTitle(shownSuspended ? "Geometric Snake (suspended: Esc resumes)" : "Geometric Snake");
    refreshDock();
}

/// Starting an edit tool marks the current layer modified in MeshLab ("fandisk *", and a
/// save prompt on quit: GLArea::setCurrentEditAction), though the tool changes no vertex or
/// face: the flag the layer had is put back once MeshLab is done starting the tool. What the
/// tool does change later (colours, a selection, new layers) goes through MeshLab's own flags.
void EditGeometricSnakePlugin::keepModifiedFlag(MeshModel &m)
{
    const bool was = m.meshModified();
    MeshModel *mm = &m;
    QTimer::singleShot(0, this, [this, mm, was] {
        if (!doc || !gs::host::HasMesh(*doc, mm)) return; // the layer may be gone
        mm->setMeshModified(was);
        if (glArea)
            if (QMainWindow *mw = qobject_cast<QMainWindow *>(glArea->window()))
                QMetaObject::invokeMethod(mw, "updateLayerDialog", Qt::QueuedConnection);
    });
}

/// Where the panel, the 3D view and MeshLab's layer dialog (with the Log) are, once the main
/// window has laid the panel out: for the user, and for the GUI tests that check the panel is
/// docked and hides neither the view nor the Log.
void EditGeometricSnakePlugin::logLayout(QDockWidget *layers)
{
    auto box = [](QWidget *w) { return QRect(w->mapToGlobal(QPoint(0, 0)), w->size()); };
    if (!dock || !dock->isVisible()) return;
    const QRect r = box(dock);
    Log(GLLogStream::SYSTEM, "Geometric snake: panel %s in MeshLab's main window at %d,%d size %dx%d",
        dock->isFloating() ? "floating" : "docked", r.x(), r.y(), r.width(), r.height());
    if (glArea) {
        const QRect v = box(glArea);
        Log(GLLogStream::SYSTEM, "Geometric snake: 3D view at %d,%d size %dx%d", v.x(), v.y(), v.width(), v.height());
    }
    if (layers) {
        // a dock under a tab shows nothing: its visible region is empty
        const QRect l = box(layers);
        Log(GLLogStream::SYSTEM, "Geometric snake: layer dialog (with the Log) at %d,%d size %dx%d, %s", l.x(), l.y(),
            l.width(), l.height(), layers->isVisible() && !layers->visibleRegion().isEmpty() ? "visible" : "hidden");
    }
}
