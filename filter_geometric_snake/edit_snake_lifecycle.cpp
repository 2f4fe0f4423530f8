// The edit tool's end and restart (issue 37, see edit_snake_lifecycle.h): it ends cleanly when
// MeshLab ends it (a filter or its dialog, closing the document) or the user does: the session
// is saved (on the mesh and in the sidecar file), the undo history kept for the mesh, and the
// Log says so; the next start on the same mesh takes the history back, or says why it cannot.

#include <GL/glew.h>

#include "edit_geometric_snake.h"
#include "edit_snake_lifecycle.h"
#include "snake_dock.h"

#include <QAction>
#include <QFileInfo>

#include <meshlab/glarea.h>
#include <vcg_ext/session/mesh_fingerprint.h>
#include <vcg_ext/session/mesh_store.h>

using vcg::tri::SnakeMeshFingerprint;

// ====================================================================== the keeper
void SnakeHistoryKeeper::Keep(MeshDocument &doc, MeshModel &m, History h, const std::string &session)
{
    watch(doc);
    store.Keep(Key(&doc, m.id()), std::move(h), SnakeMeshFingerprint::Of(m.cm), session);
}

SnakeHistoryKeeper::Store::Outcome SnakeHistoryKeeper::Take(MeshDocument &doc, MeshModel &m, const std::string &session,
                                                            History &out, std::string &why)
{
    const Key key(&doc, m.id());
    if (!store.Has(key)) return Store::Outcome::None;
    return store.Take(key, SnakeMeshFingerprint::Of(m.cm), session, out, why);
}

void SnakeHistoryKeeper::watch(MeshDocument &doc)
{
    if (!watched.insert(&doc).second) return;
    const MeshDocument *d = &doc;
    connect(&doc, &MeshDocument::meshSetChanged, this, [this, &doc] { sweep(doc); });
    connect(&doc, &QObject::destroyed, this, [this, d] {
        store.DropIf([d](const Key &k) { return k.first == d; });
        watched.erase(d);
    });
}

void SnakeHistoryKeeper::sweep(MeshDocument &doc)
{
    std::set<int> live;
    for (MeshModel *m : gs::host::Meshes(doc)) live.insert(m->id());
    store.DropIf([&](const Key &k) { return k.first == &doc && !live.count(k.second); });
}

// ====================================================================== the tool's end
void EditGeometricSnakePlugin::stop(bool save)
{
    setRunning(false);
    redrawLater.stop();
    if (faceGridReady.valid()) faceGridReady.wait(); // it reads the mesh MeshLab may now change
    faceGrid.reset();
    keptSteps = 0;
    if (ctl && save && modelAlive()) {
        try {
            const std::string session = ctl->ToJson().dump();
            vcg::tri::SnakeMeshStore<CMeshO>::Set(model->cm, session);
            keepHistory(session);
            ctl->Autosave(true);
        } catch (const std::exception &e) {
            report(QString("Geometric snake: saving the session failed: %1").arg(e.what()), true);
        }
    }
    ctl.reset();
    model = nullptr;
    currentSample = -1;
    pressed = stroking = false;
    dragSample = -1;
    stroke.clear();
    refreshDock(); // nothing stays enabled that would act on a mesh the tool left
}

/// Hands the undo history to the keeper (the session is `session`, just stored on the mesh).
void EditGeometricSnakePlugin::keepHistory(const std::string &session)
{
    if (!keeper || !doc || (!ctl->CanUndo() && !ctl->CanRedo())) return;
    const size_t steps = ctl->UndoSteps();
    keeper->Keep(*doc, *model, ctl->TakeHistory(), session);
    keptSteps = int(steps);
}

/// Both endEdit overloads (MeshLab calls both, document then mesh): the first ends the tool.
void EditGeometricSnakePlugin::endTool()
{
    const bool active = ctl && modelAlive();
    const QString label = active ? model->label() : QString();
    const QString sidecar = active ? QString::fromStdString(ctl->AutosavePath()) : QString();
    // The user ends the tool with its button (the action is unchecked by then); MeshLab ends it
    // when a filter starts or the document closes (still checked, or suspended with Esc).
    QAction *a = glArea ? glArea->getCurrentEditAction() : nullptr;
    const bool byUser = a && !a->isChecked() && !glArea->suspendedEditor;
    // the cuts' and splits' steps hold this mesh as it was: they do not outlive the tool
    const bool hadCutSteps = cutUndo.CanUndo() || cutUndo.CanRedo() || !splitSteps.empty();
    dropHostSteps();
    if (active && hadCutSteps)
        Log(GLLogStream::FILTER, "Geometric snake: the undo of the cuts and splits made on %s ends with the tool.",
            qUtf8Printable(label));
    stop(true);
    ownKeys(false);
    hideDockLater();
    if (!active || switchingLayer) return; // a layer switch restarts the tool at once
    QString msg = byUser ? QString("Geometric snake: the tool ended on %1").arg(label)
                         : QString("Geometric snake: MeshLab ended the tool on %1 (it ends edit tools when a filter or "
                                   "its dialog starts, or the document closes)").arg(label);
    msg += sidecar.isEmpty() ? QString("; the session is kept on the mesh")
                             : QString("; the session is saved to %1").arg(QFileInfo(sidecar).fileName());
    if (keptSteps > 0)
        msg += QString("; its undo history (%1 step%2) is kept until the mesh is closed: start the tool again and "
                       "Ctrl+Z goes on")
                   .arg(keptSteps)
                   .arg(keptSteps == 1 ? "" : "s");
    Log(GLLogStream::FILTER, "%s.", qUtf8Printable(msg));
}

void EditGeometricSnakePlugin::endEdit(MeshModel &, GLArea *, MLSceneGLSharedDataContext *) { endTool(); }

void EditGeometricSnakePlugin::endEdit(MeshDocument &, GLArea *, MLSceneGLSharedDataContext *) { endTool(); }

void EditGeometricSnakePlugin::layerChanged(MeshDocument &md, MeshModel &old, GLArea *gla, MLSceneGLSharedDataContext *cont)
{
    switchingLayer = true;
    endEdit(old, gla, cont);
    startEdit(md, gla, cont);
    switchingLayer = false;
}

// ====================================================================== the next start
/// Takes back the history kept for `m` (startOn, once the session is restored: `stored` is the
/// session text found on the mesh), or says in the Log why it was dropped.
void EditGeometricSnakePlugin::resumeHistory(MeshModel &m, const std::string &stored)
{
    if (!keeper || !doc || !ctl) return;
    SnakeHistoryKeeper::History h;
    std::string why;
    switch (keeper->Take(*doc, m, stored, h, why)) {
    case SnakeHistoryKeeper::Store::Outcome::None: return;
    case SnakeHistoryKeeper::Store::Outcome::Dropped:
        Log(GLLogStream::WARNING, "Geometric snake: the undo history of %s was dropped: %s.", qUtf8Printable(m.label()),
            why.c_str());
        return;
    case SnakeHistoryKeeper::Store::Outcome::Taken: {
        ctl->AdoptHistory(std::move(h));
        if (switchingLayer) return; // back on a layer after a layer switch: no news
        const int n = int(ctl->UndoSteps());
        const std::string next = n > 0 ? "Ctrl+Z undoes the " + ctl->UndoLabel() : "Ctrl+Y redoes the " + ctl->RedoLabel();
        Log(GLLogStream::FILTER, "Geometric snake: the undo history of %s is back (%d step%s; %s).",
            qUtf8Printable(m.label()), n, n == 1 ? "" : "s", next.c_str());
        return;
    }
    }
}
