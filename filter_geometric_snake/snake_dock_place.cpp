// Where the Geometric Snake panel docks in MeshLab's main window (issue 37). MeshLab keeps its
// layer dialog, with the Log the tool writes to, in the right dock area; a tab over it would hide
// the Log, and stacked under it the panel is too short on a 1000-pixel screen. The panel takes
// the left dock area (its own), or, where the user moved it, the right one beside the layer
// dialog, or a floating window; the place is remembered in MeshLab's settings (QSettings group
// GeometricSnake/Panel) for the next session.

#include "snake_dock.h"

#include <QGuiApplication>
#include <QPointer>
#include <QScreen>
#include <QSettings>
#include <QTimer>

namespace {
const char *kGroup = "GeometricSnake/Panel";
}

void SnakeDock::dockInto(QMainWindow *mw, QDockWidget *layers)
{
    if (!mw) {
        show();
        return;
    }
    if (!placed) {
        placed = true;
        QSettings set;
        set.beginGroup(kGroup);
        const Qt::DockWidgetArea area =
            set.value("area").toInt() == int(Qt::RightDockWidgetArea) ? Qt::RightDockWidgetArea : Qt::LeftDockWidgetArea;
        const bool floating = set.value("floating", false).toBool();
        const QRect geometry = set.value("geometry").toRect();
        const int width = set.value("width", 0).toInt();
        mw->addDockWidget(area, this);
        if (area == Qt::RightDockWidgetArea && layers && !layers->isFloating() &&
            mw->dockWidgetArea(layers) == Qt::RightDockWidgetArea)
            mw->splitDockWidget(layers, this, Qt::Horizontal); // side by side: the Log stays visible
        bool onScreen = false;
        for (QScreen *s : QGuiApplication::screens()) onScreen = onScreen || s->availableGeometry().intersects(geometry);
        if (floating && geometry.isValid() && onScreen) {
            setFloating(true);
            setGeometry(geometry);
        } else if (width > 0) {
            QPointer<SnakeDock> self(this);
            QTimer::singleShot(0, mw, [mw, self, width] {
                if (self && !self->isFloating()) mw->resizeDocks({self.data()}, {width}, Qt::Horizontal);
            });
        }
        // the user's moves are remembered as they happen; the width when the panel hides
        connect(this, &QDockWidget::dockLocationChanged, this, [this](Qt::DockWidgetArea) { savePlace(); });
        connect(this, &QDockWidget::topLevelChanged, this, [this](bool) { savePlace(); });
    }
    show();
    raise();
}

void SnakeDock::savePlace()
{
    QMainWindow *mw = qobject_cast<QMainWindow *>(parentWidget());
    if (!mw || !placed || !isVisible()) return;
    const Qt::DockWidgetArea area = mw->dockWidgetArea(this);
    if (area != Qt::LeftDockWidgetArea && area != Qt::RightDockWidgetArea) return;
    QSettings set;
    set.beginGroup(kGroup);
    set.setValue("area", int(area));
    set.setValue("floating", isFloating());
    if (isFloating()) set.setValue("geometry", geometry());
    else set.setValue("width", width());
}
