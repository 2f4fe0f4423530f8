#ifndef VCG_EXT_SNAKE_HISTORY_H
#define VCG_EXT_SNAKE_HISTORY_H

#include <deque>

namespace vcg {
namespace tri {

/// Undo and redo of a value-type state (a snake's curve): each change pushes the state it
/// replaces; at most `limit` steps are kept. While suspended (one step for a whole Run),
/// pushes are ignored.
template <class State>
class SnakeHistory
{
public:
    explicit SnakeHistory(size_t limit = 200) : cap(limit) {}

    /// Call before changing `current`.
    void Push(const State &current)
    {
        if (suspended) return;
        undo.push_back(current);
        if (undo.size() > cap) undo.pop_front();
        redo.clear();
    }
    bool CanUndo() const { return !undo.empty(); }
    bool CanRedo() const { return !redo.empty(); }
    /// Replaces `current` with the previous state; false if there is none.
    bool Undo(State &current)
    {
        if (undo.empty()) return false;
        redo.push_back(current);
        current = undo.back();
        undo.pop_back();
        return true;
    }
    bool Redo(State &current)
    {
        if (redo.empty()) return false;
        undo.push_back(current);
        current = redo.back();
        redo.pop_back();
        return true;
    }
    /// Suspends recording; returns the previous setting (to restore it after).
    bool Suspend(bool s)
    {
        bool old = suspended;
        suspended = s;
        return old;
    }

private:
    std::deque<State> undo, redo;
    size_t cap;
    bool suspended = false;
};

} // namespace tri
} // namespace vcg

#endif
