#ifndef GS_SNAKE_DOCK_H
#define GS_SNAKE_DOCK_H

// The panel of the Geometric Snake edit tool: a dock of MeshLab's main window, in its own dock
// area (left of the view; MeshLab's layer dialog and Log stay in view on the right), where the
// user last put it (snake_dock_place.cpp). The status line and the main buttons sit above a scroll
// area of collapsible sections, so they stay visible. Spin and combo boxes take the mouse
// wheel only when focused (scrolling the panel never edits a parameter). Widgets only:
// EditGeometricSnakePlugin connects them to the controller.

#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QMainWindow>
#include <QPushButton>
#include <QRadioButton>
#include <QSpinBox>
#include <QVBoxLayout>

/// The panel's status line: a fixed three lines, however long the message (a path has no spaces
/// to wrap at). What does not fit ends in an ellipsis; the whole message is its tooltip (and
/// MeshLab's Log has it). Its size never depends on the text, so a long message neither moves
/// the buttons below it nor widens the dock.
class StatusLine : public QLabel
{
public:
    static constexpr int Lines = 3;
    StatusLine();
    void setMessage(const QString &text);
    const QString &message() const { return full; }
    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void resizeEvent(QResizeEvent *e) override;

private:
    void relayout();
    QString full;
};

class SnakeDock : public QDockWidget
{
    Q_OBJECT
public:
    explicit SnakeDock(QWidget *parent);

    /// Shows the panel in `mainWindow` (snake_dock_place.cpp): the first time where the user
    /// last had it (QSettings), else in the left dock area; on the right it goes beside
    /// `layers` (MeshLab's layer dialog), never over it, so the Log stays visible.
    void dockInto(QMainWindow *mainWindow, QDockWidget *layers);
    /// Remembers where the panel is (area, floating geometry, width) for the next session.
    void savePlace();

    // mode
    QRadioButton *seedMode, *editMode;
    // seeds
    QLabel *seedLabel;
    QPushButton *buildOpen, *buildClosed, *removeLastSeed, *clearSeeds, *useSelection, *usePickPoints;
    QPushButton *completeLoop; // the seeds, a stroke across a part, into a loop round it
    QComboBox *seedCost;
    // energy
    QComboBox *energyType;
    QSpinBox *smoothing;
    QPushButton *computeEnergy, *showEnergy;
    // parameters
    QDoubleSpinBox *alpha, *beta, *gamma, *external, *balloon, *spacing;
    // the limits of one Run (snake/stop.h): it ends when it reaches either
    QSpinBox *maxOperations;
    QDoubleSpinBox *timeLimit;
    // slithering
    QPushButton *step, *run; // run is checkable: Run / Stop
    QLabel *convergence;
    // editing
    QCheckBox *pinDragged;
    QPushButton *pin, *insert, *remove, *undo, *redo;
    // snakes
    QComboBox *snakeList;
    QPushButton *newSnake, *deleteSnake;
    // output
    QPushButton *exportSelected, *exportAll, *addLayer, *saveSession;
    // cut (edit_geometric_snake_cut.cpp)
    QPushButton *cutSelectInside, *cutSelectOutside, *cutSplit, *cutOpen;
    QCheckBox *cutWholeFaces;
    // status
    StatusLine *status;
    QLabel *suspended; // shown while MeshLab suspends the tool (Esc)

    void setStatus(const QString &text, bool error = false);
    void setConvergence(int state); // 0 no snake, 1 moving, 2 converged, 3 running, 4 stopped (snake/stop.h)

signals:
    /// A section was opened or closed, once the panel has been laid out again (the widgets moved).
    void sectionToggled();

protected:
    QWidget *section(QVBoxLayout *into, const QString &title, bool open);
    bool placed = false; // placed once from the settings; then Qt keeps its place while hidden
    bool eventFilter(QObject *o, QEvent *e) override;
};

#endif
