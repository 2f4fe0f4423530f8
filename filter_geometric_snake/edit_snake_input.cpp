// The edit tool's input (issue 37: one concern per file): the mouse in the 3D view (seeds,
// strokes, picking and dragging samples) and the keys the tool owns while it is active,
// wherever the focus is in MeshLab's main window except text fields.

#include <GL/glew.h>

#include "edit_geometric_snake.h"
#include "snake_dock.h"

#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QKeyEvent>
#include <QLineEdit>
#include <QMouseEvent>
#include <QPlainTextEdit>
#include <QTextEdit>

#include <meshlab/glarea.h>
#include <wrap/qt/device_to_logical.h>

using namespace vcg;
using vcg::tri::SnakeError;
using vcg::tri::SurfacePoint;

// ====================================================================== mouse and keys
void EditGeometricSnakePlugin::mousePressEvent(QMouseEvent *e, MeshModel &m, GLArea *gla)
{
    if (viewButton(e, gla)) return; // the middle button pans the view (edit_snake_view.cpp)
    if (!ctl || &m != model || e->button() != Qt::LeftButton) return;
    pressed = true;
    pressPos = e->pos();
    stroking = false;
    stroke.clear();
    dragSample = -1;
    dragMoved = false;
    QPointF g = glPos(e, gla);
    if (dock->editMode->isChecked()) {
        int sn = -1;
        int i = nearestSampleOnScreen(g, sn, 20.0 * gla->devicePixelRatio());
        if (i < 0) return;
        if (sn != ctl->Selected()) {
            guardedFn("select", [&] { setRunning(false); ctl->Select(sn); });
            paramsToDock(ctl->SelectedSnake()->Params());
        }
        currentSample = i;
        dragTarget = ctl->SelectedSnake()->Samples()[i].p;
        dragLastPos = g;
        if (e->modifiers() & Qt::ShiftModifier) {
            pressed = false;
            setRunning(false);
            if (guardedFn("pin", [&] { ctl->TogglePin(i); })) afterChange();
            return;
        }
        dragSample = i;
        refreshDock();
        gla->update();
    }
}

void EditGeometricSnakePlugin::mouseMoveEvent(QMouseEvent *e, MeshModel &m, GLArea *gla)
{
    if (viewButton(e, gla)) return; // the middle button pans the view (edit_snake_view.cpp)
    if (!ctl || &m != model || !pressed || !(e->buttons() & Qt::LeftButton)) return;
    QPointF g = glPos(e, gla);
    bool far = (e->pos() - pressPos).manhattanLength() > 6;
    SurfacePoint sp;
    vcg::Point3d x;
    if (dock->editMode->isChecked()) {
        if (dragSample < 0 || !far) return;
        SurfacePoint t;
        if (pick(g, sp, x) && boundedDragTarget(g, sp, t)) {
            dragTarget = t;
            dragMoved = true;
            dragLastPos = g;
        }
    } else if (!(e->modifiers() & Qt::ControlModifier)) {
        if (!stroking && far) {
            stroking = true;
            // the press point starts the stroke
            vcg::Point2f p0 = QTLogicalToOpenGL(gla, pressPos);
            if (pick(QPointF(p0[0], p0[1]), sp, x)) stroke.push_back(sp);
        }
        if (stroking && pick(g, sp, x)) {
            stroke.push_back(sp);
            showNow(); // the stroke grows without redrawing the mesh
        }
        return;
    }
    gla->update();
}

void EditGeometricSnakePlugin::mouseReleaseEvent(QMouseEvent *e, MeshModel &m, GLArea *gla)
{
    if (viewButton(e, gla)) return; // the middle button pans the view (edit_snake_view.cpp)
    if (!ctl || &m != model || e->button() != Qt::LeftButton || !pressed) return;
    pressed = false;
    QPointF g = glPos(e, gla);
    if (dock->editMode->isChecked()) {
        if (dragSample >= 0 && dragMoved) {
            int i = dragSample;
            setRunning(false);
            if (guardedFn("move sample", [&] { ctl->MoveSample(i, dragTarget, dock->pinDragged->isChecked()); }))
                afterChange();
        }
        dragSample = -1;
        dragMoved = false;
        gla->update();
        return;
    }
    // seed mode
    if (e->modifiers() & Qt::ControlModifier) {
        int s = nearestSeedOnScreen(g, 15.0 * gla->devicePixelRatio());
        if (s >= 0) {
            if (guardedFn("remove seed", [&] { ctl->RemoveSeed(s); })) afterChange();
        } else report("No seed near the click to remove.", false);
        return;
    }
    if (stroking) {
        stroking = false;
        std::vector<SurfacePoint> st;
        st.swap(stroke);
        if (guardedFn("stroke", [&] { ctl->AddSeedsFromStroke(st); })) afterChange();
        return; // a full redraw: the stroke's dots go, its seeds stay
    }
    response.Start("seed");
    SurfacePoint sp;
    vcg::Point3d x;
    if (!pick(g, sp, x)) {
        response.Cancel();
        report("The click is not on the mesh (no seed placed).", false);
        return;
    }
    if (guardedFn("add seed", [&] { ctl->AddSeedFromPick(sp.face, sp.bary); })) {
        quickShow = true; // a seed more: drawn over the last frame (MeshLab's redraw of a large mesh is slow)
        afterChange(); // the status counts them
        quickShow = false;
        response.Handled();
        showNow(&x);
    } else
        response.Cancel();
}

