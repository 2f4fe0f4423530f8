#ifndef GS_EDIT_GEOMETRIC_SNAKE_H
#define GS_EDIT_GEOMETRIC_SNAKE_H

// MeshLab edit tool "Geometric Snake": interactive geometric snakes (Lee & Lee 2002,
// Sec. 5.5 and 7) on the current layer. Thin Qt/GL glue over vcg_ext/session/controller.h.
//
// While active, the tool owns its keys (Delete, Backspace, I, L, P, R, Space, Enter, Ctrl+Z,
// Ctrl+Y; Esc during a Run): an application event filter overrides MeshLab's shortcuts for
// them (Delete is MeshLab's "Delete Selected Faces"), so they never reach the mesh.
// A Run computes operations in time slices and redraws at most ~30 times per second.
//
// Environment hook for scripted GUI tests: GS_SNAKE_AUTOEXPORT=<file.json> makes the tool
// write all its snakes (vcg_ext/io/snake_io.h JSON) to that file after every change.

#include <functional>
#include <future>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <QElapsedTimer>
#include <QObject>
#include <QPointer>
#include <QTimer>

#include "edit_snake_response.h"
#include "meshlab_host.h" // MeshLab 2020.09 or 2022.02, chosen by CMake
#include <vcg/space/index/grid_static_ptr.h>
#include "edit_snake_lifecycle.h"
#include <vcg_ext/cut/cut_point_map.h>
#include <vcg_ext/session/controller.h>
#include <vcg_ext/session/mesh_undo.h>
#include <vcg_ext/snake/part_boundary_end.h>

class QDockWidget;
class QKeyEvent;
class QWheelEvent;
class SnakeDock;

class EditGeometricSnakePlugin : public QObject, public gs::EditToolBase
{
    Q_OBJECT

public:
    typedef vcg::tri::SnakeController<CMeshO> Controller;

    /// `keeper`: where the undo histories of the meshes the tool left are kept (the factory's).
    explicit EditGeometricSnakePlugin(SnakeHistoryKeeper *keeper = nullptr);
    virtual ~EditGeometricSnakePlugin();

    static const QString Info();

    bool startEdit(MeshDocument &md, GLArea *gla, MLSceneGLSharedDataContext *cont) override;
    bool startEdit(MeshModel &m, GLArea *gla, MLSceneGLSharedDataContext *cont) override;
    void endEdit(MeshModel &m, GLArea *gla, MLSceneGLSharedDataContext *cont) override;
    void endEdit(MeshDocument &md, GLArea *gla, MLSceneGLSharedDataContext *cont) override;
    void layerChanged(MeshDocument &md, MeshModel &old, GLArea *gla, MLSceneGLSharedDataContext *cont) override;
    void decorate(MeshModel &m, GLArea *gla, QPainter *p) override; // edit_snake_draw.cpp
    void mousePressEvent(QMouseEvent *e, MeshModel &m, GLArea *gla) override;
    void mouseMoveEvent(QMouseEvent *e, MeshModel &m, GLArea *gla) override;
    void mouseReleaseEvent(QMouseEvent *e, MeshModel &m, GLArea *gla) override;
    void keyPressEvent(QKeyEvent *e, MeshModel &m, GLArea *gla) override;
    void wheelEvent(QWheelEvent *e, MeshModel &m, GLArea *gla) override; // the view's (edit_snake_view.cpp)

protected:
    bool eventFilter(QObject *o, QEvent *e) override;

private slots:
    void runTick(); // the Run loop (edit_snake_run.cpp)

private:
    // state of the session
    std::unique_ptr<Controller> ctl;
    MeshModel *model = nullptr;
    MeshDocument *doc = nullptr;
    GLArea *glArea = nullptr;
    MLSceneGLSharedDataContext *shared = nullptr;
    QPointer<SnakeDock> dock;
    QTimer runTimer;
    // the Run in progress (time slices): its clocks and counters for the progress and the Log
    QElapsedTimer runClock;
    SnakeResponseClock response; // input to redraw, for the Log (issue 37)
    double runCompute0 = 0, sliceMs = 30;
    qint64 sliceEnd = -1;
    int runOps0 = 0;
    // the loop the Run started from, for PartBoundaryEnd::FinishRun (a loop that shrinks far)
    vcg::tri::PartBoundaryEnd<CMeshO>::Seeded runSeeded;
    bool keysOwned = false;
    bool hidePending = false;
    long exportedRevision = -1;
    long storedRevision = -1;
    int currentSample = -1;
    std::string lastError;

