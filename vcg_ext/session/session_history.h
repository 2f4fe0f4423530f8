#ifndef VCG_EXT_SNAKE_SESSION_HISTORY_H
#define VCG_EXT_SNAKE_SESSION_HISTORY_H

// The undo history of an editing session, in the units a user thinks in: every user action
// (a Run, a drag, a Build, a seed click) is one step, a snapshot of the whole session (all
// snakes, the seeds being placed, the selection, the parameters) as it was before the action.
// Snapshots share the memento of every snake an action did not touch, so a step costs about
// the snakes it changed (SnakeUndo bounds the history by that memory).
//
// The history works on the session it is given (Live: references to its owner's members) and
// must be told of every change: Record before it (the first change of an action pushes the
// step), SnakeAdded / SnakeRemoved / AllChanged when snakes come, go or all change.
//
// A step may also hold a state of the mesh outside the snakes (MeshStateType, e.g. its
// selection), saved only by the actions that change it (RecordMesh): undoing or redoing such a
// step saves the mesh state it replaces and restores the step's.

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include <vcg_ext/session/param_defs.h>
#include <vcg_ext/session/undo.h>

namespace vcg {
namespace tri {

/// No mesh state in the history.
struct NoMeshState
{
    size_t Bytes() const { return 0; }
};

template <class SnakeType, class SeedListType, class MeshStateType = NoMeshState>
class SnakeSessionHistory
{
public:
    typedef std::vector<std::unique_ptr<SnakeType>> SnakeList;
    /// The session recorded and restored: the owner's members.
    struct Live
    {
        SnakeList &snakes;
        int &selected; ///< the snake every change goes through (-1: none)
        SeedListType &seeds;
        SnakeParams &params;
    };

    explicit SnakeSessionHistory(Live live) : cur(live) {}

    // --- telling the history of changes
    /// Called before a change of the selected snake, the seeds or the parameters: the first
    /// change of an action records the session as it was. Returns true if it pushed a step.
    bool Record(const std::string &label)
    {
        if (actionDepth > 0) {
            if (actionRecorded) {
                selectedChanged();
                return false;
            }
            actionRecorded = true;
        }
        Session s = snapshot();
        undo.Push(s, bytes(s, &lastPushed), actionDepth > 0 ? actionLabel : label);
        lastPushed = s.snakes;
        selectedChanged();
        return true;
    }
    /// Pushes a step of its own for a change of the mesh state, made already: `before` is the
    /// state it replaced (the snakes, seeds and parameters are unchanged by it).
    void RecordMesh(const std::string &label, std::shared_ptr<const MeshStateType> before)
    {
        Session s = snapshot();
        s.mesh = std::move(before);
        undo.Push(s, bytes(s, &lastPushed), label);
        lastPushed = s.snakes;
    }
    /// Takes back the step the last Record pushed (the change it announced did nothing).
    void DropLast() { undo.DropLast(); }
    void SnakeAdded() { saved.push_back(nullptr); }
    void SnakeRemoved(int i) { saved.erase(saved.begin() + i); }
    /// Every snake changed (a new energy), or the session was replaced (Clear too).
    void AllChanged() { saved.assign(cur.snakes.size(), nullptr); }
    /// A new session (loaded from a file): no steps, nothing recorded.
    void Clear()
    {
        undo.Clear();
        AllChanged();
        lastPushed.clear();
    }

    // --- actions: every change until the matching EndAction is one step; they nest
    void BeginAction(const std::string &label)
    {
        if (actionDepth++ == 0) {
            actionLabel = label;
            actionRecorded = false;
        }
    }
    void EndAction()
    {
        if (actionDepth > 0) --actionDepth;
    }
    bool InAction() const { return actionDepth > 0; }

    // --- undo / redo
    bool CanUndo() const { return undo.CanUndo(); }
    bool CanRedo() const { return undo.CanRedo(); }
    /// The action Undo / Redo would take back / do again, e.g. "run" ("" if none).
    std::string UndoLabel() const { return undo.UndoLabel(); }
    std::string RedoLabel() const { return undo.RedoLabel(); }
    size_t Steps() const { return undo.UndoCount(); }
    size_t Bytes() const { return undo.Bytes(); }
    void SetLimit(size_t b) { undo.SetLimit(b); }