void EditGeometricSnakePlugin::keyPressEvent(QKeyEvent *e, MeshModel &m, GLArea *gla)
{
    // the owned keys arrive through eventFilter; here the mode keys, when the view has focus
    if (!ctl || &m != model) return;
    if (e->modifiers() & (Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier)) return;
    if (e->key() == Qt::Key_S) dock->seedMode->setChecked(true);
    else if (e->key() == Qt::Key_E) dock->editMode->setChecked(true);
    else if (!handleKey(e)) return;
    e->accept();
    gla->update();
}

// ====================================================================== owned keys
void EditGeometricSnakePlugin::ownKeys(bool on)
{
    if (on == keysOwned) return;
    keysOwned = on;
    if (on) qApp->installEventFilter(this);
    else qApp->removeEventFilter(this);
}

bool EditGeometricSnakePlugin::ownsKey(const QKeyEvent *e) const
{
    const Qt::KeyboardModifiers mods = e->modifiers() & ~Qt::KeypadModifier;
    const bool ctrl = mods & Qt::ControlModifier, other = mods & (Qt::AltModifier | Qt::MetaModifier);
    switch (e->key()) {
    case Qt::Key_Delete: return true; // with any modifier: Ctrl+Del and Shift+Del delete mesh elements too
    case Qt::Key_Backspace:
    case Qt::Key_I:
    case Qt::Key_L:
    case Qt::Key_P:
    case Qt::Key_R:
    case Qt::Key_Space:
    case Qt::Key_Return:
    case Qt::Key_Enter: return !ctrl && !other;
    case Qt::Key_Z:
    case Qt::Key_Y: return ctrl && !other;
    case Qt::Key_Escape: return running(); // otherwise Esc suspends the tool, as in MeshLab
    default: return false;
    }
}

/// Keys typed into a text field (a spin box of the panel, a layer name) stay there.
static bool isTextEntry(QWidget *w)
{
    if (auto *l = qobject_cast<QLineEdit *>(w)) return !l->isReadOnly();
    if (auto *b = qobject_cast<QAbstractSpinBox *>(w)) return !b->isReadOnly();
    if (auto *t = qobject_cast<QTextEdit *>(w)) return !t->isReadOnly();
    if (auto *t = qobject_cast<QPlainTextEdit *>(w)) return !t->isReadOnly();
    if (auto *c = qobject_cast<QComboBox *>(w)) return c->isEditable();
    return false;
}

/// While the tool is active its keys go to it wherever the focus is in MeshLab's main window
/// (the 3D view, the layer list, a button of the panel), except text fields: MeshLab's
/// shortcuts for them are overridden (ShortcutOverride accepted), then the key press is
/// handled here. Dialogs and other windows are left alone.
bool EditGeometricSnakePlugin::eventFilter(QObject *o, QEvent *e)
{
    if (seedModeMouse(o, e)) return true;
    if (!keysOwned || (e->type() != QEvent::ShortcutOverride && e->type() != QEvent::KeyPress)) return false;
    QWidget *w = qobject_cast<QWidget *>(o);
    if (!w) return false; // the QWindow passes it on to its focus widget
    QKeyEvent *k = static_cast<QKeyEvent *>(e);
    if (!ownsKey(k)) return false;
    QWidget *win = w->window();
    QWidget *main = glArea ? glArea->window() : nullptr;
    if (win != main && win != dock.data()) return false;
    if (isTextEntry(w)) return false;
    // no redraw here: what changes redraws (afterChange), or draws itself (Build, showNow)
    if (e->type() == QEvent::KeyPress) handleKey(k);
    e->accept();
    return true;
}

bool EditGeometricSnakePlugin::handleKey(const QKeyEvent *e)
{
    const bool shift = e->modifiers() & Qt::ShiftModifier, ctrl = e->modifiers() & Qt::ControlModifier;
    if (!ctl) {
        report("Geometric snake: no mesh (select a mesh layer and start the tool again).", true);
        return true;
    }
    switch (e->key()) {
    case Qt::Key_Return:
    case Qt::Key_Enter: buildSnake(shift); break;
    case Qt::Key_Backspace:
        // removes the last seed while placing seeds, else the selected sample
        if (!ctl->Seeds().empty() && (dock->seedMode->isChecked() || currentSample < 0)) {
            setRunning(false);
            if (guardedFn("remove seed", [&] { ctl->RemoveLastSeed(); })) afterChange();
        } else
            editCurrent("delete", [this] {
                ctl->DeleteSample(currentSample);
                currentSample = -1;
            });
        break;
    case Qt::Key_Delete:
        editCurrent("delete", [this] {
            ctl->DeleteSample(currentSample);
            currentSample = -1;
        });
        break;
    case Qt::Key_Space: stepOnce(); break;
    case Qt::Key_L: completeLoop(); break;
    case Qt::Key_R: setRunning(!running()); break;
    case Qt::Key_Escape: setRunning(false); break;
    case Qt::Key_P: editCurrent("pin", [this] { ctl->TogglePin(currentSample); }); break;
    case Qt::Key_I: editCurrent("insert", [this] { currentSample = ctl->InsertSampleAfter(currentSample); }); break;
    case Qt::Key_Z:
        if (!ctrl) return false;
        undoRedo(shift);
        break;
    case Qt::Key_Y:
        if (!ctrl) return false;
        undoRedo(true);
        break;
    default: return false;
    }
    return true;
}