    // cached view (from the last decorate) for exact picking and for drawing between redraws
    double P[16], MV[16]; // MeshLab's projection and modelview (column-major, like GL)
    double M[16];         // projection * modelview * mesh transform (column-major, like GL)
    double Minv[16];
    int viewport[4] = {0, 0, 1, 1};
    bool viewValid = false;

    // the view's navigation while the tool is active (edit_snake_view.cpp)
    bool viewDrag = false;       // a middle-button drag MeshLab's trackball handles (pan)
    bool shownSuspended = false; // MeshLab's "Not editing" (Esc) state the panel shows
    void passToView(QEvent *e, GLArea *gla);
    bool viewButton(QMouseEvent *e, GLArea *gla);
    void checkSuspended(GLArea *gla);
    void showSuspended();
    void keepModifiedFlag(MeshModel &m);
    void logLayout(QDockWidget *layers);

    // the status line (edit_snake_status.cpp): a message stays until the state changes, then
    // the line is recomputed from the state
    long statusRevision = -1;
    QString lastTimed; // the last action timed as the Log says it ("build, 8.9 ms") ...
    long lastTimedRevision = -1; // ... shown while the state is the one it made
    void showStatus(const QString &text, bool error);
    QString stateLine() const;

    // mouse
    bool pressed = false;
    QPoint pressPos;
    bool stroking = false;
    std::vector<vcg::tri::SurfacePoint> stroke;
    int dragSample = -1;
    bool dragMoved = false;
    vcg::tri::SurfacePoint dragTarget;
    QPointF dragLastPos; // GL coordinates of the last accepted drag event

    bool startOn(MeshModel &m);
    void stop(bool save);
    // the tool's end and restart (edit_snake_lifecycle.cpp): the undo history outlives the tool
    QPointer<SnakeHistoryKeeper> keeper;
    bool switchingLayer = false;
    int keptSteps = 0; // undo steps the last stop() kept
    void endTool();
    void keepHistory(const std::string &session);
    void resumeHistory(MeshModel &m, const std::string &stored);
    bool modelAlive() const;
    std::vector<vcg::tri::ProtectedFile> protectedFiles() const; // never overwritten by exports
    void connectDock();
    void refreshDock();
    void ownKeys(bool on);
    void hideDockLater();
    bool ownsKey(const QKeyEvent *e) const;
    bool handleKey(const QKeyEvent *e);
    void afterChange(bool forceSave = false);
    void report(const QString &msg, bool error);
    template <class F> bool guarded(const QString &what, F f);
    bool guardedFn(const QString &what, const std::function<void()> &f); // guarded(), for the other files

    // picking (edit_snake_picking.cpp)
    typedef vcg::GridStaticPtr<CFaceO, Scalarm> FaceGrid;
    bool pick(const QPointF &glPos, vcg::tri::SurfacePoint &sp, vcg::Point3d &xyz);
    void preparePickGrid();
    FaceGrid *pickGrid();
    std::unique_ptr<FaceGrid> faceGrid;               // the faces, for ray casting and closest points
    std::future<std::unique_ptr<FaceGrid>> faceGridReady; // being built since the tool started
    size_t pickGridFaces = 0;
    const CMeshO *pickGridMesh = nullptr;

