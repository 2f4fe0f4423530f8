#include <GL/glew.h>

#include "edit_geometric_snake.h"

#include <vcg_ext/session/mesh_store.h>
#include <vcg/complex/algorithms/closest.h>
#include <vcg/space/index/grid_static_ptr.h>
#include <Eigen/Dense>
#include "snake_dock.h"

#include <cmath>

#include <QComboBox>
#include <QFile>
#include <QFileInfo>
#include <QMainWindow>

#include <meshlab/glarea.h>

using namespace vcg;
using vcg::tri::SnakeError;
using vcg::tri::SnakeParams;
using vcg::tri::SurfacePoint;

EditGeometricSnakePlugin::EditGeometricSnakePlugin(SnakeHistoryKeeper *k) : keeper(k)
{
    runTimer.setInterval(0);
    connect(&runTimer, SIGNAL(timeout()), this, SLOT(runTick()));
    redrawLater.setSingleShot(true);
    redrawLater.setInterval(800);
    connect(&redrawLater, &QTimer::timeout, this, [this] {
        if (glArea) glArea->update();
    });
    for (int i = 0; i < 16; ++i) M[i] = Minv[i] = (i % 5 == 0) ? 1 : 0;
}

EditGeometricSnakePlugin::~EditGeometricSnakePlugin()
{
    ownKeys(false);
    runTimer.stop();
    if (ctl && modelAlive()) stop(true);
    if (dock) dock->savePlace();
    delete dock.data();
}

const QString EditGeometricSnakePlugin::Info()
{
    return tr("Geometric snakes (Lee & Lee 2002): place seeds on the surface and let a snake slither onto a feature curve; "
              "edit, pin, export.");
}

// ====================================================================== start / end
bool EditGeometricSnakePlugin::startEdit(MeshDocument &md, GLArea *gla, MLSceneGLSharedDataContext *cont)
{
    doc = &md;
    glArea = gla;
    shared = cont;
    // MeshLab gives an edit tool its Log only when it first draws: without this, what the tool
    // says while starting (an unreadable sidecar, a mesh it cannot work on) would be lost
    setLog(&md.Log);
    if (md.mm() == nullptr) return false;
    if (md.isBusy()) return false; // MeshLab is still loading or filtering the mesh
    keepModifiedFlag(*md.mm());
    return startOn(*md.mm());
}

bool EditGeometricSnakePlugin::startEdit(MeshModel &m, GLArea *gla, MLSceneGLSharedDataContext *cont)
{
    glArea = gla;
    shared = cont;
    return startOn(m);
}

