#ifndef GS_EDIT_GEOMETRIC_SNAKE_FACTORY_H
#define GS_EDIT_GEOMETRIC_SNAKE_FACTORY_H

#include <QObject>
#include "meshlab_host.h" // MeshLab 2020.09 or 2022.02, chosen by CMake

class SnakeHistoryKeeper;

class EditGeometricSnakeFactory : public QObject, public gs::EditPluginBase
{
    Q_OBJECT
    GS_EDIT_PLUGIN

public:
    EditGeometricSnakeFactory();
    virtual ~EditGeometricSnakeFactory() { delete editSnake; }

    QString pluginName() const override;
    gs::EditToolBase *getEditTool(const QAction *) override;
    QString getEditToolDescription(const QAction *) override;

private:
    QAction *editSnake;
    SnakeHistoryKeeper *keeper; // the undo histories of the meshes the tool left (edit_snake_lifecycle.h)
};

#endif
