// The edit tool's Cut section (issue 34): the selected snake selects one side of the mesh, cuts
// it open, or splits it into two new layers.
// - Select inside / outside embed the snake exactly (mode 1 of the issue: new vertices where it
//   crosses edges) and select the faces on one side; with "Whole faces only" they select the
//   user's faces by their centroid's side and leave the mesh as it was.
// - Cut open embeds it and makes its edges boundary edges, in this layer.
// - Split into layers adds two layers; this one is not changed.
// A selection that leaves the mesh's faces as they were is one step of the tool's undo (Ctrl+Z
// brings the selection before it back). A cut that changes the mesh moves the session's snakes
// onto the new faces (CutSessionMap) and starts the session afresh on the cut mesh. MeshLab
// 2020.09 has no undo for a mesh change: the tool keeps the mesh before the cut, the session and
// its history as one step of its own undo (SnakeMeshUndo), reached when the session after the cut
// has no step left to undo; a split's step removes the two layers it added. The session of the
// cut mesh is not the one of the file on disk: it autosaves to a recovery file beside it, the
// sidecar keeps the uncut file's session (SnakeController::OpenSidecar).

#include <GL/glew.h>

#include "edit_geometric_snake.h"
#include "snake_dock.h"

#include <QCheckBox>
#include <QFileInfo>
#include <QStringList>

#include <meshlab/glarea.h>
#include <vcg_ext/cut/cut_session_map.h>
#include <vcg_ext/cut/mesh_cut.h>
#include <vcg_ext/session/mesh_store.h>

using vcg::tri::CutCurve;
using vcg::tri::MeshCut;
using vcg::tri::SnakeError;

namespace {

/// The selected snake as a curve to cut along; throws when there is none.
CutCurve SelectedCurve(vcg::tri::SnakeController<CMeshO> &ctl)
{
    auto *s = ctl.SelectedSnake();
    if (!s) throw SnakeError("Geometric snake: no snake selected.");
    CutCurve c;
    c.points = s->Polyline();
    c.closed = s->Closed();
    return c;
}

} // namespace

void EditGeometricSnakePlugin::connectCutButtons()
{
    connect(dock->cutSelectInside, &QPushButton::clicked, this, [this] { cutSelect(true); });
    connect(dock->cutSelectOutside, &QPushButton::clicked, this, [this] { cutSelect(false); });
    connect(dock->cutSplit, &QPushButton::clicked, this, [this] { cutSplit(); });
    connect(dock->cutOpen, &QPushButton::clicked, this, [this] { cutOpen(); });
}

void EditGeometricSnakePlugin::cutSelect(bool inside)
{
    setRunning(false);
    if (!ctl || !modelAlive()) { report("Geometric snake: no mesh.", true); return; }
    const bool wholeFaces = dock->cutWholeFaces->isChecked();
    try {
        MeshCut<CMeshO>::Param p;
        p.mode = wholeFaces ? vcg::tri::CutMode::SelectOnly : vcg::tri::CutMode::Select;
        p.side = inside ? vcg::tri::CutSide::Inside : vcg::tri::CutSide::Outside;
        const nlohmann::json session = ctl->ToJson(); // for the snakes, if the cut adds faces
        const int snake = ctl->Selected() + 1;
        // the cut planned first: the mesh is copied for the undo only when it will change (a
        // snake along its embedded curve changes the selection alone, undone as one below)
        MeshCut<CMeshO>::Planned plan = MeshCut<CMeshO>::Plan(model->cm, {SelectedCurve(*ctl)}, p);
        std::string why;
        std::unique_ptr<CMeshO> before = plan.ChangesMesh() ? cutUndo.Snapshot(model->cm, why) : nullptr;
        MeshCut<CMeshO>::Result r;
        // one step of the tool's undo (Ctrl+Z brings the selection before it back)
        ctl->ChangeSelection(inside ? "select inside" : "select outside",
                             [&] { r = MeshCut<CMeshO>::Apply(model->cm, std::move(plan)); });
        QString msg = QString("Selected the %1 of snake %2: %3 faces (area %4 of %5)%6.")
                          .arg(inside ? "inside" : "outside")
                          .arg(snake)
                          .arg(r.facesInside)
                          .arg(r.areaInside)
                          .arg(r.areaInside + r.areaOutside)
                          .arg(wholeFaces ? ", whole faces by their centroid" : "");
        if (r.addedVertices > 0 || r.addedFaces > 0) {
            msg += QString(" The snake was embedded into the mesh: %1 vertices and %2 faces added; the session goes on "
                           "on the cut mesh%3.")
                       .arg(r.addedVertices)
                       .arg(r.addedFaces)
                       .arg(before ? " (Ctrl+Z undoes the cut)" : "");
            keepCut(std::move(before), why, session, inside ? "select inside" : "select outside", true);
            afterMeshCut(session, r.points, snake - 1, r.chains.empty() ? std::vector<vcg::tri::SurfacePoint>() : r.chains[0]);
        } else {
            cutUndo.ClearRedo(); // a new action
            if (glArea) glArea->updateSelection(model->id(), true, true);
        }
        report(msg, false);
        Log(GLLogStream::FILTER, "Geometric snake: %s", qUtf8Printable(msg));
    } catch (const std::exception &e) {
        report(QString::fromStdString(e.what()), true);
    }
    if (glArea) glArea->update();
}

