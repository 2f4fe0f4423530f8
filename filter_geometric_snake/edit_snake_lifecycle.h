#ifndef GS_EDIT_SNAKE_LIFECYCLE_H
#define GS_EDIT_SNAKE_LIFECYCLE_H

// The edit tool's life in MeshLab (issue 37). MeshLab ends the active edit tool whenever a
// filter starts, even one that only selects (MainWindow::startFilter calls endEdit first), and
// on a layer switch (endEdit + startEdit); it keeps one tool object per view and action and
// reuses it. The tool's undo history must outlive that: when the tool leaves a mesh it hands
// the history to the SnakeHistoryKeeper, owned by the plugin's factory, which keeps it per mesh
// (document, mesh id) until the mesh or its document is closed, and gives it back to the next
// start on that mesh if the mesh and its snakes are as the tool left them
// (vcg_ext/session/kept_histories.h).

#include <set>
#include <string>
#include <utility>

#include <QObject>

#include "meshlab_host.h" // MeshLab 2020.09 or 2022.02, chosen by CMake
#include <vcg_ext/session/controller.h>
#include <vcg_ext/session/kept_histories.h>

class SnakeHistoryKeeper : public QObject
{
public:
    typedef vcg::tri::SnakeController<CMeshO>::KeptHistory History;
    typedef std::pair<const MeshDocument *, int> Key; // the document, the mesh's id in it
    typedef vcg::tri::SnakeKeptHistories<Key, History> Store;

    explicit SnakeHistoryKeeper(QObject *parent = nullptr) : QObject(parent) {}

    /// Keeps the history `h` of mesh `m`, whose session the tool left as `session` (the text
    /// it stored on the mesh).
    void Keep(MeshDocument &doc, MeshModel &m, History h, const std::string &session);
    /// The history kept for `m` if `m` and its stored session `session` are unchanged (Taken),
    /// else Dropped with `why`, or None.
    Store::Outcome Take(MeshDocument &doc, MeshModel &m, const std::string &session, History &out, std::string &why);

private:
    Store store;
    std::set<const MeshDocument *> watched;
    // drops the histories of the meshes closed in `doc`, and all of them when it is destroyed
    void watch(MeshDocument &doc);
    void sweep(MeshDocument &doc);
};

#endif
