#include "edit_geometric_snake_factory.h"
#include "edit_geometric_snake.h"

#include <QTimer>

EditGeometricSnakeFactory::EditGeometricSnakeFactory()
{
    Q_INIT_RESOURCE(edit_geometric_snake);
    editSnake = new QAction(QIcon(":/images/geometric_snake.png"), "Geometric Snake", this);
    editSnake->setToolTip("Geometric Snake: place seeds on the surface and let a snake slither onto a feature curve");
    editSnake->setCheckable(true);
    addEditAction(editSnake);
    keeper = new SnakeHistoryKeeper(this);

    // GS_SNAKE_AUTOSTART=1 (set by scripts/run.sh): start the tool as soon as MeshLab has a
    // mesh, so the README's first command opens MeshLab ready to snake. MeshLab enables
    // edit actions once a mesh is loaded; poll for that (at most a minute).
    if (qgetenv("GS_SNAKE_AUTOSTART") == "1") {
        // MeshLab processes events while it loads a mesh and the action may be enabled then;
        // the tool refuses to start on a busy document (StartEdit returns false, MeshLab
        // unchecks the action), so keep triggering until it stays started.
        QTimer *t = new QTimer(this);
        t->setInterval(500);
        int *left = new int(240), *started = new int(0);
        connect(t, &QTimer::timeout, this, [this, t, left, started] {
            const bool enabled = editSnake->isEnabled() && !editSnake->associatedWidgets().isEmpty();
            if (editSnake->isChecked()) ++*started;
            else if (enabled) { *started = 0; editSnake->trigger(); }
            if (*started >= 2 || --*left <= 0) {
                t->stop();
                delete left;
                delete started;
            }
        });
        t->start();
    }
}

QString EditGeometricSnakeFactory::pluginName() const { return "EditGeometricSnake"; }

gs::EditToolBase *EditGeometricSnakeFactory::getEditTool(const QAction *action)
{
    if (action == editSnake) return new EditGeometricSnakePlugin(keeper);
    return nullptr;
}

QString EditGeometricSnakeFactory::getEditToolDescription(const QAction *) { return EditGeometricSnakePlugin::Info(); }

MESHLAB_PLUGIN_NAME_EXPORTER(EditGeometricSnakeFactory)