bool EditGeometricSnakePlugin::startOn(MeshModel &m)
{
    if (ctl) stop(true);
    QMainWindow *mw = glArea ? qobject_cast<QMainWindow *>(glArea->window()) : nullptr;
    if (!dock) {
        dock = new SnakeDock(mw ? static_cast<QWidget *>(mw) : glArea);
        connectDock();
    }
    {
        // in its own dock area, or beside MeshLab's layer dialog (which holds the Log)
        QDockWidget *layers = nullptr;
        if (mw)
            for (QDockWidget *d : mw->findChildren<QDockWidget *>())
                if (d != dock && d->inherits("LayerDialog")) layers = d;
        // a layer switch ends and restarts the tool: the panel stays where it is then (it
        // does not jump over the layer dialog the user is clicking in)
        hidePending = false;
        const bool first = !dock->isVisible();
        if (first) dock->dockInto(mw, layers);
        if (first && mw) QTimer::singleShot(400, this, [this, layers = QPointer<QDockWidget>(layers)] { logLayout(layers); });
    }
    shownSuspended = glArea && glArea->suspendedEditor; // a layer switch keeps MeshLab's Esc state
    showSuspended();
    ownKeys(true);
    refreshDock();
    lastError.clear(); // a new start: its problems go to the Log again
    if (m.cm.fn < 1) {
        report("Geometric snake: the current layer has no faces; select a triangle mesh layer.", true);
        return true; // keep the panel, the user may switch layers
    }
    try {
        // vcglib's adjacency asserts (aborting MeshLab) on faces that repeat a vertex: check first
        vcg::tri::MeshValidation<CMeshO>::RequireSurface(m.cm);
        vcg::tri::MeshValidation<CMeshO>::RequireAdjacencySafe(m.cm);
    } catch (const std::exception &e) {
        report(QString("Geometric snake: %1").arg(e.what()), true);
        return true; // keep the panel: the user can clean the mesh and restart the tool
    }
    try {
        m.updateDataMask(MeshModel::MM_FACEFACETOPO | MeshModel::MM_VERTFACETOPO | MeshModel::MM_VERTMARK |
                         MeshModel::MM_FACEMARK);
    } catch (...) {
        report("Geometric snake: cannot enable the mesh adjacency.", true);
        return false;
    }
    model = &m;
    ctl.reset(new Controller(m.cm));
    currentSample = -1;
    exportedRevision = storedRevision = -1;
    const std::string meshPath = m.fullName().isEmpty() ? std::string() : QFileInfo(m.fullName()).absoluteFilePath().toStdString();

    QString restored, sidecarProblem;
    bool restoredFromFile = false;
    try {
        ctl->SetEnergySettings(vcg::tri::FeatureEnergyType(dock->energyType->currentIndex()), dock->smoothing->value());
    } catch (const SnakeError &) {
    }
    const std::string stored = vcg::tri::SnakeMeshStore<CMeshO>::Get(m.cm);
    bool fromStore = false;
    if (!stored.empty()) {
        try {
            ctl->FromJson(nlohmann::json::parse(stored));
            restored = "Restored the snakes kept on this mesh.";
            fromStore = true;
        } catch (const std::exception &e) {
            report(QString("Geometric snake: could not restore the session: %1").arg(e.what()), true);
        }
    }
    // The sidecar: restored if the mesh kept no snakes; never overwritten when unreadable (the
    // session then autosaves to a new recovery file, see SnakeController::OpenSidecar).
    const Controller::SidecarStatus side = ctl->OpenSidecar(meshPath, !fromStore);
    if (side.restored) {
        restored = QString::fromStdString(side.message);
        restoredFromFile = true;
    }
    if (side.unreadable) sidecarProblem = QString("Geometric snake: %1").arg(QString::fromStdString(side.message));
    if (!meshPath.empty() && !side.restored && !fromStore) {
        // the session file is "<mesh file>.snakes.json"; an older README said "<mesh>.snakes.json":
        // a file of that name may belong to another mesh of the same base name, so it is not read
        const QFileInfo mf(QString::fromStdString(meshPath));
        const QString other = mf.absolutePath() + "/" + mf.completeBaseName() + ".snakes.json";
        if (QFileInfo::exists(other) && other != QString::fromStdString(meshPath) + ".snakes.json")
            Log(GLLogStream::WARNING, "Geometric snake: %s is not read: this mesh's session file is %s.snakes.json "
                "(rename it to that to restore it).", qUtf8Printable(QFileInfo(other).fileName()),
                qUtf8Printable(mf.fileName()));
    }
    // a restored session brings its parameters even when it holds only seeds so far
    if (ctl->SnakeCount() > 0 || side.restored || fromStore) {
        paramsToDock(ctl->Params());
        dock->energyType->setCurrentIndex(int(ctl->EnergyType()));
        dock->smoothing->setValue(ctl->EnergySmoothing());
    } else {
        try { ctl->SetParams(paramsFromDock()); } catch (const SnakeError &) {}
    }
    resumeHistory(m, stored); // the undo history kept when the tool last left this mesh (edit_snake_lifecycle.cpp)
    (ctl->SnakeCount() > 0 ? dock->editMode : dock->seedMode)->setChecked(true);
    // what the first click and the first Build need, made while the user places seeds
    ctl->PrepareInBackground();
    preparePickGrid();
    refreshDock();
    if (!sidecarProblem.isEmpty()) report(sidecarProblem, true); // stays in the status line, and goes to the Log
    else if (!restored.isEmpty()) report(restored, false);
    else report(QString("Click on %1 to place seeds, then press Enter (open) or Shift+Enter (closed).").arg(m.label()), false);
    // the snakes kept on the mesh come back silently on every layer switch; a file is news
    if (restoredFromFile) Log(GLLogStream::FILTER, "Geometric snake: %s", restored.toStdString().c_str());
    if (glArea) glArea->update();
    return true;
}