void EditGeometricSnakePlugin::cutOpen()
{
    setRunning(false);
    if (!ctl || !modelAlive()) { report("Geometric snake: no mesh.", true); return; }
    try {
        MeshCut<CMeshO>::Param p;
        p.mode = vcg::tri::CutMode::CutOpen;
        const nlohmann::json session = ctl->ToJson();
        const int snake = ctl->Selected() + 1;
        // planned first: a refused cut throws before the mesh is copied for the undo
        MeshCut<CMeshO>::Planned plan = MeshCut<CMeshO>::Plan(model->cm, {SelectedCurve(*ctl)}, p);
        std::string why;
        std::unique_ptr<CMeshO> before = cutUndo.Snapshot(model->cm, why);
        const MeshCut<CMeshO>::Result r = MeshCut<CMeshO>::Apply(model->cm, std::move(plan));
        const QString msg = QString("Cut open along snake %1: its %2 vertices on the mesh are on the boundary now "
                                    "(%3 vertices and %4 faces added); the session goes on on the cut mesh%5.")
                                .arg(snake)
                                .arg(r.curveVertices)
                                .arg(r.addedVertices)
                                .arg(r.addedFaces)
                                .arg(before ? " (Ctrl+Z undoes the cut)" : "");
        keepCut(std::move(before), why, session, "cut open", false);
        afterMeshCut(session, r.points);
        report(msg, false);
        Log(GLLogStream::FILTER, "Geometric snake: %s", qUtf8Printable(msg));
    } catch (const std::exception &e) {
        report(QString::fromStdString(e.what()), true);
    }
    if (glArea) glArea->update();
}

void EditGeometricSnakePlugin::afterMeshCut(const nlohmann::json &session, const vcg::tri::CutPointMap &map, int snake,
                                            const std::vector<vcg::tri::SurfacePoint> &chain)
{
    MeshModel *m = model;
    const nlohmann::json mapped = vcg::tri::CutSessionMap<CMeshO>::Map(session, map, m->cm);
    stop(false); // the session before the cut refers to faces that changed
    vcg::tri::UpdateTopology<CMeshO>::FaceFace(m->cm);
    vcg::tri::UpdateTopology<CMeshO>::VertexFace(m->cm);
    gs::host::UpdateBoxAndNormals(*m);
    if (shared && glArea) {
        shared->meshAttributesUpdated(m->id(), true, MLRenderingData::RendAtts(true));
        shared->manageBuffers(m->id());
    }
    // the session, its snakes on the new faces, comes back from the mesh (as on a layer switch)
    vcg::tri::SnakeMeshStore<CMeshO>::Set(m->cm, mapped.dump());
    startOn(*m);
    // the snake cut along runs on the embedded curve: selecting along it again adds nothing
    if (ctl && snake >= 0) vcg::tri::CutSessionMap<CMeshO>::KeepCurve(*ctl, snake, chain, m->cm);
    if (glArea) glArea->updateSelection(m->id(), true, true);
    // the sidecar belongs to the file on disk, which is the uncut mesh: it keeps that session
    const QString file = m->fullName();
    if (ctl && !file.isEmpty() && !ctl->AutosavePath().empty())
        Log(GLLogStream::FILTER,
            "Geometric snake: the cut mesh is not the file %s on disk: its session is saved to %s, and %s.snakes.json "
            "keeps the session of the uncut file. To keep the cut mesh's session with it, save the mesh (File > Save "
            "As) and rename that file to <new mesh file>.snakes.json.",
            qUtf8Printable(QFileInfo(file).fileName()), qUtf8Printable(QString::fromStdString(ctl->AutosavePath())),
            qUtf8Printable(QFileInfo(file).fileName()));
}

