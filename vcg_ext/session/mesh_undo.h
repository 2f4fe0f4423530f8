#ifndef VCG_EXT_SESSION_MESH_UNDO_H
#define VCG_EXT_SESSION_MESH_UNDO_H

// Undo of an action that changes the mesh itself (issue 34: a cut adds vertices and faces), in
// a host that has no mesh undo (MeshLab 2020.09). The snakes are surface points on the mesh's
// faces, so such an action ends the editing session and starts a new one on the new mesh; its
// undo step is the whole state before it: a copy of the mesh (vcglib's Append: vertices, faces,
// their flags (the selection), colour, quality, normals, texture coordinates, the textures),
// the session as saved (SnakeController::ToJson) and the session's own undo history
// (SnakeController::KeptHistory), so after the undo Ctrl+Z goes on into the steps before it.
//
// Undo and Redo swap the mesh with the step's (the state they replace goes to the other side).
// The steps are bounded by the memory their meshes take (an estimate) and by a count: a mesh
// copy is large, so by default only the last two such actions can be undone; an action whose
// mesh alone exceeds the limit is not kept (Push says so).

#include <cstddef>
#include <memory>
#include <string>
#include <utility>

#include <vcg/complex/append.h>

#include <vcg_ext/session/undo.h>

namespace vcg {
namespace tri {

namespace detail {
// Append copies only the components both meshes have: a copy of a mesh with optional (ocf)
// components enables those the original has enabled (MeshLab's colour per face, texture
// coordinates per wedge, ...). Adjacency and marks are left out: they are recomputed. Scalar
// curvature is left out too: vcglib after 2020.09 has no such component (only its directions).
#define GS_ENABLE_LIKE(NAME, CONT, HAS, ENABLE)                                                                       \
    template <class M>                                                                                                 \
    auto NAME(M &c, const M &f, int)->decltype(c.CONT.ENABLE(), void())                                              \
    {                                                                                                                  \
        if (HAS(f) && !HAS(c)) c.CONT.ENABLE(); /* an optional component enabled on f only */                  \
    }                                                                                                                  \
    template <class M>                                                                                                 \
    void NAME(M &, const M &, long)                                                                                    \
    {                                                                                                                  \
    }
GS_ENABLE_LIKE(LikeVertTexCoord, vert, tri::HasPerVertexTexCoord, EnableTexCoord)
GS_ENABLE_LIKE(LikeVertRadius, vert, tri::HasPerVertexRadius, EnableRadius)
GS_ENABLE_LIKE(LikeVertCurvatureDir, vert, tri::HasPerVertexCurvatureDir, EnableCurvatureDir)
GS_ENABLE_LIKE(LikeVertColor, vert, tri::HasPerVertexColor, EnableColor)
GS_ENABLE_LIKE(LikeVertQuality, vert, tri::HasPerVertexQuality, EnableQuality)
GS_ENABLE_LIKE(LikeFaceColor, face, tri::HasPerFaceColor, EnableColor)
GS_ENABLE_LIKE(LikeFaceQuality, face, tri::HasPerFaceQuality, EnableQuality)
GS_ENABLE_LIKE(LikeFaceNormal, face, tri::HasPerFaceNormal, EnableNormal)
GS_ENABLE_LIKE(LikeWedgeTexCoord, face, tri::HasPerWedgeTexCoord, EnableWedgeTexCoord)
GS_ENABLE_LIKE(LikeFaceCurvatureDir, face, tri::HasPerFaceCurvatureDir, EnableCurvatureDir)
#undef GS_ENABLE_LIKE

template <class M>
void EnableOptionalLike(M &c, const M &f)
{
    LikeVertTexCoord(c, f, 0), LikeVertRadius(c, f, 0), LikeVertCurvatureDir(c, f, 0);
    LikeVertColor(c, f, 0), LikeVertQuality(c, f, 0);
    LikeFaceColor(c, f, 0), LikeFaceQuality(c, f, 0), LikeFaceNormal(c, f, 0), LikeWedgeTexCoord(c, f, 0);
    LikeFaceCurvatureDir(c, f, 0);
}
} // namespace detail

/// One step of SnakeMeshUndo: the mesh, the session as saved and its undo history.
template <class MeshType, class History>
struct SnakeMeshStep
{
    std::unique_ptr<MeshType> mesh;
    std::string session;
    History history;
};

template <class MeshType, class History>
class SnakeMeshUndo : private SnakeUndo<SnakeMeshStep<MeshType, History>>
{
    typedef SnakeMeshStep<MeshType, History> Step;
    typedef SnakeUndo<Step> Steps; // the steps, their labels, bounds and sides

public:
    struct Param
    {
        size_t byteLimit = size_t(512) << 20; ///< all steps' mesh copies, undo and redo
        size_t maxSteps = 2;                  ///< undo steps kept (the newest)
    };
    explicit SnakeMeshUndo(Param p = Param()) : Steps(p.byteLimit, p.maxSteps), par(p) {}

