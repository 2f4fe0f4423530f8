#ifndef VCG_EXT_SNAKE_SESSION_H
#define VCG_EXT_SNAKE_SESSION_H

// An editing session of snakes on one mesh: its state (the energy and its settings, the snakes
// and the one selected, the seeds being placed, the parameters), the rule every change of it
// follows (the session as it was is recorded first, one undo step per user action, and the
// revision grows), and the undo / redo of whole user actions (SnakeSessionHistory), including
// the mesh's selection when an action changed it.
//
// The hosts use it through SnakeController (session/controller.h), which adds the operations;
// SnakeStoredSession (session/stored_session.h) saves and restores it.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <vcg_ext/energy/crease_energy.h>
#include <vcg_ext/energy/energy_source.h>
#include <vcg_ext/energy/feature_energy.h>
#include <vcg_ext/paths/seed_list.h>
#include <vcg_ext/paths/seed_path_cost.h>
#include <vcg_ext/session/mesh_selection_memento.h>
#include <vcg_ext/session/session_history.h>
#include <vcg_ext/snake/error.h>
#include <vcg_ext/snake/geometric_snake.h>
#include <vcg_ext/snake/part_boundary_end.h>
#include <vcg_ext/surface/snake_surface.h>
#include <vcg_ext/surface/surface_point.h>

namespace vcg {
namespace tri {

template <class MeshType>
class SnakeSession
{
public:
    typedef GeometricSnake<MeshType> Snake;
    typedef SnakeSurface<MeshType> Surface;

    explicit SnakeSession(MeshType &m) : mesh(m) {}
    // the undo history refers to the members
    SnakeSession(const SnakeSession &) = delete;
    SnakeSession &operator=(const SnakeSession &) = delete;

    MeshType &Mesh() { return mesh; }

    // --- the energy the snakes slither on (SnakeEnergySource)
    /// Computes the feature energy into the vertex quality (low = feature) and makes every
    /// snake slither on it. Throws on a bad type/smoothing or an unusable mesh.
    void ComputeEnergy(FeatureEnergyType type, int smoothing)
    {
        energy.Compute(type, smoothing);
        energyChanged();
    }
    /// The energy with the current settings, computed (if it is not yet) while `adjacency`,
    /// the caller's FF/VF build, runs: on a large mesh the two share the two cores
    /// (SnakeEnergySource::ComputeBeside).
    void ComputeEnergyBeside(const std::function<void()> &adjacency)
    {
        const bool before = energy.Computed();
        energy.ComputeBeside(adjacency);
        if (!before) energyChanged();
    }
    /// Any quality field can drive a snake: take the current vertex quality as the energy
    /// (low = feature) instead of computing one. Saved sessions remember it.
    void UseQualityAsEnergy()
    {
        energy.UseQuality();
        energyChanged();
    }
    bool EnergyFromQuality() const { return energy.FromQuality(); }
    bool EnergyComputed() const { return energy.Computed(); }
    FeatureEnergyType EnergyType() const { return energy.Type(); }
    /// Dihedral angle (degrees) above which an edge is a crease, for the crease energy.
    double CreaseAngle() const { return energy.CreaseAngle(); }
    void SetCreaseAngle(double deg)
    {
        if (energy.SetCreaseAngle(deg)) energyChanged();
    }
    int EnergySmoothing() const { return energy.Smoothing(); }
    /// Energy settings used when the energy is computed on demand (first snake).
    void SetEnergySettings(FeatureEnergyType type, int smoothing)
    {
        if (energy.SetSettings(type, smoothing)) energyChanged();
    }
    /// The shared surface; computes the energy first if that was not done yet.
    Surface &EnsureSurface() { return *energy.EnsureSurface(); }
    bool HasSurface() const { return bool(energy.SurfacePtr()); }
    /// Warnings about the energy the snakes read, for the Log.
    std::vector<std::string> EnergyWarnings() { return energy.Warnings(); }
    double MeanEdge() { return EnsureSurface().MeanEdge(); }
    /// The length unit of new snakes seeded at `seeds` (SnakeEnergySource::LengthScale).
    double LengthScale(const std::vector<SurfacePoint> &seeds = {}) { return energy.LengthScale(seeds); }
    /// False when the mesh lost or gained elements since the snakes were built on it.
    bool MeshMatches() const { return !HasSurface() || energy.SurfacePtr()->MatchesMesh(); }
    /// The parameters of a part-boundary Run's end (PartBoundaryEnd::FinishRun) with the
    /// measures of this mesh that the crease filter reads (PartBoundaryEnd::Measured: its noise
    /// and median face angle, ~20 ms on bunny00's 70k faces), taken at the first Run's end on
    /// the part-boundary energy and again after the energy changes, as the energy is (session
    /// 33: FinishRun took them at every Run's end). Other energies: the defaults, unmeasured
    /// (FinishRun does nothing for them).
    const typename PartBoundaryEnd<MeshType>::Param &RunEndParam()
    {
        if (!runEndMeasured && !energy.FromQuality() && energy.Type() == FeatureEnergyType::PartBoundary) {
            runEnd = PartBoundaryEnd<MeshType>::Measured(mesh, typename PartBoundaryEnd<MeshType>::Param());
            runEndMeasured = true;
        }
        return runEnd;
    }

