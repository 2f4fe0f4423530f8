// The edit tool's panel state (issue 37: a status line that is always true). The buttons, the
// badge and the status line are recomputed from the controller's state on every change: a
// message (an error in red, an export, the end of a Run) stays until the state changes, then the
// line says again what the state is. Counts agree in number ("1 seed"), moves are in mean edge
// lengths, a time is shown only as the Log says it, and the sample buttons act only on a
// selected sample.

#include "edit_geometric_snake.h"
#include "snake_dock.h"

#include <QAbstractButton>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>

namespace {
QString count(long n, const char *one, const char *many) { return QString("%1 %2").arg(n).arg(n == 1 ? one : many); }

/// Environment hook for scripted GUI tests: GS_SNAKE_PANEL_STATE=<file.json> makes the tool write
/// what its panel shows (status line, badge, seed count, which sample buttons are enabled,
/// suspended, the Run's limits) to that file whenever it changes, with where its buttons and
/// fields are on the screen, so that a test clicks and types into them in any MeshLab release
/// (fonts and styles move them).
void writePanelState(const SnakeDock *d)
{
    static const QString path = QString::fromLocal8Bit(qgetenv("GS_SNAKE_PANEL_STATE"));
    if (path.isEmpty() || !d) return;
    QJsonObject o;
    o["status"] = d->status->message();
    o["error"] = !d->status->styleSheet().isEmpty();
    o["badge"] = d->convergence->text();
    o["seeds"] = d->seedLabel->text();
    o["pin"] = d->pin->isEnabled();
    o["insert"] = d->insert->isEnabled();
    o["delete"] = d->remove->isEnabled();
    o["suspended"] = !d->suspended->isHidden();
    o["maxOperations"] = d->maxOperations->value();
    o["timeLimit"] = d->timeLimit->value();
    // each button by its text (a section's header by "section <title>") and each named field:
    // its screen box, and whether it is shown and enabled
    QJsonObject widgets;
    for (const QWidget *w : d->findChildren<QWidget *>()) {
        const auto *b = qobject_cast<const QAbstractButton *>(w);
        QString name = w->objectName();
        if (name.isEmpty() && b) name = b->text();
        if (name.isEmpty() || name.startsWith("qt_") || widgets.contains(name)) continue;
        const QPoint p = w->mapToGlobal(QPoint(0, 0));
        QJsonObject box{{"x", p.x()}, {"y", p.y()}, {"w", w->width()}, {"h", w->height()},
                        {"visible", w->isVisible()}, {"enabled", w->isEnabled()}};
        if (b && b->isCheckable()) box["checked"] = b->isChecked(); // an open section
        widgets[name] = box;
    }
    o["widgets"] = widgets;
    QSaveFile f(path);
    if (f.open(QIODevice::WriteOnly)) {
        f.write(QJsonDocument(o).toJson());
        f.commit();
    }
}
} // namespace

void EditGeometricSnakePlugin::showStatus(const QString &text, bool error)
{
    statusRevision = ctl ? long(ctl->Revision()) : -1;
    if (dock) dock->setStatus(text, error);
    writePanelState(dock);
}

