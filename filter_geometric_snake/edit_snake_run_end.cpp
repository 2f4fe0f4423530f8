// The end of a Run in the edit tool (issue 33: every Run ends by itself and says why). The
// limits come from the panel (Max operations, Time limit); the engine decides after every
// operation whether the Run ends (vcg_ext/snake/stop.h: converged, a closed snake collapsing or
// leaving its part, a limit); this file shows the end: the status line (red for a stop or a
// limit), MeshLab's Log once per Run (the line the GUI tests read), the snake's stats (JSON).

#include "edit_geometric_snake.h"
#include "snake_dock.h"

#include <vcg_ext/session/param_defs.h>
#include <vcg_ext/snake/part_boundary_end.h>

using namespace vcg;

tri::SnakeRunLimits EditGeometricSnakePlugin::runLimits() const
{
    tri::SnakeRunLimits lim;
    if (dock) {
        lim.maxOperations = dock->maxOperations->value();
        lim.seconds = dock->timeLimit->value();
    }
    return lim;
}

void EditGeometricSnakePlugin::runLimitsToDock()
{
    // the default operation limit of the filters and the program (one table)
    for (const auto &d : tri::SnakeParamDefs::Snake())
        if (d.name == "MaxOperations") dock->maxOperations->setValue(int(d.value));
}

tri::SnakeStop EditGeometricSnakePlugin::runCheck() const
{
    const auto *s = ctl->SelectedSnake();
    return runLimits().Check(s->Stats().stop, s->Stats().operations - runOps0, runClock.elapsed() / 1000.0);
}

void EditGeometricSnakePlugin::reportRunEnd(tri::SnakeStop why)
{
    auto *s = ctl->SelectedSnake();
    const int ops = s->Stats().operations - runOps0;
    const double compute = (ctl->ComputeMs() - runCompute0) / 1000.0, wall = runClock.elapsed() / 1000.0;
    s->EndRun(why, runLimits().Message(why, ops, wall));
    // a converged part-boundary loop ends on the cheapest edge loop round it, as in the filters
    // (searched round the loop the Run started from when it shrank far, PartBoundaryEnd::Param::seededShrink),
    // with the mesh's measures taken once per mesh (SnakeSession::RunEndParam)
    vcg::tri::PartBoundaryEnd<CMeshO>::FinishRun(*s, ctl->EnergyType(), ctl->EnergyFromQuality(), ctl->RunEndParam(),
                                                 &runSeeded);
    const std::string &msg = s->Stats().stopMessage;
    const bool problem = tri::SnakeStopIsProblem(why);
    // the Log line the GUI tests read: the end, compute time vs wall time, the reason
    Log(problem ? GLLogStream::WARNING : GLLogStream::FILTER,
        "Geometric snake: Run %s after %d operations: compute %.3f s, wall %.3f s (median %.2f ms per operation); "
        "%s: %s", why == tri::SnakeStop::Converged ? "converged" : "stopped", ops, compute, wall,
        tri::SnakeStats::Median(s->Stats().msOperation), tri::SnakeStopKey(why), msg.c_str());
    if (!dock) return;
    if (problem) {
        lastError = msg; // said once: the Log has it
        showStatus(QString("Run stopped after %1 operations (%2 s): %3")
                            .arg(ops)
                            .arg(wall, 0, 'f', 1)
                            .arg(QString::fromStdString(msg)),
                        true);
    } else if (dock->status->styleSheet().isEmpty()) { // keep an error on show
        runProgress(why == tri::SnakeStop::Converged ? "Converged" : "Stopped (Ctrl+Z undoes the Run)");
    }
}