    /// The memory a copy of `m` takes (an estimate: the elements, twice for optional components).
    static size_t MeshBytes(const MeshType &m)
    {
        return sizeof(MeshType) + 2 * (m.vert.size() * sizeof(typename MeshType::VertexType) +
                                       m.face.size() * sizeof(typename MeshType::FaceType));
    }

    /// A copy of `m` for a step, made before the action (whose outcome decides whether it is
    /// kept: Push), or nullptr if it would not fit the limit or cannot hold (`why` says why).
    std::unique_ptr<MeshType> Snapshot(MeshType &m, std::string &why) const
    {
        why.clear();
        const size_t b = MeshBytes(m);
        if (size_t(m.vn) != m.vert.size() || size_t(m.fn) != m.face.size()) {
            // a copy leaves deleted elements out: the session's face indices would not hold
            why = "the mesh has deleted vertices or faces not yet compacted";
            return nullptr;
        }
        if (b > par.byteLimit) {
            why = "the mesh is too large to keep a copy for undo (" + std::to_string(b >> 20) + " MB, the limit is " +
                  std::to_string(par.byteLimit >> 20) + " MB)";
            return nullptr;
        }
        return copyOf(m);
    }
    /// Keeps `before` (Snapshot of the mesh before the action `label`), the session and its
    /// history then, as the newest step, and drops the redo side.
    void Push(std::unique_ptr<MeshType> before, std::string session, History history, const std::string &label)
    {
        const size_t b = MeshBytes(*before);
        Steps::Push(Step{std::move(before), std::move(session), std::move(history)}, b, label);
    }
    /// Snapshot and Push at once: false (nothing kept, the redo side dropped, `why` says why) if
    /// the mesh cannot be kept.
    bool Push(MeshType &m, std::string session, History history, const std::string &label, std::string &why)
    {
        std::unique_ptr<MeshType> c = Snapshot(m, why);
        if (!c) {
            Steps::ClearRedo();
            return false;
        }
        Push(std::move(c), std::move(session), std::move(history), label);
        return true;
    }

    using Steps::CanRedo;
    using Steps::CanUndo;
    using Steps::Bytes;
    using Steps::Clear;
    using Steps::ClearRedo;
    using Steps::RedoCount;
    using Steps::RedoLabel;
    using Steps::UndoCount;
    using Steps::UndoLabel;

    /// Brings back the mesh before the newest action: `m` becomes the step's mesh, `session` and
    /// `history` (in: the current ones, kept for Redo) the step's. False if there is none. `m` must
    /// have no deleted elements (as after the action, which compacts).
    bool Undo(MeshType &m, std::string &session, History &history) { return swap(false, m, session, history); }
    bool Redo(MeshType &m, std::string &session, History &history) { return swap(true, m, session, history); }

    /// Sets `m` to `from` exactly (Append::MeshCopy, after clearing what MeshCopy appends to: the
    /// textures). Adjacency is not copied: the caller updates it.
    static void Copy(MeshType &m, const MeshType &from)
    {
        m.textures.clear();
        m.normalmaps.clear();
        Append<MeshType, MeshType>::MeshCopy(m, const_cast<MeshType &>(from), false, false);
    }

private:
    Param par;

    static std::unique_ptr<MeshType> copyOf(const MeshType &m)
    {
        std::unique_ptr<MeshType> c(new MeshType);
        detail::EnableOptionalLike(*c, m);
        Copy(*c, m);
        return c;
    }
    bool swap(bool redoSide, MeshType &m, std::string &session, History &history)
    {
        if (!Steps::Peek(redoSide)) return false;
        // the state now goes to the other side; the step's comes back
        Step s{copyOf(m), std::move(session), std::move(history)};
        const size_t b = MeshBytes(m);
        redoSide ? Steps::Redo(s, b) : Steps::Undo(s, b);
        Copy(m, *s.mesh);
        session = std::move(s.session);
        history = std::move(s.history);
        return true;
    }
};

} // namespace tri
} // namespace vcg

#endif
