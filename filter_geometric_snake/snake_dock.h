#ifndef GS_SNAKE_DOCK_H
#define GS_SNAKE_DOCK_H

// The panel of the Geometric Snake edit tool (a floating dock like MeshLab's own edit
// tools). Widgets only: EditGeometricSnakePlugin connects them to the controller.

#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QRadioButton>
#include <QSpinBox>

class SnakeDock : public QDockWidget
{
    Q_OBJECT
public:
    explicit SnakeDock(QWidget *parent);

    // mode
    QRadioButton *seedMode, *editMode;
    // seeds
    QLabel *seedLabel;
    QPushButton *buildOpen, *buildClosed, *removeLastSeed, *clearSeeds, *useSelection, *usePickPoints;
    QComboBox *seedCost;
    // energy
    QComboBox *energyType;
    QSpinBox *smoothing;
    QPushButton *computeEnergy, *showEnergy;
    // parameters
    QDoubleSpinBox *alpha, *beta, *gamma, *external, *spacing;
    // slithering
    QPushButton *step, *run;
    QLabel *convergence;
    // editing
    QCheckBox *pinDragged;
    QPushButton *pin, *insert, *remove, *undo, *redo;
    // snakes
    QComboBox *snakeList;
    QPushButton *newSnake, *deleteSnake;
    // output
    QPushButton *exportSelected, *exportAll, *addLayer, *saveSession;
    // status
    QLabel *status;

    void setStatus(const QString &text, bool error = false);
    void setConvergence(int state); // 0 no snake, 1 moving, 2 converged, 3 running
};

#endif
