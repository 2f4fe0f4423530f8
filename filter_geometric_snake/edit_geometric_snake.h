#ifndef GS_EDIT_GEOMETRIC_SNAKE_H
#define GS_EDIT_GEOMETRIC_SNAKE_H

// MeshLab edit tool "Geometric Snake": interactive geometric snakes (Lee & Lee 2002,
// Sec. 5.5 and 7) on the current layer. Thin Qt/GL glue over vcg_ext/snake_controller.h.
//
// Environment hook for scripted GUI tests: GS_SNAKE_AUTOEXPORT=<file.json> makes the tool
// write all its snakes (vcg_ext/snake_io.h JSON) to that file after every change.

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <QObject>
#include <QPointer>
#include <QTimer>

#include <common/interfaces.h>
#include <vcg/space/index/grid_static_ptr.h>
#include <memory>
#include <vcg_ext/snake_controller.h>

class SnakeDock;

class EditGeometricSnakePlugin : public QObject, public MeshEditInterface
{
    Q_OBJECT
    Q_INTERFACES(MeshEditInterface)

public:
    typedef vcg::tri::SnakeController<CMeshO> Controller;

    EditGeometricSnakePlugin();
    virtual ~EditGeometricSnakePlugin();

    static const QString Info();

    bool StartEdit(MeshDocument &md, GLArea *gla, MLSceneGLSharedDataContext *cont) override;
    bool StartEdit(MeshModel &m, GLArea *gla, MLSceneGLSharedDataContext *cont) override;
    void EndEdit(MeshModel &m, GLArea *gla, MLSceneGLSharedDataContext *cont) override;
    void EndEdit(MeshDocument &md, GLArea *gla, MLSceneGLSharedDataContext *cont) override;
    void Decorate(MeshModel &m, GLArea *gla, QPainter *p) override;
    void mousePressEvent(QMouseEvent *e, MeshModel &m, GLArea *gla) override;
    void mouseMoveEvent(QMouseEvent *e, MeshModel &m, GLArea *gla) override;
    void mouseReleaseEvent(QMouseEvent *e, MeshModel &m, GLArea *gla) override;
    void keyPressEvent(QKeyEvent *e, MeshModel &m, GLArea *gla) override;

private slots:
    void runTick();

private:
    // state of the session
    std::unique_ptr<Controller> ctl;
    MeshModel *model = nullptr;
    MeshDocument *doc = nullptr;
    GLArea *glArea = nullptr;
    MLSceneGLSharedDataContext *shared = nullptr;
    QPointer<SnakeDock> dock;
    QTimer runTimer;
    long exportedRevision = -1;
    long storedRevision = -1;
    int currentSample = -1;
    std::string lastError;

    // cached view (from the last Decorate) for exact picking
    double M[16];         // projection * modelview * mesh transform (column-major, like GL)
    double Minv[16];
    int viewport[4] = {0, 0, 1, 1};
    bool viewValid = false;

    // mouse
    bool pressed = false;
    QPoint pressPos;
    bool stroking = false;
    std::vector<vcg::tri::SurfacePoint> stroke;
    int dragSample = -1;
    bool dragMoved = false;
    vcg::tri::SurfacePoint dragTarget;

    bool startOn(MeshModel &m);
    void stop(bool save);
    bool modelAlive() const;
    std::vector<vcg::tri::ProtectedFile> protectedFiles() const; // never overwritten by exports
    void connectDock();
    void refreshDock();
    void afterChange(bool forceSave = false);
    void report(const QString &msg, bool error);
    template <class F> bool guarded(const QString &what, F f);

    // picking
    bool pick(const QPointF &glPos, vcg::tri::SurfacePoint &sp, vcg::Point3d &xyz);
    std::unique_ptr<vcg::GridStaticPtr<CFaceO, Scalarm>> pickGrid; // built on the first click
    size_t pickGridFaces = 0;
    const CMeshO *pickGridMesh = nullptr;
    bool project(const vcg::Point3d &p, vcg::Point3d &screen) const;
    int nearestSampleOnScreen(const QPointF &glPos, int &snake, double radiusPx);
    int nearestSeedOnScreen(const QPointF &glPos, double radiusPx);
    QPointF glPos(QMouseEvent *e, GLArea *gla) const;

    // actions
    void buildSnake(bool closed);
    void stepOnce();
    void setRunning(bool on);
    void applyParams();
    void computeEnergy(bool show);
    void exportCurves(bool all);
    void addAsLayer();
    void usePickPoints();
    vcg::tri::SnakeParams paramsFromDock() const;
    void paramsToDock(const vcg::tri::SnakeParams &p);

    // drawing
    void drawAll(MeshModel &m);
};

#endif
