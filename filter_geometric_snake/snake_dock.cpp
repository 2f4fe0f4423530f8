#include "snake_dock.h"

#include <algorithm>

#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QResizeEvent>
#include <QScrollArea>
#include <QTextLayout>
#include <QVBoxLayout>
#include <QPointer>
#include <QTimer>
#include <QToolButton>
#include <QWheelEvent>

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
    QWidget *outer = new QWidget;
    QVBoxLayout *top = new QVBoxLayout(outer);
    top->setContentsMargins(4, 4, 4, 4);
    top->setSpacing(4);

    // ---- always visible: mode, status line, main buttons
    QHBoxLayout *hm = new QHBoxLayout;
    seedMode = new QRadioButton("Place seeds");
    seedMode->setToolTip("Click on the surface to add a seed (the nearest vertex of the clicked triangle);\n"
                         "drag to paint a stroke of seeds; Ctrl+click removes the nearest seed.\n"
                         "Enter builds an open snake, Shift+Enter a closed one; Backspace removes the last seed (S).\n"
                         "The wheel zooms and the middle button pans the view as always;\n"
                         "Esc suspends the tool to rotate the view with the left button (Esc again resumes).");
    editMode = new QRadioButton("Edit samples");
    editMode->setToolTip("Drag a sample along the surface (point editing); click selects a sample,\n"
                         "Shift+click pins/unpins it (E). Keys: P pin, I insert, Delete/Backspace delete, Space step,\n"
                         "R run/stop, Esc stops a run, Ctrl+Z undo, Ctrl+Y redo.");
    seedMode->setChecked(true);
    hm->addWidget(new QLabel("Mouse:"));
    hm->addWidget(seedMode);
    hm->addWidget(editMode);
    hm->addStretch(1);
    convergence = new QLabel;
    convergence->setToolTip("Convergence indicator of the selected snake");
    hm->addWidget(convergence);
    top->addLayout(hm);
    suspended = new QLabel("Suspended (Esc): the mouse turns the view; the panel and the keys still act on the "
                           "snakes. Esc resumes.");
    suspended->setWordWrap(true);
    suspended->setStyleSheet("background: #ffe08a; color: black; padding: 3px;");
    suspended->setVisible(false);
    top->addWidget(suspended);
    status = new StatusLine;
    top->addWidget(status);
    QHBoxLayout *hb = new QHBoxLayout;
    run = button("Run", "Run operations until the snake converges; click again (or Esc) to stop.\n"
                        "A whole Run is one undo step (R)");
    run->setCheckable(true);
    step = button("Step", "One snake operation (Space)");
    undo = button("Undo", "Undo the last action: a whole Run, drag, Build, edit or seed (Ctrl+Z)");
    redo = button("Redo", "Redo (Ctrl+Y or Ctrl+Shift+Z)");
    hb->addWidget(run);
    hb->addWidget(step);
    hb->addWidget(undo);
    hb->addWidget(redo);
    top->addLayout(hb);

    QWidget *w = new QWidget;
    QVBoxLayout *v = new QVBoxLayout(w);
    v->setContentsMargins(0, 0, 0, 0);
    v->setSpacing(2);

    // --- seeds
    QWidget *gs = section(v, "Seeds", true);
    QGridLayout *ls = new QGridLayout(gs);
    seedLabel = new QLabel("0 seeds");
    buildOpen = button("Build open", "Close the seed list: join the seeds with shortest paths and build an open snake (Enter)");
    buildClosed = button("Build closed", "Close the seed list into a loop and build a closed snake (Shift+Enter)");
    removeLastSeed = button("Remove last", "Remove the last seed (Backspace)");
    clearSeeds = button("Clear", "Remove all seeds");
    useSelection = button("Selected vertices", "Use the selected vertices as seeds (ordered into a chain)");
    usePickPoints = button("Pick Points file", "Use the points placed with MeshLab's Pick Points tool (saved as <mesh>.pp) as seeds");
    seedCost = new QComboBox;
    seedCost->addItem("Shortest path");
    seedCost->addItem("Feature-weighted path");
    seedCost->setToolTip("How consecutive seeds are joined: shortest edge path, or a path preferring low energy (features)");
    completeLoop = button("Loop", "The seeds are a stroke across a part (a limb, an ear), from one side of it to the "
                                  "other as you see it: complete it into a closed snake round the part, by the way back "
                                  "round the hidden side (L)");
    QHBoxLayout *lsl = new QHBoxLayout;
    lsl->setContentsMargins(0, 0, 0, 0);
    lsl->addWidget(seedLabel, 1);
    lsl->addWidget(completeLoop);
    ls->addLayout(lsl, 0, 0);
    ls->addWidget(seedCost, 0, 1);
    ls->addWidget(buildOpen, 1, 0);
    ls->addWidget(buildClosed, 1, 1);
    ls->addWidget(removeLastSeed, 2, 0);
    ls->addWidget(clearSeeds, 2, 1);
    ls->addWidget(useSelection, 3, 0);
    ls->addWidget(usePickPoints, 3, 1);

    // --- editing
    QWidget *gd = section(v, "Editing (selected sample)", true);
    QGridLayout *ld = new QGridLayout(gd);
    pinDragged = new QCheckBox("Pin dragged samples");
    pinDragged->setChecked(true);
    pinDragged->setToolTip("A sample dragged to a new place stays there (fixed) while the snake slithers");
    pin = button("Pin / unpin", "Fix or release the selected sample (P)");
    insert = button("Insert", "Insert a sample after the selected one (I)");
    remove = button("Delete", "Delete the selected sample (Delete or Backspace). The mesh is never touched.");
    ld->addWidget(pinDragged, 0, 0, 1, 3);
    ld->addWidget(pin, 1, 0);
    ld->addWidget(insert, 1, 1);
    ld->addWidget(remove, 1, 2);

    // --- snakes
    QWidget *gn = section(v, "Snakes", true);
    QGridLayout *ln = new QGridLayout(gn);
    snakeList = new QComboBox;
    snakeList->setToolTip("The selected snake (drawn in magenta; the others in orange)");
    snakeList->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    snakeList->setMinimumContentsLength(18);
    newSnake = button("New", "Place seeds for another snake");
    deleteSnake = button("Delete snake", "Delete the selected snake (undoable)");
    ln->addWidget(snakeList, 0, 0, 1, 2);
    ln->addWidget(newSnake, 1, 0);
    ln->addWidget(deleteSnake, 1, 1);

    // --- output
    QWidget *go = section(v, "Output", true);
    QGridLayout *lo = new QGridLayout(go);
    exportSelected = button("Export selected...", "Write the selected snake to JSON, OBJ or PLY");
    exportAll = button("Export all...", "Write all snakes to JSON, OBJ or PLY");
    addLayer = button("Add as layer", "Add the selected snake's curve to the document as an edge layer");
    saveSession = button("Save session", "Save snakes, pins and parameters to <mesh file>.snakes.json next to the mesh now, e.g. fandisk.ply.snakes.json (also saved automatically)");
    lo->addWidget(exportSelected, 0, 0);
    lo->addWidget(exportAll, 0, 1);
    lo->addWidget(addLayer, 1, 0);
    lo->addWidget(saveSession, 1, 1);

    // --- energy
    QWidget *ge = section(v, "Feature energy", false);
    QGridLayout *le = new QGridLayout(ge);
    energyType = new QComboBox;
    energyType->addItem("Normal variation (Eq. 6)");
    energyType->addItem("Curvature norm");
    energyType->addItem("Quadric error");
    energyType->addItem("Crease distance (CAD)");
    energyType->addItem("Part boundary (concave)");
    energyType->setToolTip("The feature energy the snakes minimize (low = feature). Normal variation for creases and "
                           "ridges; Part boundary (concave) for a loop around a finger, a leg, an ear or an eye");
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

    // --- parameters
    QWidget *gp = section(v, "Parameters", false);
    QFormLayout *lp = new QFormLayout(gp);
    alpha = spin(0, 10000, 0.01, 3, 0.05, "Alpha: tension (Eq. 2). Larger = shorter, tauter snake. Range [0, 10000].");
    beta = spin(0, 10000, 0.05, 3, 0.5, "Beta: rigidity (Eq. 2). Larger = smoother, straighter snake. Range [0, 10000].");
    gamma = spin(0.01, 1e6, 0.1, 2, 1.0, "Gamma: inverse time step (Eq. 4). Larger = smaller, stabler steps. Range (0, 1e6].");
    external = spin(0, 10000, 0.1, 2, 1.0, "External weight: strength of the feature force. Range [0, 10000].");
    balloon = spin(-10, 10, 0.05, 2, 0.0, "Balloon: closed snakes only, a pressure along the curve's normal. "
                   "> 0 inflates the snake towards a rim around it, < 0 deflates it; it fades on features. "
                   "Try 0.1-0.3. Range [-10, 10].");
    spacing = spin(0.05, 1000, 0.1, 2, 1.0, "Sample spacing in mean edge lengths (used when a snake is built). Range [0.05, 1000].");
    lp->addRow("Alpha (tension)", alpha);
    lp->addRow("Beta (rigidity)", beta);
    lp->addRow("Gamma (1/step)", gamma);
    lp->addRow("External weight", external);
    lp->addRow("Balloon (pressure)", balloon);
    lp->addRow("Spacing (edges)", spacing);
    maxOperations = new QSpinBox;
    maxOperations->setObjectName("Max operations");
    maxOperations->setRange(1, 1000000);
    maxOperations->setValue(500);
    maxOperations->setToolTip("A Run ends after this many operations if the snake has not converged (Run again to go on)");
    timeLimit = spin(0, 1e6, 1, 1, 60, "A Run ends after this many seconds if the snake has not converged (0: no limit)");
    timeLimit->setObjectName("Time limit");
    lp->addRow("Max operations", maxOperations);
    lp->addRow("Time limit (s)", timeLimit);

    // --- cut (issue 34; last and closed, so it moves nothing above it)
    QWidget *gc = section(v, "Cut", false);
    QGridLayout *lc = new QGridLayout(gc);
    cutSelectInside = button("Select inside", "Embed the selected closed snake into the mesh (vertices where it crosses edges) and select the faces inside it (the side its Balloon inflates)");
    cutSelectOutside = button("Select outside", "Embed the selected snake and select the faces on its other side (the inverse selection)");
    cutSplit = button("Split into layers", "Add two layers, \"inside\" and \"outside\", cut exactly along the selected snake; this layer is not changed");
    cutOpen = button("Cut open", "Embed the selected snake and make its edges boundary edges, in this layer (an open snake ending inside the mesh makes a slit)");
    cutWholeFaces = new QCheckBox("Whole faces only (keep the mesh)");
    cutWholeFaces->setToolTip("Select inside / outside select the mesh's faces by their centroid's side, without embedding the snake; the tool's undo (Ctrl+Z) takes the selection back");
    lc->addWidget(cutSelectInside, 0, 0);
    lc->addWidget(cutSelectOutside, 0, 1);
    lc->addWidget(cutSplit, 1, 0);
    lc->addWidget(cutOpen, 1, 1);
    lc->addWidget(cutWholeFaces, 2, 0, 1, 2);
    v->addStretch(1);

    // the wheel edits a spin or combo box only when it has the focus (clicked or tabbed to);
    // otherwise it scrolls the panel
    for (QWidget *x : w->findChildren<QWidget *>())
        if (qobject_cast<QAbstractSpinBox *>(x) || qobject_cast<QComboBox *>(x)) {
            x->setFocusPolicy(Qt::StrongFocus);
            x->installEventFilter(this);
        }

    QScrollArea *sa = new QScrollArea;
    sa->setWidget(w);
    sa->setWidgetResizable(true);
    sa->setFrameShape(QFrame::NoFrame);
    sa->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    top->addWidget(sa, 1);
    setWidget(outer);
    setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetFloatable);
    setAllowedAreas(Qt::LeftDockWidgetArea | Qt::RightDockWidgetArea);
    setConvergence(0);
}