/// Makes the cut about to be applied one step of the tool's undo: `before` the mesh before it
/// (nullptr: it could not be kept, `why` says why), `session` the session then, with its history
/// (less the step the cut's own selection recorded, `dropSelectionStep`). Called once the cut is
/// made: the session's file gets the session before it (the sidecar must hold the uncut mesh's).
void EditGeometricSnakePlugin::keepCut(std::unique_ptr<CMeshO> before, const std::string &why,
                                       const nlohmann::json &session, const std::string &label, bool dropSelectionStep)
{
    try {
        // the session before the cut (the controller's is on the cut faces already)
        if (!ctl->AutosavePath().empty()) vcg::tri::SafeFileWrite::Write(ctl->AutosavePath(), session.dump(1) + "\n");
    } catch (const std::exception &e) {
        Log(GLLogStream::WARNING, "Geometric snake: saving the session before the cut failed: %s", e.what());
    }
    Controller::KeptHistory h = ctl->TakeHistory();
    if (dropSelectionStep) h.DropLast(); // the cut's selection, on faces that are gone
    h.ClearRedo();
    if (!before) {
        dropHostSteps();
        Log(GLLogStream::WARNING, "Geometric snake: this cut cannot be undone: %s; the undo history before it is "
            "dropped.", why.c_str());
        return;
    }
    cutUndo.Push(std::move(before), session.dump(), std::move(h), label);
    ++cutGeneration;
    cutRedoRevision = -1;
}

/// Drops the cut and split steps (the tool leaves the mesh, or a cut cannot be kept).
void EditGeometricSnakePlugin::dropHostSteps()
{
    cutUndo.Clear();
    splitSteps.clear();
    cutGeneration = 0;
    cutRedoRevision = -1;
}