bool EditGeometricSnakePlugin::modelAlive() const
{
    if (!model) return false;
    if (!doc) return true;
    return gs::host::HasMesh(*doc, model);
}

/// Hides the panel once control returns to the event loop, unless the tool started again
/// meanwhile (MeshLab's layer switch is endEdit + startEdit).
void EditGeometricSnakePlugin::hideDockLater()
{
    hidePending = true;
    QTimer::singleShot(0, this, [this] {
        if (hidePending && dock) {
            dock->savePlace(); // its width, for the next session
            dock->hide();
        }
        hidePending = false;
    });
}

// ====================================================================== helpers
std::vector<vcg::tri::ProtectedFile> EditGeometricSnakePlugin::protectedFiles() const
{
    if (!modelAlive() || model->fullName().isEmpty()) return {};
    return tri::SnakeSidecar::ProtectedFiles(QFileInfo(model->fullName()).absoluteFilePath().toStdString(),
                                        model->label().toStdString());
}

void EditGeometricSnakePlugin::report(const QString &msg, bool error)
{
    showStatus(msg, error);
    if (error) {
        if (msg.toStdString() != lastError) Log(GLLogStream::WARNING, "%s", msg.toStdString().c_str());
        lastError = msg.toStdString();
    }
}

template <class F>
bool EditGeometricSnakePlugin::guarded(const QString &what, F f)
{
    if (!ctl || !modelAlive()) {
        report("Geometric snake: no mesh (select a mesh layer and start the tool again).", true);
        return false;
    }
    try {
        f();
        return true;
    } catch (const SnakeError &e) {
        report(QString::fromStdString(e.what()), true);
    } catch (const std::exception &e) {
        report(QString("Geometric snake: %1 failed: %2").arg(what, e.what()), true);
    } catch (...) {
        report(QString("Geometric snake: %1 failed.").arg(what), true);
    }
    refreshDock();
    if (glArea) glArea->update();
    return false;
}

bool EditGeometricSnakePlugin::guardedFn(const QString &what, const std::function<void()> &f) { return guarded(what, f); }

void EditGeometricSnakePlugin::afterChange(bool forceSave)
{
    if (!ctl) return;
    static const char *autoExport = getenv("GS_SNAKE_AUTOEXPORT");
    if (autoExport && *autoExport && ctl->Revision() != exportedRevision && ctl->SnakeCount() > 0) {
        try {
            ctl->Export(autoExport, true, protectedFiles());
            exportedRevision = ctl->Revision();
        } catch (const std::exception &e) {
            report(QString("Geometric snake: auto-export failed: %1").arg(e.what()), true);
        }
    }
    try {
        if (ctl->Autosave(forceSave) || (forceSave && storedRevision != ctl->Revision())) {
            vcg::tri::SnakeMeshStore<CMeshO>::Set(model->cm, ctl->ToJson().dump());
            storedRevision = ctl->Revision();
        }
    } catch (const std::exception &e) {
        report(QString("Geometric snake: autosave failed: %1").arg(e.what()), true);
        ctl->SetAutosave(std::string()); // do not retry on every operation
    }
    refreshDock();
    if (glArea && !quickShow) glArea->update();
}

SnakeParams EditGeometricSnakePlugin::paramsFromDock() const
{
    SnakeParams p = ctl ? ctl->Params() : SnakeParams();
    p.alpha = dock->alpha->value();
    p.beta = dock->beta->value();
    p.gamma = dock->gamma->value();
    p.externalWeight = dock->external->value();
    p.balloon = dock->balloon->value();
    p.spacing = dock->spacing->value();
    return p;
}

void EditGeometricSnakePlugin::paramsToDock(const SnakeParams &p)
{
    QDoubleSpinBox *boxes[] = {dock->alpha, dock->beta, dock->gamma, dock->external, dock->balloon, dock->spacing};
    double vals[] = {p.alpha, p.beta, p.gamma, p.externalWeight, p.balloon, p.spacing};
    for (int i = 0; i < 6; ++i) {
        QSignalBlocker b(boxes[i]);
        boxes[i]->setValue(vals[i]);
    }
}

