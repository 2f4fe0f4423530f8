// The edit tool's Cut section (issue 34): the selected snake selects one side of the mesh, cuts
// it open, or splits it into two new layers.
// - Select inside / outside embed the snake exactly (mode 1 of the issue: new vertices where it
//   crosses edges) and select the faces on one side; with "Whole faces only" they select the
//   user's faces by their centroid's side and leave the mesh as it was.
// - Cut open embeds it and makes its edges boundary edges, in this layer.
// - Split into layers adds two layers; this one is not changed.
// A selection that leaves the mesh's faces as they were is one step of the tool's undo (Ctrl+Z
// brings the selection before it back). A cut that changes the mesh moves the session's snakes
// onto the new faces (CutSessionMap) and starts the session afresh on the cut mesh: MeshLab
// 2020.09 has no undo for a mesh change, so neither has the tool.

#include <GL/glew.h>

#include "edit_geometric_snake.h"
#include "snake_dock.h"

#include <QCheckBox>
#include <QFileInfo>

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
        MeshCut<CMeshO>::Result r;
        // one step of the tool's undo (Ctrl+Z brings the selection before it back)
        ctl->ChangeSelection(inside ? "select inside" : "select outside",
                             [&] { r = MeshCut<CMeshO>::Apply(model->cm, {SelectedCurve(*ctl)}, p); });
        QString msg = QString("Selected the %1 of snake %2: %3 faces (area %4 of %5)%6.")
                          .arg(inside ? "inside" : "outside")
                          .arg(snake)
                          .arg(r.facesInside)
                          .arg(r.areaInside)
                          .arg(r.areaInside + r.areaOutside)
                          .arg(wholeFaces ? ", whole faces by their centroid" : "");
        if (r.addedVertices > 0 || r.addedFaces > 0) {
            msg += QString(" The snake was embedded into the mesh: %1 vertices and %2 faces added; the session goes on "
                           "on the cut mesh (no undo of the cut).")
                       .arg(r.addedVertices)
                       .arg(r.addedFaces);
            afterMeshCut(session, r.points, snake - 1, r.chains.empty() ? std::vector<vcg::tri::SurfacePoint>() : r.chains[0]);
        } else if (glArea) {
            glArea->updateSelection(model->id(), true, true);
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
        const MeshCut<CMeshO>::Result r = MeshCut<CMeshO>::Apply(model->cm, {SelectedCurve(*ctl)}, p);
        const QString msg = QString("Cut open along snake %1: its %2 vertices on the mesh are on the boundary now "
                                    "(%3 vertices and %4 faces added); the session goes on on the cut mesh (no undo "
                                    "of the cut).")
                                .arg(snake)
                                .arg(r.curveVertices)
                                .arg(r.addedVertices)
                                .arg(r.addedFaces);
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
    for (int part = 0; part < 2; ++part) {
        const QString label = QString("%1 %2").arg(base, part == 0 ? "inside" : "outside");
        MeshModel *nm = doc->addNewMesh("", label, false);
        if (!nm) { report("Geometric snake: MeshLab refused to add a layer.", true); return; }
        nm->updateDataMask(src);
        vcg::tri::Append<CMeshO, CMeshO>::MeshCopy(nm->cm, part == 0 ? inside : outside);
        nm->cm.Tr = src->cm.Tr;
        gs::host::UpdateBoxAndNormals(*nm);
        if (shared && glArea) {
            shared->meshAttributesUpdated(nm->id(), true, MLRenderingData::RendAtts(true));
            shared->manageBuffers(nm->id());
        }
    }
    const QString msg = QString("Split along snake %1 into layers \"%2 inside\" (%3 faces) and \"%2 outside\" (%4 faces).")
                            .arg(ctl->Selected() + 1)
                            .arg(base)
                            .arg(inside.fn)
                            .arg(outside.fn);
    report(msg, false);
    Log(GLLogStream::FILTER, "Geometric snake: %s", qUtf8Printable(msg));
    if (glArea) glArea->update();
}
