// The edit tool's Cut section (issue 34): the selected snake selects one side of the mesh, or
// splits it into two new layers. Neither changes the mesh the snakes are on (select uses the
// cut's select-only mode: whole faces by their centroid's side), so the snakes, their undo and
// the session stay valid; the selection is MeshLab's own (Edit > Select none / invert undo it).

#include <GL/glew.h>

#include "edit_geometric_snake.h"
#include "snake_dock.h"

#include <QFileInfo>

#include <meshlab/glarea.h>
#include <vcg_ext/cut/mesh_cut.h>

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
}

void EditGeometricSnakePlugin::cutSelect(bool inside)
{
    setRunning(false);
    if (!ctl || !modelAlive()) { report("Geometric snake: no mesh.", true); return; }
    try {
        MeshCut<CMeshO>::Param p;
        p.mode = vcg::tri::CutMode::SelectOnly;
        p.side = inside ? vcg::tri::CutSide::Inside : vcg::tri::CutSide::Outside;
        const auto r = MeshCut<CMeshO>::Apply(model->cm, {SelectedCurve(*ctl)}, p);
        if (glArea) glArea->updateSelection(model->id(), true, true);
        const QString msg = QString("Selected the %1 of snake %2: %3 faces (area %4 of %5).")
                                .arg(inside ? "inside" : "outside")
                                .arg(ctl->Selected() + 1)
                                .arg(r.facesInside)
                                .arg(r.areaInside)
                                .arg(r.areaInside + r.areaOutside);
        report(msg, false);
        Log(GLLogStream::FILTER, "Geometric snake: %s", qUtf8Printable(msg));
    } catch (const std::exception &e) {
        report(QString::fromStdString(e.what()), true);
    }
    if (glArea) glArea->update();
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