QString EditGeometricSnakePlugin::stateLine() const
{
    const int nseeds = int(ctl->Seeds().size());
    const Controller::Snake *s = ctl->SelectedSnake();
    if (!s || dock->seedMode->isChecked()) {
        const QString mesh = model ? model->label() : QString("the mesh");
        if (nseeds == 0)
            return QString("No seeds: click on %1 to place seeds (drag to paint a stroke of them).").arg(mesh);
        if (nseeds == 1) return "1 seed: click to add more; an open snake needs 2 seeds, a closed one 3.";
        return QString("%1 seeds: Enter builds an open snake%2.")
            .arg(nseeds)
            .arg(nseeds >= 3 ? ", Shift+Enter a closed one" : " (a closed one needs 3 seeds)");
    }
    int pins = 0;
    for (const auto &x : s->Samples()) pins += x.fixed;
    const auto &st = s->Stats();
    const QString state = s->Converged() ? "converged" : vcg::tri::SnakeStopIsProblem(st.stop) ? "stopped" : "not converged";
    const QString last = lastTimedRevision == long(ctl->Revision()) ? lastTimed : QString::fromStdString(ctl->LastOperation());
    return QString("Snake %1 of %2: %3, %4 pinned; %5, %6; largest last move %7 edge lengths%8")
        .arg(ctl->Selected() + 1)
        .arg(ctl->SnakeCount())
        .arg(count(s->SampleCount(), "sample", "samples"))
        .arg(pins)
        .arg(count(st.operations, "operation", "operations"))
        .arg(state)
        .arg(st.lastMaxMove, 0, 'f', 3)
        .arg(last.isEmpty() ? QString(".") : QString("; last: %1.").arg(last));
}

void EditGeometricSnakePlugin::refreshDock()
{
    if (!dock) return;
    bool has = ctl != nullptr;
    int nseeds = has ? int(ctl->Seeds().size()) : 0;
    dock->seedLabel->setText(count(nseeds, "seed", "seeds"));
    dock->buildOpen->setEnabled(nseeds >= 2);
    dock->buildClosed->setEnabled(nseeds >= 3);
    dock->removeLastSeed->setEnabled(nseeds > 0);
    dock->clearSeeds->setEnabled(nseeds > 0);
    Controller::Snake *s = has ? ctl->SelectedSnake() : nullptr;
    if (s && currentSample >= s->SampleCount()) currentSample = -1;
    for (QWidget *w : std::initializer_list<QWidget *>{dock->step, dock->run, dock->exportSelected, dock->addLayer,
                                                        dock->deleteSnake})
        w->setEnabled(s != nullptr);
    // the sample buttons act on the selected sample (a click in Edit samples mode)
    for (QWidget *w : std::initializer_list<QWidget *>{dock->insert, dock->remove, dock->pin})
        w->setEnabled(s != nullptr && currentSample >= 0);
    dock->exportAll->setEnabled(has && ctl->SnakeCount() > 0);
    dock->undo->setEnabled(has && (ctl->CanUndo() || cutUndo.CanUndo() || !splitSteps.empty()));
    dock->redo->setEnabled(has && (ctl->CanRedo() || cutUndo.CanRedo()));
    dock->undo->setToolTip(has && ctl->CanUndo() ? QString("Undo %1 (Ctrl+Z)").arg(QString::fromStdString(ctl->UndoLabel()))
                                                 : QString("Nothing to undo (Ctrl+Z)"));
    dock->redo->setToolTip(has && ctl->CanRedo() ? QString("Redo %1 (Ctrl+Y)").arg(QString::fromStdString(ctl->RedoLabel()))
                                                 : QString("Nothing to redo (Ctrl+Y)"));
    {
        QSignalBlocker b(dock->snakeList);
        dock->snakeList->clear();
        if (has)
            for (int i = 0; i < ctl->SnakeCount(); ++i) {
                auto &x = ctl->Get(i);
                dock->snakeList->addItem(QString("%1: %2, %3")
                                             .arg(i + 1)
                                             .arg(x.Closed() ? "closed" : "open")
                                             .arg(count(x.SampleCount(), "sample", "samples")));
            }
        if (has && ctl->Selected() >= 0) dock->snakeList->setCurrentIndex(ctl->Selected());
    }
    // the badge: "not converged" for a snake that is not running, whether it has moved yet or not
    dock->setConvergence(!s ? 0 : running() ? 3 : s->Converged() ? 2 : vcg::tri::SnakeStopIsProblem(s->Stats().stop) ? 4 : 1);
    // a message stays until the state changes (a Run shows its own progress)
    if (has && !running() && statusRevision != long(ctl->Revision())) showStatus(stateLine(), false);
    else writePanelState(dock);
}
