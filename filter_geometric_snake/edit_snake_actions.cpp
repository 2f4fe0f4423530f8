// The edit tool's actions (issue 37: one concern per file): what the panel's buttons and the keys
// do to the session: build, point edits, undo and redo (the session's steps, then the cuts'),
// parameters, the feature energy, export, a snake as a layer, seeds from picked points.

#include <GL/glew.h>

#include "edit_geometric_snake.h"
#include "snake_dock.h"

#include <chrono>
#include <fstream>

#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QRegularExpression>
#include <QTextStream>

#include <meshlab/glarea.h>
#include <vcg/complex/algorithms/update/color.h>

using namespace vcg;
using vcg::tri::SnakeError;
using vcg::tri::SnakeParams;
using vcg::tri::SurfacePoint;

// ====================================================================== actions
void EditGeometricSnakePlugin::buildSnake(bool closed)
{
    setRunning(false);
    response.Start("build");
    if (guardedFn("build snake", [&] {
            ctl->SetNewSnakeParams(paramsFromDock()); // the other snakes stay as they are (converged)
            auto t0 = std::chrono::steady_clock::now();
            ctl->CloseSeeds(closed);
            double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
            Log(GLLogStream::FILTER, "Geometric snake: built %s snake with %d samples in %.1f ms", closed ? "a closed" : "an open",
                ctl->SelectedSnake()->SampleCount(), ms);
            lastTimed = QString("build, %1 ms").arg(ms, 0, 'f', 1); // the Log's figure
            lastTimedRevision = ctl->Revision();
        })) {
        currentSample = -1;
        dock->editMode->setChecked(true);
        quickShow = true; // the new snake drawn over the last frame; the full redraw when the user pauses
        afterChange(true);
        quickShow = false;
        response.Handled();
        showNow();
        redrawLater.start();
    } else
        response.Cancel();
}

void EditGeometricSnakePlugin::editCurrent(const QString &what, const std::function<void()> &f)
{
    if (!ctl) return;
    if (currentSample < 0) {
        report("Select a sample first (Edit samples mode, click on it).", true);
        return;
    }
    setRunning(false);
    if (guardedFn(what, f)) afterChange();
}

void EditGeometricSnakePlugin::undoRedo(bool redo)
{
    if (!ctl) return;
    setRunning(false);
    if (undoRedoHostStep(redo)) return; // a cut or split (edit_geometric_snake_cut.cpp)
    std::string label = redo ? ctl->RedoLabel() : ctl->UndoLabel();
    bool done = false;
    const long selection = ctl->SelectionRevision();
    if (guardedFn(redo ? "redo" : "undo", [&] { done = redo ? ctl->Redo() : ctl->Undo(); })) {
        if (ctl->SelectionRevision() != selection && glArea && modelAlive())
            glArea->updateSelection(model->id(), true, true); // a cut's selection came back
        if (ctl->SelectedSnake()) paramsToDock(ctl->SelectedSnake()->Params());
        afterChange();
        report(done ? QString("%1 %2.").arg(redo ? "Redid" : "Undid", QString::fromStdString(label))
                    : QString(redo ? "Nothing to redo." : "Nothing to undo."),
               false);
    }
}

void EditGeometricSnakePlugin::applyParams()
{
    if (!ctl) return;
    if (guardedFn("parameters", [&] { ctl->SetParams(paramsFromDock()); })) afterChange();
}

void EditGeometricSnakePlugin::computeEnergy(bool show)
{
    setRunning(false);
    if (!guardedFn("energy", [&] {
            auto t0 = std::chrono::steady_clock::now();
            ctl->ComputeEnergy(vcg::tri::FeatureEnergyType(dock->energyType->currentIndex()), dock->smoothing->value());
            double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
            Log(GLLogStream::FILTER, "Geometric snake: energy computed in %.1f ms", ms);
            if (show) {
                model->updateDataMask(MeshModel::MM_VERTCOLOR);
                vcg::tri::UpdateColor<CMeshO>::PerVertexQualityRamp(model->cm, 0.0f, 1.0f);
                if (shared && glArea) {
                    MLRenderingData::RendAtts atts;
                    atts[MLRenderingData::ATT_NAMES::ATT_VERTCOLOR] = true;
                    shared->meshAttributesUpdated(model->id(), false, atts);
                    MLRenderingData dt;
                    shared->getRenderInfoPerMeshView(model->id(), glArea->context(), dt);
                    for (auto pm : {MLRenderingData::PR_SOLID, MLRenderingData::PR_WIREFRAME_TRIANGLES,
                                    MLRenderingData::PR_POINTS}) {
                        dt.set(pm, MLRenderingData::ATT_NAMES::ATT_VERTCOLOR, true);
                        dt.set(pm, MLRenderingData::ATT_NAMES::ATT_FACECOLOR, false);
                    }
                    MLPerViewGLOptions opts;
                    if (dt.get(opts)) {
                        opts._persolid_fixed_color_enabled = false;
                        opts._persolid_mesh_color_enabled = false;
                        opts._perwire_fixed_color_enabled = false;
                        opts._perpoint_fixed_color_enabled = false;
                        dt.set(opts);
                    }
                    shared->setRenderingDataPerMeshView(model->id(), glArea->context(), dt);
                    shared->manageBuffers(model->id());
                }
            }
        }))
        return;
    report(show ? "Energy shown as colours (red = feature, blue = flat)." : "Energy recomputed.", false);
    afterChange(true);
}