/// Ctrl+Z / Ctrl+Y of a split or a cut, when it is the next step (the session's own steps after
/// it come first): true if it did one (or said why not).
bool EditGeometricSnakePlugin::undoRedoHostStep(bool redo)
{
    if (!ctl || !modelAlive() || (doc && doc->isBusy())) return false;
    if (!redo && !splitSteps.empty()) {
        const SplitStep s = splitSteps.back();
        if (s.cutGeneration == cutGeneration && s.sessionSteps == ctl->UndoSteps() && s.sessionLabel == ctl->UndoLabel()) {
            splitSteps.pop_back();
            QStringList removed;
            for (int id : {s.inside, s.outside})
                for (MeshModel *mm : gs::host::Meshes(*doc))
                    if (mm->id() == id && mm != model) {
                        removed << mm->label();
                        gs::host::DeleteLayer(*doc, mm);
                        break;
                    }
            const QString msg = QString("Undid the split: removed the layers %1 (Ctrl+Y does not add them back: split "
                                        "again).")
                                    .arg(removed.isEmpty() ? QString("(none left)") : "\"" + removed.join("\", \"") + "\"");
            report(msg, false);
            Log(GLLogStream::FILTER, "Geometric snake: %s", qUtf8Printable(msg));
            if (glArea) glArea->update();
            return true;
        }
    }
    const bool due = redo ? !ctl->CanRedo() && cutUndo.CanRedo() && ctl->Revision() == cutRedoRevision
                          : !ctl->CanUndo() && cutUndo.CanUndo();
    if (!due) return false;
    MeshModel *m = model;
    const std::string label = redo ? cutUndo.RedoLabel() : cutUndo.UndoLabel();
    std::string session = ctl->ToJson().dump();
    try {
        ctl->Autosave(true); // the session as it is now, to its file, before the mesh changes
    } catch (const std::exception &e) {
        Log(GLLogStream::WARNING, "Geometric snake: saving the session failed: %s", e.what());
    }
    Controller::KeptHistory h = ctl->TakeHistory();
    stop(false);
    if (!(redo ? cutUndo.Redo(m->cm, session, h) : cutUndo.Undo(m->cm, session, h))) return false;
    cutGeneration += redo ? 1 : -1;
    vcg::tri::UpdateTopology<CMeshO>::FaceFace(m->cm);
    vcg::tri::UpdateTopology<CMeshO>::VertexFace(m->cm);
    vcg::tri::UpdateBounding<CMeshO>::Box(m->cm);
    if (shared && glArea) {
        shared->meshAttributesUpdated(m->id(), true, MLRenderingData::RendAtts(true));
        shared->manageBuffers(m->id());
    }
    vcg::tri::SnakeMeshStore<CMeshO>::Set(m->cm, session);
    startOn(*m);
    if (ctl) ctl->AdoptHistory(std::move(h));
    cutRedoRevision = !redo && ctl ? ctl->Revision() : -1;
    if (glArea) glArea->updateSelection(m->id(), true, true);
    refreshDock();
    const QString msg = QString("%1 the cut (%2): the mesh has %3 vertices and %4 faces%5.")
                            .arg(redo ? "Redid" : "Undid", QString::fromStdString(label))
                            .arg(m->cm.vn)
                            .arg(m->cm.fn)
                            .arg(redo ? "" : " as before it, with its snakes");
    report(msg, false);
    Log(GLLogStream::FILTER, "Geometric snake: %s", qUtf8Printable(msg));
    if (glArea) glArea->update();
    return true;
}

void EditGeometricSnakePlugin::cutSplit()
{
    setRunning(false);
    if (!ctl || !modelAlive() || !doc) { report("Geometric snake: no mesh.", true); return; }
    CMeshO inside, outside;
    MeshCut<CMeshO>::Result r;
    try {
        r = MeshCut<CMeshO>::Split(model->cm, {SelectedCurve(*ctl)}, MeshCut<CMeshO>::Param(), inside, outside);
    } catch (const std::exception &e) {
        report(QString::fromStdString(e.what()), true);
        return;
    }
    const QString base = QFileInfo(model->label()).completeBaseName();
    MeshModel *src = model;
    int ids[2] = {-1, -1};
    for (int part = 0; part < 2; ++part) {
        const QString label = QString("%1 %2").arg(base, part == 0 ? "inside" : "outside");
        MeshModel *nm = doc->addNewMesh("", label, false);
        if (!nm) { report("Geometric snake: MeshLab refused to add a layer.", true); return; }
        ids[part] = nm->id();
        nm->updateDataMask(src);
        vcg::tri::Append<CMeshO, CMeshO>::MeshCopy(nm->cm, part == 0 ? inside : outside);
        nm->cm.Tr = src->cm.Tr;
        gs::host::UpdateBoxAndNormals(*nm);
        if (shared && glArea) {
            shared->meshAttributesUpdated(nm->id(), true, MLRenderingData::RendAtts(true));
            shared->manageBuffers(nm->id());
        }
    }
    cutUndo.ClearRedo(); // a new action
    splitSteps.push_back(SplitStep{ids[0], ids[1], cutGeneration, ctl->UndoSteps(), ctl->UndoLabel()});
    const QString msg = QString("Split along snake %1 into layers \"%2 inside\" (%3 faces) and \"%2 outside\" (%4 faces); "
                                "Ctrl+Z removes them.")
                            .arg(ctl->Selected() + 1)
                            .arg(base)
                            .arg(inside.fn)
                            .arg(outside.fn);
    report(msg, false);
    Log(GLLogStream::FILTER, "Geometric snake: %s", qUtf8Printable(msg));
    if (glArea) glArea->update();
}