    // --- undo / redo of whole user actions (SnakeSessionHistory)
    /// Groups every change until the matching EndAction into one undo step (a Run, a drag);
    /// groups nest. An action that changes nothing leaves no step.
    void BeginAction(const std::string &label) { history.BeginAction(label); }
    void EndAction() { history.EndAction(); }
    bool InAction() const { return history.InAction(); }
    /// BeginAction / EndAction for a scope.
    struct Action
    {
        SnakeSession &c;
        Action(SnakeSession &ctl, const std::string &label) : c(ctl) { c.BeginAction(label); }
        ~Action() { c.EndAction(); }
    };

    bool CanUndo() const { return history.CanUndo(); }
    bool CanRedo() const { return history.CanRedo(); }
    /// The action Undo / Redo would take back / do again, e.g. "run" ("" if none).
    std::string UndoLabel() const { return history.UndoLabel(); }
    std::string RedoLabel() const { return history.RedoLabel(); }
    /// Returns to the session as it was before the last action (all snakes, seeds, selection).
    bool Undo()
    {
        if (!history.Undo(makeSnake(), saveSelection(), loadSelection())) return false;
        touch("undo");
        return true;
    }
    bool Redo()
    {
        if (!history.Redo(makeSnake(), saveSelection(), loadSelection())) return false;
        touch("redo");
        return true;
    }
    /// A change of the mesh's face and vertex selection made by `change()` (e.g. a cut's Select
    /// inside): one undo step that brings the selection back. Nothing is recorded if change()
    /// leaves the selection as it was, or throws (the selection is then put back).
    template <class Change>
    void ChangeSelection(const std::string &label, Change change)
    {
        auto before = std::make_shared<const Selection>(Selection::Save(mesh));
        try {
            change();
        } catch (...) {
            before->Restore(mesh);
            throw;
        }
        if (Selection::Save(mesh) == *before) return;
        history.RecordMesh(label, std::move(before));
        ++selectionRevision;
        touch(label.c_str());
    }
    /// Increases whenever the session changes the mesh's selection (ChangeSelection, or an
    /// undo / redo of it): the view redraws the selection then.
    long SelectionRevision() const { return selectionRevision; }
    /// The undo history, to keep while the edit tool is away (SnakeKeptHistories): taken out
    /// (this session's history is left empty) and adopted by the next session on the same
    /// mesh once it has restored the session this one saved.
    typedef typename SnakeSessionHistory<Snake, SnakeSeedList<MeshType>, MeshSelectionMemento<MeshType>>::KeptSteps KeptHistory;
    KeptHistory TakeHistory() { return history.Take(); }
    void AdoptHistory(KeptHistory h) { history.Adopt(std::move(h)); }
    /// Memory bound of the history (default 100 MB) and its current estimate.
    void SetUndoLimit(size_t bytes) { history.SetLimit(bytes); }
    size_t UndoBytes() const { return history.Bytes(); }
    size_t UndoSteps() const { return history.Steps(); }

    // --- status
    /// Increases with every change (for redraws, autosave and auto-export).
    long Revision() const { return revision; }
    const std::string &LastOperation() const { return lastOp; }

protected:
    MeshType &mesh;
    SnakeEnergySource<MeshType> energy{mesh};
    std::vector<std::unique_ptr<Snake>> snakes;
    int selected = -1;
    SnakeSeedList<MeshType> seedList{mesh};
    SnakeParams params;
    SeedPathCost seedCost = SeedPathCost::Length;
    long revision = 0;
    std::string lastOp;

    typedef MeshSelectionMemento<MeshType> Selection;
    SnakeSessionHistory<Snake, SnakeSeedList<MeshType>, Selection> history{{snakes, selected, seedList, params}};

    /// Before a change: the first change of an action records the session as it was.
    bool record(const char *label) { return history.Record(label); }
    /// After a change.
    void touch(const char *op)
    {
        ++revision;
        lastOp = op;
    }
    /// A new energy: the snakes start afresh on it, and their mementos are outdated.
    void energyChanged()
    {
        runEndMeasured = false; // RunEndParam's measures: taken again, as the energy is
        for (auto &s : snakes) s->EnergyChanged();
        history.AllChanged();
        touch("energy");
    }
    void checkMesh() const
    {
        if (!MeshMatches())
            throw SnakeError("Geometric snake: the mesh changed (vertices or faces were added or removed) since the "
                             "snakes were built; restart the tool.");
    }

private:
    long selectionRevision = 0;
    typename PartBoundaryEnd<MeshType>::Param runEnd; // RunEndParam's
    bool runEndMeasured = false;
    auto saveSelection()
    {
        return [this] { return std::make_shared<const Selection>(Selection::Save(mesh)); };
    }
    auto loadSelection()
    {
        return [this](const Selection &s) {
            if (s.Restore(mesh)) ++selectionRevision;
        };
    }
    // builds the snakes an undo brings back
    auto makeSnake()
    {
        return [this](const SnakeParams &p) { return std::unique_ptr<Snake>(new Snake(energy.EnsureSurface(), p)); };
    }
};

} // namespace tri
} // namespace vcg

#endif