void EditGeometricSnakePlugin::exportCurves(bool all)
{
    if (!ctl) return;
    setRunning(false);
    QString dir = model && !model->fullName().isEmpty() ? QFileInfo(model->fullName()).absolutePath() : QDir::homePath();
    QString base = model ? QFileInfo(model->label()).completeBaseName() : "snake";
    QString path = QFileDialog::getSaveFileName(dock, all ? "Export all snakes" : "Export the selected snake",
                                                dir + "/" + base + "_snake.json",
                                                "Snake JSON (*.json);;OBJ polylines (*.obj);;PLY edges (*.ply)");
    if (path.isEmpty()) return;
    if (QFileInfo(path).suffix().isEmpty()) path += ".json";
    if (guardedFn("export", [&] { ctl->Export(path.toStdString(), all, protectedFiles()); })) {
        report(QString("Exported to %1").arg(path), false);
        Log(GLLogStream::FILTER, "Geometric snake: exported to %s", path.toStdString().c_str());
    }
}

void EditGeometricSnakePlugin::addAsLayer()
{
    setRunning(false);
    if (!doc) { report("Geometric snake: no document.", true); return; }
    std::vector<vcg::Point3d> pts;
    bool closed = false;
    int index = 0;
    if (!guardedFn("add as layer", [&] {
            Controller::Snake *s = ctl->SelectedSnake();
            if (!s) throw SnakeError("Geometric snake: no snake selected.");
            pts = s->PolylinePositions();
            closed = s->Closed();
            index = ctl->Selected() + 1;
        }))
        return;
    if (pts.size() < 2) { report("Geometric snake: the curve is empty.", true); return; }
    Matrix44m tr = model->cm.Tr;
    QString label = QString("%1 snake %2").arg(QFileInfo(model->label()).completeBaseName()).arg(index);
    MeshModel *nm = doc->addNewMesh("", label, false);
    if (!nm) { report("Geometric snake: MeshLab refused to add a layer.", true); return; }
    CMeshO &c = nm->cm;
    auto vi = tri::Allocator<CMeshO>::AddVertices(c, pts.size());
    for (size_t i = 0; i < pts.size(); ++i, ++vi) vi->P() = CMeshO::CoordType::Construct(pts[i]);
    size_t ne = closed ? pts.size() : pts.size() - 1;
    auto ei = tri::Allocator<CMeshO>::AddEdges(c, ne);
    for (size_t i = 0; i < ne; ++i, ++ei) {
        ei->V(0) = &c.vert[i];
        ei->V(1) = &c.vert[(i + 1) % pts.size()];
    }
    c.Tr = tr;
    gs::host::UpdateBoxAndNormals(*nm);
    if (shared && glArea) {
        shared->meshAttributesUpdated(nm->id(), true, MLRenderingData::RendAtts(true));
        MLRenderingData dt;
        MLRenderingData::RendAtts atts;
        atts[MLRenderingData::ATT_NAMES::ATT_VERTPOSITION] = true;
        dt.set(MLRenderingData::PR_WIREFRAME_EDGES, atts);
        dt.set(MLRenderingData::PR_POINTS, atts);
        shared->setRenderingDataPerMeshView(nm->id(), glArea->context(), dt);
        shared->manageBuffers(nm->id());
    }
    report(QString("Added layer \"%1\" (%2 vertices, %3 edges).").arg(label).arg(pts.size()).arg(ne), false);
    Log(GLLogStream::FILTER, "Geometric snake: added layer %s", label.toStdString().c_str());
    if (glArea) glArea->update();
}

void EditGeometricSnakePlugin::usePickPoints()
{
    if (!ctl || !model) return;
    // MeshLab's Pick Points tool saves <mesh>_picked_points.pp next to the mesh.
    QString suggestion;
    if (!model->fullName().isEmpty()) {
        QFileInfo fi(model->fullName());
        suggestion = fi.absolutePath() + "/" + fi.completeBaseName() + "_picked_points.pp";
    }
    QString path = suggestion;
    if (path.isEmpty() || !QFileInfo::exists(path))
        path = QFileDialog::getOpenFileName(dock, "Picked points file", suggestion, "Picked points (*.pp)");
    if (path.isEmpty()) return;
    // the picked points are seeds at the surface points nearest to them (SeedPointSnap), not
    // at the nearest vertices: on a CAD part every vertex lies on some crease
    size_t count = 0;
    if (guardedFn("pick points", [&] {
            const auto pts = vcg::tri::SeedPointsParser::Active(vcg::tri::SeedPointsParser::ReadPickPointsFile(path.toStdString()));
            if (pts.empty()) throw vcg::tri::SnakeError("no picked points in " + path.toStdString());
            const auto snap = vcg::tri::SeedPointSnap<CMeshO>::Snap(model->cm, pts, 1);
            ctl->SetSeedPoints(snap.points);
            count = snap.points.size();
        })) {
        dock->seedMode->setChecked(true);
        afterChange();
        report(QString("%1 seeds from %2; press Enter to build the snake.").arg(count).arg(path), false);
    }
}
