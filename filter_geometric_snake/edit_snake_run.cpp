// The edit tool's Run loop: Run / Stop (one undo step however it ends), its time slices between
// redraws, the progress in the status line, and Space's single operation. When a Run ends and
// why: edit_snake_run_end.cpp.
#include "edit_geometric_snake.h"

#include <algorithm>

#include <QSignalBlocker>

#include "snake_dock.h"

void EditGeometricSnakePlugin::step()
{
    ctl->Step();
    // an open snake that lengthened got samples in its long gaps: the sample being edited or
    // dragged keeps its place among them
    currentSample = ctl->FollowSample(currentSample);
    dragSample = ctl->FollowSample(dragSample);
}

void EditGeometricSnakePlugin::stepOnce()
{
    setRunning(false);
    if (guardedFn("step", [&] { step(); lastTimed = QString("step, %1 ms").arg(ctl->LastOperationMs(), 0, 'f', 1);
                                 lastTimedRevision = ctl->Revision(); }))
        afterChange();
}

void EditGeometricSnakePlugin::setRunning(bool on)
{
    if (on && (!ctl || !modelAlive() || !ctl->SelectedSnake())) on = false;
    if (on && !running()) {
        // the whole Run is one undo step, however it ends (converged, Stop, Esc, an error)
        ctl->BeginAction("run");
        runClock.start();
        runCompute0 = ctl->ComputeMs();
        runOps0 = ctl->SelectedSnake()->Stats().operations;
        runSeeded = vcg::tri::PartBoundaryEnd<CMeshO>::Seeded::Of(*ctl->SelectedSnake());
        runEnd = vcg::tri::SnakeStop::Running;
        sliceMs = 30;
        sliceEnd = -1;
        // a converged snake restarts (e.g. after new parameters, it may move again)
        if (ctl->SelectedSnake()->Converged() && !guardedFn("run", [&] { step(); })) {
            ctl->EndAction();
            on = false;
        } else {
            runTimer.start();
            runProgress("Running");
        }
    } else if (!on && running()) {
        runTimer.stop();
        if (ctl) ctl->EndAction();
        if (ctl && modelAlive() && ctl->SelectedSnake()) {
            // not ended by the engine or a limit: the user's Stop or Esc, or an error
            reportRunEnd(runEnd != vcg::tri::SnakeStop::Running ? runEnd : vcg::tri::SnakeStop::Cancelled);
            afterChange(true);
        }
        runEnd = vcg::tri::SnakeStop::Running;
    }
    if (dock) {
        QSignalBlocker b(dock->run);
        dock->run->setChecked(running());
        dock->run->setText(running() ? "Stop" : "Run");
    }
    refreshDock();
}

void EditGeometricSnakePlugin::runProgress(const char *state)
{
    if (!dock || !ctl || !ctl->SelectedSnake()) return;
    const auto *s = ctl->SelectedSnake();
    showStatus(QString("%1: %2 operations, largest move %3 edge lengths, %4 energy | %5 s (compute %6 s)")
                        .arg(state)
                        .arg(s->Stats().operations - runOps0)
                        .arg(s->Stats().lastMaxMove, 0, 'f', 3)
                        .arg(s->EnergyStage() > 0 ? "coarse" : "precise")
                        .arg(runClock.elapsed() / 1000.0, 0, 'f', 1)
                        .arg((ctl->ComputeMs() - runCompute0) / 1000.0, 0, 'f', 2),
                    false);
}

/// One time slice of a Run: operations for `sliceMs`, then one redraw. The slice is at
/// least 30 ms (at most ~30 redraws per second) and twice what the last redraw and event
/// handling took, so the wall time stays within ~1.5x the compute time even when drawing is
/// slow (software OpenGL); MeshLab handles its events between slices.
void EditGeometricSnakePlugin::runTick()
{
    if (!ctl || !modelAlive() || !ctl->SelectedSnake()) {
        setRunning(false);
        return;
    }
    const qint64 start = runClock.elapsed();
    if (sliceEnd >= 0) sliceMs = std::min(300.0, std::max(30.0, 2.0 * double(start - sliceEnd)));
    bool ok = true;
    do {
        ok = guardedFn("run", [&] { step(); });
        if (ok) runEnd = runCheck(); // converged, stopped by the engine, or a limit reached
    } while (ok && runEnd == vcg::tri::SnakeStop::Running && runClock.elapsed() - start < sliceMs);
    if (!ok || runEnd != vcg::tri::SnakeStop::Running) {
        setRunning(false);
        return;
    }
    runProgress("Running");
    afterChange();
    sliceEnd = runClock.elapsed();
}
