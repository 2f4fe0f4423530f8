#ifndef GS_EDIT_GEOMETRIC_SNAKE_FACTORY_H
#define GS_EDIT_GEOMETRIC_SNAKE_FACTORY_H

#include <QObject>
#include <common/interfaces.h>

class EditGeometricSnakeFactory : public QObject, public MeshEditInterfaceFactory
{
    Q_OBJECT
    MESHLAB_PLUGIN_IID_EXPORTER(MESH_EDIT_INTERFACE_FACTORY_IID)
    Q_INTERFACES(MeshEditInterfaceFactory)

public:
    EditGeometricSnakeFactory();
    virtual ~EditGeometricSnakeFactory() { delete editSnake; }

    virtual QList<QAction *> actions() const;
    virtual MeshEditInterface *getMeshEditInterface(QAction *);
    virtual QString getEditToolDescription(QAction *);

private:
    QList<QAction *> actionList;
    QAction *editSnake;
};

#endif
