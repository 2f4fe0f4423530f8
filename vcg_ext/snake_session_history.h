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

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include <vcg_ext/snake_param_defs.h>
#include <vcg_ext/snake_undo.h>

namespace vcg {
namespace tri {

template <class SnakeType, class SeedListType>
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
    template <class MakeSnake>
    bool Undo(MakeSnake make)
    {
        return swap(make, false);
    }
    template <class MakeSnake>
    bool Redo(MakeSnake make)
    {
        return swap(make, true);
    }

private:
    typedef std::shared_ptr<const typename SnakeType::Memento> MementoPtr;
    struct Session
    {
        std::vector<MementoPtr> snakes;
        int selected = -1;
        SeedListType seeds;
        SnakeParams params;
    };

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
        Session s{{}, cur.selected, cur.seeds, cur.params};
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
    template <class MakeSnake>
    bool swap(MakeSnake &make, bool redo)
    {
        Session s = snapshot();
        const size_t b = bytes(s);
        if (!(redo ? undo.Redo(s, b) : undo.Undo(s, b))) return false;
        restore(s, make);
        return true;
    }
    // the memory a snapshot adds: its snakes' mementos, except those it shares with
    // `previous` (the snakes the last action did not touch)
    size_t bytes(const Session &s, const std::vector<MementoPtr> *previous = nullptr) const
    {
        size_t b = sizeof(Session) + s.seeds.Bytes();
        for (const auto &m : s.snakes)
            if (!previous || std::find(previous->begin(), previous->end(), m) == previous->end()) b += m->Bytes();
        return b;
    }
};

} // namespace tri
} // namespace vcg

#endif
