#include "edit_geometric_snake_factory.h"
#include "edit_geometric_snake.h"

EditGeometricSnakeFactory::EditGeometricSnakeFactory()
{
    Q_INIT_RESOURCE(edit_geometric_snake);
    editSnake = new QAction(QIcon(":/images/geometric_snake.png"), "Geometric Snake", this);
    editSnake->setToolTip("Geometric Snake: place seeds on the surface and let a snake slither onto a feature curve");
    editSnake->setCheckable(true);
    actionList << editSnake;
}

QList<QAction *> EditGeometricSnakeFactory::actions() const { return actionList; }

MeshEditInterface *EditGeometricSnakeFactory::getMeshEditInterface(QAction *action)
{
    if (action == editSnake) return new EditGeometricSnakePlugin();
    return nullptr;
}

QString EditGeometricSnakeFactory::getEditToolDescription(QAction *) { return EditGeometricSnakePlugin::Info(); }

MESHLAB_PLUGIN_NAME_EXPORTER(EditGeometricSnakeFactory)
