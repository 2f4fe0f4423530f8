#ifndef VCG_EXT_SNAKE_MESH_STORE_H
#define VCG_EXT_SNAKE_MESH_STORE_H

#include <string>

#include <vcg/complex/allocate.h>

namespace vcg {
namespace tri {

/// The snakes of a mesh, kept on the mesh itself as a per-mesh attribute (vcglib): the
/// session JSON of SnakeController. The edit tool and the filters of the plugin (each its
/// own library) share it through the mesh, so a snake made by the batch filter shows up in
/// the edit tool and the export filter writes what the edit tool made.
template <class MeshType>
class SnakeMeshStore
{
public:
    static const char *Name() { return "geometric_snake_session"; }

    static bool Has(MeshType &m)
    {
        return tri::HasPerMeshAttribute(m, Name()) && !Get(m).empty();
    }
    static std::string Get(MeshType &m)
    {
        if (!tri::HasPerMeshAttribute(m, Name())) return std::string();
        auto h = tri::Allocator<MeshType>::template FindPerMeshAttribute<std::string>(m, Name());
        return tri::Allocator<MeshType>::template IsValidHandle<std::string>(m, h) ? h() : std::string();
    }
    static void Set(MeshType &m, const std::string &session)
    {
        auto h = tri::Allocator<MeshType>::template GetPerMeshAttribute<std::string>(m, Name());
        h() = session;
    }
};

} // namespace tri
} // namespace vcg

#endif
