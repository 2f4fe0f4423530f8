#include "snake_dock.h"

#include <algorithm>

#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QScrollArea>
#include <QVBoxLayout>

namespace {
QDoubleSpinBox *spin(double lo, double hi, double step, int dec, double val, const QString &tip)
{
    QDoubleSpinBox *s = new QDoubleSpinBox;
    s->setRange(lo, hi);
    s->setSingleStep(step);
    s->setDecimals(dec);
    s->setValue(val);
    s->setToolTip(tip);
    s->setKeyboardTracking(false);
    return s;
}
QPushButton *button(const QString &text, const QString &tip)
{
    QPushButton *b = new QPushButton(text);
    b->setToolTip(tip);
    return b;
}
} // namespace

SnakeDock::SnakeDock(QWidget *parent) : QDockWidget(parent)
{
    setWindowTitle("Geometric Snake");
    setObjectName("GeometricSnakeDock");
    QWidget *w = new QWidget;
    QVBoxLayout *v = new QVBoxLayout(w);
    v->setContentsMargins(4, 4, 4, 4);
    v->setSpacing(4);

    // --- mode
    QGroupBox *gm = new QGroupBox("Mouse (left button)");
    QHBoxLayout *hm = new QHBoxLayout(gm);
    seedMode = new QRadioButton("Place seeds");
    seedMode->setToolTip("Click on the surface to add a seed (the nearest vertex of the clicked triangle);\n"
                         "drag to paint a stroke of seeds; Ctrl+click removes the nearest seed.\n"
                         "Enter builds an open snake, Shift+Enter a closed one; Backspace removes the last seed.\n"
                         "Esc suspends the tool to rotate the view.");
    editMode = new QRadioButton("Edit samples");
    editMode->setToolTip("Drag a sample along the surface (point editing); click selects a sample,\n"
                         "Shift+click pins/unpins it. Keys: P pin, I insert, Del delete, Space step, R run/pause,\n"
                         "Ctrl+Z undo, Ctrl+Y redo.");
    seedMode->setChecked(true);
    hm->addWidget(seedMode);
    hm->addWidget(editMode);
    v->addWidget(gm);
    status = new QLabel;
    status->setWordWrap(true);
    status->setMinimumHeight(36);
    status->setFrameStyle(QFrame::StyledPanel | QFrame::Sunken);
    status->setToolTip("Status: samples, last operation and its time; errors in red (also in MeshLab's Log)");
    v->addWidget(status);

    // --- seeds
    QGroupBox *gs = new QGroupBox("Seeds");
    QGridLayout *ls = new QGridLayout(gs);
    seedLabel = new QLabel("0 seeds");
    buildOpen = button("Build open snake", "Close the seed list: join the seeds with shortest paths and build an open snake (Enter)");
    buildClosed = button("Build closed snake", "Close the seed list into a loop and build a closed snake (Shift+Enter)");
    removeLastSeed = button("Remove last", "Remove the last seed (Backspace)");
    clearSeeds = button("Clear", "Remove all seeds");
    useSelection = button("Use selected vertices", "Use the selected vertices as seeds (ordered into a chain)");
    usePickPoints = button("Use Pick Points", "Use the points placed with MeshLab's Pick Points tool (saved as <mesh>.pp) as seeds");
    seedCost = new QComboBox;
    seedCost->addItem("Shortest path");
    seedCost->addItem("Feature-weighted path");
    seedCost->setToolTip("How consecutive seeds are joined: shortest edge path, or a path preferring low energy (features)");
    ls->addWidget(seedLabel, 0, 0);
    ls->addWidget(seedCost, 0, 1);
    ls->addWidget(buildOpen, 1, 0);
    ls->addWidget(buildClosed, 1, 1);
    ls->addWidget(removeLastSeed, 2, 0);
    ls->addWidget(clearSeeds, 2, 1);
    ls->addWidget(useSelection, 3, 0);
    ls->addWidget(usePickPoints, 3, 1);
    v->addWidget(gs);

    // --- energy
    QGroupBox *ge = new QGroupBox("Feature energy");
    QGridLayout *le = new QGridLayout(ge);
    energyType = new QComboBox;
    energyType->addItem("Normal variation (Eq. 6)");
    energyType->addItem("Curvature norm");
    energyType->addItem("Quadric error");
    energyType->addItem("Crease distance (CAD)");
    energyType->setToolTip("The feature energy the snakes minimize (low = feature)");
    smoothing = new QSpinBox;
    smoothing->setRange(0, 100);
    smoothing->setValue(2);
    smoothing->setToolTip("Rounds of energy smoothing (Sec. 6.3): more widens the capture range but blurs the feature");
    computeEnergy = button("Compute", "Recompute the energy with this type and smoothing");
    showEnergy = button("Show as colours", "Compute the energy and show it on the mesh as a colour ramp (red = feature)");
    le->addWidget(energyType, 0, 0, 1, 2);
    le->addWidget(new QLabel("Smoothing"), 1, 0);
    le->addWidget(smoothing, 1, 1);
    le->addWidget(computeEnergy, 2, 0);
    le->addWidget(showEnergy, 2, 1);
    v->addWidget(ge);

    // --- parameters
    QGroupBox *gp = new QGroupBox("Parameters");
    QFormLayout *lp = new QFormLayout(gp);
    alpha = spin(0, 10000, 0.01, 3, 0.05, "Alpha: tension (Eq. 2). Larger = shorter, tauter snake. Range [0, 10000].");
    beta = spin(0, 10000, 0.05, 3, 0.5, "Beta: rigidity (Eq. 2). Larger = smoother, straighter snake. Range [0, 10000].");
    gamma = spin(0.01, 1e6, 0.1, 2, 1.0, "Gamma: inverse time step (Eq. 4). Larger = smaller, stabler steps. Range (0, 1e6].");
    external = spin(0, 10000, 0.1, 2, 1.0, "External weight: strength of the feature force. Range [0, 10000].");
    spacing = spin(0.05, 1000, 0.1, 2, 1.0, "Sample spacing in mean edge lengths (used when a snake is built). Range [0.05, 1000].");
    lp->addRow("Alpha (tension)", alpha);
    lp->addRow("Beta (rigidity)", beta);
    lp->addRow("Gamma (1/step)", gamma);
    lp->addRow("External weight", external);
    lp->addRow("Spacing (edges)", spacing);
    v->addWidget(gp);

    // --- slithering
    QGroupBox *gr = new QGroupBox("Slithering");
    QHBoxLayout *lr = new QHBoxLayout(gr);
    step = button("Step", "One snake operation (Space)");
    run = button("Run", "Run operations live until converged; click again to pause (R)");
    run->setCheckable(true);
    convergence = new QLabel;
    convergence->setMinimumWidth(90);
    convergence->setToolTip("Convergence indicator");
    lr->addWidget(step);
    lr->addWidget(run);
    lr->addWidget(convergence);
    v->addWidget(gr);

    // --- editing
    QGroupBox *gd = new QGroupBox("Editing (selected sample)");
    QGridLayout *ld = new QGridLayout(gd);
    pinDragged = new QCheckBox("Pin dragged samples");
    pinDragged->setChecked(true);
    pinDragged->setToolTip("A sample dragged to a new place stays there (fixed) while the snake slithers");
    pin = button("Pin / unpin", "Fix or release the selected sample (P)");
    insert = button("Insert", "Insert a sample after the selected one (I)");
    remove = button("Delete", "Delete the selected sample (Del)");
    undo = button("Undo", "Undo the last change of the selected snake (Ctrl+Z)");
    redo = button("Redo", "Redo (Ctrl+Y)");
    ld->addWidget(pinDragged, 0, 0, 1, 3);
    ld->addWidget(pin, 1, 0);
    ld->addWidget(insert, 1, 1);
    ld->addWidget(remove, 1, 2);
    ld->addWidget(undo, 2, 0);
    ld->addWidget(redo, 2, 1);
    v->addWidget(gd);

    // --- snakes
    QGroupBox *gn = new QGroupBox("Snakes");
    QHBoxLayout *ln = new QHBoxLayout(gn);
    snakeList = new QComboBox;
    snakeList->setToolTip("The selected snake (drawn in magenta)");
    newSnake = button("New", "Place seeds for another snake");
    deleteSnake = button("Delete", "Delete the selected snake");
    ln->addWidget(snakeList, 1);
    ln->addWidget(newSnake);
    ln->addWidget(deleteSnake);
    v->addWidget(gn);

    // --- output
    QGroupBox *go = new QGroupBox("Output");
    QGridLayout *lo = new QGridLayout(go);
    exportSelected = button("Export selected...", "Write the selected snake to JSON, OBJ or PLY");
    exportAll = button("Export all...", "Write all snakes to JSON, OBJ or PLY");
    addLayer = button("Add as layer", "Add the selected snake's curve to the document as an edge layer");
    saveSession = button("Save session", "Save snakes, pins and parameters to <mesh>.snakes.json now (also saved automatically)");
    lo->addWidget(exportSelected, 0, 0);
    lo->addWidget(exportAll, 0, 1);
    lo->addWidget(addLayer, 1, 0);
    lo->addWidget(saveSession, 1, 1);
    v->addWidget(go);

    v->addStretch(1);

    QScrollArea *sa = new QScrollArea;
    sa->setWidget(w);
    sa->setWidgetResizable(true);
    sa->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    setWidget(sa);
    setFeatures(QDockWidget::AllDockWidgetFeatures);
    setAllowedAreas(Qt::LeftDockWidgetArea | Qt::RightDockWidgetArea);
    setFloating(true);
    if (parent) {
        QPoint p = parent->mapToGlobal(QPoint(0, 0));
        int wd = 400, ht = std::min(900, std::max(500, parent->height() - 80));
        setGeometry(p.x() + parent->width() - wd - 10, p.y() + 60, wd, ht);
    }
    setConvergence(0);
}

void SnakeDock::setStatus(const QString &text, bool error)
{
    status->setStyleSheet(error ? "color: #b00000;" : "");
    status->setText(text);
}

void SnakeDock::setConvergence(int state)
{
    static const char *text[] = {"no snake", "moving", "converged", "running"};
    static const char *style[] = {"color: gray;", "color: #a06000; font-weight: bold;",
                                  "color: #008000; font-weight: bold;", "color: #0050c0; font-weight: bold;"};
    if (state < 0 || state > 3) state = 0;
    convergence->setText(text[state]);
    convergence->setStyleSheet(style[state]);
}