QWidget *SnakeDock::section(QVBoxLayout *into, const QString &title, bool open)
{
    // a collapsible section: a flat header button with an arrow, and its body
    QToolButton *head = new QToolButton;
    head->setText(title);
    head->setObjectName("section " + title); // named for the panel-state hook (edit_snake_status.cpp)
    head->setCheckable(true);
    head->setChecked(open);
    head->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    head->setArrowType(open ? Qt::DownArrow : Qt::RightArrow);
    head->setAutoRaise(true);
    head->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    QFont f = head->font();
    f.setBold(true);
    head->setFont(f);
    QFrame *body = new QFrame;
    body->setFrameShape(QFrame::StyledPanel);
    body->setVisible(open);
    connect(head, &QToolButton::toggled, body, [this, head, body](bool on) {
        body->setVisible(on);
        head->setArrowType(on ? Qt::DownArrow : Qt::RightArrow);
        QTimer::singleShot(100, this, &SnakeDock::sectionToggled); // after the layout has moved the widgets
    });
    into->addWidget(head);
    into->addWidget(body);
    return body;
}

bool SnakeDock::eventFilter(QObject *o, QEvent *e)
{
    if (e->type() == QEvent::Wheel) {
        QWidget *w = qobject_cast<QWidget *>(o);
        if (w && !w->hasFocus()) {
            e->ignore(); // not for this box: the scroll area scrolls
            return true;
        }
    }
    return QDockWidget::eventFilter(o, e);
}

