// One stroke across a part gives a loop round it (issue 33; contour completion, Lee et al. 2004):
// the seeds painted or clicked across a limb, from one side of it to the other on the side
// facing the user, are completed by the way back round the hidden side (vcg_ext/paths/stroke_loop.h)
// into a closed snake; L or the panel's Loop button. The hidden side is the one facing away
// from the view at the stroke.

#include "edit_geometric_snake.h"
#include "snake_dock.h"

void EditGeometricSnakePlugin::completeLoop()
{
    setRunning(false);
    if (!ctl) return;
    // towards the viewer at the stroke: the view ray through the seeds' centre, near minus far
    vcg::Point3d view(0, 0, 0), c(0, 0, 0), s, nearP, farP;
    const int n = int(ctl->Seeds().size());
    for (int i = 0; i < n; ++i) c += ctl->SeedPosition(i);
    if (n > 0 && viewValid && project(c / n, s) && unproject(vcg::Point3d(s[0], s[1], 0), nearP) &&
        unproject(vcg::Point3d(s[0], s[1], 1), farP))
        view = nearP - farP;
    if (guardedFn("complete loop", [&] {
            ctl->SetNewSnakeParams(paramsFromDock());
            ctl->CompleteSeedsToLoop(view);
            Log(GLLogStream::FILTER, "Geometric snake: completed a stroke of %d seeds into a closed snake of %d samples "
                "round the part", n, ctl->SelectedSnake()->SampleCount());
        })) {
        currentSample = -1;
        dock->editMode->setChecked(true);
        showStatus("The stroke is completed into a loop round the part; R runs the snake.", false);
        afterChange(true);
    }
}