    /// Returns the session to the state before the last action. `make(params)` builds a snake
    /// for a snapshot that holds more snakes than the session has now.
    /// With mesh states: `save()` gives the mesh's state now (a shared_ptr to MeshStateType),
    /// `load(state)` sets it.
    template <class MakeSnake, class SaveMesh, class LoadMesh>
    bool Undo(MakeSnake make, SaveMesh save, LoadMesh load)
    {
        return swap(make, save, load, false);
    }
    template <class MakeSnake, class SaveMesh, class LoadMesh>
    bool Redo(MakeSnake make, SaveMesh save, LoadMesh load)
    {
        return swap(make, save, load, true);
    }
    template <class MakeSnake>
    bool Undo(MakeSnake make)
    {
        return Undo(make, noSave, noLoad);
    }
    template <class MakeSnake>
    bool Redo(MakeSnake make)
    {
        return Redo(make, noSave, noLoad);
    }

private:
    typedef std::shared_ptr<const typename SnakeType::Memento> MementoPtr;
    struct Session
    {
        std::vector<MementoPtr> snakes;
        int selected = -1;
        SeedListType seeds;
        SnakeParams params;
        std::shared_ptr<const MeshStateType> mesh; ///< the mesh's state, if the step changed it
    };
    static std::shared_ptr<const MeshStateType> noSave() { return nullptr; }
    static void noLoad(const MeshStateType &) {}

public:
    /// The recorded steps, pure data (the snakes' mementos, seeds, parameters): taken out when
    /// the edit tool leaves the mesh and adopted by the next session on it (SnakeKeptHistories),
    /// so Undo goes on across MeshLab ending and restarting the tool.
    typedef SnakeUndo<Session> KeptSteps;
    /// Takes the steps out; the history is left empty.
    KeptSteps Take()
    {
        KeptSteps s = std::move(undo);
        undo = KeptSteps(s.Limit());
        Clear();
        return s;
    }
    /// Goes on with `s`, steps of this session (the current state is where they left off).
    void Adopt(KeptSteps s)
    {
        s.SetLimit(undo.Limit());
        undo = std::move(s);
        AllChanged();
        lastPushed.clear();
    }

private:
    Live cur;
    SnakeUndo<Session> undo;
    // saved[k]: snake k's memento while it is unchanged (nullptr: changed since), shared by
    // every snapshot taken meanwhile
    std::vector<MementoPtr> saved, lastPushed;
    int actionDepth = 0;
    bool actionRecorded = false;
    std::string actionLabel;

    // every change goes through the selected snake: its memento is outdated
    void selectedChanged()
    {
        if (cur.selected >= 0 && cur.selected < int(saved.size())) saved[cur.selected] = nullptr;
    }
    Session snapshot()
    {
        saved.resize(cur.snakes.size());
        Session s{{}, cur.selected, cur.seeds, cur.params, nullptr};
        for (size_t k = 0; k < cur.snakes.size(); ++k) {
            if (!saved[k]) saved[k] = std::make_shared<const typename SnakeType::Memento>(cur.snakes[k]->Save());
            s.snakes.push_back(saved[k]);
        }
        return s;
    }
    // Snakes are restored in place (references to them stay valid while they exist).
    template <class MakeSnake>
    void restore(const Session &s, MakeSnake &make)
    {
        cur.snakes.resize(std::min(cur.snakes.size(), s.snakes.size()));
        saved.resize(cur.snakes.size());
        for (size_t k = 0; k < s.snakes.size(); ++k) {
            if (k >= cur.snakes.size()) {
                cur.snakes.push_back(make(s.params));
                saved.push_back(nullptr);
            }
            if (saved[k] != s.snakes[k]) cur.snakes[k]->Restore(*s.snakes[k]);
            saved[k] = s.snakes[k];
        }
        cur.selected = s.selected;
        cur.seeds = s.seeds;
        cur.params = s.params;
    }
    template <class MakeSnake, class SaveMesh, class LoadMesh>
    bool swap(MakeSnake &make, SaveMesh &save, LoadMesh &load, bool redo)
    {
        const Session *next = undo.Peek(redo);
        if (!next) return false;
        Session s = snapshot();
        if (next->mesh) s.mesh = save(); // the step changes the mesh: its state now goes the other way
        const size_t b = bytes(s);
        if (!(redo ? undo.Redo(s, b) : undo.Undo(s, b))) return false;
        restore(s, make);
        if (s.mesh) load(*s.mesh);
        return true;
    }
    // the memory a snapshot adds: its snakes' mementos, except those it shares with
    // `previous` (the snakes the last action did not touch)
    size_t bytes(const Session &s, const std::vector<MementoPtr> *previous = nullptr) const
    {
        size_t b = sizeof(Session) + s.seeds.Bytes() + (s.mesh ? s.mesh->Bytes() : 0);
        for (const auto &m : s.snakes)
            if (!previous || std::find(previous->begin(), previous->end(), m) == previous->end()) b += m->Bytes();
        return b;
    }
};

} // namespace tri
} // namespace vcg

#endif