void SnakeDock::setStatus(const QString &text, bool error)
{
    status->setStyleSheet(error ? "color: #b00000;" : "");
    status->setMessage(text);
}

// ---------------------------------------------------------------------- StatusLine
StatusLine::StatusLine()
{
    setAlignment(Qt::AlignLeft | Qt::AlignTop);
    setFrameStyle(QFrame::StyledPanel | QFrame::Sunken);
    setTextInteractionFlags(Qt::TextSelectableByMouse);
    setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed); // its text never sets the dock's width
    setMessage("");
}

QSize StatusLine::sizeHint() const
{
    // as high as Lines lines of text drawn by the label, its frame and a little air
    const QMargins c = contentsMargins();
    const int text = fontMetrics().boundingRect(QRect(0, 0, 1000, 1000), Qt::AlignLeft | Qt::AlignTop,
                                                QString("Ag\n").repeated(Lines - 1) + "Ag").height();
    return QSize(100, text + c.top() + c.bottom() + 2 * margin() + 6);
}

QSize StatusLine::minimumSizeHint() const { return QSize(0, sizeHint().height()); }

void StatusLine::setMessage(const QString &text)
{
    full = text;
    setToolTip(text.isEmpty() ? QString("Status: samples, the running operation count, largest move and energy stage;\n"
                                        "errors in red (also in MeshLab's Log)")
                              : text);
    setFixedHeight(sizeHint().height());
    relayout();
}