// ====================================================================== dock wiring
void EditGeometricSnakePlugin::connectDock()
{
    SnakeDock *d = dock;
    runLimitsToDock();
    auto clicked = [this, d](QPushButton *b, std::function<void()> f) { connect(b, &QPushButton::clicked, this, f); };
    clicked(d->buildOpen, [this] { buildSnake(false); });
    clicked(d->buildClosed, [this] { buildSnake(true); });
    clicked(d->completeLoop, [this] { completeLoop(); });
    clicked(d->removeLastSeed, [this] {
        if (guarded("remove seed", [&] { ctl->RemoveLastSeed(); })) afterChange();
    });
    clicked(d->clearSeeds, [this] {
        if (guarded("clear seeds", [&] { ctl->ClearSeeds(); })) afterChange();
    });
    clicked(d->useSelection, [this] {
        if (guarded("use selection", [&] { ctl->SeedsFromSelection(); })) {
            dock->seedMode->setChecked(true);
            afterChange();
            report(QString("%1 seeds from the selected vertices; press Enter to build the snake.").arg(ctl->Seeds().size()), false);
        }
    });
    clicked(d->usePickPoints, [this] { usePickPoints(); });
    connect(d->seedCost, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this](int i) {
        guarded("seed cost", [&] { ctl->SetSeedCost(vcg::tri::SeedPathCost(i)); });
    });
    clicked(d->computeEnergy, [this] { computeEnergy(false); });
    clicked(d->showEnergy, [this] { computeEnergy(true); });
    for (QDoubleSpinBox *s : {d->alpha, d->beta, d->gamma, d->external, d->balloon, d->spacing})
        connect(s, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, [this](double) { applyParams(); });
    clicked(d->step, [this] { stepOnce(); });
    connect(d->run, &QPushButton::toggled, this, [this](bool on) { setRunning(on); });
    // the panel-state hook (edit_snake_status.cpp) tells where the widgets moved and the limits typed
    connect(d, &SnakeDock::sectionToggled, this, [this] { refreshDock(); });
    connect(d->maxOperations, QOverload<int>::of(&QSpinBox::valueChanged), this, [this](int) { refreshDock(); });
    connect(d->timeLimit, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, [this](double) { refreshDock(); });
    clicked(d->pin, [this] { editCurrent("pin", [this] { ctl->TogglePin(currentSample); }); });
    clicked(d->insert, [this] { editCurrent("insert", [this] { currentSample = ctl->InsertSampleAfter(currentSample); }); });
    clicked(d->remove, [this] {
        editCurrent("delete", [this] {
            ctl->DeleteSample(currentSample);
            currentSample = -1;
        });
    });
    clicked(d->undo, [this] { undoRedo(false); });
    clicked(d->redo, [this] { undoRedo(true); });
    connect(d->snakeList, QOverload<int>::of(&QComboBox::activated), this, [this](int i) {
        if (guarded("select", [&] { setRunning(false); ctl->Select(i); currentSample = -1; })) {
            if (ctl->SelectedSnake()) paramsToDock(ctl->SelectedSnake()->Params());
            afterChange();
        }
    });
    clicked(d->newSnake, [this] {
        setRunning(false);
        dock->seedMode->setChecked(true);
        report("Place seeds for a new snake, then press Enter (open) or Shift+Enter (closed).", false);
    });
    clicked(d->deleteSnake, [this] {
        if (guarded("delete snake", [&] { setRunning(false); ctl->DeleteSnake(ctl->Selected()); currentSample = -1; }))
            afterChange(true);
    });
    clicked(d->exportSelected, [this] { exportCurves(false); });
    clicked(d->exportAll, [this] { exportCurves(true); });
    clicked(d->addLayer, [this] { addAsLayer(); });
    connectCutButtons();
    clicked(d->saveSession, [this] {
        if (ctl && ctl->AutosavePath().empty()) {
            report("Geometric snake: this layer has no file name, so there is no sidecar file; use Export all.", true);
            return;
        }
        if (guarded("save", [&] { ctl->Autosave(true); vcg::tri::SnakeMeshStore<CMeshO>::Set(model->cm, ctl->ToJson().dump()); }))
            report(QString("Saved %1").arg(QString::fromStdString(ctl->AutosavePath())), false);
    });
}
