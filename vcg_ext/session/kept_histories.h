#ifndef VCG_EXT_SESSION_KEPT_HISTORIES_H
#define VCG_EXT_SESSION_KEPT_HISTORIES_H

// The undo histories of the meshes the edit tool left (issue 37): MeshLab ends an edit tool
// whenever a filter starts (even one that only selects), so the tool's undo must outlive the
// tool. The host keeps one history per mesh (Key: the document and the mesh's id) from the
// tool's end to its next start on that mesh, and drops it when the mesh is closed.
//
// A history is handed back only to the session it was recorded in, on the mesh it was recorded
// on: the mesh's fingerprint (SnakeMeshFingerprint) and the session's text (the snakes, seeds
// and parameters the tool saved when it ended) must be what they were. Otherwise (a filter
// removed faces, moved vertices, or made other snakes) the history is dropped and Take says
// why: its steps would put curves on faces that are no longer the ones they were on.

#include <functional>
#include <map>
#include <string>
#include <utility>

#include <vcg_ext/session/mesh_fingerprint.h>

namespace vcg {
namespace tri {

/// History: movable, with UndoCount() and RedoCount() (SnakeUndo, SnakeSessionHistory's KeptSteps).
template <class Key, class History>
class SnakeKeptHistories
{
public:
    /// Keeps `h`, recorded on the mesh `mesh` in the session saved as `session`, for `key`
    /// (replacing what was kept for it).
    void Keep(const Key &key, History h, const SnakeMeshFingerprint &mesh, const std::string &session)
    {
        kept.erase(key);
        kept.emplace(key, Kept{std::move(h), mesh, hash(session), session.size()});
    }

    enum class Outcome
    {
        None,   ///< nothing was kept for the key
        Taken,  ///< `out` holds the history
        Dropped ///< something was kept but does not apply any more: `why` says why
    };
    /// The history kept for `key`, if the mesh is still `mesh` and the session `session`; it
    /// leaves the store either way.
    Outcome Take(const Key &key, const SnakeMeshFingerprint &mesh, const std::string &session, History &out,
                 std::string &why)
    {
        why.clear();
        auto it = kept.find(key);
        if (it == kept.end()) return Outcome::None;
        Kept k = std::move(it->second);
        kept.erase(it);
        const std::string change = k.mesh.Change(mesh);
        if (!change.empty())
            why = "the mesh changed while the tool was away: " + change;
        else if (k.sessionHash != hash(session) || k.sessionSize != session.size())
            why = "the snakes of this mesh were changed while the tool was away (by a filter or another session)";
        if (!why.empty()) return Outcome::Dropped;
        out = std::move(k.history);
        return Outcome::Taken;
    }

    bool Has(const Key &key) const { return kept.count(key) > 0; }
    /// Undo and redo steps kept for `key` (0 if none).
    size_t Steps(const Key &key) const
    {
        auto it = kept.find(key);
        return it == kept.end() ? 0 : it->second.history.UndoCount() + it->second.history.RedoCount();
    }
    size_t Size() const { return kept.size(); }
    /// Drops every history whose key `gone` says is gone (a closed mesh or document); returns how many.
    size_t DropIf(const std::function<bool(const Key &)> &gone)
    {
        size_t n = 0;
        for (auto it = kept.begin(); it != kept.end();) {
            if (gone(it->first)) {
                it = kept.erase(it);
                ++n;
            } else
                ++it;
        }
        return n;
    }
    void Clear() { kept.clear(); }

private:
    struct Kept
    {
        History history;
        SnakeMeshFingerprint mesh;
        size_t sessionHash, sessionSize;
    };
    std::map<Key, Kept> kept;

    static size_t hash(const std::string &s) { return std::hash<std::string>()(s); }
};

} // namespace tri
} // namespace vcg

#endif