void StatusLine::resizeEvent(QResizeEvent *e)
{
    QLabel::resizeEvent(e);
    relayout();
}

// Wraps the message at word boundaries (anywhere inside a word longer than the line) into at
// most Lines lines of the current width; the last one is elided.
void StatusLine::relayout()
{
    const int w = contentsRect().width() - 2 * margin() - 2;
    QString text = full;
    text.replace('\n', ' ');
    if (w <= 20) {
        QLabel::setText(text);
        return;
    }
    QTextLayout layout(text, font());
    QTextOption opt;
    opt.setWrapMode(QTextOption::WrapAtWordBoundaryOrAnywhere);
    layout.setTextOption(opt);
    layout.beginLayout();
    QStringList lines;
    for (int i = 0; i < Lines; ++i) {
        QTextLine line = layout.createLine();
        if (!line.isValid()) break;
        line.setLineWidth(w);
        if (i == Lines - 1) {
            lines << fontMetrics().elidedText(text.mid(line.textStart()).trimmed(), Qt::ElideRight, w);
            break;
        }
        lines << text.mid(line.textStart(), line.textLength()).trimmed();
    }
    layout.endLayout();
    QLabel::setText(lines.join('\n'));
}

void SnakeDock::setConvergence(int state)
{
    static const char *text[] = {"no snake", "not converged", "converged", "running", "stopped"};
    static const char *style[] = {"color: gray;", "color: #a06000; font-weight: bold;",
                                  "color: #008000; font-weight: bold;", "color: #0050c0; font-weight: bold;",
                                  "color: #b00000; font-weight: bold;"};
    if (state < 0 || state > 4) state = 0;
    convergence->setText(text[state]);
    convergence->setStyleSheet(style[state]);
}
