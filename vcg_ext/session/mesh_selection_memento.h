#ifndef VCG_EXT_MESH_SELECTION_MEMENTO_H
#define VCG_EXT_MESH_SELECTION_MEMENTO_H

// The face and vertex selection of a mesh (MeshLab's selection: vcglib's S flags), saved so
// an undo step can bring it back (the edit tool's Select inside / outside). One bit per
// element: 0.3 MB for a mesh of 1.2M faces.

#include <cstddef>
#include <vector>

namespace vcg {
namespace tri {

template <class MeshType>
class MeshSelectionMemento
{
public:
    static MeshSelectionMemento Save(const MeshType &m)
    {
        MeshSelectionMemento s;
        s.face.resize(m.face.size());
        s.vert.resize(m.vert.size());
        for (size_t i = 0; i < m.face.size(); ++i) s.face[i] = !m.face[i].IsD() && m.face[i].IsS();
        for (size_t i = 0; i < m.vert.size(); ++i) s.vert[i] = !m.vert[i].IsD() && m.vert[i].IsS();
        return s;
    }

    /// Sets m's selection to this one; false (and m unchanged) if m has other element counts
    /// than when it was saved (vertices or faces were added or removed since).
    bool Restore(MeshType &m) const
    {
        if (m.face.size() != face.size() || m.vert.size() != vert.size()) return false;
        for (size_t i = 0; i < m.face.size(); ++i)
            if (!m.face[i].IsD()) face[i] ? m.face[i].SetS() : m.face[i].ClearS();
        for (size_t i = 0; i < m.vert.size(); ++i)
            if (!m.vert[i].IsD()) vert[i] ? m.vert[i].SetS() : m.vert[i].ClearS();
        return true;
    }

    bool operator==(const MeshSelectionMemento &o) const { return face == o.face && vert == o.vert; }
    bool operator!=(const MeshSelectionMemento &o) const { return !(*this == o); }
    size_t Bytes() const { return sizeof(*this) + (face.size() + vert.size()) / 8; }

private:
    std::vector<bool> face, vert;
};

} // namespace tri
} // namespace vcg

#endif
