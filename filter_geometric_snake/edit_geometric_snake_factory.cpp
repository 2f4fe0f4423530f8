#include "edit_geometric_snake_factory.h"
#include "edit_geometric_snake.h"

#include <QTimer>

EditGeometricSnakeFactory::EditGeometricSnakeFactory()
{
    Q_INIT_RESOURCE(edit_geometric_snake);
    editSnake = new QAction(QIcon(":/images/geometric_snake.png"), "Geometric Snake", this);
    editSnake->setToolTip("Geometric Snake: place seeds on the surface and let a snake slither onto a feature curve");
    editSnake->setCheckable(true);
    actionList << editSnake;

    // GS_SNAKE_AUTOSTART=1 (set by scripts/run.sh): start the tool as soon as MeshLab has a
    // mesh, so the README's first command opens MeshLab ready to snake. MeshLab enables
    // edit actions once a mesh is loaded; poll for that (at most a minute).
    if (qgetenv("GS_SNAKE_AUTOSTART") == "1") {
        QTimer *t = new QTimer(this);
        t->setInterval(300);
        int *left = new int(200);
        connect(t, &QTimer::timeout, this, [this, t, left] {
            const bool ready = editSnake->isEnabled() && !editSnake->associatedWidgets().isEmpty();
            if (ready && !editSnake->isChecked()) editSnake->trigger();
            if (ready || --*left <= 0) {
                t->stop();
                delete left;
            }
        });
        t->start();
    }
}

QList<QAction *> EditGeometricSnakeFactory::actions() const { return actionList; }

MeshEditInterface *EditGeometricSnakeFactory::getMeshEditInterface(QAction *action)
{
    if (action == editSnake) return new EditGeometricSnakePlugin();
    return nullptr;
}

QString EditGeometricSnakeFactory::getEditToolDescription(QAction *) { return EditGeometricSnakePlugin::Info(); }

MESHLAB_PLUGIN_NAME_EXPORTER(EditGeometricSnakeFactory)
