#ifndef VCG_EXT_SNAKE_UNDO_H
#define VCG_EXT_SNAKE_UNDO_H

// Undo and redo in the units a user thinks in: one entry per user action (a whole Run, a
// whole drag, a Build), not per snake operation. The history is bounded by the memory its
// states take (an estimate given by the caller), not by a count: with the default 100 MB
// a session keeps thousands of steps of a small snake and still a few dozen of a huge one.

#include <cstddef>
#include <deque>
#include <string>
#include <utility>

namespace vcg {
namespace tri {

template <class State>
class SnakeUndo
{
public:
    /// At most `byteLimit` bytes of states, and `maxEntries` undo entries.
    explicit SnakeUndo(size_t byteLimit = size_t(100) << 20, size_t maxEntries = size_t(-1))
        : limit(byteLimit), maxCount(maxEntries)
    {
    }

    /// Records `before`, the state a new action is about to change (costing `bytes`), and
    /// drops the redo branch. The oldest entries go when the history exceeds its limits; the
    /// newest entry is always kept, even alone over the limit.
    void Push(State before, size_t bytes, std::string label)
    {
        clear(redo, redoBytes);
        undo.push_back(Entry{std::move(before), bytes, std::move(label)});
        undoBytes += bytes;
        while (undo.size() > 1 && (undo.size() > maxCount || undoBytes + redoBytes > limit)) {
            undoBytes -= undo.front().bytes;
            undo.pop_front();
        }
    }
    /// Takes back the newest entry without an undo (an action that changed nothing).
    void DropLast()
    {
        if (undo.empty()) return;
        undoBytes -= undo.back().bytes;
        undo.pop_back();
    }

    bool CanUndo() const { return !undo.empty(); }
    bool CanRedo() const { return !redo.empty(); }
    /// The action the next Undo / Redo takes back / applies again ("" if none).
    std::string UndoLabel() const { return undo.empty() ? std::string() : undo.back().label; }
    std::string RedoLabel() const { return redo.empty() ? std::string() : redo.back().label; }
    size_t UndoCount() const { return undo.size(); }
    size_t RedoCount() const { return redo.size(); }
    size_t Bytes() const { return undoBytes + redoBytes; }
    size_t Limit() const { return limit; }
    void SetLimit(size_t bytes) { limit = bytes; }

    /// The state the next Undo / Redo would bring back (nullptr if none).
    const State *Peek(bool redoSide) const
    {
        const std::deque<Entry> &d = redoSide ? redo : undo;
        return d.empty() ? nullptr : &d.back().state;
    }

    /// Swaps `current` (costing `bytes`) with the state before the newest action.
    bool Undo(State &current, size_t bytes)
    {
        return move(undo, undoBytes, redo, redoBytes, current, bytes);
    }
    bool Redo(State &current, size_t bytes)
    {
        return move(redo, redoBytes, undo, undoBytes, current, bytes);
    }
    /// Drops the redo side (an action the history does not hold, e.g. a cut, was made).
    void ClearRedo() { clear(redo, redoBytes); }
    void Clear()
    {
        clear(undo, undoBytes);
        clear(redo, redoBytes);
    }

private:
    struct Entry
    {
        State state;
        size_t bytes;
        std::string label;
    };
    std::deque<Entry> undo, redo;
    size_t undoBytes = 0, redoBytes = 0;
    size_t limit, maxCount;

    static void clear(std::deque<Entry> &d, size_t &bytes)
    {
        d.clear();
        bytes = 0;
    }
    static bool move(std::deque<Entry> &from, size_t &fromBytes, std::deque<Entry> &to, size_t &toBytes, State &current,
                     size_t bytes)
    {
        if (from.empty()) return false;
        Entry e = std::move(from.back());
        from.pop_back();
        fromBytes -= e.bytes;
        to.push_back(Entry{std::move(current), bytes, e.label});
        toBytes += bytes;
        current = std::move(e.state);
        return true;
    }
};

} // namespace tri
} // namespace vcg

#endif