    // showing an input at once, over the last frame (edit_snake_quick_draw.cpp)
    bool seedModeMouse(QObject *o, QEvent *e);
    void showNow(const vcg::Point3d *mustShow = nullptr);
    bool quickShow = false; // afterChange shows the change with showNow instead of a full redraw
    QTimer redrawLater;     // the full redraw once the user pauses (after Build)
    bool project(const vcg::Point3d &p, vcg::Point3d &screen) const;
    bool unproject(const vcg::Point3d &screen, vcg::Point3d &p) const;
    bool boundedDragTarget(const QPointF &glPos, const vcg::tri::SurfacePoint &hit, vcg::tri::SurfacePoint &target);
    int nearestSampleOnScreen(const QPointF &glPos, int &snake, double radiusPx);
    int nearestSeedOnScreen(const QPointF &glPos, double radiusPx);
    QPointF glPos(QMouseEvent *e, GLArea *gla) const;

    // actions
    void buildSnake(bool closed);
    void completeLoop(); // the seeds, a stroke across a part, into a loop round it (edit_snake_stroke_loop.cpp)
    // the Run loop (edit_snake_run.cpp)
    void stepOnce();
    void setRunning(bool on);
    void step(); // one operation; the held sample indices follow the samples it inserted
    bool running() const { return runTimer.isActive(); }
    void runProgress(const char *state);
    // the end of a Run (edit_snake_run_end.cpp)
    vcg::tri::SnakeStop runEnd = vcg::tri::SnakeStop::Running; // why the Run in progress ends, once known
    vcg::tri::SnakeRunLimits runLimits() const;
    void runLimitsToDock();
    vcg::tri::SnakeStop runCheck() const;
    void reportRunEnd(vcg::tri::SnakeStop why);
    void editCurrent(const QString &what, const std::function<void()> &f);
    void undoRedo(bool redo);
    void applyParams();
    void computeEnergy(bool show);
    void exportCurves(bool all);
    void addAsLayer();
    /// Cut along the selected snake (edit_geometric_snake_cut.cpp): select one side, cut open, split.
    void cutSelect(bool inside);
    void cutOpen();
    void cutSplit();
    void connectCutButtons();
    /// `snake` (0-based, -1: none) takes `chain`, the curve embedded along it, as its polyline.
    void afterMeshCut(const nlohmann::json &session, const vcg::tri::CutPointMap &map, int snake = -1,
                      const std::vector<vcg::tri::SurfacePoint> &chain = {});
    // the undo of cuts and splits (edit_geometric_snake_cut.cpp): MeshLab 2020.09 has no mesh
    // undo, so the tool keeps the mesh before a cut (vcg_ext/session/mesh_undo.h) and the layers
    // a split added; Ctrl+Z reaches them in order with the session's own steps
    typedef vcg::tri::SnakeMeshUndo<CMeshO, Controller::KeptHistory> CutUndo;
    CutUndo cutUndo;
    int cutGeneration = 0;     // cuts made and not undone: orders the splits with them
    long cutRedoRevision = -1; // the session's revision right after a cut's undo: its redo holds until it changes
    struct SplitStep
    {
        int inside, outside;  // the layers' ids
        int cutGeneration;
        size_t sessionSteps;  // the session's undo steps then, and the newest one's label
        std::string sessionLabel;
    };
    std::vector<SplitStep> splitSteps;
    bool undoRedoHostStep(bool redo);
    void keepCut(std::unique_ptr<CMeshO> before, const std::string &why, const nlohmann::json &session,
                 const std::string &label, bool dropSelectionStep);
    void dropHostSteps();
    void usePickPoints();
    vcg::tri::SnakeParams paramsFromDock() const;
    void paramsToDock(const vcg::tri::SnakeParams &p);

    // drawing (edit_snake_draw.cpp)
    void drawAll(MeshModel &m);
    // closed snakes: ticks on the inside (edit_snake_side_marks.cpp)
    void drawInsideMarks(const Controller::Snake &s, double lift, float dpr, const unsigned char *colour);
};

#endif
